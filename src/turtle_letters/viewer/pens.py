"""The ink of the real turtlesim, read from what it publishes. No ROS, no Qt.

turtlesim lays a line from each pose to the next while a turtle's pen is
down; the pen (up or down, colour, width) is set by a service that nobody
else hears. What it does publish each tick is the pose and the colour under
the turtle where it now is, read after the tick's teleport's line and
before its move's (the contract). So each step between two poses is a stroke waiting to be
judged (no gaps at any speed), and the colour under the turtle judges it:

- a colour that the canvas rebuilt so far does not show there is new ink:
  the steps waiting are drawn, in that colour (the background's: erased);
- at rest for two ticks (its last line now lies under it), the background,
  or another pen's ink, says the pen is up; its own colour, as it was;
- anything else says nothing: the steps wait, at most HOLD_TICKS, and are
  then judged as the pen was last known.

Steps judged not drawn are kept as doubts (at most DOUBTS stretches): new
ink read on one later, by any turtle, shows it drawn after all. That
catches the lines too thin or too fast to show under the turtle as it
stops (a 1-px line does in about half its stops). A teleport is drawn only
where the turtle, at rest where it landed, reads new ink: a pen-up
teleport onto old ink draws nothing; a pen-down teleport followed at once
by a move is not seen. The width is the one that best explains which
readings showed the line before (WIDTHS; where none tells, the default 3).
"""
import collections
import math
from typing import Dict, List, NamedTuple, Optional, Tuple

from ..letters.layout import CANVAS_PIXELS, DEFAULT_PEN_WIDTH as DEFAULT_WIDTH, PIXELS_PER_METRE, \
    SIM_TICK

HOLD_TICKS = 312            # 5 s: the longest a step waits to be judged
DOUBTS = 200                # stretches judged not drawn, kept to be proven drawn
WIDTHS = range(1, 13)       # px told apart: 1 (which no reading is sure to see) to 12
JUMP = 0.01                 # m a pose may be off its commanded step before it is a teleport

Colour = Tuple[int, int, int]
Line = Tuple[float, float, float, float, Colour, int]     # x0, y0, x1, y1 (m), colour, width


def to_pixels(x, y):
    """World metres to canvas pixels (y grows downwards), as turtlesim maps them."""
    return x * PIXELS_PER_METRE, (CANVAS_PIXELS - 1) - y * PIXELS_PER_METRE


def pixel(x, y):
    """The pixel turtlesim's colour sensor reads at (x, y) m: Qt's toPoint(),
    half away from zero."""
    return tuple(int(v + 0.5) if v >= 0 else -int(-v + 0.5) for v in to_pixels(x, y))


def covers(a, b, q, width):
    """Whether the square-capped line a-b (pixels) of `width` covers pixel q's centre."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    length = math.hypot(dx, dy)
    if length == 0:
        return False
    rx, ry = q[0] + 0.5 - a[0], q[1] + 0.5 - a[1]
    along, across = (rx * dx + ry * dy) / length, abs(ry * dx - rx * dy) / length
    return -width / 2 <= along <= length + width / 2 and across <= width / 2


def covered(line: Line):
    """The pixels `line` covers (a 1-px line: as if 1.5 px, to be found again)."""
    a, b = to_pixels(*line[:2]), to_pixels(*line[2:4])
    width = max(line[5], 1.5)
    reach = width / 2 + 1
    for y in range(max(0, int(min(a[1], b[1]) - reach)),
                   min(CANVAS_PIXELS, int(max(a[1], b[1]) + reach) + 1)):
        for x in range(max(0, int(min(a[0], b[0]) - reach)),
                       min(CANVAS_PIXELS, int(max(a[0], b[0]) + reach) + 1)):
            if covers(a, b, (x, y), width):
                yield x, y


class Pixels:
    """The rebuilt canvas, pixel by pixel, to tell new ink from old."""

    def __init__(self, background):
        self.fill(background)

    def fill(self, background):
        self.rgb = bytearray(bytes(background) * (CANVAS_PIXELS * CANVAS_PIXELS))

    def at(self, q):
        x, y = (min(max(v, 0), CANVAS_PIXELS - 1) for v in q)
        i = 3 * (y * CANVAS_PIXELS + x)
        return tuple(self.rgb[i:i + 3])

    def near(self, q, colour):
        """Whether `colour` is within a pixel of q (two rasterizations differ by one)."""
        return any(self.at((q[0] + dx, q[1] + dy)) == colour
                   for dx in (-1, 0, 1) for dy in (-1, 0, 1))

    def paint(self, line: Line):
        for x, y in covered(line):
            i = 3 * (y * CANVAS_PIXELS + x)
            self.rgb[i:i + 3] = bytes(line[4])


class Doubts:
    """Stretches judged not drawn, each as it would have been drawn, by the
    pixels it would have covered; the oldest forgotten past DOUBTS."""

    def __init__(self):
        self.stretches: Dict[int, List[Line]] = collections.OrderedDict()
        self.where: Dict[Tuple[int, int], int] = {}
        self.count = 0

    def add(self, lines: List[Line]):
        if not lines:
            return
        self.count += 1
        self.stretches[self.count] = lines
        for line in lines:
            for q in covered(line):
                self.where[q] = self.count
        if len(self.stretches) > DOUBTS:
            self._drop(next(iter(self.stretches)))

    def claim(self, q, colour) -> List[Line]:
        """The stretch of `colour` under pixel q, taken as drawn; [] if none."""
        key = self.where.get(tuple(q))
        if key is None or self.stretches[key][0][4] != colour:
            return []
        return self._drop(key)

    def _drop(self, key):
        lines = self.stretches.pop(key)
        self.where = {q: k for q, k in self.where.items() if k != key}
        return lines

    def clear(self):
        self.__init__()


class Step(NamedTuple):
    x0: float
    y0: float
    x1: float
    y1: float


class Seen(NamedTuple):
    """A reading over the background where the turtle's last line may lie."""
    line: Tuple[Tuple[float, float], Tuple[float, float]]     # that line, in pixels
    at: Tuple[int, int]
    colour: Colour


class Pen(NamedTuple):
    down: bool
    colour: Colour
    width: int


class PenReader:
    """One turtle's steps, judged by the colour under it: `read` gives back
    the lines it judges drawn."""

    def __init__(self, x, y, colour, width=DEFAULT_WIDTH):
        self.x, self.y = x, y
        self.pen = Pen(True, colour, width)     # as last known
        self.steps: List[Step] = []             # not yet judged
        self.seen: List[Seen] = []              # readings to weigh the width by
        self.tally = [0] * len(WIDTHS)          # readings each width explains, this pen's
        self.rest = 0                           # ticks standing on one spot
        self.line = None                        # the last move's line, in pixels
        self.under = None                       # the line that may lie under the turtle now
        self.jump: Optional[Step] = None        # a teleport, judged at rest where it landed

    def pose(self, x, y, theta, speed):
        """The tick's pose; `speed` the linear speed it was commanded (m/s)."""
        self.under = self.line          # the last move's line lies under it now
        if (x, y) == (self.x, self.y):
            self.rest += 1
            return
        self.rest, self.line = 0, None
        move = speed * SIM_TICK         # turtlesim moves on the new heading
        landed = (x - move * math.cos(theta), y - move * math.sin(theta))
        if math.hypot(landed[0] - self.x, landed[1] - self.y) > JUMP:
            self.jump, self.under = Step(self.x, self.y, *landed), None
        else:
            landed, self.jump = (self.x, self.y), None
        if (x, y) != landed:
            self.steps.append(Step(*landed, x, y))
            self.line = (to_pixels(*landed), to_pixels(x, y))
        self.x, self.y = x, y

    def read(self, colour, pixels, doubts, background) -> List[Line]:
        """The colour under the turtle this tick: the lines it proves or settles."""
        q = pixel(self.x, self.y)
        new = colour != pixels.at(q) and not pixels.near(q, colour)
        drawn = doubts.claim(q, colour) if new else []
        new = new and not drawn
        reading = Seen(self.under, q, colour)
        if self.under is not None and pixels.at(q) == background and \
                self.seen[-1:] != [reading]:    # a spot read again says nothing new
            self.seen.append(reading)
        if self.jump is not None and self.rest >= 2:
            if new:
                drawn.append(self.jump + (colour, self.pen.width))
            self.jump = None
        if not self.steps:
            return drawn
        if new:
            return drawn + self._judge(Pen(True, colour, self.pen.width), doubts)
        if self.rest >= 2:
            if colour == background:    # a 1-px line shows in about half its stops
                down = self.pen.down and self.pen.width == 1
            else:                       # another pen's ink shows this one up
                down = self.pen.down and colour == self.pen.colour
            return drawn + self._judge(self.pen._replace(down=down), doubts)
        if len(self.steps) > HOLD_TICKS:
            return drawn + self._judge(self.pen, doubts)
        return drawn

    def _judge(self, pen, doubts) -> List[Line]:
        """Every step waiting, drawn with `pen` if it is down, else a doubt."""
        if pen.colour != self.pen.colour:
            self.tally = [0] * len(WIDTHS)
        if pen.down:
            self._weigh(pen.colour)
            pen = pen._replace(width=self._width())
        self.pen = pen
        lines = [step + (self.pen.colour, self.pen.width) for step in self.steps]
        self.steps, self.seen = [], []
        if pen.down:
            return lines
        doubts.add(lines)
        return []

    def _weigh(self, colour):
        for seen in self.seen:
            showed = seen.colour == colour
            for i, width in enumerate(WIDTHS):
                self.tally[i] += showed == (width > 1 and covers(*seen.line, seen.at, width))

    def _width(self):
        best = max(self.tally)
        return min((w for w, n in zip(WIDTHS, self.tally) if n == best),
                   key=lambda w: abs(w - DEFAULT_WIDTH))
