#!/usr/bin/python3
"""The talker without a terminal: stdin from a pipe, /dev/null, or closed;
it never spins, never crashes, and keeps a press until someone listens."""
import os
import signal
import subprocess
import time
import unittest

import rospy
import rostest
from std_msgs.msg import String

from support.children import readable_env
from support.nodes import LogWatch, NodeProcess, node_pid, wait_until
from turtle_letters.grading.procstat import cpu_seconds
from support.terminal import Terminal

TALKER = '/talker'


class TalkerFaults(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('talker_faults_test')
        cls.logs = LogWatch()

    def setUp(self):
        self.logs.messages.clear()      # each test counts its own talker's lines

    def start_talker(self, stdin, *params):
        talker = NodeProcess('turtle_letters', 'talker.py', *params, stdin=stdin)
        self.addCleanup(talker.stop)
        pid = []

        def up():
            try:
                pid.append(node_pid(TALKER))
                return True
            except Exception:   # not registered yet
                return False
        wait_until(up, 30, 'the talker to come up', talker.output)
        return talker, pid[0]

    def assert_idles_then_ends_cleanly(self, talker, pid, sig):
        cpu0, t0 = cpu_seconds(pid), time.time()
        time.sleep(3.0)
        share = (cpu_seconds(pid) - cpu0) / (time.time() - t0)
        self.assertLess(share, 0.05, f'the idle talker uses {share:.0%} of a core')
        talker.send(sig)
        talker.process.wait(15)
        self.assertNotIn('Traceback', talker.output())

    def test_piped_press_before_any_subscriber_is_kept_then_end_of_input(self):
        read_end, write_end = os.pipe()
        talker, pid = self.start_talker(read_end)
        os.close(read_end)
        os.write(write_end, b'x\nP\n')
        os.close(write_end)                                     # end of input
        self.logs.wait_for('End of input', 15, TALKER, explain=talker.output)
        time.sleep(0.5)
        heard = []
        subscriber = rospy.Subscriber('/chatter', String, lambda m: heard.append(m.data))
        self.addCleanup(subscriber.unregister)      # or it would take the next talkers' presses
        wait_until(lambda: heard, 10, 'the kept press')
        self.assertEqual(heard, ['P'])                         # kept, not lost
        self.assertEqual(self.logs.count('End of input', TALKER), 1)
        self.assert_idles_then_ends_cleanly(talker, pid, signal.SIGTERM)

    def test_presses_made_while_the_first_subscriber_connects_keep_their_order(self):
        read_end, write_end = os.pipe()
        self.addCleanup(rospy.delete_param, TALKER + '/typing')    # the next talker's default
        # a topic of its own: no subscriber of another test can take the kept presses
        talker, _ = self.start_talker(read_end, '_typing:=true', 'chatter:=/in_order/chatter')
        os.close(read_end)
        self.addCleanup(os.close, write_end)
        typed = 'abcdefghijklmnopqrstuvwxyz0123456789' * 2
        os.write(write_end, typed[:10].encode())               # kept: nobody listens yet
        # its own output: a line logged this early may precede the /rosout connection
        wait_until(lambda: "'J' is kept" in talker.output(), 15, 'the tenth press kept',
                   talker.output)
        heard = []
        subscriber = rospy.Subscriber('/in_order/chatter', String,
                                      lambda m: heard.append(m.data), queue_size=100)
        self.addCleanup(subscriber.unregister)
        for char in typed[10:]:                                 # while it connects, and after
            os.write(write_end, char.encode())
            time.sleep(0.005)
        wait_until(lambda: len(heard) >= len(typed), 15, 'every press', talker.output)
        time.sleep(0.5)                                         # a duplicate would come by now
        self.assertEqual(''.join(heard), typed.upper())

    def test_kept_presses_are_bounded(self):
        read_end, write_end = os.pipe()
        talker, pid = self.start_talker(read_end)
        os.close(read_end)
        os.write(write_end, b'P' * 100 + b'\n')
        os.close(write_end)
        self.logs.wait_for('End of input', 15, TALKER, explain=talker.output)
        heard = []
        subscriber = rospy.Subscriber('/chatter', String, lambda m: heard.append(m.data))
        self.addCleanup(subscriber.unregister)
        wait_until(lambda: len(heard) >= 32, 10, '32 kept presses')
        time.sleep(1.0)                 # more than 32 would have come by now
        self.assertEqual(heard, ['P'] * 32)
        # its own output: a line logged this early may precede the /rosout connection
        self.assertEqual(talker.output().count('further presses are dropped'), 1)
        self.assert_idles_then_ends_cleanly(talker, pid, signal.SIGTERM)

    def test_a_line_without_end_is_read_as_it_comes(self):
        heard = []
        subscriber = rospy.Subscriber('/chatter', String, lambda m: heard.append(m.data))
        self.addCleanup(subscriber.unregister)
        read_end, write_end = os.pipe()
        talker, pid = self.start_talker(read_end)
        os.close(read_end)
        self.addCleanup(os.close, write_end)
        wait_until(lambda: subscriber.get_num_connections(), 20, 'the talker on /chatter')
        for _ in range(16):             # 1 MiB with no newline, then a press
            os.write(write_end, b'x' * 65536)
        os.write(write_end, b'P')
        wait_until(lambda: heard, 15, 'a press after a long unfinished line')
        self.assertEqual(heard, ['P'])
        self.assertTrue(talker.alive())

    def test_dev_null(self):
        talker, pid = self.start_talker(subprocess.DEVNULL)
        self.logs.wait_for('End of input', 15, TALKER, explain=talker.output)
        self.assert_idles_then_ends_cleanly(talker, pid, signal.SIGINT)

    def test_stdin_closed(self):
        talker = NodeProcess('turtle_letters', 'talker.py', stdin=None)
        self.addCleanup(talker.stop)
        # A closed fd 0 cannot be passed to Popen: close it in the shell.
        talker.stop(signal.SIGKILL)
        talker.process = subprocess.Popen(
            ['bash', '-c', 'exec rosrun turtle_letters talker.py <&-'],
            stdout=open(talker.out_path, 'w'), stderr=subprocess.STDOUT, env=readable_env())
        self.logs.wait_for('No standard input', 15, TALKER, explain=talker.output)
        self.assert_idles_then_ends_cleanly(talker, node_pid(TALKER), signal.SIGTERM)

    def test_sigterm_in_a_terminal_restores_it(self):
        term = Terminal('stty -g > before; rosrun turtle_letters talker.py; '
                        'stty -g > after; echo "TALKER" "EXITED"', cwd=True)
        self.addCleanup(term.close)
        self.assertTrue(term.wait_for('talker: press P', 30), term.screen())
        self.assertIn('-icanon', term.flags())
        os.kill(node_pid(TALKER), signal.SIGTERM)
        self.assertTrue(term.wait_for('TALKER EXITED', 20), term.screen())
        self.assertEqual(term.read('after'), term.read('before'))
        self.assertNotIn('Traceback', term.screen())


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'talker_faults', TalkerFaults)
