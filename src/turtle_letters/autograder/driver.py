"""One student, from the folder they handed in to their row, stage by stage:

    find     submission.find      the lab's package in the folder
    run      session.run          built, launched on the grader's world, P typed, watched
    observe  observations.of_run  the drawing in what the grader's simulator recorded
    read     reading.page         the letters in its ink (a pen colour each, where as
                                  many; a frame or another line of writing left out
                                  where only so they read): the strokes, then OCR,
                                  then a longer row OCR read, read whole (_longer)
    alone    session.alone        executables started together that drew nothing of
                                  the letters, each run alone in a fresh world (a TA's try)
    score    rubric.grade         the points
    write    reports.write_student  results.json, log.txt, the picture and the ink

Each stage's failure is a value the next ones carry (a Step, a problem in
Facts), and the row says it. The grader's own failure on a submission
becomes that student's row, its traceback in their log.txt, never the
class's end. Nothing here knows of the others graded at once: `place`
(cli.Place) gives a sandbox and says whether grading was stopped.
"""
import time
import traceback

from ..isolation.files import shown
from ..reading.ocr import read_text, told_apart
from ..reading.page import Page, Writing, read_page
from . import observations as seen
from . import reports, rubric as rubrics, session, submission
from .roster import MAX_TEXT, Student


# s within which a stop asked (Ctrl-C) is noted by the grader. Ctrl-C reaches its
# process group: a helper in the instant before its own session (a mount making a
# sandbox) dies of it, and its failure must not be taken for the student's.
STOP_NOTED = 2.0


class Stopped(Exception):
    """Grading was stopped (Ctrl-C, SIGTERM) before this student was done."""


def grade(student: Student, rubric, out, place, warning=''):
    """The student's (row, facts), their files written; Stopped if grading
    stops first."""
    if place.stopping.is_set():
        raise Stopped()
    started = time.monotonic()
    with place.grading(student.id):
        facts, run, notes, error = _facts_or_failure(student, rubric, place)
    try:
        row = reports.Row(student.id, student.name, student.expected,               # score
                          rubrics.drawn_text(facts), rubrics.grade(facts, rubric),
                          time.monotonic() - started,
                          reports.leaderboard(facts, run.cpu_pct if run else None), None,
                          '; '.join(filter(None, [warning] + notes)))
        row = reports.write_student(out, row, facts, _log(run, facts, notes, error))  # write
        return row, facts
    except Exception as e:      # the grader failed even there (no space left): the row says so
        facts = failed(student, e)
        return reports.Row(student.id, student.name, student.expected, '',
                           rubrics.grade(facts, rubric), 0.0, [], None), facts


def likely_long(student: Student):
    """Whether the student's row is likely among a class's longest: their
    package starts several scripts together, each of which may run again
    alone (submission.started_together). Read from their files before any
    run; a folder the grader cannot read so is not (its row says why)."""
    if student.folder is None:
        return False
    try:
        return submission.started_together(submission.find(student.folder))
    except Exception:       # whatever it is, _facts_or_failure meets it and says so
        return False


def _log(run, facts, notes, error):
    """log.txt's sections: (title, text)."""
    sections = list(run.log) if run else [('submission', facts.problem)]
    sections += [('left out of the submission', '\n'.join(notes))] if notes else []
    return sections + ([("the grader's own error", error)] if error else [])


def _facts_or_failure(student, rubric, place):
    """(facts, run, notes, the grader's own error or '')."""
    try:
        return _facts(student, rubric, place) + ('',)
    except Stopped:
        raise
    except Exception as e:      # whatever the submission made the grader meet
        if place.stopping.wait(STOP_NOTED):
            raise Stopped() from None
        return failed(student, e), None, [], traceback.format_exc()


def _facts(student, rubric, place):
    """(facts, run, what of the submission was left out): the stages that
    run the submission."""
    if student.folder is None:
        return rubrics.Facts.never_ran(student.expected, 'no submission'), None, []
    package = submission.find(student.folder)                               # find
    if package.problem:
        return rubrics.Facts.never_ran(student.expected, package.problem), None, package.notes
    with place.sandbox() as box:
        run = session.run(package, rubric.limits, box, student.expected)    # run
        facts = observed(student.expected, run, rubric)                     # observe, read
        facts, run = each_alone(student.expected, rubric, box, facts, run)  # alone
    if box.stopped:
        raise Stopped()
    return facts, run, package.notes


def observed(expected, run, rubric):
    """The facts of one run: its steps, its drawing, the letters read in it."""
    drawing = seen.of_run(run, rubric.limits.settle)
    facts = rubrics.Facts.observed(expected, run, drawing, *read(drawing, expected))
    # a writer that never ended, stopped mid-word: as a TA watched it, a canvas it
    # wiped (Drawing.fullest), where one credits more letters than the canvas left
    for canvas in drawing.fullest if drawing else []:
        if len(rubrics.credited(facts)) == len(expected):
            break
        shown = seen.of_run(run, rubric.limits.settle, canvas)
        other = rubrics.Facts.observed(expected, run, shown, *read(shown, expected))
        if len(rubrics.credited(other)) > len(rubrics.credited(facts)):
            facts = other
    return facts


def read(drawing, expected):
    """(the letters read on the canvas, a reading.page.Page; OCR's reading
    of the writing they were read in, or None; the longer row it reads
    whole as, or ''): the strokes first (page.read_page: a letter in each
    pen colour where there are as many, else the row; a frame or another
    line of writing left out where only so they read); OCR, the slower
    reader, is asked only where the strokes do not read what was expected,
    or see another letter as plainly (told_apart); then, where the letters
    are not credited, the row of more letters OCR read (_longer)."""
    if drawing is None or not drawing.strokes:
        return Page([], Writing([], []), ''), None, ''
    page, ocr = _read_as(drawing, expected)
    return page, ocr, _longer(drawing, expected, page, ocr)


def _read_as(drawing, expected):
    page = read_page(drawing.strokes, drawing.looks, expected, drawing.homes)
    page = page._replace(readings=told_apart(page.writing.ink, page.readings))
    if rubrics.as_read(page.readings, expected).upper() == expected:    # a small l is an L
        return page, None
    return page, read_text(page.writing.ink, expected)


def _longer(drawing, expected, page, ocr):
    """OCR's text where it is more letters than `expected` (up to
    MAX_TEXT), `expected` is not credited, and the ink, read again as if
    a roster asked for that text, is credited it whole, as a row would be:
    a student who drew a row where one letter was asked is told so, not
    the letter nearest the row (a real class's LIT, where the roster asked
    for L: `no letter reads (closest: I)`). '' where not so. The letters
    asked for are never credited on it: a row drawn longer than expected
    is not searched for them."""
    if ocr is None or not len(expected) < len(ocr.text) <= MAX_TEXT or \
            len(rubrics.credited(rubrics.Facts.of_drawing(expected, drawing, page, ocr))) == \
            len(expected):
        return ''
    again = rubrics.Facts.of_drawing(ocr.text, drawing, *_read_as(drawing, ocr.text))
    return ocr.text if len(rubrics.credited(again)) == len(ocr.text) else ''


def reread(student_folder):
    """(the letter criterion's line in ID/results.json, '' where none is;
    its line now): the drawing the grader kept (reports.read_ink) read
    again as read() reads it, no student code run. Only the ink is read
    again: the rest of the row (built, launched, ended) stands as graded."""
    expected, drawing = reports.read_ink(student_folder)
    now = rubrics.letter_line(rubrics.Facts.of_drawing(expected, drawing,
                                                       *read(drawing, expected)))
    return reports.criterion_output(student_folder, rubrics.CRITERIA['letter'][0]), now


def each_alone(expected, rubric, box, facts, run):
    """A TA's try: executables started together (no launch file) that did
    not draw the letters run each alone in a fresh world, in a TA's order
    (session.drivers_first), limits.alone of them at most, until one draws
    them; the best (facts, run) kept, its launch step and log saying what
    the others drew (_not_kept). Not where one of them alone acted on the
    turtles: alone, it draws the same. The alone runs share one drawing's
    limit, each watched for what is left of it: a package whose nodes never
    stop costs the class two limits, not one for each node. The best is
    the one of most points, then of most letters read (_ranked)."""
    first, best = run, _ranked(facts, rubric)
    fought = len(first.executables) > 1 and not seen.one_driver(first.record)
    names = session.drivers_first(first, box)[:rubric.limits.alone] if fought else []
    left, tries = rubric.limits.drawing, []
    for i, name in enumerate(names):
        if box.stopped or len(rubrics.credited(facts)) == len(expected):
            break
        if left < rubric.limits.settle:
            facts = facts._replace(launch=session.untried(facts.launch, names[i:], rubric.limits))
            break
        tried = session.alone(first, name, rubric.limits._replace(drawing=left), box)
        left -= tried.watched_for()
        tried_facts = observed(expected, tried, rubric)
        rank = _ranked(tried_facts, rubric)
        tries.append((name, rubrics.drawn_text(tried_facts), rank[0], tried))
        if rank > best:
            facts, run, best = tried_facts, tried, rank
    return _not_kept(facts, run, tries, len(first.log))


def _ranked(facts, rubric):
    """A try's rank among each_alone's: its points, then the letters its
    drawing reads as (rubric.drawn_text): of two tries of equal points, the
    one whose ink a reader reads, as a TA keeps it (a real package's LIT,
    drawn by one script alone where L was asked, beside its run together,
    which OCR read LIV: 30 points each, and the row said what no letter reads)."""
    return rubrics.grade(facts, rubric).score, sum(c.isalpha() for c in rubrics.drawn_text(facts))


def _not_kept(facts, run, tries, shared):
    """(facts, run) kept of each_alone's `tries` (name, drawn, score, run),
    with what each other one drew said in its launch step, and its own log
    sections (those after the first `shared`, the run together's) in the
    kept run's log: a TA sees every try, not only the best."""
    others = [one_try for one_try in tries if one_try[3] is not run]
    if not others or facts.launch is None:
        return facts, run
    said = ', '.join(f'{name} alone drew {drawn or "no letter"} ({score:g} points)'
                     for name, drawn, score, _ in others)
    facts = facts._replace(launch=facts.launch._replace(
        says=f'{facts.launch.says}; also tried, not kept: {said}'))
    for name, _, _, tried in others:
        run.log += [(f'{name} alone, not kept: {title}', text)
                    for title, text in tried.log[shared:]]
    return facts, run


def failed(student, error):
    """The facts of a submission the grader itself failed on."""
    problem = f'the grader failed on this submission: {type(error).__name__}: {error}'
    return rubrics.Facts.never_ran(student.expected, shown(problem))
