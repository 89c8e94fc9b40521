"""A drawing: a text's plan, and the modes that carry a plan out. No ROS here.

plan_text() turns a text at its places into a Plan: its strokes, and the
primitives (plan.Turn, Line, Pen) that draw them. A mode from MODES carries
the plan out on a turtle, anything with the lab's calls:

    rotate(degrees), move(meters)   timed: the lab's open-loop primitives
    steer(primitive)                feedback: closed loop on the pose
    glide(points)                   smooth: a whole stroke without stopping
    pen(down)                       up for travel, down to draw

turtle.Turtle is one such turtle; the unit tests' recorder is another.
"""
import math
import time
from typing import List, NamedTuple

from .font import BUILTIN
from .plan import SAME_POINT, Line, Pen, Turn, plan_strokes, word_strokes
from .route import ink_length, order_strokes, travel_length


class Plan(NamedTuple):
    start: tuple            # where the turtle is when it begins
    strokes: List[list]     # in the order and direction they are drawn, meters
    primitives: list        # what timed and feedback modes carry out
    ink: float              # m drawn
    travel: float           # m with the pen up
    seconds: float          # how long it should take


def plan_text(text, places, start, settings) -> Plan:
    """The strokes of `text` at `places` and the primitives that draw them
    from `start` (a PlannedPose). A Hershey font's strokes go in the order and
    direction that travels least with the pen up; the builtin font's keep the
    order and direction they are drawn in (so every N is the lab's N)."""
    s = settings
    here = (start.x, start.y)
    strokes = word_strokes(text, places, s.size, s.font)
    if s.font is not BUILTIN:
        strokes = order_strokes(strokes, here)
    primitives, _ = plan_strokes(strokes, start, s.turn_direction)
    plan = Plan(here, strokes, primitives, ink_length(strokes), travel_length(strokes, here), 0.0)
    return plan._replace(seconds=MODES[s.mode].seconds(plan, s))


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
        here, drawn = plan.start, 0.0
        for stroke in plan.strokes:
            if math.hypot(stroke[0][0] - here[0], stroke[0][1] - here[1]) > SAME_POINT:
                turtle.pen(False)
                turtle.glide(stroke[:1])
                turtle.pen(True)
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
            turtle.pen(primitive.down)
            pen_down = primitive.down
            continue
        step(primitive)
        if isinstance(primitive, Line) and pen_down:
            drawn += primitive.length
            progress(drawn, plan.ink)


class Progress:
    """Every `period` s of a drawing, one line: how far, and how long to go."""

    def __init__(self, say, period=5.0, now=time.monotonic):
        self.say, self.period, self.now = say, period, now
        self.started = self.last = now()

    def __call__(self, ink_drawn, ink):
        now = self.now()
        if now - self.last < self.period or not 0 < ink_drawn < ink - 1e-6:
            return
        self.last = now
        to_go = (now - self.started) * (ink - ink_drawn) / ink_drawn
        self.say(f'{100 * ink_drawn / ink:.0f}% of the ink drawn ({ink_drawn:.2f} of {ink:.2f} m); '
                 f'about {to_go:.0f} s to go')
