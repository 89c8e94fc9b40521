#!/usr/bin/python3
"""Node turtle_letters_room: grants parts of a shared canvas, one at a time."""
from turtle_letters.classroom.room import main

if __name__ == '__main__':
    main()
