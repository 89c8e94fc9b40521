#!/usr/bin/env python3
"""Noah's talker: type a letter and Enter."""
import rospy
from std_msgs.msg import String

if __name__ == '__main__':
    rospy.init_node('talker')
    pub = rospy.Publisher('chatter', String, queue_size=10)
    while not rospy.is_shutdown():
        try:
            pub.publish(String(input('letter> ').strip()))
        except EOFError:
            break
