"""How far a drawing has got, as the log, the draw action's feedback and
draw.py's bar say it. No ROS here."""
import itertools
import time

from ..letters.route import ink_length


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
