#!/usr/bin/python3
"""Node scoreboard: grades every student's turtle on the classroom's canvas."""
from turtle_letters.grading.scoreboard import main

if __name__ == '__main__':
    main()
