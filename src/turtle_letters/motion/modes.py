"""The modes that carry a plan (letters/plan.py) out on a turtle: anything
with the lab's calls. No ROS here.

    rotate(degrees), move(meters)   timed: the lab's open-loop primitives
    steer(primitive)                feedback: closed loop on the pose
    glide(points)                   smooth: a whole stroke without stopping
    pen(down, colour)               up for travel, down to draw

turtle.Turtle is one such turtle; the unit tests' recorder is another.
`progress(ink_drawn, ink)` is told after each line drawn.
"""
import math

from ..letters.primitives import Line, Pen, Turn, Written, pen_changes
from ..letters.route import ink_length
from ..letters.written import Scaled


class Timed:
    """The lab's way: every Turn a rotate(degrees), every Line a move(meters),
    and a written letter (the lab's N) its own calls (lab.py)."""

    def carry_out(self, plan, turtle, progress):
        def step(primitive, drew):
            if isinstance(primitive, Written):
                primitive.program(Scaled(turtle, primitive.scale, primitive.direction, drew))
            elif isinstance(primitive, Turn):
                turtle.rotate(math.degrees(primitive.angle))
            else:
                turtle.move(primitive.length)
                drew(primitive.length)
        _each_primitive(plan, turtle, step, progress)


class Feedback:
    """The same primitives, each steered to its end on the pose (a written
    letter's one by one)."""

    def carry_out(self, plan, turtle, progress):
        def step(primitive, drew):
            for each in primitive.steps if isinstance(primitive, Written) else [primitive]:
                turtle.steer(each)
                if isinstance(each, Line):
                    drew(each.length)
        _each_primitive(plan, turtle, step, progress)


class Smooth:
    """Each stroke glided through without stopping; pen-up glides between them."""

    def carry_out(self, plan, turtle, progress):
        drawn = 0.0
        for stroke, colour, travel in pen_changes(plan.strokes, plan.colours, plan.start):
            if travel:
                turtle.pen(False)
                turtle.glide(stroke[:1])
            if colour is not False:
                turtle.pen(True, colour)
            turtle.glide(stroke[1:])
            drawn += ink_length([stroke])
            progress(drawn, plan.ink)


MODES = {'timed': Timed(), 'feedback': Feedback(), 'smooth': Smooth()}


def _each_primitive(plan, turtle, step, progress):
    """Pens to the turtle, the rest to `step(primitive, drew)`, which tells
    `drew(meters)` each line it drives; with the pen down, that is ink."""
    pen_down, drawn = True, 0.0

    def drew(meters):
        nonlocal drawn
        if pen_down:
            drawn += meters
            progress(drawn, plan.ink)
    for primitive in plan.primitives:
        if isinstance(primitive, Pen):
            turtle.pen(primitive.down, primitive.colour)
            pen_down = primitive.down
        else:
            step(primitive, drew)
