#!/usr/bin/python3
"""The talker in a real terminal: the trigger key publishes the trigger once,
other keys and escape sequences (arrows, function keys, Alt+key, Esc) nothing,
and Ctrl-C gives the terminal back as it was."""
import threading
import time
import unittest

import rospy
import rostest
from std_msgs.msg import String

from support.nodes import wait_until
from support.terminal import Terminal

# tmux key names; tmux sends each as the real terminal's escape sequence
# (F1 is ESC O P, Up is ESC [ A, M-p is ESC p).
ESCAPE_KEYS = ('F1', 'F2', 'F3', 'F4', 'F5', 'F12', 'Up', 'Down', 'Left', 'Right', 'Home',
               'End', 'PageUp', 'Delete', 'Insert', 'M-p', 'M-P', 'M-a', 'C-Up', 'S-F1')


class TalkerInATerminal(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('talker_terminal_test')
        cls.heard = []
        cls.lock = threading.Lock()
        cls.subscriber = rospy.Subscriber('/chatter', String, cls.on_chatter, queue_size=100)

    @classmethod
    def on_chatter(cls, msg):
        with cls.lock:
            cls.heard.append(msg.data)

    def start_talker(self, *params, prompt):
        if rospy.has_param('/talker'):
            rospy.delete_param('/talker')      # another test's private parameters
        # The shell records the terminal settings itself, just before and just
        # after the talker (at its prompt, bash's line editor has its own).
        self.term = Terminal(f'stty -g > before; rosrun turtle_letters talker.py {" ".join(params)}; '
                             'stty -g > after; echo "TALKER" "EXITED $?"', cwd=True)
        self.addCleanup(self.term.close)
        self.assertTrue(self.term.wait_for(prompt, 30), self.term.screen())
        self.assertIn('-icanon', self.term.flags())        # cbreak: no Enter needed
        wait_until(lambda: self.subscriber.get_num_connections(), 20, 'the talker on /chatter',
                   self.term.screen)
        with self.lock:
            self.heard.clear()

    def heard_after(self, count, timeout=10.0):
        """What was heard once `count` messages came, or after `timeout` s (the
        callers assert on it, so a shortfall is said with what did come)."""
        try:
            wait_until(lambda: len(self.heard) >= count, timeout, f'{count} messages')
        except AssertionError:
            pass
        return list(self.heard)

    def quit_and_check_terminal(self):
        self.term.send_keys('C-c')
        self.assertTrue(self.term.wait_for('TALKER EXITED', 20), self.term.screen())
        self.assertEqual(self.term.read('after'), self.term.read('before'))
        self.assertNotIn('Traceback', self.term.screen())

    def test_p_publishes_p_once_other_keys_nothing(self):
        self.start_talker(prompt='talker: press P')
        self.term.send_keys('p')
        self.assertEqual(self.heard_after(1), ['P'])
        for key in ('x', 'q', '1', 'Space', 'Enter', 'Tab'):
            self.term.send_keys(key)
        self.term.send_keys('P')
        self.assertEqual(self.heard_after(2), ['P', 'P'])
        time.sleep(0.5)         # keys arrive in order: nothing may follow the last P
        self.assertEqual(self.heard, ['P', 'P'], 'a key other than P published something')
        self.quit_and_check_terminal()

    def test_escape_sequences_publish_nothing_in_the_lab(self):
        self.start_talker(prompt='talker: press P')
        for key in ESCAPE_KEYS:
            self.term.send_keys(key)
        self.term.send_keys('Escape')
        time.sleep(0.3)          # a bare Esc: nothing follows it at once
        self.term.send_keys('p')
        self.assertEqual(self.heard_after(1), ['P'])
        time.sleep(0.5)
        self.assertEqual(self.heard, ['P'], 'an escape sequence published something')
        self.quit_and_check_terminal()

    def test_escape_sequences_publish_nothing_in_typing_mode(self):
        self.start_talker('_typing:=true', prompt='talker: press a letter')
        for key in ESCAPE_KEYS:
            self.term.send_keys(key)
        self.term.send_keys('Escape')
        time.sleep(0.3)
        self.term.send_keys('h', 'i')
        self.assertEqual(self.heard_after(2), ['H', 'I'])
        time.sleep(0.5)
        self.assertEqual(self.heard, ['H', 'I'], 'an escape sequence published something')
        self.quit_and_check_terminal()

    def test_the_trigger_key_follows_the_trigger(self):
        self.start_talker('_trigger:=Q', prompt='talker: press Q')
        self.term.send_keys('p', 'q', 'Q')
        self.assertEqual(self.heard_after(2), ['Q', 'Q'])
        time.sleep(0.5)
        self.assertEqual(self.heard, ['Q', 'Q'])
        self.quit_and_check_terminal()

    def test_a_longer_trigger_is_sent_by_enter(self):
        self.start_talker('_trigger:=GO', prompt="talker: press Enter to send 'GO'")
        self.term.send_keys('g', 'o', 'Enter')
        self.assertEqual(self.heard_after(1), ['GO'])
        time.sleep(0.5)
        self.assertEqual(self.heard, ['GO'])
        self.quit_and_check_terminal()


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'talker_terminal', TalkerInATerminal)
