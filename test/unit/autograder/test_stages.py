"""The driver's stages (driver.py) in order, with fakes of the place, the sandbox and
the session's runs: a student to their row without root or ROS. What each
run observes is stood in for by its facts; the rubric, the row and the
files are real."""
import contextlib
import json
import os
import threading
from types import SimpleNamespace

from turtle_letters.autograder import driver, rubric as rubrics
from turtle_letters.autograder.observations import Drawing
from turtle_letters.autograder.roster import Student
from turtle_letters.autograder.session import Step
from turtle_letters.autograder.submission import Package

HERE = os.path.dirname(__file__)
RUBRIC = rubrics.load(os.path.join(HERE, '..', '..', '..', 'config', 'rubric.yaml'))
OK = Step(True, 'fine')
L_PATH = [(1.0, 3.0), (1.0, 1.0), (2.2, 1.0)]


class Place:
    """A fake place: one sandbox of fakes, never stopped."""

    def __init__(self):
        self.stopping, self.box = threading.Event(), SimpleNamespace(stopped=False)

    @contextlib.contextmanager
    def grading(self, _):
        yield

    @contextlib.contextmanager
    def sandbox(self):
        yield self.box


def run_of(name, executables=(), drivers=()):
    """A fake session.Run: its steps, what it started, who published on
    cmd_vel, its log."""
    graph = dict(kind='graph', t=1.0, cmd_vel_publishers=list(drivers))
    by = [dict(k='by', t=1.0, node=node) for node in drivers]
    return SimpleNamespace(name=name, package=SimpleNamespace(name='lab'), build=OK,
                           launch=Step(False, f'{name} launched'),
                           waited=OK, talker=OK, stuck='', waiting='', limit='', broken='',
                           fought='',
                           events=[graph],
                           record=[dict(k='spawn', t=0.0, turtle='turtle1', x=5.5, y=5.5)] + by,
                           executables=list(executables), cpu_pct=None, limit_s=None,
                           script_until=None, gone=None, watched_for=lambda: 0.0, log=[(f'roslaunch ({name})', f'{name} ran')])


def observing(drawn):
    """A stand-in for driver.observed: what each run's record showed, {run name: Drawing}."""
    def observed(expected, run, rubric):
        drawing = drawn.get(run.name)
        return rubrics.Facts.observed(expected, run, drawing, *driver.read(drawing, expected))
    return observed


def test_executables_that_drew_nothing_together_run_each_alone_until_one_draws(
        tmp_path, monkeypatch):
    """Together, three executables drew nothing; alone, a.py draws nothing
    and b.py draws the L: b.py's run is the row, saying what a.py drew, and
    c.py is never tried."""
    tried = []
    monkeypatch.setattr(driver.submission, 'find', lambda folder: Package(
        name="lab", folder=folder, launch=None, problem='', notes=[]))
    monkeypatch.setattr(driver.session, 'run', lambda package, limits, box, letters: run_of(
        'together', ['a.py', 'b.py', 'c.py']))
    monkeypatch.setattr(driver.session, 'alone', lambda first, name, limits, box: (
        tried.append(name), run_of(name))[1])
    l_drawn = Drawing([L_PATH], 1.0, 5.0, 200, [])
    monkeypatch.setattr(driver, 'observed', observing({'b.py': l_drawn}))
    place = Place()
    place.box.work = str(tmp_path)      # no copy of the package: no turtles named
    row, facts = driver.grade(Student('s1', 'Lena', 'L', str(tmp_path)), RUBRIC,
                              str(tmp_path / 'out'), place)
    assert tried == ['a.py', 'b.py']
    assert facts.launch.says.startswith('b.py launched; also tried, not kept: a.py alone drew '
                                        'no letter (') and row.drawn == 'L', facts.launch.says
    with open(tmp_path / 'out' / 's1' / 'log.txt') as f:
        assert 'b.py ran' in f.read()
    with open(tmp_path / 'out' / 's1' / 'results.json') as f:
        assert json.load(f)['score'] == row.grade.score


def test_of_tries_of_equal_points_the_one_whose_drawing_reads_is_kept(tmp_path, monkeypatch):
    """Together, two scripts drew a scribble no letter reads; run.py alone
    drew LIT where L is asked (niv's package, a real class's): each earns
    the same points, and the row is run.py's, saying what it drew; the
    scribble's run is tried first and said not kept."""
    import math
    monkeypatch.setattr(driver.submission, 'find', lambda folder: Package(
        name="lab", folder=folder, launch=None, problem='', notes=[]))
    monkeypatch.setattr(driver.session, 'run', lambda package, limits, box, letters: run_of(
        'together', ['a.py', 'run.py']))
    monkeypatch.setattr(driver.session, 'alone', lambda first, name, limits, box: run_of(name))
    from support.glyph_rows import row
    spiral = [[(3 + 0.02 * k * math.cos(0.2 * k), 3 + 0.02 * k * math.sin(0.2 * k))
               for k in range(120)]]
    scribble, lit = Drawing(spiral, 1.0, 5.0, 200, []), Drawing(row('LIT'), 1.0, 5.0, 200, [])
    drawn = {'together': scribble, 'a.py': scribble, 'run.py': lit}
    monkeypatch.setattr(driver, 'observed', observing(drawn))
    place = Place()
    place.box.work = str(tmp_path)
    row_, facts = driver.grade(Student('s4', 'Niv', 'L', str(tmp_path)), RUBRIC,
                               str(tmp_path / 'out'), place)
    assert row_.drawn == 'LIT' and facts.launch.says.startswith(
        'run.py launched; also tried, not kept: a.py alone drew ? ('), facts.launch.says
    assert rubrics.letter_line(facts).startswith('drew LIT where one letter, L, is expected')


def test_executables_of_which_one_alone_drove_are_not_run_alone(tmp_path, monkeypatch):
    """Together, controller.py drove an L (P expected) and talker.py only
    talked: alone, each would do the same, so the together run is the row."""
    monkeypatch.setattr(driver.submission, 'find', lambda folder: Package(
        name="lab", folder=folder, launch=None, problem='', notes=[]))
    monkeypatch.setattr(driver.session, 'run', lambda package, limits, box, letters: run_of(
        'together', ['controller.py', 'talker.py'], drivers=['/controller0']))

    def alone(*_):
        raise AssertionError('no executable is run alone where one alone drove')
    monkeypatch.setattr(driver.session, 'alone', alone)
    l_drawn = Drawing([L_PATH], 1.0, 5.0, 200, [])
    monkeypatch.setattr(driver, 'observed', observing({'together': l_drawn}))
    row, facts = driver.grade(Student('s3', 'Pavel', 'P', str(tmp_path)), RUBRIC,
                              str(tmp_path / 'out'), Place())
    assert facts.launch.says == 'together launched' and row.drawn == 'L'


def test_a_package_that_cannot_be_found_is_a_row_that_says_why_and_runs_nothing(
        tmp_path, monkeypatch):
    monkeypatch.setattr(driver.submission, 'find', lambda folder: Package(
        name="", folder=folder, launch=None, problem='no package.xml in the folder', notes=[]))

    def no_run(*_):
        raise AssertionError('nothing is run for a package not found')
    monkeypatch.setattr(driver.session, 'run', no_run)
    row, facts = driver.grade(Student('s2', 'Ann', 'A', str(tmp_path)), RUBRIC,
                              str(tmp_path / 'out'), Place())
    assert facts.problem == 'no package.xml in the folder'
    assert row.grade.score == 0 and 'no package.xml in the folder' in row.grade.reason


def test_read_takes_each_pen_colour_for_a_letter_where_there_are_as_many_as_expected():
    """The read stage: an M in one turtle's green pen, an o in another's
    driven round over the M's last leg, as the simulator recorded their
    looks. Each colour is read alone: MO, the M first; in one pen, the
    same ink is a row, and the cut through the overlap does not read MO."""
    import math
    from support.cadet_paths import arc, driven
    from support.glyph_rows import row
    m = row('M')
    right, bottom = max(p[0] for s in m for p in s), min(p[1] for s in m for p in s)
    ink = m + [driven([arc(0.6, 0.97 * math.tau)], right, bottom + 0.5)]
    green, lavender = (0, 255, 0, 2), (180, 184, 255, 2)
    apart = Drawing(ink, 1.0, 5.0, 90, [], looks=[green] * len(m) + [lavender])
    together = apart._replace(looks=[green] * len(ink))
    assert [r.letter for r in driver.read(apart, 'MO')[0].readings] == ['M', 'O']
    assert [r.letter for r in driver.read(together, 'MO')[0].readings] != ['M', 'O']


def test_ocr_reads_only_a_row_the_strokes_do_not_read_as_expected_a_small_l_an_l():
    """The read stage asks OCR, the slower reader, only where the strokes
    do not read the letters expected; an A and a bare stroke as tall read
    as the Al expected (rubric's small l): OCR is not asked, and the row
    does not say what it would have read (a real class's Al said 'OCR
    reads A (0% sure)' beside its credit). Expected AT, it is asked."""
    a = [[(1.0, 1.0), (1.6, 3.0), (2.2, 1.0)], [(1.2, 1.7), (2.0, 1.7)], [(3.0, 1.0), (3.0, 3.0)]]
    drawing = Drawing(a, 1.0, 5.0, 90, [])
    assert driver.read(drawing, 'AL')[1] is None
    assert driver.read(drawing, 'AT')[1] is not None


def test_a_row_drawn_where_one_letter_is_asked_is_said_drawn_and_credits_nothing():
    """A student who drew LIT where the roster asks for L (two real
    classes' rows: a LIT, a MATT) is told what they drew, read as the row
    it is, not which single letter lies nearest it; the L is not credited
    (a longer row is not searched for the letter asked), and with a roster
    of LIT the same ink earns it whole. A J and a P, which OCR reads WP,
    read as WP by neither reader once asked: nothing is said drawn."""
    from support.glyph_rows import row
    lit = Drawing(row('LIT'), 1.0, 20.0, 300, [])
    facts = rubrics.Facts.of_drawing('L', lit, *driver.read(lit, 'L'))
    line = rubrics.letter_line(facts)
    assert facts.longer == 'LIT' and rubrics.drawn_text(facts) == 'LIT', line
    assert line.startswith('drew LIT where one letter, L, is expected (read as a row of 3, it '
                           'reads LIT whole: a roster that asks for LIT credits it'), line
    assert rubrics.credited(facts) == [] and '; read as one letter, none reads (closest' in line
    asked = rubrics.Facts.of_drawing('LIT', lit, *driver.read(lit, 'LIT'))
    assert [e for _, e in rubrics.credited(asked)] == list('LIT') and asked.longer == ''
    jp = Drawing(row('JP'), 1.0, 20.0, 300, [])
    facts = rubrics.Facts.of_drawing('J', jp, *driver.read(jp, 'J'))
    assert facts.ocr.text == 'WP' and facts.longer == ''
    assert rubrics.letter_line(facts).startswith('no letter reads from the path (closest')


def test_letters_read_in_one_line_of_writing_are_graded_there_and_the_row_says_so():
    """The read and score stages: SNB above 002 inside a border (a real
    class's snb.py), in pens as the simulator recorded them. The letters
    are read in the top line; the row says where, and their accuracy is
    that of SNB drawn alone: neither the border nor the digits count."""
    from support.glyph_rows import row
    ink = [[(0.3, 2.2), (10.5, 2.2), (10.5, 9.5), (0.3, 9.5), (0.3, 2.5)]] + \
        row('SNB', bottom=6.0) + row('002', bottom=3.0)
    looks = [(255, 0, 255, 3)] + [(80, 80, 200, 3)] * (len(ink) - 1)
    page = Drawing(ink, 1.0, 40.0, 900, [], looks=looks)
    alone = Drawing(row('SNB', bottom=6.0), 1.0, 40.0, 900, [], looks=looks[:len(row('SNB'))])
    marks = {}
    for name, drawing in (('page', page), ('alone', alone)):
        facts = rubrics.Facts.observed('SNB', run_of(name), drawing,
                                       *driver.read(drawing, 'SNB'))
        marks[name] = {m.name: m for m in rubrics.grade(facts, RUBRIC).tests}
    letter, accuracy = 'The letter drawn is the expected one', 'Its accuracy'
    assert marks['page'][letter].output == \
        'drew SNB, as expected (read in the top line of the 2 lines of its writing)'
    assert marks['alone'][letter].output == 'drew SNB, as expected'
    assert marks['page'][accuracy] == marks['alone'][accuracy]


def written(strokes, t, pen=(255, 255, 255, 4)):
    """The simulator's record of a turtle writing `strokes` from `t`, a
    point each 16 ms, travelling between them with its pen up; and when it ends."""
    record = []
    for stroke in strokes:
        for (x0, y0), (x1, y1) in zip([stroke[0]] + stroke, stroke):
            t += 0.016
            ink = [[x0, y0, x1, y1, *pen]] if (x0, y0) != (x1, y1) else []
            record.append(dict(k='move', t=t, turtle='turtle_main', to=[x1, y1, 0.0], ink=ink))
    return record, t


def test_a_writer_that_never_ends_is_read_on_the_fullest_canvas_it_wiped():
    """The observe and read stages: a never-ending writer of USI (a real
    class's), which clears the canvas and writes again, stopped by the time
    limit with its U begun and a long chase laid, its pen down. The canvas
    left is read first; a TA saw USI written whole before a clear, and that
    canvas is graded, the row says so. A writer that ended is graded on the
    canvas it left."""
    from support.cadet_paths import driven, forward
    from support.glyph_rows import row
    from turtle_letters.autograder import observations as seen
    whole, t = written(row('USI'), 2.0)
    begun, end = written([row('U')[0][:len(row('U')[0]) // 2]], t + 1.0)
    wandering, end = written([driven([forward(0.5)] * 40, 9.0, 1.0)], end)
    run = run_of('usi')
    run.record += whole + [dict(k='clear', t=t + 0.5)] + begun + wandering
    run.since, run.trigger, run.finished, run.script_until = 1.5, 1.5, end, None
    facts = driver.observed('USI', run, RUBRIC)
    assert rubrics.drawn_text(facts) == 'USI' and facts.drawing.shown[0] == 0.0
    letter = {m.name: m for m in rubrics.grade(facts, RUBRIC).tests}[
        'The letter drawn is the expected one'].output
    assert letter.startswith('drew USI, as expected (graded on the canvas turtlesim showed from '
                             '0.0 to ') and 'the drawing never ended' in letter
    # ended: standing still long after, the canvas left is what counts
    run.finished = end + 60
    assert seen.of_run(run, RUBRIC.limits.settle).fullest == []
    assert rubrics.drawn_text(driver.observed('USI', run, RUBRIC)) != 'USI'
    run.finished = end
    # a wiped canvas that credits no more: the canvas left, and the row says both
    dash, t = written([[(1.0, 1.0), (1.5, 1.0)]], 2.0)
    run.record[1:] = dash + [dict(k='clear', t=t + 0.5)] + begun + wandering
    assert rubrics.letter_line(driver.observed('USI', run, RUBRIC)).endswith(
        'the drawing never ended, and the fullest canvas it wiped credits no more letters)')
