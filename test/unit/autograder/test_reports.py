"""What the grader hands back: Gradescope's results.json, the CSV, junit
and the report page, each from the same rows."""
import csv
import json
import xml.etree.ElementTree as ElementTree

from turtle_letters.autograder import reports
from turtle_letters.autograder.observations import Drawing
from turtle_letters.autograder.rubric import Facts, Grade, Mark
from turtle_letters.reading.ocr import read_text
from turtle_letters.reading.rows import read_row

PASSED = Grade([Mark('It builds', 10, 10, 'built'), Mark('Its accuracy', 15, 20, '7% off')],
               25, 30, 'pass', 'Its accuracy: 7% off')
FAILED = Grade([Mark('It builds', 0, 10, 'catkin_make failed: <x> & "y"')], 0, 10, 'fail',
               'It builds: catkin_make failed: <x> & "y"')
ROWS = [reports.Row('a/1', 'Ann', 'A', 'A', PASSED, 12.0, [('drawing time (s)', 9.5, 'asc')],
                    'a%2F1/drawing.png'),
        reports.Row('b2', 'Bob <b>', 'B', '', FAILED, 3.0, [], None, 'not on the roster')]


def test_results_json_is_gradescopes_format():
    data = reports.results_json(ROWS[0])
    assert data['score'] == 25 and data['execution_time'] == 12.0
    assert [(t['name'], t['status']) for t in data['tests']] == [
        ('It builds', 'passed'), ('Its accuracy', 'failed')]
    assert data['leaderboard'] == [dict(name='drawing time (s)', value=9.5, order='asc')]
    assert data['output'].startswith('PASS: 25/30.')


def test_csv_junit_and_page_hold_every_row(tmp_path):
    reports.write_csv(str(tmp_path / 'grades.csv'), ROWS)
    reports.write_junit(str(tmp_path / 'junit.xml'), ROWS)
    reports.write_html(str(tmp_path / 'report.html'), ROWS, 'class')
    with open(tmp_path / 'grades.csv') as f:
        rows = list(csv.reader(f))
    assert rows[0] == reports.CSV_COLUMNS
    assert rows[2] == ['b2', 'Bob <b>', 'B', '', '0', '10', 'fail',
                       'It builds: catkin_make failed: <x> & "y"']
    suite = ElementTree.parse(str(tmp_path / 'junit.xml')).getroot()
    assert suite.get('tests') == '2' and suite.get('failures') == '1'
    assert suite.findall('testcase')[1].find('failure').get('message') == FAILED.reason
    page = (tmp_path / 'report.html').read_text()
    assert 'Bob &lt;b&gt;' in page and '<b>' not in page.replace('<body>', '')
    assert 'src="a%252F1/drawing.png"' in page and 'No drawing.' in page


def test_long_output_keeps_its_start_and_end_without_terminal_codes():
    text = '\x1b[31mERROR\x1b[0m\r\n' + '\n'.join(f'line {i}' for i in range(500))
    lines = reports.trimmed(text)
    assert lines[0] == 'ERROR' and lines[-1] == 'line 499'
    assert any('lines left out' in line for line in lines)
    assert len(lines) == reports.HEAD + reports.TAIL + 1


def test_what_a_submission_names_or_prints_is_shown_plain_in_every_file(tmp_path):
    """An id from a non-UTF-8 folder name (as a zip of "Müller" makes it) and
    a reason with terminal codes and a form feed: every file still parses,
    with neither in it; a student grading stopped before has a row that says so."""
    odd = reports.Row('M\udcfcller', 'Ann\x1b[2J', 'A', '', FAILED._replace(
        reason='It builds: \x1b]0;owned\x07\x0cboom'), 1.0, [], None, 'left out \x1b[31mx')
    stopped = reports.not_graded('c3', 'Cy', 'C', 'grading was stopped (SIGINT)')
    reports.write_csv(str(tmp_path / 'grades.csv'), [odd, stopped])
    reports.write_junit(str(tmp_path / 'junit.xml'), [odd, stopped])
    reports.write_html(str(tmp_path / 'report.html'), [odd, stopped], 'class')
    for name in ('grades.csv', 'junit.xml', 'report.html'):
        text = (tmp_path / name).read_text(encoding='utf-8')
        assert not any(c in text for c in '\x1b\x07\x0c'), name
    with open(tmp_path / 'grades.csv') as f:
        rows = list(csv.reader(f))
    assert rows[1][:2] == ['M\ufffdller', 'Ann [2J']
    assert rows[2] == ['c3', 'Cy', 'C', '', '', '', 'not graded', 'grading was stopped (SIGINT)']
    suite = ElementTree.parse(str(tmp_path / 'junit.xml')).getroot()
    assert (suite.get('failures'), suite.get('skipped')) == ('1', '1')
    assert suite.findall('testcase')[1].find('skipped') is not None
    assert reports.folder(str(tmp_path), odd.id).endswith('/M%FCller')


def test_each_line_of_a_log_is_shown_plain_and_capped():
    lines = reports.trimmed('a\x07b\x00c\n' + 'y' * 5000)
    assert lines == ['a b c', 'y' * (reports.LOG_LINE - 1) + '\u2026']



def test_the_caption_names_no_letter_only_where_ocr_credits_none():
    """OCR asked, and crediting nothing (a bolt of lightning for an H): the
    caption says none was credited, and no letter is named only (it said
    so wherever OCR had been asked)."""
    bolt = [[(1.0, 1.0), (6.0, 6.0), (9.0, 9.0)], [(4.5, 4.5), (8.0, 4.5), (0.5, 0.3)]]
    facts = Facts('H', drawing=Drawing(bolt, 1.0, 20.0, 900, []),
                  readings=read_row(bolt, 'H'), ocr=read_text(bolt, 'H'))
    assert facts.ocr is not None and reports.overlay(facts) == []
    said = reports.caption('hanie', facts)
    assert 'credited: none' in said and 'named only' not in said


def test_a_letter_read_only_loosely_as_another_is_shown_as_the_nearest_not_as_read():
    """An L whose foot droops 0.3 m, 9% of its height off its nearest L,
    graded against K: the row says no letter reads cleanly and L lies
    nearest, and so do the picture's caption and the L's label (the
    caption said its strokes read L). Within CLEAN, the L is read."""
    drooping = [[(1.0, 3.0), (1.0, 1.0), (2.2, 0.7)]]
    loose = Facts('K', drawing=Drawing(drooping, 1.0, 5.0, 200, []),
                  readings=read_row(drooping, 'K'))
    assert 'its strokes read no letter cleanly (L the nearest)' in reports.caption('ka', loose)
    assert [label for label, _ in reports.overlay(loose)] == ['L nearest: not expected']
    clean = [[(1.0, 3.0), (1.0, 1.0), (2.2, 0.9)]]
    read = Facts('K', drawing=Drawing(clean, 1.0, 5.0, 200, []), readings=read_row(clean, 'K'))
    assert 'its strokes read L\n' in reports.caption('ka', read)
    assert [label for label, _ in reports.overlay(read)] == ['L: not expected']


def test_the_caption_says_teleports_laid_ink_shown_on_the_canvas_only():
    """A class's M laid by pen-down teleports, the dot of its i driven: the
    canvas shows the M as turtlesim did, and the caption says why the ink
    enlarged, the driven ink read, lacks it."""
    dot = [[(4.08, 2.5), (4.0, 2.58), (3.92, 2.5), (4.0, 2.42), (4.08, 2.5)]]
    m = [[(1.0, 1.0), (1.0, 3.0), (2.0, 1.0), (3.0, 3.0), (3.0, 1.0)]]
    jumped = Drawing(dot, 1.0, 9.0, 9, [], 5, 5, teleported=m, teleported_looks=[()])
    said = reports.caption('mi', Facts('MI', drawing=jumped, readings=read_row(dot, 'MI')))
    plain = reports.caption('mi', Facts('MI', drawing=jumped._replace(teleported=[]),
                                        readings=read_row(dot, 'MI')))
    assert 'turtlesim showed it (teleports laid ink too)' in said and 'the driven ink' in said
    assert 'teleports' not in plain and 'driven' not in plain


def test_the_caption_says_ink_from_before_the_drawing_is_shown_on_the_canvas_only():
    """A real class's script drove a metre before asking at a prompt for
    its letter: the canvas shows the metre too, the ink enlarged is the
    drawing's."""
    ell = [[(2.0, 5.0), (2.0, 2.0), (3.5, 2.0)]]
    metre = [[(5.5, 5.5), (6.5, 5.5)]]
    before = Drawing(ell, 1.0, 9.0, 9, [], earlier=metre, earlier_looks=[()])
    said = reports.caption('harf', Facts('L', drawing=before, readings=read_row(ell, 'L')))
    plain = reports.caption('harf', Facts('L', drawing=before._replace(earlier=[]),
                                          readings=read_row(ell, 'L')))
    assert 'turtlesim showed it (ink from before the drawing too)' in said
    assert 'the ink of the drawing enlarged' in said
    assert 'before' not in plain and 'of the drawing' not in plain
    both = reports.caption('harf', Facts('L', drawing=before._replace(teleported=metre),
                                         readings=read_row(ell, 'L')))
    assert '(teleports laid ink and ink from before the drawing too)' in both
