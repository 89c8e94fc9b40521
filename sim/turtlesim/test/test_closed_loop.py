#!/usr/bin/python3
"""A closed-loop client gets its answer at the next tick, as on the real
turtlesim: the path it drives is exactly the one the simulator's kinematics
give when every command sent in answer to a pose applies at the next tick."""
import math
import struct
import threading
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose
from turtlesim.srv import TeleportAbsolute

from turtlesim_compat.world import CENTRE, Turtle

RUNS = 4
TICKS = 400          # 6.4 s of simulated time per run
LEGS = [(2.0, math.pi / 2), (1.5, math.pi), (2.5, -math.pi / 2), (1.0, 0.3)]
SPEED, TURN = 1.3, 0.9


def float32(value):
    """What a float32 field of the Pose message carries."""
    return struct.unpack('f', struct.pack('f', value))[0]


class DriveThenTurn:
    """Drive straight until a distance is covered, then turn to a heading,
    leg after leg: each command decided from the pose just read."""

    def __init__(self):
        self.leg = 0
        self.start = None
        self.turning = False

    def command(self, x, y, theta):
        distance, heading = LEGS[self.leg % len(LEGS)]
        if self.start is None:
            self.start = (x, y)
        if not self.turning:
            if math.hypot(x - self.start[0], y - self.start[1]) < distance:
                return (SPEED, 0.0)
            self.turning = True
        error = math.atan2(math.sin(heading - theta), math.cos(heading - theta))
        if abs(error) > 0.01:
            return (0.0, math.copysign(TURN, error))
        self.leg, self.start, self.turning = self.leg + 1, (x, y), False
        return (SPEED, 0.0)


def reference_trace(ticks):
    """The same client on the simulator's kinematics, each command applied at
    the very next tick."""
    start = float32(CENTRE)         # where the run teleports to, through a float32 field
    turtle = Turtle('turtle1', start, start, 0.0)
    client = DriveThenTurn()
    trace = []
    for tick in range(ticks):
        seen = (float32(turtle.x), float32(turtle.y), float32(turtle.theta))
        trace.append(seen)
        linear, angular = client.command(*seen)
        turtle.command(linear, 0.0, angular, now=tick)
        turtle.step(now=tick)
    return trace


class ClosedLoop(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('closed_loop_test')
        cls.cmd_vel = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=1, tcp_nodelay=True)
        cls.teleport = rospy.ServiceProxy('/turtle1/teleport_absolute', TeleportAbsolute)
        rospy.wait_for_service('/turtle1/teleport_absolute', timeout=30)

    def drive(self):
        """One run of the client against the running simulator; its trace."""
        self.cmd_vel.publish(Twist())
        self.teleport(CENTRE, CENTRE, 0.0)     # returns once the tick has applied it
        deadline = time.time() + 10
        while self.cmd_vel.get_num_connections() == 0 and time.time() < deadline:
            time.sleep(0.01)
        client = DriveThenTurn()
        trace = []
        finished = threading.Event()

        def on_pose(msg):
            if finished.is_set():
                return
            trace.append((msg.x, msg.y, msg.theta))
            if len(trace) == TICKS:
                finished.set()
                self.cmd_vel.publish(Twist())
                return
            twist = Twist()
            twist.linear.x, twist.angular.z = client.command(msg.x, msg.y, msg.theta)
            self.cmd_vel.publish(twist)
        subscriber = rospy.Subscriber('/turtle1/pose', Pose, on_pose, queue_size=TICKS,
                                      tcp_nodelay=True)
        finished.wait(TICKS * 0.016 * 5 + 10)
        subscriber.unregister()
        return trace

    def test_every_run_drives_the_reference_path(self):
        expected = reference_trace(TICKS)
        late = []
        for run in range(RUNS):
            trace = self.drive()
            self.assertEqual(len(trace), TICKS, f'run {run}: poses missing')
            self.assertEqual(trace[0][:2], expected[0][:2], 'the teleport did not take')
            first = next((k for k, (a, b) in enumerate(zip(trace, expected)) if a != b), None)
            if first is not None:
                worst = max(math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in zip(trace, expected))
                late.append(f'run {run}: apart from tick {first} on, up to {worst * 1000:.1f} mm')
        self.assertEqual(late, [], 'a command took effect a tick late')


if __name__ == '__main__':
    rostest.rosrun('turtlesim', 'closed_loop', ClosedLoop)
