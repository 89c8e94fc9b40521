#!/usr/bin/python3
"""Node grader: scores each drawing of a turtle against the ideal letter."""
from turtle_letters.grading.grader import main

if __name__ == '__main__':
    main()
