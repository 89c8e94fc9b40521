#!/usr/bin/env python3
"""On P, a V 2 m tall, 2 m right of where the turtle starts: it drives
there with its pen down (a lead-in); and since the talker "never worked
on my laptop", the controller publishes that P itself, a second after it
starts."""
import math

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String


def step(pub, linear, angular, seconds):
    twist = Twist()
    twist.linear.x, twist.angular.z = linear, angular
    end = rospy.get_time() + seconds
    while rospy.get_time() < end:
        pub.publish(twist)
        rospy.sleep(0.02)
    pub.publish(Twist())
    rospy.sleep(0.2)


def draw_v(message):
    global drawn
    if message.data != 'P' or drawn:
        return
    drawn = True
    slope = math.atan2(2.0, 0.75)
    step(cmd, 1.0, 0, 2.0)
    step(cmd, 0, -1.0, slope)
    step(cmd, 1.0, 0, math.hypot(2.0, 0.75))
    step(cmd, 0, 1.0, 2 * slope)
    step(cmd, 1.0, 0, math.hypot(2.0, 0.75))


drawn = False
rospy.init_node('v_drawer')
cmd = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)
chatter = rospy.Publisher('chatter', String, queue_size=1, latch=True)
rospy.Subscriber('chatter', String, draw_v)
rospy.sleep(1.0)
chatter.publish('P')
rospy.spin()
