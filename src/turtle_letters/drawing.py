"""A drawing, in the lab's own calls. No ROS here.

LetterDrawer turns text into the calls the lab's class makes: in timed mode
rotate(degrees) and move(meters), so the lab's N is literally rotate(90),
move(3.0), rotate(225), move(3.5), rotate(135), move(3.0); in feedback mode
steer(primitive), which closes the loop on the pose; in smooth mode
glide(points), which traces a whole stroke without stopping; pen(down) to
lift the pen for travel; clear() when the canvas (or the turtle's part of
it) is full. A subclass supplies those calls:
TurtleController with ROS, a recorder in the unit tests.
"""
import math
from typing import List, NamedTuple

from .font import BUILTIN
from .settings import DEFAULT_PEN
from .plan import (SAME_POINT, Layout, Line, Pen, PlannedPose, Turn, plan_strokes,
                   word_strokes)
from .route import ink_length, order_strokes, travel_length


class Plan(NamedTuple):
    start: tuple            # where the turtle is when it begins
    strokes: List[list]     # in the order and direction they are drawn, meters
    primitives: list        # what timed and feedback modes carry out
    ink: float              # m drawn
    travel: float           # m with the pen up
    seconds: float          # how long it should take


class LetterDrawer:
    def __init__(self, settings):
        self.settings = settings
        # On a shared canvas, (first place, bounds) of this turtle's part
        # (see parts.py); None: the whole canvas, from where the turtle stands.
        self.part = None
        self.resume_at = None   # where a restarted controller's next letter goes in its part
        self._layout = None
        # turtlesim's pen starts down in its default colour: a call is needed
        # only for another colour, or when the pen may have been left up
        self._pen_ready = settings.pen == DEFAULT_PEN

    def forget_layout(self):
        """After a failed drawing: the next one starts a new layout where the
        turtle then is (in a part: at the part's next place, past what the
        failed one reserved), and puts the pen down first."""
        self.resume_at = self.cursor if self.part is not None else None
        self._layout = None
        self._pen_ready = False

    def reserve(self, text, where: PlannedPose):
        """The places of `text`'s characters and whether the canvas must be
        cleared first; raises plan.DoesNotFit (then nothing was reserved)."""
        if self._layout is None:
            s = self.settings
            if self.part is None:
                self._layout = Layout((where.x, where.y), s.size, s.font)
            else:
                self._layout = Layout(self.part[0], s.size, s.font, bounds=self.part[1])
                if self.resume_at is not None:
                    self._layout.cursor = self.resume_at
        return self._layout.reserve(text)

    @property
    def cursor(self):
        """Where the next letter goes, once a drawing has been laid out."""
        return self._layout.cursor if self._layout is not None else self.resume_at

    def plan(self, text, places, start: PlannedPose) -> Plan:
        """The strokes of `text` at `places` and the primitives that draw them
        from `start`. A Hershey font's strokes go in the order and direction
        that travels least with the pen up; the builtin font's keep the order
        and direction they are drawn in (so every N is the lab's N)."""
        s = self.settings
        here = (start.x, start.y)
        strokes = word_strokes(text, places, s.size, s.font)
        if s.font is not BUILTIN:       # the builtin font keeps the lab's order and direction
            strokes = order_strokes(strokes, here)
        primitives, _ = plan_strokes(strokes, start, s.turn_direction)
        ink, travel = ink_length(strokes), travel_length(strokes, here)
        if s.mode == 'smooth':
            seconds = (ink + travel) / s.linear_speed
        else:
            seconds = sum(abs(p.angle) / s.angular_speed if isinstance(p, Turn)
                          else p.length / s.linear_speed
                          for p in primitives if not isinstance(p, Pen))
        return Plan(here, strokes, primitives, ink, travel, seconds)

    def trace(self, plan: Plan, must_clear: bool):
        """Carry out a plan; progress(ink drawn, ink in all) after each part."""
        if must_clear:
            self.clear()
        if not self._pen_ready:
            self.pen(True)
            self._pen_ready = True
        drawn = 0.0
        if self.settings.mode == 'smooth':
            here = plan.start
            for stroke in plan.strokes:
                if math.hypot(stroke[0][0] - here[0], stroke[0][1] - here[1]) > SAME_POINT:
                    self.pen(False)
                    self.glide(stroke[:1])
                    self.pen(True)
                self.glide(stroke[1:])
                here = stroke[-1]
                drawn += ink_length([stroke])
                self.progress(drawn, plan.ink)
            return
        pen_down = True
        for primitive in plan.primitives:
            self._carry_out(primitive)
            if isinstance(primitive, Pen):
                pen_down = primitive.down
            elif isinstance(primitive, Line) and pen_down:
                drawn += primitive.length
                self.progress(drawn, plan.ink)

    def _carry_out(self, primitive):
        if isinstance(primitive, Pen):
            self.pen(primitive.down)
        elif self.settings.mode == 'feedback':
            self.steer(primitive)
        elif isinstance(primitive, Turn):
            self.rotate(math.degrees(primitive.angle))
        else:
            self.move(primitive.length)

    # Supplied by a subclass.
    def rotate(self, degrees):
        raise NotImplementedError

    def move(self, meters):
        raise NotImplementedError

    def steer(self, primitive):
        raise NotImplementedError

    def glide(self, points):
        raise NotImplementedError

    def progress(self, ink_drawn, ink):
        pass

    def pen(self, down):
        raise NotImplementedError

    def clear(self):
        raise NotImplementedError
