#!/usr/bin/env python3
"""Logs the turtle's heading as a quaternion, and plots its path when
stopped, with numpy, tf and matplotlib as a course machine has them."""
import matplotlib.pyplot as plt
import numpy as np
import rospy
import tf.transformations as tft
from turtlesim.msg import Pose

path = []


def on_pose(pose):
    q = tft.quaternion_from_euler(0.0, 0.0, pose.theta)
    rospy.loginfo_throttle(5.0, 'heading %.2f rad, quaternion %s', pose.theta, np.round(q, 3))
    path.append((pose.x, pose.y))


def plot_path():
    if path:
        plt.plot(*zip(*path))
        plt.savefig('kenji_path.png')


rospy.init_node('heading')
rospy.Subscriber('turtle1/pose', Pose, on_pose)
rospy.on_shutdown(plot_path)
rospy.spin()
