"""From letters to motion primitives, and where on the canvas letters go.

No ROS here. A drawing is a list of primitives: Turn (in place), Line
(straight ahead) and Pen (up or down). Each carries both the relative amount
(what the lab's timed primitives use) and the absolute target in the world
(what feedback mode steers to).
"""
import math
from typing import List, NamedTuple, Optional, Tuple

from .font import BUILTIN, Font, Glyph

WORLD_SIZE = 499 / 45.0     # turtlesim's usable canvas, meters
MARGIN = 0.5                # no stroke comes closer than this to a wall
TURN_DIRECTIONS = ('ccw', 'shortest')
# Poses come as float32: a heading read from one may be a few microradians
# off the plan's, and that must not make a full turn of an almost-zero one.
ANGLE_TOLERANCE = 1e-5      # rad
SAME_POINT = 1e-5           # m: a float32 pose is up to a micrometre off the point it stands on


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


class PlannedPose(NamedTuple):
    """Where the plan has the turtle: the start or end of a path."""
    x: float
    y: float
    heading: float


def distance_to_segment(q, a, b) -> float:
    """How far point q is from the segment a-b."""
    abx, aby = b[0] - a[0], b[1] - a[1]
    length2 = abx * abx + aby * aby
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((q[0] - a[0]) * abx + (q[1] - a[1]) * aby)
                                              / length2))
    return math.hypot(q[0] - a[0] - t * abx, q[1] - a[1] - t * aby)


def shown(text: str, limit: int = 40) -> str:
    """`text` quoted for a log line: at most `limit` characters of it."""
    return repr(text if len(text) <= limit else text[:limit] + '...')


class DoesNotFit(ValueError):
    """The request would take the turtle outside the canvas' margins."""


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


def glyph_strokes(glyph: Glyph, origin: Tuple[float, float], size: float):
    """The glyph's strokes in world meters, its bottom-left corner at `origin`."""
    ox, oy = origin
    return [[(ox + size * gx, oy + size * gy) for gx, gy in stroke] for stroke in glyph.strokes]


def plan_strokes(strokes, start: PlannedPose, direction: str = 'ccw', colours=None):
    """Primitives that draw `strokes` (in meters) in this order, starting
    from the turtle's `start` pose; returns them and the end pose. `colours`
    (a picture's): each stroke's pen colour, None for the node's own.

    The pen is lifted only to travel to a stroke that does not start where
    the turtle is, so the lab's N from its start point is exactly the lab's
    six primitives.
    """
    primitives = []
    pose = start
    ink = None
    for stroke, colour in zip(strokes, colours or [None] * len(strokes)):
        if math.hypot(stroke[0][0] - pose.x, stroke[0][1] - pose.y) > SAME_POINT:
            travel, pose = path(stroke[:1], pose, direction)
            primitives += [Pen(False)] + travel + [Pen(True, colour)]
        elif colour != ink:
            primitives.append(Pen(True, colour))
        ink = colour
        drawn, pose = path(stroke[1:], pose, direction)
        primitives += drawn
    return primitives, pose


def plan_glyph(glyph: Glyph, origin: Tuple[float, float], size: float, start: PlannedPose,
               direction: str = 'ccw'):
    """Primitives that draw `glyph` with its bottom-left corner at `origin`."""
    return plan_strokes(glyph_strokes(glyph, origin, size), start, direction)


def word_strokes(text: str, places, size: float, font: Font = BUILTIN):
    """Every stroke of `text` in meters, in reading order (places from Layout)."""
    return [stroke for char, place in zip(text, places) if place is not None
            for stroke in glyph_strokes(font.glyph(char), place, size)]


def glyph_for(char: str, font: Font = BUILTIN) -> Optional[Glyph]:
    return font.glyph(char)


def largest_size(font: Font = BUILTIN) -> float:
    """The largest letter height at which the font's widest glyph fits."""
    return (WORLD_SIZE - 2 * MARGIN) / max(font.ascent + font.descent,
                                           font.widest + 2 * font.overhang)



class Layout:
    """Letter places on the canvas, like a typewriter: the first at
    `first_place`, then to the right, then a new line below at the left
    margin; when the canvas is full, it is cleared and we start again.

    With `bounds` (a part of a shared canvas, see parts.py) the letters stay
    inside that box instead, and new lines start below the first place."""

    def __init__(self, first_place: Tuple[float, float], size: float,
                 font: Font = BUILTIN, bounds=None) -> None:
        self.size = size
        self.font = font
        self.bounds = bounds
        if bounds is not None:
            self.left = first_place[0]
        else:
            self.left = MARGIN + font.overhang * size     # where a new line starts
            if not self.fits_at(*first_place, font.widest):
                # The turtle starts too near a wall for this size: begin top left.
                first_place = (self.left, WORLD_SIZE - MARGIN - font.ascent * size)
        self.first_place = first_place
        self.cursor = first_place

    def fits_at(self, x: float, y: float, width: float) -> bool:
        low_x, low_y, high_x, high_y = self.bounds or (MARGIN, MARGIN, WORLD_SIZE - MARGIN,
                                                       WORLD_SIZE - MARGIN)
        reach = self.font.overhang * self.size
        slack = 1e-9
        return (low_x <= x - reach + slack and x + width * self.size + reach <= high_x + slack
                and low_y <= y - self.font.descent * self.size + slack
                and y + self.font.ascent * self.size <= high_y + slack)

    def places(self, widths: List[float], cursor: Tuple[float, float], partial=False):
        """Where boxes of these widths go from `cursor`, or None once the
        canvas is full (with `partial`, the places of those that fit). Stops
        at the first that does not fit: the work is bounded by the canvas."""
        x, y = cursor
        placed = []
        for width in widths:
            if not self.fits_at(x, y, width):
                x, y = self.left, y - self.font.line_height * self.size
                if not self.fits_at(x, y, width):
                    return (placed if partial else None), cursor
            placed.append((x, y))
            x += (width + self.font.letter_spacing) * self.size
        return placed, (x, y)

    def how_many_fit(self, widths: List[float]) -> int:
        return len(self.places(widths, self.first_place, partial=True)[0])

    def reserve(self, text: str):
        """Places for every character of `text` (None for a space) and
        whether the canvas must be cleared first; raises DoesNotFit."""
        font = self.font
        widths = [font.space_width if c == ' ' else font.glyph(c).width for c in text]
        placed, cleared = self.reserve_widths(widths, shown(text), 'characters')
        return [None if c == ' ' else p for c, p in zip(text, placed)], cleared

    def reserve_widths(self, widths: List[float], what: str, units: str):
        """Places for boxes of these widths (letter heights) and whether the
        canvas must be cleared first; raises DoesNotFit, naming `what`."""
        placed, cursor = self.places(widths, self.cursor)
        cleared = False
        if placed is None:
            placed, cursor = self.places(widths, self.first_place)
            cleared = True
            if placed is None:
                where = 'on the canvas' if self.bounds is None else "in the turtle's part of the canvas"
                raise DoesNotFit(
                    f'{what} does not fit {where} at size {self.size:g} m: '
                    f'at most {self.how_many_fit(widths)} of its {len(widths)} {units} fit')
        self.cursor = cursor
        return placed, cleared
