#!/usr/bin/python3
"""grade_class.py: grades a class's lab packages as handed in (see --help)."""
import sys

from turtle_letters.autograder.cli import main

if __name__ == '__main__':
    sys.exit(main())
