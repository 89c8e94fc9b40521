#!/usr/bin/env python3
"""Tariq's controller: draws a perfect T, by teleporting the turtle."""
import rospy
from std_msgs.msg import String
from turtlesim.msg import Pose
from turtlesim.srv import TeleportAbsolute

rospy.init_node('t_drawer')
teleport = rospy.ServiceProxy('turtle1/teleport_absolute', TeleportAbsolute)
start = rospy.wait_for_message('turtle1/pose', Pose)


def on_chatter(msg):
    if msg.data != 'P':
        return
    x, y = start.x, start.y
    for px, py in [(x, y + 2.0), (x - 0.8, y + 2.0), (x + 0.8, y + 2.0)]:
        teleport(px, py, 0.0)
        rospy.sleep(0.5)


rospy.Subscriber('chatter', String, on_chatter)
rospy.spin()
