"""Grading a class as handed in: each cadet's package built, run in a sandbox, its letter read and scored."""
