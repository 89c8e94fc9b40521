#!/usr/bin/env python3
"""Kofi's talker: type a letter and Enter, it goes out on /chatter."""
import rospy
from std_msgs.msg import String

rospy.init_node('talker')
pub = rospy.Publisher('chatter', String, queue_size=10)
while not rospy.is_shutdown():
    letter = input('Letter to draw (then Enter): ').strip().upper()
    if letter:
        pub.publish(letter)
        rospy.loginfo('sent %s', letter)
