"""A classroom that survives what classrooms do, on machines made of network
namespaces (support/netns.py), all in one run against the simulator on the
master's machine (classroom.launch: roscore, turtlesim and the room):

- ann and ben start at the same instant, both asking for the first free part;
- cat draws a parallel word and is stopped with Ctrl-C mid-word;
- dan's controller is killed with SIGKILL mid-drawing, and dan starts again;
- fay starts a second controller under ann's name while ann draws;
- gus's cable is pulled for 3 s mid-drawing, then put back, and he triggers again.

At the end no two live parts overlap, every turtle on the canvas (but
turtlesim's own turtle1) belongs to a live controller, every completed
letter is within a single letter's tolerance and inside its owner's part,
and every failure said one line and no traceback.
"""
import os
import re
import time

import pytest
import yaml

from support.accuracy import expected, vertex_errors, worst_off
from support.netns import classroom as network_classroom
from support.netns import output, read_poses, stop, wait_for_line
from turtle_letters.letters.font import BUILTIN
from turtle_letters.letters.geometry import PlannedPose

ADDRESSES = {'master': 1, 'ann': 2, 'ben': 3, 'cat': 4, 'dan': 5, 'fay': 6, 'gus': 7}
TOLERANCE = 0.05        # m: a single letter's, as test_draw_letter's
FAST = ['talker:=false', 'angular_speed:=1.0']
# Asked on the master's machine: the parts, and which of their controllers answer.
LIVE_PARTS = '''
import rospy, yaml
from turtle_letters.classroom.claims import live, stored_parts
parts = stored_parts('/turtle_letters/parts')
alive = live(parts)
print(yaml.safe_dump({n: p for n, p in parts.items() if n in alive}))
'''


@pytest.fixture(scope='module')
def room():
    with network_classroom(ADDRESSES) as hosts:
        yield hosts


def student(room, host, label, *args):
    return room[host].start(label, 'roslaunch', 'turtle_letters', 'student.launch', *args)


def trigger(room, host, name):
    return room[host].start(f'trigger_{time.monotonic_ns()}', 'rostopic', 'pub', '-1',
                            f'/{name}/chatter', 'std_msgs/String', "data: 'P'")


def record(room, name):
    recorder = room['master'].start(f'{name}_poses_{time.monotonic_ns()}', 'rostopic', 'echo',
                                    '-p', f'/{name}/pose')
    wait_for_line(recorder, r'\d+,', 30)
    return recorder


def controller_pid(launch, name):
    match = wait_for_line(launch, rf'process\[{name}/turtlebot_controller-\d+\]: started with '
                          r'pid \[(\d+)\]', 60)
    return int(match.group(1))


def live_parts(room):
    done = room['master'].call('/usr/bin/python3', '-c', LIVE_PARTS)
    assert done.returncode == 0, done.stdout
    return yaml.safe_load(done.stdout) or {}


def inside(box, point, slack=1e-3):
    return box[0] - slack <= point[0] <= box[2] + slack and box[1] - slack <= point[1] <= box[3] + slack


def assert_letter(name, letter, recorder, part):
    """The letter drawn since the recorder started: exact, and inside the
    part from the moment the turtle is in it (a killed controller's turtle
    coasts on for turtlesim's 1 s, maybe out of its part: it comes back with
    the pen up)."""
    poses = read_poses(recorder.out_path)
    poses = poses[next(i for i, p in enumerate(poses) if inside(part['box'], p)):]
    x, y, theta = poses[0]
    strokes, travel = expected(letter, [tuple(part['place'])], PlannedPose(x, y, theta), 1.0,
                               BUILTIN, 'ccw')
    path = [(p[0], p[1]) for p in poses]
    errors = vertex_errors(path, [v for stroke in strokes for v in stroke])
    assert max(errors) < TOLERANCE, f'{name}: vertex errors {errors}'
    assert worst_off(path, strokes, travel) < TOLERANCE, name
    outside = [p for p in path if not inside(part['box'], p)]
    assert not outside, f'{name}: {len(outside)} poses outside its part {part["box"]}'


def test_a_classroom_survives_crashes_restarts_a_name_twice_ctrl_c_and_a_dropped_link(room):
    master = room['master']
    sim = master.start('classroom', 'roslaunch', 'turtle_letters', 'classroom.launch')
    wait_for_line(sim, r'The room grants parts', 60)

    # ann and ben at the same instant: the room grants the first part to one.
    launches = {name: student(room, name, 'student', f'name:={name}', *FAST)
                for name in ('ann', 'ben')}
    launches['cat'] = student(room, 'cat', 'student', 'name:=cat', 'text:=CAT',
                              'parallel:=true', *FAST)
    for name in ('dan', 'gus'):
        launches[name] = student(room, name, 'student', f'name:={name}', *FAST)
    for name, launch in launches.items():
        wait_for_line(launch, r'Ready: publish', 90)
    recorders = {name: record(room, name) for name in ('ann', 'ben')}
    for name in ('ann', 'ben', 'dan', 'gus'):
        trigger(room, name, name)

    # fay under ann's name: refused in one line, before it disturbs ann.
    twin = student(room, 'fay', 'twin', 'name:=ann', *FAST)
    assert twin.wait(60) != 0
    fatal = [line for line in output(twin).splitlines() if '[FATAL]' in line]
    assert len(fatal) == 1 and 'name:=ann is in use' in fatal[0], output(twin)

    # cat: Ctrl-C mid-word.
    wait_for_line(launches['cat'], r'cat__3: move', 60)
    assert stop(launches['cat']) is not None, 'cat did not stop on Ctrl-C'

    # dan: SIGKILL mid-drawing, then the same name again.
    dan_pid = controller_pid(launches['dan'], 'dan')
    wait_for_line(launches['dan'], r'move [0-9.]+ m: start', 60)
    killed = room['dan'].call('kill', '-9', str(dan_pid))
    assert killed.returncode == 0, killed.stdout
    launches['dan'].wait(30)

    # gus: the cable out for 3 s mid-drawing, then back.
    wait_for_line(launches['gus'], r'move [0-9.]+ m: start', 60)
    room['gus'].network.link('gus', up=False)
    time.sleep(3.0)
    room['gus'].network.link('gus', up=True)
    stopped = wait_for_line(launches['gus'], r"Drawing of 'G' stopped:[^\n]*", 60)

    launches['dan'] = student(room, 'dan', 'student_again', 'name:=dan', *FAST)
    wait_for_line(launches['dan'], r'Turtle dan takes back the part', 90)
    wait_for_line(launches['dan'], r'Ready: publish', 30)
    for name in ('dan', 'gus'):
        recorders[name] = record(room, name)
        trigger(room, name, name)
    for name in ('ann', 'ben', 'dan', 'gus'):
        wait_for_line(launches[name], rf"Done drawing '{name[0].upper()}'", 180)
    for recorder in recorders.values():
        stop(recorder)

    parts = live_parts(room)
    assert sorted(parts) == ['ann', 'ben', 'dan', 'gus'], parts
    for a in parts:
        for b in parts:
            box_a, box_b = parts[a]['box'], parts[b]['box']
            assert a == b or not (box_a[0] < box_b[2] - 1e-9 and box_b[0] < box_a[2] - 1e-9
                                  and box_a[1] < box_b[3] - 1e-9
                                  and box_b[1] < box_a[3] - 1e-9), (a, b)
    topics = master.call('rostopic', 'list').stdout.split()
    turtles = sorted(t.split('/')[1] for t in topics if t.endswith('/pose'))
    assert turtles == ['ann', 'ben', 'dan', 'gus', 'turtle1'], turtles

    for name in ('ann', 'ben', 'dan', 'gus'):
        assert_letter(name, name[0].upper(), recorders[name], parts[name])

    # One line for each failure, no traceback anywhere.
    assert "Drawing of 'G' stopped" in stopped.group(0)
    assert len(re.findall(r"Drawing of 'G' stopped", output(launches['gus']))) == 1
    seen = [os.path.join(h.home, f) for h in room.values() for f in os.listdir(h.home)
            if f.endswith('.out')]        # all that every process printed
    for path in seen:
        with open(path, errors='replace') as f:
            assert 'Traceback' not in f.read(), path
    for launch in launches.values():
        stop(launch)
