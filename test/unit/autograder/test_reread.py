"""A class's drawings read again from what the grader kept (grade_class.py
--reread): the ink kept exactly, read as the grader read it, and the criterion that
reads differently now shown beside what it said. The readers are real."""
import json
import math
import os

from turtle_letters.autograder import cli, driver, reports, rubric as rubrics
from turtle_letters.autograder.observations import Drawing
from turtle_letters.autograder.session import Step

from support.cadet_paths import driven
from support.glyph_rows import row

HERE = os.path.dirname(__file__)
RUBRIC = rubrics.load(os.path.join(HERE, '..', '..', '..', 'config', 'rubric.yaml'))
OK = Step(True, 'fine')


def graded(out, student_id, drawing, expected):
    """The student's folder in `out` as the grader writes it, and their letter line."""
    facts = rubrics.Facts.of_drawing(expected, drawing, *driver.read(drawing, expected))._replace(
        build=OK, launch=OK, waited=OK, talker=OK)
    grade = rubrics.grade(facts, RUBRIC)
    row = reports.Row(student_id, student_id, expected, rubrics.drawn_text(facts), grade, 1.0,
                      [], None)
    reports.write_student(str(out), row, facts, [('roslaunch', 'ran')])
    return os.path.join(str(out), student_id), rubrics.letter_line(facts)


def n_driven():
    """The lab's N as a turtle lays it in 16 ms steps: floats no decimal writes short."""
    return driven([(0, 0.25, 2 * math.pi), (1, 0, 3), (0, 0.25, 5 * math.pi), (1, 0, 3.5),
                   (0, 0.25, 3 * math.pi), (1, 0, 3)], 3.0, 2.0)


def test_the_ink_kept_is_the_ink_read_every_float_exactly(tmp_path):
    drawing = Drawing([n_driven()], 1.0, 22.0, 420, [], looks=[(255, 255, 255, 3)],
                      wiped=[(2.5, 'clear')], turtles=['turtle1'])
    folder, line = graded(tmp_path, 's1', drawing, 'N')
    expected, kept = reports.read_ink(folder)
    assert expected == 'N' and kept.strokes == [[list(p) for p in drawing.strokes[0]]]
    assert [tuple(p) for p in kept.strokes[0]] == drawing.strokes[0]
    assert kept.commands == 420 and kept.wiped == [[2.5, 'clear']]
    assert driver.reread(folder) == (line, line) and line.startswith('drew N, as expected')


def test_a_drawing_without_ink_keeps_no_file(tmp_path):
    folder, _ = graded(tmp_path, 's2', Drawing([], 1.0, 5.0, 0, []), 'F')
    assert os.path.exists(os.path.join(folder, 'results.json'))
    assert not os.path.exists(os.path.join(folder, reports.INK_FILE))


def test_reread_says_each_student_and_which_read_differently(tmp_path, capsys):
    """Two students graded: Kofi's kept row and line stand; Maria's
    results.json is another drawing's, as a row graded by an older reader
    is: her criterion is shown now and as it was."""
    touching = Drawing(row('MF', gap=0.0), 1.0, 30.0, 600, [])
    _, line = graded(tmp_path, 'kofi', touching, 'MF')
    maria, _ = graded(tmp_path, 'maria', Drawing([n_driven()], 1.0, 22.0, 420, []), 'M')
    other, was = graded(tmp_path / 'other', 'maria', touching, 'M')
    os.replace(os.path.join(other, 'results.json'), os.path.join(maria, 'results.json'))
    assert cli.main(['--reread', str(tmp_path)]) == 0
    said = capsys.readouterr().out.splitlines()
    assert said[0] == f'kofi: as graded: {line}'
    assert said[1].startswith('maria: now: drew N, expected M')
    assert said[2] == f'       was: {was}' and was != said[1]
    assert said[3] == '2 drawings read again, 1 read differently now'


def test_a_folder_that_kept_no_drawing_is_refused_with_exit_2(tmp_path, capsys):
    (tmp_path / 'empty').mkdir()
    with open(tmp_path / 'empty' / 'results.json', 'w') as f:
        json.dump({}, f)
    for out in (tmp_path, tmp_path / 'missing'):
        assert cli.main(['--reread', str(out)]) == 2
        assert f'no drawing kept in {out}' in capsys.readouterr().err


def test_a_kept_file_cut_short_is_said_and_the_others_are_read(tmp_path, capsys):
    folder, line = graded(tmp_path, 'lena', Drawing([n_driven()], 1.0, 22.0, 420, []), 'N')
    cut, _ = graded(tmp_path, 'omar', Drawing([n_driven()], 1.0, 22.0, 420, []), 'O')
    with open(os.path.join(cut, reports.INK_FILE), 'r+') as f:
        f.truncate(100)
    assert cli.main(['--reread', str(tmp_path)]) == 1
    said = capsys.readouterr().out.splitlines()
    assert said[0] == f'lena: as graded: {line}'
    assert said[1].startswith('omar: not read again: ink.json is no drawing the grader kept '
                              '(JSONDecodeError: ')
    assert said[2] == '1 drawing read again, 0 read differently now; 1 not read (above)'
