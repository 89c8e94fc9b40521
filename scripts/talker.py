#!/usr/bin/python3
"""Node talker: publishes "P" on chatter when the key P is pressed."""
from turtle_letters.talker import main

if __name__ == '__main__':
    main()
