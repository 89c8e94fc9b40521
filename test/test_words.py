#!/usr/bin/python3
"""A word from the controller's ~text topic, drawn to the millimetre in a
closed-loop mode (feedback or smooth), in any font: the path on the strokes
and the pen-up travel moves (in smooth mode, off them only where a late
command ran on), every vertex reached, the ink in the pen's
colour and none on the travel moves. Configured by the <test>'s parameters:
~text, ~size, ~pen, and ~font, ~turn_direction as given to the launch file."""
import math
import unittest

import rospy
import rostest
from PyQt5.QtGui import QImage
from std_msgs.msg import String
from std_srvs.srv import Trigger
from turtlesim.msg import Pose as PoseMsg

from support.accuracy import (distance_to_polyline, distances_off, expected, strays,
                              touches_a_wall, vertex_errors)
from support.nodes import LogWatch, PoseRecorder, wait_until
from support.pictures import pixel
from turtle_letters.letters.hershey import load_font
from turtle_letters.letters.layout import Layout
from turtle_letters.letters.geometry import PlannedPose

VERTEX_TOLERANCE = 0.002      # m (the 1 mm target is the benchmark's)
BACKGROUND = (69, 86, 255)


class Words(unittest.TestCase):
    """One word drawn once (in setUpClass); each test checks one thing of it."""

    @classmethod
    def setUpClass(cls):
        rospy.init_node('words_test')
        text = rospy.get_param('~text')
        size = rospy.get_param('~size')
        font = load_font(rospy.get_param('~font', 'builtin'))
        direction = rospy.get_param('~turn_direction', 'shortest')
        cls.pen = tuple(int(c) for c in rospy.get_param('~pen').split()[:3])
        logs = LogWatch()
        first = rospy.wait_for_message('/turtle1/pose', PoseMsg, timeout=30)
        poses = PoseRecorder()
        poses.wait_connected()
        pub = rospy.Publisher('/turtlebot_controller/text', String, queue_size=1, latch=True)
        pub.publish(String(text))

        start = PlannedPose(first.x, first.y, first.theta)
        places, _ = Layout((start.x, start.y), size, font).reserve(text)
        cls.strokes, cls.travel = expected(text, places, start, size, font, direction)

        def done():
            if logs.count('Refused', '/turtlebot_controller'):
                raise AssertionError(f'the controller refused {text!r}')
            return logs.count('Done drawing', '/turtlebot_controller')
        wait_until(done, 250, "the controller's Done line")
        poses.wait_until_still(0, 10, still_for=0.5)
        cls.poses_drawn = poses.since(0)
        cls.path = [(p.x, p.y) for p in cls.poses_drawn]

    def test_every_vertex_is_reached(self):
        vertices = [v for stroke in self.strokes for v in stroke]
        errors = vertex_errors(self.path, vertices)
        missed = [(v, round(e * 1000, 2)) for v, e in zip(vertices, errors) if e >= VERTEX_TOLERANCE]
        self.assertEqual(missed, [], 'vertices missed (m) by mm')

    def test_the_path_keeps_to_the_strokes_and_travel_moves(self):
        if rospy.get_param('/turtlebot_controller/mode') == 'smooth':
            # A command that comes late (a busy machine) makes turtlesim use
            # the one before once more: the turtle runs on along its move,
            # past a vertex or off a curve, and comes back to the strokes
            # (motion.SmoothExecutor, the README). How often and how far is
            # the load's doing; that each stray begins so is the controller's,
            # and so is a stray at every vertex.
            found = strays(self.poses_drawn, self.strokes + self.travel, VERTEX_TOLERANCE)
            own = [(round(p.x, 3), round(p.y, 3), round(worst * 1000, 2))
                   for p, worst, late in found if not late]
            self.assertEqual(own, [], 'strays (m, worst mm off) begun by a new command')
            vertices = sum(len(stroke) for stroke in self.strokes)
            self.assertLess(len(found), vertices / 4, f'{len(found)} strays, {vertices} vertices')
        else:
            worst = max(distances_off(self.path, self.strokes, self.travel))
            self.assertLess(worst, VERTEX_TOLERANCE, f'{worst * 1000:.2f} mm off the strokes')
        self.assertFalse(touches_a_wall(self.path))
        self.assertGreater(len(self.travel), 2, 'the word should need pen-up travel')

    def test_the_picture_has_ink_in_the_pen_colour_and_none_on_travel(self):
        try:
            rospy.wait_for_service('/turtlesim/save_canvas', timeout=5)
        except rospy.ROSException:
            self.skipTest('the real turtlesim cannot save its canvas')
        saved = rospy.ServiceProxy('/turtlesim/save_canvas', Trigger)()
        self.assertTrue(saved.success, saved.message)
        image = QImage(saved.message)
        turtle = self.path[-1]          # its icon covers the ink under it
        for a, b in self.travel:
            for i in range(1, 20):
                q = (a[0] + (b[0] - a[0]) * i / 20, a[1] + (b[1] - a[1]) * i / 20)
                if min(distance_to_polyline(q, s) for s in self.strokes) > 0.15:
                    self.assertEqual(pixel(image, *q), BACKGROUND, f'pen-up line at {q}')
        for stroke in self.strokes:
            for a, b in zip(stroke, stroke[1:]):
                mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
                if math.hypot(mid[0] - turtle[0], mid[1] - turtle[1]) < 0.5:
                    continue
                self.assertEqual(pixel(image, *mid), self.pen, f'no stroke in the pen colour at {mid}')


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'words', Words)
