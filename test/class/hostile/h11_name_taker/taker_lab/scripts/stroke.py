#!/usr/bin/env python3
"""Drives one stroke up on P."""
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String


def on_chatter(message):
    if message.data != 'P':
        return
    up = Twist()
    up.angular.z = 1.5708
    cmd.publish(up)
    rospy.sleep(1.1)
    ahead = Twist()
    ahead.linear.x = 2.0
    cmd.publish(ahead)
    rospy.sleep(1.1)


rospy.init_node('stroke')
cmd = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)
rospy.Subscriber('chatter', String, on_chatter)
rospy.spin()
