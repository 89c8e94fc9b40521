"""What a run showed, made sense of: when a drawing starts and ends, which
ink counts (the grader's simulator's record), and who triggered it."""
import pytest

from turtle_letters.autograder.observations import (GONE_STILL, SCRIPT_PAUSE, chatter_peak,
                                                   drawing, drew, fight, looked_for_from,
                                                   moved, one_driver, other_words,
                                                   own_triggers, stood_for, strokes, roles,
                                                   trigger, unheard, unprompted, WATCHER)

TICK = 0.016
PEN = [179, 184, 255, 3]


def graph(t=0.0, controller='/drawer', **roles):
    return dict(dict(kind='graph', t=t, simulator=[], pose_publishers=[],
                     cmd_vel_publishers=[controller]), **roles)


def line(t0, x0, x1, y=5.0, turtle='turtle1', ink=True, speed=1.0):
    """The record of a turtle driven along x at `speed` from x0 to x1."""
    n = round(abs(x1 - x0) / (speed * TICK))
    xs = [x0 + (x1 - x0) * i / n for i in range(n + 1)]
    return [dict(k='move', t=t0 + i * TICK, turtle=turtle, to=[b, y, 0.0],
                 ink=[[a, y, b, y] + PEN] if ink else []) for i, (a, b) in
            enumerate(zip(xs, xs[1:]), 1)]


def jump(t, x0, x1, y=5.0, ink=False, turtle='turtle1'):
    return dict(k='jump', t=t, turtle=turtle, to=[x1, y, 0.0],
                ink=[[x0, y, x1, y] + PEN] if ink else [])


def test_a_drawing_runs_from_the_first_move_after_the_trigger_to_standing_still():
    record = line(1, 5.0, 6.0)
    d = drawing(record, [graph()], since=0.5, settle=2.0, until=5.0)
    assert d.started == pytest.approx(1 + TICK)
    assert d.ended == pytest.approx(record[-1]['t'])
    assert len(d.strokes) == 1
    assert d.strokes[0][0] == (5.0, 5.0) and d.strokes[0][-1] == pytest.approx((6.0, 5.0))
    assert d.jumps == d.jump_ink == 0 and d.impostors == []


def test_a_turtle_still_moving_has_not_ended():
    record = line(1, 5.0, 8.0)
    assert drawing(record, [graph()], since=0.5, settle=2.0, until=record[-1]['t']).ended is None
    assert stood_for(record, 0.5, record[-1]['t']) == 0.0
    assert moved(record, 0.5) and not moved(record, 10.0)


def test_travel_with_the_pen_up_is_no_ink_and_ink_laid_by_a_teleport_is_apart():
    record = line(1, 1.0, 2.0) + line(2, 2.0, 3.0, ink=False) + line(3, 3.0, 4.0) + \
        [jump(4.1, 4.0, 1.0), jump(4.2, 1.0, 4.0, ink=True)] + line(5, 4.0, 5.0)
    d = drawing(record, [graph()], since=0.5, settle=2.0, until=10.0)
    assert [(s[0][0], round(s[-1][0], 6)) for s in d.strokes] == [(1.0, 2.0), (3.0, 4.0),
                                                                 (4.0, 5.0)]
    assert d.jumps == 2 and d.jump_ink == 1
    # the teleport's ink is kept apart, for the picture of the canvas: never read
    assert d.teleported == [[(1.0, 5.0), (4.0, 5.0)]] and d.teleported_looks == [tuple(PEN)]


def test_ink_teleports_laid_before_the_last_clear_is_not_on_the_canvas():
    record = [jump(1.0, 1.0, 4.0, ink=True), dict(k='clear', t=1.5)] + line(2, 4.0, 5.0) + \
        [jump(3.0, 5.0, 5.0, y=5.0, ink=False), jump(3.1, 5.0, 6.0, ink=True)]
    d = drawing(record, [graph()], since=0.5, settle=2.0, until=10.0)
    assert d.teleported == [[(5.0, 5.0), (6.0, 5.0)]]


def test_ink_laid_before_the_drawing_and_not_wiped_is_on_the_canvas_unread():
    """A real class's script drove its turtle a metre, then asked at a
    prompt for the letter to draw: turtlesim still shows that metre beside
    the letter, and it is no part of the drawing read. A clear before the
    drawing ends wipes it; one after does not."""
    metre, letter = line(1, 5.0, 6.0), line(5, 2.0, 3.0)
    d = drawing(metre + letter + [dict(k='clear', t=20.0)], [graph()], since=4.0, settle=2.0,
                until=30.0)
    assert [(s[0][0], round(s[-1][0], 6)) for s in d.strokes] == [(2.0, 3.0)]
    assert [(s[0][0], round(s[-1][0], 6)) for s in d.earlier] == [(5.0, 6.0)]
    assert d.earlier_looks == [tuple(PEN)]
    teleported = [jump(0.5, 1.0, 2.0, ink=True)] + letter
    assert drawing(teleported, [graph()], since=4.0, settle=2.0, until=30.0).earlier == \
        [[(1.0, 5.0), (2.0, 5.0)]]
    wiped = metre + [dict(k='clear', t=3.0)] + letter
    assert drawing(wiped, [graph()], since=4.0, settle=2.0, until=30.0).earlier == []


def test_every_turtles_ink_counts_each_in_lines_of_its_own():
    mixed = [(t, e) for e in line(1, 1.0, 2.0) for t in [e['t']]] + \
        [(e['t'] + TICK / 2, e) for e in line(1, 6.0, 7.0, turtle='pen2')]
    record = [e for _, e in sorted(mixed, key=lambda te: te[0])]
    d = drawing(record, [graph()], since=0.5, settle=2.0, until=10.0)
    assert sorted(round(s[-1][0], 6) for s in d.strokes) == [2.0, 7.0]
    assert d.turtles == ['turtle1', 'pen2']


def test_strokes_join_a_turtles_segments_only_end_to_start():
    lines = [('a', [0, 0, 1, 0]), ('a', [1, 0, 1, 1]), ('a', [2, 2, 3, 3]), ('b', [3, 3, 4, 4])]
    assert strokes(lines)[0] == [[(0, 0), (1, 0), (1, 1)], [(2, 2), (3, 3)], [(3, 3), (4, 4)]]


def test_a_change_of_pen_starts_a_line_of_its_own_look():
    white, red = [255, 255, 255, 3], [255, 0, 0, 6]
    lines = [('a', [0, 0, 1, 0, *white]), ('a', [1, 0, 1, 1, *white]), ('a', [1, 1, 2, 1, *red])]
    assert strokes(lines) == ([[(0, 0), (1, 0), (1, 1)], [(1, 1), (2, 1)]],
                              [tuple(white), tuple(red)])


def test_nodes_posing_as_the_simulator_are_named():
    events = [graph(), graph(1.0, pose_publishers=['/f_drawer'], simulator=['/fake_sim'])]
    d = drawing(line(1, 5.0, 6.0), events, since=0.5, settle=2.0, until=9.0)
    assert d.impostors == ['/f_drawer', '/fake_sim']


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
    record = line(1, 5.0, 6.0) + [dict(k='clear', t=9.0)]
    record.insert(30, dict(k='clear', t=record[29]['t']))
    d = drawing(record, [graph()], since=0.5, settle=2.0, until=12.0)
    assert [(round(s, 2), what) for s, what in d.wiped] == [(round(29 * TICK, 2), 'clear')]


def test_after_a_reset_between_two_passes_the_canvas_left_is_the_drawing():
    """Two passes of a letter with /reset between them (a real class's CC):
    what counts is the ink on the canvas as it was left, all of it driven."""
    first = line(1, 2.0, 4.0) + [jump(3.2, 4.0, 2.0, ink=True)]
    second = line(3.5, 5.0, 7.0)
    record = first + [dict(k='reset', t=3.3)] + second
    d = drawing(record, [graph()], since=0.5, settle=2.0, until=12.0)
    assert len(d.strokes) == 1 and d.strokes[0][0] == (5.0, 5.0)
    assert d.jump_ink == 0 and d.jumps == 1 and d.wiped == [(3.3 - (1 + TICK), 'reset')]


def test_a_set_up_of_teleports_and_calls_longer_than_the_settle_is_no_end():
    """A real class's script: a teleport with the pen down, /clear, and more
    service calls for longer than `settle` before its first drive. The
    drawing ends only once a turtle was driven, and is what the clear left."""
    record = [jump(1.0, 5.0, 3.0, ink=True), dict(k='clear', t=1.5)] + line(4.0, 3.0, 4.0)
    d = drawing(record, [graph()], since=0.5, settle=2.0, until=12.0)
    assert d.ended == pytest.approx(record[-1]['t'])
    assert len(d.strokes) == 1 and d.strokes[0][0] == (3.0, 5.0) and d.jump_ink == 0


def test_the_commands_counted_while_the_turtle_drew():
    record = line(1, 5.0, 6.0)
    counts = [dict(k='cmd', t=t, turtle='turtle1', n=10) for t in (0.5, 1.5, 1.9, 4.0)]
    merged = sorted(record + counts, key=lambda e: e['t'])
    assert drawing(merged, [graph()], since=0.5, settle=2.0, until=9.0).commands == 20


def sent(t, turtle, *nodes):
    return dict(k='cmd', t=t, turtle=turtle, n=len(nodes), by=sorted(nodes))


def test_two_nodes_driving_one_turtle_within_turtlesims_command_timeout_fight():
    """Two scripts of `rostopic pub -1` lines started together, each line a
    node of its own, 3 s apart in a script: their commands to turtle1 come
    0.6 s apart, both followed at once (turtlesim obeys a command for 1 s).
    One controller's steady commands are no fight, nor two turtles driven
    each by its own node, nor one script's lines, nor a node that takes
    over more than the timeout after the last one's command, nor a fight
    before `since`."""
    scripts = [sent(1.0, 'turtle1', '/rostopic_11'), sent(4.0, 'turtle1', '/rostopic_12'),
               sent(4.6, 'turtle1', '/rostopic_21'), sent(7.0, 'turtle1', '/rostopic_13')]
    assert fight(scripts, 0.0) == (4.6, 'turtle1', 'at once')
    assert fight(scripts, 4.3) is None
    steady = [sent(0.1 * i, 'turtle1', '/controller') for i in range(100)]
    assert fight(steady, 0.0) is None
    two_turtles = sorted(steady + [sent(0.1 * i + 0.05, 'turtle2', '/other') for i in range(100)],
                         key=lambda e: e['t'])
    assert fight(two_turtles, 0.0) is None
    assert fight([sent(1.0, 'turtle1', '/a'), sent(2.2, 'turtle1', '/b')], 0.0) is None
    assert fight([sent(1.0, 'turtle1', '/a', '/b')], 0.0) == (1.0, 'turtle1', 'at once')
    assert fight([dict(k='cmd', t=1.0, turtle='turtle1', n=2)], 0.0) is None    # told no senders


def test_two_scripts_whose_lines_take_turns_on_one_turtle_fight():
    """Two scripts of `rostopic pub -1` lines started together, their lines
    2 s apart, never within turtlesim's command timeout: by the script that
    started each line's node (owner), turtle1 went from one script to the
    other and back. Told no owner, each line is a node of its own and no
    turn is seen; one script's lines 0.5 s apart are no fight, nor a
    handoff from one script to the other, nor a turn on another turtle."""
    scripts = {'/rostopic_11_5': 'a.sh', '/rostopic_21_6': 'b.sh', '/rostopic_12_7': 'a.sh',
               '/rostopic_22_8': 'b.sh', '/rostopic_13_9': 'a.sh'}

    def owner(node):
        return scripts.get(node, node)
    lines = [sent(1.0 + 2 * k, 'turtle1', node) for k, node in enumerate(scripts)]
    assert fight(lines, 0.0, owner) == (5.0, 'turtle1', 'by turns')
    assert fight(lines, 0.0) is None
    assert fight(lines, 2.0, owner) == (7.0, 'turtle1', 'by turns')
    close = [sent(1.0 + 0.5 * k, 'turtle1', node) for k, node in
             enumerate(['/rostopic_11_5', '/rostopic_12_7', '/rostopic_13_9'])]
    assert fight(close, 0.0, owner) is None
    handoff = [sent(1.0 + 2 * k, 'turtle1', node) for k, node in
               enumerate(['/rostopic_11_5', '/rostopic_12_7', '/rostopic_21_6', '/rostopic_22_8'])]
    assert fight(handoff, 0.0, owner) is None
    apart = [sent(e['t'], 'turtle2' if owner(e['by'][0]) == 'b.sh' else 'turtle1', *e['by'])
             for e in lines]
    assert fight(apart, 0.0, owner) is None


def test_the_drawing_ends_when_the_turtles_stood_still_long_enough_and_not_before():
    record = line(1, 5.0, 6.0)
    end = record[-1]['t']
    assert stood_for(record, 0.5, end + 1.0) == pytest.approx(1.0)
    assert stood_for(record, 3.0, end + 1.0) is None
    assert drawing(record, [graph()], 0.5, 2.0, until=end + 1.9).ended is None
    assert drawing(record, [graph()], 0.5, 2.0, until=end + 2.0).ended == end
    paused = record + line(end + 1.5, 6.0, 7.0)
    assert drawing(paused, [graph()], 0.5, 2.0, until=20.0).ended == paused[-1]['t']


def test_a_pause_while_a_shell_script_runs_ends_the_drawing_only_when_much_longer():
    """A script of `rostopic pub -1` lines starts a node for each: on a
    slow machine the next line's move came 3 s after the last (settle 2 s).
    While the script runs, only SCRIPT_PAUSE times settle ends the drawing;
    once it has ended, settle counts from its end."""
    first = line(1, 5.0, 6.0)
    record = first + line(first[-1]['t'] + 3.0, 6.0, 7.0)
    last = record[-1]['t']
    script_ended = last + 1.0       # `rostopic pub -1` waits a while before it exits
    assert drawing(record, [graph()], 0.5, 2.0, until=30.0).ended == first[-1]['t']
    assert drawing(record, [graph()], 0.5, 2.0, 30.0, script_ended).ended == last
    assert drawing(record, [graph()], 0.5, 2.0, script_ended + 1.9, script_ended).ended is None
    assert drawing(record, [graph()], 0.5, 2.0, script_ended + 2.0, script_ended).ended == last
    longer = first + line(first[-1]['t'] + SCRIPT_PAUSE * 2.0, 6.0, 7.0)
    assert drawing(longer, [graph()], 0.5, 2.0, 60.0, 59.0).ended == first[-1]['t']


def test_once_every_process_of_the_submission_ended_a_command_timeout_of_standing_ends_it():
    """roslaunch ended, and its sandbox's every process with it (`gone`):
    no command can come, so the turtles standing GONE_STILL s after both the
    last move and `gone` end the drawing, however long the settle."""
    record = line(1, 5.0, 6.0)
    last = record[-1]['t']
    gone = last - 0.5       # the last command played out after its sender ended
    ended = dict(settle=5.0, script_until=gone)
    assert drawing(record, [graph()], 0.5, until=last + GONE_STILL, gone=gone, **ended).ended \
        == last
    assert drawing(record, [graph()], 0.5, until=last + GONE_STILL - 0.1, gone=gone,
                   **ended).ended is None
    assert drawing(record, [graph()], 0.5, until=last + GONE_STILL, **ended).ended is None
    late = last + 2.0       # seen ended later: counted from then
    assert drawing(record, [graph()], 0.5, until=late + GONE_STILL - 0.1, gone=late,
                   **ended).ended is None
    assert drawing(record, [graph()], 0.5, until=late + GONE_STILL, gone=late, **ended).ended \
        == last


def test_spawns_kills_and_pens_count_from_the_launch_but_the_simulators_own_turtle1():
    record = [dict(k='spawn', t=0.0, turtle='turtle1', x=5.5, y=5.5),
              dict(k='kill', t=0.5, turtle='turtle1'),
              dict(k='spawn', t=0.6, turtle='theo', x=4.0, y=5.0),
              dict(k='pen', t=0.7, turtle='theo', off=True),
              dict(k='pen', t=1.5, turtle='theo', off=True)] + line(2, 4.0, 5.0, turtle='theo')
    d = drawing(record, [graph()], since=1.0, settle=2.0, until=9.0)
    assert (d.spawns, d.pens, d.pen_lifts, d.turtles) == (2, 2, 0, ['theo'])


def test_a_setup_move_before_the_trigger_is_no_drawing_and_no_failure_to_wait():
    """A pen-up teleport at 1 s and a turn in place, then the letter from
    9.6 s, after the trigger at 9.5 s: the drawing is the letter (a model
    of the issue's: looked for from the launch, it ended at the wait for
    the trigger, with no ink)."""
    turn = dict(k='move', t=1.5, turtle='turtle1', to=[2.0, 5.0, 1.0],
                ink=[[2.0, 5.0, 2.0, 5.0] + PEN])
    record = [jump(1.0, 5.5, 2.0), turn] + line(9.6, 2.0, 4.0)
    assert not drew(record, 0.0, 9.5) and drew(record, 0.0)
    since = looked_for_from(record, 0.0, 9.5)
    d = drawing(record, [graph()], since=since, settle=5.0, until=20.0)
    assert since == 9.5 and len(d.strokes) == 1 and d.commands == 0 and d.jumps == 0
    assert round(d.strokes[0][-1][0], 6) == 4.0


def test_a_turtle_that_drew_before_the_trigger_is_looked_at_from_the_launch():
    record = line(1.0, 2.0, 3.0) + line(9.6, 3.0, 4.0)
    assert looked_for_from(record, 0.5, 9.5) == 0.5


def test_a_talker_that_publishes_p_before_the_key_is_typed_is_named():
    """A "P" every second from the launch on: the key typed at 6 s is not
    what made it (the grader's own P and the driver's do not count)."""
    events = [graph(controller='/v_drawer')] + \
        [dict(kind='chatter', t=float(t), data='P', sender='/talker') for t in range(1, 9)] + \
        [dict(kind='chatter', t=2.5, data='P', sender='/v_drawer'),
         dict(kind='chatter', t=3.5, data='P', sender='/grade_watch')]
    assert unprompted(events, 0.5, 6.0) == ['/talker']
    assert unprompted(events[:1] + events[7:], 0.5, 6.0) == []
    assert trigger(events, 6.0) == 6.0


def test_only_a_turtlesim_pose_published_by_a_cadets_node_poses_as_turtlesim():
    """A node's own /letter/pose (a Pose2D) is its business; a turtlesim/Pose
    on a turtle's pose topic from a node not the simulator is an impostor's."""
    state = ([['/letter/pose', ['/planner']], ['/turtle1/pose', ['/grading_turtlesim', '/fake']],
              ['/turtle1/cmd_vel', ['/drawer']], ['/chatter', ['/talker', '/grade_watch']]],
             [['/chatter', ['/drawer', '/grade_watch']]],
             [['/spawn', ['/grading_turtlesim']]])
    types = [['/letter/pose', 'geometry_msgs/Pose2D'], ['/turtle1/pose', 'turtlesim/Pose'],
             ['/turtle1/cmd_vel', 'geometry_msgs/Twist'], ['/chatter', 'std_msgs/String']]
    found = roles(state, types, ('/grade_watch', '/grading_turtlesim'))
    assert found == dict(pose_publishers=['/fake'], cmd_vel_publishers=['/drawer'],
                         chatter_publishers=['/talker'], chatter_subscribers=['/drawer'],
                         simulator=[], offered={}, unheard={'/turtle1/cmd_vel': ['/drawer']})


def test_the_services_a_cadets_nodes_offer_are_named_but_their_loggers():
    state = ([], [], [['/spawn', ['/grading_turtlesim']], ['/turtle_write', ['/writer']],
                      ['/writer/get_loggers', ['/writer']], ['/writer/set_logger_level', ['/writer']],
                      ['/grade_watch/get_loggers', ['/grade_watch']]])
    found = roles(state, [], ('/grade_watch', '/grading_turtlesim'))
    assert found['offered'] == {'/writer': ['/turtle_write']}


def test_ink_in_the_backgrounds_colour_is_no_ink():
    """A pen of the background's colour erases: an L drawn with it earns nothing."""
    erasing = [dict(e, ink=[s[:4] + [69, 86, 255, 3] for s in e['ink']]) for e in line(1, 5.0, 7.0)]
    d = drawing(erasing + line(5, 7.0, 8.0), [graph()], since=0.5, settle=5.0, until=12.0)
    assert len(d.strokes) == 1 and d.strokes[0][0] == (7.0, 5.0)


def test_one_node_acted_alone_only_if_the_simulator_took_commands_and_calls_from_it_only():
    """Two nodes may offer a cmd_vel and one send nothing (it waits for
    typed goals): the simulator's `by` lines say who acted."""
    drove = [dict(k='spawn', t=0.0, turtle='turtle1')] + line(1, 4.0, 5.0)
    by = [dict(k='by', t=1.0, node='/controller0')]
    assert one_driver(drove + by + [dict(k='by', t=0.5, node='/controller0')])
    assert not one_driver(drove + by + [dict(k='by', t=2.0, node='/rosservice_12_34')])
    assert not one_driver(drove)        # none said to act: who drove is not known

def test_commands_published_where_no_node_subscribes_are_unheard():
    """A real class's node published its Twist on /cmd_vel (a turtlebot's),
    where no turtle listens: nothing moved, and the row must say why."""
    state = ([['/cmd_vel', ['/my_initials_1']], ['/turtle1/cmd_vel', ['/drawer']],
              ['/goal', ['/drawer']]],
             [['/turtle1/cmd_vel', ['/grading_turtlesim']], ['/cmd_vel', []]], [])
    types = [['/cmd_vel', 'geometry_msgs/Twist'], ['/turtle1/cmd_vel', 'geometry_msgs/Twist'],
             ['/goal', 'turtlesim/Pose']]
    found = roles(state, types, ('/grade_watch', '/grading_turtlesim'))
    assert found['unheard'] == {'/cmd_vel': ['/my_initials_1']}
    gone = dict(kind='graph', t=2.0, unheard={})        # the node exited: the master forgot it
    assert unheard([dict(found, kind='graph', t=1.0), gone]) == {'/cmd_vel': ['/my_initials_1']}


def test_a_drawing_that_never_ended_offers_the_canvases_it_wiped_the_fullest_first():
    """A writer that never ends wipes its canvas and writes again: the
    canvases it wiped, the fullest first, each a drawing of its own,
    saying when it stood. A drawing that ended offers none."""
    record = line(1, 1.0, 3.0) + [dict(k='clear', t=3.5)] + line(4, 1.0, 5.0) + \
        [dict(k='reset', t=8.5)] + line(9, 1.0, 2.0)
    d = drawing(record, [graph()], since=0.5, settle=2.0, until=record[-1]['t'])
    assert d.ended is None and d.fullest == [0, -1] and d.shown == ()
    assert [round(s[-1][0], 6) for s in d.strokes] == [2.0]
    fullest = drawing(record, [graph()], since=0.5, settle=2.0, until=record[-1]['t'], canvas=0)
    assert [round(s[-1][0], 6) for s in fullest.strokes] == [5.0]
    assert fullest.shown == pytest.approx((3.5 - (1 + TICK), 8.5 - (1 + TICK)))
    first = drawing(record, [graph()], since=0.5, settle=2.0, until=record[-1]['t'], canvas=-1)
    assert [round(s[-1][0], 6) for s in first.strokes] == [3.0] and first.shown[0] == 0.0
    assert drawing(record, [graph()], since=0.5, settle=2.0, until=20.0).fullest == []


def test_where_each_turtle_appeared_is_kept_for_reading_past_a_lead_in():
    """turtle1 at turtlesim's centre, a turtle spawned while the drawing ran,
    and turtle1 put back by a reset are where lines may begin with a lead-in;
    a spawn after the drawing ended is not."""
    centre = dict(k='spawn', t=0.0, turtle='turtle1', x=5.544445, y=5.544445, theta=0.0)
    record = [centre] + line(1, 5.544445, 7.0) + [
        dict(k='spawn', t=1.5, turtle='t2', x=2.0, y=3.0, theta=0.0),
        dict(centre, t=1.6)] + line(2, 2.0, 3.0, turtle='t2') + [
        dict(k='spawn', t=11.0, turtle='t3', x=9.0, y=9.0, theta=0.0)]
    d = drawing(record, [graph()], since=0.5, settle=2.0, until=12.0)
    assert d.homes == [(2.0, 3.0), (5.544445, 5.544445)]


def test_other_words_on_chatter_where_none_of_the_runs_was_p():
    said = [dict(kind='chatter', t=1.0, sender=WATCHER, data='P'),
            dict(kind='chatter', t=1.5, sender='/talker_1', data='hello world 1'),
            dict(kind='chatter', t=1.6, sender='/talker_1', data='hello world 2')]
    assert other_words(said) == ('/talker_1', 'hello world 1')
    assert other_words(said + [dict(kind='chatter', t=2.0, sender='/keys', data=' P')]) is None
    assert other_words(said[:1]) is None
