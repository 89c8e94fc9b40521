#!/usr/bin/env python3
"""Logs the turtle's heading as a quaternion, with numpy and tf as a
course machine has them."""
import numpy as np
import rospy
import tf.transformations as tft
from turtlesim.msg import Pose


def on_pose(pose):
    q = tft.quaternion_from_euler(0.0, 0.0, pose.theta)
    rospy.loginfo_throttle(5.0, 'heading %.2f rad, quaternion %s', pose.theta, np.round(q, 3))


rospy.init_node('heading')
rospy.Subscriber('turtle1/pose', Pose, on_pose)
rospy.spin()
