"""The order and direction in which a word's strokes are drawn. No ROS here.

Pen-up travel between strokes is time spent drawing nothing. Strokes may be
drawn in any order and either direction, so the shortest travel is a small
travelling-salesman problem; a greedy tour improved by 2-opt moves (which
reverse a run of strokes, each stroke reversed too) gets close enough, and
is kept only when it beats reading order.
"""
import math
from typing import List, Sequence, Tuple

Point = Tuple[float, float]
Stroke = List[Point]


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


def _greedy(strokes: Sequence[Stroke], start: Point) -> List[Stroke]:
    left = list(strokes)
    tour, here = [], start
    while left:
        best = min(range(len(left)),
                   key=lambda i: min(_gap(here, left[i][0]), _gap(here, left[i][-1])))
        stroke = left.pop(best)
        if _gap(here, stroke[-1]) < _gap(here, stroke[0]):
            stroke = stroke[::-1]
        tour.append(stroke)
        here = stroke[-1]
    return tour


def _two_opt(tour: List[Stroke], start: Point) -> List[Stroke]:
    """Reverse runs tour[i..j] (and each stroke in them) while that shortens
    the travel; a run of one stroke just turns that stroke round."""
    improved = True
    while improved:
        improved = False
        for i in range(len(tour)):
            before = tour[i - 1][-1] if i else start
            for j in range(i, len(tour)):
                after = tour[j + 1][0] if j + 1 < len(tour) else None
                old = _gap(before, tour[i][0]) + (_gap(tour[j][-1], after) if after else 0.0)
                new = _gap(before, tour[j][-1]) + (_gap(tour[i][0], after) if after else 0.0)
                if new < old - 1e-12:
                    tour[i:j + 1] = [s[::-1] for s in reversed(tour[i:j + 1])]
                    improved = True
    return tour


def order_strokes(strokes: Sequence[Stroke], start: Point) -> List[Stroke]:
    """The strokes in the order and direction to draw them from `start`:
    never more travel than reading order."""
    tour = _two_opt(_greedy(strokes, start), start)
    if travel_length(tour, start) < travel_length(strokes, start):
        return tour
    return list(strokes)
