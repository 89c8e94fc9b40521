"""Every glyph of the stroke font, and the lab's N."""
import math
import string

import pytest

from support.accuracy import primitives_of
from turtle_letters.letters.font import ASCENT, FONT
from turtle_letters.letters.geometry import PlannedPose
from turtle_letters.letters.primitives import Line, Pen, Turn

ALL = sorted(FONT)


def test_the_font_has_a_to_z_and_0_to_9():
    assert set(FONT) == set(string.ascii_uppercase + string.digits)


@pytest.mark.parametrize('char', ALL)
def test_strokes_stay_inside_the_glyph_box(char):
    glyph = FONT[char]
    for stroke in glyph.strokes:
        assert len(stroke) >= 2
        for x, y in stroke:
            assert -1e-12 <= x <= glyph.width + 1e-12
            assert -1e-12 <= y <= ASCENT


@pytest.mark.parametrize('char', [c for c in ALL if c != 'N'])
def test_other_glyphs_share_the_height_of_one(char):
    ys = [y for stroke in FONT[char].strokes for _, y in stroke]
    assert (min(ys), max(ys)) == (0, 1)


@pytest.mark.parametrize('char', ALL)
def test_pen_is_lifted_exactly_between_strokes(char):
    glyph = FONT[char]
    start = glyph.strokes[0][0]
    primitives, _ = primitives_of(char, [(1.0, 1.0)],
                                  PlannedPose(1.0 + 3 * start[0], 1.0 + 3 * start[1], 0.0))
    pens = [p.down for p in primitives if isinstance(p, Pen)]
    assert pens == [False, True] * (len(glyph.strokes) - 1)
    assert not primitives or not isinstance(primitives[-1], Pen)


def test_n_is_the_labs_sequence_of_primitives():
    primitives, end = primitives_of('N', [(5.544445, 5.544445)], PlannedPose(5.544445, 5.544445, 0.0))
    kinds = [type(p) for p in primitives]
    assert kinds == [Turn, Line] * 3
    degrees = [math.degrees(p.angle) for p in primitives[0::2]]
    meters = [p.length for p in primitives[1::2]]
    assert degrees == pytest.approx([90, 225, 135])
    assert meters == pytest.approx([3.0, 3.5, 3.0])
    vertices = [v for p in primitives[1::2] for v in (p.x, p.y)]
    assert vertices == pytest.approx([5.5444, 8.5444, 8.0193, 6.0696, 8.0193, 9.0696], abs=1e-4)
    assert end.heading == pytest.approx(math.pi / 2)
