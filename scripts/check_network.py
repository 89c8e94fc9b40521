#!/usr/bin/python3
"""Whether this machine can take part in a ROS system over the network: see turtle_letters.network."""
import sys

from turtle_letters.classroom.network import main

if __name__ == '__main__':
    sys.exit(main())
