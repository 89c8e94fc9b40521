#!/usr/bin/python3
"""A word with parallel:=true: turtle1 draws the first letter and a spare
turtle spawned at each other letter's place draws that one, all at once.
Each letter's path is checked as a single letter's; the spare turtles are
gone afterwards; the word takes about as long as its slowest letter."""
import re
import time
import unittest

import rosgraph
import rospy
import rostest
from std_msgs.msg import String
from turtlesim.msg import Pose

from support.accuracy import expected, vertex_errors, worst_off
from support.nodes import LogWatch, PoseRecorder, wait_until
from turtle_letters.letters.layout import Layout
from turtle_letters.letters.geometry import PlannedPose
from turtle_letters.letters.primitives import Turn, plan_strokes

TOLERANCE = 0.05            # m: a single letter's, as test_draw_letter's
LINEAR_SPEED = 1.0          # m/s, the default


def seconds(primitives, angular_speed):
    """How long timed primitives take, by the plan."""
    return sum(abs(p.angle) / angular_speed if isinstance(p, Turn) else p.length / LINEAR_SPEED
               for p in primitives if hasattr(p, 'angle') or hasattr(p, 'length'))


class ParallelWord(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('parallel_word_test')
        cls.text = rospy.get_param('~text')
        cls.size = rospy.get_param('~size')
        cls.angular_speed = rospy.get_param('~angular_speed')
        cls.turtles = ['turtle1'] + [f'turtle1__{i}' for i in range(2, len(cls.text) + 1)]
        first = rospy.wait_for_message('/turtle1/pose', Pose, timeout=30)
        cls.recorders = [PoseRecorder(turtle=t) for t in cls.turtles]
        cls.recorders[0].wait_connected()
        logs = LogWatch()
        start = PlannedPose(first.x, first.y, first.theta)
        cls.places, _ = Layout((start.x, start.y), cls.size).reserve(cls.text)
        cls.starts = [start] + [PlannedPose(x, y, 0.0) for x, y in cls.places[1:]]
        text = rospy.Publisher('/turtlebot_controller/text', String, queue_size=1, latch=True)
        t0 = time.time()
        text.publish(String(cls.text))
        wait_until(lambda: logs.count('Done drawing') or logs.count('stopped'), 240,
                   'the word to be drawn')
        cls.seconds = time.time() - t0
        cls.logs, cls.t0 = logs, t0

    def test_each_letter_is_drawn_as_a_single_letter_is(self):
        self.assertEqual(self.logs.count('stopped'), 0)
        for char, place, start, recorder in zip(self.text, self.places, self.starts,
                                                self.recorders):
            with self.subTest(char=char):
                strokes, travel = expected(char, [place], start, self.size)
                path = recorder.path()
                self.assertTrue(path, 'no pose of the turtle drawing it')
                errors = vertex_errors(path, [v for stroke in strokes for v in stroke])
                self.assertLess(max(errors), TOLERANCE, f'vertices {errors}')
                self.assertLess(worst_off(path, strokes, travel), TOLERANCE)

    def test_the_spare_turtles_are_killed_when_done(self):
        def spares():
            topics = rosgraph.Master('/parallel_word_test').getPublishedTopics('')
            return [t for t, _ in topics if t.startswith('/turtle1__')]
        wait_until(lambda: not spares(), 10, 'the spare turtles to be killed', spares)

    def slowest(self):
        """The slowest letter's seconds, by the plan."""
        return max(seconds(plan_strokes(expected(c, [p], s, self.size)[0], s)[0],
                           self.angular_speed)
                   for c, p, s in zip(self.text, self.places, self.starts))

    def test_its_progress_is_told_with_the_time_its_slowest_letter_takes(self):
        told = [m for m in self.logs.messages if '% of the ink drawn' in m.msg]
        self.assertTrue(told, 'no progress told while the word was drawn')
        first = told[0]
        to_go = float(re.search(r'about (\d+) s to go', first.msg).group(1))
        ends_at = first.header.stamp.to_sec() - self.t0 + to_go
        self.assertLess(ends_at, 1.5 * self.slowest() + 5.0, first.msg)

    def test_the_word_takes_about_as_long_as_its_slowest_letter(self):
        slowest = self.slowest()
        print(f'\n{self.text!r} in parallel: {self.seconds:.1f} s; its slowest letter by the '
              f'plan: {slowest:.1f} s', flush=True)
        # Loose: the 1.2 x target is the benchmark's, on an idle machine.
        self.assertLess(self.seconds, 2.0 * slowest + 5.0)


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'parallel_word', ParallelWord)
