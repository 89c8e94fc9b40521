#!/usr/bin/env python3
import rospy
from std_msgs.msg import String

rospy.init_node('talker')
pub = rospy.Publisher('chatter', String, queue_size=10)
while not rospy.is_shutdown():
    try:
        pub.publish(input('Letter: ').strip().upper())
    except EOFError:
        break
