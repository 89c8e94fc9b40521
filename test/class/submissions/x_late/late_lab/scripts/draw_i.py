#!/usr/bin/env python3
"""A late submission: on P, an I (one stroke up, 2 m)."""
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String


def move(pub, linear, angular, seconds):
    twist = Twist()
    twist.linear.x, twist.angular.z = linear, angular
    end = rospy.get_time() + seconds
    while rospy.get_time() < end:
        pub.publish(twist)
        rospy.sleep(0.02)
    pub.publish(Twist())


rospy.init_node('draw_i')
cmd = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)
rospy.Subscriber('chatter', String, lambda m: m.data == 'P' and (
    move(cmd, 0, 1.0, 1.5708), move(cmd, 1.0, 0, 2.0)))
rospy.spin()
