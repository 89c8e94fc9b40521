#!/usr/bin/env python3
"""Kofi's controller: on "P" the turtle draws a K, 2 m tall, its arms
meeting at the middle of the stem. Timed moves at 50 Hz."""
import math
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String


class KDrawer:
    def __init__(self):
        self.pub = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=1)
        self.go = False
        rospy.Subscriber('/chatter', String, self.heard)

    def heard(self, msg):
        if msg.data == 'P':
            self.go = True

    def drive(self, linear, angular, seconds):
        cmd = Twist()
        cmd.linear.x = linear
        cmd.angular.z = angular
        rate = rospy.Rate(50)
        end = rospy.Time.now() + rospy.Duration(seconds)
        while rospy.Time.now() < end and not rospy.is_shutdown():
            self.pub.publish(cmd)
            rate.sleep()
        self.pub.publish(Twist())
        rospy.sleep(0.3)

    def turn(self, degrees):
        self.drive(0.0, 1.0, math.radians(degrees))

    def forward(self, metres):
        self.drive(1.0, 0.0, metres)

    def draw_k(self):
        arm = math.sqrt(2.0)
        self.turn(90)
        self.forward(2.0)
        self.turn(180)
        self.forward(1.0)
        self.turn(135)
        self.forward(arm)
        self.turn(180)
        self.forward(arm)
        self.turn(90)
        self.forward(arm)

    def spin(self):
        rate = rospy.Rate(10)
        while not rospy.is_shutdown():
            if self.go:
                self.draw_k()
                self.go = False
            rate.sleep()


if __name__ == '__main__':
    rospy.init_node('k_drawer')
    KDrawer().spin()
