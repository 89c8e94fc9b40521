#!/usr/bin/env python
"""The lab's controller as its students write it, kept to be graded: on "P"
it draws the N with busy loops timed on rospy.Time.now(), publishing the
speed as fast as it can until the time is up. `~second_turn` (deg, the lab's
225) makes a wrong N on purpose, for the grader's failing example."""
import math

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String


class LabController:
    def __init__(self):
        self.cmd_vel = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=10)
        self.second_turn = float(rospy.get_param('~second_turn', 225.0))
        self.triggered = False
        rospy.Subscriber('chatter', String, self.on_chatter, queue_size=1)

    def on_chatter(self, msg):
        self.triggered = self.triggered or msg.data == 'P'

    def drive(self, seconds, linear=0.0, angular=0.0):
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        start = rospy.Time.now().to_sec()
        while rospy.Time.now().to_sec() - start < seconds and not rospy.is_shutdown():
            self.cmd_vel.publish(twist)
        self.cmd_vel.publish(Twist())

    def rotate(self, degrees, speed=0.25):
        self.drive(math.radians(degrees) / speed, angular=speed)

    def move(self, meters, speed=1.0):
        self.drive(meters / speed, linear=speed)

    def run(self):
        rate = rospy.Rate(20)
        while not rospy.is_shutdown():
            if self.triggered:
                self.rotate(90)
                self.move(3.0)
                self.rotate(self.second_turn)
                self.move(3.5)
                self.rotate(135)
                self.move(3.0)
                self.triggered = False
            rate.sleep()


if __name__ == '__main__':
    rospy.init_node('turtlebot_controller')
    try:
        LabController().run()
    except rospy.ROSInterruptException:
        pass
