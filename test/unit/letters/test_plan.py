"""Turns, travel with the pen up, and the typewriter layout."""
import math

import pytest

from support.accuracy import primitives_of
from support.recorder import CENTRE, settings
from turtle_letters.letters.font import FONT
from turtle_letters.letters.geometry import PlannedPose, turn_between
from turtle_letters.letters.layout import MARGIN, WORLD_SIZE, DoesNotFit, Layout
from turtle_letters.letters.plan import plan_text
from turtle_letters.letters.primitives import Line, Pen, Turn
from turtle_letters.letters.sheet import Sheet


@pytest.mark.parametrize('start, target, ccw, shortest', [
    (0, math.pi / 2, math.pi / 2, math.pi / 2),
    (math.pi / 2, -math.pi / 4, 5 * math.pi / 4, -3 * math.pi / 4),
    (1.0, 1.0, 0.0, 0.0),
])
def test_turns_counter_clockwise_or_the_short_way(start, target, ccw, shortest):
    assert turn_between(start, target, 'ccw') == pytest.approx(ccw)
    assert turn_between(start, target, 'shortest') == pytest.approx(shortest)


def test_travel_to_a_letter_elsewhere_is_made_with_the_pen_up():
    primitives, end = primitives_of('L', [(1.0, 1.0)], PlannedPose(5.0, 5.0, 0.0), 2.0,
                                    direction='shortest')
    assert primitives[0] == Pen(False)
    up_to = primitives.index(Pen(True))
    travel = primitives[1:up_to]
    assert isinstance(travel[-1], Line) and (travel[-1].x, travel[-1].y) == (1.0, 3.0)
    assert all(isinstance(p, (Turn, Line)) for p in travel)
    assert (end.x, end.y) == pytest.approx((2.2, 1.0))


def test_places_go_right_then_a_line_below_then_start_again():
    layout = Layout((5.544445, 5.544445), 3.0)
    places = []
    cleared = []
    for _ in range(6):
        (place,), was_cleared = layout.reserve('N')
        places.append(place)
        cleared.append(was_cleared)
    assert places[0] == (5.544445, 5.544445)
    assert places[1][0] == MARGIN and places[1][1] < places[0][1] - 3.525
    assert places[2][1] == places[1][1] and places[2][0] > places[1][0]
    first_again = cleared.index(True)
    assert places[first_again] == places[0]
    for x, y in places:     # every letter box clear of the walls
        assert MARGIN <= x and x + FONT['N'].width * 3.0 <= WORLD_SIZE - MARGIN
        assert MARGIN <= y and y + 3.525 <= WORLD_SIZE - MARGIN


def test_text_that_cannot_fit_is_refused_saying_how_much_fits():
    layout = Layout((5.544445, 5.544445), 3.0)
    with pytest.raises(DoesNotFit, match=r'at most 6 of its 9 characters fit'):
        layout.reserve('ABCDEFGHI')
    assert layout.cursor == (5.544445, 5.544445)      # nothing reserved
    places, _ = layout.reserve('AB D')
    assert places[2] is None


def test_a_letter_too_big_for_the_canvas_is_refused():
    with pytest.raises(DoesNotFit, match='at most 0'):
        Layout((1.0, 1.0), 9.0).reserve('N')


@pytest.mark.parametrize('off', [-3e-6, 3e-6])
def test_a_heading_a_float32_hair_off_is_no_turn(off):
    """A pose read as float32 is microradians off the plan: no full turn for that."""
    assert turn_between(off, 0.0, 'ccw') == 0.0
    assert turn_between(0.0, off, 'ccw') == 0.0


def test_a_turtle_a_float32_hair_from_the_first_point_draws_the_lab_n_as_is():
    """A spawned turtle stands on its letter's place as float32 allows."""
    hair = 9.388888888888889 - 9.38888931274414
    primitives, _ = primitives_of('N', [(0.5, 9.388888888888889)],
                                  PlannedPose(0.5, 9.388888888888889 - hair, 0.0), 1.0)
    assert Pen(False) not in primitives
    assert [round(math.degrees(p.angle)) for p in primitives if isinstance(p, Turn)] == [90, 225, 135]


def test_a_text_far_too_long_is_refused_and_quoted_short():
    text = 'N' * 1_000_000
    with pytest.raises(DoesNotFit) as refused:
        Layout((5.544445, 5.544445), 3.0).reserve(text)
    message = str(refused.value)
    assert "'" + 'N' * 40 + "...'" in message and 'N' * 41 not in message
    assert 'at most 4 of its 1000000 characters fit' in message


def test_fitting_reads_no_further_than_the_canvas_holds():
    read = []

    def widths():       # a quadratic fit read the text once per character
        for _ in range(100_000):
            read.append(1)
            yield FONT['N'].width
    assert Layout((5.544445, 5.544445), 3.0).how_many_fit(widths()) == 4
    assert len(read) == 5


def test_the_plan_says_ink_travel_and_time():
    where = PlannedPose(CENTRE, CENTRE, 0.0)
    plan = plan_text('N', [(CENTRE, CENTRE)], where, settings())
    assert (plan.ink, plan.travel) == (pytest.approx(9.5), 0.0)
    # the lab's 40.9 s: 9.5 m at 1 m/s, and 450 degrees at 0.25 rad/s
    assert plan.seconds == pytest.approx(9.5 + 2.5 * math.pi / 0.25)
    assert plan_text('N', [(CENTRE, CENTRE)], where, settings(mode='smooth')).seconds == \
        pytest.approx(9.5)


def test_a_hershey_word_is_drawn_in_the_shorter_order():
    from turtle_letters.letters.plan import glyph_strokes
    from turtle_letters.letters.route import travel_length
    given = settings(font='futural', size=1.0)
    where = PlannedPose(CENTRE, CENTRE, 0.0)
    places = Sheet(1.0, given.font).reserve('Hi!', where)[0]
    plan = plan_text('Hi!', places, where, given)
    reading = [s for c, p in zip('Hi!', places) for s in glyph_strokes(given.font.glyph(c), p, 1.0)]
    assert plan.travel < travel_length(reading, plan.start)
