"""Angles, headings and distances on turtlesim's canvas. No ROS here."""
import math
from typing import NamedTuple

# Poses come as float32: a heading read from one may be a few microradians
# off the plan's, and that must not make a full turn of an almost-zero one.
ANGLE_TOLERANCE = 1e-5      # rad
SAME_POINT = 1e-5           # m: a float32 pose is up to a micrometre off the point it stands on
TURN_DIRECTIONS = ('ccw', 'shortest')


class PlannedPose(NamedTuple):
    """Where the plan has the turtle: the start or end of a path."""
    x: float
    y: float
    heading: float


def wrap(angle: float) -> float:
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def turn_between(heading: float, target: float, direction: str) -> float:
    """The turn from one heading to another: always counter-clockwise (the
    lab's way, 0 to 2 pi) or the shorter way (-pi to pi)."""
    if direction == 'ccw':
        angle = (target - heading) % (2.0 * math.pi)
        if angle < ANGLE_TOLERANCE or math.isclose(angle, 2.0 * math.pi, abs_tol=ANGLE_TOLERANCE):
            return 0.0
        return angle
    angle = wrap(target - heading)
    return 0.0 if abs(angle) < ANGLE_TOLERANCE else angle


def distance_to_segment(q, a, b) -> float:
    """How far point q is from the segment a-b."""
    abx, aby = b[0] - a[0], b[1] - a[1]
    length2 = abx * abx + aby * aby
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((q[0] - a[0]) * abx + (q[1] - a[1]) * aby)
                                              / length2))
    return math.hypot(q[0] - a[0] - t * abx, q[1] - a[1] - t * aby)
