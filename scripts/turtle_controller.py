#!/usr/bin/python3
"""Node turtlebot_controller: draws the letter N (or any letter) on "P"."""
from turtle_letters.controller import main

if __name__ == '__main__':
    main()
