"""A drawing's progress: the log's lines and the action's report, with the
time to go by the plan."""
import math

import pytest

from support.recorder import settings
from turtle_letters.actions.progress import Progress
from turtle_letters.letters.font import BUILTIN
from turtle_letters.letters.geometry import PlannedPose
from turtle_letters.letters.plan import plan_text
from turtle_letters.letters.sheet import Sheet

START = PlannedPose(1.0, 6.0, 0.0)
TURN_90 = math.pi / 2 / 0.25        # s at the lab's 0.25 rad/s


def plan_of(text, **given):
    return plan_text(text, Sheet(3.0, BUILTIN).reserve(text, START)[0], START, settings(**given))


def test_the_time_to_go_after_the_ns_first_line_is_the_plans_not_the_inks():
    """The issue's case: 9.3 s in, a third of the ink drawn, 32 s to go (the
    225-degree turn alone takes 15.7 s); extrapolating the ink said 20."""
    said, clock = [], [0.0]
    plan = plan_of('N')
    progress = Progress(said.append, plan, period=5.0, now=lambda: clock[0])
    clock[0] = TURN_90 + 3.0
    progress(3.0, plan.ink)
    assert progress.to_go() == pytest.approx(plan.seconds - clock[0])
    assert said == [f'32% of the ink drawn (3.00 of 9.50 m); about {plan.seconds - clock[0]:.0f} s to go']
    assert said[0].endswith('about 32 s to go')


def test_a_slower_pace_than_planned_stretches_the_time_to_go():
    clock = [0.0]
    plan = plan_of('N')
    progress = Progress(lambda line: None, plan, now=lambda: clock[0])
    clock[0] = 2 * (TURN_90 + 3.0)          # half the planned speed so far
    progress(3.0, plan.ink)
    assert progress.to_go() == pytest.approx(2 * (plan.seconds - TURN_90 - 3.0))
    clock[0] += 10.0                         # and it counts down between lines
    assert progress.to_go() == pytest.approx(2 * (plan.seconds - TURN_90 - 3.0) - 10.0)


def test_progress_is_said_every_few_seconds_only():
    said, clock = [], [0.0]
    plan = plan_of('N')
    progress = Progress(said.append, plan, period=5.0, now=lambda: clock[0])
    clock[0] = 2.0
    progress(1.0, plan.ink)         # too soon
    clock[0] = 12.0
    progress(3.0, plan.ink)
    progress(6.5, plan.ink)         # too soon again
    clock[0] = 50.0
    progress(plan.ink, plan.ink)    # done: nothing to say
    assert len(said) == 1 and said[0].startswith('32% of the ink drawn')


def test_the_report_counts_ink_and_strokes_and_never_goes_back():
    clock = [0.0]
    plan = plan_of('NL')
    progress = Progress(lambda line: None, plan, now=lambda: clock[0])
    assert progress.report() == (0.0, plan.seconds, 0)
    n_ink = 3.0 + math.hypot(3.0 * 0.825, 3.0 * 0.825) + 3.0
    clock[0] = 50.0
    progress(n_ink, plan.ink)                   # the N's last line: one stroke done
    share, to_go, strokes = progress.report()
    assert (round(share, 6), strokes) == (round(n_ink / plan.ink, 6), 1)
    assert 0 < to_go < plan.seconds
    progress(n_ink - 1.0, plan.ink)             # a report never goes back
    assert progress.report()[0] == share
    clock[0] = 500.0
    progress(plan.ink, plan.ink)
    assert progress.report() == (1.0, pytest.approx(0.0, abs=1e-6), len(plan.strokes))


def test_a_parallel_word_lasts_as_long_as_its_slowest_letter():
    from turtle_letters.letters.plan import plan_request
    given = settings(parallel=True, size=1.0)
    sequential = plan_of('LIN', size=1.0)
    job = plan_request('LIN', Sheet(1.0, BUILTIN), START, given)
    assert len(job.letters) == 3
    assert job.plan.seconds == max(p.seconds for p in job.letters) < sequential.seconds
