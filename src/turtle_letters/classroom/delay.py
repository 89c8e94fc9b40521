"""Node delay_relay.py: a network that is slow, made on one machine. It
passes each message of `in` on to `out` after ~delay s, give or take up to
~jitter s, in the order they came (ROS carries a topic over one TCP
connection, which keeps order however late it is). Tests put it between a
controller and turtlesim with remaps, each way, since this machine has no
netem:

    rosrun turtle_letters delay_relay.py in:=/slow/turtle1/cmd_vel \\
        out:=/turtle1/cmd_vel _delay:=0.05 _jitter:=0.03

The message type is the first message's own (any type is relayed). The
release times (`Delays`) are pure logic, tested on their own.
"""
import heapq
import random
import threading
import time

import rospy
from roslib.message import get_message_class


class Delays:
    """When each message goes out: `delay` +- `jitter` s after it came, never
    before the one before it went (order kept)."""

    def __init__(self, delay, jitter, rng=None):
        if delay < 0 or jitter < 0 or jitter > delay:
            raise ValueError(f'delay {delay:g} s and jitter {jitter:g} s: both 0 or more, '
                             f'and the jitter at most the delay')
        self.delay, self.jitter = delay, jitter
        self.rng = rng or random.Random()
        self.last = float('-inf')

    def release(self, arrived):
        due = arrived + self.delay + self.rng.uniform(-self.jitter, self.jitter)
        self.last = max(self.last, due)
        return self.last


class Relay:
    """Messages held until their time, then published, by one thread."""

    def __init__(self, delays):
        self.delays, self.publisher = delays, None
        self.held, self.count = [], 0
        self.ready = threading.Condition()

    def on_message(self, message):
        if self.publisher is None:      # the type is known once a message comes
            kind = get_message_class(message._connection_header['type'])
            self.publisher = rospy.Publisher('out', kind, queue_size=1000, tcp_nodelay=True)
            self.kind = kind
        decoded = self.kind().deserialize(message._buff)
        with self.ready:
            self.count += 1
            heapq.heappush(self.held, (self.delays.release(time.monotonic()), self.count, decoded))
            self.ready.notify()

    def run(self):
        while not rospy.is_shutdown():
            with self.ready:
                if not self.held:
                    self.ready.wait(0.1)
                    continue
                due = self.held[0][0] - time.monotonic()
                if due > 0:
                    self.ready.wait(due)
                    continue
                _, _, message = heapq.heappop(self.held)
            self.publisher.publish(message)


def main():
    rospy.init_node('delay_relay')
    try:
        delays = Delays(float(rospy.get_param('~delay', 0.05)), float(rospy.get_param('~jitter', 0.0)))
    except (TypeError, ValueError) as e:
        rospy.logfatal('%s: %s', rospy.get_name(), e)
        raise SystemExit(2)
    relay = Relay(delays)
    rospy.Subscriber('in', rospy.AnyMsg, relay.on_message, queue_size=1000, tcp_nodelay=True)
    rospy.loginfo('%s: %s to %s, %g s +- %g s late', rospy.get_name(), rospy.resolve_name('in'),
                  rospy.resolve_name('out'), delays.delay, delays.jitter)
    relay.run()
