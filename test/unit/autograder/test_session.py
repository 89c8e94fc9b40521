"""The session's steps that need no world: when the grader stops watching
a run (each reason alone ends it, among them a full record of the
grader's simulator that said it stopped the run, and did not), what a
failed build says, and what runs for want of a launch file."""
import os
import time
from types import SimpleNamespace

import pytest

from turtle_letters.autograder import world
from turtle_letters.autograder.processes import Capped
from turtle_letters.autograder.session import (NO_TURTLESIM, Refused, Run, Step,
                                                drivers_first, executables, started_instead,
                                               first_error, generated_launch, missing_include,
                                               prepare)
from turtle_letters.autograder.submission import find
from turtle_letters.autograder.world import Lab


def lab_of(**changed):
    """A Lab of fakes: its sandbox, world, terminal and watcher as `changed` says."""
    lab = Lab.__new__(Lab)
    lab.box = SimpleNamespace(going=lambda: not changed.get('limit') and
                              not changed.get('stopped'))
    lab.terminal = SimpleNamespace(process=SimpleNamespace(poll=lambda: changed.get('ended')))
    lab.watcher = SimpleNamespace(full=changed.get('events_full', False))
    lab.world = SimpleNamespace(full=changed.get('record_full', False),
                                broken=lambda: changed.get('broken', ''))
    return lab


def test_a_run_in_order_is_watched():
    assert lab_of().going()


@pytest.mark.parametrize('reason', [dict(ended=0), dict(limit='memory limit of 2 GiB reached'),
                                    dict(stopped=True), dict(events_full=True),
                                    dict(record_full=True), dict(broken='shut down')])
def test_each_reason_alone_ends_the_watch(reason):
    assert not lab_of(**reason).going()


class Part:
    """A fake part of the lab: it says when it was started and stopped."""

    def __init__(self, name, said, fails=False):
        self.name, self.said, self.fails = name, said, fails

    def __call__(self, *_):         # made, as the Lab makes its terminal and watcher
        self.said.append(f'{self.name} started')
        if self.fails:
            raise OSError(f'{self.name} could not start')
        return self

    def start(self):                # started, as the Lab starts its world
        self(None)

    def stop(self):
        self.said.append(f'{self.name} stopped')
        return f'{self.name} said this'


@pytest.mark.parametrize('failing', [None, 'world', 'terminal', 'watcher'])
def test_the_lab_stops_what_it_started_in_order_however_far_its_start_came(monkeypatch,
                                                                          failing):
    said = []
    parts = {name: Part(name, said, fails=name == failing)
             for name in ('world', 'terminal', 'watcher')}
    monkeypatch.setattr(world, 'GradingWorld', lambda box, limits: parts['world'])
    monkeypatch.setattr(world, 'Terminal', parts['terminal'])
    monkeypatch.setattr(world, 'Watcher', parts['watcher'])
    started = ['world', 'terminal', 'watcher']
    started = started[:started.index(failing) + 1] if failing else started
    if failing:
        with pytest.raises(OSError):
            Lab(None, ['roslaunch'], None)
    else:
        assert Lab(None, ['roslaunch'], None).stop() == 'watcher said this'
    stopped = [name for name in ('terminal', 'world', 'watcher') if name in started]
    stopped = [n for n in stopped if n != failing or n == 'world']    # the world is always stopped
    assert said == [f'{n} started' for n in started] + [f'{n} stopped' for n in stopped]


def test_a_failed_build_says_its_first_error_in_its_own_words():
    """A compiler's error line; CMake's message under "CMake Error at"
    (catkin refusing a project named otherwise than its package), not the
    "Configuring incomplete" that follows it, nor make's "Error 2"."""
    cmake = ("-- Using CATKIN_DEVEL_PREFIX\n"
             "CMake Error at /usr/share/catkin/cmake/catkin_package_xml.cmake:54 (message):\n"
             "  'ws/src/lab1/package.xml' does not match current PROJECT_NAME\n"
             "  'lab_one'.  You must call project() with the same name.\n"
             "Call Stack (most recent call first):\n"
             "  CMakeLists.txt:4 (catkin_package)\n\n"
             "-- Configuring incomplete, errors occurred!\n")
    assert first_error(cmake).endswith("(message): 'ws/src/lab1/package.xml' does not match "
                                       "current PROJECT_NAME 'lab_one'.  You must call project() "
                                       "with the same name.")
    gcc = "make[2]: *** [x] Error 1\nsrc/main.cpp:58:27: error: no matching function\n"
    assert first_error(gcc) == 'src/main.cpp:58:27: error: no matching function'
    assert first_error('nothing useful\n') == 'see log.txt'
    # catkin_pkg's reasons come on the lines under its own (a real class's package.xml)
    catkin = ("Error(s) in package 'ws/src/lab/package.xml':\n"
              "Invalid email \"a@b\" for person \"a\"\n\n-- Configuring incomplete\n")
    assert first_error(catkin) == ("Error(s) in package 'ws/src/lab/package.xml': "
                                   "Invalid email \"a@b\" for person \"a\"")


def handed_in(tmp_path, name, files):
    """Package `name` of `files` (path: text), each mode 644, as the grader
    finds and prepares it: (the package, its box, the files made executable)."""
    folder = tmp_path / 'sub' / name
    files = {'package.xml': f'<package format="2"><name>{name}</name></package>', **files}
    for path, text in files.items():
        (folder / path).parent.mkdir(parents=True, exist_ok=True)
        (folder / path).write_text(text)
        os.chmod(folder / path, 0o644)
    package = find(str(tmp_path / 'sub'))
    made = prepare(package, str(tmp_path / 'work'))
    return package, SimpleNamespace(work=str(tmp_path / 'work')), made


def test_an_include_folder_catkin_says_a_package_lacks_is_made_only_inside_it(tmp_path):
    """A real class's CMakeLists.txt names INCLUDE_DIRS include, a folder
    catkin_create_pkg made and git never kept: the folder catkin names is
    made in the package's copy, a TA's fallback; never one outside it, nor
    where something is already."""
    work = str(tmp_path)
    package = tmp_path / 'ws' / 'src' / 'letters'
    package.mkdir(parents=True)

    def said(folder, relative_to):     # catkin's message, as CMake wraps it
        return (f'CMake Error at /usr/share/catkin/cmake/catkin_package.cmake:312 (message):\n'
                f"  catkin_package() include dir '{folder}' does not exist relative to\n"
                f"  '{relative_to}'\nCall Stack (most recent call first):\n")
    assert missing_include(work, said('include', package)) == str(package / 'include')
    assert missing_include(work, 'CMake Error at CMakeLists.txt:3 (project):\n') is None
    assert missing_include(work, said('../../../etc', package)) is None
    assert missing_include(work, said('include', tmp_path / 'ws')) is None
    assert missing_include(work, said('include', '/etc')) is None
    (package / 'include').symlink_to(tmp_path / 'elsewhere')
    assert missing_include(work, said('include', package)) is None


def test_scripts_handed_in_without_the_execute_bit_are_started_for_want_of_a_launch_file(tmp_path):
    """A real class's package: no launch file, its one script mode 644.
    The copy's script is made executable, and that is the one started."""
    package, box, made = handed_in(tmp_path, 'lab', {'scripts/draw_m.py':
                                                     '#!/usr/bin/env python3\n'})
    assert made == ['scripts/draw_m.py'] and executables(box, package) == ['draw_m.py']
    assert 'type="draw_m.py"' in open(generated_launch(box, package, ['draw_m.py'])).read()


def test_a_shell_script_without_its_bang_is_started_with_bash(tmp_path):
    """A real class's package: its launch file starts turtlesim alone; its
    letters are a shell script of rosservice and rostopic calls, mode 644
    and without #!, which its cadets ran with bash. The grader's launch
    file starts the script with bash."""
    package, box, made = handed_in(tmp_path, 'hw', {
        'launch/turtle.launch': '<launch><node pkg="turtlesim" type="turtlesim_node" '
                                'name="s"/></launch>',
        'scripts/letters.sh': 'rosservice call /clear\n'})
    assert made == ['scripts/letters.sh'] and executables(box, package) == ['letters.sh']
    text = open(generated_launch(box, package, ['letters.sh'])).read()
    assert 'type="letters.sh" name="letters0" output="screen" launch-prefix="bash"/>' in text


# Scripts handed in executable that exec cannot start, as real classes wrote them,
# and one it can: started for want of a launch file, each as a TA would run it.
UNSTARTABLE = {'scripts/spawn.py': 'import rospy\n',                     # no #! line at all
               'scripts/topic.py': '#!usr/bin/env python\nimport rospy\n',    # no leading /
               'scripts/windows.py': '#!/usr/bin/env python3\r\nimport rospy\r\n',  # CR LF
               'scripts/sound.py': '#! /usr/bin/env python3\nimport rospy\n',
               'scripts/crlf.sh': '#!/bin/bash\r\nrosservice call /clear\r\n'}  # CR LF


def test_a_python_script_exec_cannot_start_is_started_with_python3(tmp_path):
    """A real class's scripts: one without a #! line and one whose #! names
    no path died in roslaunch ("Unable to launch", "No such file or
    directory"); a #! line that ends in a carriage return fails so too. The
    grader's launch file starts each with python3, and a shell script saved
    so with bash; a sound one, as it is. A module handed in mode 644
    without #! is no program: it is not started."""
    package, box, _ = handed_in(tmp_path, 'lab', {**UNSTARTABLE, 'src/lab/shapes.py': 'N = 1\n'})
    for path in UNSTARTABLE:
        os.chmod(os.path.join(box.work, 'ws', 'src', 'lab', path), 0o755)
    names = executables(box, package)
    assert names == ['crlf.sh', 'sound.py', 'spawn.py', 'topic.py', 'windows.py']
    text = open(generated_launch(box, package, names)).read()
    for name in ('spawn', 'topic', 'windows'):
        assert f'type="{name}.py" name="{name}' in text and \
            f'name="{name}{names.index(name + ".py")}" output="screen" ' \
            f'launch-prefix="python3"/>' in text, text
    assert 'name="sound1" output="screen"/>' in text, text
    assert 'name="crlf0" output="screen" launch-prefix="bash"/>' in text, text


def test_the_scripts_run_with_python3_or_bash_are_named_in_the_row_with_why():
    run = Run(None)
    run.generated = 'keys.py, letters.sh, sound.py, spawn.py'
    run.unstartable = {'letters.sh': 'bash', 'sound.py': 'python3', 'spawn.py': 'python3'}
    run.launch = Step(True, 'turtlesim up, /keys0 listening on /chatter, in 2.0 s')
    fell_short, step = started_instead(run)
    assert fell_short == '; sound.py, spawn.py: no #! line exec can follow (#!/usr/bin/env ' \
                         'python3 is one), so the grader ran them with python3, as a TA ' \
                         'would; letters.sh: no #! line exec can follow (#!/bin/bash is one), ' \
                         'so the grader ran it with bash, as a TA would'
    assert step.says == 'no launch file: the grader started its executables (keys.py, ' \
                        'letters.sh, sound.py, spawn.py) as a launch file would' + fell_short


def test_the_terminal_says_whether_it_reads_in_lines_or_key_by_key():
    """A prompt's input() reads the terminal in lines; a talker that reads
    each key sets it key by key (cbreak), as the lab's does."""
    box = SimpleNamespace(started=lambda process: process)
    keys = 'import sys, time, tty\ntty.setcbreak(sys.stdin.fileno())\nprint("k")\ntime.sleep(60)\n'
    for code, in_lines in (('print("k")\ninput()\n', True), (keys, False)):
        terminal = world.Terminal(['/usr/bin/python3', '-c', code], box)
        try:
            deadline = time.monotonic() + 10
            while b'k' not in terminal.output.text().encode() and time.monotonic() < deadline:
                time.sleep(0.05)
            assert terminal.in_lines() is in_lines, code
        finally:
            terminal.process.kill()
            terminal.process.wait()
            os.close(terminal.master)
            terminal.reader.stop()


def test_a_launch_roslaunch_refused_a_node_of_is_waited_for_only_a_while_after():
    """roslaunch's refusal, in a terminal's output among its other lines
    (and in the part kept of a long one), starts the others' time."""
    output = Capped()
    output.add(b'started roslaunch server\r\n' + b'.' * (2 * Capped.HEAD))
    refused = Refused(output, 0.3)
    assert not refused.waited_out()
    time.sleep(0.4)
    assert not refused.waited_out(), 'no refusal yet: the launch may take its whole limit'
    output.add(b'\x1b[31mERROR: cannot launch node of type [lab/controler.py]\x1b[0m\r\n')
    assert not refused.waited_out()
    time.sleep(0.4)
    assert refused.waited_out()


def package_copy(tmp_path, files):
    """A sandbox's work folder holding the copy of a package `lab` of `files`
    ({path in it: text}), and a run of it: (box, run)."""
    for path, text in files.items():
        (tmp_path / 'ws' / 'src' / 'lab' / path).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / 'ws' / 'src' / 'lab' / path).write_text(text)
    return SimpleNamespace(work=str(tmp_path)), SimpleNamespace(
        package=SimpleNamespace(name='lab'), executables=sorted(os.path.basename(path)
                                                                for path in files), record=[])


def test_executables_that_drove_together_are_tried_alone_first(tmp_path):
    """The generated launch file's node names (of the file, and its place)
    tell which executable acted (the simulator's `by` lines):
    spin_forever.py and n_controller.py did, keyboard.py only talked."""
    box, run = package_copy(tmp_path, {'keyboard.py': '', 'n_controller.py': '',
                                       'spin_forever.py': ''})
    run.record = [dict(k='by', t=1.0, node='/spin_forever2'),
                  dict(k='by', t=1.2, node='/n_controller1')]
    assert drivers_first(run, box) == ['n_controller.py', 'spin_forever.py', 'keyboard.py']
    run.record = [dict(k='by', t=1.0, node='/keyboard1')]   # a name that is not its place
    assert drivers_first(run, box) == run.executables


def test_of_scripts_that_drove_together_the_one_naming_more_turtles_is_tried_alone_first(
        tmp_path):
    """A course's two scripts of `rostopic pub -1` lines, their nodes
    anonymous: one draws the first letter with turtle1, the other spawns
    turtle2 for the second letter too: the second, the whole drawing, is
    tried first (a real class's five of six were run alone in name order,
    the script of turtle1 alone first, for nothing). A link is not read."""
    one = 'rostopic pub -1 /turtle1/cmd_vel geometry_msgs/Twist -- "[2, 0, 0]" "[0, 0, 0]"\n'
    two = 'rosservice call /spawn 8 5 0 ""\nrosservice call /turtle2/set_pen 0 255 0 3 0\n' + \
        one + one.replace('turtle1', 'turtle2')
    box, run = package_copy(tmp_path, {'scripts/letter.sh': one * 3,
                                       'scripts/letters_two.sh': two})
    run.record = [dict(k='by', t=1.0, node='/rostopic_2171_1796590448'),
                  dict(k='by', t=1.1, node='/rosservice_2170_1796590447')]
    assert drivers_first(run, box) == ['letters_two.sh', 'letter.sh']
    (tmp_path / 'ws' / 'src' / 'lab' / 'scripts' / 'letters_two.sh').unlink()
    (tmp_path / 'elsewhere.sh').write_text(two)
    os.symlink(tmp_path / 'elsewhere.sh', tmp_path / 'ws' / 'src' / 'lab' / 'scripts' /
               'letters_two.sh')
    assert drivers_first(run, box) == ['letter.sh', 'letters_two.sh']   # a link is not read


def test_a_node_the_grader_started_that_died_says_why_beside_how_it_was_started():
    """A real class's script with no launch file, its `if __name__` inside its
    class: started by the grader, it died of a NameError, and the row said
    only that the grader had started it."""
    run = Run(None)
    run.generated, run.launch = 'cls.py', Step(False, "cls0 died: NameError: name 'Turtle' "
                                                      "is not defined (p/scripts/cls.py, line 9)")
    fell_short, step = started_instead(run)
    assert step == Step(False, 'no launch file: the grader started its executables (cls.py) as '
                               "a launch file would; cls0 died: NameError: name 'Turtle' is not "
                               'defined (p/scripts/cls.py, line 9)')
    assert fell_short == "; cls0 died: NameError: name 'Turtle' is not defined " \
                         '(p/scripts/cls.py, line 9)'
    run.passed_over = 'launch/a.launch starts nodes of turtlesim only, none of p'
    assert started_instead(run)[1].says.startswith(
        'launch/a.launch starts nodes of turtlesim only, none of p: the grader started its '
        "executables (cls.py) instead, as a TA would; cls0 died: NameError")
    run.launch = Step(False, NO_TURTLESIM, 2.0)    # the lab came up
    assert started_instead(run)[0] == ''
    run.launch = Step(True, 'turtlesim up, /c listening on /chatter, in 2.0 s')
    assert started_instead(run) == ('', Step(False, 'launch/a.launch starts nodes of turtlesim '
                                                    'only, none of p: the grader started its '
                                                    'executables (cls.py) instead, as a TA '
                                                    'would'))
