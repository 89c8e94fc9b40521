"""From strokes to motion primitives. No ROS here.

A drawing is a list of primitives: Turn (in place), Line (straight ahead),
Pen (up or down) and Written (a letter written in the lab's own calls).
Turn and Line carry both the relative amount (what the lab's timed
primitives use) and the absolute target in the world (what feedback mode
steers to).
"""
import math
from typing import Callable, List, NamedTuple, Optional, Tuple

from .geometry import ANGLE_TOLERANCE, SAME_POINT, PlannedPose, turn_between, wrap
from .written import record, turn_as_told


class Turn(NamedTuple):
    angle: float            # radians, counter-clockwise positive
    heading: float          # the heading it ends at


class Line(NamedTuple):
    length: float           # meters, forward
    x: float                # where it ends
    y: float
    heading: float          # the heading it is driven at


class Pen(NamedTuple):
    down: bool
    colour: Optional[Tuple[int, int, int]] = None     # when down: None is the node's ~pen


class Written(NamedTuple):
    """A letter whose `program` (font.Writer's) timed mode runs as it is
    written, `scale` times its size and turning the `direction` way, from
    the letter's corner facing +x; `steps` are the Turns and Lines of its
    calls there (what feedback mode steers)."""
    program: Callable
    scale: float
    direction: str
    steps: list


def path(points: List[Tuple[float, float]], start: PlannedPose, direction: str):
    """Primitives that drive from `start` through `points`; returns them and the end pose."""
    primitives = []
    x, y, heading = start
    for px, py in points:
        length = math.hypot(px - x, py - y)
        if length < SAME_POINT:
            continue
        target = math.atan2(py - y, px - x)
        angle = turn_between(heading, target, direction)
        if abs(angle) > ANGLE_TOLERANCE:
            primitives.append(Turn(angle, target))
        heading = target
        primitives.append(Line(length, px, py, heading))
        x, y = px, py
    return primitives, PlannedPose(x, y, heading)


def written_steps(writer, scale, start: PlannedPose, direction: str):
    """The Turns and Lines of a written letter's calls from `start`; and the end pose."""
    steps = []
    x, y, heading = start
    for call, amount in record(writer.program):
        if call == 'rotate':
            angle = math.radians(turn_as_told(amount, direction))
            heading = wrap(heading + angle)
            steps.append(Turn(angle, heading))
        else:
            x, y = x + amount * scale * math.cos(heading), y + amount * scale * math.sin(heading)
            steps.append(Line(amount * scale, x, y, heading))
    return steps, PlannedPose(x, y, heading)


def pen_changes(strokes, colours, here):
    """For each stroke, in order: (stroke, colour, travel), where travel
    says the pen goes up to reach the stroke's start from where the last
    one ended (from `here` for the first), and colour is the pen's for the
    stroke (None: ~pen) when it must be put down, else False (it is down
    already in that colour)."""
    ink = None
    for stroke, colour in zip(strokes, colours or [None] * len(strokes)):
        travel = math.hypot(stroke[0][0] - here[0], stroke[0][1] - here[1]) > SAME_POINT
        yield stroke, (colour if travel or colour != ink else False), travel
        ink, here = colour, stroke[-1]


def plan_strokes(strokes, start: PlannedPose, direction: str = 'ccw', colours=None,
                 writers=None, size=None):
    """Primitives that draw `strokes` (in meters) in this order, starting
    from the turtle's `start` pose; returns them and the end pose. `colours`
    (a picture's): each stroke's pen colour, None for the node's own.
    `writers` (a text's): each stroke's font.Writer, or None; a written
    stroke is drawn by its letter's calls at letter height `size`, from its
    first point facing +x.

    The pen is lifted only to travel to a stroke that does not start where
    the turtle is, so the lab's N from its start point is exactly the lab's
    six calls.
    """
    primitives, pose = [], start
    writers = writers or [None] * len(strokes)
    for (stroke, colour, travel), writer in zip(pen_changes(strokes, colours, start), writers):
        if travel:
            moves, pose = path(stroke[:1], pose, direction)
            primitives += [Pen(False)] + moves
        if writer is not None and abs(turn_between(pose.heading, 0.0, direction)) > 0.0:
            primitives.append(Turn(turn_between(pose.heading, 0.0, direction), 0.0))
            pose = pose._replace(heading=0.0)
        if colour is not False:
            primitives.append(Pen(True, colour))
        if writer is None:
            drawn, pose = path(stroke[1:], pose, direction)
            primitives += drawn
        else:
            steps, pose = written_steps(writer, size / writer.size, pose, direction)
            primitives.append(Written(writer.program, size / writer.size, direction, steps))
    return primitives, pose
