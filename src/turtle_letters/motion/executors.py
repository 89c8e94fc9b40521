"""Executors: what to command on each simulator tick to carry out one
primitive (a Turn or a Line of plan.py). No ROS here.

Turtlesim advances a fixed 16 ms per tick and publishes one pose per tick,
whatever the wall clock says (a loaded machine makes ticks late, not longer).
An executor is called once per pose (anything with turtlesim/Pose's fields)
and answers with the command for the next tick, or None when it is done.

- Timed (the lab's way, open loop): a primitive lasts amount / speed seconds,
  and position is never looked at. On the simulator's clock (the default)
  elapsed time is counted from the velocities the pose reports the simulator
  used, and the last tick gets the fraction of the speed that completes the
  amount: exact on any machine. A tick that went too far because a command
  came late (a busy machine, a network) is taken back: the turtle backs up,
  or turns back, along its own line; over a slow network it slows into
  the end (APPROACH), so that a command held up runs on less past it. On
  the wall clock, as the lab's rospy.Time.now() loop does, it commands the
  speed until amount / speed seconds have passed; a busy machine slows the
  simulator's ticks, so the turtle then comes up short.
- Feedback (closed loop on the pose): steer to the primitive's absolute target
  in the turtle's own frame. Each command is at most half the remaining error
  per tick, so a command the simulator applies twice (it arrived a tick late)
  still lands on the target instead of overshooting it.
"""
import math
import time
from typing import Callable, NamedTuple, Optional

from ..letters.geometry import wrap
from ..letters.layout import SIM_TICK
from ..letters.primitives import Turn
from .latency import Ahead, shows

SETTLED = 1e-5              # m or rad: a timed primitive is done this close to its amount
SETTLE_TICKS = 4            # a timed primitive's way back is spread over this many ticks
# Over a slow network a timed primitive slows into its end no harder than this (m/s^2,
# or rad/s^2): a command held up on its way leaves turtlesim driving the one before it
# on, and the slower that one, the less ink runs past the end.
APPROACH = 1.0
POSITION_TOLERANCE = 1e-4   # m: feedback stops this close to a vertex
HEADING_TOLERANCE = 1e-4    # rad
# Over a slow network a pose is a guess (where the commands in flight lead):
# done this close to it, the turtle is within a few mm of it.
LATE_POSITION_TOLERANCE, LATE_HEADING_TOLERANCE = 1e-3, 1e-3
TURN_PER_TICK = 0.05        # rad: smooth mode turns at most 3.1 rad/s
SHARP = 0.1                 # rad: over a slow network, smooth mode waits at a vertex turning more
ON_COURSE = 1e-5            # rad: smooth mode holds its command while it faces the vertex this closely


class Command(NamedTuple):
    linear_x: float = 0.0
    linear_y: float = 0.0
    angular: float = 0.0


STOP = Command()


def _clamp(value: float, limit: float) -> float:
    return max(-limit, min(limit, value))


class TimedExecutor:
    """Turn or drive for amount / speed seconds, on the simulator's clock
    ('sim') or the wall clock ('wall', read with `now`)."""

    def __init__(self, primitive, linear_speed: float, angular_speed: float,
                 clock: str = 'sim', now: Callable[[], float] = time.monotonic,
                 latency=None) -> None:
        self.latency = latency      # commands in flight, counted in (sim clock)
        self.first = latency.count if latency else 0    # the number of our first command
        self.turning = isinstance(primitive, Turn)
        amount = primitive.angle if self.turning else primitive.length
        self.sign = 1.0 if amount >= 0 else -1.0
        self.amount = abs(amount)
        self.speed = angular_speed if self.turning else linear_speed
        self.clock = clock
        self.now = now
        self.elapsed_amount = 0.0
        self.started_at = None
        # Sim clock: the way the turtle is told to go now (+1 along the
        # primitive, -1 back), whether it is told to stand, and the speed
        # cap of this round (the first at full speed; see update()).
        self.way = 1.0
        self.stopping = False
        self.stops = 0          # stops sent in a row
        self.cap = self.speed

    def _on_the_way(self) -> float:
        """How much of the amount our commands in flight will still make."""
        if self.latency is None or self.clock == 'wall':
            return 0.0
        part = 2 if self.turning else 0
        return sum(c[part] * self.sign * SIM_TICK for c in self.latency.in_flight(self.first))

    def _approach(self, remaining) -> float:
        """The speed from which the turtle stops within `remaining` slowing at
        APPROACH, over a slow network (none is needed otherwise: each command
        acts at the next tick)."""
        if self.latency is None or not self.latency.lag:
            return math.inf
        return math.sqrt(2 * APPROACH * remaining)

    def _command(self) -> Optional[Command]:
        remaining = (self.amount - self.elapsed_amount - self._on_the_way()) * self.way
        if remaining <= 1e-9:
            if self.clock == 'wall':
                return None
            self.stopping = True
            self.stops += 1
            return STOP
        if self.clock == 'wall':
            speed = self.speed
        else:
            speed = self.way * min(self.cap, remaining / SIM_TICK, self._approach(remaining))
        speed *= self.sign
        return Command(angular=speed) if self.turning else Command(linear_x=speed)

    def start(self, pose) -> Optional[Command]:
        """The first command, sent at once (the pose is not needed)."""
        self.started_at = self.now()
        return self._command()

    def update(self, pose) -> Optional[Command]:
        """On the sim clock, a primitive ends when a pose shows the turtle
        standing and the amount used is right. A command that came a tick
        late makes it go too far: then it goes back the difference, spread
        over SETTLE_TICKS ticks so that a late stop costs a quarter of it,
        and so on until it is right; over a network whose delay varies, over
        4 ticks more for each tick it varies by, since a late or bunched
        command there acts a tick more or less. (A pose's linear velocity has no sign;
        between two stops every command goes the same way.)"""
        if self.clock == 'wall':
            # The command sent now moves the turtle on the next tick: it is
            # sent while that tick ends nearer the time up than short of it.
            ahead = self.now() - self.started_at + SIM_TICK / 2
            self.elapsed_amount = self.speed * ahead
            return self._command()
        used = abs(pose.angular_velocity if self.turning else pose.linear_velocity)
        self.elapsed_amount += self.way * used * SIM_TICK
        if self.stopping:
            if used or self.stops <= self._stops_to_show():
                self.stops += 1
                return STOP                      # the stop has not come yet
            error = self.amount - self.elapsed_amount
            if abs(error) <= SETTLED:
                return None
            self.way = 1.0 if error > 0 else -1.0
            spread = self.latency.spread if self.latency is not None else 0
            self.cap = min(self.speed, abs(error) / ((SETTLE_TICKS + 4 * spread) * SIM_TICK))
            self.stopping, self.stops = False, 0
        return self._command()

    def _stops_to_show(self) -> int:
        """Stops sent before a standing pose surely shows them: over a slow
        network, one might show a stop from before our last commands."""
        lag = self.latency.lag if self.latency is not None else 0
        return self.latency.most + 2 if lag else 0


class FeedbackExecutor:
    """Reach the primitive's absolute heading or point, measured on the pose."""

    def __init__(self, primitive, linear_speed: float, angular_speed: float,
                 latency=None) -> None:
        self.latency = latency      # the pose is taken where the commands in flight lead
        self.primitive = primitive
        self.linear_speed = linear_speed
        self.angular_speed = angular_speed
        # A counter-clockwise turn of more than half a circle must not be
        # taken the short way round: count what is left of it.
        self.turn_left = primitive.angle if isinstance(primitive, Turn) else 0.0
        self.last_theta = None

    def start(self, pose) -> Optional[Command]:
        """The first command, from the latest pose, sent at once."""
        return self.update(pose)

    def update(self, pose) -> Optional[Command]:
        # Over a slow network: the pose its commands in flight lead to, and
        # a gentler approach the more the delay varies (a late command is
        # used twice, an overtaken one never).
        # It is done only once the late pose shows it too: what was guessed
        # of the commands in flight has come true.
        ticks, near, turned, seen = 2, POSITION_TOLERANCE, HEADING_TOLERANCE, pose
        if self.latency is not None and self.latency.lag:
            pose = Ahead(pose, self.latency.in_flight())
            ticks += 2 * self.latency.spread
            near, turned = LATE_POSITION_TOLERANCE, LATE_HEADING_TOLERANCE
        if self.last_theta is not None:
            self.turn_left -= wrap(pose.theta - self.last_theta)
        self.last_theta = pose.theta
        heading_error = wrap(self.primitive.heading - pose.theta)
        if isinstance(self.primitive, Turn) and abs(self.turn_left) > math.pi / 2:
            heading_error = self.turn_left
        angular = _clamp(heading_error / (ticks * SIM_TICK), self.angular_speed)
        seen_heading = abs(wrap(self.primitive.heading - seen.theta)) < turned
        if isinstance(self.primitive, Turn):
            if abs(heading_error) < turned and seen_heading:
                return None
            return Command(angular=angular)

        dx, dy = self.primitive.x - pose.x, self.primitive.y - pose.y
        cos_t, sin_t = math.cos(pose.theta), math.sin(pose.theta)
        ahead, left = cos_t * dx + sin_t * dy, -sin_t * dx + cos_t * dy
        seen_there = math.hypot(self.primitive.x - seen.x, self.primitive.y - seen.y) < near
        if math.hypot(ahead, left) < near and abs(heading_error) < turned and seen_there \
                and seen_heading:
            return None
        vx, vy = ahead / (ticks * SIM_TICK), left / (ticks * SIM_TICK)
        scale = min(1.0, self.linear_speed / max(math.hypot(vx, vy), 1e-12))
        return Command(vx * scale, vy * scale, angular)


class SmoothExecutor:
    """Trace a polyline at the linear speed, without stopping at its vertices.

    Turtlesim turns first and then moves along the NEW heading, with
    linear.x ahead and linear.y to the left, so a command can move the turtle
    by any displacement in one tick, whatever way it faces. Each tick's move
    is a straight line, so a tick that would pass a vertex is cut short to
    land on it exactly: every move lies on one edge, and the drawn line is the
    stroke. Closed loop: every move is worked out from the pose just read, and
    a vertex counts as reached only when a pose shows the turtle on it.

    Meanwhile the turtle turns to face along the edge, by at most TURN_PER_TICK
    a tick. A command that comes late (a busy machine) finds turtlesim using
    the one before once more: the turtle runs on along its line, a tick's
    move (linear_speed x 16 ms) past a vertex for each tick it is late, and
    heads from there for the next vertex. A turn used twice
    would also bend the next move off the line, by as much as that turn: hence
    small turns. Nothing else is given up to lateness, since slowing down
    before each vertex to make up for it would cost more time than it saves.
    """

    def __init__(self, points, linear_speed: float, latency=None) -> None:
        self.latency = latency      # the pose is taken where the commands in flight lead
        self.points = list(points)
        self.step = linear_speed * SIM_TICK
        self.next = 0           # index of the vertex to reach next
        self.came_from = None   # where the turtle stood at the start

    def start(self, pose) -> Optional[Command]:
        self.came_from = (pose.x, pose.y)
        return self.update(pose)

    def _turns_at(self, i) -> bool:
        """Whether the line turns at vertex `i` by more than SHARP (the last always does)."""
        if i + 1 >= len(self.points) or (i == 0 and self.came_from is None):
            return True
        before = self.points[i - 1] if i else self.came_from
        here, after = self.points[i], self.points[i + 1]
        return abs(wrap(math.atan2(after[1] - here[1], after[0] - here[0]) -
                        math.atan2(here[1] - before[1], here[0] - before[0]))) > SHARP

    def update(self, pose) -> Optional[Command]:
        # Over a slow network: the pose its commands in flight lead to; the
        # more the delay varies, the more gently a vertex is come to (a late
        # command is used twice, an overtaken one never), and a vertex where
        # the line turns is left only once the late pose shows it reached.
        near, gentle, seen, late = POSITION_TOLERANCE, 0, pose, False
        if self.latency is not None and self.latency.lag:
            pose = Ahead(pose, self.latency.in_flight())
            near, gentle, late = LATE_POSITION_TOLERANCE, self.latency.spread, True
        x, y = pose.x, pose.y
        while self.next < len(self.points) and math.hypot(
                self.points[self.next][0] - x, self.points[self.next][1] - y) < near:
            vertex = self.points[self.next]
            if late and self._turns_at(self.next) and \
                    math.hypot(vertex[0] - seen.x, vertex[1] - seen.y) >= near:
                return STOP     # there, by the guess: wait for the pose to show it
            self.next += 1
        if self.next == len(self.points):
            return None
        vx, vy = self.points[self.next]
        dx, dy = vx - x, vy - y
        distance = math.hypot(dx, dy)
        turn = _clamp(wrap(math.atan2(vy - y, vx - x) - pose.theta), TURN_PER_TICK)
        step = self.step
        if gentle and distance < (2 + gentle) * step:
            step = distance / (1 + gentle)
        if distance > step and abs(turn) < ON_COURSE:
            # Straight at the vertex: the same command each tick, which the
            # driver need not send again (a long edge costs a few messages).
            return Command(step / SIM_TICK, 0.0, 0.0)
        if distance > step:                         # not this tick: go on along the edge
            dx, dy = dx * step / distance, dy * step / distance
        new_theta = pose.theta + turn               # the heading turtlesim moves along
        cos_t, sin_t = math.cos(new_theta), math.sin(new_theta)
        return Command((cos_t * dx + sin_t * dy) / SIM_TICK, (-sin_t * dx + cos_t * dy) / SIM_TICK,
                       turn / SIM_TICK)


class StallWatch:
    """Notices a turtle that does not move as commanded although its poses
    come: commands that never reach the simulator, or another node's
    commands on the same cmd_vel. Turtlesim reports in each pose the
    velocities it moved the turtle with; they must be one of the commands
    sent lately (a command takes a tick or two to arrive)."""

    def __init__(self, limit: float = 1.0, remembered: int = 8) -> None:
        self.limit = limit              # s of disobedience before it counts
        self.remembered = remembered    # how many recent commands may show
        self.recent = []
        self.since = None

    def sent(self, command) -> None:
        self.recent = (self.recent + [tuple(command)])[-self.remembered:]

    def stalled(self, pose, now: float) -> bool:
        """Whether, at `now` (s), the turtle has disobeyed for `limit` s."""
        obeyed = any(shows(pose, c) for c in self.recent)
        if obeyed or not any(any(c) for c in self.recent):     # obeying, or told to stand
            self.since = None
            return False
        if self.since is None:
            self.since = now
        return now - self.since >= self.limit


CLOCKS = ('sim', 'wall')
