"""A drawing: a text's or a picture's plan, and the modes that carry a plan
out. No ROS here.

plan_request() finds a request (a text, or an SvgFile) its place on the sheet
and plans it (plan_text, plan_picture): its strokes, and the primitives
(plan.Turn, Line, Pen) that draw them. A mode from MODES carries the plan out
on a turtle, anything with the lab's calls:

    rotate(degrees), move(meters)   timed: the lab's open-loop primitives
    steer(primitive)                feedback: closed loop on the pose
    glide(points)                   smooth: a whole stroke without stopping
    pen(down, colour)               up for travel, down to draw

turtle.Turtle is one such turtle; the unit tests' recorder is another.
"""
import itertools
import math
import time
from typing import List, NamedTuple, Optional

from . import svgart
from .font import BUILTIN
from .plan import SAME_POINT, Line, Pen, Turn, plan_strokes, shown, word_strokes
from .route import ink_length, order_strokes, travel_length


DEFAULT_PEN = (179, 184, 255, 3)    # turtlesim's own: r, g, b, width in pixels


class Plan(NamedTuple):
    start: tuple            # where the turtle is when it begins
    strokes: List[list]     # in the order and direction they are drawn, meters
    primitives: list        # what timed and feedback modes carry out
    ink: float              # m drawn
    travel: float           # m with the pen up
    seconds: float          # how long it should take
    colours: Optional[list] = None  # a picture's: each stroke's pen colour (None: ~pen)


class SvgFile(NamedTuple):
    """A request to draw an SVG file's line art (a text request is a str)."""
    path: str


class Planned(NamedTuple):
    plan: Plan
    chars: list             # (character, place) of a text: a parallel word's
    must_clear: bool        # the canvas (or part) is full: start again
    label: str              # what is drawn, for the log
    note: str               # something to say about it, or ''

    def summary(self, settings):
        """What the drawing's first log line says after "Drawing"."""
        p = self.plan
        return (f'{self.label} ({settings.mode} mode{", in parallel" * settings.parallel}): '
                f'ink {p.ink:.2f} m, travel {p.travel:.2f} m, about {p.seconds:.0f} s')


def plan_request(request, sheet, start, settings) -> Planned:
    """A text's or a picture's plan, at the next free place on `sheet`;
    raises plan.DoesNotFit or svgart.SvgError (then nothing is reserved)."""
    if isinstance(request, SvgFile):
        picture = svgart.picture(svgart.read(request.path), settings.size)
        name = shown(request.path.rsplit('/', 1)[-1])
        place, must_clear = sheet.reserve_picture(picture.width / settings.size, name, start)
        note = (f'{name}: {picture.texts} text element(s) not drawn (text in an SVG is not '
                'line art)' if picture.texts else '')
        return Planned(plan_picture(picture, place, start, settings), [], must_clear,
                       f'{name}, {len(picture.strokes)} strokes', note)
    places, must_clear = sheet.reserve(request, start)
    chars = [(c, p) for c, p in zip(request, places) if p is not None]
    return Planned(plan_text(request, places, start, settings), chars, must_clear,
                   repr(request), '')


def plan_text(text, places, start, settings) -> Plan:
    """The strokes of `text` at `places` and the primitives that draw them
    from `start` (a PlannedPose). A Hershey font's strokes go in the order and
    direction that travels least with the pen up; the builtin font's keep the
    order and direction they are drawn in (so every N is the lab's N)."""
    strokes = word_strokes(text, places, settings.size, settings.font)
    if settings.font is not BUILTIN:
        strokes = order_strokes(strokes, (start.x, start.y))
    return _plan(strokes, None, start, settings)


def plan_picture(picture, place, start, settings) -> Plan:
    """A picture (svgart.Picture) with its lower left corner at `place`: its
    strokes a colour at a time, each colour's in the order that travels least.
    A ~pen other than turtlesim's own overrides the file's colours."""
    if settings.pen != DEFAULT_PEN:
        picture = picture._replace(colours=[None] * len(picture.strokes))
    here, strokes, colours = (start.x, start.y), [], []
    for colour in dict.fromkeys(picture.colours):        # in the order they come
        mine = [[(place[0] + x, place[1] + y) for x, y in stroke]
                for stroke, c in zip(picture.strokes, picture.colours) if c == colour]
        mine = order_strokes(mine, here)
        strokes += mine
        colours += [colour] * len(mine)
        here = mine[-1][-1]
    return _plan(strokes, colours, start, settings)


def _plan(strokes, colours, start, settings):
    here = (start.x, start.y)
    primitives, _ = plan_strokes(strokes, start, settings.turn_direction, colours)
    plan = Plan(here, strokes, primitives, ink_length(strokes), travel_length(strokes, here), 0.0,
                colours)
    return plan._replace(seconds=MODES[settings.mode].seconds(plan, settings))


class Timed:
    """The lab's way: every Turn a rotate(degrees), every Line a move(meters)."""

    def seconds(self, plan, settings):
        return sum(abs(p.angle) / settings.angular_speed if isinstance(p, Turn)
                   else p.length / settings.linear_speed
                   for p in plan.primitives if not isinstance(p, Pen))

    def carry_out(self, plan, turtle, progress):
        def step(primitive):
            if isinstance(primitive, Turn):
                turtle.rotate(math.degrees(primitive.angle))
            else:
                turtle.move(primitive.length)
        _each_primitive(plan, turtle, step, progress)


class Feedback:
    """The same primitives, each steered to its end on the pose."""

    def seconds(self, plan, settings):
        return MODES['timed'].seconds(plan, settings)

    def carry_out(self, plan, turtle, progress):
        _each_primitive(plan, turtle, turtle.steer, progress)


class Smooth:
    """Each stroke glided through without stopping; pen-up glides between them."""

    def seconds(self, plan, settings):
        return (plan.ink + plan.travel) / settings.linear_speed

    def carry_out(self, plan, turtle, progress):
        here, drawn, ink = plan.start, 0.0, None
        for stroke, colour in zip(plan.strokes, plan.colours or [None] * len(plan.strokes)):
            if math.hypot(stroke[0][0] - here[0], stroke[0][1] - here[1]) > SAME_POINT:
                turtle.pen(False)
                turtle.glide(stroke[:1])
                turtle.pen(True, colour)
            elif colour != ink:
                turtle.pen(True, colour)
            ink = colour
            turtle.glide(stroke[1:])
            here = stroke[-1]
            drawn += ink_length([stroke])
            progress(drawn, plan.ink)


MODES = {'timed': Timed(), 'feedback': Feedback(), 'smooth': Smooth()}


def _each_primitive(plan, turtle, step, progress):
    """Pens to the turtle, the rest to `step`; progress after each line drawn."""
    pen_down, drawn = True, 0.0
    for primitive in plan.primitives:
        if isinstance(primitive, Pen):
            turtle.pen(primitive.down, primitive.colour)
            pen_down = primitive.down
            continue
        step(primitive)
        if isinstance(primitive, Line) and pen_down:
            drawn += primitive.length
            progress(drawn, plan.ink)


class Progress:
    """How far a drawing has got (ink_drawn, m); every `period` s of it, one
    line saying so. `now`: a clock that may leave pauses out."""

    def __init__(self, say, period=5.0, now=time.monotonic):
        self.say, self.period, self.now = say, period, now
        self.started = self.last = now()
        self.ink_drawn = 0.0

    def __call__(self, ink_drawn, ink):
        self.ink_drawn = max(self.ink_drawn, ink_drawn)
        now = self.now()
        if now - self.last < self.period or not 0 < ink_drawn < ink - 1e-6:
            return
        self.last = now
        to_go = (now - self.started) * (ink - ink_drawn) / ink_drawn
        self.say(f'{100 * ink_drawn / ink:.0f}% of the ink drawn ({ink_drawn:.2f} of {ink:.2f} m); '
                 f'about {to_go:.0f} s to go')

    def report(self, plan):
        """(share of the ink drawn, seconds to go, strokes finished) by `plan`."""
        share = min(1.0, self.ink_drawn / plan.ink) if plan.ink > 0 else 0.0
        to_go = max(0.0, plan.seconds - (self.now() - self.started))
        ends = itertools.accumulate(ink_length([stroke]) for stroke in plan.strokes)
        return share, to_go, sum(1 for end in ends if end <= self.ink_drawn + 1e-6)
