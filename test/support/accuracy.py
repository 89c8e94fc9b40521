"""Judging a recorded turtle path against the ideal strokes. No ROS here:
the tests and the benchmark both use it."""
import math

from turtle_letters.font import BUILTIN
from turtle_letters.plan import WORLD_SIZE, Line, Pen, plan_strokes, word_strokes
from turtle_letters.route import order_strokes

# The lab's ideal N from the turtle's start pose (the lab's own figures).
LAB_N_VERTICES = [(5.5444, 5.5444), (5.5444, 8.5444), (8.0193, 6.0696), (8.0193, 9.0696)]


def distance_to_segment(p, a, b):
    (px, py), (ax, ay), (bx, by) = p, a, b
    dx, dy = bx - ax, by - ay
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / length2))
    return math.hypot(px - (ax + t * dx), py - (ay + t * dy))


def distance_to_polyline(p, vertices):
    return min(distance_to_segment(p, a, b) for a, b in zip(vertices, vertices[1:]))


def worst_distance_from(path, vertices):
    return max(distance_to_polyline(p, vertices) for p in path)


def vertex_errors(path, vertices):
    """For each vertex, how close the path ever came to it."""
    return [min(math.hypot(x - vx, y - vy) for x, y in path) for vx, vy in vertices]


def touches_a_wall(path, clearance=1e-6):
    return any(not (clearance < v < WORLD_SIZE - clearance) for p in path for v in p)


def expected(text, places, start, size, font=BUILTIN, direction='ccw'):
    """The strokes of `text` at `places` (from plan.Layout) and the pen-up
    travel segments that reach them from the turtle's `start`, by the
    package's own plan: what a drawing's path must keep to."""
    strokes = word_strokes(text, places, size, font)
    if font is not BUILTIN:
        strokes = order_strokes(strokes, (start.x, start.y))
    primitives, _ = plan_strokes(strokes, start, direction)
    travel = []
    pen_down, here = True, (start.x, start.y)
    for p in primitives:
        if isinstance(p, Pen):
            pen_down = p.down
        elif isinstance(p, Line):
            if not pen_down:
                travel.append([here, (p.x, p.y)])
            here = (p.x, p.y)
    return strokes, travel


def distances_off(path, strokes, travel):
    """How far each point of the path is from the strokes and travel segments, m."""
    allowed = strokes + travel
    return [min(distance_to_polyline(q, line) for line in allowed) for q in path]


def worst_off(path, strokes, travel):
    """How far the path strays from the strokes and travel segments, m."""
    return max(distances_off(path, strokes, travel))
