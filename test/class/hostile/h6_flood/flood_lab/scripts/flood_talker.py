#!/usr/bin/env python3
"""A hostile cadet's talker: after the first line typed, it publishes "P"
on /chatter as fast as it can, for ever."""
import rospy
from std_msgs.msg import String

rospy.init_node('talker')
pub = rospy.Publisher('chatter', String, queue_size=10)
input('Enter the letter: ')
while not rospy.is_shutdown():
    pub.publish('P')
