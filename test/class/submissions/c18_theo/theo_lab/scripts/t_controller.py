#!/usr/bin/env python3
"""Theo's controller: his own turtle, theo, draws a T (turtle1 is killed)."""
import math

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String
from turtlesim.msg import Pose
from turtlesim.srv import Kill, Spawn


def own_turtle():
    rospy.wait_for_service('kill')
    rospy.ServiceProxy('kill', Kill)('turtle1')
    rospy.ServiceProxy('spawn', Spawn)(4.0, 3.0, 0.0, 'theo')


class Controller:
    def __init__(self):
        self.pose, self.go = None, False
        self.cmd = rospy.Publisher('theo/cmd_vel', Twist, queue_size=10)
        self.pose_sub = rospy.Subscriber('theo/pose', Pose, self.on_pose)
        rospy.Subscriber('chatter', String, self.on_chatter)

    def on_pose(self, pose):
        self.pose = pose

    def on_chatter(self, msg):
        self.go = msg.data == 'P'

    def go_to(self, x, y, speed=1.0):
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
                cmd.linear.x = min(speed, 2.0 * math.hypot(dx, dy))
            self.cmd.publish(cmd)
            rate.sleep()
        self.cmd.publish(Twist())

    def run(self):
        while not rospy.is_shutdown():
            if self.go and self.pose:
                x, y = self.pose.x, self.pose.y
                for px, py in [(x, y + 2.0), (x - 0.8, y + 2.0), (x + 0.8, y + 2.0)]:
                    self.go_to(px, py)
                self.go = False
            rospy.sleep(0.1)


if __name__ == '__main__':
    rospy.init_node('t_controller')
    own_turtle()
    Controller().run()
