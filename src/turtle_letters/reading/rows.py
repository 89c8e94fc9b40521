"""The letters a row of ink draws, left to right, as a cadet draws their
initials: set apart where clear space parts them (or, drawn round their
edges, edge by edge), else cut where the parts read as the letters
expected; the row read turned back by its slope; specks and unfinished
letters no letter. Each letter is read by recognition.read. No ROS here.

A row is cut several ways (looking ahead or not, turned back or level),
and the ways share parts: a Row works out each part's fit and reading
once. A way of cutting is read whole only where it may read more letters
in place than the best so far: each part is first read as its expected
letter alone, which is cheap, and a part that does not read so cannot
read so among all 26.
"""
import functools
import itertools
import math
import string
from typing import List

import numpy
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from .ink import (box, boxed, closed, dash, flooded, inside, length, outline, samples, turned,
                  turns_along)
from .forms import CLEAN, READABLE, candidates, templates
from .recognition import (MOST_TILT, SAMPLE, TILTS, Reading, Unfinished, best_fit, plainly_other,
                          read)

GAP = 0.1           # clear space between two letters' ink, share of the height of the row
SPECK = 0.1         # ink set apart, smaller than this share of all the ink's extent: a speck, no letter
SHORT = 0.5         # a letter of a row less high than this share of the row reads only cleanly
SMALL = 0.25        # ... less high than this share: unfinished, no letter
NEAR_TILTS = (-5, 5)    # degrees a part is tried off level when finding where to cut
TIE = 0.01          # cuts whose fits differ by less fit as well
CORNER_TURN = 45    # degrees a line turns at a corner a row may be cut at, at least
NEAR_CORNERS = 2    # corners within a tenth of a share of the best cut also tried, at most
FAR_CORNERS = 3     # ... and corners within the cut's reach, nearest it first, at most
BARE = 0.2          # a form narrower than this share of its height is a bare stroke
ANY = '?'           # in a text to cut a row into, a letter that may be any
ACROSS = 75         # degrees off a row's slope past which a letter of it lies across the row
SQUARE = 60         # degrees apart two turns of a row lie where it may stand either way up
AS_LOW = 1.3        # a turn leaving a row this share as high as the lowest does: it may lie so
FAR_OFF = 30        # degrees off level past which, on a tie, neither way up of a row is taken
CLEAR_LINES = 40    # lines of a row past which its letters are not sought clear of each other
CLEAR_POINTS = 400  # ... and the points of a line compared, at most
RIVALS = 3          # the letters fitting a loose letter's place next best tried in its stead
NEAR_CUT = 0.15     # share of an even share within which two cuts bound the same ink
NUB = 0.05          # a piece of a line a cut severs, shorter than this share of the height: no one's
# Degrees off its row's level (levels) a letter of a row is tried at, at most, before
# the finer steps: a row's letters lean alike, and a part of a row fit a letter of
# its own at 35 or 45 degrees that none of the row's was (the recognition benchmark's
# rows, each to ±25: 3 more read right, 3 fewer wrong letters, in 12% less time).
ROW_TILTS = tuple(t for t in TILTS if abs(t) <= 25)


class Row:
    """A row's ink, finely sampled, and what was worked out about its
    parts: how well the part between two x fits a letter (near level),
    and the reading of a part, tried at `tilts` (a letter alone, at all
    of read()'s), each once."""

    def __init__(self, ink, tilts=TILTS):
        self.ink, self.tilts = ink, tilts
        self.x0, _, self.width, self.height = box([p for line in ink for p in line])
        self._fits, self._readings = {}, {}

    @functools.cached_property
    def fine(self):
        """The ink with points at most SAMPLE / 2 of its height apart: where it is cut."""
        return [samples([line], SAMPLE * self.height / 2) for line in self.ink if line]

    @functools.cached_property
    def corners(self):
        """The x of each corner of the ink (a turn of CORNER_TURN degrees or more
        from one fine point to the next), ascending: where two touching
        letters' strokes meet (a U turning off a square O's side)."""
        xs = []
        for line in self.fine:
            points = numpy.asarray(line, dtype=float)
            moved = numpy.hypot(*numpy.diff(points, axis=0).T) > 0
            points = points[numpy.r_[True, moved]]     # a point repeated has no heading
            xs += points[1:-1][numpy.abs(turns_along(points)) >= CORNER_TURN][:, 0].tolist()
        return sorted(xs)

    @functools.cached_property
    def _across(self):
        return [numpy.array([p[0] for p in line]) for line in self.fine]

    def fit(self, left, right, letter):
        """How far the part between x `left` (not included) and `right`
        strays from `letter` (ANY: any letter), at best, near level; inf with
        no ink there."""
        key = (left, right, letter)
        if key not in self._fits:
            part = self.between(left, right)
            letters = string.ascii_uppercase if letter == ANY else letter
            best = best_fit(part, letters, NEAR_TILTS, (), refined=1) if part else None
            self._fits[key] = best.fit if best else math.inf
        return self._fits[key]

    def letters(self, cuts):
        """Each letter between `cuts` (ascending x), as (its ink alone, its
        ink reaching NUB of the height past its cuts: a stroke two touching
        letters share, an M's last leg as an F's stem, is each letter's; a
        cut as near it as the nub a cut may leave, the side a cadet's U
        shares with its square O, too)."""
        edges = list(zip([-math.inf] + list(cuts), list(cuts) + [math.inf]))
        reach = NUB * self.height
        return [(self.between(lo, hi), self.between(lo - reach, hi + reach)) for lo, hi in edges]

    def share(self, part):
        """How high `part` stands, as a share of the row's height (0: no ink)."""
        return box([p for line in part for p in line])[3] / self.height if part else 0.0

    def between(self, lo, hi, lines=None):
        """The ink between x `lo` (not included) and `hi`: each line's runs of
        points there (of the fine `lines` given by index, or all), but a
        nub: a run the cut severs from the rest of its line, shorter than
        NUB of the height, is neither letter's (a real class's F, its bar
        driven back a little short of its stem, left a nub past the stem,
        in the M beside it, a metre above the M)."""
        parts, nub = [], NUB * self.height
        for k, (line, xs) in enumerate(zip(self.fine, self._across)):
            if lines is not None and k not in lines:
                continue
            inside = numpy.r_[False, (xs > lo) & (xs <= hi), False]
            edges = numpy.flatnonzero(inside[1:] != inside[:-1])
            parts += [line[start:stop] for start, stop in zip(edges[::2], edges[1::2])
                      if (start == 0 and stop == len(line)) or length([line[start:stop]]) >= nub]
        return parts

    @functools.cached_property
    def outlined(self):
        """Whether a letter of the row set apart is drawn round its edge
        (ink.outline), and not as a box: a block letter's outline. (The
        recognition benchmark's DejaVu Sans Bold NI, its I stretched to a
        box 0.51 as wide as high, read as the NO it was graded against.)"""
        return any(outline(group) is not None and boxed(group) is None
                   for group in apart(self.ink))

    def ink_near(self, x, within):
        """How many of the fine points lie within `within` of x across."""
        return sum(int(numpy.count_nonzero(numpy.abs(xs - x) < within)) for xs in self._across)

    def reading(self, part, letters=string.ascii_uppercase, exact=''):
        """The reading of `part`, a letter of this row, as one of `letters`,
        its fit to the letter `exact` exact (read() gives another letter's
        than the best no better than the best's only; OCR may credit the
        letter expected): none where it stands less than SMALL of the
        row's height, nor less than SHORT unless it fits within CLEAN (its
        best fit kept, for the report). (A name's later letters written
        small, 'Jo' or 'Ri', are its letters; the end of a curve beside a
        whole letter is no I.) Nor does a box read where other letters of the
        row are outlines (outlined): an outline O or D is two closed lines,
        and a single box is an outline I stretched, wider than its band."""
        key = (tuple(tuple(tuple(p) for p in line) for line in part), letters, exact)
        if key not in self._readings:
            reading = read(part, letters, self.tilts)
            fits = reading.fits
            alone = self.reading(part, exact).best if exact and reading.letter != exact else None
            if alone:
                fits = {**fits, exact: alone}
            letter = reading.letter
            height = self.share(part)
            if height < SMALL or (height < SHORT and reading.best.fit > CLEAN) or \
                    (letter not in (None, 'I') and boxed(part) is not None and self.outlined):
                letter = None
            self._readings[key] = Reading(letter, reading.best, fits)
        return self._readings[key]


def apart(ink):
    """The ink's letters, left to right: lines whose spans across overlap,
    or lie less than GAP of the row's height apart, are one letter's; in a
    row drawn round its letters' edges (ink.outline), touching or not, each
    closed line that lies inside no other is a letter's edge (by_edges)."""
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
    if len(lines) < 2 or outline(lines) is None:
        return [group for group, _ in groups]
    return [letter for group, _ in groups for letter in by_edges(group, height)]


def clear_of_each_other(ink, height):
    """The ink's letters where each lies clear of the others, by GAP of the
    row's `height`, though their spans across overlap (a J's bar reaching
    over the o after it): lines nearer each other than that are one
    letter's. Left to right; the ink whole where it has more than
    CLEAR_LINES lines (the cost is bounded)."""
    lines = [line for line in ink if line]
    if len(lines) > CLEAR_LINES:
        return [lines]
    near = GAP * height
    points = [numpy.array(samples([line], near / 4)).reshape(-1, 2) for line in lines]
    points = [p[::max(1, len(p) // CLEAR_POINTS)] for p in points]     # bounded
    owner = numpy.repeat(numpy.arange(len(lines)), [len(p) for p in points])
    pairs = owner[cKDTree(numpy.concatenate(points)).query_pairs(near, output_type='ndarray')]
    near_lines = coo_matrix((numpy.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])),
                            shape=(len(lines), len(lines)))
    _, letter = connected_components(near_lines, directed=False)    # each line's letter
    letters = {}
    for line, k in zip(lines, letter):
        letters.setdefault(k, []).append(line)
    return sorted(letters.values(), key=lambda group: min(p[0] for line in group for p in line))


def by_edges(lines, height):
    """The letters of `lines` drawn round their edges: each closed line
    mostly inside no other, with those mostly inside it (its holes, an O's
    inner edge); a line that is not closed goes with the letter whose span
    across holds its middle, else the first. Left to right."""
    edges = [line for line in lines if closed(line, height)]
    inner = {id(line) for line in edges
             if any(other is not line and inside(line, other) for other in edges)}
    letters = [[line] for line in edges if id(line) not in inner]
    if not letters:
        return [lines]
    for line in lines:
        if id(line) in inner:
            home = [letter for letter in letters if inside(line, letter[0])]
        elif not closed(line, height):
            middle = (min(p[0] for p in line) + max(p[0] for p in line)) / 2
            home = [letter for letter in letters
                    if min(p[0] for p in letter[0]) <= middle <= max(p[0] for p in letter[0])]
        else:
            continue
        (home or letters)[0].append(line)
    return sorted(letters, key=lambda letter: min(p[0] for p in letter[0]))


def cut(row, expected, ahead=True):
    """Where to cut `row` (a Row) into the letters of `expected` side by
    side, its letters touching (a Z's foot run on into an A's leg): each
    cut, left to right, between 0.4 and 1.6 of an even share of the row
    (from 0.1 where the letter before it may be a bare stroke, an I; to
    1.9 where one after it may), where the part before it fits its
    expected letter best and, `ahead`, the part after it fits the next
    letter too (the last cut: the rest as the last letter; an earlier
    one: the next even share). (From 0.1 to 1.9 for every letter, the
    recognition benchmark read 10 more rows with an I and 10 fewer of
    outlines, cut where a sliver fit.) A narrow row is one letter: no cut."""
    if narrow(row.ink):
        return []
    end = row.x0 + row.width
    share, cuts, left = row.width / len(expected), [], row.x0 - 1e-9     # a part is (left, right]
    for k, letter in enumerate(expected[:-1]):
        def before(x):
            return row.fit(left, x, letter)

        def after(x):
            return row.fit(x, end + 1 if k == len(expected) - 2 else x + share, expected[k + 1])
        # every tenth of a share, then the twentieths beside the best of those
        lo = 0.1 if letter in _bare() else 0.4
        hi = 1.9 if _bare() & set(expected[k + 1:]) else 1.6
        options = [left + share * (lo + 0.1 * i) for i in range(int(round((hi - lo) * 10)) + 1)]
        fits = _scored([x for x in options if x < end] or [left + share], before,
                       after if ahead else None)
        nearest = min(fits)[1]
        fits += _scored([x for x in (nearest - share / 20, nearest + share / 20) if left < x < end],
                        before, after if ahead else None)
        # a corner near the best cut, where two touching letters' strokes meet, kept only
        # where both letters fit it within CLEAN: a corner within a letter leaves a piece
        # that fits some letter (a zigzag N's last two legs are a V)
        corners = sorted((x for x in row.corners if left < x < end and
                          abs(x - nearest) < share / 10), key=lambda x: abs(x - nearest))
        fits += [(fit, x) for fit, x in _scored(corners[:NEAR_CORNERS], before,
                                                after if ahead else None) if fit <= CLEAN]
        best = min(f for f, _ in fits)
        # the corners in reach nearest it, a hair to either side (where one letter's last
        # stroke runs into the next one's first, the corner is neither's: a zigzag M's
        # last foot is its F's), kept where they fit within CLEAN, or READABLE where no
        # cut tried reads: the grid cut the real MF's M a tenth of its last leg short
        far = sorted({x + side for x in row.corners if options[0] <= x <= options[-1]
                      for side in (-share / 100, share / 100) if left < x + side < end},
                     key=lambda x: abs(x - nearest))[:2 * FAR_CORNERS]
        limit = READABLE if best > READABLE else CLEAN
        fits += [(fit, x) for fit, x in _scored(far, before, after if ahead else None)
                 if fit <= limit]
        best = min(f for f, _ in fits)
        # of the cuts that fit as well, the one through the least ink (the leftmost of those)
        cuts.append(min(sorted(x for f, x in fits if f <= best + TIE),
                        key=lambda x: row.ink_near(x, share / 40)))
        left = cuts[-1]
    return cuts


def narrow(ink):
    """Whether `ink`, as it lies, is one letter set apart (apart) and
    narrower than BARE of its height: one stroke's width, a letter at most,
    never a row of them side by side. (Cut along its length, a real class's
    one stroke, bent at its top, read as two slivers and an I; turned to
    lie as low as it may, a straight stroke's cuts read as no letter in the
    place of its I. Two I's side by side, however near, are two letters.)"""
    points = [p for line in ink for p in line]
    if len(points) < 2:
        return False
    _, _, width, height = box(points)
    return width < BARE * height and len(apart(ink)) == 1


@functools.lru_cache(maxsize=1)
def _bare():
    """The letters one of whose forms is a bare stroke (narrower than BARE of its height)."""
    return frozenset(c for c, aspect in zip((c for c, _, _ in candidates()), templates().aspects)
                     if aspect < BARE)


def _scored(options, before, after=None):
    """(fit, x) of each cut of `options` that may fit within TIE of the
    best: the worse of the fits of the parts `before` and `after` it. The
    part after is read in the order of the part before's fit, and not
    once that is worse than the best so far by TIE: a cut fits no better
    than the part before it."""
    firsts = sorted((before(x), x) for x in options)
    if after is None:
        return firsts
    scored, best = [], math.inf
    for fit, x in firsts:
        if fit > best + TIE:
            break
        scored.append((max(fit, after(x)), x))
        best = min(best, scored[-1][0])
    return scored


def letters_of(ink, expected, ahead=True):
    """The ink's letters, left to right, each as (its ink alone, its ink
    with the strokes it shares: Row.letters): set apart by GAP, or where
    fewer are set apart than `expected` has, cut (cut(), looking `ahead`
    or not)."""
    groups = apart(ink)
    if len(expected) < 2 or len(groups) >= len(expected):
        return [(group, group) for group in groups]
    row = row_of(ink)
    return row.letters(cut(row, expected, ahead))


def row_of(ink):
    """The Row of `ink`: the same one for the same ink, so that OCR, which
    reads the letters the strokes' reader cut, finds the cuts worked out."""
    return _row(tuple(tuple(tuple(p) for p in line) for line in ink))


@functools.lru_cache(maxsize=8)
def _row(lines):
    return Row([list(line) for line in lines], ROW_TILTS)


def levels(ink, count=2):
    """(tilt, centre, the ink turned back by it) for the row's slope, then
    level (0): the row as it lies level, the likelier first. Where the row
    lies as low two ways (row_slopes), its slope is the lower one unless
    the other reads more letters of any kind, `count` of them (_seen):
    which way is up is not decided by the letters hoped for. Where both
    read as many, and some, and both lie FAR_OFF level or more, which is
    up is in doubt: the row is read level only; and a turn that leaves it a
    dash (ink.dash) is none: it is a line, sloped. (A cadet's square O and G
    touching, sloped 43 degrees, read one letter either way, and stood on
    its end, the lower way, it is an E. A level QI lies as low at -50 and
    50, and reads level.)"""
    x, y, w, h = box([p for line in ink for p in line])
    centre = (x + w / 2, y + h / 2)

    def level(tilt):
        return turned(ink, -tilt, centre) if tilt else ink
    slope, *rival = row_slopes(ink)
    if rival:
        far_off = min(abs(slope), abs(rival[0])) >= FAR_OFF
        seen = _seen(level(slope), count)
        # the rival is read only where it may change the way: the slope reads fewer than
        # `count`, or both lie far off, where a tie is a doubt
        seen_rival = _seen(level(rival[0]), count) if seen < count or far_off else 0
        doubted = seen_rival == seen > 0 and far_off
        slope = 0 if doubted else rival[0] if seen_rival > seen else slope
    ways = [(tilt, centre, level(tilt)) for tilt in ([slope] if slope else []) + [0]]
    return [way for way in ways if not way[0] or not dash(way[2], count)]   # a line sloped


def row_slopes(ink):
    """Degrees a row of letters may lie off level: the turn within 50
    degrees of level, in steps of 5, that leaves the row least high (a row
    is level where its letters stand side by side); and another at least
    SQUARE from it, where one leaves the row within AS_LOW as low (a row of
    two narrow letters is as low stood on its end)."""
    points = numpy.array([p for line in ink for p in line])
    if len(points) < 3:
        return [0]
    turns = numpy.arange(-50, 55, 5)
    angles = numpy.radians(turns)
    heights = numpy.array([numpy.ptp(points[:, 1] * math.cos(a) - points[:, 0] * math.sin(a))
                           for a in angles])
    lowest = int(numpy.argmin(heights))
    padded = numpy.r_[math.inf, heights, math.inf]
    rivals = [i for i in numpy.argsort(heights) if padded[i] >= heights[i] <= padded[i + 2] and
              abs(turns[i] - turns[lowest]) >= SQUARE and heights[i] <= AS_LOW * heights[lowest]]
    return [int(turns[i]) for i in [lowest] + rivals[:1]]


def _seen(ink, count):
    """How many letters of any kind `ink`, as it lies, reads as a row of `count`."""
    if dash(ink, count):
        return 0
    return sum(reading.letter is not None for reading in _blind(row_of(ink), count))


def _blind(row, count):
    """The readings of `row` (a Row) as it lies, as a row of `count` letters
    not known: its letters set apart, or cut letter by letter with ANY
    letter at each place."""
    groups = apart(row.ink)
    parts = groups if len(groups) >= count else \
        [alone for alone, _ in row.letters(cut(row, ANY * count, ahead=False))]
    return [row.reading(part) for part in parts]


def in_colours(ink, looks, count):
    """The ink's letters where each is drawn in a pen colour of its own, as
    a class drew its initials, a turtle and a colour each (`looks`: each
    line's (r, g, b, ...)): its lines by colour, left to right by the
    middle of their span across, where they come in `count` colours, 2 or
    more; else None. Specks and dots are none of it, as in a row
    (without_specks: an i's dot is a dot beside its R, not beside its
    stem alone). (A real class's M and a, green and lavender, the a
    drawn over the M's last leg: cut as one row, it read NB.)"""
    if count < 2 or len(looks) != len(ink) or any(len(look) < 3 for look in looks):
        return None
    kept, colours = {id(line) for line in without_specks(ink)}, {}
    for line, look in zip(ink, looks):
        if id(line) in kept:
            colours.setdefault(tuple(look[:3]), []).append(line)
    if len(colours) != count:
        return None

    def middle(lines):
        x, _, w, _ = box([p for line in lines for p in line])
        return x + w / 2
    return sorted(colours.values(), key=middle)


def read_row(ink, expected='') -> List[Reading]:
    """The letters `ink` draws, left to right: the whole read as one when
    one letter is expected, else each letter set apart by GAP read alone;
    where fewer are set apart than expected, the ink is cut into them, and
    a letter cut is its expected letter if it reads so alone or with the
    strokes it shares. A row that does not read so level is read turned
    back by its slope (levels). The cuts only find the letters; a
    reading of all the letters says what each is. Specks and dots are no
    part of it (without_specks), and a letter of a row well under its
    height reads only as Row.reading says (a small o after a J does; a
    quarter of an S's curve beside a whole U is no I). A flood of ink
    (ink.flooded) is no letter, nor a shape of one, and nor is a dash
    (ink.dash: a line driven level). A narrow row is one letter (narrow).
    Where the reading's effort is spent (recognition.bounded), the ways
    read whole before then stand, and none read is no letter. A row read
    whole keeps a loose letter only where the row read blind allows it
    (_unobjected), and a piece of a loop cut off is no letter (_unsevered)."""
    ink = without_specks(ink)
    count = len(expected) if isinstance(expected, str) else expected
    unread = [Reading(None, None, {}) for _ in range(max(1, count))]
    if flooded(ink, max(1, count)) or dash(ink, max(1, count)):
        return unread
    try:
        if count <= 1 or narrow(ink):
            return [Row(ink).reading(ink, exact=expected[:1] if isinstance(expected, str) else '')]
        if not isinstance(expected, str):
            row = Row(ink)
            return [row.reading(group) for group in apart(ink)]
    except Unfinished:
        return unread
    best, level = _best_way(ink, expected)
    return _unobjected(level, best, expected) if best else unread


def _unobjected(level, readings, expected):
    """`readings` of a row read whole as `expected`, a letter read past
    CLEAN dropped where the row read blind as it lay when read (`level`:
    _blind) reads a letter in every place, or where it cut that place as
    the roster's cut did (_cut_alike), and another plainly in its place
    (recognition.plainly_other; read blind at its likelier slope instead, a
    zigzag M run into its F, read level as NF, was an M and a C 20 degrees
    off, and the N, the M's first three legs, stood):
    a cut sought for a letter that is not there may find ink that fits it
    loosely (a cadet's BP cut for EP read its B as an E within 8% of its
    height; cut blind, BP within 2%; a duplex D cut for YOX with the X's
    tips an O within 12%, blind a D within 5%, the X cut short no letter).
    Nowhere else does a row read blind in part object: a blind cut through
    a letter leaves pieces that read as other letters (the recognition
    benchmark's BN, its B cut blind an E within 3%, and a piece no letter;
    objecting so lost 5 rows read right for 2 wrong credits).
    Nor does one that another letter, cut for in its place, reads cleanly
    (_bettered). Where the effort is spent, none past CLEAN stands."""
    loose = [k for k, (r, e) in enumerate(zip(readings, expected))
             if r.letter == e and r.best.fit > CLEAN]
    if not loose or _score(readings, expected)[0] < len(expected):
        return readings
    row = row_of(level)
    try:
        blind = _blind(row, len(expected))
    except Unfinished:
        blind = None        # not checked: not credited

    def denied(k):      # the costly check (_bettered) last, where the others let it stand
        return blind is None or (plainly_other(blind[k], expected[k]) and (
            all(r.letter for r in blind) or _cut_alike(row, expected, k, readings[k]))) or \
            _bettered(row, readings, expected, k)
    return [Reading(None, r.best, r.fits) if k in loose and denied(k) else r
            for k, r in enumerate(readings)]


def _cut_alike(row, expected, k, reading):
    """Whether the row cut blind (_blind) bounds place k within NEAR_CUT of
    a share of where the cut for `expected` that read `reading` there does
    (looking ahead, else not): the blind reading there is of the same ink,
    not of a piece cut through it (a rowmant R, read where the row was cut
    looking ahead, cut blind through its bowl left its stem an I)."""
    count = len(expected)
    if len(apart(row.ink)) >= count:
        return True
    try:
        blind = cut(row, ANY * count, ahead=False)
        for ahead in (True, False):
            cuts = cut(row, expected, ahead)
            place = _as_expected(row, expected[k], *row.letters(cuts)[k])
            if place.letter == reading.letter and place.best.fit == reading.best.fit:
                edges = slice(max(0, k - 1), k + 1)
                return all(abs(a - b) <= NEAR_CUT * row.width / count
                           for a, b in zip(cuts[edges], blind[edges]))
    except Unfinished:
        return True     # not checked: not credited, as in _unobjected
    return False


def _bettered(row, readings, expected, k):
    """Whether, in a row cut for `expected` (fewer set apart), another letter
    than the one read loosely at place k, one of the RIVALS that fit it
    there next best, reads within CLEAN in its place where the row is cut
    for it (looking ahead), the row's other letters still read in place:
    that ink is that letter, drawn cleanly, and the one expected a loose
    fit the cut found for it (a timesi GO cut for GD read a D where its O
    is, within 8.5% of the height; cut for GO, the O reads within 1%).
    Where the reading's effort is spent first, it is not."""
    if len(apart(row.ink)) >= len(expected):
        return False
    fits = sorted((f.fit, c) for c, f in readings[k].fits.items() if c != expected[k])
    try:
        for _, letter in [(fit, c) for fit, c in fits if fit <= READABLE][:RIVALS]:
            other = expected[:k] + letter + expected[k + 1:]
            letters = row.letters(cut(row, other))
            place = _as_expected(row, letter, *letters[k])     # first: the others only if it reads
            if place.letter == letter and place.best.fit <= CLEAN and all(
                    _as_expected(row, c, *part).letter == c
                    for j, (c, part) in enumerate(zip(other, letters)) if j != k):
                return True
    except Unfinished:
        pass
    return False


def _best_way(ink, expected):
    """(the readings of the way (levels) that reads the most of `expected` in
    place, of those read whole before the reading's effort was spent, and the
    ink as that way lays it); (None, None) where none was."""
    best, chosen = None, None
    try:
        ways = levels(ink, len(expected))
        for tilt, centre, level in ways:
            floor = -1 if best is None else _score(best, expected)[0]
            back = functools.partial(_turned_back, tilt=tilt, centre=centre, slope=ways[0][0])
            readings = _read_letters(row_of(level), expected, floor, back)
            if readings is not None:
                if best is None or _score(readings, expected) > _score(best, expected):
                    best, chosen = readings, level
            if _score(best, expected)[0] == len(expected):
                break
    except Unfinished:
        pass
    return best, chosen


def _turned_back(reading, tilt, centre, slope=0):
    """A reading of ink turned back by `tilt`, as the ink lies: no letter
    where the two tilts add up to more than a letter is read at alone
    (MOST_TILT: a J lying on its side is no J), nor where it lies across
    its row, more than ACROSS off the row's `slope` (levels): a row of
    touching initials sloped 37 degrees, read level as one ink, fit a U
    standing 47 degrees the other way within 7% of its height."""
    def back(fit):
        return fit._replace(strokes=turned(fit.strokes, tilt, centre), tilt=fit.tilt + tilt)
    best = reading.best and back(reading.best) if tilt else reading.best
    letter = reading.letter if best is None or (
        abs(best.tilt) <= MOST_TILT and abs(best.tilt - slope) <= ACROSS) else None
    fits = {c: back(f) for c, f in reading.fits.items()} if tilt else reading.fits
    return Reading(letter, best, fits)


def _score(readings, expected):
    """(letters read as expected, less their fits): the larger, the better."""
    return (sum(r.letter == e for r, e in zip(readings, expected)),
            -sum(r.best.fit for r in readings if r.best is not None))


def _read_letters(row, expected, floor=-1, back=lambda reading: reading):
    """The row's readings, each as `back` turns it back to lie as the ink
    does (the ways are compared so: a letter read level may lie past
    MOST_TILT once turned back, and is then no letter): its letters set
    apart; or each clear of the others (clear_of_each_other); or cut
    looking ahead, and (a row that does not read so) cut letter by letter
    too, the better kept (_confirmed); or, where as many of its letters
    read in place so, each letter set apart read whole: a row unfinished
    (a U where USI was expected) is fewer letters. A way is read whole only where it may
    read more letters in place than `floor` and the best way so far
    (_hoped); None where none may."""
    groups = apart(row.ink)
    if len(groups) >= len(expected):
        return [back(row.reading(group, exact=letter))
                for group, letter in itertools.zip_longest(groups, expected, fillvalue='')]
    best, clear = None, clear_of_each_other(row.ink, row.height)
    if len(groups) < len(clear) == len(expected):
        best = [back(row.reading(part, exact=letter)) for part, letter in zip(clear, expected)]
        if _score(best, expected)[0] == len(expected):
            return best
    for ahead in (True, False):
        cuts = cut(row, expected, ahead)
        letters = row.letters(cuts)
        beat = floor if best is None else _score(best, expected)[0]
        if beat >= 0 and _hoped(row, letters, expected) <= beat:
            continue
        readings = _unsevered(row, cuts, [back(_as_expected(row, letter, alone, shared))
                                          for letter, (alone, shared) in zip(expected, letters)])
        if 0 < _score(readings, expected)[0] < len(expected):
            readings = _confirmed(row, expected, readings, ahead)
        if best is None or _score(readings, expected) > _score(best, expected):
            best = readings
        if _score(best, expected)[0] == len(expected):
            return best
    whole = [(group, group) for group in groups]     # fewer drawn than expected
    beat = floor if best is None else _score(best, expected)[0]
    if _hoped(row, whole, expected) < max(1, beat):
        return best
    whole = [_clean_only(back(row.reading(group, exact=letter)))
             for (group, _), letter in zip(whole, expected)]
    return whole if best is None or _score(whole, expected)[0] >= _score(best, expected)[0] \
        else best


def _unsevered(row, cuts, readings):
    """`readings` of `row` cut at `cuts`, a letter dropped where most of its
    ink is a lesser piece of a closed line the cuts sever that reads alone,
    within CLEAN, as another letter: a TA sees a loop drawn whole as one
    letter (a rowmans BLO cut for BLI read the right side of its O, a
    closed line of its own and an O within 2.2% of the height, as an I
    within 6%). The place holding most of the loop is its letter's, and
    may be more (a Q's ring, nicked by the cut beside it, is an O alone)."""
    edges = list(zip([-math.inf] + list(cuts), list(cuts) + [math.inf]))
    kept = list(readings)
    for k, line in enumerate(row.fine):
        xs = row._across[k]
        if not closed(line, row.height) or not any(xs.min() < x < xs.max() for x in cuts):
            continue
        whole = row.reading([line])
        if whole.letter is None or whole.best.fit > CLEAN:
            continue
        for place, (lo, hi) in enumerate(edges):
            piece = length(row.between(lo, hi, {k}))
            if kept[place].letter not in (None, whole.letter) and \
                    piece >= length(row.between(lo, hi)) / 2 and piece < length([line]) / 2:
                kept[place] = Reading(None, kept[place].best, kept[place].fits)
    return kept


def _clean_only(reading):
    """`reading`, its letter dropped unless it reads within CLEAN: ink read as
    fewer letters than expected may be two of them touching (a roman IQ,
    read whole, fit a Q within 10% of its height)."""
    if reading.letter is None or reading.best.fit <= CLEAN:
        return reading
    return Reading(None, reading.best, reading.fits)


def _confirmed(row, expected, readings, ahead):
    """`readings` of a row cut for `expected` that did not all read so,
    each letter read in place kept only where it reads CLEAN, the ink
    beside it across each cut reads CLEAN as some letter, and the row cut blind
    reads it there too, cut with any letter at its place and with any
    letter at every place, as a TA reads a row not knowing the roster.
    A cut sought for a letter that is not there finds ink that fits it: a
    sliver of an O as an I, a gothic C's half as a B; and a cut through a
    letter leaves a piece that is no letter: a square P cut through its
    bowl is an F, a square B an E; a piece read loosely holds a stroke of
    its neighbour's (a cadet's B with a zigzag N's first leg, its last two
    legs a V credited against AV). (Rows 2000 to 2499 of the recognition
    benchmark, graded against other initials: 38 such letters credited;
    kept so, 5. A touching UEI cut for ELB read its E's bars and the I as
    a B where only the B's place was cut blind.)"""
    kept = []
    for k, (reading, letter) in enumerate(zip(readings, expected)):
        beside = readings[max(0, k - 1):k] + readings[k + 1:k + 2]
        doubted = reading.letter == letter and (
            reading.best.fit > CLEAN or any(r.letter is None or r.best.fit > CLEAN
                                            for r in beside) or
            not _reads_blind(row, expected, k, ahead))
        kept.append(Reading(None, reading.best, reading.fits) if doubted else reading)
    return kept


def _reads_blind(row, expected, k, ahead):
    """Whether letter k of `expected` reads in its place where the row is
    cut with ANY letter there, and where it is cut with ANY letter at every
    place (each alone let a wrong letter through that the other stopped)."""
    for blind in (expected[:k] + ANY + expected[k + 1:], ANY * len(expected)):
        alone, shared = row.letters(cut(row, blind, ahead))[k]
        if _as_expected(row, expected[k], alone, shared).letter != expected[k]:
            return False
    return True


def read_blind(ink, count):
    """The row of `count` letters as a TA reads it not knowing the roster,
    at its likelier level (levels; cut level as well, a row of NB tilted
    25 degrees has a sliver of its N that is an I)."""
    ink = without_specks(ink)
    if dash(ink, count):
        return [Reading(None, None, {}) for _ in range(count)]
    if narrow(ink):
        return [Row(ink).reading(ink)]
    return _blind(row_of(levels(ink, count)[0][2]), count)


def _hoped(row, letters, expected):
    """How many of `letters` ((alone, shared) each) may read as expected in
    place, at most: those that read so as their expected letter alone."""
    return sum(row.reading(alone, letter).letter == letter or
               row.reading(shared, letter).letter == letter
               for letter, (alone, shared) in zip(expected, letters))


def _as_expected(row, letter, alone, shared):
    """The reading of a letter cut: `alone`, or with the strokes it shares
    where only so it reads as `letter` (read among all 26 only where it
    reads so as `letter` alone), and its own ink stands SMALL of the row
    or more: less is a neighbour's stroke, not a letter lent one (one
    stroke, the first leg of a U begun, cut three ways for USI, read as
    the I beside a sliver). Nor where its own ink reads another letter,
    or fits one best within CLEAN, better than the strokes lent make it
    `letter`: they are its neighbour's, and cannot make it so (a duplex
    I, fitting an I within 4% and a J as well, lent the end of the W
    before it, fit a J within 5%; a cadet's J, a T within 10% alone, fit
    an I within 12%)."""
    first = row.reading(alone, exact=letter)
    if first.letter == letter or row.share(alone) < SMALL or \
            row.reading(shared, letter).letter != letter:
        return first
    second = row.reading(shared, exact=letter)
    return first if second.letter != letter or _reads_another(first, letter, second.best.fit) \
        else second


def _reads_another(reading, letter, than):
    """Whether `reading` is of another letter than `letter`, read so or
    fitting best within CLEAN, and fits it within `than`."""
    best = reading.best
    return best is not None and best.letter != letter and best.fit <= than and \
        (reading.letter == best.letter or best.fit <= CLEAN)


def without_specks(ink):
    """`ink` less its specks: ink set apart (apart()) whose extent is under
    SPECK of all the ink's (a turtle spawned with its pen down, a nudge),
    and dots (an i's: _dot)."""
    points = [p for line in ink for p in line]
    if len(points) < 2:
        return ink
    _, _, w, h = box(points)
    speck = SPECK * max(w, h)
    kept = [line for group in apart(ink) if _extent(group) >= speck for line in group]
    return [line for line in kept if not _dot(line, kept, speck)]


def _extent(lines):
    _, _, w, h = box([p for line in lines for p in line])
    return max(w, h)


def _dot(line, ink, speck):
    """Whether `line` of `ink` is a dot: less than `speck` across, and
    farther from all other ink than its own size and half a speck (an i's
    dot above its stem; a dash of a dashed line lies nearer the next)."""
    size = _extent([line]) if line else speck
    if size >= speck:
        return False
    others = numpy.array([p for other in ink if other is not line for p in other])
    if not len(others):
        return False
    dot = numpy.asarray(line, dtype=float).reshape(-1, 2)[::max(1, len(line) // 8)]   # bounded
    nearest = numpy.hypot(*(others[:, None, :] - dot[None, :, :]).transpose(2, 0, 1)).min()
    return nearest > max(size, speck / 2)
