"""Which letter of A-Z a path draws, at any size, place and aspect. No ROS.

Each candidate (each form of a letter, forms.py) is stretched onto the
path's box, its height and width each on its own, and the two are compared both ways: how far the path strays from
the candidate's strokes, and how far the strokes are from anything drawn.
The worse of the two, as a share of the letter's height, is the fit; the
best-fitting candidate is the letter, if its fit is at most READABLE.
What is read is ink: the unbroken lines a turtle drew with its pen down,
as many as there are. Travel with the pen up is no part of it; a cadet who
retraces strokes to reach the next one loses nothing either, since
retraced ink lies on the strokes.
"""
import math
import string
from typing import Dict, List, NamedTuple, Optional

import numpy
from scipy.ndimage import distance_transform_edt

from .forms import READABLE, Point, grid_rows, templates
from .ink import CELL, WIDEST, box, outline, sampled, samples, thinned, turned

LEVEL = 0.03        # a fit this good level is not tried tilted
TILTS = (-45, -35, -25, -15, -10, -5, 5, 10, 15, 25, 35, 45)    # degrees a letter is tried off level
NEAR_TILTS = (-10, -5, 5, 10)   # ... when only finding where to cut a row
FINER = (5.0, 2.5)  # then degrees either way of the best tilts, in turn
REFINED = 3         # the best-fitting letters whose tilts are tried finer
MOST_TILT = max(TILTS) + sum(FINER)     # degrees off level a letter is read at, at most
GAP = 0.1           # clear space between two letters' ink, share of the height of the row
SPECK = 0.1         # ink set apart, smaller than this share of all the ink's extent: a speck, no letter
SHORT = 0.5         # a letter of a row less high than this share of the row is unfinished, no letter
SAMPLE = 0.02       # share of the height between compared points
HOPELESS = READABLE  # a candidate straying farther is not fitted exactly: it cannot read
MAX_STRETCH = 3.0   # how far a candidate's width-to-height may be changed, either way


class Fit(NamedTuple):
    letter: str
    fit: float                  # the worst deviation, as a share of the path's height
    strokes: List[List[Point]]  # the candidate on the path's box, m
    tilt: float = 0.0           # degrees counter-clockwise the ink lies off level
    readable: float = READABLE  # the fit within which this candidate reads


class Reading(NamedTuple):
    letter: Optional[str]       # None: no letter reads well enough
    best: Optional[Fit]         # the best-fitting candidate, read or not
    fits: Dict[str, Fit]        # the best fit of each letter


def placed(strokes, path_box):
    """`strokes` stretched onto `path_box`, keeping their width-to-height
    within MAX_STRETCH of their own (a line is not every letter squashed)."""
    x0, y0, w0, h0 = box([p for s in strokes for p in s])
    x, y, w, h = path_box
    aspect = min(max(w / h, w0 / h0 / MAX_STRETCH), w0 / h0 * MAX_STRETCH)
    width, left = aspect * h, x + (w - aspect * h) / 2
    across = width / w0 if w0 else 0.0      # a candidate of no width (a plain I) stays a line
    return [[(left + (px - x0) * across, y + (py - y0) / h0 * h) for px, py in s]
            for s in strokes]


class Distances:
    """How far each spot from x `lo` to `hi` of a box of height 1 lies
    from some points, to a grid of CELL (scipy's Euclidean distance
    transform)."""

    def __init__(self, xs, ys, lo, hi):
        self.lo = lo
        self.grid = numpy.ones((int(1 / CELL) + 3, int((hi - lo) / CELL) + 3), dtype=bool)
        self.grid[self.rows(ys), self.cols(xs)] = False
        self.grid = distance_transform_edt(self.grid) * CELL

    def rows(self, ys):
        return numpy.clip(grid_rows(ys), 0, self.grid.shape[0] - 1)

    def cols(self, xs):
        return numpy.clip(numpy.rint((xs - self.lo) / CELL).astype(int) + 1, 0, self.grid.shape[1] - 1)


class Fitting:
    """The candidates of some letters on one drawing's box: how far each
    strays from the ink (a bound, cheap for all of them at once) and its
    fit (both ways, as read() takes it) for those worth it. A candidate
    kept narrower than MAX_STRETCH allows may be wider than the box: the
    grids reach as far as the widest."""

    def __init__(self, drawn, aspect, letters):
        t = templates()
        self.drawn, self.choice = drawn, t.of(letters)
        own = numpy.array(t.aspects)[self.choice.chosen]
        width = numpy.clip(aspect, own / MAX_STRETCH, own * MAX_STRETCH)
        across = numpy.divide(width, own, out=numpy.zeros_like(own), where=own > 0)
        slot = self.choice.slot
        self.xs = ((aspect - width) / 2)[slot] + self.choice.xs * across[slot]
        self.lo, self.hi = min(0.0, (aspect - width.max()) / 2), max(aspect, (aspect + width.max()) / 2)
        self.ink = Distances(drawn[:, 0], drawn[:, 1], self.lo, self.hi)

    @property
    def chosen(self):
        return self.choice.chosen

    def bounds(self):
        """Each candidate's farthest point from the ink: its fit is no less."""
        rows = numpy.clip(self.choice.rows, 0, self.ink.grid.shape[0] - 1)
        return numpy.maximum.reduceat(self.ink.grid[rows, self.ink.cols(self.xs)],
                                      self.choice.starts[:-1])

    def fit(self, i, bound):
        """Candidate i's fit: the worse of its bound and how far the ink strays from it."""
        part = slice(self.choice.starts[i], self.choice.starts[i + 1])
        shape = Distances(self.xs[part], self.choice.ys[part], self.lo, self.hi)
        return max(bound, float(shape.grid[shape.rows(self.drawn[:, 1]),
                                           shape.cols(self.drawn[:, 0])].max()))


def _fits(ink, letters, beat=None):
    """Each letter's best fit to `ink`, as it lies; of a letter whose
    candidates all stray farther than `beat`'s fit of it (or than
    HOPELESS), the bound only, marked so."""
    points = [p for line in ink for p in line]
    x, y, w, h = box(points)
    if w > WIDEST * h:
        return {}
    drawn = (sampled([line for line in ink if line], CELL * h / 2) - (x, y)) / h
    fitting = Fitting(drawn, w / h, letters)
    bounds = fitting.bounds()
    fits: Dict[str, Fit] = {}
    for i in numpy.argsort(bounds):
        letter, strokes, readable = templates().candidates[fitting.chosen[i]]
        best = fits[letter].fit if letter in fits else math.inf
        if bounds[i] >= best:
            continue
        worth = bounds[i] <= HOPELESS and (beat is None or letter not in beat or
                                           bounds[i] < beat[letter].fit)
        if worth or letter not in fits:
            fit = fitting.fit(i, bounds[i]) if worth else float(bounds[i])
            if fit < best:
                fits[letter] = Fit(letter, fit, placed(strokes, (x, y, w, h)), 0.0, readable)
    return fits


def read(ink, letters=string.ascii_uppercase, tilts=TILTS, finer=FINER) -> Reading:
    """The letter of `letters` that `ink` (lines of (x, y), m) draws, best
    fit first; ink that fits no letter well level is tried turned back by
    each of TILTS, then by `finer` steps around the tilts that fit best
    (a wide letter 5 degrees off strays a tenth of its height); its fits
    keep the tilt (their strokes turned with it)."""
    points = [p for line in ink for p in line]
    if len(points) < 2 or box(points)[3] <= 0:
        return Reading(None, None, {})
    ink = outline(ink) or ink       # an outline is read by its middle line
    points = [p for line in ink for p in line]
    ink = thinned(ink, SAMPLE * box(points)[3] / 2)
    fits = _fits(ink, letters)
    if min((f.fit for f in fits.values()), default=math.inf) > LEVEL:
        x, y, w, h = box(points)
        centre = (x + w / 2, y + h / 2)
        done = {0.0} | set(tilts)
        _tried(ink, letters, fits, tilts, centre)
        for step in finer:
            if min((f.fit for f in fits.values()), default=math.inf) <= LEVEL:
                break
            near = {f.tilt for f in sorted(fits.values(), key=lambda f: f.fit)[:REFINED]
                    if f.fit <= 2 * f.readable}
            more = sorted({t + d for t in near for d in (-step, step)} - done)
            done |= set(more)
            _tried(ink, letters, fits, more, centre)
    best = min(fits.values(), key=lambda f: f.fit, default=None)
    letter = best.letter if best is not None and best.fit <= best.readable else None
    return Reading(letter, best, fits)


def _tried(ink, letters, fits, tilts, centre):
    """`fits` bettered by the ink turned back by each of `tilts`, about `centre`."""
    for tilt in tilts:
        level = turned(ink, -tilt, centre)
        if box([p for line in level for p in line])[3] <= 0:
            continue
        for letter, fit in _fits(level, letters, fits).items():
            if fit.fit < fits.get(letter, fit._replace(fit=math.inf)).fit:
                fits[letter] = fit._replace(strokes=turned(fit.strokes, tilt, centre), tilt=tilt)


def apart(ink):
    """The ink's letters, left to right: lines whose spans across overlap,
    or lie less than GAP of the row's height apart, are one letter's."""
    lines = sorted((line for line in ink if line), key=lambda line: min(p[0] for p in line))
    if not lines:
        return []
    height = box([p for line in lines for p in line])[3]
    groups = []         # [lines, right edge]
    for line in lines:
        left, right = min(p[0] for p in line), max(p[0] for p in line)
        if groups and left <= groups[-1][1] + GAP * height:
            groups[-1][0].append(line)
            groups[-1][1] = max(groups[-1][1], right)
        else:
            groups.append([[line], right])
    return [group for group, _ in groups]


def columns(ink, cuts, overlap=0.0):
    """The ink split at the x of each of `cuts` (ascending): each line's
    parts between two cuts, as the letters between them; a part reaches
    `overlap` past its cuts (a stroke two touching letters share, an M's
    last leg as an F's stem, is each letter's)."""
    bounds = list(zip([-math.inf] + list(cuts), list(cuts) + [math.inf]))
    letters = []
    for lo, hi in bounds:
        parts = []
        for line in ink:
            run = []
            for p in line:
                if lo - overlap < p[0] <= hi + overlap:
                    run.append(p)
                elif run:
                    parts.append(run)
                    run = []
            if run:
                parts.append(run)
        letters.append(parts)
    return letters


def cut(ink, expected, ahead=True):
    """Where to cut the ink into the letters of `expected` side by side, its
    letters touching (a Z's foot run on into an A's leg): each cut, left to
    right, between 0.4 and 1.6 of an even share of the row, where the part
    before it fits its expected letter best and, `ahead`, the part after it
    fits the next letter too (the last cut: the rest as the last letter;
    an earlier one: the next even share). The ink (finely sampled) and the cuts."""
    height = box([p for line in ink for p in line])[3]
    fine = [samples([line], SAMPLE * height / 2) for line in ink if line]
    x0, _, width, _ = box([p for line in fine for p in line])
    share, cuts, left = width / len(expected), [], x0 - 1e-9     # a part is (left, right]
    for k, letter in enumerate(expected[:-1]):
        def fit(x):
            before = _fit_before(fine, left, x, letter)
            if not ahead:
                return before
            last = k == len(expected) - 2
            return max(before, _fit_before(fine, x, x0 + width + 1 if last else x + share,
                                           expected[k + 1]))
        # every tenth of a share, then the twentieths beside the best of those
        options = [left + share * (0.4 + 0.1 * i) for i in range(13)]
        options = [x for x in options if x < x0 + width] or [left + share]
        fits = [(fit(x), x) for x in options]
        nearest = min(fits)[1]
        fits += [(fit(x), x) for x in (nearest - share / 20, nearest + share / 20)
                 if left < x < x0 + width]
        best = min(f for f, _ in fits)
        # of the cuts that fit as well (to a hundredth), the one through the least ink
        cuts.append(min((x for f, x in fits if f <= best + 0.01),
                        key=lambda x: sum(abs(p[0] - x) < share / 40 for line in fine for p in line)))
        left = cuts[-1]
    return fine, cuts


def _fit_before(ink, left, right, letter):
    part = columns(ink, [left, right])[1]
    reading = read(part, letter, NEAR_TILTS, ()) if part else None
    return reading.best.fit if reading is not None and reading.best is not None else math.inf


def letters_of(ink, expected, ahead=True):
    """The ink's letters, left to right, each as (its ink alone, its ink
    reaching SAMPLE of the height past its cuts: a stroke two touching
    letters share, an M's last leg as an F's stem, is each letter's): set
    apart by GAP, or where fewer are set apart than `expected` has, cut
    (cut(), looking `ahead` or not)."""
    groups = apart(ink)
    if len(expected) < 2 or len(groups) >= len(expected):
        return [(group, group) for group in groups]
    fine, cuts = cut([line for group in groups for line in group], expected, ahead)
    height = box([p for line in fine for p in line])[3]
    return list(zip(columns(fine, cuts), columns(fine, cuts, SAMPLE * height)))


def row_tilts(ink):
    """Degrees a row of letters may lie off level, the likelier first: the
    turn within 50 degrees of level, in steps of 5, that leaves the row
    least high (a row is level where its letters stand side by side), then 0."""
    points = numpy.array([p for line in ink for p in line])
    if len(points) < 3:
        return [0]
    angles = numpy.radians(numpy.arange(-50, 55, 5))
    heights = [numpy.ptp(points[:, 1] * math.cos(a) - points[:, 0] * math.sin(a)) for a in angles]
    slope = int(round(math.degrees(angles[int(numpy.argmin(heights))])))
    return ([slope] if slope else []) + [0]


def read_row(ink, expected='') -> List[Reading]:
    """The letters `ink` draws, left to right: the whole read as one when
    one letter is expected, else each letter set apart by GAP read alone;
    where fewer are set apart than expected, the ink is cut into them, and
    a letter cut is its expected letter if it reads so alone or with the
    strokes it shares. A row that does not read so level is read turned
    back by its slope (row_tilts). The cuts only find the letters; a
    reading of all the letters says what each is. Specks are no part of
    it (without_specks), and a letter of a row less than SHORT of the
    row's height reads as no letter (unfinished: a quarter of an S's curve
    beside a whole U is no I)."""
    ink = without_specks(ink)
    count = len(expected) if isinstance(expected, str) else expected
    if count <= 1:
        return [read(ink)]
    if not isinstance(expected, str):
        return [_of_row(group, ink) for group in apart(ink)]
    points = [p for line in ink for p in line]
    x, y, w, h = box(points)
    centre, best = (x + w / 2, y + h / 2), None
    for tilt in row_tilts(ink):
        level = turned(ink, -tilt, centre) if tilt else ink
        readings = [_turned_back(r, tilt, centre) for r in _read_letters(level, expected)]
        score = _score(readings, expected)
        if best is None or score > best[0]:
            best = score, readings
        if score[0] == len(expected):
            break
    return best[1]


def _turned_back(reading, tilt, centre):
    """A reading of ink turned back by `tilt`, as the ink lies: no letter
    where the two tilts add up to more than a letter is read at alone
    (MOST_TILT: a J lying on its side is no J)."""
    if not tilt:
        return reading

    def back(fit):
        return fit._replace(strokes=turned(fit.strokes, tilt, centre), tilt=fit.tilt + tilt)
    best = reading.best and back(reading.best)
    letter = reading.letter if best is None or abs(best.tilt) <= MOST_TILT else None
    return Reading(letter, best, {c: back(f) for c, f in reading.fits.items()})


def _score(readings, expected):
    """(letters read as expected, less their fits): the larger, the better."""
    return (sum(r.letter == e for r, e in zip(readings, expected)),
            -sum(r.best.fit for r in readings if r.best is not None))


def _read_letters(ink, expected):
    """The row's readings, level: set apart, or cut looking ahead, and (a
    row that does not read so) cut letter by letter too, the better kept;
    or, where as many of its letters read so, each letter set apart read
    whole: a row unfinished (a U where USI was expected) is fewer letters."""
    if len(apart(ink)) >= len(expected):
        return [_of_row(group, ink) for group in apart(ink)]
    best = None
    for ahead in (True, False):
        readings = []
        for letter, (alone, shared) in zip(expected, letters_of(ink, expected, ahead)):
            first = _of_row(alone, ink)
            second = _of_row(shared, ink) if first.letter != letter else first
            readings.append(second if second.letter == letter else first)
        if best is None or _score(readings, expected) > _score(best, expected):
            best = readings
        if _score(best, expected)[0] == len(expected):
            return best
    whole = [_of_row(group, ink) for group in apart(ink)]   # fewer drawn than expected
    return whole if _score(whole, expected)[0] >= _score(best, expected)[0] else best


def _of_row(part, row):
    """The reading of `part`, a letter of `row`: none where it stands less
    than SHORT of the row's height (its best fit kept, for the report)."""
    reading = read(part)
    if part and box([p for line in part for p in line])[3] < SHORT * box(
            [p for line in row for p in line])[3]:
        return Reading(None, reading.best, reading.fits)
    return reading


def without_specks(ink):
    """`ink` less its specks: ink set apart (apart()) whose extent is under
    SPECK of all the ink's (a turtle spawned with its pen down, a nudge)."""
    points = [p for line in ink for p in line]
    if len(points) < 2:
        return ink
    _, _, w, h = box(points)

    def extent(group):
        _, _, gw, gh = box([p for line in group for p in line])
        return max(gw, gh)
    return [line for group in apart(ink) if extent(group) >= SPECK * max(w, h) for line in group]
