#!/usr/bin/python3
"""A classroom on one machine: ten controllers, each in a namespace of its
own and driving a turtle it spawned, all triggered at once (as ten
students' machines would, see test/network for real ones). Each letter is
checked like a single letter; no part of the canvas crosses another, and
no turtle leaves its own."""
import json
import os
import unittest

import rospy
import rostest
from std_msgs.msg import String

from support.accuracy import expected, vertex_errors, worst_off
from support.nodes import (LogWatch, NodeProcess, PoseRecorder, subscribed, wait_for_connections,
                           wait_until)
from turtle_letters.letters.font import BUILTIN
from turtle_letters.classroom.parts import overlaps
from turtle_letters.letters.geometry import PlannedPose

LETTERS = 'NAK7EZMWX4'
SIZE = 1.0
TOLERANCE = 0.05            # m: a single letter's, as test_draw_letter's
# The lab's timed mode, turning faster so that the class takes seconds.
SETTINGS = ('_mode:=timed', '_angular_speed:=1.0', f'_size:={SIZE}')


class Classroom(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('classroom_test')
        rospy.wait_for_service('/spawn', 30)
        cls.logs = LogWatch()
        cls.tables = []
        rospy.Subscriber('/scoreboard', String, lambda m: cls.tables.append(m.data), queue_size=50)
        cls.names = [f'student{i}' for i in range(len(LETTERS))]
        cls.recorders = {n: PoseRecorder(turtle=n) for n in cls.names}
        cls.controllers = [NodeProcess('turtle_letters', 'turtle_controller.py', f'__ns:={n}',
                                       f'_turtle:=/{n}', f'_letter:={letter}', *SETTINGS)
                           for n, letter in zip(cls.names, LETTERS)]
        wait_until(lambda: cls.logs.count('Ready:') == len(cls.names), 120,
                   'every controller to be ready', cls.outputs)
        chatters = [rospy.Publisher(f'/{n}/chatter', String, queue_size=1) for n in cls.names]
        for chatter, recorder in zip(chatters, cls.recorders.values()):
            wait_for_connections(chatter)
            recorder.wait_connected()
        for n in cls.names:         # the scoreboard watches each turtle before it moves
            wait_until(lambda n=n: subscribed('/scoreboard', f'/{n}/pose'), 30,
                       f"the scoreboard's subscription to /{n}/pose")
        # A student who drew a picture from their own laptop before: their ~svg
        # names a file on that machine, not this one. The scoreboard still
        # grades their letter (it used to refuse their parameters).
        rospy.set_param(f'/{cls.names[3]}/turtlebot_controller/svg',
                        f'/home/{cls.names[3]}/art/on-my-laptop.svg')
        rospy.sleep(0.5)
        cls.starts = {n: r.last() for n, r in cls.recorders.items()}
        for chatter in chatters:
            chatter.publish(String('P'))
        wait_until(lambda: cls.logs.count('Done drawing') + cls.logs.count('stopped') == 10, 300,
                   'every drawing to end', cls.outputs)
        cls.parts = {n: part['box'] for n, part in rospy.get_param('/turtle_letters/parts').items()}

    @classmethod
    def outputs(cls):
        return '\n'.join(c.output()[-1500:] for c in cls.controllers)

    @classmethod
    def tearDownClass(cls):
        for controller in cls.controllers:
            controller.stop()

    def test_the_scoreboard_grades_every_letter_a_pass(self):
        wait_until(lambda: self.tables and len(self.tables[-1].splitlines()) == 1 + len(LETTERS),
                   60, 'a scoreboard of every student', lambda: (self.tables or ['none'])[-1])
        rows = [line.split() for line in self.tables[-1].splitlines()[1:]]
        self.assertEqual(sorted((row[0], row[1], row[2]) for row in rows),
                         sorted((n, letter, 'PASS') for n, letter in zip(self.names, LETTERS)))
        folder = rospy.get_param('~grades')
        with open(os.path.join(folder, 'scoreboard.json')) as f:
            reports = json.load(f)
        self.assertEqual(len(reports), len(LETTERS))
        self.assertLess(max(r['worst_vertex_mm'] for r in reports.values()), 1.0)
        self.assertGreater(os.path.getsize(os.path.join(folder, 'scoreboard.png')), 10000)

    def test_every_letter_is_drawn_as_a_single_letter_is(self):
        self.assertEqual(self.logs.count('stopped'), 0, self.outputs())
        for name, letter in zip(self.names, LETTERS):
            with self.subTest(turtle=name, letter=letter):
                first = self.starts[name]
                start = PlannedPose(first.x, first.y, first.theta)
                strokes, travel = expected(letter, [(first.x, first.y)], start, SIZE, BUILTIN,
                                           'ccw')
                path = self.recorders[name].path()
                errors = vertex_errors(path, [v for stroke in strokes for v in stroke])
                self.assertLess(max(errors), TOLERANCE, f'vertices {errors}')
                self.assertLess(worst_off(path, strokes, travel), TOLERANCE)

    def test_every_turtle_has_a_part_and_no_two_parts_cross(self):
        self.assertLessEqual(set(self.names), set(self.parts))
        for a in self.names:
            for b in self.names:
                if a < b:
                    with self.subTest(a=a, b=b):
                        self.assertFalse(overlaps(self.parts[a], self.parts[b]),
                                         f'{self.parts[a]} and {self.parts[b]}')

    def test_no_turtle_leaves_its_part(self):
        for name in self.names:
            with self.subTest(turtle=name):
                x0, y0, x1, y1 = self.parts[name]
                outside = [(round(x, 3), round(y, 3)) for x, y in self.recorders[name].path()
                           if not (x0 <= x <= x1 and y0 <= y <= y1)]
                self.assertEqual(outside, [], f'it left its part {self.parts[name]}')


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'classroom', Classroom)
