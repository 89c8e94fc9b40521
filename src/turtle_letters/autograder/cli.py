"""`grade_class.py`: a class's lab packages graded as handed in.

    grade_class.py SUBMISSIONS --roster ROSTER.csv --out OUT [--jobs N] [--rubric FILE]
    grade_class.py --one FOLDER --name NAME [--letter L] --out OUT   (exit 0 pass, 1 fail)
    grade_class.py --gradescope           (/autograder/submission to results/results.json)

Each student in roster order, N at a time, each in a sandbox with a ROS
master of its own (session.py); the rubric scores what happened (rubric.py)
and reports.py writes it out. The grader's own failure on one submission
is that student's row, never the class's. Exit 0 once every student has a
row, 2 on input that stops grading before anything runs, 130 (Ctrl-C) or
143 (SIGTERM) when stopped: every sandbox ended, the class files written
for the students graded so far and marked incomplete.
"""
import argparse
import concurrent.futures
import contextlib
import json
import os
import queue
import shutil
import signal
import sys
import tempfile
import threading
import time
import traceback

import rospkg

from ..isolation.files import shown
from ..reading.ocr import read_text, said as ocr_said
from ..reading.recognition import read_row
from . import observations as seen
from ..isolation import sandbox
from . import reports, rubric as rubrics, session, submission
from .roster import RosterError, Student
from .roster import expected as expected_of
from .roster import read as read_roster

GRADESCOPE = '/autograder'
MAX_ALONE = 4           # executables a TA tries each alone, at most


def arguments(argv):
    parser = argparse.ArgumentParser(prog='grade_class.py', description=__doc__.split('\n')[0])
    parser.add_argument('submissions', nargs='?', help='a folder per student, named by their id')
    parser.add_argument('--roster', help='CSV with id,name and optionally letter')
    parser.add_argument('--out', help='where the grades go')
    parser.add_argument('--jobs', type=int, default=1, help='students graded at once (1)')
    parser.add_argument('--rubric', help='a YAML rubric over the package default')
    parser.add_argument('--one', metavar='FOLDER', help='grade one submission; exit 0 on pass')
    parser.add_argument('--name', default='', help="with --one: the cadet's name")
    parser.add_argument('--letter', default='', help='with --one: the letter (or letters) expected')
    parser.add_argument('--no-sandbox', dest='isolated', action='store_false',
                        help='run each submission unisolated, where the machine is a sandbox '
                             "already (Gradescope's container); a master port each, no more")
    parser.add_argument('--gradescope', action='store_true',
                        help='grade AUTOGRADER/submission into AUTOGRADER/results/results.json')
    parser.add_argument('--autograder', default=GRADESCOPE,
                        help=f"with --gradescope: Gradescope's folder ({GRADESCOPE})")
    args = parser.parse_args(argv)
    modes = [bool(args.submissions), bool(args.one), args.gradescope]
    if sum(modes) != 1:
        parser.error('give SUBMISSIONS with --roster, or --one FOLDER, or --gradescope')
    if args.submissions and not (args.roster and args.out):
        parser.error('SUBMISSIONS needs --roster and --out')
    if args.one and not (args.out and (args.name or args.letter)):
        parser.error('--one needs --out, and --name or --letter')
    if args.jobs < 1:
        parser.error(f'--jobs {args.jobs}: at least 1')
    if args.one or args.gradescope:
        args.jobs = 1
    return args


def default_rubric():
    return os.path.join(rospkg.RosPack().get_path('turtle_letters'), 'config', 'rubric.yaml')


class Stopped(Exception):
    """Grading was stopped (Ctrl-C, SIGTERM) before this student was done."""


class Place:
    """Where submissions run: what they must not see, whether in a sandbox,
    and a slot each for the `jobs` graded at once: a user of its own and a
    core (alone: a core too, so that a grade does not depend on who is
    graded beside it); the sandboxes running, for `stop` to end them, and
    who is being graded."""

    def __init__(self, hidden, isolated, jobs):
        self.hidden, self.isolated = hidden, isolated
        cores = sorted(os.sched_getaffinity(0))
        self.slots = queue.Queue()
        for slot in range(jobs):
            self.slots.put((slot, cores[slot % len(cores)]))
        # re-entrant: a second Ctrl-C's handler takes it in whatever thread it lands
        self.stopping, self.lock = threading.Event(), threading.RLock()
        self.boxes, self.current = set(), []

    @contextlib.contextmanager
    def sandbox(self):
        """A sandbox in a free slot, ended by `stop` even while it runs. It
        is made and removed under the lock, so that a forced exit finds
        every sandbox whole in `boxes`, never one half made or half gone."""
        slot, cpu = self.slots.get()
        box = sandbox.Sandbox(self.hidden, self.isolated, cpu, slot=slot)
        try:
            with self.lock:
                box.__enter__()
                self.boxes.add(box)
            if self.stopping.is_set():
                box.stop()
            yield box
        finally:
            with self.lock:
                if box in self.boxes:
                    box.__exit__(None, None, None)
                    self.boxes.discard(box)
            self.slots.put((slot, cpu))

    def stop(self):
        """Every sandbox running ended now, and none started after."""
        self.stopping.set()
        with self.lock:
            boxes = list(self.boxes)
        for box in boxes:
            box.stop()


def facts_of(student, rubric, place):
    """Run the student's submission and say what happened: (facts, run,
    what of the submission was left out)."""
    if student.folder is None:
        return rubrics.Facts.never_ran(student.expected, 'no submission'), None, []
    package = submission.find(student.folder)
    if package.problem:
        return rubrics.Facts.never_ran(student.expected, package.problem), None, package.notes
    with place.sandbox() as box:
        run = session.run(package, rubric.limits, box)
        facts = facts_of_run(student, run, rubric)
        facts, run = each_alone(student, rubric, box, facts, run)
    if box.stopped:
        raise Stopped()
    return facts, run, package.notes


def each_alone(student, rubric, box, facts, run):
    """A TA's fallback: executables started together (no launch file) that
    did not draw the letters run each alone, in a fresh world, the first
    MAX_ALONE of them, until one does; the best (facts, run) kept."""
    first, best = run, rubrics.grade(facts, rubric).score
    for name in first.executables[:MAX_ALONE] if len(first.executables) > 1 else []:
        if box.stopped or len(rubrics.credited(facts)) == len(student.expected):
            break
        tried = session.alone(first, name, rubric.limits, box)
        tried_facts = facts_of_run(student, tried, rubric)
        if rubrics.grade(tried_facts, rubric).score > best:
            facts, run, best = tried_facts, tried, rubrics.grade(tried_facts, rubric).score
    return facts, run


def facts_of_run(student, run, rubric):
    """The facts of one run: its steps, and its drawing read."""
    drawing, readings, ocr = None, [], None
    if run.trigger is not None:
        drawing = seen.drawing(run.record, run.events, run.since, rubric.limits.settle,
                               run.finished)
        readings = read_row(drawing.strokes, student.expected) if drawing.strokes else []
        # OCR, the slower reader, is asked where the strokes do not read what was expected
        if drawing.strokes and rubrics.drawn(readings) != student.expected:
            ocr = read_text(drawing.strokes, student.expected)
    return rubrics.Facts(
        student.expected, build=run.build, launch=run.launch, waited=run.waited,
        talker=run.talker, drawing=drawing, readings=readings, stuck=run.stuck, limit=run.limit,
        own_triggers=seen.own_triggers(run.events), chatter_peak=seen.chatter_peak(run.events),
        broken=run.broken, ocr=ocr)


def facts_or_failure(student, rubric, place):
    """(facts, run, notes, the grader's own error or ''): a failure of the
    grader on this submission becomes its facts, never the class's end."""
    try:
        return facts_of(student, rubric, place) + ('',)
    except Stopped:
        raise
    except Exception as e:      # whatever the submission made the grader meet
        if place.stopping.is_set():
            raise Stopped() from None
        return failed(student, e), None, [], traceback.format_exc()


def failed(student, error):
    """The facts of a submission the grader itself failed on."""
    problem = f'the grader failed on this submission: {type(error).__name__}: {error}'
    return rubrics.Facts.never_ran(student.expected, shown(problem))


def grade_student(student: Student, rubric, out, place, warning=''):
    """One student's row; their results.json and log.txt written (the picture: later)."""
    if place.stopping.is_set():
        raise Stopped()
    started = time.monotonic()
    with place.lock:
        place.current.append(student.id)
    try:
        facts, run, notes, error = facts_or_failure(student, rubric, place)
    finally:
        with place.lock:
            place.current.remove(student.id)
    warning = '; '.join(filter(None, [warning] + notes))
    graded = rubrics.grade(facts, rubric)
    drawn = rubrics.drawn_text(facts)
    board = leaderboard(facts, run)
    row = reports.Row(student.id, student.name, student.expected, drawn, graded,
                      time.monotonic() - started, board, None, warning)
    sections = run.log if run else [('submission', facts.problem)]
    sections += [('left out of the submission', '\n'.join(notes))] if notes else []
    sections += [("the grader's own error", error)] if error else []
    os.makedirs(reports.folder(out, student.id), exist_ok=True)
    reports.write_log(out, student.id, sections)
    reports.write_results(os.path.join(reports.folder(out, student.id), 'results.json'), row)
    return row, facts


def leaderboard(facts, run):
    d = facts.drawing
    if d is None or d.started is None:
        return []
    board = [('drawing time (s)', round(d.seconds, 2), 'asc'),
             ('cmd_vel rate (/s)', round(d.commands / max(d.seconds, 1e-6), 1), 'asc')]
    if run and run.cpu_pct is not None:
        board.append(('controller CPU (%)', round(run.cpu_pct, 1), 'asc'))
    fits = [r.best.fit for r in facts.readings if r.best is not None]
    if fits:
        board.append(('worst deviation (% of height)', round(100 * max(fits), 2),
                      'asc'))
    return board


def draw_picture(out, row, facts):
    """OUT/ID/drawing.png: the ink as turtlesim drew it, and over it each
    letter read, named; the expected letters in words only (Qt: main
    thread only). A guess (ink no letter fits) is never drawn."""
    d = facts.drawing
    if d is None or not d.strokes:
        return row
    from ..grading.picture import draw_ink
    right = rubrics.credited(facts)
    letters = [(e if r.letter == e else f'{e} (OCR)', r.fits[e].strokes)
               for r, e in right if e in r.fits]
    letters += [(f'{r.letter}: not expected', r.best.strokes) for r in facts.readings
                if r.letter and all(r is not c for c, _ in right)]
    ocr = f'; {ocr_said(facts.ocr)}' if facts.ocr is not None else ''
    caption = (f'{row.id}: expected {facts.expected or "?"}; its strokes read '
               f'{rubrics.drawn(facts.readings) or "no letter"}{ocr}\n'
               f'credited: {"".join(e for _, e in right) or "none"}; left: the canvas as '
               f'turtlesim showed it; right: the ink enlarged, each letter read dashed over it')
    path = os.path.join(reports.folder(out, row.id), 'drawing.png')
    draw_ink(path, d.strokes, d.looks or [()] * len(d.strokes), d.background, letters, caption)
    return row._replace(picture=os.path.relpath(path, out))


def said(row, isolated):
    """The row's line on the terminal."""
    g = row.grade
    sid, name = row.csv()[:2]
    return (('' if isolated else '[no sandbox: nothing isolated] ') +
            f'{sid} {name}: drew {row.drawn or "no letter"}, expected {row.expected or "?"}: '
            f'{reports.points(g)} {g.verdict.upper()}: {g.reason}')


class Progress:
    """On a terminal, a bar under the rows: students done, those being
    graded, the time left (tqdm); elsewhere, the rows only."""

    def __init__(self, total, place):
        from tqdm import tqdm
        self.place = place
        self.bar = tqdm(total=total, unit='student', file=sys.stderr, dynamic_ncols=True,
                        disable=not sys.stderr.isatty(), bar_format='{l_bar}{bar}| {n}/{total} '
                        'students [{elapsed}<{remaining}]{postfix}')
        self.ticker = threading.Thread(target=self._show_current, daemon=True)
        self.ticker.start()

    def _show_current(self):
        while not self.bar.disable and not self.place.stopping.wait(1.0):
            with self.place.lock:
                current = ', '.join(shown(sid, 30) for sid in self.place.current)
            self.bar.set_postfix_str(f'grading {current}' if current else '')

    def row(self, line):
        self.bar.write(line, file=sys.stdout)
        sys.stdout.flush()
        self.bar.update()

    def close(self):
        self.bar.close()


def grade_all(students, rubric, out, hidden, args, warnings=None):
    """(every student's row in roster order, `args.jobs` at a time; the
    signal's name if Ctrl-C or SIGTERM stopped it, with only the rows done)."""
    warnings = warnings or {}
    place = Place(hidden, args.isolated, args.jobs)
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs)
    futures = [pool.submit(grade_student, s, rubric, out, place, warnings.get(s.id, ''))
               for s in students]
    progress, rows, stopped = Progress(len(students), place), {}, ''
    before = _on_signal(_first_stop(place))
    try:
        for i, future in enumerate(futures):
            rows[i] = _finished(out, _graded(future, students[i], rubric), progress,
                                args.isolated)
            # each row kept as it comes: a grader killed outright keeps what it graded
            reports.write_csv(os.path.join(out, 'grades.csv'), [rows[j] for j in sorted(rows)])
            _Painting.release()     # a stop that came while it painted: its row is kept
    except KeyboardInterrupt as e:
        stopped = str(e) or 'SIGINT'
        print(f'\ngrade_class.py: {stopped}: stopping (again to force)', file=sys.stderr,
              flush=True)
        place.stop()
        for future in futures:
            future.cancel()
    finally:
        place.stopping.set()
        pool.shutdown(wait=True)
        _on_signal(*before)
    for i, future in enumerate(futures):    # done while it stopped: they count
        if i not in rows and future.done() and not future.cancelled() and \
                future.exception() is None:
            rows[i] = _finished(out, future.result(), progress, args.isolated)
    progress.close()
    return [rows[i] for i in sorted(rows)], stopped


def _graded(future, student, rubric):
    """The student's (row, facts); where the grader failed even in scoring
    or writing their files, a row that says so, with no files."""
    try:
        return future.result()
    except Stopped:
        raise
    except Exception as e:
        facts = failed(student, e)
        return reports.Row(student.id, student.name, student.expected, '',
                           rubrics.grade(facts, rubric), 0.0, [], None), facts


class _Painting:
    """Whether a picture is being painted, and a stop that came meanwhile:
    Ctrl-C raised mid-paint leaves Qt painting on an image Python frees,
    and the grader dies of SIGSEGV instead of writing the class files."""
    now = False
    held = None

    @classmethod
    def release(cls):
        """The stop that waited for the picture, acted on now."""
        held, cls.held = cls.held, None
        if held is not None:
            signal.getsignal(held[0])(*held)


def _finished(out, graded, progress, isolated):
    row, facts = graded
    _Painting.now = True
    try:
        row = draw_picture(out, row, facts)
    except Exception as e:      # no picture costs no row
        row = row._replace(warning='; '.join(filter(None, [row.warning, f'no picture: {e}'])))
    finally:
        _Painting.now = False
    progress.row(said(row, isolated))
    return row


def _on_signal(handler, on_term=None):
    """`handler` for Ctrl-C and SIGTERM (or `on_term` for it); the handlers they had."""
    return signal.signal(signal.SIGINT, handler), \
        signal.signal(signal.SIGTERM, on_term or handler)


def _interrupt(number, _):
    raise KeyboardInterrupt(signal.Signals(number).name)


def _first_stop(place):
    """Ctrl-C or SIGTERM while grading: the next one forces, from now on."""
    def first(number, frame):
        if _Painting.now:
            _Painting.held = (number, frame)
            return
        _on_signal(_force(place))
        _interrupt(number, frame)
    return first


def _force(place):
    """A second Ctrl-C: end what runs and remove the sandboxes at once, and leave."""
    def force(number, _):
        print('grade_class.py: forced: no class files written', file=sys.stderr, flush=True)
        place.stop()
        with place.lock:        # every sandbox whole: none is being made or removed now
            for box in place.boxes:
                box.__exit__(None, None, None)
            _reap_children()
            os._exit(128 + number)
    return force


def _reap_children(seconds=2.0):
    """Waits for the children just killed, so that none is left for init to
    reap (a slow init shows them a while longer)."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        try:
            pid, _ = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            return
        if pid == 0:
            time.sleep(0.01)


def write_class(out, rows, title):
    reports.write_csv(os.path.join(out, 'grades.csv'), rows)
    reports.write_junit(os.path.join(out, 'junit.xml'), rows)
    reports.write_html(os.path.join(out, 'report.html'), rows, title)


def with_ungraded(rows, students, stopped):
    """`rows`, and for each student grading stopped before, a row that says so."""
    graded = {row.id for row in rows}
    return rows + [reports.not_graded(s.id, s.name, s.expected, f'grading was stopped '
                                      f'({stopped}) before this student was graded')
                   for s in students if s.id not in graded]


EXIT = {'': 0, 'SIGINT': 130, 'SIGTERM': 143}


def grade_class(args, rubric):
    try:
        students, warnings = read_roster(args.roster, args.submissions, rubric.expected)
    except RosterError as e:
        print(f'grade_class.py: {e}', file=sys.stderr)
        return 2
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    for line in warnings:
        print(f'warning: {shown(line)}', file=sys.stderr)
    noted = {line.split(':', 1)[0]: line for line in warnings}
    hidden = [args.submissions, args.roster, out]
    started = time.monotonic()
    rows, stopped = grade_all(students, rubric, out, hidden, args, noted)
    title = f'turtle_letters: {len(rows)} students graded'
    if stopped:
        title = f'turtle_letters: INCOMPLETE, stopped by {stopped}: {len(rows)} of ' \
                f'{len(students)} students graded'
    write_class(out, with_ungraded(rows, students, stopped), title)
    print(f'{sum(r.grade.verdict == "pass" for r in rows)} of {len(rows)} passed in '
          f'{(time.monotonic() - started) / 60:.1f} min; {out}/report.html' +
          (f' (incomplete: {len(students) - len(rows)} not graded)' if stopped else ''),
          flush=True)
    return EXIT[stopped]


def wanted(name, letter, rubric):
    """What the student is to draw (--letter, else the rubric's `expected`
    of the name); None, said, when --letter is no text of A-Z."""
    try:
        return expected_of(name, letter, rubric.expected)
    except ValueError as e:
        print(f'grade_class.py: --letter: {e}', file=sys.stderr)
        return None


def grade_one(args, rubric):
    folder = os.path.abspath(args.one)
    expected = wanted(args.name, args.letter, rubric)
    if expected is None:
        return 2
    student = Student(os.path.basename(folder.rstrip('/')), args.name, expected, folder)
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    rows, stopped = grade_all([student], rubric, out, [out], args)
    if stopped:
        write_class(out, with_ungraded(rows, [student], stopped),
                    f'turtle_letters: {shown(student.id)}: INCOMPLETE, stopped by {stopped}')
        return EXIT[stopped]
    write_class(out, rows, f'turtle_letters: {shown(student.id)}')
    for test in rows[0].grade.tests:
        print(f'  {test.name}: {test.score:g}/{test.max_score:g}: {test.output}')
    return 0 if rows[0].grade.verdict == 'pass' else 1


def grade_gradescope(args, rubric):
    root = args.autograder
    try:
        with open(os.path.join(root, 'submission_metadata.json')) as f:
            users = json.load(f).get('users') or [{}]
        name = str(users[0].get('name', ''))
    except (OSError, ValueError, AttributeError) as e:
        print(f'grade_class.py: {root}/submission_metadata.json: {e}', file=sys.stderr)
        return 2
    expected = wanted(name, args.letter, rubric)
    if expected is None:
        return 2
    student = Student('submission', name, expected, os.path.join(root, 'submission'))
    out = tempfile.mkdtemp(prefix='turtle_letters_gradescope_')
    try:
        rows, stopped = grade_all([student], rubric, out, [out], args)
        if stopped:
            return EXIT[stopped]
        os.makedirs(os.path.join(root, 'results'), exist_ok=True)
        reports.write_results(os.path.join(root, 'results', 'results.json'), rows[0])
    finally:
        shutil.rmtree(out, ignore_errors=True)
    return 0


def main(argv=None):
    args = arguments(sys.argv[1:] if argv is None else argv)
    _on_signal(_interrupt)      # SIGTERM stops grading as Ctrl-C does
    problem = sandbox.problem() if args.isolated else None
    if problem:
        print(f'grade_class.py: {problem}; nothing was graded', file=sys.stderr)
        return 2
    try:
        rubric = rubrics.load(default_rubric(), args.rubric)
    except rubrics.RubricError as e:
        print(f'grade_class.py: rubric: {e}', file=sys.stderr)
        return 2
    if args.gradescope:
        return grade_gradescope(args, rubric)
    return grade_one(args, rubric) if args.one else grade_class(args, rubric)
