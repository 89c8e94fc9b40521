"""Scoring a drawing against its letter: the grader node, the room's scoreboard, the pictures."""
