"""The grader's scoring, on paths that turtles really drew (test/unit/grading/traces:
grade.py's reports of real runs on the bundled simulator) and on made ones."""
import json
import os
from types import SimpleNamespace

import pytest

from turtle_letters.letters.font import BUILTIN
from turtle_letters.grading.scoring import DrawingWatch, Tolerances, ideal_letter, score
from turtle_letters.letters.geometry import PlannedPose

TRACES = os.path.join(os.path.dirname(__file__), 'traces')


def trace(name):
    """(path, the ideal N from where the turtle stood) of a recorded drawing."""
    with open(os.path.join(TRACES, name)) as f:
        path = [tuple(p) for p in json.load(f)['path']]
    return path, ideal_letter('N', 3.0, BUILTIN, PlannedPose(path[0][0], path[0][1], 0.0))


def test_this_packages_timed_n_passes_to_the_micrometre():
    path, strokes = trace('timed_n.json')
    graded = score(path, strokes)
    assert graded.passed, graded.reason
    assert graded.worst_vertex < 1e-5 and graded.end_error < 1e-5 and graded.off < 1e-5
    assert graded.missing == [] and graded.ink_off == 0.0
    assert graded.reason == 'every vertex within 0.00 mm, closed (at most 20 mm)'


def test_a_wrong_second_turn_fails_at_the_vertex_it_misses():
    path, strokes = trace('wrong_second_turn_n.json')
    graded = score(path, strokes)
    assert not graded.passed
    assert graded.reason.startswith('vertex 3 of 4 missed by 825 mm (at most 20 mm); '
                                    'the worst, vertex 4, by 1082 mm')
    assert graded.vertex_errors[:2] == pytest.approx([0, 0], abs=0.02)
    assert graded.ink_off > 3.0            # the diagonal and the last leg are elsewhere


def test_a_drawing_stopped_short_is_not_closed():
    path, strokes = trace('timed_n.json')
    short = path[:next(i for i, p in enumerate(path) if p[1] > strokes[0][-1][1] - 0.5
                       and p[0] > strokes[0][-1][0] - 0.01)]      # 0.5 m short of the top
    graded = score(short, strokes)
    assert not graded.passed
    assert graded.reason.startswith('vertex 4 of 4 missed by 50')


def test_the_tolerance_decides_and_the_reason_states_it():
    path, strokes = trace('timed_n.json')
    shifted = [(x + 0.015, y) for x, y in path]
    assert not score(shifted, strokes, path[0], Tolerances(0.01)).passed
    graded = score(shifted, strokes, path[0], Tolerances(0.02))
    assert graded.passed
    assert graded.reason == 'every vertex within 15.00 mm, closed (at most 20 mm)'


def test_pen_up_moves_between_strokes_are_not_ink_off_but_a_detour_is():
    start = PlannedPose(1.0, 6.0, 0.0)
    strokes = ideal_letter('T', 3.0, BUILTIN, start)
    assert len(strokes) == 2
    straight = [(start.x, start.y)] + [p for s in strokes for p in s]
    assert score(straight, strokes, (start.x, start.y)).ink_off == 0.0
    detour = [(start.x, start.y)] + strokes[0] + [(strokes[0][-1][0], 1.0)] + strokes[1]
    graded = score(detour, strokes, (start.x, start.y))
    assert graded.ink_off > 2.0 and graded.passed   # all vertices drawn: the detour is reported


def test_a_drawing_starts_with_the_first_move_and_ends_after_standing_still():
    watch, events = DrawingWatch(settle=2.0), []

    def pose(x, moving):
        return SimpleNamespace(x=x, y=5.0, theta=0.0, linear_velocity=moving, angular_velocity=0.0)
    for t, x, moving in [(0.0, 1.0, 0), (0.5, 1.0, 0), (1.0, 1.5, 1), (2.0, 2.0, 1),
                         (2.5, 2.0, 0), (3.5, 2.0, 0), (4.0, 2.0, 0)]:
        events.append(watch.feed(t, pose(x, moving)))
    assert events == [None, None, 'started', None, None, None, 'ended']
    assert watch.path[:3] == [(1.0, 5.0), (1.5, 5.0), (2.0, 5.0)]
    assert watch.seconds == 1.0


def test_a_watch_that_joins_mid_drawing_waits_for_the_next_one():
    watch = DrawingWatch(settle=2.0, ready=0.3)

    def pose(x, moving):
        return SimpleNamespace(x=x, y=5.0, theta=0.0, linear_velocity=moving, angular_velocity=0.0)
    events = [watch.feed(t, pose(x, moving)) for t, x, moving in [
        (0.0, 1.0, 1), (0.1, 1.1, 1),               # joined while it moves
        (0.2, 1.1, 0), (0.25, 1.2, 1),              # a stop between two strokes
        (0.3, 1.3, 0), (2.0, 1.3, 0),               # the drawing is over
        (2.5, 1.4, 1), (3.0, 1.5, 1), (3.1, 1.5, 0), (5.2, 1.5, 0)]]   # the next one
    assert events == [None] * 6 + ['started', None, None, 'ended']
    assert watch.path[0] == (1.3, 5.0)
