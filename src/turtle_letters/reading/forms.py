"""The forms each letter of A-Z is read in: the builtin font's glyph, the
ways cadets draw it with rotate and move, the Hershey families a cadet may
draw in (and one's lowercase letters: a name written 'Jo'), and block
letters by their middle lines; each sampled once in its
own box (Templates), for recognition.py to stretch onto ink. No ROS here."""
import math
import string
from typing import List, NamedTuple, Tuple

import numpy

from ..letters.font import FONT
from .ink import CELL, box, outline, samples

Point = Tuple[float, float]
READABLE = 0.15     # worst deviation, share of the height, of a path still read as its letter
CLEAN = READABLE / 2    # a fit this close reads its letter beyond doubt
SPARSE = 3          # a candidate's bound is taken on every SPARSE-th of its points


def _round(centre, radius, start, end):
    """Points on a circle about `centre` from `start` to `end`, degrees, 15 apart."""
    steps = int(abs(end - start) / 15)
    return [(centre[0] + radius * math.cos(math.radians(start + (end - start) * k / steps)),
             centre[1] + radius * math.sin(math.radians(start + (end - start) * k / steps)))
            for k in range(steps + 1)]


def _arches(count, height, hump=0.3):
    """`count` round arches side by side, `height` high, each arch's radius
    `hump` of that: up the first leg, over an arch, down the next leg (and
    back up it to the next arch): a turtle's small m (2), and an h's lower
    half (1)."""
    radius = hump * height
    legs = height - radius
    path = [(0, 0)]
    for k in range(count):
        left = 2 * radius * k
        path += [(left, legs)] + _round((left + radius, legs), radius, 180, 0)[1:] + \
            [(left + 2 * radius, 0)]
    return path


_SQUARE_P = [(0, 0), (0, 1), (0.6, 1), (0.6, 0.5), (0, 0.5)]
_SQUARE_O = [(0, 0), (0, 1), (0.6, 1), (0.6, 0), (0, 0)]
_ARCH = [(0.3 - 0.3 * math.cos(math.radians(a)), 0.7 + 0.3 * math.sin(math.radians(a)))
         for a in range(0, 181, 15)]      # an A's round top
_CURL = _round((0.27, 0.27), 0.23, 0, -225)     # a J's hook, on past its half circle
_BOWL = _round((0.45, 0.55), 0.45, 0, 360)     # a small a's round bowl, from its right, once round
# a B of one loop: up its straight back, round its top bowl to a point inside, round the bottom
_LOOP_B = [(0, 0.27)] + _round((0.27, 0.73), 0.27, 180, -75) + \
    _round((0.27, 0.27), 0.27, 75, -180)
# How cadets draw letters with rotate and move, beside the font's glyphs:
# square corners, a K's arms meeting at the stem's middle (or stopping short
# of its corners, a real class's Ko), an A's bar from a quarter to half its
# height (or its top an arch, a real class's Al), an N with level feet, M and
# N as zigzags (a real class's MF), an I of one stroke, a J barred across its
# top (two other classes' Jo, one with its hook curled on up), an R of a stem,
# a round bowl half its height and a leg from the stem (a real class's R; the
# mirror of one fit a script R as well as it did: recognition.MIRRORED), a B
# of a stem and two round bowls (a gothic L fit one with its bar run on past
# its stem nearer than any B). A square-cornered O is an O: no D is drawn with
# four right angles. (The recognition benchmark draws each letter's last form
# here as a cadet's.)
VARIANTS: List[Tuple[str, List[List[Point]]]] = [
    ('A', [[(0, 0)] + _ARCH + [(0.6, 0)], [(0, 0.45), (0.6, 0.45)]]),   # arched
    ('A', [[(0, 0), (0.3, 1), (0.6, 0)], [(0.075, 0.25), (0.525, 0.25)]]),
    ('A', [[(0, 0), (0.3, 1), (0.6, 0)], [(0.12, 0.4), (0.48, 0.4)]]),
    ('A', [[(0, 0), (0.3, 1), (0.6, 0)], [(0.15, 0.5), (0.45, 0.5)]]),
    ('B', [[(0, 0), (0, 1)] + _round((0, 0.75), 0.25, 90, -90)[1:] +
           _round((0, 0.25), 0.25, 90, -90)[1:]]),     # round bowls
    ('B', [_SQUARE_P, [(0.6, 0.5), (0.6, 0), (0, 0)]]),
    ('C', [[(0.6, 1), (0, 1), (0, 0), (0.6, 0)]]),
    ('G', [[(0.6, 1), (0, 1), (0, 0), (0.6, 0), (0.6, 0.45), (0.3, 0.45)]]),
    ('I', [[(0, 0), (0, 1)]]),
    ('J', [[(0.6, 1), (0.6, 0), (0, 0), (0, 0.3)]]),
    ('J', [[(0.05, 1), (0.85, 1)], [(0.5, 1)] + _CURL]),    # barred, its hook curled back up
    ('J', [[(0, 1), (0.6, 1)], [(0.4, 1), (0.4, 0.2), (0.34, 0.06), (0.2, 0), (0.06, 0.06),
                                (0, 0.2)]]),                              # barred, a real class's
    ('K', [[(0, 1), (0, 0)], [(0.55, 0.9), (0, 0.5), (0.6, 0.25)]]),    # arms short
    ('K', [[(0, 1), (0, 0)], [(0.6, 1), (0, 0.5), (0.6, 0)]]),
    ('M', [[(0, 0), (0, 1), (0.35, 0), (0.7, 1), (0.7, 0)]]),
    ('M', [[(0, 0), (0.175, 1), (0.35, 0), (0.525, 1), (0.7, 0)]]),     # a zigzag, no upright
    ('N', [[(0, 0), (0, 1), (0.6, 0), (0.6, 1)]]),
    ('N', [[(0, 0), (0.15, 1), (0.45, 0), (0.6, 1)]]),                   # a zigzag
    ('O', [_SQUARE_O]),
    ('P', [_SQUARE_P]),
    ('Q', [_SQUARE_O, [(0.35, 0.3), (0.6, 0)]]),
    ('R', [[(0, 0), (0, 1)] + _round((0, 0.75), 0.25, 90, -90)[1:] + [(0.35, 0)]]),  # round bowl
    ('R', [_SQUARE_P + [(0.6, 0)]]),
    ('R', [_SQUARE_P + [(0.3, 0.5), (0.6, 0)]]),
    ('S', [[(0.6, 1), (0, 1), (0, 0.5), (0.6, 0.5), (0.6, 0), (0, 0)]]),
    ('U', [[(0, 1), (0, 0), (0.6, 0), (0.6, 1)]]),
    ('W', [[(0, 1), (0.175, 0), (0.35, 1), (0.525, 0), (0.7, 1)]]),
]
# Forms read only within FLOURISHED_READABLE: their curves lie near many
# letters' strokes. A B of one loop, its bowls meeting inside, off its back (a
# real class's BK), read within READABLE took a tilted, touching GI for a B.
CLOSE_VARIANTS: List[Tuple[str, List[List[Point]]]] = [('B', [_LOOP_B])]
# Hershey families a cadet may draw in (the lab's `font` draws each of
# them), read as their own glyphs: a script or gothic capital is far from
# the builtin font's. Families absent (no hershey-fonts-data) are left out.
# A flourished family's capital has ink almost everywhere in its box (a
# spiral lies within 0.15 of gothic's O): it must fit more closely.
FAMILIES = ('futural', 'rowmand', 'rowmant', 'timesr', 'timesi')
FLOURISHED = ('scripts', 'scriptc', 'cursive', 'gothiceng', 'gothicger', 'gothicita')
FLOURISHED_READABLE = 0.1
# A name's later letters written small, as names are ('Jo', 'Ca': nine of a
# real class of sixteen): futural's lowercase, each a form of its capital (a
# TA reading initials reads an a as an A). The rest are their capital made
# small (c o s v w x z) or a stroke, an I's (i j l).
SMALL_FAMILY, SMALL_LETTERS = 'futural', 'abdefghkmnpqrtuy'
# ... and as a turtle drives them, its arcs round where futural's are flat, each
# read within its bound: an a, a round bowl and a stem down its right side from
# the bowl's middle (a real class's Ma and Ca; futural's a has its stem from the
# top); an m of two round arches on three legs (a real class's m, which
# futural's fit 8 to 9% of its height off, past CLEAN); and, drawn so in the
# tests, a b and a d, a stem and a round bowl at its foot (no letter), and an h
# (an arched A, 15% off), these three only within FLOURISHED_READABLE (a d fit
# a DejaVu outline L 15% off). Not an n, a C turned a quarter (outline C's fit
# one 9 to 11% off, nearer than any C), nor an e, a bar and a ring (a DejaVu
# outline B fit one 12% off, 11% a B).
SMALL_VARIANTS: List[Tuple[str, List[List[Point]], float]] = [
    ('A', [_BOWL + [(0.9, 0)]], READABLE),                  # its bowl, then down
    ('A', [[(0.9, 0)] + _BOWL[:19]], READABLE),             # up, then round three quarters
    ('M', [_arches(2, 1)], READABLE),
    ('B', [[(0, 1), (0, 0)], _round((0.25, 0.25), 0.25, 180, -180)], FLOURISHED_READABLE),
    ('D', [[(0.5, 1), (0.5, 0)], _round((0.25, 0.25), 0.25, 0, 360)], FLOURISHED_READABLE),
    ('H', [[(0, 1), (0, 0)], _arches(1, 0.5)], FLOURISHED_READABLE),
]
# Block letters, read by their middle lines: Liberation's (the recognition
# benchmark draws DejaVu's, so its figure for outlines is of fonts unseen).
BLOCK_FONTS = (('/usr/share/fonts/truetype/liberation/LiberationSans-Bold.ttf', READABLE),
               ('/usr/share/fonts/truetype/liberation/LiberationSerif-Bold.ttf', FLOURISHED_READABLE))


def _candidates():
    """(letter, strokes, the fit it reads within) of every form a letter is read in."""
    from ..letters.hershey import FontError, load_font
    found = [(c, FONT[c].strokes, READABLE) for c in string.ascii_uppercase] + \
        [(c, strokes, READABLE) for c, strokes in VARIANTS] + SMALL_VARIANTS + \
        [(c, strokes, FLOURISHED_READABLE) for c, strokes in CLOSE_VARIANTS]
    for family in FAMILIES + FLOURISHED:
        try:
            font = load_font(family)
        except (FontError, OSError):
            continue
        readable = FLOURISHED_READABLE if family in FLOURISHED else READABLE
        found += [(c, font.glyph(c).strokes, readable) for c in string.ascii_uppercase]
        if family == SMALL_FAMILY:
            found += [(c.upper(), font.glyph(c).strokes, READABLE) for c in SMALL_LETTERS]
    return found + _block_letters()


def _block_letters():
    """(letter, middle line, the fit it reads within) of BLOCK_FONTS' bold
    capitals: an outline is read by its middle line (outline()), and a
    block letter's middle line is not a pen's letter (serifs, wide joins)."""
    from ..letters.outlines import outline_glyphs
    found = []
    for path, readable in BLOCK_FONTS:
        try:
            glyphs = outline_glyphs(path)
        except (OSError, ImportError):
            continue
        for c in string.ascii_uppercase:
            middle = outline(glyphs[c])
            found += [(c, middle, readable)] if middle else []
    return found


class Templates:
    """Every candidate sampled once, in its own box of height 1 (x from 0):
    placing one on a drawing's box is then a stretch of its points."""

    def __init__(self, candidates):
        self.candidates, points, self.aspects, self.starts = candidates, [], [], []
        for _, strokes, _ in candidates:
            x0, y0, w0, h0 = box([p for s in strokes for p in s])
            unit = [[((x - x0) / h0, (y - y0) / h0) for x, y in s] for s in strokes]
            self.starts.append(len(points))
            points += samples(unit, CELL)     # once, at the start
            self.aspects.append(w0 / h0)
        self.points = numpy.array(points)
        self.owner = numpy.repeat(numpy.arange(len(candidates)),
                                  numpy.diff(self.starts + [len(points)]))
        self._chosen = {}

    def of(self, letters):
        """The candidates for `letters`, their points, and the grid rows of those."""
        if letters not in self._chosen:
            chosen = [i for i, (c, _, _) in enumerate(self.candidates) if c in letters]
            indices = numpy.flatnonzero(numpy.isin(self.owner, chosen))
            slot = numpy.searchsorted(chosen, self.owner[indices])
            starts = numpy.r_[numpy.flatnonzero(numpy.r_[True, slot[1:] != slot[:-1]]), len(slot)]
            points = self.points[indices]
            # every SPARSE-th point of each, its first among them: a bound needs no more
            sparse = numpy.flatnonzero((numpy.arange(len(slot)) - starts[slot]) % SPARSE == 0)
            self._chosen[letters] = Choice(
                numpy.array(chosen, dtype=int), points[:, 0], points[:, 1],
                grid_rows(points[:, 1]), slot, starts, sparse,
                numpy.r_[numpy.searchsorted(sparse, starts[:-1]), len(sparse)])
        return self._chosen[letters]


class Choice(NamedTuple):
    """The candidates of some letters, their points in their own boxes."""
    chosen: numpy.ndarray   # each candidate's index in Templates.candidates
    xs: numpy.ndarray       # its points', across, in heights from its left
    ys: numpy.ndarray       # ... and up, 0 to 1
    rows: numpy.ndarray     # ... and their rows of a grid of CELL
    slot: numpy.ndarray     # each point's candidate, 0 to len(chosen) - 1
    starts: numpy.ndarray   # where each candidate's points start, and the last ends
    sparse: numpy.ndarray   # which points a bound is taken on
    sparse_starts: numpy.ndarray    # where each candidate's start in `sparse`, and the last ends


def grid_rows(ys):
    return numpy.rint(ys / CELL).astype(int) + 1


_templates = []     # made on first use: loading the families takes a moment


def templates():
    if not _templates:
        _templates.append(Templates(_candidates()))
    return _templates[0]


def candidates():
    return templates().candidates
