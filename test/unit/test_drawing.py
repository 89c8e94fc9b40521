"""The drawing, in the lab's calls: what the lab's turtle is asked to do."""
import math
from types import SimpleNamespace

import pytest

from turtle_letters.drawing import MODES, Progress, plan_text
from turtle_letters.font import BUILTIN
from turtle_letters.plan import WORLD_SIZE, DoesNotFit, PlannedPose
from turtle_letters.settings import Settings
from turtle_letters.sheet import Sheet

CENTRE = WORLD_SIZE / 2


def settings(**given):
    return Settings(lambda name, default: given.get(name.lstrip('~'), default))


class Recorder:
    """A turtle with its calls written down instead of carried out."""

    def __init__(self):
        self.calls = []

    def rotate(self, degrees):
        self.calls.append(('rotate', round(degrees, 9)))

    def move(self, meters):
        self.calls.append(('move', round(meters, 9)))

    def steer(self, primitive):
        self.calls.append(('steer', type(primitive).__name__))

    def pen(self, down, colour=None):
        self.calls.append(('pen', down) if colour is None else ('pen', down, colour))

    def glide(self, points):
        self.calls.append(('glide', len(points)))


class Drawer:
    """What the controller does with a text: its places on a sheet, a plan,
    and the mode's calls on a recording turtle."""

    def __init__(self, **given):
        self.settings = settings(**given)
        self.sheet = Sheet(self.settings.size, self.settings.font)
        self.turtle = Recorder()

    def draw(self, text, where=PlannedPose(CENTRE, CENTRE, 0.0)):
        places, _ = self.sheet.reserve(text, where)
        plan = plan_text(text, places, where, self.settings)
        MODES[self.settings.mode].carry_out(plan, self.turtle, lambda drawn, ink: None)
        return self.turtle.calls


def test_the_labs_n_written_out_in_the_labs_class_is_the_n_the_font_plans():
    # the lab's class is a ROS node: where rospy is absent, this one is skipped
    controller = pytest.importorskip('turtle_letters.controller')
    lab = SimpleNamespace(turtle=Recorder())
    controller.TurtleController.draw_the_labs_n(lab)
    assert lab.turtle.calls == Drawer().draw('N')


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


def test_the_labs_n_is_the_labs_six_calls():
    assert Drawer().draw('N') == [
        ('rotate', 90.0), ('move', 3.0), ('rotate', 225.0), ('move', 3.5),
        ('rotate', 135.0), ('move', 3.0)]


def test_feedback_mode_steers_the_same_primitives():
    assert Drawer(mode='feedback').draw('N') == [
        ('steer', 'Turn'), ('steer', 'Line')] * 3


def test_travel_to_a_stroke_lifts_the_pen():
    calls = Drawer(size=1.0).draw('K')
    pens = [c for c in calls if c[0] == 'pen']
    # K's three strokes each start away from where the turtle is
    assert pens == [('pen', False), ('pen', True)] * 3


def test_a_full_canvas_is_started_again_at_the_first_place():
    sheet = Sheet(3.0, settings().font)
    start = PlannedPose(CENTRE, CENTRE, 0.0)
    first, must_clear = sheet.reserve('N', start)
    assert not must_clear
    for _ in range(3):                          # the N at 3 m: four places a canvas
        assert not sheet.reserve('N', start)[1]
    places, must_clear = sheet.reserve('N', start)
    assert must_clear and places == first


def test_a_word_that_does_not_fit_is_refused_and_reserves_nothing():
    sheet = Sheet(3.0, settings().font)
    start = PlannedPose(CENTRE, CENTRE, 0.0)
    with pytest.raises(DoesNotFit, match='at most .* of its 12 characters fit'):
        sheet.reserve('NNNNNNNNNNNN', start)
    assert sheet.reserve('N', start) == ([(CENTRE, CENTRE)], False)


def test_a_part_carries_on_from_its_cursor_and_after_a_failure_past_it():
    from turtle_letters.parts import letter_bounds, part_box
    font = settings().font
    sheet = Sheet(1.0, font)
    box = part_box((1.0, 5.0), 5.0, 1.0, font)      # five letter heights wide
    sheet.give_part((1.0, 5.0), letter_bounds(box, 1.0, font), cursor=(2.0, 5.0))
    assert sheet.reserve('N', None)[0] == [(2.0, 5.0)]
    after = sheet.cursor
    sheet.forget()              # the drawing failed: its place is not used again
    assert sheet.reserve('N', None)[0] == [after]


def test_smooth_mode_glides_through_each_stroke_lifting_the_pen_between():
    assert Drawer(mode='smooth').draw('N') == [('glide', 3)]
    calls = Drawer(mode='smooth', size=1.0).draw('K')
    # as in timed mode: three travels, each to a stroke of one edge
    assert calls == [('pen', False), ('glide', 1), ('pen', True),
                                       ('glide', 1)] * 3


def test_the_plan_says_ink_travel_and_time():
    where = PlannedPose(CENTRE, CENTRE, 0.0)
    plan = plan_text('N', [(CENTRE, CENTRE)], where, settings())
    assert (plan.ink, plan.travel) == (pytest.approx(9.5), 0.0)
    # the lab's 40.9 s: 9.5 m at 1 m/s, and 450 degrees at 0.25 rad/s
    assert plan.seconds == pytest.approx(9.5 + 2.5 * math.pi / 0.25)
    assert plan_text('N', [(CENTRE, CENTRE)], where, settings(mode='smooth')).seconds == \
        pytest.approx(9.5)


def test_a_hershey_word_is_drawn_in_the_shorter_order():
    from turtle_letters.plan import word_strokes
    from turtle_letters.route import travel_length
    given = settings(font='futural', size=1.0)
    where = PlannedPose(CENTRE, CENTRE, 0.0)
    places = Sheet(1.0, given.font).reserve('Hi!', where)[0]
    plan = plan_text('Hi!', places, where, given)
    reading = word_strokes('Hi!', places, 1.0, given.font)
    assert plan.travel < travel_length(reading, plan.start)


def test_every_mode_has_one_object_and_the_parameter_table_offers_each():
    from turtle_letters.settings import PARAMETERS
    mode = next(p for p in PARAMETERS if p.name == 'mode')
    for name in MODES:
        assert mode.check(name) == name
    with pytest.raises(ValueError):
        mode.check('busy-loop')


def test_progress_is_said_every_few_seconds_with_the_time_to_go():
    said, clock = [], [0.0]
    progress = Progress(said.append, period=5.0, now=lambda: clock[0])
    clock[0] = 2.0
    progress(1.0, 4.0)          # too soon
    clock[0] = 6.0
    progress(2.0, 4.0)
    progress(3.0, 4.0)          # too soon again
    clock[0] = 12.0
    progress(4.0, 4.0)          # done: nothing to say
    assert said == ['50% of the ink drawn (2.00 of 4.00 m); about 6 s to go']


def test_the_report_counts_ink_and_strokes_and_the_time_left_by_the_plan():
    clock = [0.0]
    plan = plan_text('NL', Sheet(3.0, BUILTIN).reserve('NL', PlannedPose(1.0, 6.0, 0.0))[0],
                     PlannedPose(1.0, 6.0, 0.0), settings())
    progress = Progress(lambda line: None, now=lambda: clock[0])
    assert progress.report(plan) == (0.0, plan.seconds, 0)
    n_ink = 3.0 + math.hypot(3.0 * 0.825, 3.0 * 0.825) + 3.0
    clock[0] = 50.0
    progress(n_ink, plan.ink)                   # the N's last line: one stroke done
    share, to_go, strokes = progress.report(plan)
    assert (round(share, 6), round(to_go, 6), strokes) == (
        round(n_ink / plan.ink, 6), round(plan.seconds - 50.0, 6), 1)
    progress(n_ink - 1.0, plan.ink)             # a report never goes back
    assert progress.report(plan)[0] == share
    clock[0] = 500.0
    progress(plan.ink, plan.ink)
    assert progress.report(plan) == (1.0, 0.0, len(plan.strokes))
