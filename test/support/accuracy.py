"""Judging a recorded turtle path against the ideal strokes, for the tests:
the measures are the grader's (turtle_letters.grading). No ROS here."""
from turtle_letters.grading.scoring import distance_to_lines, vertex_errors  # noqa: F401
from turtle_letters.letters.font import BUILTIN
from turtle_letters.letters.geometry import distance_to_segment  # noqa: F401 (for the tests)
from turtle_letters.letters.layout import WORLD_SIZE
from turtle_letters.letters.plan import text_strokes
from turtle_letters.letters.primitives import Line, Pen, Written, plan_strokes

# The lab's ideal N from the turtle's start pose (the lab's own figures).
LAB_N_VERTICES = [(5.5444, 5.5444), (5.5444, 8.5444), (8.0193, 6.0696), (8.0193, 9.0696)]


def distance_to_polyline(p, vertices):
    return distance_to_lines(p, [vertices])


def worst_distance_from(path, vertices):
    return max(distance_to_polyline(p, vertices) for p in path)


def touches_a_wall(path, clearance=1e-6):
    return any(not (clearance < v < WORLD_SIZE - clearance) for p in path for v in p)


def expected(text, places, start, size, font=BUILTIN, direction='ccw'):
    """The strokes of `text` at `places` (from plan.Layout) and the pen-up
    travel segments that reach them from the turtle's `start`, by the
    package's own plan: what a drawing's path must keep to."""
    strokes = text_strokes(text, places, size, font, start)[0]
    primitives, _ = primitives_of(text, places, start, size, font, direction)
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


def primitives_of(text, places, start, size=3.0, font=BUILTIN, direction='ccw'):
    """The primitives the package plans for `text` at `places` (from
    layout.Layout) from the turtle's `start`, each written letter's (the
    lab's N) as the steps of its calls; and the end pose."""
    strokes, writers = text_strokes(text, places, size, font, start)
    primitives, end = plan_strokes(strokes, start, direction, None, writers, size)
    return [s for p in primitives for s in (p.steps if isinstance(p, Written) else [p])], end


def distances_off(path, strokes, travel):
    """How far each point of the path is from the strokes and travel segments, m."""
    return [distance_to_lines(q, strokes + travel) for q in path]


def worst_off(path, strokes, travel):
    """How far the path strays from the strokes and travel segments, m."""
    return max(distances_off(path, strokes, travel))
