"""The canvas rebuilt from poses and the colour under each turtle (the
whole model against turtlesim's canvas is test_pens.py), and from the
bundled simulator's ink."""
import pytest

from support.ticks import drive
from turtle_letters.viewer.trails import DEFAULT_BACKGROUND, Stroke, Trails, to_pixels

PEN = (179, 184, 255)
RED = (255, 0, 0)


def test_a_pen_down_leaves_a_stroke_per_tick_in_its_colour():
    trails = Trails()
    drive(trails, 'turtle1', [(1.0, 1.0), (1.5, 1.0), (2.0, 1.0)], PEN)
    assert trails.strokes == [Stroke('turtle1', PEN, 1.0, 1.0, 1.5, 1.0),
                              Stroke('turtle1', PEN, 1.5, 1.0, 2.0, 1.0)]


def test_steps_over_the_background_wait_and_at_rest_the_background_lifts_them():
    trails = Trails()
    drive(trails, 'turtle1', [(1.0, 1.0), (1.02, 1.0), (1.04, 1.0)], DEFAULT_BACKGROUND)
    assert trails.strokes == []             # too fast to show, or up: not yet told
    drive(trails, 'turtle1', [(1.04, 1.0), (1.04, 1.0)], DEFAULT_BACKGROUND)
    assert trails.strokes == []             # at rest on the background: it was up
    drive(trails, 'turtle1', [(1.06, 1.0)], DEFAULT_BACKGROUND)
    drive(trails, 'turtle1', [(1.08, 1.0)], RED)
    assert trails.strokes == [Stroke('turtle1', RED, 1.04, 1.0, 1.06, 1.0),
                              Stroke('turtle1', RED, 1.06, 1.0, 1.08, 1.0)]


def test_a_jump_is_a_teleport_drawn_only_on_new_ink_where_it_lands():
    trails = Trails()
    drive(trails, 't', [(1.0, 1.0), (1.0, 1.0)], PEN)
    trails.pose('t', 3.0, 1.0, 0.0)         # no speed: a teleport
    drive(trails, 't', [(3.0, 1.0), (3.0, 1.0), (3.0, 1.0)], DEFAULT_BACKGROUND)
    assert trails.strokes == []
    trails.pose('t', 5.0, 1.0, 0.0)
    drive(trails, 't', [(5.0, 1.0), (5.0, 1.0), (5.0, 1.0)], RED)
    assert trails.strokes == [Stroke('t', RED, 3.0, 1.0, 5.0, 1.0)]


def test_a_reader_gets_what_came_since_it_looked_and_everything_after_a_clear():
    trails = Trails()
    drive(trails, 'a', [(1.0, 1.0), (1.02, 1.0), (1.04, 1.0), (1.04, 1.0), (1.04, 1.0)], PEN)
    clears, strokes, turtles = trails.since(0, 1)
    assert (clears, len(strokes), set(turtles)) == (0, 1, {'a'})
    trails.clear((10, 20, 30))
    drive(trails, 'a', [(1.06, 1.0)], RED)
    clears, strokes, _ = trails.since(0, 2)
    assert clears == 1 and [s[:6] for s in strokes] == [('a', RED, 1.04, 1.0, 1.06, 1.0)]
    assert trails.background == (10, 20, 30)


def test_a_killed_turtle_goes_and_its_strokes_stay_until_a_reset():
    trails = Trails()
    drive(trails, 'turtle2', [(1.0, 1.0), (2.0, 1.0)], PEN)
    trails.gone('turtle2')
    assert trails.turtles == {} and len(trails.strokes) == 1
    trails.reset()
    assert trails.strokes == [] and trails.clears == 1


def test_metres_map_to_turtlesims_pixels():
    assert to_pixels(0.0, 0.0) == (0.0, 499.0)
    assert to_pixels(11.088889, 11.088889) == pytest.approx((499.0, 0.0), abs=1e-3)



def test_a_pose_that_is_not_finite_is_no_place():
    trails = Trails()
    trails.pose('/turtle1', 1.0, 1.0, 0.0)
    for bad in ((float('nan'), 1.0, 0.0), (1.0, float('inf'), 0.0), (2.0, 1.0, float('nan'))):
        trails.pose('/turtle1', *bad)
    trails.colour('/turtle1', (179, 184, 255))
    assert trails.turtles_now()['/turtle1'][:3] == (1.0, 1.0, 0.0) and trails.strokes == []


def test_the_simulators_ink_is_drawn_as_laid_and_the_colour_under_a_turtle_no_more():
    trails = Trails()
    trails.ink([dict(k='move', turtle='turtle1', ink=[[1.0, 1.0, 1.05, 1.0, 255, 0, 0, 1]]),
                dict(k='jump', turtle='turtle1', ink=[]),
                dict(k='move', turtle='turtle1', ink=[[1.05, 1.0, float('nan'), 1.0, 9, 9, 9, 3]])])
    trails.pose('turtle1', 2.0, 2.0, 0.0)
    trails.colour('turtle1', (255, 0, 0))       # the pose-based guess: not drawn beside the ink
    assert trails.strokes == [Stroke('turtle1', (255, 0, 0), 1.0, 1.0, 1.05, 1.0, 1)]
    trails.ink([dict(k='clear', background=[10, 20, 30])])
    assert (trails.strokes, trails.clears, trails.background) == ([], 1, (10, 20, 30))
    trails.ink([dict(k='reset', background=[69, 86, 255]), dict(k='spawn', turtle='turtle1')])
    assert (trails.turtles, trails.clears, trails.background) == ({}, 2, (69, 86, 255))
