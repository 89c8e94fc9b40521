"""The lab's N: the six calls of lab.py are what "P" runs in timed mode,
and everything else (the font, the other modes, the grader) takes the N
from them."""
import math

import pytest

from support.recorder import Drawer
from turtle_letters.grading.scoring import ideal_letter
from turtle_letters.lab import draw_the_labs_n
from turtle_letters.letters.font import BUILTIN, written_glyph
from turtle_letters.letters.geometry import PlannedPose

SIX_CALLS = [('rotate', 90.0), ('move', 3.0), ('rotate', 225.0), ('move', 3.5),
             ('rotate', 135.0), ('move', 3.0)]


def test_p_in_timed_mode_runs_the_six_calls_of_lab_py():
    drawer = Drawer()
    assert drawer.draw('N') == SIX_CALLS
    assert all('draw_the_labs_n' in callers for callers in drawer.turtle.callers)


def test_at_another_size_the_same_calls_move_to_scale():
    assert Drawer(size=1.5).draw('N') == [
        ('rotate', 90.0), ('move', 1.5), ('rotate', 225.0), ('move', 1.75),
        ('rotate', 135.0), ('move', 1.5)]


def test_turning_the_shorter_way_turns_the_225_degrees_back_135():
    assert Drawer(turn_direction='shortest').draw('N') == [
        ('rotate', 90.0), ('move', 3.0), ('rotate', -135.0), ('move', 3.5),
        ('rotate', 135.0), ('move', 3.0)]


def test_a_second_n_is_travelled_to_and_faces_east_before_its_six_calls():
    calls = Drawer().draw('NN')
    second = calls[calls.index(('pen', True)) + 1:]
    assert second == SIX_CALLS
    travel = calls[6:calls.index(('pen', True))]
    turns = [amount for call, amount in travel if call == 'rotate']
    # from the first N's heading (north) round to the travel's, then to east
    assert sum(turns) % 360 == pytest.approx(270.0)


def test_the_fonts_n_is_the_path_the_six_calls_trace():
    k = 3.5 / 3.0 / math.sqrt(2.0)
    assert BUILTIN.glyph('N').strokes == [[(0.0, 0.0), (0.0, 1.0), pytest.approx((k, 1 - k)),
                                          pytest.approx((k, 2 - k))]]
    assert BUILTIN.glyph('N').writer.program is draw_the_labs_n


def test_a_changed_call_is_what_the_turtle_draws_and_the_grader_expects():
    def changed(turtle):
        turtle.rotate(90)
        turtle.move(3.0)
        turtle.rotate(200)          # a cadet's change
        turtle.move(3.5)
        turtle.rotate(135)
        turtle.move(3.0)
    font = BUILTIN._replace(glyphs=dict(BUILTIN.glyphs, N=written_glyph(changed, 3.0)))
    drawer = Drawer()
    drawer.settings.font = font
    assert ('rotate', 200.0) in drawer.draw('N')
    (corner, top, foot, _), = ideal_letter('N', 3.0, font, PlannedPose(2.0, 5.0, 0.0))
    heading = math.radians(90 + 200)
    assert corner == (2.0, 5.0)
    assert foot == pytest.approx((2.0 + 3.5 * math.cos(heading), 8.0 + 3.5 * math.sin(heading)))


def test_feedback_mode_steers_the_steps_of_the_six_calls():
    drawer = Drawer(mode='feedback')
    assert drawer.draw('N') == [('steer', 'Turn'), ('steer', 'Line')] * 3
