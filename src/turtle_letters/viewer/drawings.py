"""Each student's drawing as their draw action tells it: the text asked for
(its goal), how far it is (its feedback: share done, seconds to go,
paused), and how it ended (its result). Every action named NAMESPACE/draw
is followed, from its first feedback on the graph."""
import threading

import rospy
from turtle_letters.msg import DrawActionFeedback, DrawActionGoal, DrawActionResult

FEEDBACK_TYPE = 'turtle_letters/DrawActionFeedback'


class Drawings:
    def __init__(self):
        self.rows = {}          # student: what the page shows of their drawing
        self.followed = {}      # action: its subscribers
        self.lock = threading.Lock()

    def look(self, topics):
        """Follows each draw action whose feedback `topics` (name: type) now lists."""
        for topic, kind in topics.items():
            action = topic[:-len('/feedback')]
            if kind == FEEDBACK_TYPE and action.endswith('/draw') and action not in self.followed:
                self._follow(action)

    def _follow(self, action):
        student = action[:-len('/draw')].strip('/') or '/'
        self.followed[action] = [
            rospy.Subscriber(f'{action}/goal', DrawActionGoal, lambda m: self._set(
                student, text=m.goal.text or m.goal.svg, progress=0.0, eta=None,
                paused=False, ended=''), queue_size=10),
            rospy.Subscriber(f'{action}/feedback', DrawActionFeedback, lambda m: self._set(
                student, progress=round(m.feedback.progress, 3), eta=round(m.feedback.eta, 1),
                paused=m.feedback.paused), queue_size=10),
            rospy.Subscriber(f'{action}/result', DrawActionResult, lambda m: self._set(
                student, ended=m.result.message, eta=0.0,
                progress=1.0 if m.result.drawn else None), queue_size=10)]

    def _set(self, student, **fields):
        with self.lock:
            row = self.rows.setdefault(student, dict(text='', progress=0.0, eta=None,
                                                     paused=False, ended=''))
            row.update({k: v for k, v in fields.items() if v is not None or k == 'eta'})

    def table(self):
        with self.lock:
            return {student: dict(row) for student, row in self.rows.items()}
