"""`make bench`'s classroom group: many turtles on one simulator.

- 1, 10 and 30 controllers, each in its own namespace driving a turtle it
  spawned, all drawing the N at once (timed mode, the lab's speeds, letters
  1 m high so that 30 parts fit): the simulator's rate and CPU while they
  draw, each controller's CPU, every letter's worst vertex error.
  The room's scoreboard grades them all: its CPU per graded turtle, and how
  many it graded a pass.
- A parallel word of 5 letters against its slowest letter drawn alone by
  one turtle from the same place.
"""
import json
import os
import tempfile
import time

import rospy
from std_msgs.msg import String
from std_srvs.srv import Empty

from support.accuracy import expected, vertex_errors
from support.nodes import PoseRecorder, connections, subscribed, wait_until
from turtle_letters.classroom.names import spare_name
from turtle_letters.grading.procstat import cpu_seconds
from turtle_letters.letters.font import BUILTIN
from turtle_letters.letters.layout import Layout
from turtle_letters.letters.geometry import PlannedPose
from turtle_letters.letters.primitives import Turn, plan_strokes

SIZE = 1.0
PARALLEL_WORD = 'NORTH'
WORD_ANGULAR_SPEED = 1.0    # rad/s: the word group turns faster, to take a minute, not five
VERTEX_TARGET_MM = 8.0      # a single letter's in timed mode
SCOREBOARD_TARGET_PCT = 2.0     # CPU per graded turtle


def _fresh_canvas():
    rospy.ServiceProxy('/reset', Empty)()
    if rospy.has_param('/turtle_letters'):
        rospy.delete_param('/turtle_letters')


def _start_controllers(processes, names, *params):
    controllers = [processes.start(name, 'rosrun', 'turtle_letters', 'turtle_controller.py',
                                   f'__ns:={name}', f'_turtle:=/{name}', *params)
                   for name in names]
    for name in names:
        node = f'/{name}/turtlebot_controller'
        wait_until(lambda: connections(node, f'/{name}/cmd_vel', 'o') >= 1, 180,
                   f'{name} to spawn its turtle and connect')
    return controllers


def _moving_span(recorder):
    """When the turtle first and last moved (wall clock), or None."""
    with recorder.lock:
        moving = [t for t, p in recorder.poses if p.linear_velocity or p.angular_velocity]
    return (moving[0], moving[-1]) if moving else None


def _wait_until_all_drew(recorders, timeout):
    def done():
        spans = [_moving_span(r) for r in recorders]
        return all(spans) and time.time() - max(s[1] for s in spans) > 1.5
    wait_until(done, timeout, 'every turtle to draw and stop')


def classroom_run(processes, sim_pid, turtles):
    """`turtles` controllers drawing the N at once."""
    _fresh_canvas()
    names = [f'student{i:02d}' for i in range(turtles)]
    controllers = _start_controllers(processes, names, f'_size:={SIZE}')
    grades = tempfile.mkdtemp(prefix='bench_grades_')
    scoreboard = processes.start('scoreboard', 'rosrun', 'turtle_letters', 'scoreboard.py',
                                 f'_out:={grades}')
    controllers.append(scoreboard)
    try:
        recorders, chatters = _connected(names)
        time.sleep(1.0)     # the controllers' start-up ends before the clock starts
        starts = [r.last() for r in recorders]
        for r in recorders:
            r.reset()
        cpu0 = {c.pid: cpu_seconds(c.pid) for c in controllers}
        sim_cpu0, t0 = cpu_seconds(sim_pid), time.time()
        bench_cpu0 = time.process_time()
        for chatter in chatters:
            chatter.publish(String('P'))
        _wait_until_all_drew(recorders, 600)
        wait_until(lambda: len(_grades(grades)) == turtles, 60, 'the scoreboard to grade them all')
        span = time.time() - t0
        sim_cpu = cpu_seconds(sim_pid) - sim_cpu0
        controller_cpu = [100 * (cpu_seconds(c.pid) - cpu0[c.pid]) / span for c in controllers]
        scoreboard_cpu = controller_cpu.pop()
        with recorders[0].lock:
            stamps = [t for t, _ in recorders[0].poses]
        errors = [_worst_vertex_mm(
            expected('N', [(start.x, start.y)], PlannedPose(start.x, start.y, start.theta),
                     SIZE, BUILTIN, 'ccw')[0], start, recorder)
            for start, recorder in zip(starts, recorders)]
        drawing = [s[1] - s[0] for s in map(_moving_span, recorders)]
        for chatter in chatters:
            chatter.unregister()
    finally:
        for controller in controllers:
            processes.stop(controller)
    return {'turtles': turtles, 'sim_rate_hz': (len(stamps) - 1) / (stamps[-1] - stamps[0]),
            'sim_cpu_pct': 100 * sim_cpu / span, 'controller_cpu_pct': max(controller_cpu),
            'controller_cpu_median_pct': sorted(controller_cpu)[len(controller_cpu) // 2],
            'vertex_max_mm': max(errors), 'vertex_mm_each': errors,
            'over_target': sum(e > VERTEX_TARGET_MM for e in errors), 'drawing_s': max(drawing),
            'bench_cpu_pct': 100 * (time.process_time() - bench_cpu0) / span,
            'scoreboard_cpu_per_turtle_pct': scoreboard_cpu / turtles,
            'graded_pass': sum(r['verdict'] == 'pass' for r in _grades(grades).values())}


def _connected(names):
    """(a pose recorder, a chatter publisher) of each student's turtle, once
    the scoreboard watches each, its controller listens and a pose came."""
    for name in names:
        wait_until(lambda: subscribed('/scoreboard', f'/{name}/pose'), 60,
                   f'the scoreboard watching {name}')
    recorders = [PoseRecorder(turtle=name) for name in names]
    chatters = [rospy.Publisher(f'/{name}/chatter', String, queue_size=1) for name in names]
    for chatter, recorder in zip(chatters, recorders):
        wait_until(lambda: chatter.get_num_connections() > 0, 60, 'a controller on chatter')
        recorder.wait_connected()
        wait_until(lambda: recorder.poses, 10, 'a pose of each turtle')
    return recorders, chatters


def _grades(folder):
    try:
        with open(os.path.join(folder, 'scoreboard.json')) as f:
            return json.load(f)
    except (OSError, ValueError):
        return {}


def _letter_seconds(char, place, start):
    primitives = plan_strokes(expected(char, [place], start, SIZE)[0], start)[0]
    return sum(abs(p.angle) / WORD_ANGULAR_SPEED if isinstance(p, Turn) else p.length
               for p in primitives if hasattr(p, 'angle') or hasattr(p, 'length'))


def parallel_word_run(processes):
    """PARALLEL_WORD with parallel:=true, then its slowest letter alone."""
    _fresh_canvas()
    speeds = (f'_size:={SIZE}', f'_angular_speed:={WORD_ANGULAR_SPEED}')
    turtles = ['turtle1'] + [spare_name('turtle1', i) for i in range(2, len(PARALLEL_WORD) + 1)]
    recorders = [PoseRecorder(turtle=t) for t in turtles]
    recorders[0].wait_connected()
    wait_until(lambda: recorders[0].poses, 10, 'a pose of turtle1')
    first = recorders[0].last()
    start = PlannedPose(first.x, first.y, first.theta)
    places, _ = Layout((start.x, start.y), SIZE).reserve(PARALLEL_WORD)
    starts = [start] + [PlannedPose(x, y, 0.0) for x, y in places[1:]]
    controller = processes.start('word', 'rosrun', 'turtle_letters', 'turtle_controller.py',
                                 '_parallel:=true', *speeds)
    text = rospy.Publisher('/turtlebot_controller/text', String, queue_size=1)
    try:
        wait_until(lambda: text.get_num_connections() > 0, 60, 'the controller on ~text')
        wait_until(lambda: connections('/turtlebot_controller', '/turtle1/cmd_vel', 'o') >= 1, 60,
                   "the controller's cmd_vel")
        time.sleep(1.0)
        text.publish(String(PARALLEL_WORD))
        wait_until(lambda: all(_moving_span(r) for r in recorders), 120, 'every letter to start')
        _wait_until_all_drew(recorders, 600)
    finally:
        text.unregister()
        processes.stop(controller)
    spans = [_moving_span(r) for r in recorders]
    word_s = max(s[1] for s in spans) - min(s[0] for s in spans)
    errors = [_worst_vertex_mm(expected(char, [place], begin, SIZE)[0], begin, recorder)
              for char, place, begin, recorder in zip(PARALLEL_WORD, places, starts, recorders)]
    for recorder in recorders:
        recorder.unregister()
    slowest, alone_s = _slowest_alone(processes, places, starts, speeds)
    return {'word': PARALLEL_WORD, 'word_s': word_s, 'slowest_letter': PARALLEL_WORD[slowest],
            'slowest_alone_s': alone_s, 'vertex_max_mm': max(errors)}


def _worst_vertex_mm(strokes, start, recorder):
    """How far, mm, the recorded path's corners lie from `strokes`' at worst."""
    path = [(start.x, start.y)] + recorder.path()
    return max(vertex_errors(path, [v for s in strokes for v in s])) * 1000


def _slowest_alone(processes, places, starts, speeds):
    """(the index of the word's slowest letter by the plan, the s it takes
    drawn alone from the same place)."""
    slowest = max(range(len(PARALLEL_WORD)),
                  key=lambda i: _letter_seconds(PARALLEL_WORD[i], places[i], starts[i]))
    _fresh_canvas()
    x, y = places[slowest]
    solo = processes.start('solo', 'rosrun', 'turtle_letters', 'turtle_controller.py',
                           '__ns:=solo', '_turtle:=/solo', f'_x:={x}', f'_y:={y}',
                           f'_letter:={PARALLEL_WORD[slowest]}', *speeds)
    recorder = PoseRecorder(turtle='solo')
    trigger = rospy.Publisher('/solo/chatter', String, queue_size=1)
    try:
        wait_until(lambda: connections('/solo/turtlebot_controller', '/solo/cmd_vel', 'o') >= 1,
                   60, 'the solo turtle')
        wait_until(lambda: trigger.get_num_connections() > 0, 60, 'the solo controller on chatter')
        recorder.wait_connected()
        time.sleep(1.0)
        trigger.publish(String('P'))
        _wait_until_all_drew([recorder], 600)
    finally:
        trigger.unregister()
        processes.stop(solo)
    alone = _moving_span(recorder)
    recorder.unregister()
    return slowest, alone[1] - alone[0]


def classroom_lines(results):
    lines = ['']
    for c in results.get('classroom', []):
        lines.append(
            f"classroom, {c['turtles']:2} turtles drawing the N at once: simulator "
            f"{c['sim_rate_hz']:.2f}{'!' if abs(c['sim_rate_hz'] - 62.5) > 0.625 else ''} Hz, "
            f"{c['sim_cpu_pct']:.1f}{'!' if c['turtles'] >= 30 and c['sim_cpu_pct'] > 15 else ''}% "
            f"CPU; controller CPU median {c['controller_cpu_median_pct']:.2f}%, worst "
            f"{c['controller_cpu_pct']:.2f}{'!' if c['controller_cpu_pct'] > 3 else ''}%; worst "
            f"vertex {c['vertex_max_mm']:.2f}{'!' if c['over_target'] else ''} mm "
            f"({c['over_target']} letters over {VERTEX_TARGET_MM:g} mm); "
            f"drawing {c['drawing_s']:.1f} s; scoreboard "
            f"{c['scoreboard_cpu_per_turtle_pct']:.2f}"
            f"{'!' if c['scoreboard_cpu_per_turtle_pct'] > SCOREBOARD_TARGET_PCT else ''}% CPU "
            f"per turtle, {c['graded_pass']} of {c['turtles']} graded a pass")
    w = results.get('parallel_word')
    if w:
        ratio = w['word_s'] / w['slowest_alone_s']
        lines.append(
            f"parallel word {w['word']!r}: {w['word_s']:.1f} s, its slowest letter "
            f"({w['slowest_letter']}) alone {w['slowest_alone_s']:.1f} s: "
            f"{ratio:.2f}{'!' if ratio > 1.2 else ''} x; worst vertex "
            f"{w['vertex_max_mm']:.2f}{'!' if w['vertex_max_mm'] > 8 else ''} mm")
    lines.append('Classroom targets: simulator 62.5 Hz +-1%, <= 15% CPU with 30 turtles; '
                 'controller <= 3% CPU each; vertex <= 8 mm; scoreboard <= '
                 f'{SCOREBOARD_TARGET_PCT:g}% CPU per graded turtle; a parallel word <= 1.2 x its '
                 'slowest letter alone.')
    return lines
