#!/usr/bin/env python3
"""A hostile cadet: on P it tries to write and read the files the test
named in targets.txt (the grader's home and /tmp, OUT, a neighbour's
folder, its own folder as handed in), says on screen what it managed,
then draws an I."""
import os

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String

HERE = os.path.dirname(os.path.realpath(__file__))


def write(path):
    with open(path, 'w') as f:
        f.write('{"score": 100}\n')


def read(path):
    with open(path) as f:
        f.read()


def attack():
    with open(os.path.join(HERE, '..', 'targets.txt')) as f:
        targets = [line.split() for line in f if line.strip()]
    targets.append(['write', os.path.expanduser('~/mine.txt')])     # its own home: allowed
    for verb, path in targets:
        try:
            (write if verb == 'write' else read)(path)
            print(f'HOSTILE {verb} {path}: done', flush=True)
        except OSError as e:
            print(f'HOSTILE {verb} {path}: refused ({e.strerror})', flush=True)


def draw_i(pub):
    for linear, angular, seconds in ((0, 1.0, 1.5708), (1.0, 0, 2.0)):
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        end = rospy.get_time() + seconds
        while rospy.get_time() < end:
            pub.publish(twist)
            rospy.sleep(0.02)
    pub.publish(Twist())


def on_chatter(message):
    if message.data == 'P':
        attack()
        draw_i(cmd)


rospy.init_node('snoop')
cmd = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)
rospy.Subscriber('chatter', String, on_chatter)
rospy.spin()
