"""The lab's turtle: its pen (the drawing's calls run on it, see test_lab)."""
from types import SimpleNamespace

import pytest

from support.recorder import settings


def test_a_pen_of_another_colour_is_put_down_before_the_first_drawing_only():
    turtle_module = pytest.importorskip('turtle_letters.turtle')
    pens = []
    driver = SimpleNamespace(set_pen=lambda pen, down: pens.append((pen, down)))
    ours = turtle_module.Turtle(driver, settings(pen='230 40 40 3'))
    ours.pen_down()
    ours.pen_down()
    assert pens == [((230, 40, 40, 3), True)]
    default = turtle_module.Turtle(driver, settings())
    default.pen_down()          # turtlesim's pen starts down in its own colour
    assert len(pens) == 1
    default.pen(False)
    default.pen_down()          # left up by a travel: down again
    assert pens[1:] == [((179, 184, 255, 3), False), ((179, 184, 255, 3), True)]
