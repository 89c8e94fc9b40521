"""How cleanly ink makes its letters, whatever font it follows: turtles'
lines and arcs are clean; a weave strays; an O that does not close leaves
a gap. Paths driven in turtlesim's ticks (support.cadet_paths)."""
import math

import pytest

from turtle_letters.reading.cleanness import CLOSE, strays

from support.cadet_paths import arc, driven, forward, turn

HALF = math.pi / 2


def circle(radius, angle, seconds=2.0):
    """An arc of `radius` through `angle` radians in `seconds`: whole ticks."""
    return radius * abs(angle) / seconds, angle / seconds, seconds


CLEAN = {
    'L': [driven([forward(2.0), turn(HALF), forward(1.2)], 1.0, 3.0, -HALF)],
    'N': [driven([forward(2.0), turn(-2.68), forward(2.24), turn(2.68), forward(2.0)],
                 1.0, 1.0, HALF)],
    'O': [driven([circle(1.0, 2 * math.pi)], 2.0, 1.0)],
    'S': [driven([circle(0.5, math.pi), circle(0.5, -math.pi)], 2.0, 3.0, math.pi)],
    'J': [driven([forward(1.5), arc(0.4, -math.pi)], 2.0, 3.0, -HALF)],
    'a round-cornered U': [driven([forward(1.4), arc(0.3, math.pi), forward(1.4)],
                                  1.0, 3.0, -HALF)],
}


@pytest.mark.parametrize('name', sorted(CLEAN))
def test_a_turtles_lines_and_arcs_stray_nowhere_and_close(name):
    assert strays(CLEAN[name]) == pytest.approx((0.0, 0.0), abs=0.003), name


def woven(amplitude, wavelength=0.4):
    """An L whose 2 m stem weaves `amplitude` m either side, every
    `wavelength` m (a controller that overshoots its heading)."""
    stem = [(1.0 + amplitude * math.sin(2 * math.pi * k * 0.01 / wavelength), 3.0 - k * 0.01)
            for k in range(201)]
    return [stem + [(1.0 + k * 0.01, 1.0) for k in range(1, 121)]]


@pytest.mark.parametrize('amplitude', (0.02, 0.04, 0.06))
def test_a_weave_strays_as_far_as_it_weaves(amplitude):
    assert 0.7 * amplitude / 2.0 < strays(woven(amplitude)).wobble < 1.2 * amplitude / 2.0


def test_a_loop_that_stops_short_leaves_a_gap_and_an_open_letter_none():
    short = strays([driven([circle(1.0, 2 * math.pi - 0.1)], 2.0, 1.0)])
    assert short.gap == pytest.approx(2 * math.sin(0.05) / 2.0, rel=0.05)
    assert CLOSE[0] < short.gap < CLOSE[1]
    c = strays([driven([circle(1.0, 1.6 * math.pi)], 2.0, 1.0)])    # a C: wide open
    assert c.gap == 0.0 and c.wobble < 0.003


def test_no_ink_strays_nowhere():
    assert strays([]) == (0.0, 0.0)
    assert strays([[(1.0, 1.0)]]) == (0.0, 0.0)
