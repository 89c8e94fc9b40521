#!/usr/bin/python3
"""Typing mode end to end: roslaunch in a terminal, two keys typed faster
than the turtle draws; both letters come out, in order, where they belong."""
import threading
import time
import unittest

import rospy
import rostest
from turtlesim.msg import Pose as PoseMsg

from terminal import Terminal
from turtle_letters.geometry import touches_a_wall, vertex_errors
from turtle_letters.plan import Layout, glyph_for, glyph_strokes

SIZE = 1.5
LAUNCH = ('roslaunch turtle_letters draw_letter.launch headless:=true typing:=true '
          f'mode:=feedback turn_direction:=shortest linear_speed:=2.0 angular_speed:=2.0 '
          f'size:={SIZE}')


class TypingInATerminal(unittest.TestCase):
    def test_typed_keys_are_drawn_in_order(self):
        rospy.init_node('typing_terminal_test')
        term = Terminal(LAUNCH)
        self.addCleanup(term.close)
        self.assertTrue(term.wait_for('talker: press a letter or digit', 60), term.screen())
        first = rospy.wait_for_message('/turtle1/pose', PoseMsg, timeout=30)
        poses, lock = [], threading.Lock()

        def on_pose(msg):
            with lock:
                poses.append(msg)
        rospy.Subscriber('/turtle1/pose', PoseMsg, on_pose, queue_size=1000)
        time.sleep(1.0)

        term.send_keys('h', 'i')          # the second key arrives mid-drawing
        places, _ = Layout((first.x, first.y), SIZE).reserve('HI')
        h = [v for s in glyph_strokes(glyph_for('H'), places[0], SIZE) for v in s]
        i = [v for s in glyph_strokes(glyph_for('I'), places[1], SIZE) for v in s]
        end = glyph_strokes(glyph_for('I'), places[1], SIZE)[-1][-1]
        deadline = time.time() + 200
        while time.time() < deadline:
            with lock:
                path = [(p.x, p.y) for p in poses]
            if path and max(vertex_errors(path, [end])) < 0.002:
                break
            time.sleep(0.2)
        self.assertLess(max(vertex_errors(path, h)), 0.002, 'H not drawn:\n' + term.screen())
        self.assertLess(max(vertex_errors(path, i)), 0.002, 'I not drawn:\n' + term.screen())
        # in order: every vertex of H is reached before the first of I
        def first_visit(v):
            return next(k for k, q in enumerate(path) if max(vertex_errors([q], [v])) < 0.002)
        self.assertLess(max(first_visit(v) for v in h), min(first_visit(v) for v in i))
        self.assertFalse(touches_a_wall(path))
        term.send_keys('C-c')
        self.assertTrue(term.wait_for('done', 30), term.screen())


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'typing_terminal', TypingInATerminal)
