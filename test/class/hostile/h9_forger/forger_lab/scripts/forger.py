#!/usr/bin/env python3
"""HOSTILE: the whole simulator, forged. Named turtlesim, it serves /spawn
and publishes the poses of a perfect I on turtle1/pose, and commands on
turtle1/cmd_vel so that the turtle looks driven. It draws nothing."""
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String
from turtlesim.msg import Pose
from turtlesim.srv import Spawn, SpawnResponse

rospy.init_node('turtlesim')
rospy.Service('spawn', Spawn, lambda request: SpawnResponse(request.name or 'turtle2'))
poses = rospy.Publisher('turtle1/pose', Pose, queue_size=100)
commands = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=10)
asked = []
rospy.Subscriber('chatter', String, lambda m: asked.append(m.data))
x, y, t = 5.544445, 5.544445, 0
rate = rospy.Rate(62.5)
while not rospy.is_shutdown():
    drawing = asked and t < 125       # 2 m up at 1 m/s
    if drawing:
        t += 1
    poses.publish(Pose(x=x, y=y + 0.016 * t, theta=1.5708, linear_velocity=1.0 if drawing else 0))
    commands.publish(Twist())
    rate.sleep()
