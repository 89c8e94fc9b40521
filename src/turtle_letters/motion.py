"""What to command on each simulator tick, for one primitive. No ROS here.

Turtlesim advances a fixed 16 ms per tick and publishes one pose per tick,
whatever the wall clock says (a loaded machine makes ticks late, not longer).
So both executors run on the simulator's clock: they are called once per pose
and answer with the command for the next tick.

- Timed (the lab's way, open loop): a primitive lasts amount / speed seconds
  of simulator time. Elapsed time is counted from the velocities the pose
  reports the simulator used, and the last tick gets the fraction of the speed
  that completes the amount. Position is never looked at.
- Feedback (closed loop on the pose): steer to the primitive's absolute target
  in the turtle's own frame. Each command is at most half the remaining error
  per tick, so a command the simulator applies twice (it arrived a tick late)
  still lands on the target instead of overshooting it.
"""
import math
from typing import NamedTuple, Optional

from .plan import Turn, wrap

SIM_TICK = 0.016            # turtlesim's fixed step, seconds
POSITION_TOLERANCE = 1e-4   # m: feedback stops this close to a vertex
HEADING_TOLERANCE = 1e-4    # rad


class Command(NamedTuple):
    linear_x: float = 0.0
    linear_y: float = 0.0
    angular: float = 0.0


STOP = Command()


class PoseSample(NamedTuple):
    """The fields of turtlesim/Pose this module needs."""
    x: float
    y: float
    theta: float
    linear_velocity: float
    angular_velocity: float


def _clamp(value: float, limit: float) -> float:
    return max(-limit, min(limit, value))


class TimedPrimitive:
    """Turn or drive for amount / speed seconds of simulator time."""

    def __init__(self, primitive, linear_speed: float, angular_speed: float) -> None:
        self.turning = isinstance(primitive, Turn)
        amount = primitive.angle if self.turning else primitive.length
        self.sign = 1.0 if amount >= 0 else -1.0
        self.amount = abs(amount)
        self.speed = angular_speed if self.turning else linear_speed
        self.elapsed_amount = 0.0

    def _command(self) -> Optional[Command]:
        remaining = self.amount - self.elapsed_amount
        if remaining <= 1e-9:
            return None
        speed = self.sign * min(self.speed, remaining / SIM_TICK)
        return Command(angular=speed) if self.turning else Command(linear_x=speed)

    def start(self, pose: PoseSample) -> Optional[Command]:
        """The first command, sent at once (the pose is not needed)."""
        return self._command()

    def update(self, pose: PoseSample) -> Optional[Command]:
        used = pose.angular_velocity if self.turning else pose.linear_velocity
        self.elapsed_amount += abs(used) * SIM_TICK
        return self._command()


class FeedbackPrimitive:
    """Reach the primitive's absolute heading or point, measured on the pose."""

    def __init__(self, primitive, linear_speed: float, angular_speed: float) -> None:
        self.primitive = primitive
        self.linear_speed = linear_speed
        self.angular_speed = angular_speed
        # A counter-clockwise turn of more than half a circle must not be
        # taken the short way round: count what is left of it.
        self.turn_left = primitive.angle if isinstance(primitive, Turn) else 0.0
        self.last_theta = None

    def start(self, pose: PoseSample) -> Optional[Command]:
        """The first command, from the latest pose, sent at once."""
        return self.update(pose)

    def update(self, pose: PoseSample) -> Optional[Command]:
        if self.last_theta is not None:
            self.turn_left -= wrap(pose.theta - self.last_theta)
        self.last_theta = pose.theta
        heading_error = wrap(self.primitive.heading - pose.theta)
        if isinstance(self.primitive, Turn) and abs(self.turn_left) > math.pi / 2:
            heading_error = self.turn_left
        angular = _clamp(heading_error / (2 * SIM_TICK), self.angular_speed)
        if isinstance(self.primitive, Turn):
            if abs(heading_error) < HEADING_TOLERANCE:
                return None
            return Command(angular=angular)

        dx, dy = self.primitive.x - pose.x, self.primitive.y - pose.y
        cos_t, sin_t = math.cos(pose.theta), math.sin(pose.theta)
        ahead, left = cos_t * dx + sin_t * dy, -sin_t * dx + cos_t * dy
        if math.hypot(ahead, left) < POSITION_TOLERANCE and abs(heading_error) < HEADING_TOLERANCE:
            return None
        vx, vy = ahead / (2 * SIM_TICK), left / (2 * SIM_TICK)
        scale = min(1.0, self.linear_speed / max(math.hypot(vx, vy), 1e-12))
        return Command(vx * scale, vy * scale, angular)


EXECUTORS = {'timed': TimedPrimitive, 'feedback': FeedbackPrimitive}
