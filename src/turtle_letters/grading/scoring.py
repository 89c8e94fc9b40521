"""Grading a drawing: a recorded path against the ideal letter. No ROS here.
The grader node (grader.py), the classroom's scoreboard and the benchmark
all score with score().

The ideal letter is this package's plan for it, from where the turtle stood
when it first moved: its strokes, and the straight pen-up moves between
them. A student's controller may draw the strokes in another order; the
figures that judge it do not depend on the order:
- vertex errors: how close the path ever came to each vertex of the strokes;
- off: how far the path strayed from the strokes and the moves between them;
- ink off: the length of path farther than the tolerance from all of those;
- missing strokes: strokes the path passes along for less than half their length;
- closed: the drawing ended on an end of a stroke (the lab's N: its last
  vertex), not short of it.
"""
import math
from typing import List, NamedTuple, Optional

from ..letters.geometry import PlannedPose, distance_to_segment
from ..letters.layout import Layout
from ..letters.plan import text_strokes

COVERED = 0.5               # a stroke the path follows for less of its length is missing
SAMPLE_STEP = 0.05          # m between the points of a stroke checked for coverage
SETTLE = 2.0                # s standing still that end a drawing


class Tolerances(NamedTuple):
    """The lab's, by default: every vertex within 2 cm, and the N closed."""
    vertex: float = 0.02    # m


class Score(NamedTuple):
    vertex_errors: List[float]      # m, for each vertex of the strokes in turn
    worst_vertex: float             # m
    off: float                      # m: the farthest point of the path from the letter
    ink_off: float                  # m of path farther than the tolerance from the letter
    missing: List[int]              # indices of strokes not drawn
    end_error: float                # m from where the drawing ended to the nearest stroke end
    passed: bool
    reason: str                     # one line: why it failed, or what it achieved


def ideal_letter(letter, size, font, start: PlannedPose):
    """The strokes of `letter` at the place a lab's turtle standing at
    `start` draws it, in the order this package draws them."""
    places, _ = Layout((start.x, start.y), size, font).reserve(letter)
    return ideal_text(letter, places, size, font, start)


def ideal_text(text, places, size, font, start: PlannedPose):
    """The strokes of `text` at `places`, in the order this package draws
    them from `start`."""
    return text_strokes(text, places, size, font, start)[0]


def moves_between(strokes, start):
    """The straight pen-up moves from `start` to the first stroke and between strokes."""
    moves, here = [], start
    for stroke in strokes:
        moves.append([here, stroke[0]])
        here = stroke[-1]
    return moves


def distance_to_lines(point, lines):
    """How far `point` is from the nearest of `lines` (polylines, or single points)."""
    return min(math.dist(point, line[0]) if len(line) == 1 else
               min(distance_to_segment(point, a, b) for a, b in zip(line, line[1:]))
               for line in lines)


def vertex_errors(path, vertices):
    """For each vertex, how close the path ever came to it."""
    return [min(math.dist(p, v) for p in path) for v in vertices]


def pieces(line, step=SAMPLE_STEP):
    """A polyline cut into pieces at most `step` long: (middle, length) of each."""
    for a, b in zip(line, line[1:]):
        n = max(1, math.ceil(math.dist(a, b) / step))
        for i in range(n):
            t = (i + 0.5) / n
            yield (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t), math.dist(a, b) / n


def coverage(stroke, path, tolerance):
    """The share of the stroke's length that the path passes within `tolerance` of."""
    cut = list(pieces(stroke))
    if not cut:                     # a dot
        return 1.0 if distance_to_lines(stroke[0], [path]) <= tolerance else 0.0
    near = sum(length for middle, length in cut if distance_to_lines(middle, [path]) <= tolerance)
    return near / sum(length for _, length in cut)


def score(path, strokes, start=None, tolerances: Optional[Tolerances] = None) -> Score:
    """Judge `path` ((x, y) poses, m, from where the turtle first moved)
    against the ideal `strokes`; `start`: where the moves to them begin."""
    tolerance = (tolerances or Tolerances()).vertex
    vertices = [v for stroke in strokes for v in stroke]
    errors = vertex_errors(path, vertices)
    allowed = strokes + moves_between(strokes, start or path[0])
    away = [distance_to_lines(p, allowed) for p in path]
    ink_off = sum(length for middle, length in pieces(path)
                  if distance_to_lines(middle, allowed) > tolerance)
    missing = [i for i, s in enumerate(strokes) if coverage(s, path, tolerance) < COVERED]
    end_error = min(math.dist(path[-1], end) for s in strokes for end in (s[0], s[-1]))
    worst = max(range(len(errors)), key=errors.__getitem__)
    if errors[worst] > tolerance:
        first = next(i for i, e in enumerate(errors) if e > tolerance)   # where it went wrong
        reason = (f'vertex {first + 1} of {len(vertices)} missed by {errors[first] * 1000:.0f} mm '
                  f'(at most {tolerance * 1000:.0f} mm)')
        if first != worst:
            reason += f'; the worst, vertex {worst + 1}, by {errors[worst] * 1000:.0f} mm'
    elif missing:
        reason = f'stroke {missing[0] + 1} of {len(strokes)} missing ({len(missing)} in all)'
    elif end_error > tolerance:
        reason = (f'not closed: the drawing ended {end_error * 1000:.0f} mm from a stroke\'s end '
                  f'(at most {tolerance * 1000:.0f} mm)')
    else:
        reason = (f'every vertex within {errors[worst] * 1000:.2f} mm, closed '
                  f'(at most {tolerance * 1000:.0f} mm)')
    passed = not missing and errors[worst] <= tolerance and end_error <= tolerance
    return Score(errors, errors[worst], max(away), ink_off, missing, end_error, passed, reason)


class DrawingWatch:
    """When a turtle's drawing starts and ends, from its poses (anything
    with turtlesim/Pose's fields), one at a time with the time it came: it
    starts with the first pose that moves, from where the turtle stood, and
    ends once the turtle has stood still for `settle` s. A drawing counts
    only if the turtle was seen standing for `ready` s before it: a watch
    that joins in the middle of a drawing (or sees it stop for a moment
    between two strokes) waits for the next one."""

    def __init__(self, settle: float = SETTLE, ready: float = 0.3) -> None:
        self.settle, self.ready = settle, ready
        self.still_since = None     # the time the turtle was last seen to stop
        self.reset()

    def reset(self) -> None:
        self.stood = None           # the last pose before the drawing
        self.path = []              # (x, y) from where it stood
        self.started_at = self.moved_at = None

    def feed(self, now: float, pose) -> Optional[str]:
        """'started', 'ended' or None."""
        moving = bool(pose.linear_velocity or pose.angular_velocity)
        if self.started_at is None:
            if not moving:
                self.stood = pose
                self.still_since = now if self.still_since is None else self.still_since
                return None
            ready = self.still_since is not None and now - self.still_since >= self.ready
            self.still_since = None
            if not ready:
                return None
            self.path = [(self.stood.x, self.stood.y)]
            self.started_at = now
        self.path.append((pose.x, pose.y))
        if moving:
            self.moved_at = now
        elif now - self.moved_at >= self.settle:
            self.still_since = self.moved_at
            return 'ended'
        return 'started' if len(self.path) == 2 else None

    @property
    def seconds(self) -> float:
        """How long the turtle moved, from its first move to its last."""
        return self.moved_at - self.started_at
