#!/usr/bin/python3
"""Typing mode end to end: roslaunch in a terminal, two keys typed faster
than the turtle draws; both letters come out, in order, where they belong.
Then, while a letter is drawn, 32 keys at once (as many as may wait): every
one is drawn, in order."""
import unittest

import rospy
import rostest
from turtlesim.msg import Pose as PoseMsg

from support.accuracy import touches_a_wall, vertex_errors
from support.nodes import LogWatch, PoseRecorder, wait_until
from support.terminal import Terminal
from turtle_letters.letters.font import BUILTIN
from turtle_letters.letters.layout import Layout
from turtle_letters.letters.plan import glyph_strokes

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
        poses = PoseRecorder()
        poses.wait_connected()

        term.send_keys('h', 'i')          # the second key arrives mid-drawing
        places, _ = Layout((first.x, first.y), SIZE).reserve('HI')
        h = [v for s in glyph_strokes(BUILTIN.glyph('H'), places[0], SIZE) for v in s]
        i = [v for s in glyph_strokes(BUILTIN.glyph('I'), places[1], SIZE) for v in s]
        wait_until(lambda: max(vertex_errors(poses.path() or [(0, 0)], i)) < 0.002, 200,
                   'every vertex of the I', term.screen)
        path = poses.path()
        self.assertLess(max(vertex_errors(path, h)), 0.002, 'H not drawn:\n' + term.screen())
        self.assertLess(max(vertex_errors(path, i)), 0.002, 'I not drawn:\n' + term.screen())
        # in order: every vertex of H is reached before the first of I
        def first_visit(v):
            return next(k for k, q in enumerate(path) if max(vertex_errors([q], [v])) < 0.002)
        self.assertLess(max(first_visit(v) for v in h), min(first_visit(v) for v in i))
        self.assertFalse(touches_a_wall(path))
        term.send_keys('C-c')
        self.assertTrue(term.wait_for('done', 30), term.screen())

    def test_32_keys_typed_at_once_all_wait_their_turn(self):
        rospy.init_node('typing_terminal_test')
        logs = LogWatch()
        term = Terminal(BURST_LAUNCH)
        self.addCleanup(term.close)
        self.assertTrue(term.wait_for('talker: press a letter or digit', 60), term.screen())
        rospy.wait_for_message('/turtle1/pose', PoseMsg, timeout=30)
        controller = '/turtlebot_controller'
        term.send_keys('9')               # the turtle is busy, and the talker connected
        logs.wait_for("Drawing '9'", 60, controller, term.screen)
        term.send_keys(BURST.lower())     # one write: the talker reads them all at once

        def drawn():
            return [m.msg.split("'")[1] for m in logs.messages
                    if m.name == controller and m.msg.startswith("Done drawing '")]
        wait_until(lambda: len(drawn()) == 1 + len(BURST) or logs.count('ignored', controller),
                   280, 'every key drawn', term.screen)
        self.assertEqual(logs.count('ignored', controller), 0, term.screen())
        self.assertEqual(''.join(drawn()), '9' + BURST)
        term.send_keys('C-c')
        self.assertTrue(term.wait_for('done', 30), term.screen())


BURST = 'ABCDEFGHIJKLMNOPQRSTUVWXYZ012345'     # 32, jobs.TYPED_AHEAD, typed while one is drawn
BURST_LAUNCH = ('roslaunch turtle_letters draw_letter.launch headless:=true typing:=true '
                'mode:=smooth linear_speed:=4.0 size:=0.5')


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'typing_terminal', TypingInATerminal)
