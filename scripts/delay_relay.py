#!/usr/bin/python3
"""A topic passed on late, as over a slow network: see turtle_letters.classroom.delay."""
from turtle_letters.classroom.delay import main

if __name__ == '__main__':
    main()
