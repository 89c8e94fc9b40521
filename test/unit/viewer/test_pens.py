"""The real turtlesim's ink read from its poses and colour sensor: the
bundled simulator's kinematics and Qt canvas (turtlesim_compat) stand in
for turtlesim, tick by tick in its order (teleports, the colour read, the
move's line), and the rebuilt picture is held against its canvas."""
import pytest
from PyQt5.QtGui import QColor

from turtlesim_compat.canvas import Canvas
from turtlesim_compat.world import World
from turtle_letters.viewer.picture import Painting
from turtle_letters.viewer.trails import DEFAULT_BACKGROUND, Trails

RED, GREEN, WHITE = (255, 0, 0), (0, 160, 0), (255, 255, 255)
NEAR = 2            # px: a rasterization may differ by a pixel or two


class Turtlesim:
    """One turtle on the model of turtlesim, heard by a Trails as the viewer hears it."""

    def __init__(self, background=DEFAULT_BACKGROUND):
        self.world, self.canvas = World(), Canvas(background)
        self.turtle = self.world.spawn(1.0, 1.0, 0.0)
        self.trails, self.ticks = Trails(background), 0
        self.tick()

    def tick(self):
        t, now = self.turtle, self.ticks * 0.016
        self.canvas.draw(t.teleport())
        moved, _ = t.move(now)
        self.trails.pose('turtle1', t.x, t.y, t.theta, t.linear_speed)
        self.trails.colour('turtle1', self.canvas.colour_at(t.x, t.y))
        self.canvas.draw(moved)         # after the colour is read
        self.ticks += 1

    def drive(self, metres, speed, turn=0.0):
        for _ in range(round(metres / speed / 0.016)):
            self.turtle.command(speed, 0.0, turn, self.ticks * 0.016)
            self.tick()
        self.turtle.command(0.0, 0.0, 0.0, self.ticks * 0.016)
        self.rest()

    def rest(self, ticks=10):
        for _ in range(ticks):
            self.tick()

    def teleport(self, x, y, theta=0.0):
        self.turtle.teleport_absolute(x, y, theta)
        self.rest()

    def pen(self, colour, width=3, off=0):
        self.turtle.set_pen(*colour, width, off)


def ink(image, background):
    found = set()
    for y in range(image.height()):
        for x in range(image.width()):
            c = QColor(image.pixel(x, y))
            if (c.red(), c.green(), c.blue()) != background:
                found.add((x, y, (c.red(), c.green(), c.blue())))
    return found


def near_share(pixels, others):
    """The share of `pixels` with one of `others` of their colour within NEAR px."""
    near = sum(1 for x, y, c in pixels if any((x + dx, y + dy, c) in others
                                              for dx in range(-NEAR, NEAR + 1)
                                              for dy in range(-NEAR, NEAR + 1)))
    return near / max(len(pixels), 1)


def compare(sim, background=DEFAULT_BACKGROUND):
    """(share of turtlesim's ink on the rebuilt canvas, share of the rebuilt ink turtlesim has)."""
    painting = Painting(sim.trails)
    painting.update()
    truth, rebuilt = ink(sim.canvas._paths, background), ink(painting.image, background)
    assert truth, 'turtlesim drew nothing'
    return near_share(truth, rebuilt), near_share(rebuilt, truth)


@pytest.mark.parametrize('width, speed', [(2, 0.5), (2, 1.0)] + [
    (width, speed) for width in (3, 6) for speed in (0.5, 1.0, 2.0, 2.5, 4.0)])
def test_a_line_at_any_speed_and_width_is_whole_and_nothing_more(width, speed):
    """(Where it stops: a 1-px line hardly ever shows under a moving turtle
    and in about half its stops, and a 2-px one faster than about 1.5 m/s
    shows only where it stops, in nine of ten: such lines are drawn where a
    reading finds them.)"""
    sim = Turtlesim()
    sim.pen(RED, width)
    sim.drive(3.0, speed)
    sim.turtle.command(0.0, 0.0, 1.0, sim.ticks * 0.016)
    sim.rest(100)                       # a turn in place, then on
    sim.drive(2.0, speed)
    found, extra = compare(sim)
    assert found > 0.97 and extra > 0.97


def test_the_widths_told_apart_at_the_labs_speed():
    """At 1 m/s a step is 0.72 px: the readings tell 2 and 3 px apart, and
    any wider pen from them (as at least 4)."""
    for width in (2, 3, 5, 8):
        sim = Turtlesim()
        sim.pen(RED, width)
        sim.drive(3.0, 1.0)
        told = sim.trails.readers['turtle1'].pen.width
        assert told == width if width <= 3 else told >= 4


def test_a_pen_up_teleport_onto_ink_draws_no_line_and_a_pen_down_one_does():
    sim = Turtlesim()
    sim.pen(RED, 1)
    sim.drive(3.0, 2.5)                 # a 1-px line too fast to show under the turtle
    sim.pen(RED, 1, off=1)
    sim.teleport(2.0, 1.0)              # onto it
    sim.teleport(9.0, 9.0)              # and away
    sim.pen(GREEN, 3)
    sim.teleport(9.0, 5.0)              # pen down: a green line
    found, extra = compare(sim)
    assert found > 0.97 and extra > 0.97


def test_travel_with_the_pen_up_is_no_ink():
    sim = Turtlesim()
    sim.drive(2.0, 1.0)
    sim.pen(WHITE, 3, off=1)
    sim.turtle.command(0.0, 0.0, 1.6, 0)
    sim.rest(60)
    sim.drive(2.0, 2.0)                 # up, across nothing
    sim.pen(WHITE, 3)
    sim.drive(1.0, 1.0)
    found, extra = compare(sim)
    assert found > 0.97 and extra > 0.97


def test_a_pen_in_the_background_colour_erases():
    sim = Turtlesim()
    sim.pen(RED, 5)
    sim.drive(3.0, 1.0)
    sim.pen(DEFAULT_BACKGROUND, 5)
    sim.turtle.command(0.0, 0.0, 3.14159 / 0.5, 0)
    sim.rest(31)
    sim.drive(1.5, 1.0)                 # back over half of it
    found, extra = compare(sim)
    assert found > 0.97 and extra > 0.97


def test_a_clear_to_another_background_is_read_again():
    sim = Turtlesim()
    sim.drive(1.0, 1.0)
    sim.canvas.clear((10, 20, 30))
    sim.trails.clear((10, 20, 30))
    sim.drive(1.0, 1.0)
    found, extra = compare(sim, (10, 20, 30))
    assert found > 0.97 and extra > 0.97 and sim.trails.background == (10, 20, 30)


def test_a_turtle_parked_on_the_background_keeps_no_reading_per_tick():
    """After pen-up travel, a turtle standing on the background gave a
    reading a tick, which nothing cleared: 37,000 after 10 minutes. One
    reading of a spot says all the ticks on it can say."""
    sim = Turtlesim()
    sim.pen(WHITE, 3, off=1)
    sim.drive(2.0, 1.0)                 # up, across nothing
    sim.rest(10 * 60 * 62)              # parked for ten minutes of turtlesim's ticks
    assert len(sim.trails.readers['turtle1'].seen) <= 2
    sim.pen(WHITE, 3)
    sim.drive(1.0, 1.0)
    found, extra = compare(sim)
    assert found > 0.97 and extra > 0.97
