"""How far a drawing has got, as the log, the draw action's feedback and
draw.py's bar say it. No ROS here."""
import itertools
import time

from ..letters.route import ink_length


class Progress:
    """How far a drawing of `plan` (letters/plan.Plan) has got: the ink
    drawn (m), and the time to go by the plan, at the pace kept so far;
    every `period` s of it, one line saying so. `now`: a clock that may
    leave pauses out."""

    def __init__(self, say, plan=None, period=5.0, now=time.monotonic):
        self.say, self.plan, self.period, self.now = say, plan, period, now
        self.started = self.last = now()
        self.ink_drawn = 0.0
        self._planned_at = 0.0          # the plan's seconds where the ink was last told
        self._told_at = self.started

    def __call__(self, ink_drawn, ink):
        now = self.now()
        if ink_drawn > self.ink_drawn:
            self.ink_drawn = ink_drawn
            self._planned_at, self._told_at = self._planned(ink_drawn), now
        if now - self.last < self.period or not 0 < ink_drawn < ink - 1e-6:
            return
        self.last = now
        self.say(f'{100 * ink_drawn / ink:.0f}% of the ink drawn ({ink_drawn:.2f} of {ink:.2f} m); '
                 f'about {self.to_go():.0f} s to go')

    def to_go(self):
        """The plan's seconds still to come, at the pace kept so far, less
        the time since the ink was last told."""
        if self.plan is None:
            return 0.0
        spent = self._told_at - self.started
        pace = spent / self._planned_at if self._planned_at > 0 else 1.0
        since = self.now() - self._told_at
        return max(0.0, (self.plan.seconds - self._planned_at) * pace - since)

    def _planned(self, ink_drawn):
        """The plan's seconds when `ink_drawn` m are down (between two points
        of its schedule, in proportion)."""
        ink0, seconds0 = 0.0, 0.0
        for ink, seconds in self.plan.schedule if self.plan else ():
            if ink >= ink_drawn - 1e-9:
                share = (ink_drawn - ink0) / (ink - ink0) if ink - ink0 > 1e-12 else 1.0
                return seconds0 + (seconds - seconds0) * share
            ink0, seconds0 = ink, seconds
        return seconds0

    def report(self):
        """(share of the ink drawn, seconds to go, strokes finished)."""
        plan = self.plan
        share = min(1.0, self.ink_drawn / plan.ink) if plan.ink > 0 else 0.0
        ends = itertools.accumulate(ink_length([stroke]) for stroke in plan.strokes)
        return share, self.to_go(), sum(1 for end in ends if end <= self.ink_drawn + 1e-6)
