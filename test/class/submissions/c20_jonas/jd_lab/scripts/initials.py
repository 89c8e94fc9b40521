#!/usr/bin/env python3
"""Jonas's controller: his initials, J and D, the pen lifted between them."""
import math

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String
from turtlesim.msg import Pose
from turtlesim.srv import SetPen


class Initials:
    def __init__(self):
        self.pose, self.go = None, False
        self.cmd = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=10)
        self.pen = rospy.ServiceProxy('turtle1/set_pen', SetPen)
        rospy.Subscriber('turtle1/pose', Pose, self.on_pose)
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

    def letter(self, corners):
        self.pen(255, 255, 255, 3, 1)
        self.go_to(*corners[0])
        self.pen(255, 255, 255, 3, 0)
        for corner in corners[1:]:
            self.go_to(*corner)

    def run(self):
        while not rospy.is_shutdown():
            if self.go and self.pose:
                x, y = self.pose.x, self.pose.y
                self.letter([(x + 1.0, y + 2), (x + 1.0, y), (x, y), (x, y + 0.6)])
                self.letter([(x + 1.6, y), (x + 1.6, y + 2), (x + 2.2, y + 2), (x + 2.6, y + 1.6),
                             (x + 2.6, y + 0.4), (x + 2.2, y), (x + 1.6, y)])
                self.go = False
            rospy.sleep(0.1)


if __name__ == '__main__':
    rospy.init_node('initials')
    Initials().run()
