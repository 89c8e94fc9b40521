"""The drawing, in the lab's calls: what the lab's class is asked to do."""
import math

import pytest

from turtle_letters.drawing import LetterDrawer
from turtle_letters.plan import WORLD_SIZE, DoesNotFit, PlannedPose
from turtle_letters.settings import Settings

CENTRE = WORLD_SIZE / 2


class Recorder(LetterDrawer):
    """The lab's class with its calls written down instead of carried out."""

    def __init__(self, **given):
        super().__init__(Settings(lambda name, default: given.get(name.lstrip('~'), default)))
        self.calls = []

    def rotate(self, degrees):
        self.calls.append(('rotate', round(degrees, 9)))

    def move(self, meters):
        self.calls.append(('move', round(meters, 9)))

    def steer(self, primitive):
        self.calls.append(('steer', type(primitive).__name__))

    def pen(self, down):
        self.calls.append(('pen', down))

    def clear(self):
        self.calls.append(('clear',))

    def glide(self, points):
        self.calls.append(('glide', len(points)))

    def draw(self, text, where=PlannedPose(CENTRE, CENTRE, 0.0)):
        places, must_clear = self.reserve(text, where)
        self.trace(self.plan(text, places, where), must_clear)
        return self.calls


def test_the_labs_n_is_the_labs_six_calls():
    assert Recorder().draw('N') == [
        ('rotate', 90.0), ('move', 3.0), ('rotate', 225.0), ('move', 3.5),
        ('rotate', 135.0), ('move', 3.0)]


def test_feedback_mode_steers_the_same_primitives():
    assert Recorder(mode='feedback').draw('N') == [
        ('steer', 'Turn'), ('steer', 'Line')] * 3


def test_travel_to_a_stroke_lifts_the_pen():
    calls = Recorder(size=1.0).draw('K')
    pens = [c for c in calls if c[0] == 'pen']
    # K's three strokes each start away from where the turtle is
    assert pens == [('pen', False), ('pen', True)] * 3


def test_a_full_canvas_is_cleared_and_drawing_starts_again_at_the_first_place():
    drawer = Recorder()
    start = PlannedPose(CENTRE, CENTRE, 0.0)
    first, must_clear = drawer.reserve('N', start)
    assert not must_clear
    for _ in range(3):                          # the N at 3 m: four places a canvas
        assert not drawer.reserve('N', start)[1]
    places, must_clear = drawer.reserve('N', start)
    assert must_clear and places == first
    drawer.trace(drawer.plan('N', places, start), must_clear)
    assert drawer.calls[0] == ('clear',)


def test_a_word_that_does_not_fit_is_refused_and_reserves_nothing():
    drawer = Recorder()
    start = PlannedPose(CENTRE, CENTRE, 0.0)
    with pytest.raises(DoesNotFit, match='at most .* of its 12 characters fit'):
        drawer.reserve('NNNNNNNNNNNN', start)
    assert drawer.reserve('N', start) == ([(CENTRE, CENTRE)], False)


def test_smooth_mode_glides_through_each_stroke_lifting_the_pen_between():
    assert Recorder(mode='smooth').draw('N') == [('glide', 3)]
    calls = Recorder(mode='smooth', size=1.0).draw('K')
    # as in timed mode: three travels, each to a stroke of one edge
    assert calls == [('pen', False), ('glide', 1), ('pen', True),
                                       ('glide', 1)] * 3


def test_the_plan_says_ink_travel_and_time():
    drawer = Recorder()
    where = PlannedPose(CENTRE, CENTRE, 0.0)
    plan = drawer.plan('N', drawer.reserve('N', where)[0], where)
    assert (plan.ink, plan.travel) == (pytest.approx(9.5), 0.0)
    # the lab's 40.9 s: 9.5 m at 1 m/s, and 450 degrees at 0.25 rad/s
    assert plan.seconds == pytest.approx(9.5 + 2.5 * math.pi / 0.25)


def test_a_hershey_word_is_drawn_in_the_shorter_order():
    from turtle_letters.route import travel_length
    drawer = Recorder(font='futural', size=1.0)
    where = PlannedPose(CENTRE, CENTRE, 0.0)
    places = drawer.reserve('Hi!', where)[0]
    plan = drawer.plan('Hi!', places, where)
    from turtle_letters.plan import word_strokes
    reading = word_strokes('Hi!', places, 1.0, drawer.settings.font)
    assert plan.travel < travel_length(reading, plan.start)


def test_a_pen_of_another_colour_is_put_down_before_the_first_drawing_only():
    drawer = Recorder(pen='230 40 40 3')
    assert drawer.draw('N')[0] == ('pen', True)
    drawer.calls.clear()
    assert drawer.draw('N')[0] == ('pen', False)      # straight to the travel
