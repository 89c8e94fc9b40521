"""A turtle with its calls written down instead of carried out, and what
the controller does with a text on one: for unit tests of planning and
modes. No ROS here."""
import sys

from turtle_letters.letters.geometry import PlannedPose
from turtle_letters.letters.layout import WORLD_SIZE
from turtle_letters.letters.plan import plan_text
from turtle_letters.letters.sheet import Sheet
from turtle_letters.motion.modes import MODES
from turtle_letters.settings import Settings

CENTRE = WORLD_SIZE / 2


def settings(**given):
    return Settings(lambda name, default: given.get(name.lstrip('~'), default))


class Recorder:
    """The lab's calls, written down; `callers` notes, for each call, the
    functions it was called from (the innermost first)."""

    def __init__(self):
        self.calls, self.callers = [], []

    def _note(self, call):
        self.calls.append(call)
        frame, names = sys._getframe(2), []
        while frame is not None:
            names.append(frame.f_code.co_name)
            frame = frame.f_back
        self.callers.append(names)

    def rotate(self, degrees):
        self._note(('rotate', round(degrees, 9)))

    def move(self, meters):
        self._note(('move', round(meters, 9)))

    def steer(self, primitive):
        self._note(('steer', type(primitive).__name__))

    def pen(self, down, colour=None):
        self._note(('pen', down) if colour is None else ('pen', down, colour))

    def glide(self, points):
        self._note(('glide', len(points)))


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
