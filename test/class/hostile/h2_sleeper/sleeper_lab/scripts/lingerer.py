#!/usr/bin/env python3
"""A hostile cadet: leaves two processes behind that mean to outlive the
grading (nohup under setsid, and a double fork that ignores SIGTERM and
SIGHUP), then draws an I on P."""
import os
import signal
import subprocess

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String


def linger():
    subprocess.Popen(['setsid', 'nohup', 'sleep', '987654'], stdout=subprocess.DEVNULL,
                     stderr=subprocess.DEVNULL, start_new_session=True)
    if os.fork() == 0:
        os.setsid()
        if os.fork() == 0:
            signal.signal(signal.SIGTERM, signal.SIG_IGN)
            signal.signal(signal.SIGHUP, signal.SIG_IGN)
            os.execvp('sleep', ['sleep', '987653'])
        os._exit(0)
    os.wait()


def draw_i(pub):
    for linear, angular, seconds in ((0, 1.0, 1.5708), (1.0, 0, 2.0)):
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        end = rospy.get_time() + seconds
        while rospy.get_time() < end:
            pub.publish(twist)
            rospy.sleep(0.02)
    pub.publish(Twist())


linger()
rospy.init_node('lingerer')
cmd = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)
rospy.Subscriber('chatter', String, lambda m: m.data == 'P' and draw_i(cmd))
rospy.spin()
