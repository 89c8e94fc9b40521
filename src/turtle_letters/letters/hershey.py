"""Hershey fonts, read from the .jhf files of Debian's hershey-fonts-data
package. No ROS here.

The format: one record per glyph, the printable ASCII characters in order
from the space. A record is a 5-column number, a 3-column count of
coordinate pairs, then the pairs, two characters each, whose values are
their character codes less ord('R'). The first pair is the glyph's left and
right edge; the others are points of its strokes, x to the right and y
downwards, and the pair " R" lifts the pen. A record longer than a line goes
on over the next lines.

In every font of the package capitals span y = -12 to 9 with the baseline at
9, so one letter height (`~size`) is taken as those 21 units.
"""
import os
from typing import Dict, List, Tuple

from .font import BUILTIN, Font, Glyph

FOLDER = '/usr/share/hershey-fonts'
BASELINE = 9                # Hershey units, y downwards
CAP_HEIGHT = 21
PEN_UP = ' R'


class FontError(ValueError):
    pass


def parse_jhf(text: str) -> List[Tuple[int, int, List[List[Tuple[int, int]]]]]:
    """Each record's left and right edge and strokes, in Hershey units."""
    records, pending = [], ''
    for line in text.splitlines():
        if not line.strip():
            continue
        pending += line
        count = int(pending[5:8])
        data = pending[8:]
        if len(data) < 2 * count:
            continue                        # the record goes on over the next line
        pairs = [data[i:i + 2] for i in range(0, 2 * count, 2)]
        left, right = (ord(c) - ord('R') for c in pairs[0])
        strokes, stroke = [], []
        for pair in pairs[1:]:
            if pair == PEN_UP:
                strokes.append(stroke)
                stroke = []
            else:
                stroke.append((ord(pair[0]) - ord('R'), ord(pair[1]) - ord('R')))
        strokes.append(stroke)
        records.append((left, right, [s for s in strokes if s]))
        pending = ''
    return records


def glyphs_from(records) -> Dict[str, Glyph]:
    """Records to glyphs in letter heights, y up from the baseline, x from
    the glyph's left edge."""
    glyphs = {}
    for code, (left, right, strokes) in zip(range(32, 127), records):
        glyphs[chr(code)] = Glyph(
            (right - left) / CAP_HEIGHT,
            [[((x - left) / CAP_HEIGHT, (BASELINE - y) / CAP_HEIGHT) for x, y in stroke]
             for stroke in strokes])
    return glyphs


def installed(folder: str = FOLDER) -> List[str]:
    try:
        return sorted(f[:-len('.jhf')] for f in os.listdir(folder) if f.endswith('.jhf'))
    except OSError:
        return []


def load_font(name: str, folder: str = FOLDER) -> Font:
    """`builtin`, or the Hershey font of that name; FontError says which exist."""
    if name == 'builtin':
        return BUILTIN
    path = os.path.join(folder, name + '.jhf')
    if name not in installed(folder):
        fonts = ', '.join(['builtin'] + installed(folder))
        if fonts == 'builtin':
            fonts += f' (no Hershey font in {folder}: install hershey-fonts-data)'
        raise FontError(fonts)
    with open(path, encoding='latin-1') as f:
        glyphs = glyphs_from(parse_jhf(f.read()))
    space = glyphs.pop(' ')
    ys = [y for g in glyphs.values() for s in g.strokes for _, y in s]
    overhang = max(max(-x, x - g.width) for g in glyphs.values() for s in g.strokes for x, _ in s)
    return Font(name, glyphs, ascent=max(ys), descent=-min(ys), letter_spacing=0.0,
                line_height=(max(ys) - min(ys)) * 1.1, space_width=space.width,
                case_sensitive=True, overhang=max(0.0, overhang))
