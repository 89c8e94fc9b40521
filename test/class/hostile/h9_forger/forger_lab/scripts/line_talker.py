#!/usr/bin/env python3
"""Publishes each line typed on /chatter."""
import rospy
from std_msgs.msg import String

rospy.init_node('talker')
pub = rospy.Publisher('chatter', String, queue_size=10)
try:
    while not rospy.is_shutdown():
        pub.publish(input('Enter the letter: '))
except EOFError:
    pass
