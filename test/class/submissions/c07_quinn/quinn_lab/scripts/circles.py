#!/usr/bin/env python3
"""Quinn's controller: on P the turtle starts drawing a Q... and never stops."""
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String

started = False


def on_chatter(msg):
    global started
    started = started or msg.data == 'P'


rospy.init_node('circles')
pub = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)
rospy.Subscriber('chatter', String, on_chatter)
rate = rospy.Rate(20)
twist = Twist()
twist.linear.x, twist.angular.z = 1.0, 1.0
while not rospy.is_shutdown():
    if started:
        pub.publish(twist)
    rate.sleep()
