#!/usr/bin/python3
"""The lab through its launch file: P (from the real `rostopic pub` command)
draws the N; a trigger during a drawing changes nothing; the next trigger
draws the next N at the next place."""
import math
import subprocess
import threading
import time
import unittest

import rospy
import rostest
from rosgraph_msgs.msg import Log
from turtlesim.msg import Pose

from turtle_letters.geometry import LAB_N, touches_a_wall, vertex_errors, worst_distance_from
TOLERANCE = 0.05        # m: path and vertices
HEADING_TOLERANCE = 0.05
PUBLISH_P = ['rostopic', 'pub', '-1', '/chatter', 'std_msgs/String', "data: 'P'"]


class Recorder:
    def __init__(self):
        self.lock = threading.Lock()
        self.poses = []
        self.logs = []
        rospy.Subscriber('/turtle1/pose', Pose, self.on_pose, queue_size=1000)
        rospy.Subscriber('/rosout', Log, lambda m: self.logs.append(m.msg), queue_size=1000)

    def on_pose(self, msg):
        with self.lock:
            self.poses.append((time.time(), msg))

    def since(self, t0):
        with self.lock:
            return [m for t, m in self.poses if t >= t0]

    def wait_until_still(self, t0, timeout, still_for=2.0):
        """Wait for motion after t0, then for `still_for` s without any."""
        deadline = time.time() + timeout
        moved_at = None
        while time.time() < deadline:
            moving = [t for t, m in self.poses[-200:]
                      if t >= t0 and (m.linear_velocity or m.angular_velocity)]
            if moving:
                moved_at = moving[-1]
            if moved_at and time.time() - moved_at > still_for:
                return True
            time.sleep(0.1)
        return False


class DrawLetter(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('draw_letter_test')
        cls.rec = Recorder()
        rospy.wait_for_message('/turtle1/pose', Pose, timeout=30)
        rospy.wait_for_service('/clear', timeout=30)

    def draw_and_record(self, timeout, extra_trigger_after=None):
        t0 = time.time()
        subprocess.run(PUBLISH_P, check=True, timeout=30)
        if extra_trigger_after is not None:
            time.sleep(extra_trigger_after)
            subprocess.run(PUBLISH_P, check=True, timeout=30)
        self.assertTrue(self.rec.wait_until_still(t0, timeout), 'the turtle never finished')
        return self.rec.since(t0)

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
        poses = self.draw_and_record(timeout=150, extra_trigger_after=5.0)
        self.check_n(poses, LAB_N)
        self.assertTrue(any('ignored: a drawing is under way' in m for m in self.rec.logs))
        self.assertFalse(any('hit the wall' in m for m in self.rec.logs))

    def test_2_the_next_p_draws_the_next_n_at_the_next_place(self):
        start = self.rec.since(0)[-1]
        poses = self.draw_and_record(timeout=250)
        # next place: no room to the right of the first N, so a new line
        # below, at the left margin (0.5 m), 1.4 letter heights lower
        x0, y0 = 0.5, LAB_N[0][1] - 1.4 * 3.0
        shifted = [(x - LAB_N[0][0] + x0, y - LAB_N[0][1] + y0) for x, y in LAB_N]
        arrived = next(i for i, p in enumerate(poses)
                       if math.hypot(p.x - shifted[0][0], p.y - shifted[0][1]) < TOLERANCE)
        self.assertGreater(math.hypot(start.x - x0, start.y - y0), 3.0)
        self.check_n(poses[arrived:], shifted)
        self.assertFalse(any('hit the wall' in m for m in self.rec.logs))


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'draw_letter', DrawLetter)
