"""Judging a recorded turtle path against the ideal strokes, for the tests:
the measures are the grader's (turtle_letters.grading). No ROS here."""
from turtle_letters.grading.scoring import distance_to_lines, vertex_errors  # noqa: F401
from turtle_letters.letters.font import BUILTIN
from turtle_letters.letters.geometry import PlannedPose, distance_to_segment  # noqa: F401
from turtle_letters.letters.layout import SIM_TICK, WORLD_SIZE
from turtle_letters.letters.plan import text_strokes
from turtle_letters.letters.primitives import Line, Pen, Turn, Written, plan_strokes

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


def strays(poses, lines, tolerance):
    """Each run of turtlesim's `poses` (in order) `tolerance` m or more off
    `lines`: [its first pose, how far off it goes (m), whether it began with
    the tick before's command used again]. A late command does that (the
    contract: a command holds until another comes): the turtle runs on along
    its move, past a vertex or off a curve, for as many ticks as the command
    is late, which load does not bound. A stray begun by a new command is
    the controller's own doing."""
    found, inside = [], False
    for i, pose in enumerate(poses):
        off = distance_to_lines((pose.x, pose.y), lines)
        if off < tolerance:
            inside = False
        elif inside:
            found[-1][1] = max(found[-1][1], off)
        else:
            inside = True
            found.append([pose, off, i > 0 and _same_command(poses[i - 1], pose)])
    return found


def _same_command(before, pose):
    """Whether turtlesim moved `pose` by the command it moved `before` by
    (a pose carries its tick's command: hypot(linear.x, linear.y), angular.z)."""
    return (before.linear_velocity, before.angular_velocity) == \
        (pose.linear_velocity, pose.angular_velocity)


def worst_off(path, strokes, travel):
    """How far the path strays from the strokes and travel segments, m."""
    return max(distances_off(path, strokes, travel))


ROUND_TRIPS_A_STROKE = 20   # what a slow network may cost each stroke of the lab's N


def lab_n():
    """The lab's N from the centre, as the package plans it: its primitives."""
    centre = WORLD_SIZE / 2
    return primitives_of('N', [(centre, centre)], PlannedPose(centre, centre, 0.0))[0]


def lab_n_plan_s(mode, speed=1.0, turn_speed=0.25):
    """The lab's N's time by its plan: its lines at `speed`, and (but in
    smooth mode, which turns on the way) its turns at `turn_speed`."""
    primitives = lab_n()
    lines = sum(abs(p.length) for p in primitives if isinstance(p, Line)) / speed
    turns = sum(abs(p.angle) for p in primitives if isinstance(p, Turn)) / turn_speed
    return lines if mode == 'smooth' else lines + turns


def slow_network_budget_s(mode, delay_s, jitter_s):
    """The longest the lab's N may take over a network `delay_s` +- `jitter_s`
    late each way: its plan's time and a tenth, and what the delay costs,
    ROUND_TRIPS_A_STROKE round trips for each of its strokes, its turns and
    lines (a stroke ends on a pose that shows the turtle there, and a
    correction waits for the commands before it to show)."""
    round_trip = 2 * (delay_s + jitter_s) + SIM_TICK
    return lab_n_plan_s(mode) * 1.1 + len(lab_n()) * ROUND_TRIPS_A_STROKE * round_trip
