#!/usr/bin/python3
"""End to end, as a user: roslaunch in a terminal, the key P, the N on the
canvas; Ctrl-C ends every node and gives the terminal back as it was."""
import math
import threading
import time
import unittest

import rospy
import rosnode
import rostest
from turtlesim.msg import Pose

from turtle_letters.geometry import LAB_N, touches_a_wall, vertex_errors, worst_distance_from
from terminal import Terminal


class LaunchInATerminal(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('launch_terminal_test')

    def launch(self, arguments=''):
        self.poses = []
        self.lock = threading.Lock()
        self.term = Terminal('stty -g > before; roslaunch turtle_letters draw_letter.launch '
                             f'headless:=true {arguments}; stty -g > after; '
                             'echo "LAUNCH" "ENDED $?"', cwd=True)
        self.addCleanup(self.term.close)

    def on_pose(self, msg):
        with self.lock:
            self.poses.append(msg)

    def test_press_p_draws_the_n_then_ctrl_c_ends_it_all(self):
        self.launch()
        self.assertTrue(self.term.wait_for('talker: press P', 60), self.term.screen())
        rospy.wait_for_message('/turtle1/pose', Pose, timeout=30)
        rospy.Subscriber('/turtle1/pose', Pose, self.on_pose, queue_size=1000)
        time.sleep(1.0)

        self.term.send_keys('p')
        deadline = time.time() + 150
        started = False
        while time.time() < deadline:
            with self.lock:
                last = self.poses[-1]
                started = started or last.angular_velocity != 0 or last.linear_velocity != 0
                done = started and math.hypot(last.x - LAB_N[-1][0], last.y - LAB_N[-1][1]) < 0.05 \
                    and last.linear_velocity == 0
            if done:
                break
            time.sleep(0.2)
        with self.lock:
            path = [(p.x, p.y) for p in self.poses]
        self.assertTrue(started, 'the key P did not start a drawing:\n' + self.term.screen())
        self.assertLess(max(vertex_errors(path, LAB_N)), 0.05)
        self.assertLess(worst_distance_from(path, LAB_N), 0.05)
        self.assertFalse(touches_a_wall(path))

        nodes = ['/turtlesim', '/talker', '/turtlebot_controller']
        t0 = time.time()
        self.term.send_keys('C-c')
        self.assertTrue(self.term.wait_for('LAUNCH ENDED', 30), self.term.screen())
        self.assertLess(time.time() - t0, 15.0)
        self.assertEqual(set(nodes) & set(rosnode.get_node_names()), set())
        self.assertEqual(self.term.read('after'), self.term.read('before'))
        self.assertNotIn('Traceback', self.term.screen())

    def test_the_trigger_argument_reaches_the_keyboard(self):
        self.launch('trigger:=Q mode:=feedback linear_speed:=3 angular_speed:=3')
        self.assertTrue(self.term.wait_for('talker: press Q', 60), self.term.screen())
        rospy.wait_for_message('/turtle1/pose', Pose, timeout=30)
        rospy.Subscriber('/turtle1/pose', Pose, self.on_pose, queue_size=1000)
        self.assertTrue(self.term.wait_for("Ready: publish 'Q'", 30), self.term.screen())
        self.term.send_keys('p')
        time.sleep(2.0)
        with self.lock:
            self.assertFalse(any(p.linear_velocity or p.angular_velocity for p in self.poses),
                             'the key P started a drawing although the trigger is Q')
        self.term.send_keys('q')
        self.assertTrue(self.term.wait_for("Drawing 'N'", 20), self.term.screen())
        self.term.send_keys('C-c')
        self.assertTrue(self.term.wait_for('LAUNCH ENDED', 30), self.term.screen())
        self.assertEqual(self.term.read('after'), self.term.read('before'))


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'launch_terminal', LaunchInATerminal)
