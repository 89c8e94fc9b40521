#!/usr/bin/env python3
"""Lars's controller: Lena's L, with the pause between strokes that many
cadets put in (3 s): the drawing goes on after it."""
import math

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String
from turtlesim.msg import Pose


class LController:
    def __init__(self):
        self.pose = None
        self.start = False
        self.cmd = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=10)
        rospy.Subscriber('turtle1/pose', Pose, self.on_pose)
        rospy.Subscriber('chatter', String, self.on_chatter)

    def on_pose(self, pose):
        self.pose = pose

    def on_chatter(self, msg):
        self.start = msg.data == 'P'

    def go_to(self, x, y):
        rate = rospy.Rate(30)
        while not rospy.is_shutdown():
            dx, dy = x - self.pose.x, y - self.pose.y
            if math.hypot(dx, dy) < 0.01:
                break
            error = math.atan2(dy, dx) - self.pose.theta
            error = math.atan2(math.sin(error), math.cos(error))
            cmd = Twist()
            cmd.angular.z = 4.0 * error
            if abs(error) < 0.2:
                cmd.linear.x = min(1.0, 2.0 * math.hypot(dx, dy))
            self.cmd.publish(cmd)
            rate.sleep()
        self.cmd.publish(Twist())

    def run(self):
        rate = rospy.Rate(10)
        while not rospy.is_shutdown():
            if self.start and self.pose:
                x, y = self.pose.x, self.pose.y
                for px, py in [(x, y + 2.5), (x, y), (x + 1.5, y)]:
                    self.go_to(px, py)
                    rospy.sleep(3.0)
                self.start = False
            rate.sleep()


if __name__ == '__main__':
    rospy.init_node('lars_controller')
    LController().run()
