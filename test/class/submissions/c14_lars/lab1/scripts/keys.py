#!/usr/bin/env python3
"""Lena's talker: press a key (no Enter needed); q quits."""
import sys
import termios
import tty

import rospy
from std_msgs.msg import String


def read_key():
    fd = sys.stdin.fileno()
    old = termios.tcgetattr(fd)
    try:
        tty.setraw(fd)
        return sys.stdin.read(1)
    finally:
        termios.tcsetattr(fd, termios.TCSADRAIN, old)


if __name__ == '__main__':
    rospy.init_node('keys')
    pub = rospy.Publisher('chatter', String, queue_size=1)
    print('Press P to draw, q to quit')
    while not rospy.is_shutdown():
        key = read_key()
        if key == 'q':
            break
        if key.isalpha():
            pub.publish(String(key.upper()))
