#!/usr/bin/python3
"""The lab through its launch file: P (from the real `rostopic pub` command)
draws the N; a trigger during a drawing changes nothing; the next trigger
draws the next N at the next place."""
import math
import subprocess
import time
import unittest

import rospy
import rostest
from turtlesim.msg import Pose

from support.accuracy import LAB_N_VERTICES, touches_a_wall, vertex_errors, worst_distance_from
from support.nodes import LogWatch, PoseRecorder, wait_until

TOLERANCE = 0.05        # m: path and vertices
HEADING_TOLERANCE = 0.05
PUBLISH_P = ['rostopic', 'pub', '-1', '/chatter', 'std_msgs/String', "data: 'P'"]


class DrawLetter(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('draw_letter_test')
        cls.poses = PoseRecorder()
        cls.logs = LogWatch()
        rospy.wait_for_message('/turtle1/pose', Pose, timeout=30)
        rospy.wait_for_service('/clear', timeout=30)

    def draw_and_record(self, timeout, trigger_again_mid_drawing=False):
        t0 = time.time()
        subprocess.run(PUBLISH_P, check=True, timeout=30)
        if trigger_again_mid_drawing:
            wait_until(lambda: self.poses.moving_since(t0), 30, 'the drawing to start')
            subprocess.run(PUBLISH_P, check=True, timeout=30)
        self.poses.wait_until_still(t0, timeout, still_for=2.0)
        return self.poses.since(t0)

    def check_n(self, poses, vertices, strokes_from=0):
        path = [(p.x, p.y) for p in poses]
        self.assertFalse(touches_a_wall(path))
        errors = vertex_errors(path, vertices)
        self.assertLess(max(errors), TOLERANCE, f'vertex errors {errors}')
        drawn = path[strokes_from:]
        self.assertLess(worst_distance_from(drawn, vertices), TOLERANCE)
        end = poses[-1]
        self.assertLess(math.hypot(end.x - vertices[-1][0], end.y - vertices[-1][1]), TOLERANCE)
        self.assertLess(abs(math.remainder(end.theta - math.pi / 2, 2 * math.pi)),
                        HEADING_TOLERANCE)

    def test_1_p_draws_the_labs_n_and_a_second_p_meanwhile_changes_nothing(self):
        poses = self.draw_and_record(timeout=150, trigger_again_mid_drawing=True)
        self.check_n(poses, LAB_N_VERTICES)
        self.assertEqual(self.logs.count('ignored: a drawing is waiting or under way'), 1)
        self.assertEqual(self.logs.count("Drawing 'N'"), 1)
        self.assertEqual(self.logs.count('hit the wall'), 0)

    def test_2_the_next_p_draws_the_next_n_at_the_next_place(self):
        start = self.poses.last()
        poses = self.draw_and_record(timeout=250)
        # next place: no room to the right of the first N, so a new line
        # below, at the left margin (0.5 m), 1.4 letter heights lower
        x0, y0 = 0.5, LAB_N_VERTICES[0][1] - 1.4 * 3.0
        shifted = [(x - LAB_N_VERTICES[0][0] + x0, y - LAB_N_VERTICES[0][1] + y0) for x, y in LAB_N_VERTICES]
        arrived = next(i for i, p in enumerate(poses)
                       if math.hypot(p.x - shifted[0][0], p.y - shifted[0][1]) < TOLERANCE)
        self.assertGreater(math.hypot(start.x - x0, start.y - y0), 3.0)
        self.check_n(poses[arrived:], shifted)
        self.assertEqual(self.logs.count('hit the wall'), 0)


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'draw_letter', DrawLetter)
