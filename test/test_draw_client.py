#!/usr/bin/python3
"""draw.py as people and scripts use it: in a terminal a progress bar, and
Ctrl-C cancels the drawing (the turtle stops) before it exits, or, as it
starts, leaves quietly; through a pipe one line per 10 %; a refused
drawing or a missing server in one line, with its exit status."""
import glob
import re
import time
import unittest

import rospy
import rostest
from turtlesim.msg import Pose

from support.nodes import PoseRecorder, wait_until
from support.terminal import Terminal

STOPPED_WITHIN = 1.0    # s after Ctrl-C: the client's cancel, then one tick


class DrawClient(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('draw_client_test')
        cls.poses = PoseRecorder()
        rospy.wait_for_message('/turtle1/pose', Pose, timeout=30)

    def run_in_terminal(self, command):
        term = Terminal(f'{command}; echo "DRAW" "EXITED $?"', cwd=True)
        self.addCleanup(term.close)
        return term

    def exit_status(self, term, timeout):
        self.assertTrue(term.wait_for('DRAW EXITED', timeout), term.screen())
        return int(re.search(r'DRAW EXITED (\d+)', term.screen()).group(1))

    def test_a_progress_bar_and_ctrl_c_cancels_the_drawing(self):
        t0 = time.time()
        term = self.run_in_terminal('rosrun turtle_letters draw.py N')
        wait_until(lambda: len([p for p in self.poses.since(t0) if p.linear_velocity]) > 30, 60,
                   'the turtle to be moving along a line', term.screen)
        self.assertRegex(term.screen(), r'N: +\d+%\|.*\| \[00:\d\d, stroke 0/1, about \d+ s to go\]')
        term.send_keys('C-c')
        pressed = time.time()
        self.assertEqual(self.exit_status(term, 20), 130)
        self.assertIn("draw.py: cancelled: Drawing of 'N' cancelled during move", term.screen())
        self.assertNotIn('Traceback', term.screen())
        time.sleep(1.0)
        after = [p for t, p in self.poses.poses if t > pressed + STOPPED_WITHIN]
        self.assertEqual({(p.x, p.y, p.linear_velocity, p.angular_velocity) for p in after},
                         {(after[0].x, after[0].y, 0.0, 0.0)})

    def test_ctrl_c_as_it_starts_or_looks_for_its_server_leaves_in_a_line(self):
        """Early (its imports) or later (it waits 5 s for a server that is
        not there): exit 130, never a traceback, and nothing sent. Timed from
        when Python runs it: sooner, rosrun's own shell script is interrupted,
        as bash is; and within Python's own start (its site module), which
        no program can reach, Python fails with exit 1 (pressed 1.0 s after
        the command, on a loaded machine twice as slow as most)."""
        for after in (0.5, 2.5):
            term = self.run_in_terminal('rosrun turtle_letters draw.py --ns nobody N')
            wait_until(lambda: python_runs('draw.py --ns nobody N'), 20,
                       'python3 to run draw.py', term.screen)
            time.sleep(after)
            term.send_keys('C-c')
            self.assertEqual(self.exit_status(term, 20), 130, term.screen())
            self.assertNotIn('Traceback', term.screen())
            self.assertNotIn('no action server', term.screen())

    def test_through_a_pipe_a_line_per_ten_percent_and_the_result(self):
        term = self.run_in_terminal('rosrun turtle_letters draw.py L | tee out; '
                                    '(exit ${PIPESTATUS[0]})')
        self.assertEqual(self.exit_status(term, 150), 0)
        lines = term.read('out').splitlines()
        self.assertRegex(lines[0], r'^L: 0%, stroke 0/1, about \d+ s to go$')
        self.assertRegex(lines[-2], r'^L: 100%, stroke 1/1, about \d+ s to go$')
        self.assertRegex(lines[-1], r"^Done drawing 'L'; .* \(\d+\.\d s, ink \d+\.\d\d m, travel ")

    def test_a_refused_drawing_and_a_missing_server_in_one_line(self):
        term = self.run_in_terminal('rosrun turtle_letters draw.py "N\u00e9"')
        self.assertEqual(self.exit_status(term, 30), 1)
        self.assertIn("font builtin has no glyph for ['\u00c9']", term.screen())
        term = self.run_in_terminal('rosrun turtle_letters draw.py --ns nobody N')
        self.assertEqual(self.exit_status(term, 30), 2)
        self.assertIn('draw.py: no action server /nobody/draw answered within 5 s', term.screen())


def python_runs(command):
    """Whether a /usr/bin/python3 process runs a command line holding `command`."""
    for cmdline in glob.glob('/proc/[0-9]*/cmdline'):
        try:
            with open(cmdline, 'rb') as f:
                args = f.read().split(b'\0')
        except OSError:     # it ended as we looked
            continue
        if args[0].endswith(b'python3') and command.encode() in b' '.join(args):
            return True
    return False


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'draw_client', DrawClient)
