"""The grader's own world fails under a student's run: its simulator is
killed from outside, as the machine might (the submission, another user,
cannot). The student is run again in a fresh world and loses nothing; the
launch line says what happened. Root only, as grading is."""
import csv
import json
import os
import signal
import threading
import time

import pytest

from support.grading import leftovers, sandbox_processes, started_grading

HERE = os.path.dirname(os.path.abspath(__file__))
LENA = os.path.join(HERE, 'submissions', 'c03_lena')
RUBRIC = os.path.join(HERE, 'rubric.yaml')
pytestmark = pytest.mark.skipif(os.geteuid() != 0, reason='grading makes network namespaces: '
                                                          'root only')


def the_simulator_killed_once(before, killed, grading):
    """Once the submission's roslaunch runs beside the grader's simulator,
    SIGKILL to that simulator; its pid put in `killed`."""
    while grading.poll() is None:
        running = {pid: line for pid, line in sandbox_processes().items() if pid not in before}
        simulators = [pid for pid, line in running.items()
                      if line.startswith('/usr/bin/python3') and 'turtlesim_node' in line]
        if simulators and any('roslaunch' in line for line in running.values()):
            time.sleep(1.0)         # into the run
            os.kill(simulators[0], signal.SIGKILL)
            killed.append(simulators[0])
            return
        time.sleep(0.1)


def test_a_simulator_killed_under_a_run_costs_the_student_nothing(tmp_path):
    before = sandbox_processes()
    grading = started_grading('--one', LENA, '--letter', 'L', '--rubric', RUBRIC,
                              '--out', str(tmp_path / 'out'))
    killed = []
    killer = threading.Thread(target=the_simulator_killed_once, args=(before, killed, grading))
    killer.start()
    try:
        printed, _ = grading.communicate(timeout=900)
    finally:
        if grading.poll() is None:
            os.killpg(grading.pid, signal.SIGKILL)
        killer.join()
    assert grading.returncode == 0 and killed, printed
    with open(tmp_path / 'out' / 'grades.csv') as f:
        row = next(csv.DictReader(f))
    assert (row['drawn'], row['verdict'], row['score']) == ('L', 'pass', '100'), row
    written = json.loads((tmp_path / 'out' / 'c03_lena' / 'results.json').read_text())
    launches = next(t for t in written['tests'] if t['name'] == 'It launches')
    assert launches['score'] == launches['max_score'], launches
    assert launches['output'].endswith(
        "; the grader's simulator ended (exit 137) in the first run, not by the submission's "
        "doing: the grader ran it again in a fresh world"), launches
    log = (tmp_path / 'out' / 'c03_lena' / 'log.txt').read_text()
    assert "the grader's own failure" in log and log.count('roslaunch ') >= 2, log
    assert leftovers(before) == ([], [])
