"""The delay relay's release times: late by the delay give or take the
jitter, and never out of order."""
import random

import pytest

from turtle_letters.classroom.delay import Delays


def test_each_message_goes_out_late_by_the_delay_give_or_take_the_jitter_in_order():
    delays = Delays(0.05, 0.03, random.Random(1))
    arrivals = [i * 0.016 for i in range(500)]
    released = [delays.release(t) for t in arrivals]
    lateness = [r - t for r, t in zip(released, arrivals)]
    assert released == sorted(released)
    assert min(lateness) >= 0.02 - 1e-9 and max(lateness) <= 0.08 + 1e-9
    assert 0.045 < sum(lateness) / len(lateness) < 0.075     # order kept: a little later on average


@pytest.mark.parametrize('delay, jitter', [(-0.01, 0.0), (0.01, 0.02), (0.05, -0.01)])
def test_a_delay_that_cannot_be_is_refused_in_words(delay, jitter):
    with pytest.raises(ValueError, match='jitter at most the delay'):
        Delays(delay, jitter)
