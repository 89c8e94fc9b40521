"""The stroke order: less pen-up travel than reading order, never more."""
import pytest

from turtle_letters.letters.font import BUILTIN
from turtle_letters.letters.hershey import load_font
from turtle_letters.letters.layout import Layout
from turtle_letters.letters.plan import glyph_strokes
from turtle_letters.letters.route import ink_length, order_strokes, travel_length

START = (1.0, 5.0)


def word_strokes(text, font, size=0.8):
    places, _ = Layout(START, size, font).reserve(text)
    return [s for c, p in zip(text, places) if p for s in glyph_strokes(font.glyph(c), p, size)]


@pytest.mark.parametrize('font, text', [
    ('futural', 'Hello, World!'), ('scripts', 'Hello, World!'), ('timesr', 'ROS 1'),
    ('builtin', 'AK7'), ('builtin', 'N'), ('scripts', 'turtle')])
def test_never_longer_than_reading_order_and_the_same_ink(font, text):
    font = BUILTIN if font == 'builtin' else load_font(font)
    strokes = word_strokes(text, font)
    ordered = order_strokes(strokes, START)
    assert travel_length(ordered, START) <= travel_length(strokes, START)
    assert ink_length(ordered) == pytest.approx(ink_length(strokes))
    assert sorted(map(sorted, ordered)) == sorted(map(sorted, strokes))   # each stroke once


def test_a_word_with_many_strokes_gets_much_shorter_travel():
    strokes = word_strokes('Hello, World!', load_font('futural'))
    assert travel_length(order_strokes(strokes, START), START) < \
        0.8 * travel_length(strokes, START)


def test_the_labs_n_is_left_as_it_is():
    strokes = word_strokes('N', BUILTIN, size=3.0)
    assert order_strokes(strokes, START) == strokes


def test_a_stroke_is_turned_round_when_its_end_is_nearer():
    strokes = [[(5.0, 5.0), (1.0, 5.0)]]
    assert order_strokes(strokes, START) == [[(1.0, 5.0), (5.0, 5.0)]]
