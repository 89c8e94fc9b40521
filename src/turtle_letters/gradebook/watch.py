"""The grader's eyes in a submission's network namespace: a node of ours,
run outside the sandbox, that reports as JSON lines on stdout every pose
and /chatter message (with the time it came and the node that sent it),
how many commands came on cmd_vel each COUNTED s, turtlesim's own word
when its canvas is cleared or reset, and, twice a second, who publishes
and serves what. A line "P" on stdin publishes "P" on /chatter. Run as
`python3 -m turtle_letters.gradebook.watch`.

Commands are counted unread (rospy.AnyMsg): a busy-loop controller sends
thousands a second, and reading each would load the machine that grades,
and so the drawings of the students graded beside it. For the same reason
only the first CHATTER_SHOWN messages on /chatter of each COUNTED s are
reported one by one; the rest are counted."""
import json
import sys
import threading
import time

import rosgraph
import rospy
from rosgraph_msgs.msg import Log
from std_msgs.msg import String
from turtlesim.msg import Pose

from ..motion.driver import CANVAS_WORDS
from .observations import COUNTED, WATCHER

NAME = WATCHER
GRAPH_PERIOD = 0.5      # s between reports of the graph
CHATTER_SHOWN = 5       # /chatter messages reported whole each COUNTED s


class Reporter:
    """One JSON line per event, whole, whichever thread reports it."""

    def __init__(self, out=sys.stdout):
        self.out, self.lock = out, threading.Lock()

    def __call__(self, kind, **fields):
        line = json.dumps(dict(kind=kind, t=time.monotonic(), **fields))
        with self.lock:
            self.out.write(line + '\n')
            self.out.flush()


def sender(msg):
    return msg._connection_header.get('callerid', '?')


def graph(master):
    """Who publishes the turtle's topics, who listens on /chatter, who serves /spawn."""
    publishers, subscribers, services = master.getSystemState()
    published, subscribed = dict(publishers), dict(subscribers)
    return dict(pose_publishers=published.get('/turtle1/pose', []),
                cmd_vel_publishers=[n for n in published.get('/turtle1/cmd_vel', []) if n != NAME],
                chatter_publishers=[n for n in published.get('/chatter', []) if n != NAME],
                chatter_subscribers=[n for n in subscribed.get('/chatter', []) if n != NAME],
                simulator=dict(services).get('/spawn', []))


def wait_for_master(master):
    while True:
        try:
            return master.getPid()
        except OSError:
            time.sleep(0.1)


def main():
    report = Reporter()
    master = rosgraph.Master(NAME)
    wait_for_master(master)
    rospy.init_node(NAME[1:], disable_signals=True, disable_rosout=True)
    rospy.Subscriber('/turtle1/pose', Pose, lambda m: report(
        'pose', x=m.x, y=m.y, theta=m.theta, v=m.linear_velocity, w=m.angular_velocity,
        sender=sender(m)), queue_size=1000)
    commands = Counter()
    rospy.Subscriber('/turtle1/cmd_vel', rospy.AnyMsg, commands.add, queue_size=1000)
    chatter_heard = Counter()

    def on_chatter(message):
        if chatter_heard.add(message) < CHATTER_SHOWN:
            report('chatter', data=message.data[:80], sender=sender(message))

    def on_log(message):
        if message.msg in CANVAS_WORDS:
            report('canvas', what=CANVAS_WORDS[message.msg], sender=sender(message))
    rospy.Subscriber('/chatter', String, on_chatter, queue_size=100)
    rospy.Subscriber('/rosout', Log, on_log, queue_size=100)
    chatter = rospy.Publisher('/chatter', String, queue_size=1, latch=True)
    threading.Thread(target=_obey, args=(chatter, report), daemon=True).start()
    next_graph, counted_at = 0.0, time.monotonic()
    while not rospy.is_shutdown():
        if time.monotonic() >= next_graph:
            try:
                report('graph', **graph(master))
            except OSError as e:
                report('graph_error', error=str(e))
            next_graph = time.monotonic() + GRAPH_PERIOD
        counted = commands.take()
        if counted:
            report('cmd_vel', count=counted)
        now, heard = time.monotonic(), chatter_heard.take()
        if heard:       # counted since `since`: the rate comes from the times, not the period
            report('chatter_count', count=heard, since=counted_at)
        counted_at = now
        time.sleep(COUNTED)


class Counter:
    """Messages counted as they come, taken in batches."""

    def __init__(self):
        self.count, self.lock = 0, threading.Lock()

    def add(self, _):
        """Counts one; how many were counted before it in this batch."""
        with self.lock:
            self.count += 1
            return self.count - 1

    def take(self):
        with self.lock:
            count, self.count = self.count, 0
        return count


def _obey(chatter, report):
    for line in sys.stdin:
        if line.strip() == 'P':
            chatter.publish(String('P'))
            report('published', data='P')


if __name__ == '__main__':
    main()
