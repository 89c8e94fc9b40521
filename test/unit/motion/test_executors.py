"""The executors in closed loop with the simulator's own step function."""
import math
import random

import pytest

from support.accuracy import primitives_of
from support.ticks import PoseMessage, sample
from turtle_letters.letters.font import BUILTIN
from turtle_letters.letters.geometry import PlannedPose
from turtle_letters.letters.primitives import Line, Turn
from turtle_letters.motion.executors import FeedbackExecutor, StallWatch, TimedExecutor
from turtlesim_compat.world import CENTRE, Turtle

EXECUTORS = {'timed': TimedExecutor, 'feedback': FeedbackExecutor}


def run(primitives, mode, turtle, late_every=0, linear=1.0, angular=0.25):
    """Drive `turtle` through `primitives`; every `late_every`-th command misses
    its tick (the simulator applies the previous one once more). Returns the
    turtle's position at every tick."""
    track = []
    tick = 0
    for primitive in primitives:
        executor = EXECUTORS[mode](primitive, linear, angular)
        command = executor.start(sample(turtle))
        while command is not None:
            tick += 1
            late = late_every and tick % late_every == 0
            if not late:
                turtle.command(*command, now=tick)
            turtle.step(now=tick)
            if late:
                turtle.command(*command, now=tick)
            track.append((turtle.x, turtle.y))
            command = executor.update(sample(turtle))
            assert tick < 100000, 'the primitive never ended'
        turtle.command(0.0, 0.0, 0.0, now=tick)
        turtle.step(now=tick)
    return track


def n_at_centre():
    return primitives_of('N', [(CENTRE, CENTRE)], PlannedPose(CENTRE, CENTRE, 0.0))[0]


@pytest.mark.parametrize('mode', ['timed', 'feedback'])
def test_the_n_ends_on_its_last_vertex(mode):
    turtle = Turtle('t', CENTRE, CENTRE, 0.0)
    primitives = n_at_centre()
    run(primitives, mode, turtle)
    assert (primitives[-1].x, primitives[-1].y) == pytest.approx((8.0193, 9.0696), abs=1e-4)
    assert (turtle.x, turtle.y) == pytest.approx((primitives[-1].x, primitives[-1].y), abs=1e-4)
    assert turtle.theta == pytest.approx(math.pi / 2, abs=1e-4)


class CountingTurtle(Turtle):
    """Counts the ticks it moves in (a primitive also has a tick that shows it stopped)."""
    moving_ticks = 0

    def step(self, now, *args):
        if self.linear_speed or self.angular:
            self.moving_ticks += 1
        return super().step(now, *args)


def test_timed_primitives_last_amount_over_speed_of_simulated_time():
    turtle = CountingTurtle('t', CENTRE, CENTRE, 0.0)
    run([Turn(math.pi / 2, math.pi / 2)], 'timed', turtle)
    assert turtle.moving_ticks == math.ceil((math.pi / 2) / 0.25 / 0.016)
    turtle.moving_ticks = 0
    run([Line(3.0, CENTRE, CENTRE + 3.0, math.pi / 2)], 'timed', turtle)
    assert turtle.moving_ticks == math.ceil(3.0 / 0.016)
    assert turtle.y == pytest.approx(CENTRE + 3.0, abs=1e-9)


def test_the_whole_lab_n_takes_the_labs_time_in_simulated_seconds():
    turtle = CountingTurtle('t', CENTRE, CENTRE, 0.0)
    run(n_at_centre(), 'timed', turtle)
    assert turtle.moving_ticks * 0.016 == pytest.approx(40.9, abs=0.15)


@pytest.mark.parametrize('char', ['N', 'A', 'K', 'S', '8'])
def test_feedback_reaches_every_vertex_within_a_millimetre_despite_late_commands(char):
    glyph = BUILTIN.glyph(char)
    origin = (3.0, 3.0)
    first = glyph.strokes[0][0]
    turtle = Turtle('t', origin[0] + 3 * first[0], origin[1] + 3 * first[1], 0.0)
    for primitive in primitives_of(char, [origin], PlannedPose(turtle.x, turtle.y, 0.0),
                                   direction='shortest')[0]:
        if isinstance(primitive, Line):
            start = (turtle.x, turtle.y)
            track = run([primitive], 'feedback', turtle, late_every=5)
            assert math.hypot(turtle.x - primitive.x, turtle.y - primitive.y) < 1e-3
            # never past the vertex along the stroke, never off it sideways
            ux, uy = math.cos(primitive.heading), math.sin(primitive.heading)
            for x, y in track:
                along = (x - start[0]) * ux + (y - start[1]) * uy
                across = -(x - start[0]) * uy + (y - start[1]) * ux
                assert along <= primitive.length + 1e-3 and abs(across) < 1e-3
        elif isinstance(primitive, Turn):
            run([primitive], 'feedback', turtle, late_every=5)
            assert abs(math.remainder(turtle.theta - primitive.heading, 2 * math.pi)) < 1e-3


def test_feedback_turns_the_long_way_when_the_plan_says_so():
    turtle = Turtle('t', CENTRE, CENTRE, math.pi / 2)
    angles = []
    executor = EXECUTORS['feedback'](Turn(5 * math.pi / 4, -math.pi / 4), 1.0, 0.25)
    command = executor.start(sample(turtle))
    while command is not None:
        turtle.command(*command, now=0)
        turtle.step(now=0)
        angles.append(turtle.angular)
        command = executor.update(PoseMessage(turtle.x, turtle.y, turtle.theta, 0.0, turtle.angular))
    assert min(angles) >= 0.0
    assert turtle.theta == pytest.approx(-math.pi / 4, abs=1e-4)


class WallClock:
    """The wall clock as the controller would read it: `seconds_per_tick`
    pass between two poses (16 ms on an idle machine, more when loaded)."""

    def __init__(self, seconds_per_tick):
        self.seconds_per_tick = seconds_per_tick
        self.time = 100.0

    def __call__(self):
        return self.time


def drive_on_the_wall_clock(meters, seconds_per_tick):
    turtle = Turtle('t', 1.0, 1.0, 0.0)
    clock = WallClock(seconds_per_tick)
    executor = TimedExecutor(Line(meters, 0, 0, 0), 1.0, 0.25, clock='wall', now=clock)
    command = executor.start(sample(turtle))
    tick = 0
    while command is not None:
        tick += 1
        turtle.command(*command, now=tick)
        turtle.step(now=tick)
        clock.time += clock.seconds_per_tick
        command = executor.update(sample(turtle))
    return turtle.x - 1.0


def test_the_wall_clock_is_the_labs_way_right_when_idle_short_when_loaded():
    # idle: 16 ms a tick; whole ticks, the nearest count: at most half a tick off
    assert drive_on_the_wall_clock(3.0, 0.016) == pytest.approx(3.0, abs=0.0081)
    assert drive_on_the_wall_clock(3.005, 0.016) == pytest.approx(3.005, abs=0.0081)
    assert drive_on_the_wall_clock(3.011, 0.016) == pytest.approx(3.011, abs=0.0081)
    # loaded: ticks come every 20 ms, each still moves the turtle 16 ms worth
    assert drive_on_the_wall_clock(3.0, 0.020) == pytest.approx(3.0 * 16 / 20, abs=0.0161)


def test_the_sim_clock_drives_the_exact_distance():
    turtle = Turtle('t', 1.0, 1.0, 0.0)
    run([Line(3.0, 0, 0, 0)], 'timed', turtle)
    assert turtle.x - 1.0 == pytest.approx(3.0, abs=1e-6)


def trace_smoothly(points, turtle, speed=1.0):
    """The smooth executor against the simulator's step; every tick's position."""
    from turtle_letters.motion.executors import SmoothExecutor
    executor = SmoothExecutor(points, speed)
    command = executor.start(sample(turtle))
    track = [(turtle.x, turtle.y)]
    tick = 0
    while command is not None:
        tick += 1
        turtle.command(*command, now=tick)
        turtle.step(now=tick)
        track.append((turtle.x, turtle.y))
        command = executor.update(sample(turtle))
        assert tick < 100000, 'the stroke never ended'
    return track, tick


def test_smooth_traces_the_labs_n_on_its_strokes_in_ink_length_over_speed():
    from support.accuracy import distance_to_polyline, vertex_errors
    stroke = [(CENTRE + 3 * x, CENTRE + 3 * y) for x, y in BUILTIN.glyph("N").strokes[0]]
    turtle = Turtle('t', CENTRE, CENTRE, 0.0)
    track, ticks = trace_smoothly(stroke, turtle)
    assert max(distance_to_polyline(p, stroke) for p in track) < 1e-5
    assert max(vertex_errors(track, stroke)) < 1e-5
    # 9.5 m at 1 m/s is 593.75 ticks; a tick cut short at each of 3 corners, and the end
    assert ticks <= 594 + 4
    # every tick moves at most the speed's worth: it never overshoots a vertex
    assert all(math.hypot(b[0] - a[0], b[1] - a[1]) <= 0.016 + 1e-6 for a, b in zip(track, track[1:]))


def test_smooth_holds_one_command_along_a_straight_edge():
    """The driver sends a command only when it changes: a long edge should
    not need one message a tick."""
    from turtle_letters.motion.executors import TURN_PER_TICK, SmoothExecutor
    stroke = [(CENTRE + 3 * x, CENTRE + 3 * y) for x, y in BUILTIN.glyph("N").strokes[0]]
    turtle = Turtle('t', CENTRE, CENTRE, math.pi / 2)
    executor = SmoothExecutor(stroke[1:], 1.0)
    commands = [executor.start(sample(turtle))]
    while commands[-1] is not None:
        turtle.command(*commands[-1], now=len(commands))
        turtle.step(now=len(commands))
        commands.append(executor.update(sample(turtle)))
    changes = sum(a != b for a, b in zip(commands, commands[1:]))
    assert len(commands) > 590
    # it changes while the turtle turns round its two 135-degree corners, and little else
    turning = 2 * math.ceil(math.radians(135) / TURN_PER_TICK)
    assert changes < turning + 20, changes


def test_smooth_turns_to_face_along_the_edge_a_little_each_tick():
    from turtle_letters.motion.executors import TURN_PER_TICK, SmoothExecutor
    turtle = Turtle('t', 2.0, 2.0, 0.0)
    executor = SmoothExecutor([(2.0, 4.0), (4.0, 4.0)], 1.0)
    command = executor.start(sample(turtle))
    headings = []
    for tick in range(1, 40):
        turtle.command(*command, now=tick)
        turtle.step(now=tick)
        headings.append(turtle.theta)
        command = executor.update(sample(turtle))
    # straight up the edge from the first tick on, whichever way it faces
    assert (turtle.x, turtle.y) == pytest.approx((2.0, 2.0 + 39 * 0.016))
    assert headings[0] == pytest.approx(TURN_PER_TICK)
    assert all(b - a <= TURN_PER_TICK + 1e-9 for a, b in zip(headings, headings[1:]))
    assert headings[-1] == pytest.approx(math.pi / 2)


class LateLink:
    """Commands on their way to the simulator, each arriving a number of ticks
    late drawn from `delays`, in the order sent: the simulator uses the newest
    that has come, so a late command means the one before once more, and a
    command overtaken by the next one is never used."""

    def __init__(self, delays, seed):
        self.delays = delays
        self.rng = random.Random(seed)
        self.arrivals = []          # (tick it arrives, command), in the order sent

    def send(self, command, tick):
        last = self.arrivals[-1][0] if self.arrivals else 0
        self.arrivals.append((max(last, tick + self.rng.choice(self.delays)), command))

    def deliver(self, turtle, tick, now):
        """Hand the turtle what has arrived by `tick`."""
        while self.arrivals and self.arrivals[0][0] <= tick:
            turtle.command(*self.arrivals.pop(0)[1], now=now)


def trace_with_late_commands(strokes, speed, delays, seed):
    """Smooth mode through `strokes` over a LateLink. The worst distance of
    any tick's position from the stroke or travel line it is on, m."""
    from support.accuracy import distance_to_polyline
    from turtle_letters.motion.executors import SmoothExecutor
    link = LateLink(delays, seed)
    turtle = Turtle('t', *strokes[0][0], 0.0)
    worst, tick = 0.0, 0
    here = strokes[0][0]
    for stroke in strokes:
        for points, line in (([stroke[0]], [here, stroke[0]]), (stroke[1:], stroke)):
            executor = SmoothExecutor(points, speed)
            command = executor.start(sample(turtle))
            while command is not None:
                link.send(command, tick)
                link.deliver(turtle, tick, now=tick)
                turtle.step(now=tick)
                tick += 1
                if line[0] != line[-1]:
                    worst = max(worst, distance_to_polyline((turtle.x, turtle.y), line))
                command = executor.update(sample(turtle))
                assert tick < 100000, 'the stroke never ended'
            link.send((0.0, 0.0, 0.0), tick)
        here = stroke[-1]
    return worst


def cursive_word():
    from turtle_letters.letters.hershey import load_font
    from turtle_letters.letters.geometry import PlannedPose
    from turtle_letters.letters.layout import Layout
    from turtle_letters.letters.plan import text_strokes
    font = load_font('scripts')
    places, _ = Layout((1.0, 6.0), 1.0, font).reserve('turtle, go!')
    return text_strokes('turtle, go!', places, 1.0, font, PlannedPose(1.0, 6.0, 0.0))[0]


@pytest.mark.parametrize('seed', range(3))
@pytest.mark.parametrize('speed', [1.0, 2.0])
def test_smooth_runs_on_at_most_a_tick_past_a_vertex_when_a_command_comes_late(seed, speed):
    """The cursive word a test draws, on a busy machine: one command in five
    comes a tick late. It costs no more than one tick's move off the line."""
    worst = trace_with_late_commands(cursive_word(), speed, [0, 0, 0, 0, 1], seed)
    assert worst <= 1.1 * speed * 0.016


@pytest.mark.parametrize('seed', range(3))
def test_smooth_commands_late_two_ticks_in_a_row_cost_about_a_tick_each(seed):
    """Turns of at most TURN_PER_TICK: a turn used again bends the next move
    only a little (turning straight to the edge, it could send it backwards)."""
    worst = trace_with_late_commands(cursive_word(), 1.0, [0, 0, 0, 1, 2], seed)
    assert worst <= 3 * 0.016


def test_a_turtle_that_does_as_told_is_never_stalled():
    watch = StallWatch(limit=1.0)
    for tick in range(200):
        command = (1.0, 0.0, 0.5 if tick % 2 else 0.25)
        watch.sent(command)
        # turtlesim reports the command of the tick before
        pose = PoseMessage(0, 0, 0, 1.0, 0.25 if tick % 2 else 0.5)
        assert not watch.stalled(pose, tick * 0.016)


@pytest.mark.parametrize('reported', [(0.0, 0.0), (0.3, 0.0)])
def test_a_turtle_that_does_not_do_as_told_is_stalled_after_the_limit(reported):
    """Commands not delivered (it stands), or another node's (it moves otherwise)."""
    watch = StallWatch(limit=1.0)
    watch.sent((1.0, 0.0, 0.0))
    pose = PoseMessage(0, 0, 0, *reported)
    assert not watch.stalled(pose, 10.0)
    assert not watch.stalled(pose, 10.9)
    assert watch.stalled(pose, 11.0)


def test_a_standing_order_is_not_disobeyed():
    watch = StallWatch(limit=1.0)
    watch.sent((0.0, 0.0, 0.0))
    assert not watch.stalled(PoseMessage(0, 0, 0, 0.5, 0.0), 0.0)
    assert not watch.stalled(PoseMessage(0, 0, 0, 0.5, 0.0), 5.0)


@pytest.mark.parametrize('seed', range(5))
def test_timed_commands_that_come_irregularly_late_still_end_on_every_vertex(seed):
    """Commands 0 to 3 ticks late, at random (a loaded machine): some are used
    twice, some never; every vertex of the N is still reached."""
    link = LateLink([0, 0, 1, 2, 3], seed)
    turtle = Turtle('t', CENTRE, CENTRE, 0.0)
    primitives = n_at_centre()
    track = []
    tick = 0
    for primitive in primitives:
        executor = TimedExecutor(primitive, 1.0, 0.25, 'sim')
        command = executor.start(sample(turtle))
        while command is not None:
            link.send(command, tick)
            link.deliver(turtle, tick, now=tick * 0.016)
            turtle.step(now=tick * 0.016)
            tick += 1
            track.append((turtle.x, turtle.y))
            command = executor.update(sample(turtle))
            assert tick < 100000, 'the primitive never ended'
    for vertex in [(p.x, p.y) for p in primitives if isinstance(p, Line)]:
        assert min(math.hypot(x - vertex[0], y - vertex[1]) for x, y in track) < 1e-3
