"""The step function and bookkeeping of the simulator, against the contract."""
import math

import pytest

from turtlesim_compat.world import (CENTRE, COMMAND_TIMEOUT, TICK_SECONDS, WORLD_SIZE,
                                    RequestError, Turtle, World, to_pixels, wrap_angle)


def turtle_at(x=CENTRE, y=CENTRE, theta=0.0):
    return Turtle('t', x, y, theta)


def test_canvas_constants_follow_the_real_node():
    assert WORLD_SIZE == pytest.approx(11.088889, abs=1e-6)
    assert CENTRE == pytest.approx(5.544445, abs=1e-6)
    assert to_pixels(0, 0) == (0, 499)
    assert to_pixels(WORLD_SIZE, WORLD_SIZE) == pytest.approx((499, 0))


def test_straight_line_moves_speed_times_fixed_tick():
    t = turtle_at()
    t.command(1.0, 0.0, 0.0, now=0.0)
    for i in range(100):
        t.step(now=0.001 * i)   # wall time barely passes: the step is fixed anyway
    assert t.x == pytest.approx(CENTRE + 100 * TICK_SECONDS)
    assert t.y == pytest.approx(CENTRE)


def test_turning_uses_the_new_heading_for_the_move():
    t = turtle_at()
    t.command(1.0, 0.0, 1.0, now=0.0)
    t.step(now=0.0)
    assert t.theta == pytest.approx(TICK_SECONDS)
    assert t.x == pytest.approx(CENTRE + math.cos(TICK_SECONDS) * TICK_SECONDS)
    assert t.y == pytest.approx(CENTRE + math.sin(TICK_SECONDS) * TICK_SECONDS)


def test_sideways_velocity_moves_left_of_the_heading():
    t = turtle_at(theta=math.pi / 2)
    t.command(0.0, 1.0, 0.0, now=0.0)
    t.step(now=0.0)
    assert t.x == pytest.approx(CENTRE - TICK_SECONDS)
    assert t.y == pytest.approx(CENTRE)
    assert t.linear_speed == pytest.approx(1.0)


@pytest.mark.parametrize('angle, wrapped', [(math.pi, -math.pi), (-math.pi, -math.pi),
                                            (3 * math.pi / 2, -math.pi / 2), (0.5, 0.5)])
def test_wrap_into_minus_pi_to_pi(angle, wrapped):
    assert wrap_angle(angle) == pytest.approx(wrapped)


def test_heading_wraps_while_turning():
    t = turtle_at(theta=math.pi - 0.001)
    t.command(0.0, 0.0, 1.0, now=0.0)
    t.step(now=0.0)
    assert -math.pi <= t.theta < -math.pi + 0.02


def test_wall_clamps_and_reports_where_from():
    t = turtle_at(x=WORLD_SIZE - 0.001)
    t.command(1.0, 0.0, 0.0, now=0.0)
    _, clamped_from = t.step(now=0.0)
    assert clamped_from == pytest.approx((WORLD_SIZE - 0.001 + TICK_SECONDS, CENTRE))
    assert t.x == WORLD_SIZE
    _, clamped_from = turtle_at().step(now=0.0)
    assert clamped_from is None


def test_huge_velocity_only_clamps_at_the_wall():
    t = turtle_at()
    t.command(1e30, 0.0, 0.0, now=0.0)
    t.step(now=0.0)
    assert (t.x, t.y) == (WORLD_SIZE, pytest.approx(CENTRE))


def test_command_times_out_after_one_wall_second():
    t = turtle_at()
    t.command(1.0, 0.0, 0.5, now=10.0)
    t.step(now=10.0 + COMMAND_TIMEOUT)          # not more than 1 s: still moving
    assert t.linear_speed == 1.0
    x = t.x
    t.step(now=10.0 + COMMAND_TIMEOUT + 0.01)
    assert (t.linear_speed, t.angular, t.x) == (0.0, 0.0, x)


def test_teleports_apply_in_order_at_the_next_step_and_draw():
    t = turtle_at()
    t.teleport_absolute(1.0, 2.0, 0.0)
    t.teleport_relative(1.0, math.pi / 2)
    assert (t.x, t.y) == (CENTRE, CENTRE)      # nothing until the tick
    segments, _ = t.step(now=0.0)
    assert (t.x, t.y, t.theta) == pytest.approx((1.0, 3.0, math.pi / 2))
    assert [(s.x1, s.y1) for s in segments] == pytest.approx([(1.0, 2.0), (1.0, 3.0)])


def test_teleport_absolute_above_the_top_is_clamped_at_once_without_a_wall_hit():
    t = turtle_at()
    t.teleport_absolute(3.0, 20.0, 0.0)
    _, clamped_from = t.step(now=0.0)
    assert (t.x, t.y) == (3.0, WORLD_SIZE)
    assert clamped_from is None


def test_teleport_absolute_below_the_bottom_hits_the_wall_in_the_step():
    t = turtle_at()
    t.teleport_absolute(3.0, -2.0, 0.0)
    _, clamped_from = t.step(now=0.0)
    assert (t.x, t.y) == (3.0, 0.0)
    assert clamped_from == (3.0, -2.0)


def test_pen_off_draws_nothing_and_keeps_its_colour():
    t = turtle_at()
    t.set_pen(255, 0, 0, 5, 0)
    t.set_pen(0, 0, 0, 0, 1)
    t.command(1.0, 0.0, 0.0, now=0.0)
    assert t.step(now=0.0)[0] == []
    assert (t.pen.colour, t.pen.width, t.pen.down) == ((255, 0, 0), 5, False)
    t.set_pen(0, 255, 0, 0, 0)      # a new pen: width 0 is Qt's default, 1 px (the contract)
    assert (t.pen.colour, t.pen.width, t.pen.down) == ((0, 255, 0), 1, True)
    (segment,), _ = t.step(now=0.0)
    assert (segment.colour, segment.width) == ((0, 255, 0), 1)


@pytest.mark.parametrize('bad', [math.nan, math.inf, -math.inf])
def test_non_finite_numbers_are_refused_and_change_nothing(bad):
    t = turtle_at()
    with pytest.raises(RequestError):
        t.command(bad, 0.0, 0.0, now=0.0)
    with pytest.raises(RequestError):
        t.teleport_absolute(1.0, bad, 0.0)
    with pytest.raises(RequestError):
        t.teleport_relative(0.0, bad)
    with pytest.raises(RequestError):
        World().spawn(bad, 1.0, 0.0)
    t.step(now=0.0)
    assert (t.x, t.y, t.theta, t.linear_speed) == (CENTRE, CENTRE, 0.0, 0.0)


@pytest.mark.parametrize('name', ['lab/alice', '/alice', 'a_2'])
def test_names_roscpp_takes_are_taken(name):
    assert World().spawn(1, 1, 0, name).name == name


def test_names_count_up_and_restart_on_reset():
    w = World()
    assert w.reset().name == 'turtle1'
    assert w.spawn(1, 1, 0).name == 'turtle2'
    w.kill('turtle2')
    assert w.spawn(1, 1, 0).name == 'turtle3'
    assert w.spawn(1, 1, 0, 'bob').name == 'bob'
    assert w.reset().name == 'turtle1'
    assert list(w.turtles) == ['turtle1']


@pytest.mark.parametrize('name', ['turtle1', '1abc', 'has space', 'a-b', 'ü'])
def test_duplicate_and_invalid_names_are_refused(name):
    w = World()
    w.reset()
    with pytest.raises(RequestError):
        w.spawn(1, 1, 0, name)
    assert list(w.turtles) == ['turtle1']


def test_kill_of_an_unknown_turtle_is_refused():
    w = World()
    w.reset()
    with pytest.raises(RequestError):
        w.kill('nobody')
    assert list(w.turtles) == ['turtle1']


def test_a_tick_is_its_teleports_then_its_move():
    """The node senses the colour between the two parts (the contract's order)."""
    t = turtle_at()
    t.command(1.0, 0.0, 0.0, now=0.0)
    t.teleport_relative(1.0, 0.0)
    (jump,) = t.teleport()
    (move,), hit = t.move(now=0.0)
    assert move.x0 == jump.x1 and move.x1 == t.x and hit is None    # the move starts there


def test_a_cap_on_turtles_refuses_the_spawn_past_it_and_none_by_default():
    capped = World(max_turtles=2)
    capped.spawn(1, 1, 0)
    capped.spawn(2, 2, 0)
    with pytest.raises(RequestError, match=r'at most 2 turtles \(its ~max_turtles\)'):
        capped.spawn(3, 3, 0)
    capped.kill('turtle1')
    assert capped.spawn(3, 3, 0).name == 'turtle3'
    free = World()
    assert len([free.spawn(i % 10, 1, 0) for i in range(100)]) == 100
