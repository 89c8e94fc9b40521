#!/usr/bin/env python3
"""Draws an I on the first P, and never again."""
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String


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
    global drawn
    if message.data == 'P' and not drawn:
        drawn = True
        draw_i(cmd)


drawn = False
rospy.init_node('i_drawer')
cmd = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)
rospy.Subscriber('chatter', String, on_chatter)
rospy.spin()
