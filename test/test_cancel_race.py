#!/usr/bin/python3
"""The draw action never locks up when a cancel meets a drawing's end: a
cancel takes actionlib's lock and then the server's, so the drawing's end
must never call actionlib under the server's. Goals that end at once (a
word too long for the canvas is refused as it is planned) are cancelled
as they end, RACES times, each a few milliseconds apart; every one gets
its result, and then the lab's N is still drawn."""
import random
import unittest

import actionlib
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus

from turtle_letters.msg import DrawAction, DrawGoal

RACES = 300
ENDS_WITHIN = 10.0      # s for a goal's result: a locked server never sends it
TOO_LONG = DrawGoal(text='N' * 12)


class CancelAsItEnds(unittest.TestCase):
    def test_cancels_that_meet_drawings_ends_never_lock_the_server(self):
        rospy.init_node('cancel_race_test')
        client = actionlib.SimpleActionClient('/draw', DrawAction)
        self.assertTrue(client.wait_for_server(rospy.Duration(30)), 'no /draw action server')
        chance = random.Random(38)
        for race in range(RACES):
            client.send_goal(TOO_LONG)
            rospy.sleep(chance.uniform(0.0, 0.004))
            client.cancel_goal()
            self.assertTrue(client.wait_for_result(rospy.Duration(ENDS_WITHIN)),
                            f'goal {race + 1}: no result within {ENDS_WITHIN:g} s: '
                            f'the draw action is locked')
        # "busy: ... send it again once that has ended", as its refusal says: a
        # locked server stays busy for good, and still fails here
        for _ in range(20):
            client.send_goal(DrawGoal(text='N'))
            self.assertTrue(client.wait_for_result(rospy.Duration(120)), 'the N never ended')
            if client.get_state() != GoalStatus.REJECTED:
                break
            rospy.sleep(0.5)
        self.assertEqual(client.get_state(), GoalStatus.SUCCEEDED, client.get_goal_status_text())


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'cancel_race', CancelAsItEnds)
