"""The order and direction in which a word's strokes are drawn. No ROS here.

Pen-up travel between strokes is time spent drawing nothing. Strokes may be
drawn in any order and either direction, so the shortest travel is a small
travelling-salesman problem; a greedy tour improved by 2-opt moves (which
reverse a run of strokes, each stroke reversed too) gets close enough, and
is kept only when it beats reading order. The work is bounded, for an SVG
file's thousands of strokes: the greedy tour looks near each point only,
and 2-opt tries a fixed number of pairs at most.
"""
import collections
import math
from typing import List, Sequence, Tuple

Point = Tuple[float, float]
Stroke = List[Point]

TWO_OPT_WORK = 3_000_000    # pairs of strokes tried at the most (a few seconds)
CHECK_EVERY = 200           # strokes placed between two calls of check()


def _gap(a: Point, b: Point) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


def ink_length(strokes: Sequence[Stroke]) -> float:
    return sum(_gap(a, b) for s in strokes for a, b in zip(s, s[1:]))


def travel_length(strokes: Sequence[Stroke], start: Point) -> float:
    """Pen-up distance from `start` through the strokes in this order."""
    here, total = start, 0.0
    for stroke in strokes:
        total += _gap(here, stroke[0])
        here = stroke[-1]
    return total


class _Ends:
    """Both ends of every stroke not drawn yet, filed in a grid of square
    cells about one stroke's share of the drawing wide: the nearest end is
    found among a few cells around a point, not among all the strokes."""

    def __init__(self, strokes: Sequence[Stroke], start: Point) -> None:
        points = [start] + [end for s in strokes for end in (s[0], s[-1])]
        self.x0, self.y0 = min(p[0] for p in points), min(p[1] for p in points)
        span = max(max(p[0] for p in points) - self.x0, max(p[1] for p in points) - self.y0)
        self.size = max(span / math.sqrt(len(strokes)), 1e-9)
        self.reach = int(span / self.size) + 2      # rings enough to cover the grid
        self.cells = collections.defaultdict(set)
        for i, stroke in enumerate(strokes):
            for end in (stroke[0], stroke[-1]):
                self.cells[self._cell(end)].add(i)
        self.strokes = strokes

    def _cell(self, point: Point) -> Tuple[int, int]:
        return (int((point[0] - self.x0) // self.size), int((point[1] - self.y0) // self.size))

    def nearest(self, here: Point) -> int:
        """The stroke with an end nearest `here` (the first of equals)."""
        ci, cj = self._cell(here)
        best = (math.inf, -1)
        for ring in range(self.reach + 1):
            if (ring - 1) * self.size > best[0]:        # no nearer end is farther out
                break
            for cell in _ring(ci, cj, ring):
                for i in self.cells.get(cell, ()):
                    s = self.strokes[i]
                    best = min(best, (min(_gap(here, s[0]), _gap(here, s[-1])), i))
        return best[1]

    def remove(self, i: int) -> None:
        for end in (self.strokes[i][0], self.strokes[i][-1]):
            self.cells[self._cell(end)].discard(i)


def _ring(ci: int, cj: int, ring: int):
    """The cells `ring` steps from (ci, cj) (Chebyshev distance)."""
    if ring == 0:
        yield ci, cj
        return
    for d in range(-ring, ring + 1):
        yield ci + d, cj - ring
        yield ci + d, cj + ring
    for d in range(-ring + 1, ring):
        yield ci - ring, cj + d
        yield ci + ring, cj + d


def _greedy(strokes: Sequence[Stroke], start: Point, check) -> List[Stroke]:
    """Nearest stroke next, turned to start at its nearer end."""
    ends, tour, here = _Ends(strokes, start), [], start
    for count in range(len(strokes)):
        if count % CHECK_EVERY == 0:
            check()
        i = ends.nearest(here)
        ends.remove(i)
        stroke = strokes[i]
        if _gap(here, stroke[-1]) < _gap(here, stroke[0]):
            stroke = stroke[::-1]
        tour.append(stroke)
        here = stroke[-1]
    return tour


def _two_opt(tour: List[Stroke], start: Point, check) -> List[Stroke]:
    """Reverse runs tour[i..j] (and each stroke in them) while that shortens
    the travel; a run of one stroke just turns that stroke round. At most
    TWO_OPT_WORK pairs are tried: a word converges long before, a large
    picture keeps what it has by then, whatever the machine."""
    improved, work = True, 0
    while improved and work < TWO_OPT_WORK:
        improved = False
        for i in range(len(tour)):
            check()
            before = tour[i - 1][-1] if i else start
            for j in range(i, len(tour)):
                after = tour[j + 1][0] if j + 1 < len(tour) else None
                old = _gap(before, tour[i][0]) + (_gap(tour[j][-1], after) if after else 0.0)
                new = _gap(before, tour[j][-1]) + (_gap(tour[i][0], after) if after else 0.0)
                if new < old - 1e-12:
                    tour[i:j + 1] = [s[::-1] for s in reversed(tour[i:j + 1])]
                    improved = True
            work += len(tour) - i
            if work >= TWO_OPT_WORK:
                break
    return tour


def order_strokes(strokes: Sequence[Stroke], start: Point, check=lambda: None) -> List[Stroke]:
    """The strokes in the order and direction to draw them from `start`:
    never more travel than reading order. `check()` is called every so
    often, and may raise to stop the planning (a cancel)."""
    if not strokes:
        return []
    tour = _two_opt(_greedy(strokes, start, check), start, check)
    if travel_length(tour, start) < travel_length(strokes, start):
        return tour
    return list(strokes)
