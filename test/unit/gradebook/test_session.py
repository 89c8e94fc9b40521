"""When the grader stops watching a run: each reason alone ends it, among
them a full record of the grader's simulator (it said it stopped the run,
and did not)."""
from types import SimpleNamespace

import pytest

from turtle_letters.gradebook.session import watching


def parts(**changed):
    launch = SimpleNamespace(poll=lambda: changed.get('ended'))
    box = SimpleNamespace(reached=lambda: changed.get('limit', ''),
                          stopped=changed.get('stopped', False))
    watcher = SimpleNamespace(full=changed.get('events_full', False))
    world = SimpleNamespace(full=changed.get('record_full', False),
                            broken=lambda: changed.get('broken', ''))
    return launch, box, watcher, world


def test_a_run_in_order_is_watched():
    assert watching(*parts())


@pytest.mark.parametrize('reason', [dict(ended=0), dict(limit='memory limit of 2 GiB reached'),
                                    dict(stopped=True), dict(events_full=True),
                                    dict(record_full=True), dict(broken='shut down')])
def test_each_reason_alone_ends_the_watch(reason):
    assert not watching(*parts(**reason))
