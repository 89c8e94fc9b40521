#!/usr/bin/python3
"""End to end, as a user: roslaunch in a terminal, the key P, the N on the
canvas; Ctrl-C ends every node and gives the terminal back as it was."""
import time
import unittest

import rospy
import rosnode
import rostest

from support.accuracy import LAB_N_VERTICES, touches_a_wall, vertex_errors, worst_distance_from
from support.nodes import PoseRecorder, wait_until
from support.terminal import Terminal


class LaunchInATerminal(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('launch_terminal_test')

    def launch(self, arguments=''):
        self.term = Terminal('stty -g > before; roslaunch turtle_letters draw_letter.launch '
                             f'headless:=true {arguments}; stty -g > after; '
                             'echo "LAUNCH" "ENDED $?"', cwd=True)
        self.addCleanup(self.term.close)

    def test_press_p_draws_the_n_then_ctrl_c_ends_it_all(self):
        self.launch()
        self.assertTrue(self.term.wait_for('talker: press P', 60), self.term.screen())
        poses = PoseRecorder()
        poses.wait_connected()

        t0 = time.time()
        self.term.send_keys('p')
        wait_until(lambda: poses.moving_since(t0), 30, 'the key P to start a drawing',
                   self.term.screen)
        poses.wait_until_still(t0, 150)
        path = poses.path()
        self.assertLess(max(vertex_errors(path, LAB_N_VERTICES)), 0.05)
        self.assertLess(worst_distance_from(path, LAB_N_VERTICES), 0.05)
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
        poses = PoseRecorder()
        poses.wait_connected()
        self.assertTrue(self.term.wait_for("Ready: publish 'Q'", 30), self.term.screen())
        self.term.send_keys('p')
        time.sleep(2.0)                 # a drawing would have started by now
        self.assertEqual(poses.moving_since(0), [],
                         'the key P started a drawing although the trigger is Q')
        self.term.send_keys('q')
        self.assertTrue(self.term.wait_for("Drawing 'N'", 20), self.term.screen())
        self.term.send_keys('C-c')
        self.assertTrue(self.term.wait_for('LAUNCH ENDED', 30), self.term.screen())
        self.assertEqual(self.term.read('after'), self.term.read('before'))


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'launch_terminal', LaunchInATerminal)
