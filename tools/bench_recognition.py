"""`make bench`'s recognition group: how well each reader reads letters as
people draw them, on a corpus made here. No ROS.

The corpus: capitals of the Hershey families in Debian's hershey-fonts-data
(roman simplex, duplex and triplex, italic, script, gothic), the outlines
of DejaVu's bold capitals (fonttools, fonts-dejavu-core), and the rotate-
and-move forms cadets draw (forms.VARIANTS); each at a random tilt
(+-45 degrees), aspect (0.5 to 2), size (0.5 m to the canvas) and place,
walked at a random speed in turtlesim's 16 ms steps; rows of 2 or 3 letters
touching or nearly. Each drawing is graded against its own letters,
against another letter or row at random, and against each text either
reader takes it for (its best-fitting letters, OCR's text) or may confuse
it with (one place's letter swapped for the one fitting it next best,
confusions()): a wrong letter
credited, the figure that must stay 0, is a drawing any letter of which is
credited where another was drawn (the whole text, or one letter in its
place: a row that does not read whole earns a share for each letter read
in place). Figures for the strokes' reader, OCR, and the two combined
as the grader combines them. `--drawings FILE` keeps each drawing's
verdict; `--against FILE` of an earlier run names the drawings whose
verdict a change moved, and any the corpus itself changed.
"""
import argparse
import json
import math
import multiprocessing
import random
import statistics
import string
import time

from turtle_letters.reading.forms import VARIANTS
from turtle_letters.reading.ink import turned
from turtle_letters.reading.ocr import read_text, supports, told_apart
from turtle_letters.reading.page import read_page
from turtle_letters.letters.hershey import load_font
from turtle_letters.letters.layout import SIM_TICK, WORLD_SIZE
from turtle_letters.letters.outlines import DEJAVU_BOLD, outline_glyphs

HERSHEY = ('rowmans', 'rowmand', 'rowmant', 'timesi', 'scripts', 'gothiceng')
TARGET_RIGHT, TARGET_WORST_S = 97.0, 1.0
READERS = ('strokes', 'ocr', 'both')


def corpus_fonts():
    """[(family, {letter: strokes})]: Hershey's, DejaVu's outlines, cadets' forms."""
    fonts = []
    for name in HERSHEY:
        font = load_font(name)
        fonts.append((name, {c: font.glyph(c).strokes for c in string.ascii_uppercase}))
    for path in DEJAVU_BOLD:
        fonts.append((path.rsplit('/', 1)[1][:-4] + ' outline', outline_glyphs(path)))
    fonts.append(('cadets', {letter: strokes for letter, strokes in VARIANTS}))
    return fonts


def walked(line, step):
    """A polyline as a turtle leaves it: a point every `step` m along it."""
    points = [line[0]]
    for a, b in zip(line, line[1:]):
        n = max(1, math.ceil(math.dist(a, b) / step))
        points += [(a[0] + (b[0] - a[0]) * i / n, a[1] + (b[1] - a[1]) * i / n)
                   for i in range(1, n + 1)]
    return points


def drawn(glyphs, text, rng):
    """`text` drawn as a cadet would: its letters side by side, touching or
    nearly, at a random size, aspect, tilt, place and speed."""
    aspect, gap = rng.uniform(0.5, 2.0), rng.uniform(-0.03, 0.08)
    ink, x = [], 0.0
    for letter in text:
        strokes = glyphs[letter]
        left = min(px for s in strokes for px, _ in s)
        ink += [[((px - left + x) * aspect, py) for px, py in s] for s in strokes]
        x += max(px for s in strokes for px, _ in s) - left + gap
    xs, ys = [p[0] for s in ink for p in s], [p[1] for s in ink for p in s]
    longest = max(max(xs) - min(xs), max(ys) - min(ys))
    size = rng.uniform(0.5, WORLD_SIZE - 1.0) / longest
    ink = [[((px - min(xs)) * size, (py - min(ys)) * size) for px, py in s] for s in ink]
    ink = turned(ink, rng.uniform(-45, 45), (0.0, 0.0))
    step = rng.uniform(0.5, 2.0) * SIM_TICK
    return [walked(line, step) for line in ink]


def readers(ink, expected):
    """(the letters the strokes read, '?' for none; the letters the grader
    credits them with, OCR telling apart two letters they see cleanly
    (ocr.told_apart); whether OCR read the text; seconds of each; the texts
    the two take the ink for or may confuse it with (confusions), where not
    `expected`), both asked: the figures
    of each alone. (The grader asks OCR only where the strokes do not read
    the expected text: the two combined count its time only there.)"""
    started = time.monotonic()
    page = read_page(ink, [], expected)     # as the grader reads: the row, else its lines
    readings = page.readings
    told = told_apart(page.writing.ink, readings)   # timed with the strokes: the grader asks
    middle = time.monotonic()
    ocr = read_text(page.writing.ink, expected)
    seconds = (middle - started, time.monotonic() - middle)
    taken = {_letters(readings, guessed=True), ocr.text, *confusions(readings, expected)}
    taken = {text for text in taken if len(text) == len(expected) and text.isalpha()}
    return _letters(readings), _letters(told), supports(ocr, expected, told), seconds, \
        taken - {expected}


def confusions(readings, expected):
    """`expected` with the letter of one place swapped for the one that
    fits the ink there best after it (`readings`: the strokes'), a text
    for each place: the likeliest letter a roster may say that was not
    drawn there, read or not."""
    texts = []
    for k, (reading, letter) in enumerate(zip(readings, expected)):
        rivals = sorted((fit.fit, other) for other, fit in reading.fits.items() if other != letter)
        texts += [expected[:k] + rivals[0][1] + expected[k + 1:]] if rivals else []
    return texts


def _letters(readings, guessed=False):
    """The letters read, '?' for none (`guessed`: the best-fitting letter instead)."""
    return ''.join(r.letter or (r.best.letter if guessed and r.best else '?') for r in readings)


def wrong_in_place(read, drawn, other):
    """Whether a letter of `other` is credited in its place where `drawn`
    has another: the grader credits each letter the strokes read in place
    (the rest of a row that does not read whole earns its share)."""
    return any(r == o != d for r, o, d in zip(read, other, drawn))


def credited_wrongly(ink, text, other):
    """(by the strokes, by OCR, by the strokes as the grader credits them):
    whether `ink`, a drawing of `text`, graded against `other`, earns a
    letter it does not draw."""
    read, told, ocr, _, _ = readers(ink, other)
    return wrong_in_place(read, text, other), ocr, wrong_in_place(told, text, other)


_fonts = []     # each worker's corpus fonts, loaded once


def read_drawings(path):
    """The records of a --drawings FILE; ValueError naming the first line that is none."""
    drawings = []
    with open(path) as lines:
        for number, line in enumerate(lines, 1):
            try:
                drawing = json.loads(line)
                fields = {'n', 'family', 'texts', *READERS} <= set(drawing)
            except (ValueError, TypeError):
                fields = False
            if not fields:
                raise ValueError(f"line {number} is not a drawing's record of --drawings")
            drawings.append(drawing)
    return drawings


def one_drawing(job):
    """Drawing n of the corpus (its own random stream, whatever the
    workers), read against its own text, against another at random, and
    against each text the readers take it for (a cadet's D read as an O is
    graded against an O where the roster says O): (family, the texts it
    was wrong against, and each reader's right, wrong and seconds)."""
    n, singles, seed = job
    if not _fonts:
        _fonts.extend(corpus_fonts())
    rng = random.Random(seed * 1000003 + n)
    family, glyphs = _fonts[n % len(_fonts)]
    letters = sorted(glyphs)
    text = ''.join(rng.choice(letters) for _ in range(1 if n < singles else rng.choice((2, 3))))
    other = text
    while other == text:
        other = ''.join(rng.choice(string.ascii_uppercase) for _ in text)
    ink = drawn(glyphs, text, rng)
    read, told, o, (s_time, o_time), taken = readers(ink, text)
    wrong = {against: credited_wrongly(ink, text, against) for against in {other} | taken}
    ws = [against for against, (by_strokes, _, _) in wrong.items() if by_strokes]
    wo = [against for against, (_, by_ocr, _) in wrong.items() if by_ocr]
    wt = [against for against, (_, _, by_told) in wrong.items() if by_told]
    s = read == text
    return family, f'{text} as {"/".join(sorted(set(wt + wo)) or [other])}', {
        'strokes': (s, bool(ws), s_time), 'ocr': (o, bool(wo), o_time),
        'both': (told == text or o, bool(wt or wo), s_time + (0.0 if told == text else o_time))}


def recognition_run(singles=2000, rows=500, seed=1, jobs=1, drawings=None):
    """The corpus read, `jobs` drawings at a time (each reader's time is
    measured while the others read too); each drawing's record (record())
    appended to the list `drawings`, if given."""
    tally = {name: dict(right=0, wrong=0, seconds=[]) for name in READERS}
    by_family, wrongs = {}, []
    work = [(n, singles, seed) for n in range(singles + rows)]
    with multiprocessing.Pool(jobs) as pool:
        for n, (family, texts, results) in enumerate(pool.imap(one_drawing, work, chunksize=8)):
            if drawings is not None:
                drawings.append(record(n, family, texts, results))
            for name, (right, wrong, seconds) in results.items():
                tally[name]['right'] += right
                tally[name]['wrong'] += wrong
                tally[name]['seconds'].append(seconds)
            wrongs += [f'drawing {n}, {family} {texts}'] if results['both'][1] else []
            by_family.setdefault(family, []).append(results['both'][0])
    total = singles + rows
    return dict(singles=singles, rows=rows, wrongs=wrongs, readers={
        name: dict(right_pct=100 * t['right'] / total, wrong_pct=100 * t['wrong'] / total,
                   median_s=statistics.median(t['seconds']), worst_s=max(t['seconds']))
        for name, t in tally.items()},
        families={f: 100 * sum(r) / len(r) for f, r in by_family.items()})


def record(n, family, texts, results):
    """Drawing n's outcome, as a line of a --drawings file: its family, its
    text and what it was graded against, and each reader's verdict."""
    return dict(n=n, family=family, texts=texts, **{
        name: dict(right=right, wrong=wrong, seconds=round(seconds, 4))
        for name, (right, wrong, seconds) in results.items()})


def changes(before, after):
    """Lines for the drawings whose verdict differs between two runs'
    records, by drawing number: a reading changed, or the corpus did (a
    drawing of another text: a form added after a letter's last one in
    forms.VARIANTS changes the cadets' drawings, and every figure with them)."""
    old = {d['n']: d for d in before}
    lines = []
    for d in after:
        was = old.get(d['n'])
        if was is None:
            continue
        if _drawn(was) != _drawn(d):
            lines.append(f"drawing {d['n']}: the corpus changed ({was['family']} {_drawn(was)} "
                         f"is now {d['family']} {_drawn(d)})")
            continue
        moved = [f'{name} {_verdict(d[name])} (was {_verdict(was[name])})' for name in READERS
                 if _verdict(d[name]) != _verdict(was[name])]
        if moved:
            lines.append(f"drawing {d['n']}, {d['family']} {d['texts']}: " + '; '.join(moved))
    return lines


def _drawn(drawing):
    return drawing['texts'].split(' as ')[0]


def _verdict(reader):
    return ('read right' if reader['right'] else 'not read') + \
        (', a wrong letter credited' if reader['wrong'] else '')


def recognition_lines(results):
    run = results.get('recognition')
    if not run:
        return []
    lines = [f"recognition, {run['singles']} single letters and {run['rows']} rows of 2 or 3 "
             f"(tilt +-45, aspect 0.5-2, 0.5 m to the canvas, touching neighbours):"]
    for name, r in run['readers'].items():
        lines.append(
            f"  {name:8s} read right {r['right_pct']:5.1f}%{'!' if r['right_pct'] < TARGET_RIGHT else ''}"
            f", wrong letter credited {r['wrong_pct']:.2f}%{'!' if r['wrong_pct'] else ''}, "
            f"per drawing median {r['median_s']:.3f} s, worst {r['worst_s']:.2f} s"
            f"{'!' if r['worst_s'] > TARGET_WORST_S else ''}")
    lines.append('  read right by both together, by family: ' + ', '.join(
        f'{family} {pct:.0f}%' for family, pct in run['families'].items()))
    lines += [f'  wrong letter credited: {wrong}' for wrong in run.get('wrongs', [])]
    lines.append('  (the strokes reader holds rowmand, rowmant, timesi, scripts, gothiceng and the '
                 "cadets' forms among its own candidates; rowmans and DejaVu's outlines it has "
                 'never seen)')
    return lines


if __name__ == '__main__':
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('singles', type=int, nargs='?', default=2000)
    parser.add_argument('rows', type=int, nargs='?', default=500)
    parser.add_argument('--jobs', type=int, default=1, help='drawings read at a time')
    parser.add_argument('--drawings', metavar='FILE',
                        help="write each drawing's verdict to FILE, a JSON object a line "
                             '(opened before the run: a path that cannot be written stops it)')
    parser.add_argument('--against', metavar='FILE',
                        help="a --drawings FILE of an earlier run of the same corpus: print "
                             'the drawings whose verdict changed since')
    args = parser.parse_args()
    try:
        before = read_drawings(args.against) if args.against else None
    except (OSError, ValueError) as e:
        parser.error(f'--against {args.against}: {e}')
    try:    # after --against is read: the two may be one file
        out = open(args.drawings, 'w') if args.drawings else None
    except OSError as e:
        parser.error(f'--drawings {args.drawings}: {e}')
    drawings = []
    run = recognition_run(args.singles, args.rows, jobs=args.jobs, drawings=drawings)
    for line in recognition_lines({'recognition': run}):
        print(line)
    if out is not None:
        with out:
            out.writelines(json.dumps(d) + '\n' for d in drawings)
    if before is not None:
        moved = changes(before, drawings)
        print(f'changed since {args.against}: {len(moved)} of {len(drawings)} drawings')
        for line in moved:
            print(f'  {line}')
