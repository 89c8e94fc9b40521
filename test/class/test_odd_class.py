"""A class folder as a learning-management system's zip really makes one,
graded in one run: a tree nested deeper than Python walks, a folder name
that is not UTF-8, a FIFO, a package handed in twice, a package named
turtlesim, a hostile build that prints 1 GB and an error line full of
terminal codes, three executables and no launch file (one spins turtle1
for ever), the same with two that turn it for ever and one that offers a
cmd_vel and sends nothing (tried alone after those that acted), a workspace with a
sibling package that cannot build here, and a Python package whose
CMakeLists.txt names another project, and a package whose launch file
starts turtlesim alone, its letter a shell script without #! that its
course runs with bash, and one whose controller its launch file starts in
a terminal this machine lacks (terminator), and one whose controller was
written on Windows (its #! line ends in a carriage return), and one that
asks at a prompt which letter to draw, as another course's lab does, and
one whose CMakeLists.txt names an include folder git never kept, and
one handed in without a CMakeLists.txt (its letter a shell script, as a
real class's was: run unbuilt), and one whose script stops at its first
`rostopic pub -l` (latch, where -1 was meant), as a real class's did,
and a C++ package whose CMakeLists.txt builds none of its nodes (its
add_executable lines commented out, as catkin_create_pkg writes them),
with its launch file and without, and two scripts of `rostopic pub -1`
lines that take turns on turtle1, never at once, and a repository of a
course's projects: a Gazebo package whose launch file starts its own
node, beside the letter's package, with no launch file, whose script
pauses 8 s between strokes. Each costs its own row only, says why in words, and the grader's own
memory stays bounded. Root only, as grading is."""
import csv
import json
import os
import shutil
import subprocess
import xml.etree.ElementTree as ElementTree

import pytest

from support.grading import leftovers, nest, peak_memory_kb, sandbox_processes, started_grading

HERE = os.path.dirname(os.path.abspath(__file__))
LENA = os.path.join(HERE, 'submissions', 'c03_lena')
NOAH = os.path.join(HERE, 'submissions', 'c16_noah')
HANA = os.path.join(HERE, 'submissions', 'c21_hana')    # C++: a talker and a drawer
SPIN = """#!/usr/bin/env python3
import rospy
from geometry_msgs.msg import Twist
rospy.init_node('spin')
cmd = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)
turn = Twist()
turn.linear.x, turn.angular.z = 1.0, 1.5
while not rospy.is_shutdown():
    cmd.publish(turn)
    rospy.sleep(0.05)
"""
TURN = SPIN.replace('1.0, 1.5', '0.0, 1.0')     # turns turtle1 in place for ever: no ink
IDLE = SPIN.split('turn = Twist()')[0] + 'rospy.spin()\n'    # offers a cmd_vel, sends nothing
GAZEBO_WORLD = {'package.xml': '<package format="2"><name>gazebo_world</name>'
                               '<buildtool_depend>catkin</buildtool_depend></package>',
                'CMakeLists.txt': 'cmake_minimum_required(VERSION 3.0.2)\nproject(gazebo_world)\n'
                                  'find_package(catkin REQUIRED COMPONENTS gazebo_ros)\n'}
# A course whose cadets start turtlesim with roslaunch, then type `bash
# letters.sh`: a launch file of turtlesim alone, and a shell script of
# rosservice and rostopic calls, mode 644 and without #!, that draws an L.
# Its turn comes 8 s after its first stroke, longer than `settle`, as each
# `rostopic pub -1` of a real class's scripts did on a slow machine.
BY_HAND = {'package.xml': '<package format="2"><name>hw3</name><version>0.0.1</version>'
                          '<description>hw3</description><maintainer email="cadet@example.com">c'
                          '</maintainer><license>MIT</license>'
                          '<buildtool_depend>catkin</buildtool_depend></package>',
           'CMakeLists.txt': 'cmake_minimum_required(VERSION 3.0.2)\nproject(hw3)\n'
                             'find_package(catkin REQUIRED)\ncatkin_package()\n',
           'launch/turtle.launch': '<launch><node pkg="turtlesim" type="turtlesim_node" '
                                   'name="sim"/></launch>\n',
           'scripts/letters.sh': 'rosservice call /turtle1/set_pen 255 255 255 3 1\n'
                                 'rosservice call /turtle1/teleport_absolute -- 4 8 -1.5708\n'
                                 'rosservice call /turtle1/set_pen 255 255 255 3 0\n'
                                 "rostopic pub -1 /turtle1/cmd_vel geometry_msgs/Twist -- "
                                 "'[3.0, 0.0, 0.0]' '[0.0, 0.0, 0.0]'\n"
                                 'sleep 8\n'
                                 "rostopic pub -1 /turtle1/cmd_vel geometry_msgs/Twist -- "
                                 "'[0.0, 0.0, 0.0]' '[0.0, 0.0, 1.5708]'\n"
                                 "rostopic pub -1 /turtle1/cmd_vel geometry_msgs/Twist -- "
                                 "'[2.0, 0.0, 0.0]' '[0.0, 0.0, 0.0]'\n"}
# The same, each move a `rostopic pub -l` (latch, typed for -1), its first a
# turn, as a real class's script was: that first one waits to be stopped.
LATCHED = dict(BY_HAND, **{'scripts/letters.sh': BY_HAND['scripts/letters.sh'].replace(
    "rostopic pub -1 /turtle1/cmd_vel geometry_msgs/Twist -- '[3.0, 0.0, 0.0]'",
    "rostopic pub -l /turtle1/cmd_vel geometry_msgs/Twist -- '[0.0, 0.0, 0.0]' '[0.0, 0.0, 1.0]'"
    "\nrostopic pub -l /turtle1/cmd_vel geometry_msgs/Twist -- '[3.0, 0.0, 0.0]'")})
# Another course's lab: no talker, the script asks which letter to draw,
# as a real class's did ("enter a letter (A,B)"), and draws an L if told L.
ASKS = {'package.xml': BY_HAND['package.xml'].replace('hw3', 'asks'),
        'CMakeLists.txt': BY_HAND['CMakeLists.txt'].replace('hw3', 'asks'),
        'scripts/asks.py': '#!/usr/bin/env python3\n'
                           'import rospy\n'
                           'from geometry_msgs.msg import Twist\n'
                           "rospy.init_node('asks')\n"
                           "cmd = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)\n"
                           'while not rospy.is_shutdown():\n'
                           "    if input('a letter to draw (L): ').strip() != 'L':\n"
                           "        print('no such letter')\n"
                           '        continue\n'
                           '    for x, z in ((0.0, -1.5708), (2.5, 0.0), (0.0, 1.5708), '
                           '(1.5, 0.0)):\n'
                           '        move = Twist()\n'
                           '        move.linear.x, move.angular.z = x, z\n'
                           '        cmd.publish(move)\n'
                           '        rospy.sleep(1.5)\n'}
# Two scripts of `rostopic pub -1` lines, both executable, no launch file:
# legs.sh draws an L; bars.sh, started with it, waits for its first move and
# turns turtle1 between its lines, each 3 s or more from any of legs.sh's,
# as a real class's two scripts took turns on turtle1. legs.sh alone draws the L.
PUB = "rostopic pub -1 /turtle1/cmd_vel geometry_msgs/Twist -- '[{}, 0.0, 0.0]' '[0.0, 0.0, {}]'\n"
TURNS = {'package.xml': BY_HAND['package.xml'].replace('hw3', 'turns'),
         'CMakeLists.txt': BY_HAND['CMakeLists.txt'].replace('hw3', 'turns'),
         'scripts/legs.sh': '#!/bin/bash\n' + BY_HAND['scripts/letters.sh'].split('rostopic')[0] +
                            PUB.format(3.0, 0.0) + 'sleep 3\n' + PUB.format(0.0, 1.5708) +
                            'sleep 3\n' + PUB.format(2.0, 0.0),
         'scripts/bars.sh': '#!/bin/bash\nrostopic echo -n 1 /turtle1/cmd_vel > /dev/null\n' +
                            'sleep 3\n' + PUB.format(0.0, 0.8) + 'sleep 3\n' + PUB.format(0.0, 0.8)}
# A real repository's projects, as ASU's was: a Gazebo package whose launch file
# starts its own node (not turtlesim's), and the letter's package, no launch file,
# its script mode 644, `#!/usr/bin/env python`, pausing 8 s (more than `settle`)
# between an L's strokes, as that script paused 9.
L_DRAW = ('#!/usr/bin/env python\n'
          'import rospy\n'
          'from geometry_msgs.msg import Twist\n'
          "rospy.init_node('l_draw')\n"
          "cmd = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=1)\n"
          'rospy.sleep(2)\n'
          'for x, z, pause in ((0.0, -1.5708, 1.5), (2.5, 0.0, 9.5), (0.0, 1.5708, 1.5), '
          '(1.5, 0.0, 1.5)):\n'
          '    move = Twist()\n'
          '    move.linear.x, move.angular.z = x, z\n'
          '    cmd.publish(move)\n'
          '    rospy.sleep(pause)\n')
PROJECTS = {'gazebo_chase/package.xml': BY_HAND['package.xml'].replace('hw3', 'gazebo_chase'),
            'gazebo_chase/CMakeLists.txt': BY_HAND['CMakeLists.txt'].replace('hw3',
                                                                             'gazebo_chase'),
            'gazebo_chase/launch/chase.launch': '<launch><node pkg="gazebo_chase" '
                                                'type="chase.py" name="chase"/></launch>\n',
            'gazebo_chase/scripts/chase.py': IDLE.replace('turtle1/cmd_vel', 'tb3_1/cmd_vel'),
            'nodes/package.xml': BY_HAND['package.xml'].replace('hw3', 'turtle_description'),
            'nodes/CMakeLists.txt': BY_HAND['CMakeLists.txt'].replace('hw3',
                                                                      'turtle_description'),
            'nodes/l_draw.py': L_DRAW}
PRINTER = os.path.join(HERE, 'hostile', 'h7_printer')
RUBRIC = os.path.join(HERE, 'rubric.yaml')
NOAHS = ('o6_three', 'o10_turning', 'o19_passed_over')     # Noah's package, changed
MULLER = os.fsdecode(b'o2_M\xfcller')      # "Müller" as a Latin-1 zip names it
GRADER_MEMORY_KB = 400 * 1024               # the whole grader, Qt and all, on 1 GB of output
pytestmark = pytest.mark.skipif(os.geteuid() != 0, reason='grading makes network namespaces: '
                                                          'root only')
# id as shown: (drawn, verdict, words in the reason)
CONCLUSIONS = {
    'o1_deep': ('', 'fail', 'its folders nest more than 40 deep: not graded'),
    'o3_fifo': ('L', 'pass', 'every criterion met'),
    'o4_twice': ('L', 'pass', 'every criterion met'),
    'o5_turtlesim': ('', 'fail', 'its only package is named turtlesim, as the simulator is'),
    'h7_printer': ('', 'fail', 'catkin_make failed: error:'),
    'o2_M\ufffdller': ('L', 'fail', 'no letter is expected'),
    # spin_forever.py and n_controller.py drive turtle1 at once: stopped, as a TA stops them
    'o6_three': ('N', 'pass', 's into the drawing: stopped there), then n_controller.py alone '
                              'in a fresh world'),
    'o19_passed_over': ('N', 'pass', 'launch/turtle.launch starts nodes of turtlesim only, none '
                                     'of lab_one: the grader started its executables (keyboard.py, '
                                     'n_controller.py, spin_forever.py) together (they drove '
                                     'turtle1 at once'),
    # legs.sh and bars.sh take turns on turtle1, never at once: stopped, as a TA stops them
    'o20_turns': ('L', 'pass', 'no launch file: the grader started its executables (bars.sh, '
                               'legs.sh) together (they took turns driving turtle1'),
    'o7_siblings': ('L', 'pass', 'every criterion met'),
    'o8_unbuilt': ('L', 'pass', "does not match current PROJECT_NAME 'lab_one'"),
    'o9_by_hand': ('L', 'pass', 'launch/turtle.launch starts nodes of turtlesim only, none of '
                               'hw3: the grader started its executables (letters.sh) instead'),
    'o21_projects': ('L', 'pass', 'no launch file: the grader started its executables '
                                  '(l_draw.py) as a launch file would'),
    'o10_turning': ('', 'fail', 'spin_forever.py, idle.py, keyboard.py not run alone: the '
                                'alone runs had used the 50 s they share'),
    'o11_prefixed': ('L', 'pass', "error while attempting to run: terminator -x "
                                  "lab1/scripts/l_controller.py; the grader ran its "
                                  "executables instead (keys.py, l_controller.py)"),
    'o12_windows': ('L', 'pass', 'the grader ran its executables instead (keys.py, '
                                 'l_controller.py), as a TA would; l_controller.py: no #! line '
                                 'exec can follow'),
    'o13_asks': ('L', 'pass', 'no launch file: the grader started its executables (asks.py)'),
    'o14_included': ('L', 'pass', "include dir 'include' does not exist relative to 'lab1'; "
                                  "git keeps no empty folder: the grader made lab1/include/, "
                                  "empty, as a TA would, and it built"),
    'o16_latched': ('', 'fail', 'as a TA would; failed on The letter drawn is the expected one: '
                                'nothing was drawn: scripts/letters.sh line 4: rostopic pub'),
    'o15_no_cmake': ('L', 'fail', 'The source directory hw3 does not contain a CMakeLists.txt '
                                  'file.; the grader ran its scripts unbuilt, from their folder'),
    'o17_never_built': ('', 'fail', 'hana_lab has no executable to run instead: its '
                                    'CMakeLists.txt builds no program of src/h_drawer.cpp, '
                                    'src/h_talker.cpp (add_executable(name src/h_drawer.cpp) '
                                    'builds one)'),
    'o18_no_launch': ('', 'fail', 'no launch file, and hana_lab has no executable to run: its '
                                  'CMakeLists.txt builds no program of src/h_drawer.cpp'),
}


@pytest.fixture(scope='module')
def graded(tmp_path_factory):
    top = tmp_path_factory.mktemp('odd')
    cls, out = str(top / 'class'), str(top / 'out')
    _lenas_changed(cls)
    _noahs_changed(cls)
    _others(cls)
    lenas = ('o1_', 'o3_', 'o4_', 'o5_', 'o7_', 'o8_', 'o9_', 'o11', 'o12', 'o13',
             'o14', 'o15', 'o16', 'o20', 'o21')  # not o2
    (top / 'roster.csv').write_text(
        'id,name,letter\n' + ''.join(f'{sid},Lena Ortiz,L\n' for sid in CONCLUSIONS
                                     if sid[:3] in lenas) +
        ''.join(f'{sid},Noah Klein,N\n' for sid in NOAHS) +
        'h7_printer,Hugo Stile,P\no17_never_built,Hana Sato,H\no18_no_launch,Hana Sato,H\n')
    before = sandbox_processes()
    try:
        yield (out,) + peak_memory_kb(started_grading(
            cls, '--roster', str(top / 'roster.csv'), '--rubric', RUBRIC, '--out', out,
            '--jobs', '2')) + (before,)
    finally:    # too deep for pytest's own clean-up
        subprocess.run(['rm', '-rf', os.path.join(cls, 'o1_deep')], check=True)


def _replaced(path, old, new):
    """The file at `path` with `old` replaced by `new`, its line endings kept."""
    with open(path, newline='') as f:
        text = f.read()
    with open(path, 'w', newline='') as f:
        f.write(text.replace(old, new))


def _lenas_changed(cls):
    """Lena's package, each copy changed one odd way, and a sibling beside one."""
    for name in ('o1_deep', MULLER, 'o3_fifo', 'o4_twice', 'o5_turtlesim', 'o8_unbuilt',
                 'o11_prefixed', 'o12_windows', 'o14_included', 'o7_siblings'):
        shutil.copytree(LENA, os.path.join(cls, name))
    nest(os.path.join(cls, 'o1_deep', 'lab1'), 1100)
    os.mkfifo(os.path.join(cls, 'o3_fifo', 'lab1', 'scripts', 'pipe'))
    shutil.copytree(os.path.join(cls, 'o4_twice', 'lab1'), os.path.join(cls, 'o4_twice',
                                                                         'lab1 (copy)'))
    _replaced(os.path.join(cls, 'o5_turtlesim', 'lab1', 'package.xml'),
              '<name>lab1</name>', '<name>turtlesim</name>')
    # a project named otherwise than its package: catkin refuses it
    _replaced(os.path.join(cls, 'o8_unbuilt', 'lab1', 'CMakeLists.txt'),
              'project(lab1)', 'project(lab_one)')
    # catkin_create_pkg made include/, which git never kept
    _replaced(os.path.join(cls, 'o14_included', 'lab1', 'CMakeLists.txt'),
              'catkin_package()', 'catkin_package(INCLUDE_DIRS include)')
    # a window of its own, in a terminal no machine of ours has
    _replaced(os.path.join(cls, 'o11_prefixed', 'lab1', 'launch', 'start.launch'),
              'name="l_controller"/>', 'name="l_controller" launch-prefix="terminator -x"/>')
    # each line ending in CR LF
    _replaced(os.path.join(cls, 'o12_windows', 'lab1', 'scripts', 'l_controller.py'),
              '\n', '\r\n')
    for name, text in GAZEBO_WORLD.items():
        os.makedirs(os.path.join(cls, 'o7_siblings', 'gazebo_world'), exist_ok=True)
        with open(os.path.join(cls, 'o7_siblings', 'gazebo_world', name), 'w') as f:
            f.write(text)


def _noahs_changed(cls):
    """Noah's package (no launch file) with executables that fight or idle."""
    shutil.copytree(NOAH, os.path.join(cls, 'o6_three'))
    _written(os.path.join(cls, 'o6_three', 'noah_ws', 'src', 'lab_one', 'scripts'),
             {'spin_forever.py': SPIN})
    # o6's fight again, where its launch file starts turtlesim alone (a real class's
    # started Gazebo): the alone run's line says so, not "no launch file"
    shutil.copytree(os.path.join(cls, 'o6_three'), os.path.join(cls, 'o19_passed_over'))
    launch = os.path.join(cls, 'o19_passed_over', 'noah_ws', 'src', 'lab_one', 'launch')
    os.makedirs(launch)
    with open(os.path.join(launch, 'turtle.launch'), 'w') as f:
        f.write('<launch>\n  <node pkg="turtlesim" type="turtlesim_node" name="sim"/>\n'
                '</launch>\n')
    shutil.copytree(NOAH, os.path.join(cls, 'o10_turning'))
    _written(os.path.join(cls, 'o10_turning', 'noah_ws', 'src', 'lab_one', 'scripts'),
             {'n_controller.py': TURN, 'spin_forever.py': TURN, 'idle.py': IDLE})


def _written(folder, scripts):
    """Each of `scripts` (name: text) written in `folder`, executable."""
    for name, text in scripts.items():
        with open(os.path.join(folder, name), 'w') as f:
            f.write(text)
        os.chmod(os.path.join(folder, name), 0o755)


def _others(cls):
    """A hostile printer, Hana's C++ never built (one without its launch
    folder), and packages written here: by hand, a prompt, latched lines."""
    shutil.copytree(PRINTER, os.path.join(cls, 'h7_printer'))
    for sid in ('o17_never_built', 'o18_no_launch'):
        shutil.copytree(HANA, os.path.join(cls, sid))
        # as catkin_create_pkg wrote them: commented out, never built
        cmake = os.path.join(cls, sid, 'hana_lab', 'CMakeLists.txt')
        _replaced(cmake, 'add_executable', '# add_executable')
        _replaced(cmake, 'target_link_libraries', '# target_link_libraries')
    shutil.rmtree(os.path.join(cls, 'o18_no_launch', 'hana_lab', 'launch'))
    no_cmake = {name: text for name, text in BY_HAND.items() if name != 'CMakeLists.txt'}
    for folder, files in (('o9_by_hand/hw3', BY_HAND), ('o13_asks/asks', ASKS),
                          ('o15_no_cmake/hw3', no_cmake), ('o16_latched/hw3', LATCHED),
                          ('o20_turns/turns', TURNS), ('o21_projects', PROJECTS)):
        for name, text in files.items():
            path = os.path.join(cls, folder, name)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, 'w') as f:
                f.write(text)
            os.chmod(path, 0o755 if name in ('scripts/asks.py', 'scripts/legs.sh',
                                             'scripts/bars.sh', 'gazebo_chase/scripts/chase.py')
                     else 0o644)


def rows_of(out):
    with open(os.path.join(out, 'grades.csv'), encoding='utf-8') as f:
        return {row['id']: row for row in csv.DictReader(f)}


def criteria(out, sid):
    """Each criterion's points and words, as results.json has them, or ''."""
    path = os.path.join(out, sid, 'results.json')
    if not os.path.exists(path):
        return ''
    with open(path, encoding='utf-8') as f:
        return '; '.join(f"{t['name']}: {t['score']:g}/{t['max_score']:g}: {t['output']}"
                         for t in json.load(f)['tests'])


def test_each_odd_submission_costs_its_own_row_and_says_why(graded):
    out, _, printed, _ = graded
    assert 'passed in' in printed, printed[-3000:]
    rows = rows_of(out)
    assert sorted(rows) == sorted(CONCLUSIONS), printed[-3000:]
    for sid, (drawn, verdict, words) in CONCLUSIONS.items():
        said = f"{sid}: {rows[sid]['reason']}; {criteria(out, sid)}"
        assert (rows[sid]['drawn'], rows[sid]['verdict']) == (drawn, verdict), said
        assert words in rows[sid]['reason'], said


def test_a_script_that_ends_with_its_last_move_is_seen_to_stand(graded):
    """o9's script ends with its last `rostopic pub -1`, and roslaunch with it,
    while the turtle still moves: the drawing ends, the turtle standing."""
    with open(os.path.join(graded[0], 'o9_by_hand', 'results.json')) as f:
        tests = {t['name']: t for t in json.load(f)['tests']}
    ends = tests['The drawing ends, the turtle standing still']
    assert ends['status'] == 'passed' and ends['output'].startswith('ended after'), ends


def test_a_script_stopped_at_a_latched_rostopic_pub_says_where_and_what_to_type(graded):
    """o16's script turns with `rostopic pub -l`, which never exits: the
    letter's line and the ending's say so, not only that nothing was drawn."""
    with open(os.path.join(graded[0], 'o16_latched', 'results.json')) as f:
        said = {t['name']: t['output'] for t in json.load(f)['tests']}
    why = ('scripts/letters.sh line 4: rostopic pub without -1 publishes once and waits to be '
           'stopped (Ctrl-C), so no line after it ran; -1 publishes once and exits')
    assert said['The letter drawn is the expected one'] == f'nothing was drawn: {why}', said
    assert said['The drawing ends, the turtle standing still'] == \
        f'the turtle never moved after the trigger: {why}', said


def test_a_script_tried_alone_and_not_kept_is_said_and_logged(graded):
    """o20's bars.sh, tried alone first (in name order), waits for a move
    that never comes and draws nothing; legs.sh alone draws the L, and is
    kept: the row says what bars.sh drew, and its log holds bars.sh's run."""
    reason = rows_of(graded[0])['o20_turns']['reason']
    assert 'then legs.sh alone in a fresh world' in reason, reason
    assert '; also tried, not kept: bars.sh alone drew no letter (' in reason, reason
    log = open(os.path.join(graded[0], 'o20_turns', 'log.txt')).read()
    assert '==== bars.sh alone, not kept: roslaunch ' in log, log[-3000:]


def test_a_prompt_that_asks_for_the_letter_is_typed_it_and_the_row_says_so(graded):
    """o13 asks at a prompt which letter to draw: P earns nothing there, so
    the roster's L is typed, and it is drawn; only `talker` is lost for it."""
    with open(os.path.join(graded[0], 'o13_asks', 'results.json')) as f:
        tests = {t['name']: t for t in json.load(f)['tests']}
    talker = tests['The talker publishes P on a key press']
    assert talker['status'] == 'failed' and talker['output'] == (
        "no \"P\" on /chatter within 5 s of P and Enter; a node waited for a line on the "
        "terminal ('a letter to draw (L):'): the grader typed L and Enter, as a TA would"), talker
    assert tests['The letter drawn is the expected one']['output'] == 'drew L, as expected'


def test_what_was_left_out_is_said_in_the_students_log(graded):
    out = graded[0]
    fifo = open(os.path.join(out, 'o3_fifo', 'log.txt')).read()
    assert 'left out lab1/scripts/pipe: not a plain file, folder or link' in fifo
    twice = open(os.path.join(out, 'o4_twice', 'log.txt')).read()
    assert 'left out lab1 (copy): a second package named lab1 (graded the one in lab1)' in twice
    assert os.path.exists(os.path.join(out, 'o2_M%FCller', 'results.json'))
    projects = open(os.path.join(out, 'o21_projects', 'log.txt')).read()
    assert 'left out gazebo_chase: gazebo_chase, which turtle_description neither depends on ' \
        'nor launches' in projects
    siblings = open(os.path.join(out, 'o7_siblings', 'log.txt')).read()
    assert 'left out gazebo_world: gazebo_world, which lab1 neither depends on nor launches' \
        in siblings


def test_what_the_printer_printed_reaches_no_file_raw_and_the_grader_stays_small(graded):
    out, peak, _, _ = graded
    reason = rows_of(out)['h7_printer']['reason']     # its error line, up to the form feed
    assert reason == 'It builds: catkin_make failed: error:  [2J ]0;owned ', reason  # BEL: ' '
    for name in ('grades.csv', 'junit.xml', 'report.html', 'h7_printer/results.json',
                 'h7_printer/log.txt'):
        with open(os.path.join(out, name), encoding='utf-8') as f:
            text = f.read()
        assert not any(c in text for c in '\x1b\x07\x0c'), name
    ElementTree.parse(os.path.join(out, 'junit.xml'))
    log = open(os.path.join(out, 'h7_printer', 'log.txt')).read()     # its start and end
    assert 'lines left out' in log and len(log) < 100000 and 'the printer stops here' in log
    assert 0 < peak < GRADER_MEMORY_KB, f'the grader held {peak / 1024:.0f} MiB'


def test_nothing_is_left(graded):
    assert leftovers(graded[3]) == ([], [])
