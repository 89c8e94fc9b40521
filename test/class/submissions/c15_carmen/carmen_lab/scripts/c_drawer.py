#!/usr/bin/env python3
"""Carmen's lab: the turtle draws a C as soon as it is launched (no talker:
she never got the keyboard part working)."""
import math

import rospy
from geometry_msgs.msg import Twist


def drive(pub, linear, angular, seconds):
    cmd = Twist()
    cmd.linear.x, cmd.angular.z = linear, angular
    rate = rospy.Rate(50)
    end = rospy.Time.now() + rospy.Duration(seconds)
    while rospy.Time.now() < end and not rospy.is_shutdown():
        pub.publish(cmd)
        rate.sleep()
    pub.publish(Twist())
    rospy.sleep(0.3)


if __name__ == '__main__':
    rospy.init_node('c_drawer')
    pub = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=10)
    rospy.sleep(2.0)
    drive(pub, 0.0, 1.0, math.pi)           # face west
    drive(pub, 1.0, 0.0, 1.2)               # the top
    drive(pub, 0.0, 1.0, math.pi / 2)       # face south
    drive(pub, 1.0, 0.0, 2.0)               # the back
    drive(pub, 0.0, 1.0, math.pi / 2)       # face east
    drive(pub, 1.0, 0.0, 1.2)               # the bottom
    rospy.spin()
