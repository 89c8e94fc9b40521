"""The grader's ears in a submission's network namespace: a node of ours,
run outside the sandbox, that reports as JSON lines on stdout each /chatter
message (with the time it came and the node that sent it) and, twice a
second, who publishes and serves what. A line "P" on stdin publishes "P"
on /chatter. Run as `python3 -m turtle_letters.autograder.watch`.

What was drawn is not its to see: the grader's simulator records that
(world.py). Only the first CHATTER_SHOWN messages on /chatter of each
COUNTED s are reported one by one, the rest counted: a talker in a busy
loop must not load the machine that grades, and so the drawings of the
students graded beside it."""
import json
import sys
import threading
import time

import rosgraph
import rospy
from std_msgs.msg import String

from . import observations as seen
from .observations import COUNTED, WATCHER
from .world import SIMULATOR

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
    """Who drives a turtle, who talks and listens on /chatter, and which
    nodes besides the grader's simulator publish poses or serve /spawn."""
    return seen.roles(master.getSystemState(), master.getTopicTypes(), (NAME, SIMULATOR))


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
    chatter_heard = Counter()

    def on_chatter(message):
        if chatter_heard.add(message) < CHATTER_SHOWN:
            report('chatter', data=message.data[:80], sender=sender(message))
    rospy.Subscriber('/chatter', String, on_chatter, queue_size=100)
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
