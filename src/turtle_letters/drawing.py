"""A drawing, in the lab's own calls. No ROS here.

LetterDrawer turns text into the calls the lab's class makes: in timed mode
rotate(degrees) and move(meters), so the lab's N is literally rotate(90),
move(3.0), rotate(225), move(3.5), rotate(135), move(3.0); in feedback mode
steer(primitive), which closes the loop on the pose; pen(down) to lift the pen
for travel; clear() when the canvas is full. A subclass supplies those calls:
TurtleController with ROS, a recorder in the unit tests.
"""
import math

from .plan import Layout, Pen, PlannedPose, Turn, plan_strokes, word_strokes
from .route import order_strokes


class LetterDrawer:
    def __init__(self, settings):
        self.settings = settings
        self._layout = None

    def forget_layout(self):
        """The next drawing starts a new layout where the turtle then is."""
        self._layout = None

    def reserve(self, text, where: PlannedPose):
        """The places of `text`'s characters and whether the canvas must be
        cleared first; raises plan.DoesNotFit (then nothing was reserved)."""
        if self._layout is None:
            self._layout = Layout((where.x, where.y), self.settings.size, self.settings.font)
        return self._layout.reserve(text)

    def plan(self, text, places, start: PlannedPose):
        """The strokes of `text` at `places`, in the order that travels least
        with the pen up, and the primitives that draw them from `start`."""
        s = self.settings
        strokes = order_strokes(word_strokes(text, places, s.size, s.font), (start.x, start.y))
        primitives, _ = plan_strokes(strokes, start, s.turn_direction)
        return strokes, primitives

    def trace(self, text, places, must_clear, start: PlannedPose):
        """Draw `text` at `places` (from reserve), from the turtle's `start`."""
        if must_clear:
            self.clear()
        self.pen(True)
        for primitive in self.plan(text, places, start)[1]:
            self._carry_out(primitive)

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

    def pen(self, down):
        raise NotImplementedError

    def clear(self):
        raise NotImplementedError
