"""Which letter of A-Z a path draws, at any size and place, stretched up to
MAX_STRETCH times a form's own width or narrowed as much. No ROS.

Each candidate (each form of a letter, forms.py) is stretched onto the
path's box, its height and width each on its own, and the two are
compared both ways: how far the path strays from the candidate's
strokes, and how far the strokes are from anything drawn.
The worse of the two, as a share of the letter's height, is the fit; the
best-fitting candidate is the letter, if its fit is at most READABLE and
no other letter's is within AMBIGUOUS of it (a block J's middle line fit
an I 0.05 of its height off, and a J 0.051: that ink says neither), nor,
for ink that bands like an outline read past CLEAN, within RIVAL times it.
What is read is ink: the unbroken lines a turtle drew with its pen down,
as many as there are. Travel with the pen up is no part of it; a cadet who
retraces strokes to reach the next one loses nothing either, since
retraced ink lies on the strokes.
"""
import contextlib
import contextvars
import functools
import math
import string
from typing import Dict, List, NamedTuple, Optional

import numpy
from scipy.ndimage import distance_transform_edt
from scipy.spatial.distance import directed_hausdorff

from .forms import CLEAN, READABLE, Point, grid_rows, templates
from .ink import (CELL, WIDEST, box, boxed, closed, outline, sampled, straight, thinned,
                  turned)

LEVEL = 0.03        # a fit this good level is not tried tilted
TILTS = (-45, -35, -25, -15, -10, -5, 5, 10, 15, 25, 35, 45)    # degrees a letter is tried off level
FINER = (5.0, 2.5)  # then degrees either way of the best tilts, in turn
REFINED = 3         # the best-fitting letters whose tilts are tried finer
MOST_TILT = max(TILTS) + sum(FINER)     # degrees off level a letter is read at, at most
SAMPLE = 0.02       # share of the height between compared points
HOPELESS = READABLE  # a candidate straying farther is not fitted exactly: it cannot read
AMBIGUOUS = 0.005   # another letter fitting within this of the best: the two cannot be told apart
# Ink that bands like an outline, read past CLEAN, another letter fitting within RIVAL
# times as far off: a bold letter's middle line or edge is a crude stroke, and OCR
# decides (a DejaVu Sans Bold D half as wide again is an O 11% of its height off, a D 12%).
RIVAL = 1.4
WITNESSES = 4       # the ink cells farthest from the last few candidates fitted, kept
MAX_STRETCH = 3.0   # how far a candidate's width-to-height may be changed, either way
# Letters of one shape a quarter-turn apart (a Z at 40 degrees is an N at -50, a C at
# 45 a U at -45; a cadet's square forms exactly, any family's nearly): ink that reads
# as both, their tilts about a quarter-turn apart (within TWIN_TURN of 90 degrees), is
# the one standing TWIN_LEVEL degrees or more nearer level, as a person reads it; and
# neither where neither does (a square U at -44 degrees is a square C at 46).
TWINS = {'N': 'Z', 'Z': 'N', 'C': 'U', 'U': 'C'}
TWIN_TURN = 15
TWIN_LEVEL = 5
# A box this wide for its height is a block I's edge and a square O alike: no letter.
# (A DejaVu Sans Bold I stretched to 0.48 was credited as the O it was graded against.)
# Nor is its middle line an I where other ink runs off it: a cadet's square Q, kept
# whole in a row, read as the I it was graded against, within 1.4% of its height.
DOUBTFUL_BOX = (0.3, 0.5)
# A letter read past CLEAN whose mirror image fits it within MIRRORED times as far off
# is that letter drawn backwards: a turtle's R with its bowl left of its stem fit a
# script family's R within its 10% exactly, and mirrored back, a turtle's R within 3%.
MIRRORED = 0.5
# Fittings (bounded()) one reading of a canvas builds at most, by the strokes or for OCR's
# cuts: the recognition benchmark's costliest drawing built 1,308 (1,098 since best_fit).
FITTINGS = 2500


class Unfinished(Exception):
    """A reading's effort (bounded()) was spent before the reading ended."""


class Effort:
    """The Fittings a reading may still build: each is a distance grid of
    the ink and every candidate's bound on it, most of a slow row's time."""

    def __init__(self, fittings):
        self.left = fittings

    def spend(self):
        if self.left <= 0:
            raise Unfinished()
        self.left -= 1


_effort = contextvars.ContextVar('effort', default=None)    # the Effort of bounded(), if any


@contextlib.contextmanager
def bounded(fittings=None):
    """Within it, reading builds at most `fittings` Fittings (the Effort
    yielded counts them), and the next raises Unfinished: the cost of
    reading a canvas is bounded, whatever it holds, by a count rather than
    a clock, so that a drawing reads the same on any machine. (None:
    FITTINGS.)"""
    effort = Effort(FITTINGS if fittings is None else fittings)
    token = _effort.set(effort)
    try:
        yield effort
    finally:
        _effort.reset(token)


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
        return _within(grid_rows(ys), self.grid.shape[0])

    def cols(self, xs):
        return _within(numpy.rint((xs - self.lo) / CELL).astype(int) + 1, self.grid.shape[1])


def _within(indices, size):
    """`indices` past either edge of `size` put on it (numpy.clip, without its cost on
    small arrays: a reading takes a hundred thousand)."""
    return numpy.minimum(numpy.maximum(indices, 0), size - 1)


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
        self.across = numpy.divide(width, own, out=numpy.zeros_like(own), where=own > 0)
        self.left = (aspect - width) / 2
        # the grid starts on a whole cell: a letter's fit is the same whichever letters are asked
        self.lo = math.floor(min(0.0, (aspect - width.max()) / 2) / CELL) * CELL
        self.hi = max(aspect, (aspect + width.max()) / 2)
        self.ink = Distances(drawn[:, 0], drawn[:, 1], self.lo, self.hi)
        self.witnesses = []     # indices of inked, fit()'s
        self._placed = (None, None)     # (i, _cells(i)): a bound is followed by its fit

    @functools.cached_property
    def inked(self):
        """The ink's cells, each once, for fit(): the few candidates fitted exactly need them."""
        width = self.ink.grid.shape[1]
        cells = numpy.unique(self.ink.rows(self.drawn[:, 1]) * width +
                             self.ink.cols(self.drawn[:, 0]))
        return numpy.column_stack((cells // width, cells % width)).astype(float)

    @property
    def chosen(self):
        return self.choice.chosen

    def _on_ink(self, points, slot):
        """How far from the ink each of the choice's `points` (indices or a
        slice) lies, placed: each of candidate `slot` (its index, or one a point).
        The grid holds every candidate placed (from 0 to 1 high, from lo to hi
        across, a cell to spare each side): no index is put within it."""
        return self.ink.grid[self.choice.rows[points], self._columns(points, slot)]

    def _columns(self, points, slot):
        """The grid's columns the choice's `points`, of candidate `slot`, lie in, placed."""
        xs = self.left[slot] + self.choice.xs[points] * self.across[slot]
        return numpy.rint((xs - self.lo) / CELL).astype(int) + 1

    def bounds(self):
        """Each candidate's farthest point from the ink, of its sparse ones: below its bound."""
        sparse = self.choice.sparse
        return numpy.maximum.reduceat(self._on_ink(sparse, self.choice.slot[sparse]),
                                      self.choice.sparse_starts[:-1])

    def _cells(self, i):
        """Candidate i's points placed, as the grid's (rows, columns), as _on_ink places them."""
        if self._placed[0] != i:
            part = slice(self.choice.starts[i], self.choice.starts[i + 1])
            self._placed = i, (self.choice.rows[part], self._columns(part, i))
        return self._placed[1]

    def bound(self, i):
        """Candidate i's farthest point from the ink, of all its points: its fit is no less."""
        return float(self.ink.grid[self._cells(i)].max())

    def fit(self, i, bound, below=math.inf):
        """(candidate i's fit, True): the worse of its bound and how far the ink strays
        from it, cell to nearest cell on the ink's grid (scipy's directed Hausdorff
        distance: the figure a distance transform of the candidate gave, in about two
        thirds of its time). Or (a bound, False) where the ink that strayed farthest
        from earlier candidates (WITNESSES of it) strays `below` or more from this one:
        its fit is no less (three in four exact fits of a row were no better than
        the fits they had to beat)."""
        shape = numpy.column_stack(self._cells(i)).astype(float)
        if self.witnesses:
            far = self.inked[self.witnesses]
            near = ((far[:, None, :] - shape[None, :, :]) ** 2).sum(axis=2)   # squared
            strays = max(bound, math.sqrt(float(near.min(axis=1).max())) * CELL)
            if strays >= below:
                return strays, False
        distance, worst, _ = directed_hausdorff(self.inked, shape)
        if worst not in self.witnesses:
            self.witnesses = [int(worst)] + self.witnesses[:WITNESSES - 1]
        return max(bound, float(distance) * CELL), True


class _Found(NamedTuple):
    """A letter's best fit while reading: its strokes are placed once, at the end."""
    fit: float
    candidate: int      # its index in templates().candidates
    box: tuple          # the box of the ink it was fitted to, turned back by `tilt`
    tilt: float = 0.0
    exact: bool = True  # False: a bound, the fit no less


def _fits(ink, letters, beat=None, refined=REFINED) -> Dict[str, _Found]:
    """Each letter's best fit to `ink`, as it lies: exact for the `refined`
    best-fitting letters, and each other's no better than theirs. A
    candidate is fitted exactly only where its bound is under HOPELESS
    and below the `refined`-th best letter's fit so far, here and in `beat`
    (the ink at other tilts); a letter none of whose candidates was has
    its least bound, or a fit's bound (Fitting.fit), marked so; with
    `refined` 1, letters none of whose candidates may fit best are left
    out. (A bound taken on every SPARSE-th point
    only skips candidates; a bound kept is taken on all: a row's cuts
    compare the bounds of parts that fit no letter, and the sparse ones
    moved a real MF's cut off its M.)"""
    points = [p for line in ink for p in line]
    x, y, w, h = box(points)
    if h <= 0 or w > WIDEST * h:      # a dash, or a dot (an outline's middle may be one)
        return {}
    drawn = (sampled([line for line in ink if line], CELL * h / 2) - (x, y)) / h
    effort = _effort.get()
    if effort is not None:
        effort.spend()
    fitting = Fitting(drawn, w / h, letters)
    bounds = fitting.bounds()
    candidates = templates().candidates
    fits: Dict[str, _Found] = {}
    exact = {c: f.fit for c, f in (beat or {}).items() if f.exact}
    limit = _limit(exact, refined)
    for i in numpy.argsort(bounds):     # sparse bounds: each no more than its bound
        if refined == 1 and bounds[i] >= limit:
            break       # no later candidate fits better than the best: only it is asked for
        letter = candidates[fitting.chosen[i]][0]
        best = fits[letter].fit if letter in fits else math.inf
        fitted = letter in fits and fits[letter].exact
        if bounds[i] >= best or (fitted and bounds[i] >= limit):
            continue
        bound = fitting.bound(i)
        if bound < limit and bound <= HOPELESS and bound < best:
            fit, exactly = fitting.fit(i, bound, min(limit, best if fitted else math.inf))
            if not exactly and fitted:
                continue
            found = _Found(fit, int(fitting.chosen[i]), (x, y, w, h), exact=exactly)
            if exactly and fit < exact.get(letter, math.inf):
                exact[letter] = found.fit
                limit = _limit(exact, refined)
        elif not fitted:
            found = _Found(bound, int(fitting.chosen[i]), (x, y, w, h), exact=False)
        else:
            continue
        if found.fit < best:
            fits[letter] = found
    return fits


def _limit(exact, refined):
    """The `refined`-th best of some letters' fits: a candidate bounded above it is no better."""
    best = sorted(exact.values())[:refined]
    return best[-1] if len(best) == refined else math.inf


def read(ink, letters=string.ascii_uppercase, tilts=TILTS, finer=FINER,
         refined=REFINED) -> Reading:
    """The letter of `letters` that `ink` (lines of (x, y), m) draws, best
    fit first; ink that fits no letter well level is tried turned back by
    each of TILTS, then by `finer` steps around the tilts that fit best
    (a wide letter 5 degrees off strays a tenth of its height); its fits
    keep the tilt (their strokes turned with it). The best fit is exact,
    and so are the next `refined` - 1 letters'; another letter's is no
    better than theirs (_fits): read it alone for its own (rows.Row.reading
    does, for the letter expected). With `refined` 1, letters that cannot
    fit best are left out: a row's cuts ask only how well a part fits. A
    box DOUBTFUL_BOX wide for its height (ink.boxed) reads as no letter, nor
    as an I with other ink beside it, and
    a bare stroke (ink.straight) as an I or none: a line sloped 27 degrees
    fit a J tilted 52 within 8% of its height, its hook no more than that.
    Nor is a letter drawn backwards read (_backwards)."""
    points = [p for line in ink for p in line]
    if len(points) < 2 or box(points)[3] <= 0:
        return Reading(None, None, {})
    reading = _read_either(ink, letters, tilts, finer, refined)
    loops = [line for line in ink if closed(line, box(points)[3])]
    doubtful = reading.letter is not None and _doubtful(ink) or \
        reading.letter == 'I' and 0 < len(loops) < len(ink) and _doubtful(loops)
    if reading.letter not in (None, 'I') and straight(ink) or doubtful or \
            _backwards(ink, reading, tilts, finer):
        return Reading(None, reading.best, reading.fits)
    return reading


def _doubtful(ink):
    return DOUBTFUL_BOX[0] <= (boxed(ink) or 0) <= DOUBTFUL_BOX[1]


def best_fit(ink, letters=string.ascii_uppercase, tilts=TILTS, finer=FINER,
             refined=REFINED) -> Optional[Fit]:
    """read()'s best fit, the letter not decided: none of read()'s checks of
    the letter read (a mirror image read for _backwards is as many fittings
    again), for a row's cuts, which ask only how well a part fits."""
    points = [p for line in ink for p in line]
    if len(points) < 2 or box(points)[3] <= 0:
        return None
    return _read_either(ink, letters, tilts, finer, refined).best


def _backwards(ink, reading, tilts, finer):
    """Whether the letter read, past CLEAN, is drawn backwards: the ink's
    mirror image fits it within MIRRORED times as far off."""
    if reading.letter is None or reading.best.fit <= CLEAN:
        return False
    mirror = [[(-x, y) for x, y in line] for line in ink]
    back = _read_either(mirror, reading.letter, tilts, finer, 1).best
    return back is not None and back.fit <= MIRRORED * reading.best.fit


def _read_either(ink, letters, tilts, finer, refined):
    """read(), of an outline by its middle line, else of the ink as drawn."""
    middle = outline(ink)
    if middle is None:
        return _read(ink, letters, tilts, finer, refined)
    reading = _unsure(_read(middle, letters, tilts, finer, refined))
    if reading.best is not None and reading.best.fit <= reading.best.readable:
        height = box([p for line in ink for p in line])[3]
        if all(closed(line, height) for line in ink):
            return reading      # read, or two letters fit it alike: it says neither
        # ink off the closed lines is no part of the middle line (a duplex Q's
        # short tail: the middle line is an O): the ink as drawn, where it fits better
        drawn = _read(ink, letters, tilts, finer, refined)
        better = drawn.letter is not None and drawn.best.fit + AMBIGUOUS <= reading.best.fit
        return drawn if better else reading
    # a cadet's loop back to its start (a B's stem and two round bowls) may
    # band like an outline: where its middle line fits no letter, its strokes are read
    drawn = _unsure(_read(ink, letters, tilts, finer, refined))
    return drawn if drawn.letter is not None else reading


def _unsure(reading):
    """A `reading` of ink that bands like an outline (its middle line, or its
    edge as drawn), no letter where it is past CLEAN and another letter fits
    within RIVAL times as far off."""
    best = reading.best
    if reading.letter and best.fit > CLEAN and any(
            f.fit <= RIVAL * best.fit for f in reading.fits.values() if f is not best):
        return Reading(None, best, reading.fits)
    return reading


def _read(ink, letters, tilts, finer, refined) -> Reading:
    """read(), of ink read as it is drawn."""
    points = [p for line in ink for p in line]
    ink = thinned(ink, SAMPLE * box(points)[3] / 2)
    fits = _fits(ink, letters, refined=refined)
    x, y, w, h = box(points)
    centre = (x + w / 2, y + h / 2)
    if min((f.fit for f in fits.values()), default=math.inf) > LEVEL:
        done = {0.0} | set(tilts)
        _tried(ink, letters, fits, tilts, centre, refined)
        for step in finer:
            if min((f.fit for f in fits.values()), default=math.inf) <= LEVEL:
                break
            near = {f.tilt for f in sorted(fits.values(), key=lambda f: f.fit)[:REFINED]
                    if f.fit <= 2 * _readable(f)}
            more = sorted({t + d for t in near for d in (-step, step)} - done)
            done |= set(more)
            _tried(ink, letters, fits, more, centre, refined)
    placed_fits = {letter: _placed(letter, f, centre) for letter, f in fits.items()}
    best = upright_twin(min(placed_fits.values(), key=lambda f: f.fit, default=None),
                        placed_fits)
    letter = best.letter if best is not None and best.fit <= best.readable else None
    if letter and any(f.fit < best.fit + AMBIGUOUS for f in placed_fits.values()
                      if f is not best and not twin_farther(f, best)):
        letter = None       # the second-best letter's fit is exact (REFINED >= 2)
    return Reading(letter, best, placed_fits)


def plainly_other(reading, expected):
    """Whether `reading` (a Reading) is another letter than `expected`,
    read within CLEAN, where `expected` does not fit within CLEAN too."""
    return reading.letter not in (None, expected) and reading.best.fit <= CLEAN and \
        not (expected in reading.fits and reading.fits[expected].fit <= CLEAN)


def upright_twin(best, fits):
    """`best`, or its twin (TWINS) where that reads too, lying about a
    quarter-turn from it and TWIN_LEVEL nearer level."""
    twin = fits.get(TWINS.get(best.letter)) if best is not None else None
    if twin is not None and twin.fit <= twin.readable and twin_farther(best, twin):
        return twin
    return best


def twin_farther(fit, other):
    """Whether `fit` is the twin (TWINS) of `other`, about a quarter-turn
    from it and standing TWIN_LEVEL farther from level."""
    return fit.letter == TWINS.get(other.letter) and quarter_apart(fit, other) and \
        abs(fit.tilt) >= abs(other.tilt) + TWIN_LEVEL


def quarter_apart(fit, other):
    """Whether two Fits lie about a quarter-turn apart (within TWIN_TURN of 90 degrees)."""
    return abs(abs(fit.tilt - other.tilt) - 90) <= TWIN_TURN


def _readable(found):
    return templates().candidates[found.candidate][2]


def _placed(letter, found, centre):
    """The Fit of a letter found: its candidate's strokes on the ink's box, turned with it."""
    strokes = placed(templates().candidates[found.candidate][1], found.box)
    if found.tilt:
        strokes = turned(strokes, found.tilt, centre)
    return Fit(letter, found.fit, strokes, found.tilt, _readable(found))


def _tried(ink, letters, fits, tilts, centre, refined):
    """`fits` bettered by the ink turned back by each of `tilts`, about `centre`."""
    for tilt in tilts:
        level = turned(ink, -tilt, centre)
        if box([p for line in level for p in line])[3] <= 0:
            continue
        for letter, found in _fits(level, letters, fits, refined).items():
            if letter not in fits or found.fit < fits[letter].fit:
                fits[letter] = found._replace(tilt=tilt)
