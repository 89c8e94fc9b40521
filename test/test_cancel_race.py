#!/usr/bin/python3
"""The draw action never locks up when a cancel meets a drawing's end: a
cancel takes actionlib's lock and then the server's, so the drawing's end
must never call actionlib under the server's. Goals that end at once (a
word too long for the canvas is refused as it is planned) are cancelled
as they end, RACES times, each a few milliseconds apart; the server gives
every one its result, and the N sent next is taken at once and drawn.

The goals and cancels go out on the action's own topics, and each end is
the server's result message: rospy's SimpleActionClient, cancelling a goal
the server has not yet acknowledged, may call it lost when the next status
comes without it (ros/actionlib#126), and its wait then ends while the
server still has the goal."""
import random
import threading
import unittest

import actionlib
import rospy
import rostest
from actionlib_msgs.msg import GoalID, GoalStatus

from support.nodes import wait_for_connections
from turtle_letters.msg import DrawAction, DrawActionGoal, DrawActionResult, DrawGoal

RACES = 300
ENDS_WITHIN = 10.0      # s for a goal's result: a locked server never sends it
TOO_LONG = DrawGoal(text='N' * 12)
ENDED = {GoalStatus.ABORTED: 'aborted', GoalStatus.PREEMPTED: 'cancelled',
         GoalStatus.RECALLED: 'recalled'}


class Results:
    """The status of every goal the server has sent a result for, by goal id."""

    def __init__(self):
        self.status = {}
        self.changed = threading.Condition()
        self.subscriber = rospy.Subscriber('/draw/result', DrawActionResult, self._on_result,
                                           queue_size=RACES)

    def _on_result(self, message):
        with self.changed:
            self.status[message.status.goal_id.id] = message.status.status
            self.changed.notify_all()

    def wait(self, goal_id, timeout):
        """The goal's end status, or None if the server sent none within `timeout` s."""
        with self.changed:
            self.changed.wait_for(lambda: goal_id in self.status, timeout)
            return self.status.get(goal_id)


class CancelAsItEnds(unittest.TestCase):
    def test_cancels_that_meet_drawings_ends_never_lock_the_server(self):
        rospy.init_node('cancel_race_test')
        client = actionlib.SimpleActionClient('/draw', DrawAction)
        self.assertTrue(client.wait_for_server(rospy.Duration(30)), 'no /draw action server')
        results = Results()
        goals = rospy.Publisher('/draw/goal', DrawActionGoal, queue_size=10)
        cancels = rospy.Publisher('/draw/cancel', GoalID, queue_size=10)
        for endpoint in (results.subscriber, goals, cancels):
            wait_for_connections(endpoint)
        chance, seen = random.Random(38), {}
        for race in range(RACES):
            goal_id = GoalID(stamp=rospy.Time.now(), id=f'cancel_race_{race}')
            goals.publish(DrawActionGoal(goal_id=goal_id, goal=TOO_LONG))
            rospy.sleep(chance.uniform(0.0, 0.004))
            cancels.publish(GoalID(id=goal_id.id))
            status = results.wait(goal_id.id, ENDS_WITHIN)
            self.assertIn(status, ENDED, f'goal {race + 1}: no result within {ENDS_WITHIN:g} s, '
                          'or not one a cancelled goal ends with: the draw action is locked')
            seen[ENDED[status]] = seen.get(ENDED[status], 0) + 1
        print(f'{RACES} goals, each cancelled as it ended: {seen}', flush=True)
        # every goal before it has its result, so nothing is under way
        client.send_goal(DrawGoal(text='N'))
        self.assertTrue(client.wait_for_result(rospy.Duration(120)), 'the N never ended')
        self.assertEqual(client.get_state(), GoalStatus.SUCCEEDED, client.get_goal_status_text())


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'cancel_race', CancelAsItEnds)
