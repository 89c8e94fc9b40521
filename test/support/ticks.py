"""Ticks of a turtlesim as the viewer and the executors hear them, for
their unit tests. No ROS here."""
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
    """A tick per point: the pose, then the colour under it, as turtlesim publishes them."""
    for x, y in points:
        trails.pose(name, x, y, 0.0)
        trails.colour(name, colour)
