"""The grader's own failure on one submission is that student's row, with
its cause in one line and its traceback in their log.txt, never the end
of the class. No submission known today makes the grader fail (each odd
one has its own row: test/class/test_odd_class.py), so the failure is
stood in for: the RecursionError a tree 1,100 deep once raised."""
import os
import signal
import subprocess
import threading
import time

import pytest

from turtle_letters.autograder import cli, driver, rubric as rubrics
from turtle_letters.autograder.roster import Student

HERE = os.path.dirname(__file__)
RUBRIC = os.path.join(HERE, '..', '..', '..', 'config', 'rubric.yaml')


def ann_and_bob(tmp_path):
    """(rows, stopped) of a class of two who handed in nothing, graded into tmp_path/out."""
    args = cli.arguments([str(tmp_path), '--roster', 'r.csv', '--out', str(tmp_path / 'out'),
                          '--no-sandbox'])
    students = [Student('a1', 'Ann', 'A', None), Student('b2', 'Bob', 'B', None)]
    return cli.grade_all(students, rubrics.load(RUBRIC), str(tmp_path / 'out'), [], args)


def test_the_graders_own_failure_on_a_submission_is_its_row_only(tmp_path, monkeypatch):
    def fails(folder):
        raise RecursionError('maximum recursion depth exceeded')
    monkeypatch.setattr(driver.submission, 'find', fails)
    place = cli.Place([], isolated=False, jobs=1, caps=None)
    student = Student('a\x1b[2J1', 'Ann', 'A', str(tmp_path))
    row, _ = driver.grade(student, rubrics.load(RUBRIC), str(tmp_path / 'out'), place)
    assert (row.grade.verdict, row.grade.score) == ('fail', 0)
    assert row.grade.reason == ('It builds: not tried: the grader failed on this submission: '
                                'RecursionError: maximum recursion depth exceeded')
    log = (tmp_path / 'out' / 'a%1B%5B2J1' / 'log.txt').read_text()
    assert "==== the grader's own error" in log and 'in fails' in log
    assert cli.said(row, True).startswith('a [2J1 Ann: drew no letter')


def test_once_stopped_no_student_is_begun(tmp_path):
    place = cli.Place([], isolated=False, jobs=1, caps=None)
    place.stopping.set()
    with pytest.raises(driver.Stopped):
        driver.grade(Student('a1', 'Ann', 'A', None), rubrics.load(RUBRIC),
                          str(tmp_path / 'out'), place)
    assert not os.path.exists(tmp_path / 'out')


def test_a_helper_that_died_of_the_ctrl_c_stopping_the_class_is_no_failure_of_the_student(
        tmp_path, monkeypatch):
    """Ctrl-C reaches the grader's process group: a mount it was starting for
    a sandbox, not yet in a session of its own, died of it (as CI saw: s4
    "fail: CalledProcessError ... mount ... died with SIGINT"). The grader
    notes the stop a moment later; the student is not graded, not failed."""
    def mount_died(folder):
        raise subprocess.CalledProcessError(-signal.SIGINT, ['mount', '-t', 'tmpfs'])
    monkeypatch.setattr(driver.submission, 'find', mount_died)
    place = cli.Place([], isolated=False, jobs=1, caps=None)
    noted = threading.Timer(0.3, place.stop)      # the main thread looks each 0.2 s
    noted.start()
    try:
        with pytest.raises(driver.Stopped):
            driver.grade(Student('a1', 'Ann', 'A', str(tmp_path)), rubrics.load(RUBRIC),
                         str(tmp_path / 'out'), place)
    finally:
        noted.join()
    assert not os.path.exists(tmp_path / 'out' / 'a1')


def test_a_failure_even_in_writing_a_students_files_is_their_row_and_the_class_goes_on(
        tmp_path, monkeypatch):
    def full(*_):
        raise OSError(28, 'No space left on device')
    before = signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)
    monkeypatch.setattr(driver.reports, 'write_results', full)
    rows, stopped = ann_and_bob(tmp_path)
    assert stopped == '' and [r.id for r in rows] == ['a1', 'b2']
    assert rows[0].grade.reason == ('It builds: not tried: the grader failed on this '
                                    'submission: OSError: [Errno 28] No space left on device')
    # both as they were: Ctrl-C ignored under nohup, SIGTERM not made so too
    assert (signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)) == before


def test_a_ctrl_c_while_a_picture_is_painted_keeps_its_row_once(tmp_path, monkeypatch, capsys):
    """A picture is painted in its student's thread, which no signal
    interrupts: the stop waits for it, then stops the class; the row painted
    is kept, and printed once."""
    painted = []

    def paint_and_press_ctrl_c(out, student_id, facts):
        painted.append(student_id)
        if len(painted) == 1:
            os.kill(os.getpid(), signal.SIGINT)     # lands mid-paint, as a key press would
            time.sleep(0.5)                         # the main thread takes it meanwhile
        painted.append('done')
        return 'drawing.png'
    monkeypatch.setattr(driver.reports, 'picture', paint_and_press_ctrl_c)
    rows, stopped = ann_and_bob(tmp_path)
    assert stopped == 'SIGINT' and painted == ['a1', 'done'] and [r.id for r in rows] == ['a1']
    assert rows[0].picture == 'drawing.png'
    assert capsys.readouterr().out.count('a1 Ann:') == 1


def test_each_row_is_written_as_it_is_graded(tmp_path, monkeypatch):
    """grades.csv holds every row finished so far, rewritten after each: a
    grader killed outright (the machine out of memory) keeps what it graded."""
    written = []
    real = cli.reports.write_csv
    monkeypatch.setattr(cli.reports, 'write_csv',
                        lambda path, rows: (written.append([r.id for r in rows]),
                                            real(path, rows)))
    ann_and_bob(tmp_path)
    assert written == [['a1'], ['a1', 'b2']]
    assert (tmp_path / 'out' / 'grades.csv').read_text().count('\n') == 3


def test_the_students_likely_longest_are_graded_first_each_part_in_roster_order(tmp_path):
    """Who starts several scripts together (run again each alone: a class's
    longest rows) goes first, so that such a row is not left for the end
    while the other jobs stand idle; a folder that cannot be read so, or
    none, keeps its place among the rest."""
    def package(name, scripts):
        folder = tmp_path / name
        folder.mkdir()
        (folder / 'package.xml').write_text(f'<package format="2"><name>{name}</name></package>')
        for script in scripts:
            (folder / script).write_text('#!/bin/bash\nrosservice call /clear\n')
        return str(folder)
    students = [Student('a1', 'Ann', 'A', package('ann', ['a.sh'])),
                Student('b2', 'Bob', 'B', package('bob', ['b.sh', 'b2.sh'])),
                Student('c3', 'Cy', 'C', None),
                Student('d4', 'Di', 'D', str(tmp_path / 'gone')),
                Student('e5', 'Ed', 'E', package('ed', ['e.sh', 'e2.sh', 'e3.sh']))]
    assert cli.grading_order(students) == [1, 4, 0, 2, 3]


def test_the_class_files_keep_roster_order_when_a_later_student_finished_first():
    """Two at a time, the third student may finish before the second, who
    is then stopped: the second's 'not graded' row stays in its place."""
    students = [Student(sid, name, 'A', None) for sid, name in
                (('a1', 'Ann'), ('b2', 'Bob'), ('c3', 'Cy'))]
    done = [cli.reports.not_graded(sid, name, 'A', 'stands in for a graded row')
            for sid, name in (('a1', 'Ann'), ('c3', 'Cy'))]
    rows = cli.with_ungraded(done, students, 'SIGINT')
    assert [r.id for r in rows] == ['a1', 'b2', 'c3']
    assert rows[1].grade.reason == 'grading was stopped (SIGINT) before this student was graded'
    assert rows[2] is done[1]


def test_the_graders_thread_keeps_to_its_students_core_while_it_grades_them():
    """Each student's grading thread (the reading, seconds of a core, and
    Tesseract's) is held to its slot's core, the one the student's world
    and nodes are pinned to: it never takes the core of the student graded
    beside, whose timed drawing runs meanwhile. The thread's cores are its
    own again after; the main thread's are never changed."""
    place = cli.Place([], isolated=False, jobs=2, caps=None)
    cores, seen = os.sched_getaffinity(0), {}
    both_in = threading.Barrier(2)

    def grading(name):
        with place.sandbox() as box:
            both_in.wait(timeout=10)
            seen[name] = (set(box.cpus), os.sched_getaffinity(0))
        seen[name + ' after'] = os.sched_getaffinity(0)
    threads = [threading.Thread(target=grading, args=(name,)) for name in 'ab']
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert seen['a'][0] == seen['a'][1] and seen['b'][0] == seen['b'][1]
    assert seen['a'][1] != seen['b'][1] or len(cores) == 1
    assert seen['a after'] == seen['b after'] == cores == os.sched_getaffinity(0)
