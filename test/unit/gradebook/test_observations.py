"""What the watcher saw, made sense of: when a drawing starts and ends,
which poses count, and which steps no command could make."""
import pytest

from turtle_letters.gradebook.observations import (TICK, chatter_peak, drawing, moved,
                                                   own_triggers, stood_for, trigger)

SIM = '/turtlesim'


def graph(t=0.0, controller='/drawer'):
    return dict(kind='graph', t=t, simulator=[SIM], cmd_vel_publishers=[controller])


def pose(t, x, y, v=0.0, w=0.0, sender=SIM):
    return dict(kind='pose', t=t, x=x, y=y, theta=0.0, v=v, w=w, sender=sender)


def line(t0, x0, x1, speed=1.0):
    """Poses one tick apart, driving along x at `speed` from x0 to x1."""
    n = round(abs(x1 - x0) / (speed * TICK))
    return [pose(t0 + i * TICK, x0 + (x1 - x0) * i / n, 5.0, v=speed) for i in range(1, n + 1)]


def standing(t0, seconds, x):
    return [pose(t0 + i * TICK, x, 5.0) for i in range(int(seconds / TICK))]


def test_a_drawing_runs_from_the_first_move_after_the_trigger_to_standing_still():
    events = [graph()] + standing(0, 1, 5.0) + line(1, 5.0, 6.0) + standing(2.01, 3, 6.0)
    d = drawing(events, since=0.5, settle=2.0)
    assert d.started == pytest.approx(1 + TICK)
    assert d.ended == pytest.approx(1 + TICK * len(line(1, 5.0, 6.0)))
    assert d.path[0] == (5.0, 5.0) and d.path[-1] == pytest.approx((6.0, 5.0))
    assert not d.teleports and not d.made_up


def test_a_turtle_still_moving_has_not_ended():
    events = [graph()] + standing(0, 1, 5.0) + line(1, 5.0, 8.0)
    assert drawing(events, since=0.5, settle=2.0).ended is None
    assert stood_for(events, 0.5) == 0.0
    assert moved(events, 0.5)


def test_a_teleport_moves_the_turtle_but_no_command_could():
    jump = [pose(1.0 + TICK, 7.0, 5.0)]         # 2 m in a tick, at no speed
    events = [graph()] + standing(0, 1, 5.0) + jump + standing(1.1, 3, 7.0)
    d = drawing(events, since=0.5, settle=2.0)
    assert d.started is not None
    assert [round(m, 2) for _, m in d.teleports] == [2.0]


def test_a_late_pose_is_no_teleport():
    # two poses 0.1 s apart, at 1 m/s: the ticks between them were not seen
    events = [graph(), pose(0.0, 5.0, 5.0), pose(1.0, 5.0, 5.0), pose(1.016, 5.016, 5.0, v=1),
              pose(1.116, 5.116, 5.0, v=1), pose(1.132, 5.132, 5.0, v=1)]
    assert drawing(events, since=0.5, settle=2.0).teleports == []


def test_poses_from_any_node_but_the_simulator_are_made_up_and_not_drawn():
    fake = [pose(1 + i * TICK, 5.0 + i * 0.016, 5.0, v=1.0, sender='/f_drawer') for i in range(60)]
    events = [graph()] + standing(0, 3, 5.0) + fake
    d = drawing(events, since=0.5, settle=2.0)
    assert d.made_up == ['/f_drawer']
    assert d.started is None and d.path == []


def test_the_trigger_is_the_cadets_p_unless_the_grader_sent_it():
    events = [dict(kind='chatter', t=1.0, data='P', sender='/grade_watch'),
              dict(kind='chatter', t=2.0, data='p', sender='/talker'),
              dict(kind='chatter', t=3.0, data='P\n', sender='/talker')]
    assert trigger(events, 0.0) == 3.0
    assert trigger(events, 0.0, by_grader=True) == 1.0
    assert trigger(events, 3.5) is None


def test_a_p_from_the_node_that_drives_the_turtle_is_no_trigger():
    events = [graph(controller='/v_drawer'),
              dict(kind='chatter', t=1.0, data='P', sender='/v_drawer'),
              dict(kind='chatter', t=4.0, data='P', sender='/talker')]
    assert trigger(events, 0.0) == 4.0
    assert own_triggers(events) == ['/v_drawer']
    assert own_triggers(events[:1] + events[2:]) == []


def counted(rate, takes):
    """The watcher's counts of a talker at `rate` a second, taken at `takes` (s)."""
    return [dict(kind='chatter_count', t=t, since=before, count=round(rate * (t - before)))
            for before, t in zip(takes, takes[1:])]


def test_chatter_is_judged_by_the_times_of_its_counts_not_the_watchers_period():
    busy = [0.0, 0.1, 0.45, 0.5, 1.3, 1.35, 1.4, 2.2, 2.3]     # a watcher late on a busy core
    assert chatter_peak(counted(50, busy)) == pytest.approx(50, abs=3)
    assert chatter_peak(counted(9000, [i / 10 for i in range(30)])) == pytest.approx(9000, rel=0.01)
    assert chatter_peak(counted(900, [0.0, 0.1])) == pytest.approx(90)     # one burst: no flood
    assert chatter_peak([]) == 0


def test_turtlesim_cleared_or_reset_while_the_turtle_drew():
    said = [dict(kind='canvas', t=t, what=what, sender=sender) for t, what, sender in
            ((0.2, 'clear', SIM), (1.5, 'clear', SIM), (1.6, 'reset', '/faker'), (9.0, 'reset', SIM))]
    events = [graph()] + standing(0, 1, 5.0) + line(1, 5.0, 6.0) + standing(2.01, 3, 6.0) + said
    d = drawing(events, since=0.5, settle=2.0)
    assert [(round(s, 1), what) for s, what in d.wiped] == [(0.5, 'clear')]


def test_the_commands_counted_while_the_turtle_drew():
    counts = [dict(kind='cmd_vel', t=t, count=10) for t in (0.5, 1.5, 1.9, 4.0)]
    events = [graph()] + standing(0, 1, 5.0) + line(1, 5.0, 6.0) + standing(2.01, 3, 6.0) + counts
    assert drawing(events, since=0.5, settle=2.0).commands == 20


def test_the_drawing_ends_when_the_watch_says_so_and_not_before():
    events = [graph()] + standing(0, 1, 5.0) + line(1, 5.0, 6.0)
    assert stood_for(events, 0.5) == 0.0 and stood_for(events, 3.0) is None
    for pose_ in standing(2.01, 3, 6.0):
        events.append(pose_)
        still = stood_for(events, 0.5)
        ended = drawing(events, since=0.5, settle=2.0).ended is not None
        assert ended == (still >= 2.0), (pose_['t'], still)
