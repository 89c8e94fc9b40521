"""A drawing's progress: the log's lines and the action's report."""
import math

from support.recorder import settings
from turtle_letters.actions.progress import Progress
from turtle_letters.letters.font import BUILTIN
from turtle_letters.letters.geometry import PlannedPose
from turtle_letters.letters.plan import plan_text
from turtle_letters.letters.sheet import Sheet


def test_progress_is_said_every_few_seconds_with_the_time_to_go():
    said, clock = [], [0.0]
    progress = Progress(said.append, period=5.0, now=lambda: clock[0])
    clock[0] = 2.0
    progress(1.0, 4.0)          # too soon
    clock[0] = 6.0
    progress(2.0, 4.0)
    progress(3.0, 4.0)          # too soon again
    clock[0] = 12.0
    progress(4.0, 4.0)          # done: nothing to say
    assert said == ['50% of the ink drawn (2.00 of 4.00 m); about 6 s to go']


def test_the_report_counts_ink_and_strokes_and_the_time_left_by_the_plan():
    clock = [0.0]
    plan = plan_text('NL', Sheet(3.0, BUILTIN).reserve('NL', PlannedPose(1.0, 6.0, 0.0))[0],
                     PlannedPose(1.0, 6.0, 0.0), settings())
    progress = Progress(lambda line: None, now=lambda: clock[0])
    assert progress.report(plan) == (0.0, plan.seconds, 0)
    n_ink = 3.0 + math.hypot(3.0 * 0.825, 3.0 * 0.825) + 3.0
    clock[0] = 50.0
    progress(n_ink, plan.ink)                   # the N's last line: one stroke done
    share, to_go, strokes = progress.report(plan)
    assert (round(share, 6), round(to_go, 6), strokes) == (
        round(n_ink / plan.ink, 6), round(plan.seconds - 50.0, 6), 1)
    progress(n_ink - 1.0, plan.ink)             # a report never goes back
    assert progress.report(plan)[0] == share
    clock[0] = 500.0
    progress(plan.ink, plan.ink)
    assert progress.report(plan) == (1.0, 0.0, len(plan.strokes))
