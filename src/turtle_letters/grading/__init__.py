"""The live grader in the lab: a drawing scored against its letter, the room's scoreboard, the pictures."""
