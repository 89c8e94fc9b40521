"""A stroke font for the turtle: A-Z and 0-9 as polylines. No ROS here.

Coordinates are in units of the letter height (`~size` meters): the pen
starts at the first point of the first stroke; every glyph sits in the box
[0, width] x [0, ASCENT]. All glyphs are 1 high, except the lab's N, whose
right leg ends higher because the lab draws it with a 3.5 m diagonal between
3.0 m legs. The N is not written out here: it is the path that the lab's
six calls (lab.py) trace, and timed mode runs those calls to draw it.
"""
from typing import Callable, Dict, List, NamedTuple, Optional, Tuple

from ..lab import LAB_SIZE, draw_the_labs_n
from .geometry import PlannedPose
from .primitives import Line, written_steps

Point = Tuple[float, float]
PRECISION = 12      # decimals kept of a traced point: cos(90 deg) is 6e-17, not 0

LETTER_SPACING = 0.3    # gap between letter boxes
LINE_HEIGHT = 1.4       # baseline to baseline


class Writer(NamedTuple):
    """A glyph written as the lab writes letters: `program(turtle)` calls
    rotate and move for a letter `size` m high, from its lower-left corner
    facing +x (written.py)."""
    program: Callable
    size: float


class Glyph(NamedTuple):
    width: float
    strokes: List[List[Point]]
    writer: Optional[Writer] = None     # how timed mode draws it, if written


def written_glyph(program, size):
    """A glyph of one stroke: the path `program`'s calls trace from (0, 0)
    facing +x, in letter heights (it is written `size` m high)."""
    steps, _ = written_steps(Writer(program, size), 1.0 / size, PlannedPose(0.0, 0.0, 0.0), 'ccw')
    stroke = [(0.0, 0.0)] + [(round(s.x, PRECISION), round(s.y, PRECISION))
                             for s in steps if isinstance(s, Line)]
    return Glyph(max(x for x, _ in stroke), [stroke], Writer(program, size))


LAB_N = written_glyph(draw_the_labs_n, LAB_SIZE)

_O = [(0.15, 0), (0, 0.15), (0, 0.85), (0.15, 1), (0.45, 1), (0.6, 0.85),
      (0.6, 0.15), (0.45, 0), (0.15, 0)]
_P = [(0, 0), (0, 1), (0.45, 1), (0.6, 0.85), (0.6, 0.65), (0.45, 0.5), (0, 0.5)]
_C = [(0.6, 0.85), (0.45, 1), (0.15, 1), (0, 0.85), (0, 0.15), (0.15, 0), (0.45, 0),
      (0.6, 0.15)]

FONT: Dict[str, Glyph] = {
    'A': Glyph(0.6, [[(0, 0), (0.3, 1), (0.6, 0)], [(0.1, 1 / 3), (0.5, 1 / 3)]]),
    'B': Glyph(0.6, [_P, [(0.45, 0.5), (0.6, 0.35), (0.6, 0.15), (0.45, 0), (0, 0)]]),
    'C': Glyph(0.6, [_C]),
    'D': Glyph(0.6, [[(0, 0), (0, 1), (0.4, 1), (0.6, 0.8), (0.6, 0.2), (0.4, 0), (0, 0)]]),
    'E': Glyph(0.6, [[(0.6, 1), (0, 1), (0, 0), (0.6, 0)], [(0, 0.5), (0.45, 0.5)]]),
    'F': Glyph(0.6, [[(0.6, 1), (0, 1), (0, 0)], [(0, 0.5), (0.45, 0.5)]]),
    'G': Glyph(0.6, [_C + [(0.6, 0.45), (0.3, 0.45)]]),
    'H': Glyph(0.6, [[(0, 0), (0, 1)], [(0.6, 1), (0.6, 0)], [(0, 0.5), (0.6, 0.5)]]),
    'I': Glyph(0.4, [[(0, 1), (0.4, 1)], [(0.2, 1), (0.2, 0)], [(0, 0), (0.4, 0)]]),
    'J': Glyph(0.6, [[(0.6, 1), (0.6, 0.15), (0.45, 0), (0.15, 0), (0, 0.15), (0, 0.3)]]),
    'K': Glyph(0.6, [[(0, 1), (0, 0)], [(0.6, 1), (0, 0.4)], [(0.2, 0.6), (0.6, 0)]]),
    'L': Glyph(0.6, [[(0, 1), (0, 0), (0.6, 0)]]),
    'M': Glyph(0.7, [[(0, 0), (0, 1), (0.35, 0.5), (0.7, 1), (0.7, 0)]]),
    'N': LAB_N,
    'O': Glyph(0.6, [_O]),
    'P': Glyph(0.6, [_P]),
    'Q': Glyph(0.6, [_O, [(0.35, 0.3), (0.6, 0)]]),
    'R': Glyph(0.6, [_P + [(0.3, 0.5), (0.6, 0)]]),
    'S': Glyph(0.6, [[(0.6, 0.85), (0.45, 1), (0.15, 1), (0, 0.85), (0, 0.65), (0.15, 0.5),
                      (0.45, 0.5), (0.6, 0.35), (0.6, 0.15), (0.45, 0), (0.15, 0), (0, 0.15)]]),
    'T': Glyph(0.6, [[(0, 1), (0.6, 1)], [(0.3, 1), (0.3, 0)]]),
    'U': Glyph(0.6, [[(0, 1), (0, 0.15), (0.15, 0), (0.45, 0), (0.6, 0.15), (0.6, 1)]]),
    'V': Glyph(0.6, [[(0, 1), (0.3, 0), (0.6, 1)]]),
    'W': Glyph(0.7, [[(0, 1), (0.175, 0), (0.35, 0.6), (0.525, 0), (0.7, 1)]]),
    'X': Glyph(0.6, [[(0, 1), (0.6, 0)], [(0, 0), (0.6, 1)]]),
    'Y': Glyph(0.6, [[(0, 1), (0.3, 0.5), (0.6, 1)], [(0.3, 0.5), (0.3, 0)]]),
    'Z': Glyph(0.6, [[(0, 1), (0.6, 1), (0, 0), (0.6, 0)]]),
    '0': Glyph(0.6, [_O, [(0, 0.15), (0.6, 0.85)]]),
    '1': Glyph(0.4, [[(0, 0.8), (0.2, 1), (0.2, 0)], [(0, 0), (0.4, 0)]]),
    '2': Glyph(0.6, [[(0, 0.85), (0.15, 1), (0.45, 1), (0.6, 0.85), (0.6, 0.6), (0, 0),
                      (0.6, 0)]]),
    '3': Glyph(0.6, [[(0, 0.85), (0.15, 1), (0.45, 1), (0.6, 0.85), (0.6, 0.65), (0.45, 0.5),
                      (0.2, 0.5)],
                     [(0.45, 0.5), (0.6, 0.35), (0.6, 0.15), (0.45, 0), (0.15, 0), (0, 0.15)]]),
    '4': Glyph(0.6, [[(0.45, 0), (0.45, 1), (0, 0.3), (0.6, 0.3)]]),
    '5': Glyph(0.6, [[(0.6, 1), (0, 1), (0, 0.55), (0.45, 0.55), (0.6, 0.4), (0.6, 0.15),
                      (0.45, 0), (0.15, 0), (0, 0.15)]]),
    '6': Glyph(0.6, [_C + [(0.6, 0.4), (0.45, 0.55), (0, 0.55)]]),
    '7': Glyph(0.6, [[(0, 1), (0.6, 1), (0.2, 0)]]),
    '8': Glyph(0.6, [[(0.15, 0.5), (0, 0.65), (0, 0.85), (0.15, 1), (0.45, 1), (0.6, 0.85),
                      (0.6, 0.65), (0.45, 0.5), (0.15, 0.5), (0, 0.35), (0, 0.15), (0.15, 0),
                      (0.45, 0), (0.6, 0.15), (0.6, 0.35), (0.45, 0.5)]]),
    '9': Glyph(0.6, [[(0.6, 0.45), (0.15, 0.45), (0, 0.6), (0, 0.85), (0.15, 1), (0.45, 1),
                      (0.6, 0.85), (0.6, 0.15), (0.45, 0), (0.15, 0), (0, 0.15)]]),
}

SPACE_WIDTH = 0.6   # a space in text advances like a letter but draws nothing
# The box: 1 high, with room for the lab N's raised leg (1.175), and for
# wherever an N changed in lab.py may reach.
_HEIGHTS = [y for glyph in FONT.values() for stroke in glyph.strokes for _, y in stroke]
ASCENT = max(1.2, max(_HEIGHTS))
DESCENT = max(0.0, -min(_HEIGHTS))


class Font(NamedTuple):
    """A stroke font, in letter heights: its glyphs and the room they need.
    A glyph's strokes run from x = 0 to its width; y = 0 is the baseline."""
    name: str
    glyphs: Dict[str, Glyph]
    ascent: float           # the highest point above the baseline
    descent: float          # the lowest point below it (0 or more)
    letter_spacing: float   # between two glyphs' boxes
    line_height: float      # baseline to baseline
    space_width: float
    case_sensitive: bool    # the builtin font draws lower case as upper case
    overhang: float = 0.0   # how far strokes reach past a glyph's edges (cursive joins)
    # Strokes drawn in reading order and as written (the builtin font: so
    # every N is the lab's N); else in the order that travels least.
    in_reading_order: bool = False

    def glyph(self, char: str):
        return self.glyphs.get(char if self.case_sensitive else char.upper())

    def undrawable(self, text: str) -> List[str]:
        """The characters of `text` with no glyph (spaces are fine: they advance)."""
        return sorted({c for c in text if c != ' ' and self.glyph(c) is None})

    @property
    def widest(self) -> float:
        return max(g.width for g in self.glyphs.values())


BUILTIN = Font('builtin', FONT, ASCENT, DESCENT, LETTER_SPACING, LINE_HEIGHT, SPACE_WIDTH, False,
               in_reading_order=True)


def shown(text: str, limit: int = 40) -> str:
    """`text` quoted for a log line: at most `limit` characters of it."""
    return repr(text if len(text) <= limit else text[:limit] + '...')
