"""The shared canvas as the viewer rebuilds it. With the bundled simulator
it is the ink the simulator laid, as it says on its `ink` topic: each
segment with its colour and width, each clear and reset with the
background (`ink()`). With the real turtlesim, which publishes no ink, it
is rebuilt from what it does publish: each turtle's pose, and its
color_sensor, the colour under it. That colour is the pen's while the pen
is down and the background's while it is up, so a step ending on another
colour than the background is a stroke in that colour. No ROS here.

turtlesim reads the colour before it draws the tick's own line, so what it
reads is the line before, which a 3-px pen covers while a tick's step is
under 1.5 px (up to about 2 m/s): a pen lifted or put down shows a tick
late, and about one reading in twenty on a straight line falls on a pixel
the line missed, a tick-long gap that the strokes' square caps close. A
stroke runs from where the last colour was read to the newest pose. The
width is not published: such strokes are PEN_WIDTH wide, turtlesim's default. A
pen-up step that ends on another line reads its colour and retraces a tick
of it.
"""
import math
import threading
from typing import Dict, List, NamedTuple, Optional, Tuple

from ..letters.layout import CANVAS_PIXELS, PIXELS_PER_METRE

PEN_WIDTH = 3                   # px: turtlesim's default pen
DEFAULT_BACKGROUND = (69, 86, 255)


def to_pixels(x, y):
    """World metres to canvas pixels (y grows downwards), as turtlesim maps them."""
    return x * PIXELS_PER_METRE, (CANVAS_PIXELS - 1) - y * PIXELS_PER_METRE


class Stroke(NamedTuple):
    turtle: str
    colour: Tuple[int, int, int]
    x0: float
    y0: float
    x1: float
    y1: float
    width: int = PEN_WIDTH


class Turtle(NamedTuple):
    x: float
    y: float
    theta: float
    drawn_to: Tuple[float, float]       # where its last stroke (or pen-up step) ended
    colour: Optional[Tuple[int, int, int]] = None   # the last colour read under it


class Trails:
    """Every turtle and every stroke so far; thread-safe, as ROS callbacks
    write while the server reads. `strokes` only grows until a clear; each
    clear counts in `clears`, so a reader can tell its place is gone."""

    def __init__(self, background=DEFAULT_BACKGROUND):
        self.background = tuple(background)
        self.turtles: Dict[str, Turtle] = {}
        self.strokes: List[Stroke] = []     # those after the first `folded` since the clear
        self.folded = 0
        self.clears = 0
        self.inked = False      # strokes come from the simulator's ink, not the colour under it
        self.lock = threading.Lock()

    def pose(self, name, x, y, theta):
        """Turtle `name` at a pose; a pose that is not all finite numbers
        (a NaN from a broken node) is no place, and leaves it where it was."""
        if not all(math.isfinite(v) for v in (x, y, theta)):
            return
        with self.lock:
            turtle = self.turtles.get(name)
            drawn_to = turtle.drawn_to if turtle else (x, y)
            colour = turtle.colour if turtle else None
            self.turtles[name] = Turtle(x, y, theta, drawn_to, colour)

    def colour(self, name, rgb):
        """The colour under turtle `name` now: a stroke to its newest pose,
        unless that colour is the background (its pen is up)."""
        rgb = tuple(int(c) for c in rgb)
        with self.lock:
            turtle = self.turtles.get(name)
            if turtle is None:
                return
            here = (turtle.x, turtle.y)
            if rgb != self.background and here != turtle.drawn_to and not self.inked:
                self.strokes.append(Stroke(name, rgb, *turtle.drawn_to, *here))
            self.turtles[name] = turtle._replace(drawn_to=here, colour=rgb)

    def ink(self, lines):
        """The simulator's own account of a tick (its `ink` topic): the
        segments its pens laid, clears and resets with their background."""
        with self.lock:
            self.inked = True
            for line in lines:
                kind = line.get('k')
                if kind in ('clear', 'reset'):
                    self.background = tuple(line.get('background', self.background))
                    self.strokes = []
                    self.clears += 1
                    self.folded = 0
                    if kind == 'reset':
                        self.turtles = {}
                elif kind == 'kill':
                    self.turtles.pop(line.get('turtle'), None)
                for x0, y0, x1, y1, r, g, b, width in line.get('ink', []):
                    if all(math.isfinite(v) for v in (x0, y0, x1, y1)):
                        self.strokes.append(Stroke(line.get('turtle', ''), (r, g, b), x0, y0,
                                                   x1, y1, width))

    def gone(self, name):
        """Turtle `name` was killed: its strokes stay, as on turtlesim's canvas."""
        with self.lock:
            self.turtles.pop(name, None)

    def clear(self):
        with self.lock:
            self.strokes = []
            self.clears += 1
            self.folded = 0

    def reset(self):
        """turtlesim reset: the canvas cleared and every turtle gone
        (turtle1 comes back by its pose)."""
        with self.lock:
            self.strokes, self.turtles = [], {}
            self.clears += 1
            self.folded = 0

    def turtles_now(self):
        with self.lock:
            return dict(self.turtles)

    def since(self, clears, count):
        """(clears, strokes after the first `count`, turtles) for a reader
        that has seen `count` strokes since clear number `clears`; all the
        strokes when a clear came since; None for the strokes when those it
        lacks are folded away (it must start again from a picture)."""
        with self.lock:
            start = count if clears == self.clears else 0
            if start < self.folded:
                return self.clears, None, dict(self.turtles)
            return self.clears, self.strokes[start - self.folded:], dict(self.turtles)

    def fold(self, clears, count):
        """Forgets the first `count` strokes since clear number `clears`, if
        it is the last: every reader has them (in a picture), so memory
        stays bounded."""
        with self.lock:
            if clears != self.clears:
                return
            drop = min(count - self.folded, len(self.strokes))
            if drop > 0:
                del self.strokes[:drop]
                self.folded += drop
