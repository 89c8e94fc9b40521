"""An instructor stops a class's grading: Ctrl-C from the terminal (SIGINT
to its process group), or SIGTERM to the grader alone. Grading stops at
once, every sandbox is ended, the class files are written for the students
graded so far and say who was not, and nothing is left. Root only."""
import csv
import os
import shutil
import signal
import subprocess
import time
import xml.etree.ElementTree as ElementTree

import pytest

from support.grading import grade_class, leftovers, sandbox_processes, started_grading

HERE = os.path.dirname(os.path.abspath(__file__))
LENA = os.path.join(HERE, 'submissions', 'c03_lena')
RUBRIC = os.path.join(HERE, 'rubric.yaml')
STOPS_WITHIN = 30.0     # s from the signal to the grader's exit (it takes well under 1 s idle)
pytestmark = pytest.mark.skipif(os.geteuid() != 0, reason='grading makes network namespaces: '
                                                          'root only')


def a_class(top, size):
    """`size` copies of Lena's L and their roster; the grading's arguments."""
    for n in range(1, size + 1):
        shutil.copytree(LENA, str(top / 'class' / f's{n}'))
    (top / 'roster.csv').write_text('id,name,letter\n' + ''.join(
        f's{n},Lena Ortiz,L\n' for n in range(1, size + 1)))
    return [str(top / 'class'), '--roster', str(top / 'roster.csv'), '--rubric', RUBRIC,
            '--out', str(top / 'out'), '--jobs', '2']


def namespaces_listed():
    return subprocess.run(['ip', 'netns', 'list'], stdout=subprocess.PIPE,
                          universal_newlines=True).stdout


def sandbox_running():
    return 'tlgrade' in namespaces_listed()


def stop(grading, how):
    """Sends `how`; (the grader's exit code, s it took to exit, what it printed)."""
    how()
    sent = time.monotonic()
    try:
        printed, _ = grading.communicate(timeout=120)
    finally:
        if grading.poll() is None:
            os.killpg(grading.pid, signal.SIGKILL)
            grading.wait()  # reaped: a zombie's pid is a grader still running to the next one
    return grading.returncode, time.monotonic() - sent, printed


def rows_of(out):
    with open(out / 'grades.csv') as f:
        return [(row['id'], row['verdict']) for row in csv.DictReader(f)]


def test_ctrl_c_keeps_the_students_graded_and_leaves_nothing(tmp_path):
    before = sandbox_processes()
    grading = started_grading(*a_class(tmp_path, 4))
    first = ''
    while 'PASS' not in first and grading.poll() is None:     # one student is done
        first = grading.stdout.readline()
    deadline = time.monotonic() + 60
    while not sandbox_running() and time.monotonic() < deadline:     # the next one runs
        time.sleep(0.2)
    code, took, printed = stop(grading, lambda: os.killpg(grading.pid, signal.SIGINT))
    assert code == 130, first + printed
    assert took < STOPS_WITHIN, took
    rows = rows_of(tmp_path / 'out')
    assert [sid for sid, _ in rows] == ['s1', 's2', 's3', 's4']
    graded = [sid for sid, verdict in rows if verdict == 'pass']
    assert 's1' in graded and len(graded) < 4, rows
    assert all(verdict in ('pass', 'not graded') for _, verdict in rows), \
        (tmp_path / 'out' / 'grades.csv').read_text()      # a failure's reason too
    for sid, verdict in rows:       # no made-up failure for the ones it stopped
        assert os.path.exists(tmp_path / 'out' / sid / 'results.json') == (verdict == 'pass')
    suite = ElementTree.parse(str(tmp_path / 'out' / 'junit.xml')).getroot()
    assert suite.get('skipped') == str(4 - len(graded)) and suite.get('failures') == '0'
    assert 'INCOMPLETE, stopped by SIGINT' in (tmp_path / 'out' / 'report.html').read_text()
    assert 'incomplete' in printed
    assert leftovers(before) == ([], [])


def test_sigterm_to_the_grader_alone_does_the_same(tmp_path):
    before = sandbox_processes()
    grading = started_grading(*a_class(tmp_path, 2))
    deadline = time.monotonic() + 60
    while not sandbox_running() and time.monotonic() < deadline:
        time.sleep(0.2)
    time.sleep(2)       # into the build
    code, took, printed = stop(grading, lambda: os.kill(grading.pid, signal.SIGTERM))
    assert (code, rows_of(tmp_path / 'out')) == \
        (143, [('s1', 'not graded'), ('s2', 'not graded')]), printed
    assert took < STOPS_WITHIN, took
    assert leftovers(before) == ([], [])


def test_in_a_terminal_a_bar_shows_the_class_going_and_ctrl_c_stops_it(tmp_path):
    """As an instructor sees it in a real terminal (tmux): a bar with the
    students done, the one being graded and the time left, each row above
    it as it comes; Ctrl-C typed stops it, with the terminal left sane."""
    from support.terminal import Terminal
    before = sandbox_processes()
    args = ' '.join(a_class(tmp_path, 3)).replace('--jobs 2', '--jobs 1')
    terminal = Terminal(f'stty -g > before; rosrun turtle_letters grade_class.py {args}; '
                        f'echo "exit $?" > code; stty -g > after; echo "SETTINGS" "SAVED"',
                        cwd=True)
    try:
        assert terminal.wait_for('0/3 students', 60), terminal.screen()
        assert terminal.wait_for('grading s1', 30), terminal.screen()
        assert terminal.wait_for('1/3 students', 120), terminal.screen()
        screen = terminal.screen()
        assert 's1 Lena Ortiz: drew L, expected L: 100/100 PASS' in screen, screen
        assert '<' in screen.split('1/3 students')[1].split('\n')[0]      # [elapsed<left]
        terminal.send_keys('C-c')
        assert terminal.wait_for('SIGINT: stopping', 30), terminal.screen()
        # the echo comes after stty has written: the file alone exists, empty,
        # from the moment the shell opens it (an empty read failed CI once)
        assert terminal.wait_for('SETTINGS SAVED', STOPS_WITHIN), terminal.screen()
        assert terminal.read('code') == 'exit 130', terminal.screen()
        assert terminal.read('after') == terminal.read('before')
    finally:
        terminal.close()
    assert rows_of(tmp_path / 'out')[0] == ('s1', 'pass')
    assert leftovers(before) == ([], [])


def ctrl_c_twice_once_a_sandbox_runs(grading, poll, then):
    """Wait (looking every `poll` s) for a sandbox, `then` s more, and press
    Ctrl-C twice; what stop() returns."""
    deadline = time.monotonic() + 60
    while not sandbox_running() and time.monotonic() < deadline:
        time.sleep(poll)
    time.sleep(then)

    def twice():
        os.killpg(grading.pid, signal.SIGINT)
        time.sleep(0.02)
        os.killpg(grading.pid, signal.SIGINT)
    return stop(grading, twice)


def test_a_second_ctrl_c_forces_it_out_and_still_leaves_nothing(tmp_path):
    before = sandbox_processes()
    grading = started_grading(*a_class(tmp_path, 2))
    code, took, printed = ctrl_c_twice_once_a_sandbox_runs(grading, poll=0.2, then=2)
    assert code == 130 and took < STOPS_WITHIN, printed
    assert 'forced' in printed and 'Traceback' not in printed, printed
    assert leftovers(before) == ([], [])


def test_two_ctrl_c_as_it_starts_leave_nothing(tmp_path):
    """At the first namespace it makes (its trial of the sandbox, or the
    first student's), two Ctrl-C: out in words, nothing left."""
    before = sandbox_processes()
    grading = started_grading(*a_class(tmp_path, 1))
    code, took, printed = ctrl_c_twice_once_a_sandbox_runs(grading, poll=0.01, then=0)
    assert code == 130 and took < STOPS_WITHIN, printed
    assert 'SIGINT' in printed and 'Traceback' not in printed, printed
    assert leftovers(before) == ([], [])


def test_a_grader_killed_outright_leaves_what_the_next_one_removes(tmp_path):
    """SIGKILL (or a lost session, a stopped machine) leaves the grader no
    time to clean up: its sandbox's namespace, cgroups and folders stay,
    named by its pid, until the next grader removes them and says so."""
    from turtle_letters.isolation.stale import left_behind
    before = sandbox_processes()
    killed = started_grading(*a_class(tmp_path / 'killed', 1))
    deadline = time.monotonic() + 60
    while f'tlgrade{killed.pid}n' not in namespaces_listed() and \
            time.monotonic() < deadline:
        time.sleep(0.2)
    time.sleep(2)       # into the build
    os.killpg(killed.pid, signal.SIGKILL)
    killed.wait()
    left = left_behind()    # its own: it removed any earlier grader's as it started
    assert all(left) and all(str(killed.pid) in name for name in sum(left, [])), left
    again = grade_class(*a_class(tmp_path / 'again', 1))
    said = [line for line in again.stdout.splitlines() if 'graders no longer running' in line]
    assert said == [f'grade_class.py: removed what graders no longer running left '
                    f'(pid {killed.pid}): {len(left[0])} network namespaces, '
                    f'{len(left[1])} cgroups, {len(left[2])} folders'], again.stdout
    assert rows_of(tmp_path / 'again' / 'out') == [('s1', 'pass')], again.stdout
    assert left_behind() == ([], [], []) and leftovers(before) == ([], [])

