#!/usr/bin/env python3
"""A hostile cadet: draws an I on P, then spins forever, deaf to Ctrl-C,
SIGTERM and SIGHUP."""
import signal

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String


def draw_i(pub):
    for linear, angular, seconds in ((0, 1.0, 1.5708), (1.0, 0, 2.0)):
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        end = rospy.get_time() + seconds
        while rospy.get_time() < end:
            pub.publish(twist)
            rospy.sleep(0.02)
    pub.publish(Twist())


def on_chatter(message):
    if message.data == 'P':
        draw_i(cmd)
        while True:
            pass


for deaf in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
    signal.signal(deaf, signal.SIG_IGN)
rospy.init_node('immortal', disable_signals=True)
cmd = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)
rospy.Subscriber('chatter', String, on_chatter)
rospy.spin()
