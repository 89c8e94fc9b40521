"""What the grader hands back: per student, OUT/ID/results.json (Gradescope's
format), drawing.png, log.txt and ink.json (the drawing, to read again:
driver.reread); per class, grades.csv, junit.xml and
report.html, a page that opens from disk. No ROS here."""
import csv
import html
import json
import os
import re
import urllib.parse
import xml.etree.ElementTree as ElementTree
from typing import List, NamedTuple, Optional

from ..isolation.files import safe_name, shown
from ..reading.ocr import said as ocr_said
from .observations import Drawing
from .rubric import Grade, credited, credited_as_small_l, drawn, nearest_only

NOT_GRADED = 'not graded'
CSV_COLUMNS = ['id', 'name', 'expected', 'drawn', 'score', 'max_score', 'verdict', 'reason']
HEAD, TAIL = 15, 60          # lines kept of a step's output at its start and its end
LOG_LINE = 1000              # characters kept of one line of log.txt
RESULTS_FILE = 'results.json'  # OUT/ID/: the row, in Gradescope's format
INK_FILE = 'ink.json'        # OUT/ID/: the drawing the letters were read from
TERMINAL_CODES = re.compile(r'\x1b\[[0-9;?]*[A-Za-z]|\x1b\][^\x07]*\x07|\r')


class Row(NamedTuple):
    id: str
    name: str
    expected: str
    drawn: str
    grade: Grade
    seconds: float                  # the whole grading of this student
    leaderboard: List[tuple]        # (name, value, order)
    picture: Optional[str]          # drawing.png's path relative to OUT, if drawn
    warning: str = ''

    def csv(self):
        """Its cells, each a line safe to show (an id from a folder's name is the user's text)."""
        g = self.grade
        score = ['', ''] if g.score is None else [f'{g.score:g}', f'{g.max_score:g}']
        return [shown(self.id), shown(self.name), self.expected, self.drawn, *score, g.verdict,
                shown(g.reason)]


def not_graded(sid, name, expected, why):
    """The row of a student grading stopped before: no score, verdict 'not graded'."""
    return Row(sid, name, expected, '', Grade([], None, None, NOT_GRADED, why), 0.0, [], None)


def points(grade):
    """'score/max', or '' for a student not graded."""
    return '' if grade.score is None else f'{grade.score:g}/{grade.max_score:g}'


def folder(out, student_id):
    return os.path.join(out, safe_name(student_id))


def plain(text):
    """Text a terminal showed, without its colour and title codes."""
    return TERMINAL_CODES.sub('', text)


def trimmed(text):
    """A step's output without terminal codes, its start and end kept, each line safe to show."""
    lines = plain(text).splitlines()
    if len(lines) > HEAD + TAIL:
        lines = lines[:HEAD] + [f'... {len(lines) - HEAD - TAIL} lines left out ...'] + \
            lines[-TAIL:]
    return [shown(line, LOG_LINE) for line in lines]


def write_log(out, student_id, sections):
    path = os.path.join(folder(out, student_id), 'log.txt')
    with open(path, 'w') as f:
        for title, text in sections:
            f.write(f'==== {shown(title)}\n' + '\n'.join(trimmed(text)) + '\n\n')


def results_json(row: Row):
    """Gradescope's results.json for one student."""
    g = row.grade
    return dict(score=g.score, execution_time=round(row.seconds, 1),
                output=f'{g.verdict.upper()}: {g.score:g}/{g.max_score:g}. {g.reason}',
                tests=[dict(name=t.name, score=t.score, max_score=t.max_score,
                            status='passed' if t.met else 'failed',
                            output=t.output) for t in g.tests],
                leaderboard=[dict(name=n, value=v, order=o) for n, v, o in row.leaderboard])


def write_results(path, row: Row):
    with open(path, 'w') as f:
        json.dump(results_json(row), f, indent=1)


def write_student(out, row: Row, facts, sections):
    """OUT/ID/: drawing.png, log.txt (`sections`: (title, text)), ink.json
    and results.json: the row, its picture's path in it. No picture costs no
    row: the row's warning says why."""
    os.makedirs(folder(out, row.id), exist_ok=True)
    write_ink(folder(out, row.id), row.expected, facts.drawing)
    try:
        row = row._replace(picture=picture(out, row.id, facts))
    except Exception as e:      # Qt could not paint it: the row stands
        row = row._replace(warning='; '.join(filter(None, [row.warning, f'no picture: {e}'])))
    write_log(out, row.id, sections)
    write_results(os.path.join(folder(out, row.id), RESULTS_FILE), row)
    return row


def write_ink(student_folder, expected, drawing):
    """ID/ink.json, where there is a drawing with ink: the expected letters
    and the drawing, every field, each float kept exactly by JSON, so that
    the ink read again (driver.reread) is the ink read."""
    if drawing is None or not drawing.strokes:
        return
    with open(os.path.join(student_folder, INK_FILE), 'w') as f:
        json.dump(dict(expected=expected, drawing=drawing._asdict()), f)


def read_ink(student_folder):
    """(expected, Drawing) kept in ID/ink.json; a field a later Drawing
    added takes its default."""
    with open(os.path.join(student_folder, INK_FILE)) as f:
        kept = json.load(f)
    fields = {k: v for k, v in kept['drawing'].items() if k in Drawing._fields}
    return kept['expected'], Drawing(**fields)


def criterion_output(student_folder, name):
    """The line of feedback ID/results.json gives the criterion `name`; ''
    where it has none, or there is no such file."""
    try:
        with open(os.path.join(student_folder, RESULTS_FILE)) as f:
            tests = json.load(f).get('tests', [])
    except (OSError, ValueError):
        return ''
    return next((t.get('output', '') for t in tests if t.get('name') == name), '')


def leaderboard(facts, cpu_pct=None):
    """The drawing's figures for Gradescope's leaderboard: (name, value, order)."""
    d = facts.drawing
    if d is None or d.started is None:
        return []
    board = [('drawing time (s)', round(d.seconds, 2), 'asc'),
             ('cmd_vel rate (/s)', round(d.commands / max(d.seconds, 1e-6), 1), 'asc')]
    if cpu_pct is not None:
        board.append(('controller CPU (%)', round(cpu_pct, 1), 'asc'))
    fits = [r.best.fit for r in facts.readings if r.best is not None]
    if fits:
        board.append(('worst deviation (% of height)', round(100 * max(fits), 2), 'asc'))
    return board


def picture(out, student_id, facts):
    """OUT/ID/drawing.png, relative to OUT: the ink as turtlesim drew it,
    and over it each letter read, named; the expected letters in words
    only; None with no ink. A guess (ink no letter fits) is never drawn.
    Painted in the student's own thread: Qt paints a QImage in any thread
    once its application is made in the main one (cli: ready_to_paint)."""
    d = facts.drawing
    if d is None or not (d.strokes or d.teleported):
        return None
    from ..grading.picture import draw_ink
    path = os.path.join(folder(out, student_id), 'drawing.png')
    draw_ink(path, d.strokes, d.looks or [()] * len(d.strokes), d.background, overlay(facts),
             caption(student_id, facts),
             (d.earlier + d.teleported, d.earlier_looks + d.teleported_looks))
    return os.path.relpath(path, out)


def overlay(facts):
    """The letters drawn over the enlarged ink, (label, strokes): each
    credited, as the strokes fit it; one OCR alone credits, named only
    (no strokes) where no form of it reads; one read but not expected."""
    right = credited(facts)
    letters = [(e, r.fits[e].strokes) if r.letter == e else
               ('l', r.best.strokes) if credited_as_small_l(r, e) else
               (f'{e} (OCR)', r.fits[e].strokes if r.fits[e].fit <= r.fits[e].readable else [])
               for r, e in right if e in r.fits or credited_as_small_l(r, e)]
    nearest = nearest_only(facts)
    return letters + [(f'{r.letter}{" nearest" if r is nearest else ""}: not expected',
                       r.best.strokes) for r in facts.readings
                      if r.letter and all(r is not c for c, _ in right)]


def caption(student_id, facts):
    """The picture's two lines: the letters expected, read and credited,
    and what each half shows (a letter of the overlay named only, said so)."""
    ocr = f'; {ocr_said(facts.ocr)}' if facts.ocr is not None else ''
    ocr += f'; read as a row of {len(facts.longer)}, {facts.longer}' if facts.longer else ''
    named = ' (one OCR alone reads: named only)' if any(not s for _, s in overlay(facts)) else ''
    jumped = facts.drawing is not None and facts.drawing.teleported
    before = facts.drawing is not None and facts.drawing.earlier
    also = ' and '.join(said for said, shown_too in (('teleports laid ink', jumped),
                                                     ('ink from before the drawing', before))
                        if shown_too)
    nearest = nearest_only(facts)
    read = f'no letter cleanly ({nearest.letter} the nearest)' if nearest else \
        drawn(facts.readings) or 'no letter'
    return (f'{shown(student_id)}: expected {facts.expected or "?"}; its strokes read '
            f'{read}{ocr}\n'
            f'credited: {"".join(e for _, e in credited(facts)) or "none"}; left: the canvas as '
            f'turtlesim showed it{f" ({also} too)" if also else ""}; right: the '
            f'{"driven " if jumped else ""}ink{" of the drawing" if before else ""} enlarged, '
            f'each letter read dashed over it{named}')


def write_csv(path, rows):
    with open(path, 'w', newline='') as f:
        writer = csv.writer(f)
        writer.writerow(CSV_COLUMNS)
        writer.writerows(row.csv() for row in rows)


def write_junit(path, rows):
    failures = sum(row.grade.verdict == 'fail' for row in rows)
    skipped = sum(row.grade.verdict == NOT_GRADED for row in rows)
    suite = ElementTree.Element('testsuite', name='grade_class', tests=str(len(rows)),
                                failures=str(failures), skipped=str(skipped))
    for row in rows:
        sid, name = row.csv()[:2]
        case = ElementTree.SubElement(suite, 'testcase', classname='grade_class',
                                      name=f'{sid} {name}'.strip(),
                                      time=f'{row.seconds:.1f}')
        details = '\n'.join(f'{t.name}: {t.score:g}/{t.max_score:g}: {t.output}'
                            for t in row.grade.tests)
        if row.grade.verdict == NOT_GRADED:
            ElementTree.SubElement(case, 'skipped', message=shown(row.grade.reason))
        elif row.grade.verdict != 'pass':
            ElementTree.SubElement(case, 'failure', message=shown(row.grade.reason)).text = details
        ElementTree.SubElement(case, 'system-out').text = details
    ElementTree.ElementTree(suite).write(path, encoding='utf-8', xml_declaration=True)


def _cell(value):
    return f'<td>{html.escape(str(value))}</td>'


def write_html(path, rows, title):
    table = ''.join(
        f'<tr class="{row.grade.verdict}">' + ''.join(_cell(v) for v in row.csv()[:4]) +
        _cell(points(row.grade)) + _cell(row.grade.verdict) +
        f'<td><a href="#{html.escape(safe_name(row.id))}">{html.escape(row.csv()[-1])}</a>'
        f'</td></tr>\n' for row in rows)
    sections = ''.join(_section(row) for row in rows)
    with open(path, 'w') as f:
        f.write(f'<!DOCTYPE html>\n<html><head><meta charset="utf-8"><title>{html.escape(title)}'
                f'</title>\n<style>{STYLE}</style></head><body>\n<h1>{html.escape(title)}</h1>\n'
                f'<table><tr><th>id</th><th>name</th><th>expected</th><th>drawn</th>'
                f'<th>score</th><th>verdict</th><th>first thing that cost points</th></tr>\n'
                f'{table}</table>\n{sections}</body></html>\n')


def _section(row):
    items = ''.join(f'<li class="{"met" if t.met else "lost"}">'
                    f'{html.escape(t.name)}: {t.score:g}/{t.max_score:g}. {html.escape(t.output)}'
                    f'</li>' for t in row.grade.tests)
    picture = (f'<img src="{urllib.parse.quote(row.picture)}" alt="the path over the letter">'
               if row.picture else '<p>No drawing.</p>')
    board = ', '.join(f'{n}: {v:g}' if isinstance(v, (int, float)) else f'{n}: {v}'
                      for n, v, _ in row.leaderboard)
    warning = f'<p class="lost">{html.escape(shown(row.warning))}</p>' if row.warning else ''
    sid, name = row.csv()[:2]
    return (f'<h2 id="{html.escape(safe_name(row.id))}">{html.escape(sid)} '
            f'{html.escape(name)}: {points(row.grade)}, {row.grade.verdict}</h2>\n{warning}<ul>{items}</ul>\n<p>{html.escape(board)}</p>'
            f'\n{picture}\n')


STYLE = ('body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}'
         'td,th{border:1px solid #bbb;padding:.3em .6em;text-align:left}'
         'tr.fail td{background:#fde8e8}tr.pass td{background:#e8f6e8}'
         'li.lost{color:#a00}img{max-width:100%;border:1px solid #ddd}')
