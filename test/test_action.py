#!/usr/bin/python3
"""The draw action of the lab's controller, as a script would use it: bad
goals answered in one line with nothing moving; the lab's N drawn with a
3 s pause mid-move (and a goal refused meanwhile), feedback that only
increases, and the result; a second N cancelled mid-move, the turtle still
within 0.2 s; the next N drawn at the next place."""
import os
import shutil
import tempfile
import time
import unittest

import actionlib
import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from std_msgs.msg import String
from std_srvs.srv import SetBool
from turtlesim.msg import Pose

from support.accuracy import LAB_N_VERTICES, expected, vertex_errors, worst_off
from support.nodes import LogWatch, PoseRecorder, wait_for_connections, wait_until
from turtle_letters.letters.font import BUILTIN
from turtle_letters.msg import DrawAction, DrawActionFeedback, DrawGoal
from turtle_letters.letters.geometry import PlannedPose
from turtle_letters.letters.sheet import Sheet

TOLERANCE = 0.002       # m: timed mode on the simulator's clock, paused or not
PAUSE = 3.0             # s: the pause, mid-move
STILL_AFTER = 0.2       # s: a cancelled turtle stands by then
SVG_DIR = '/tmp'         # action.test's svg_dirs
BAD_GOALS = {'empty': DrawGoal(text=''), 'both': DrawGoal(text='N', svg='/tmp/n.svg'),
             'no glyph': DrawGoal(text='N\u00e9'), 'too long': DrawGoal(text='N' * 12),
             'no file': DrawGoal(svg='/nonexistent/drawing.svg')}


class Recorder:
    """The draw action's feedback as published (/draw/feedback), with the
    time each came: a SimpleActionClient drops feedback that reaches it
    after its goal's result, and the last one, sent just before the
    result, on another topic, sometimes does."""

    def __init__(self):
        self.feedback = []
        self.topic = rospy.Subscriber('/draw/feedback', DrawActionFeedback, self.heard)
        wait_for_connections(self.topic, what="the action server's feedback")

    def heard(self, message):
        self.feedback.append((time.time(), message.feedback))

    def close(self, timeout=5.0):
        """Unsubscribed, once the feedback of a drawing's end came (or `timeout` s passed)."""
        def ended():
            return self.feedback and self.feedback[-1][1].progress >= 1.0
        deadline = time.time() + timeout
        while time.time() < deadline and not ended():
            time.sleep(0.02)
        self.topic.unregister()


class DrawAsAnAction(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('action_test')
        cls.logs, cls.poses = LogWatch(), PoseRecorder()
        cls.start = rospy.wait_for_message('/turtle1/pose', Pose, timeout=30)
        cls.client = actionlib.SimpleActionClient('/draw', DrawAction)
        assert cls.client.wait_for_server(rospy.Duration(30)), 'no /draw action server'
        cls.pause = rospy.ServiceProxy('/pause', SetBool)
        cls.chatter = rospy.Publisher('/chatter', String, queue_size=1)
        wait_for_connections(cls.chatter, what="the controller's chatter subscription")
        t0 = time.time()
        cls.bad = {name: cls.send(goal, 20) for name, goal in BAD_GOALS.items()}
        rospy.sleep(1.0)
        cls.moved_for_bad_goals = cls.poses.moving_since(t0)
        cls.paused_n = cls.draw_with_a_pause()
        cls.cancelled = cls.draw_and_cancel()
        cls.cancelled_planning = cls.plan_and_cancel()
        cls.next_n = cls.send(DrawGoal(text='N'), 150)

    @classmethod
    def send(cls, goal, timeout, feedback=None):
        """(status, result, when it ended) of a goal."""
        cls.client.send_goal(goal, feedback_cb=feedback)
        assert cls.client.wait_for_result(rospy.Duration(timeout)), f'no result for {goal}'
        return cls.client.get_state(), cls.client.get_result(), time.time()

    @classmethod
    def wait_mid_move(cls, t0):
        """Until the turtle is half a metre into a move."""
        def mid_move():
            moving = [p for p in cls.poses.since(t0) if p.linear_velocity]
            return len(moving) > 30
        wait_until(mid_move, 60, 'the turtle to be moving along a line')

    @classmethod
    def draw_with_a_pause(cls):
        t0, record = time.time(), Recorder()
        cls.client.send_goal(DrawGoal(text='N'))
        cls.wait_mid_move(t0)
        paused = cls.pause(True)
        paused_at = time.time()
        busy_client = actionlib.SimpleActionClient('/draw', DrawAction)
        busy_client.wait_for_server(rospy.Duration(10))
        busy = cls.busy_goal(busy_client)
        cls.chatter.publish(String('P'))
        rospy.sleep(PAUSE)
        resumed = cls.pause(False)
        resumed_at = time.time()
        assert cls.client.wait_for_result(rospy.Duration(150)), 'the paused N never ended'
        record.close()
        return dict(t0=t0, ended_at=time.time(), feedback=record.feedback, paused=paused, resumed=resumed,
                    paused_at=paused_at, resumed_at=resumed_at, busy=busy,
                    status=cls.client.get_state(), result=cls.client.get_result())

    @staticmethod
    def busy_goal(client):
        """(status, message, seconds to answer) of a goal sent while one draws."""
        t0 = time.time()
        client.send_goal(DrawGoal(text='Z'))
        client.wait_for_result(rospy.Duration(10))
        return client.get_state(), client.get_result().message, time.time() - t0

    @classmethod
    def plan_and_cancel(cls):
        """A picture of thousands of strokes, cancelled as soon as it is
        accepted: while it is planned (or before)."""
        folder = tempfile.mkdtemp(prefix='turtle_letters_action_', dir=SVG_DIR)
        path = os.path.join(folder, 'many.svg')
        lines = ''.join(f'<line x1="{i % 90}" y1="{i // 90}" x2="{i % 90 + 0.5}" y2="{i // 90}"/>'
                        for i in range(8100))
        with open(path, 'w') as f:
            f.write('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 90 90" '
                    f'stroke="black">{lines}</svg>')
        t0 = time.time()
        cls.client.send_goal(DrawGoal(svg=path))
        wait_until(lambda: cls.client.get_state() == GoalStatus.ACTIVE, 30, 'the goal accepted')
        cls.client.cancel_goal()
        ended = cls.client.wait_for_result(rospy.Duration(30))
        shutil.rmtree(folder)
        return dict(ended=ended, status=cls.client.get_state(), result=cls.client.get_result(),
                    moved=cls.poses.moving_since(t0))

    @classmethod
    def draw_and_cancel(cls):
        t0 = time.time()
        cls.client.send_goal(DrawGoal(text='N'))
        cls.wait_mid_move(t0)
        cancelled_at = time.time()
        cls.client.cancel_goal()
        cls.client.wait_for_result(rospy.Duration(10))
        rospy.sleep(2.0)        # to see that the turtle stays where it stopped
        return dict(at=cancelled_at, looked_until=time.time(), status=cls.client.get_state(),
                    result=cls.client.get_result(), poses=cls.poses.since(cancelled_at))

    def places(self):
        """The lab's three places, in order, from the start pose."""
        sheet = Sheet(3.0, BUILTIN)
        start = PlannedPose(self.start.x, self.start.y, self.start.theta)
        return [sheet.reserve('N', start)[0][0] for _ in range(3)]

    def test_bad_goals_are_answered_in_one_line_and_nothing_moves(self):
        for name, (status, result, _) in self.bad.items():
            with self.subTest(goal=name):
                self.assertIn(status, (GoalStatus.REJECTED, GoalStatus.ABORTED), result.message)
                self.assertFalse(result.drawn)
                self.assertTrue(result.message and '\n' not in result.message, result.message)
        self.assertIn('exactly one of text and svg', self.bad['both'][1].message)
        self.assertIn('does not fit', self.bad['too long'][1].message)
        self.assertIn('/nonexistent/drawing.svg', self.bad['no file'][1].message)
        self.assertEqual(self.moved_for_bad_goals, [])

    def test_the_paused_n_is_drawn_exactly(self):
        n = self.paused_n
        self.assertEqual(n['status'], GoalStatus.SUCCEEDED, n['result'].message)
        self.assertTrue(n['result'].drawn)
        self.assertAlmostEqual(n['result'].ink, 9.5, places=3)
        path = [(p.x, p.y) for t, p in self.poses.poses if n['t0'] <= t <= n['ended_at']]
        errors = vertex_errors(path, LAB_N_VERTICES)
        self.assertLess(max(errors), TOLERANCE, f'vertex errors (m) {errors}')

    def test_a_pause_holds_the_turtle_and_the_eta(self):
        n = self.paused_n
        self.assertTrue(n['paused'].success and n['resumed'].success, n['paused'].message)
        during = [p for t, p in self.poses.poses if n['paused_at'] + STILL_AFTER < t < n['resumed_at']]
        self.assertTrue(during)
        self.assertEqual({(p.x, p.y, p.linear_velocity) for p in during},
                         {(during[0].x, during[0].y, 0.0)})
        paused = [(t, f) for t, f in n['feedback'] if f.paused]
        self.assertTrue(paused, 'no feedback said paused')
        self.assertLess(abs(paused[-1][1].eta - paused[0][1].eta), 0.5)
        self.assertGreater(paused[-1][0] - paused[0][0], PAUSE - 1.5)

    def test_feedback_comes_every_second_and_only_increases(self):
        feedback = self.paused_n['feedback']
        times = [t for t, _ in feedback]
        self.assertLess(max(b - a for a, b in zip(times, times[1:])), 2.0)
        progress = [f.progress for _, f in feedback]
        self.assertEqual(progress, sorted(progress))
        self.assertEqual(progress[-1], 1.0)
        strokes = [f.stroke for _, f in feedback]
        self.assertEqual(strokes, sorted(strokes))
        self.assertEqual((strokes[-1], feedback[-1][1].strokes), (1, 1))

    def test_a_goal_while_busy_is_refused_at_once_saying_what_is_drawn(self):
        status, message, seconds = self.paused_n['busy']
        self.assertEqual(status, GoalStatus.REJECTED)
        self.assertIn("busy: 'N' is being drawn", message)
        self.assertLess(seconds, 5.0)
        self.assertEqual(self.logs.count("ignored: a drawing is waiting or under way"), 1)

    def test_a_cancelled_goal_stops_the_turtle(self):
        c = self.cancelled
        self.assertEqual(c['status'], GoalStatus.PREEMPTED, c['result'].message)
        self.assertFalse(c['result'].drawn)
        self.assertIn('cancelled during move', c['result'].message)
        after = [p for t, p in self.poses.poses if c['at'] + STILL_AFTER < t < c['looked_until']]
        self.assertGreater(len(after), 50)
        self.assertEqual({(p.x, p.y, p.theta, p.linear_velocity, p.angular_velocity)
                          for p in after},
                         {(after[0].x, after[0].y, after[0].theta, 0.0, 0.0)})

    def test_a_goal_cancelled_while_it_is_planned_ends_at_once_and_takes_no_place(self):
        c = self.cancelled_planning
        self.assertTrue(c['ended'], 'no result within 30 s of the cancel')
        self.assertEqual(c['status'], GoalStatus.PREEMPTED, c['result'].message)
        self.assertRegex(c['result'].message, 'cancelled (while it was planned|before it began|'
                                              'while waiting)')
        self.assertEqual(c['moved'], [])
        # and the next N takes the place it would have had: test_after_a_cancel...

    def test_after_a_cancel_the_next_n_goes_to_the_next_place(self):
        status, result, _ = self.next_n
        self.assertEqual(status, GoalStatus.SUCCEEDED, result.message)
        third = self.places()[2]
        stop = self.cancelled['poses'][-1]
        start = PlannedPose(stop.x, stop.y, stop.theta)
        strokes, travel = expected('N', [third], start, 3.0)
        path = self.poses.path(self.cancelled['looked_until'])
        self.assertLess(max(vertex_errors(path, strokes[0])), TOLERANCE)
        self.assertLess(worst_off(path, strokes, travel), 0.05)


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'action', DrawAsAnAction)
