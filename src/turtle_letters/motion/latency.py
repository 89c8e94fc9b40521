"""How late commands act, measured on the poses, and what the commands
still on their way will do. No ROS here.

One command is sent per pose. With nothing in between, the pose after a
command shows it (turtlesim reports the velocities it moved with), a tick
after it was sent. Over a slow network a command shows `lag` ticks later
than that: the last `lag` commands sent are in flight, and each will still
move the turtle a tick. The lag is measured in time, from when a command
unlike those before it is sent to when a pose first shows it. The
executors act on where those commands will take the turtle (`ahead`), not
on where the late pose says it was: a loop that waits for its own commands
to show oscillates around its target and never settles.
"""
import math
import statistics
from collections import deque
from typing import List

from ..letters.layout import SIM_TICK

SAME = 1e-3             # m/s or rad/s: a pose's velocities show a command this closely
REMEMBERED = 64         # commands kept (a lag is at most this)
SAMPLES = 9             # lags measured, the median of which is the lag
GIVE_UP = 60            # commands after which a change never seen is no longer waited for
DEADLINE_FACTOR, DEADLINE_SLACK = 3.0, 3.0   # a stroke's deadline: this times its time, plus s
ROUND_TRIPS = 20        # ... plus this many of the longest lag (a slow network's cost)


def signature(command):
    """What a pose reports of a command: its speed and its turn."""
    return math.hypot(command[0], command[1]), command[2]


def shows(pose, command):
    """Whether `pose` reports moving with `command` (x, y, angular)."""
    return (abs(pose.linear_velocity - math.hypot(command[0], command[1])) < SAME
            and abs(pose.angular_velocity - command[2]) < SAME)


def _alike(a, b):
    return all(abs(x - y) < SAME for x, y in zip(signature(a), signature(b)))


class Latency:
    """The commands sent, and how many poses a change of command takes to show."""

    def __init__(self):
        self.sent = deque(maxlen=REMEMBERED)
        self.lags = deque(maxlen=SAMPLES)
        self.count = 0
        self.waiting = None     # (number, time, command) of a change sent and not yet shown

    def sending(self, command, now):
        """A command sent. One unlike any of the last REMEMBERED, as a pose
        reports them, is timed: the first pose like it shows it."""
        command = tuple(command)
        if self.waiting is not None and self.count - self.waiting[0] > GIVE_UP:
            self.waiting = None         # never shown (another came first): measure anew
        if self.waiting is None and not any(_alike(command, sent) for sent in self.sent):
            self.waiting = (self.count, now, command)
        self.sent.append(command)
        self.count += 1

    def seen(self, pose, now):
        if self.waiting is not None and shows(pose, self.waiting[2]):
            self.lags.append(max(0, round((now - self.waiting[1]) / SIM_TICK) - 1))
            self.waiting = None

    @property
    def lag(self) -> int:
        """Ticks a command takes to show beyond the next one (0: no delay)."""
        return int(statistics.median(self.lags)) if self.lags else 0

    @property
    def most(self) -> int:
        """The longest lag measured lately."""
        return max(self.lags) if self.lags else 0

    @property
    def spread(self) -> int:
        """How much the lag varies (the middle half of its samples): jitter, in poses."""
        if len(self.lags) < 4:
            return 0
        lags = sorted(self.lags)
        return lags[3 * len(lags) // 4] - lags[len(lags) // 4]

    def seconds(self) -> float:
        """About how long a command takes to act, as measured."""
        return (self.lag + 1) * SIM_TICK

    def in_flight(self, since=0) -> List[tuple]:
        """The commands sent that the newest pose does not show yet, oldest
        first; of them, only those from number `since` on."""
        lag = min(self.lag, len(self.sent), max(0, self.count - since))
        return list(self.sent)[len(self.sent) - lag:] if lag else []

    def shown(self) -> int:
        """The number of the command the newest pose shows (-1: none yet)."""
        return self.count - 1 - self.lag


class Ahead:
    """A pose as the commands in flight will leave it, as turtlesim moves a
    turtle each tick: turn first, then move along the new heading."""

    def __init__(self, pose, commands):
        x, y, theta = pose.x, pose.y, pose.theta
        for linear_x, linear_y, angular in commands:
            theta += angular * SIM_TICK
            x += (math.cos(theta) * linear_x - math.sin(theta) * linear_y) * SIM_TICK
            y += (math.sin(theta) * linear_x + math.cos(theta) * linear_y) * SIM_TICK
        self.x, self.y, self.theta = x, y, math.atan2(math.sin(theta), math.cos(theta))
        last = commands[-1] if commands else None
        self.linear_velocity = math.hypot(last[0], last[1]) if last else pose.linear_velocity
        self.angular_velocity = last[2] if last else pose.angular_velocity


class Deadline:
    """A stroke's deadline: DEADLINE_FACTOR times the time it takes, plus
    DEADLINE_SLACK s, plus ROUND_TRIPS of the longest lag measured (each
    correction of a stroke waits for the commands before it to show, so a
    slow network's cost grows with its delay), from `now`; time spent
    paused does not count."""

    def __init__(self, seconds, now, latency=None):
        self.latency = latency
        self.planned = DEADLINE_FACTOR * seconds + DEADLINE_SLACK
        self.started = now
        self.paused_for, self.last = 0.0, now

    @property
    def allowed(self) -> float:
        worst = (self.latency.most + 1) * SIM_TICK if self.latency is not None else 0.0
        return self.planned + ROUND_TRIPS * worst

    def passed(self, now, paused=False) -> bool:
        if paused:
            self.paused_for += now - self.last
        self.last = now
        return now > self.started + self.paused_for + self.allowed

    def says(self, turtle, stroke, latency) -> str:
        return (f"turtle {turtle} did not reach the stroke's end ({stroke}) within "
                f'{self.allowed:.0f} s; commands take about {1000 * latency.seconds():.0f} ms '
                f'to act')
