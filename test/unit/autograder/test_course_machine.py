"""What a course's Noetic machine offers, offered here: turtlesim's headers
found where roscpp's are, whichever workspace built them; the windows
a launch-prefix opens; python3 by Noetic's names for it. No ROS here."""
import os
import subprocess

from turtle_letters.autograder import world as machine


def headers(folder):
    os.makedirs(os.path.join(folder, 'turtlesim'), exist_ok=True)
    open(os.path.join(folder, 'turtlesim', 'Pose.h'), 'w').close()


def test_turtlesim_headers_of_a_workspace_are_offered_where_roscpp_has_none(tmp_path,
                                                                           monkeypatch):
    roscpp, ws = tmp_path / 'usr_include', tmp_path / 'ws' / 'devel'
    (roscpp / 'ros').mkdir(parents=True)
    (roscpp / 'ros' / 'ros.h').touch()
    headers(str(ws / 'include'))
    monkeypatch.setattr(machine, 'ROSCPP_INCLUDES', (str(roscpp),))
    environ = {'CMAKE_PREFIX_PATH': f'/nowhere:{ws}:/usr', 'CPATH': '/mine'}
    assert machine.course_environment(environ) == {'CPATH': f'{ws}/include:/mine'}
    headers(str(roscpp))        # as on /opt/ros/noetic: beside roscpp's already
    assert machine.course_environment(environ) == {}


def test_a_window_a_launch_prefix_opens_runs_its_command_in_the_same_terminal(tmp_path):
    """xterm -e, gnome-terminal --, --command and -x, konsole -e: the
    command runs with the node's own arguments as roslaunch appends them,
    and hears what is typed in roslaunch's terminal (a talker started in an
    xterm hears the grader's P)."""
    machine.terminal_stand_ins(str(tmp_path))
    echo = ['/usr/bin/python3', '-c', 'import sys; print(sys.argv[1:], input())']

    def ran(*prefix, node=echo):
        done = subprocess.run([str(tmp_path / prefix[0]), *prefix[1:], *node, '__name:=talker'],
                              input='P\n', capture_output=True, text=True, timeout=30)
        return done.returncode, done.stdout.strip(), done.stderr
    assert ran('xterm', '-hold', '-e')[:2] == (0, "['__name:=talker'] P")
    assert ran('gnome-terminal', '--')[:2] == (0, "['__name:=talker'] P")
    assert ran('konsole', '-e')[:2] == (0, "['__name:=talker'] P")
    assert ran('x-terminal-emulator', '-T', 'talker', '-e')[:2] == (0, "['__name:=talker'] P")
    # a command line in one word, its words split as a shell would
    script = tmp_path / 'talk.py'
    script.write_text('import sys\nprint(sys.argv[1:], input())\n')
    line = f'/usr/bin/python3 {script}'
    assert ran('gnome-terminal', '--command', node=[line])[:2] == (0, "['__name:=talker'] P")
    assert ran('gnome-terminal', f'--command={line}', node=[])[:2] == (0, "['__name:=talker'] P")
    code, _, said = ran('xterm', node=[])
    assert code != 0 and 'no command after -e, -x, -- or --command' in said


def test_a_script_that_names_noetics_python_by_its_version_runs(tmp_path):
    """A real class's `#!/usr/bin/env python3.8`: Noetic's python3 on Ubuntu
    20.04; Debian 12 has no python3.8."""
    machine.interpreter_stand_ins(str(tmp_path))
    for name in machine.INTERPRETERS:
        script = tmp_path / f'{name}_script'
        script.write_text(f'#!/usr/bin/env {name}\nimport sys\nprint(sys.version_info[0])\n')
        script.chmod(0o755)
        done = subprocess.run([str(script)], capture_output=True, text=True, timeout=30,
                              env={'PATH': f'{tmp_path}:/usr/bin:/bin'})
        assert (done.returncode, done.stdout) == (0, '3\n'), (name, done.stderr)
