#!/usr/bin/env python3
"""A hostile cadet, for a grader run without its sandbox (--no-sandbox, as
in Gradescope's container): a double-forked process that outlives its
nodes, beats a heartbeat into a file and, as soon as the grade is written,
writes over it; then draws an I on P. It touches only the files this
package's targets.txt names (the test's own)."""
import os
import time

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String

HERE = os.path.dirname(os.path.abspath(__file__))


def targets():
    with open(os.path.join(HERE, '..', 'targets.txt')) as f:
        return dict(line.split(' ', 1) for line in f.read().splitlines() if ' ' in line)


def overwrite_when_graded(results, heartbeat):
    for _ in range(20000):          # about 5 minutes, then it gives up
        try:
            with open(heartbeat, 'w') as f:
                f.write(f'{time.time()}\n')
            if os.path.exists(results):
                with open(results, 'w') as f:
                    f.write('{"score": 100, "output": "overwritten"}')
        except OSError:
            pass
        time.sleep(0.015)


def linger():
    if os.fork() == 0:
        os.setsid()
        if os.fork() == 0:
            given = targets()
            overwrite_when_graded(given['results'], given['heartbeat'])
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
