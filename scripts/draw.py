#!/usr/bin/python3
"""Draw with the controller through its action `draw`: draw.py TEXT, or --svg FILE."""
import sys

from turtle_letters.actions.client import main

if __name__ == '__main__':
    sys.exit(main())
