#!/usr/bin/python3
"""Node view: the shared canvas, live, as a web page and on canvas/image."""
from turtle_letters.viewer.node import main

if __name__ == '__main__':
    main()
