"""The modes: a plan carried out in the lab's calls on a recording turtle."""
import pytest

from support.recorder import Drawer
from turtle_letters.motion.modes import MODES


def test_feedback_mode_steers_the_same_primitives():
    assert Drawer(mode='feedback').draw('N') == [
        ('steer', 'Turn'), ('steer', 'Line')] * 3


def test_travel_to_a_stroke_lifts_the_pen():
    calls = Drawer(size=1.0).draw('K')
    pens = [c for c in calls if c[0] == 'pen']
    # K's three strokes each start away from where the turtle is
    assert pens == [('pen', False), ('pen', True)] * 3


def test_smooth_mode_glides_through_each_stroke_lifting_the_pen_between():
    assert Drawer(mode='smooth').draw('N') == [('glide', 3)]
    calls = Drawer(mode='smooth', size=1.0).draw('K')
    # as in timed mode: three travels, each to a stroke of one edge
    assert calls == [('pen', False), ('glide', 1), ('pen', True),
                                       ('glide', 1)] * 3


def test_every_mode_has_one_object_and_the_parameter_table_offers_each():
    from turtle_letters.settings import PARAMETERS
    mode = next(p for p in PARAMETERS if p.name == 'mode')
    for name in MODES:
        assert mode.check(name) == name
    with pytest.raises(ValueError):
        mode.check('busy-loop')
