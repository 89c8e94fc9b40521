"""What a process prints, as the grader keeps it: its start and end, the
middle counted, however much it prints."""
import os
import pty
import shutil
import subprocess
import sys
import time

from turtle_letters.autograder.processes import (Capped, ControllerCpu, Reader, RunningScripts,
                                                controller_processes, reading_input)
from turtle_letters.autograder.session import wait_until


def test_the_start_and_end_are_kept_and_the_middle_counted():
    kept = Capped()
    kept.HEAD, kept.TAIL = 5, 5
    for data in (b'abc', b'defgh', b'ijklmnopqrstuvwxyz'):
        kept.add(data)
    assert kept.size == 26
    assert kept.text() == 'abcde\n... 16 bytes left out ...\nvwxyz'
    assert kept.text(since=3) == 'de\n... 16 bytes left out ...\nvwxyz'
    assert kept.text(since=24) == 'yz'


def test_a_flood_through_a_pipe_stays_within_its_bounds():
    kept, (read_end, write_end) = Capped(), os.pipe()
    pid = os.fork()
    if pid == 0:        # a child that prints 64 MiB, as a build that runs `yes` would
        os.close(read_end)
        for _ in range(1024):
            os.write(write_end, b'y\n' * 32768)
        os._exit(0)
    os.close(write_end)
    kept.read_all(read_end)
    os.close(read_end)
    os.waitpid(pid, 0)
    assert kept.size == 64 * 1024 * 1024
    assert len(kept.head) == Capped.HEAD and len(kept.tail) <= 2 * Capped.TAIL
    assert f'{kept.size - Capped.HEAD - Capped.TAIL} bytes left out' in kept.text()


def test_a_reader_stopped_has_read_its_last_and_no_number_it_held_is_read_again():
    """A pseudo-terminal whose other end a process keeps open: stopped, the
    reader has ended and closed its own descriptor, so a pipe opened next
    (which may get the same number) is read by its owner alone."""
    master, slave = pty.openpty()
    reader = Reader(master)
    os.write(slave, b'roslaunch says hello\n')
    reader.stop(seconds=0.5)
    assert not reader.thread.is_alive()
    assert 'roslaunch says hello' in reader.output.text()
    read_end, write_end = os.pipe()
    os.write(write_end, b'the next pipe')
    assert os.read(read_end, 100) == b'the next pipe'
    assert 'next pipe' not in reader.output.text()
    for fd in (slave, read_end, write_end):
        os.close(fd)


def test_a_controller_that_ended_has_no_cpu_figure_never_a_negative_one():
    """Its CPU time ends with its process: a share measured then was -1.4 %."""
    busy = subprocess.Popen([sys.executable, '-c', 'import time\nend = time.time() + 0.3\n'
                             'while time.time() < end: pass'])
    cpu = ControllerCpu(0, [])
    cpu.pids, cpu.used = [busy.pid], {busy.pid: 0.0}
    time.sleep(0.1)
    assert cpu.share() > 0
    cpu.used = cpu._used()
    busy.wait()
    assert cpu.share() is None


def test_a_shell_script_of_the_submission_is_seen_running_until_it_ends(tmp_path):
    """Started as roslaunch starts nodes (`bash FILE __name:=...`): the
    submission's script in its workspace counts, the grader's stand-in for
    turtlesim (a script too, outside it) does not, and one that ended is no
    longer seen."""
    (tmp_path / 'ws').mkdir()
    (tmp_path / 'stand_in').mkdir()
    (tmp_path / 'ws' / 'letters.sh').write_text('read line < "$0.go"\n')
    (tmp_path / 'stand_in' / 'turtlesim_node').write_text('sleep 60\n')
    os.mkfifo(str(tmp_path / 'ws' / 'letters.sh.go'))
    launch = subprocess.Popen(
        ['bash', '-c', 'bash "$0"/ws/letters.sh __name:=letters & '
                       'sh "$0"/stand_in/turtlesim_node __name:=sim & wait', str(tmp_path)],
        start_new_session=True)
    try:
        deadline = time.monotonic() + 10
        while not (controller_processes(launch.pid, 'sim') and
                   controller_processes(launch.pid, 'letters')) and time.monotonic() < deadline:
            time.sleep(0.05)        # both up
        scripts = RunningScripts(launch.pid, str(tmp_path / 'ws'))
        assert len(scripts.pids) == 1 and scripts.running() and scripts.until is not None
        seen = scripts.until
        with open(tmp_path / 'ws' / 'letters.sh.go', 'w') as go:     # the script ends
            go.write('\n')
        while scripts.running() and time.monotonic() < deadline:
            time.sleep(0.05)
        assert not scripts.running() and scripts.until >= seen
    finally:
        os.killpg(launch.pid, 9)
        launch.wait()


def test_where_the_grader_started_the_executables_each_is_seen_running_as_a_script_is(tmp_path):
    """With `programs` (no launch file: a TA runs each in a terminal and
    sees it end), a Python script run by its interpreter and a built
    program of the workspace count as scripts do; without, neither does;
    the grader's stand-in for turtlesim (outside it) never. A real class's
    script paused 9 s between strokes: only its running kept it drawing."""
    ws = tmp_path / 'ws'
    (ws / 'src').mkdir(parents=True)
    (ws / 'devel' / 'lib' / 'lab').mkdir(parents=True)
    (ws / 'src' / 'draw.py').write_text('import time\ntime.sleep(60)\n')
    shutil.copy('/bin/bash', ws / 'devel' / 'lib' / 'lab' / 'drawer')     # a program built there
    (tmp_path / 'stand_in').mkdir()
    (tmp_path / 'stand_in' / 'turtlesim_node').write_text('sleep 60\n')
    launch = subprocess.Popen(
        ['bash', '-c', f'{sys.executable} "$0"/ws/src/draw.py __name:=d & '
                       '"$0"/ws/devel/lib/lab/drawer -c "sleep 60; :" __name:=c & '
                       'sh "$0"/stand_in/turtlesim_node __name:=sim & wait', str(tmp_path)],
        start_new_session=True)
    try:
        assert wait_until(lambda: all(controller_processes(launch.pid, node)
                                      for node in ('d', 'c', 'sim')), 10.0)
        assert RunningScripts(launch.pid, str(ws)).pids == []
        every = RunningScripts(launch.pid, str(ws), programs=True)
        assert sorted(every.names.values()) == ['draw.py', 'drawer']
        assert every.running() and every.until is not None
    finally:
        os.killpg(launch.pid, 9)
        launch.wait()


def test_a_node_a_script_started_is_the_scripts(tmp_path):
    """Two scripts started as roslaunch starts nodes, each starting a
    process under it, as a `rostopic pub -1` line does: an anonymous node
    named with that process's pid is the script's; another node is its own."""
    (tmp_path / 'ws').mkdir()
    for name in ('a.sh', 'b.sh'):        # a child that lives, its pid where the test reads it
        (tmp_path / 'ws' / name).write_text('sleep 60 & echo $! > "$0.pid"\nwait\n')
    launch = subprocess.Popen(
        ['bash', '-c', 'bash "$0"/ws/a.sh __name:=a & bash "$0"/ws/b.sh __name:=b & wait',
         str(tmp_path)], start_new_session=True)
    try:
        pids = [tmp_path / 'ws' / f'{name}.pid' for name in ('a.sh', 'b.sh')]
        assert wait_until(lambda: all(p.exists() and p.read_text().strip() for p in pids), 10.0)
        scripts = RunningScripts(launch.pid, str(tmp_path / 'ws'))
        assert len(scripts.pids) == 2 and scripts.running()
        a, b = (int(p.read_text()) for p in pids)
        assert scripts.owner(f'/rostopic_{a}_1796576956448') == 'a.sh'
        assert scripts.owner(f'/rostopic_{b}_1796576956449') == 'b.sh'
        assert scripts.owner('/n_controller') == '/n_controller'
        assert scripts.owner(f'/rostopic_{launch.pid}_1') == f'/rostopic_{launch.pid}_1'
    finally:
        os.killpg(launch.pid, 9)
        launch.wait()


def test_a_node_waiting_for_a_line_on_its_terminal_is_seen_until_it_has_one():
    """Started as roslaunch starts nodes (`__name:=`), on a terminal: a node
    at a prompt (input()) is seen to read its standard input; one that
    sleeps with a thread at its prompt too; not once it has its line and
    sleeps."""
    master, slave = pty.openpty()
    asks = ('import threading, time\n'
            'if "--thread" in __import__("sys").argv:\n'
            '    threading.Thread(target=input, daemon=True).start()\n'
            'else:\n'
            '    input("a letter (A, B): ")\n'
            'time.sleep(60)\n')
    nodes = [subprocess.Popen([sys.executable, '-c', asks, *more, '__name:=asker'],
                              stdin=slave, stdout=slave, stderr=slave, start_new_session=True)
             for more in ([], ['--thread'])]
    os.close(slave)
    try:
        for node in nodes:
            assert wait_until(lambda: reading_input(node.pid), 10.0), 'its prompt waits'
        os.write(master, b'A\r')        # read by one of the two
        assert wait_until(lambda: sum(reading_input(n.pid) for n in nodes) == 1, 10.0)
        os.write(master, b'B\r')
        assert wait_until(lambda: not any(reading_input(n.pid) for n in nodes), 10.0), 'they sleep'
    finally:
        for node in nodes:
            node.kill()
            node.wait()
        os.close(master)


def test_a_process_reading_its_input_that_roslaunch_did_not_start_as_a_node_is_none():
    master, slave = pty.openpty()
    plain = subprocess.Popen([sys.executable, '-c', 'input()'], stdin=slave, stdout=slave,
                             start_new_session=True)
    os.close(slave)
    try:
        time.sleep(1.0)
        assert plain.poll() is None and not reading_input(plain.pid)
    finally:
        plain.kill()
        plain.wait()
        os.close(master)
