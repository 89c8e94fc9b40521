"""`grade_class.py`: a class's lab packages graded as handed in.

    grade_class.py SUBMISSIONS --roster ROSTER.csv --out OUT [--jobs N] [--rubric FILE]
    grade_class.py --one FOLDER --name NAME [--letter L] --out OUT   (exit 0 pass, 1 fail)
    grade_class.py --gradescope           (/autograder/submission to results/results.json)
    grade_class.py --reread OUT           (the drawings kept in OUT read again: no code run)

Here: the arguments, the pool (N students at a time, the likely longest
first, each in a slot of its own: a user, a core), the progress, the
signals and the class's files.
How one student becomes their row is driver.py's, stage by stage. The
grader's own failure on one submission is that student's row, never the
class's. Exit 0 once every student has a
row, 2 on input that stops grading before anything runs, 130 (Ctrl-C) or
143 (SIGTERM) when stopped: every sandbox ended, the class files written
for the students graded so far and marked incomplete.
"""
import argparse
import concurrent.futures
import contextlib
import ctypes
import json
import os
import queue
import shutil
import signal
import sys
import tempfile
import threading
import time

import rospkg

from ..isolation.files import shown
from ..isolation import sandbox, stale
from . import driver, reports, rubric as rubrics, session
from .roster import RosterError, Student
from .roster import expected as expected_of
from .roster import read as read_roster

GRADESCOPE = '/autograder'
PR_SET_CHILD_SUBREAPER = 36      # linux/prctl.h


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
    parser.add_argument('--reread', metavar='OUT',
                        help='read again the drawings a grading kept in OUT (OUT/ID/ink.json), '
                             'running no student code: where does a letter read differently now?')
    args = parser.parse_args(argv)
    modes = [bool(args.submissions), bool(args.one), args.gradescope, bool(args.reread)]
    if sum(modes) != 1:
        parser.error('give SUBMISSIONS with --roster, or --one FOLDER, or --gradescope, '
                     'or --reread OUT')
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


def default_limits():
    """The package rubric's limits, as the grader uses them without --rubric."""
    return rubrics.load(default_rubric()).limits


class Place:
    """Where submissions run: what they must not see, whether in a sandbox,
    and a slot each for the `jobs` graded at once: a user of its own and a
    core (alone: a core too, so that a grade does not depend on who is
    graded beside it); the sandboxes running, for `stop` to end them, and
    who is being graded."""

    def __init__(self, hidden, isolated, jobs, caps):
        self.hidden, self.isolated, self.caps = hidden, isolated, caps
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
        every sandbox whole in `boxes`, never one half made or half gone.
        The grader's own thread is held to the slot's core meanwhile: its
        reading (seconds of a core, Tesseract's too) never takes the core
        another student's timed drawing runs on."""
        slot, cpu = self.slots.get()
        box = sandbox.Sandbox(self.caps, self.hidden, self.isolated, cpu, slot=slot)
        cores = os.sched_getaffinity(0)     # this thread's, on Linux
        try:
            os.sched_setaffinity(0, {cpu})
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
            os.sched_setaffinity(0, cores)
            self.slots.put((slot, cpu))

    @contextlib.contextmanager
    def grading(self, student_id):
        """`student_id` among those being graded (the progress bar shows them)."""
        with self.lock:
            self.current.append(student_id)
        try:
            yield
        finally:
            with self.lock:
                self.current.remove(student_id)

    def stop(self):
        """Every sandbox running ended now, and none started after."""
        self.stopping.set()
        with self.lock:
            boxes = list(self.boxes)
        for box in boxes:
            box.stop()


def ready_to_paint():
    """Qt's application, made in the main thread as Qt wants, so that each
    student's picture is painted in their own thread (reports.picture)."""
    from ..grading.picture import application
    application()


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
    """(every student's row in roster order, `args.jobs` at a time, the
    likely longest first (grading_order); the signal's name if Ctrl-C or
    SIGTERM stopped it, with only the rows done). Each row is printed as
    it is done."""
    warnings = warnings or {}
    place = Place(hidden, args.isolated, args.jobs, session.caps(rubric.limits))
    ready_to_paint()
    progress, rows, asked = Progress(len(students), place), {}, []
    before = _on_signal(_first_stop(place, asked))     # before any student starts
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs)
    try:
        futures = {pool.submit(driver.grade, students[i], rubric, out, place,
                               warnings.get(students[i].id, '')): i
                   for i in grading_order(students)}
        waiting = set(futures)
        while waiting and not asked:
            done, waiting = concurrent.futures.wait(
                waiting, timeout=0.2, return_when=concurrent.futures.FIRST_COMPLETED)
            for future in done:
                if isinstance(future.exception(), driver.Stopped):    # a stop just asked
                    continue
                rows[futures[future]] = _finished(future.result(), progress, args.isolated)
                # each row kept as it comes: a grader killed outright keeps what it graded
                reports.write_csv(os.path.join(out, 'grades.csv'), [rows[j] for j in sorted(rows)])
        if asked:
            print(f'\ngrade_class.py: {asked[0]}: stopping (again to force)', file=sys.stderr,
                  flush=True)
            place.stop()
            for future in futures:
                future.cancel()
    finally:
        place.stopping.set()
        pool.shutdown(wait=True)
        _on_signal(*before)
    for future, i in futures.items():    # done while it stopped: they count
        if i not in rows and future.done() and not future.cancelled() and \
                future.exception() is None:
            rows[i] = _finished(future.result(), progress, args.isolated)
    progress.close()
    return [rows[i] for i in sorted(rows)], (asked[0] if asked else '')


def grading_order(students):
    """The roster's places in the order they are graded: first those whose
    row is likely long (driver.likely_long: several scripts started
    together, then each alone), then the rest, each part in roster order,
    so that no long row is left for the end, the other jobs idle beside it.
    Which rows run longest is known only as they run: a drawing that never
    ends, or one slow to draw, may still come last."""
    long = [driver.likely_long(student) for student in students]
    return sorted(range(len(students)), key=lambda i: not long[i])


def _finished(graded, progress, isolated):
    row, _ = graded
    progress.row(said(row, isolated))
    return row


def _on_signal(handler, on_term=None):
    """`handler` for Ctrl-C and SIGTERM (or `on_term` for it); the handlers
    they had. (SIG_DFL is 0: `on_term or handler` once gave SIGTERM Ctrl-C's
    handler back, and under nohup, where Ctrl-C is ignored, ignored SIGTERM
    in the grader and every child it started after.)"""
    return signal.signal(signal.SIGINT, handler), \
        signal.signal(signal.SIGTERM, handler if on_term is None else on_term)


def _interrupt(number, _):
    raise KeyboardInterrupt(signal.Signals(number).name)


def _first_stop(place, asked):
    """Ctrl-C or SIGTERM while grading: its name put in `asked`, which
    grade_all checks between rows; the next one forces, from now on. (An
    exception raised here could land anywhere in the main thread, even in
    the pool's own bookkeeping, between a thread's start and its record:
    the pool then did not wait for that student.)"""
    def first(number, _):
        asked.append(signal.Signals(number).name)
        _on_signal(_force(place))
    return first


def _force(place):
    """A second Ctrl-C: end what runs and remove the sandboxes at once, and leave."""
    def force(number, _):
        print('grade_class.py: forced: no class files written', file=sys.stderr, flush=True)
        _adopt_orphans()
        place.stop()
        with place.lock:        # every sandbox whole: none is being made or removed now
            for box in place.boxes:
                box.__exit__(None, None, None)
            _reap_children()
            sandbox.wait_reaped(set().union(*(box.users() for box in place.boxes)))
            os._exit(128 + number)
    return force


def _adopt_orphans():
    """The grader made the reaper of its descendants left without a parent
    (PR_SET_CHILD_SUBREAPER): a sandbox's own init, its bubblewrap killed,
    then ends as the grader's child, and only once all in it have ended."""
    ctypes.CDLL(None, use_errno=True).prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)


def _reap_children(seconds=10.0):
    """Waits for the children just killed and the orphans adopted, so that
    none is left for init to reap (a slow init shows them a while longer;
    CI once saw a sandbox's process still ending as the grader left)."""
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
    """A row for every student in roster order: `rows`, and for each student
    grading stopped before, a row that says so. (With two jobs a later
    student may finish before an earlier one that was stopped.)"""
    graded = {row.id: row for row in rows}
    return [graded.get(s.id) or reports.not_graded(
        s.id, s.name, s.expected, f'grading was stopped ({stopped}) before this student was graded')
        for s in students]


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


def reread_class(out):
    """--reread OUT: each drawing kept in OUT read again (driver.reread), its
    letter criterion printed as it reads now, beside what it said where that
    differs. Exit 0; 1 where a kept file is no drawing (its line says so, the
    others are read); 2 where OUT keeps none. No root, no sandbox: no code runs."""
    kept = sorted(name for name in (os.listdir(out) if os.path.isdir(out) else [])
                  if os.path.isfile(os.path.join(out, name, reports.INK_FILE)))
    if not kept:
        print(f'grade_class.py: no drawing kept in {out} (no {out}/ID/{reports.INK_FILE}): '
              f'give the --out folder of a grading', file=sys.stderr)
        return 2
    changed = broken = 0
    for name in kept:
        try:
            was, now = driver.reread(os.path.join(out, name))
        except (OSError, ValueError, KeyError, TypeError) as e:   # a file cut short, or edited
            broken += 1
            print(f'{name}: not read again: {reports.INK_FILE} is no drawing the grader kept '
                  f'({type(e).__name__}: {e})')
            continue
        if now == was:
            print(f'{name}: as graded: {now}')
        else:
            changed += 1
            print(f'{name}: now: {now}\n{" " * len(name)}  was: {was or "(no results.json)"}')
    read = len(kept) - broken
    print(f'{read} drawing{"" if read == 1 else "s"} read again, {changed} read differently '
          f'now' + (f'; {broken} not read (above)' if broken else ''))
    return 1 if broken else 0


def main(argv=None):
    args = arguments(sys.argv[1:] if argv is None else argv)
    if args.reread:
        return reread_class(args.reread)
    _on_signal(_interrupt)      # SIGTERM stops grading as Ctrl-C does
    try:
        return _checked_and_graded(args)
    except KeyboardInterrupt as stopped:    # before grading, or while its files are written
        _on_signal(signal.SIG_IGN)          # it is leaving: another Ctrl-C changes nothing
        print(f'\ngrade_class.py: {stopped}: stopped', file=sys.stderr)
        return EXIT[str(stopped)]


def _checked_and_graded(args):
    """The sandbox tried and what earlier graders left removed, each whole
    (Ctrl-C held meanwhile: a second one once left the trial's namespace
    and mount), then the class or the one submission graded."""
    with _signals_held():
        problem = sandbox.problem() if args.isolated else None
        swept = stale.sweep() if args.isolated and not problem else ''
    if problem:
        print(f'grade_class.py: {problem}; nothing was graded', file=sys.stderr)
        return 2
    if swept:
        print(f'grade_class.py: {swept}', file=sys.stderr)
    try:
        rubric = rubrics.load(default_rubric(), args.rubric)
    except rubrics.RubricError as e:
        print(f'grade_class.py: rubric: {e}', file=sys.stderr)
        return 2
    if args.gradescope:
        return grade_gradescope(args, rubric)
    return grade_one(args, rubric) if args.one else grade_class(args, rubric)


@contextlib.contextmanager
def _signals_held():
    """Ctrl-C and SIGTERM noted while the block runs, and raised once it
    has ended. (Blocking them does not do: a thread of a library's that
    leaves them unblocked takes them, and the main thread still raises.)"""
    noted = []
    before = _on_signal(lambda number, _: noted.append(signal.Signals(number).name))
    try:
        yield
    finally:
        _on_signal(*before)
    if noted:
        raise KeyboardInterrupt(noted[0])
