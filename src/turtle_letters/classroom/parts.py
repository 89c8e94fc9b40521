"""Parts of a shared canvas: where each turtle may draw. No ROS here.

In a classroom many controllers draw on one turtlesim. Each keeps its letters
inside its own part: a box one line high, from the place its first letter
starts, as wide as the widest thing it was asked to draw. The controller
claims its box on the parameter server; here is only the geometry.
"""
from typing import Iterable, Optional, Tuple

from ..letters.font import Font
from ..letters.layout import MARGIN, WORLD_SIZE

Box = Tuple[float, float, float, float]     # x0, y0, x1, y1, meters


def text_width(text: str, font: Font) -> float:
    """How wide `text` is, in letter heights (the widest glyph for no text)."""
    widths = [font.space_width if c == ' ' else font.glyph(c).width for c in text]
    if not widths:
        return font.widest
    return max(font.widest, sum(widths) + font.letter_spacing * (len(widths) - 1))


def part_box(first_place: Tuple[float, float], width: float, size: float, font: Font) -> Box:
    """The part for one line of `width` letter heights from `first_place`,
    with half a letter spacing of room all round, so parts that touch keep
    their letters a letter spacing apart."""
    x, y = first_place
    room = font.letter_spacing * size / 2
    reach = font.overhang * size
    return (x - reach - room, y - font.descent * size - room,
            x + width * size + reach + room, y + font.ascent * size + room)


def contenders(parts: dict, turtle: str, uri: str, box: Box) -> dict:
    """The claims among {turtle: claim} that stand in the way of `turtle`'s
    controller at `uri` taking `box`, if their controllers are alive: another
    turtle's part that crosses it, or our turtle's part held by another node."""
    return {name: part for name, part in parts.items()
            if (name == turtle and part.get('uri') != uri)
            or (name != turtle and overlaps(box, part['box']))}


def overlaps(a: Box, b: Box) -> bool:
    return a[0] < b[2] - 1e-9 and b[0] < a[2] - 1e-9 and a[1] < b[3] - 1e-9 and b[1] < a[3] - 1e-9


def on_canvas(box: Box, size: float, font: Font) -> bool:
    """Whether the letters in `box` keep the canvas' margins (the room
    around them may reach into the margin)."""
    room = font.letter_spacing * size / 2
    low, high = MARGIN - 1e-9, WORLD_SIZE - MARGIN + 1e-9
    return (box[0] + room >= low and box[1] + room >= low
            and box[2] - room <= high and box[3] - room <= high)


def free_place(width: float, size: float, font: Font,
               taken: Iterable[Box]) -> Optional[Tuple[float, float]]:
    """The first place, top left to bottom right, whose part is on the
    canvas and overlaps none of `taken`; None when there is none.

    The candidates are the canvas' top left corner and the places just right
    of and just below every taken part: a free place, if any, is found
    packed against its neighbours."""
    taken = list(taken)
    room = font.letter_spacing * size / 2
    reach = font.overhang * size
    left_of_place = reach + room                     # from a part's left edge to its place
    below_top = font.ascent * size + room            # from a part's top edge to its place
    xs = {MARGIN + reach} | {box[2] + left_of_place for box in taken}
    ys = {WORLD_SIZE - MARGIN - font.ascent * size} | {box[1] - below_top for box in taken}
    for y in sorted(ys, reverse=True):
        for x in sorted(xs):
            box = part_box((x, y), width, size, font)
            if on_canvas(box, size, font) and not any(overlaps(box, t) for t in taken):
                return (x, y)
    return None


def fits_a_line(width: float, size: float, font: Font) -> bool:
    """Whether one line of `width` letter heights fits the canvas at all."""
    first = (MARGIN + font.overhang * size, WORLD_SIZE - MARGIN - font.ascent * size)
    return on_canvas(part_box(first, width, size, font), size, font)


def letter_bounds(box: Box, size: float, font: Font) -> Box:
    """Where the letters of a part may go: the part without its room."""
    room = font.letter_spacing * size / 2
    return (box[0] + room, box[1] + room, box[2] - room, box[3] - room)
