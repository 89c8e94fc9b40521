"""The stroke order: less pen-up travel than reading order, never more."""
import math
import random

import pytest

from turtle_letters.letters.font import BUILTIN
from turtle_letters.letters.hershey import load_font
from turtle_letters.letters.layout import Layout
from turtle_letters.letters.plan import glyph_strokes
from turtle_letters.letters.route import _greedy, ink_length, order_strokes, travel_length

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


def nearest_first(strokes, start):
    """The greedy tour by brute force: each time, the stroke with the
    nearest end (the first of equals), turned to start there."""
    left, tour, here = list(strokes), [], start
    while left:
        best = min(range(len(left)), key=lambda i: min(math.dist(here, left[i][0]),
                                                        math.dist(here, left[i][-1])))
        stroke = left.pop(best)
        if math.dist(here, stroke[-1]) < math.dist(here, stroke[0]):
            stroke = stroke[::-1]
        tour.append(stroke)
        here = stroke[-1]
    return tour


@pytest.mark.parametrize('count', [1, 2, 7, 60, 500])
def test_the_grid_finds_the_same_greedy_tour_as_a_search_of_every_stroke(count):
    rng = random.Random(count)
    strokes = [[(rng.uniform(0, 10), rng.uniform(0, 10)), (rng.uniform(0, 10), rng.uniform(0, 10))]
               for _ in range(count)]
    assert _greedy(strokes, (0.5, 9.0), lambda: None) == nearest_first(strokes, (0.5, 9.0))


def test_strokes_that_share_their_ends_are_taken_in_the_same_order_too():
    lattice = ([[(x, y), (x + 1, y)] for x in range(8) for y in range(8)]
               + [[(x, y), (x, y + 1)] for x in range(8) for y in range(8)])
    assert _greedy(lattice, (0, 0), lambda: None) == nearest_first(lattice, (0, 0))
    text = word_strokes('Hello, World!', load_font('futural'))
    assert _greedy(text, START, lambda: None) == nearest_first(text, START)


def test_a_check_that_raises_stops_the_ordering_of_many_strokes():
    rng = random.Random(1)
    strokes = [[(rng.uniform(0, 10), rng.uniform(0, 10)), (rng.uniform(0, 10), rng.uniform(0, 10))]
               for _ in range(5000)]
    calls = []

    def check():
        calls.append(1)
        if len(calls) > 30:
            raise InterruptedError('cancelled')
    with pytest.raises(InterruptedError):
        order_strokes(strokes, (0.0, 0.0), check)
