"""Ticks of a turtlesim as the viewer and the executors hear them, for
their unit tests. No ROS here."""
import math
import struct
from typing import NamedTuple


class PoseMessage(NamedTuple):
    """The fields of turtlesim/Pose, without ROS."""
    x: float
    y: float
    theta: float
    linear_velocity: float
    angular_velocity: float


def f32(value):
    """Pose fields travel as float32."""
    return struct.unpack('f', struct.pack('f', value))[0]


def sample(turtle):
    """A simulated turtle's pose, as turtlesim publishes it."""
    return PoseMessage(f32(turtle.x), f32(turtle.y), f32(turtle.theta),
                       f32(turtle.linear_speed), f32(turtle.angular))


def drive(trails, name, points, colour):
    """A tick per point, each step driven at the speed it takes in a tick:
    the pose, then the colour under it, as turtlesim publishes them."""
    last = trails.turtles.get(name)
    for x, y in points:
        step = (x - last[0], y - last[1]) if last else (0.0, 0.0)
        trails.pose(name, x, y, math.atan2(step[1], step[0]), math.hypot(*step) / 0.016)
        trails.colour(name, colour)
        last = (x, y)
