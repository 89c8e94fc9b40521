#!/usr/bin/python3
"""Grades a controller as a rostest: publishes the trigger once the
controller and the grader listen, and passes when the grader's verdict on
the drawing is the one expected (`~expect`: pass by default), failing with
the grader's one-line reason otherwise."""
import json
import unittest

import rospy
import rostest
from std_msgs.msg import String

from support.nodes import subscribed, wait_for_connections, wait_until

GRADER = '/grader'


class Grade(unittest.TestCase):
    def test_the_drawing_gets_the_verdict_expected(self):
        rospy.init_node('grade_test')
        expect = rospy.get_param('~expect', 'pass')
        reports = []
        rospy.Subscriber(GRADER + '/report', String,
                         lambda msg: reports.append(json.loads(msg.data)), queue_size=10)
        chatter = rospy.Publisher('/chatter', String, queue_size=1, latch=True)
        wait_for_connections(chatter, 60, "the controller's subscription to /chatter")
        wait_until(lambda: subscribed(GRADER, '/turtle1/pose'), 60, "the grader's pose subscription")
        rospy.sleep(0.5)        # the grader sees the turtle stand before it moves
        chatter.publish(String('P'))
        wait_until(lambda: reports, 240, "the grader's report on the drawing")
        report = reports[0]
        if report['verdict'] != expect:
            self.fail(f"the grader says {report['verdict'].upper()} (expected {expect}): "
                      f"{report['reason']}")
        if expect == 'pass':
            self.assertLessEqual(report['worst_vertex_mm'], report['tolerance_mm'])
        else:
            self.assertTrue(report['reason'])


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'grade', Grade)
