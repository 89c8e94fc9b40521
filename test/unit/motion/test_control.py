"""A drawing's cancel and pause, and its clock that leaves the pauses out."""
from turtle_letters.motion.control import Control


def test_the_clock_stands_still_while_paused_and_goes_on_after():
    now = [100.0]
    control = Control(now=lambda: now[0])
    now[0] = 104.0
    assert control.clock() == 104.0
    assert control.pause(True) and control.paused
    now[0] = 107.0
    assert control.clock() == 104.0
    assert not control.pause(True)              # already paused: the pause counts once
    now[0] = 110.0
    assert control.pause(False) and not control.paused
    assert control.clock() == 104.0
    assert not control.pause(False)
    now[0] = 111.5
    assert control.clock() == 105.5


def test_a_cancel_is_seen_and_stays():
    control = Control()
    assert not control.cancelled
    control.cancel()
    control.pause(True)
    assert control.cancelled
