"""How cleanly ink makes its letters, as a TA judges a drawing, whatever
font it follows: straight where straight and round where round, closed
where it closes. No ROS here.

A turtle draws lines and arcs: a move, or a move while turning. Each line
of ink is cut at its corners (a turn on the spot), and each piece is fitted
by a straight line or a circle's arc; a piece neither fits is split where
its two halves fit best (an S's two arcs, a J's stem and hook), down to
pieces SHORTEST of the height long: a weave shorter than that is no
letter's shape, and strays. (A turn of a wrong angle is a corner like
any other: the readers judge the letter's proportions, not this. Nor is
a staircase told from a letter's serifs: a turtle that turns on the spot
every few centimetres, each step RUN of the height or more, draws
corners, and strays nowhere.) How far the ink strays from the lines
and arcs it draws is its wobble (a controller that overshoots and weaves).
A line whose end comes back near itself but misses it (an O, a P's bowl
drawn in one stroke) leaves a gap. Proportions are the readers' to judge:
a letter read is one a reader accepts. (On 29 drawings of real classes,
turtlesim's own ink strays at most 1.44% of its height: doc/grading.md.)
The ink is thinned to points 0.5% of the height apart, and to POINTS at
most, more coarsely spaced for longer ink (a flood of turtles): the cost
is bounded.
"""
import math
from typing import NamedTuple

import numpy

from .ink import box, length, thinned, turns_along
from .rows import without_specks

CORNER = 25.0       # degrees a line turns at one point, past which it may be a corner
RUN = 0.02          # ... this share of the height or more along from the corner before
SHORTEST = 0.25     # share of the height a piece is at least, where it is split further
STRAIGHT = 0.005    # share of the height a piece may stray and not be split
CLOSE = (0.02, 0.12)    # shares of the height an end misses its own line by: a gap
POINTS = 4000       # points of ink fitted, at most


class Strays(NamedTuple):
    wobble: float       # the farthest the ink strays from its lines and arcs, share of the height
    gap: float          # the widest gap a line leaves where it comes back to itself (0: none)


def strays(ink) -> Strays:
    """How cleanly `ink` (lines of (x, y)) makes its letters: Strays."""
    ink = without_specks([[tuple(p) for p in line] for line in ink if len(line)])
    points = [p for line in ink for p in line]
    height = box(points)[3] if len(points) > 1 else 0.0
    if height <= 0:
        return Strays(0.0, 0.0)
    lines = [numpy.asarray(line, dtype=float)
             for line in thinned(ink, max(height / 200, length(ink) / POINTS)) if len(line) > 1]
    wobble = max((_stray(piece) for line in lines for part in _between_corners(line, height)
                  for piece in _pieces(part, height)), default=0.0)
    return Strays(wobble / height, max((_gap(line, height) for line in lines), default=0.0))


def _between_corners(line, height):
    """`line` (an array of points) cut at its corners: where it turns more
    than CORNER at one point, RUN of the height or more along it from the
    corner before (or its start) and to its end."""
    along = numpy.r_[0.0, numpy.cumsum(numpy.hypot(*numpy.diff(line, axis=0).T))]
    cuts = [0]
    for i in numpy.flatnonzero(numpy.abs(turns_along(line)) > CORNER) + 1:
        if along[i] - along[cuts[-1]] >= RUN * height <= along[-1] - along[i]:
            cuts.append(int(i))
    cuts.append(len(line) - 1)
    return [line[a:b + 1] for a, b in zip(cuts, cuts[1:]) if b > a]


def _pieces(part, height):
    """`part` as pieces each fitted by a line or an arc: split in two where
    the halves fit best, while it strays more than STRAIGHT of the height
    and both halves are SHORTEST of it long or more (a dozen splits tried)."""
    along = numpy.r_[0.0, numpy.cumsum(numpy.hypot(*numpy.diff(part, axis=0).T))]
    shortest = SHORTEST * height
    splits = [i for i in range(2, len(part) - 2)
              if along[i] >= shortest and along[-1] - along[i] >= shortest]
    if not splits or _stray(part) <= STRAIGHT * height:
        return [part]
    tried = splits[::max(1, len(splits) // 12)]
    best = min(tried, key=lambda i: max(_stray(part[:i + 1]), _stray(part[i:])))
    return _pieces(part[:best + 1], height) + _pieces(part[best:], height)


def _stray(points):
    """How far `points` lie from the line or the circle's arc that fits them best."""
    if len(points) < 3:
        return 0.0
    middle = points.mean(axis=0)
    across = numpy.linalg.svd(points - middle)[2][1]    # the line's normal
    off_line = numpy.abs((points - middle) @ across).max()
    x, y = points[:, 0], points[:, 1]       # the circle x² + y² = ax + by + c, least squares
    (a, b, c), *_ = numpy.linalg.lstsq(numpy.column_stack((x, y, numpy.ones(len(x)))),
                                       x * x + y * y, rcond=None)
    cx, cy = a / 2, b / 2
    radius = math.sqrt(max(c + cx * cx + cy * cy, 0.0))
    off_arc = numpy.abs(numpy.hypot(x - cx, y - cy) - radius).max()
    return float(min(off_line, off_arc))


def _gap(line, height):
    """The widest miss of `line`'s ends by the line itself, away from the
    end by SHORTEST of the height along it, where within CLOSE (0 if none):
    an O that does not close, a P's bowl that stops short of its stem."""
    along = numpy.r_[0.0, numpy.cumsum(numpy.hypot(*numpy.diff(line, axis=0).T))]
    widest = 0.0
    for end, far in ((line[0], along > SHORTEST * height),
                     (line[-1], along < along[-1] - SHORTEST * height)):
        if far.any():
            miss = numpy.hypot(*(line[far] - end).T).min() / height
            if CLOSE[0] < miss < CLOSE[1]:
                widest = max(widest, float(miss))
    return widest
