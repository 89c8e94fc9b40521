#!/usr/bin/python3
"""The talker in a real terminal: a press of P publishes "P" once, other
keys nothing, and Ctrl-C gives the terminal back as it was."""
import threading
import time
import unittest

import rospy
import rostest
from std_msgs.msg import String

from terminal import Terminal

PROMPT = 'talker: press P'


class TalkerInATerminal(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('talker_terminal_test')
        cls.heard = []
        cls.lock = threading.Lock()
        rospy.Subscriber('/chatter', String, cls.on_chatter, queue_size=100)

    @classmethod
    def on_chatter(cls, msg):
        with cls.lock:
            cls.heard.append(msg.data)

    def setUp(self):
        # The shell records the terminal settings itself, just before and just
        # after the talker (at its prompt, bash's line editor has its own).
        self.term = Terminal('stty -g > before; rosrun turtle_letters talker.py; '
                             'stty -g > after; echo "TALKER" "EXITED $?"', cwd=True)
        self.addCleanup(self.term.close)

    def heard_after(self, count, timeout=10.0):
        deadline = time.time() + timeout
        while len(self.heard) < count and time.time() < deadline:
            time.sleep(0.05)
        return list(self.heard)

    def test_keys_and_ctrl_c(self):
        self.assertTrue(self.term.wait_for(PROMPT, 30), self.term.screen())
        self.assertIn('-icanon', self.term.flags())        # cbreak: no Enter needed
        deadline = time.time() + 10
        while rospy.get_published_topics() and time.time() < deadline:
            if any(t == '/chatter' for t, _ in rospy.get_published_topics()):
                break
            time.sleep(0.1)
        time.sleep(1.0)                                      # our subscription connects

        self.term.send_keys('p')
        self.assertEqual(self.heard_after(1), ['P'])
        for key in ('x', 'q', '1', 'Space', 'Enter', 'Escape'):
            self.term.send_keys(key)
        self.term.send_keys('P')
        self.assertEqual(self.heard_after(2), ['P', 'P'])
        time.sleep(1.0)
        self.assertEqual(self.heard, ['P', 'P'], 'a key other than P published something')

        self.term.send_keys('C-c')
        self.assertTrue(self.term.wait_for('TALKER EXITED', 20), self.term.screen())
        self.assertEqual(self.term.read('after'), self.term.read('before'))
        self.assertNotIn('Traceback', self.term.screen())


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'talker_terminal', TalkerInATerminal)
