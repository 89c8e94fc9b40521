"""The shared canvas as the viewer rebuilds it. With the bundled simulator
it is the ink the simulator laid, as it says on its `ink` topic: each
segment with its colour and width, each clear and reset with the
background (`ink()`). With the real turtlesim, which publishes no ink, it
is read from what it does publish, each turtle's pose and the colour under
it, by a PenReader a turtle (pens.py). No ROS here.
"""
import math
import threading
from typing import Dict, List, NamedTuple, Tuple

from ..letters.layout import DEFAULT_BACKGROUND, DEFAULT_PEN, DEFAULT_PEN_WIDTH as PEN_WIDTH
from .pens import Doubts, PenReader, Pixels, to_pixels


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
        self.readers: Dict[str, PenReader] = {}
        self.pixels = None      # the canvas pixel by pixel, once a turtle is read by its pen
        self.doubts = Doubts()
        self.lock = threading.Lock()

    def pose(self, name, x, y, theta, speed=0.0):
        """Turtle `name` at a pose, commanded `speed` m/s; a pose that is not
        all finite numbers (a NaN from a broken node) is no place, and
        leaves it where it was."""
        if not all(math.isfinite(v) for v in (x, y, theta, speed)):
            return
        with self.lock:
            self.turtles[name] = Turtle(x, y, theta)
            reader = self.readers.get(name)
            if self.inked:              # the simulator says its ink itself
                return
            if reader is None:
                self.readers[name] = PenReader(x, y, DEFAULT_PEN)
            else:
                reader.pose(x, y, theta, speed)

    def colour(self, name, rgb):
        """The colour under turtle `name` now: the strokes it shows drawn."""
        rgb = tuple(int(c) for c in rgb)
        with self.lock:
            reader = self.readers.get(name)
            if reader is None or self.inked:
                return
            if self.pixels is None:
                self.pixels = Pixels(self.background)
            for line in reader.read(rgb, self.pixels, self.doubts, self.background):
                self.pixels.paint(line)
                x0, y0, x1, y1, colour, width = line
                self.strokes.append(Stroke(name, colour, x0, y0, x1, y1, width))

    def ink(self, lines):
        """The simulator's own account of a tick (its `ink` topic): the
        segments its pens laid, clears and resets with their background."""
        with self.lock:
            self.inked = True
            for line in lines:
                kind = line.get('k')
                if kind in ('clear', 'reset'):
                    self._cleared(line.get('background'))
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
            self.readers.pop(name, None)

    def clear(self, background=None):
        """turtlesim cleared its canvas (to `background`, if it is known)."""
        with self.lock:
            self._cleared(background)

    def reset(self, background=None):
        """turtlesim reset: the canvas cleared and every turtle gone
        (turtle1 comes back by its pose)."""
        with self.lock:
            self._cleared(background)
            self.turtles, self.readers = {}, {}

    def _cleared(self, background):
        self.background = tuple(background or self.background)
        self.strokes, self.folded = [], 0
        self.clears += 1
        self.doubts.clear()
        if self.pixels is not None:
            self.pixels.fill(self.background)
        for reader in self.readers.values():
            reader.steps, reader.jump = [], None

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
