"""The names of a parallel word's spare turtles. No ROS here."""

# Student and turtle names may not hold two _ in a row (settings.py), so no
# student's turtle can be named like another's spare.
SPARE_MARK = '__'


def spare_name(name, number):
    """The spare turtle that draws character `number` (2, 3...) of a parallel word."""
    return f'{name}{SPARE_MARK}{number}'
