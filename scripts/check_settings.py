#!/usr/bin/python3
"""draw_letter.launch's check of the controller's parameters, before any node
starts: turtle_letters.settings.check_launch."""
import sys

from turtle_letters.settings import check_launch

if __name__ == '__main__':
    sys.exit(check_launch(sys.argv[1:]))
