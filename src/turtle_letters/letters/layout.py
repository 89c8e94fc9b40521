"""Where letters go on the canvas, like a typewriter, and how large they
may be. No ROS here."""
from typing import List, Tuple

from .font import BUILTIN, Font, shown

# turtlesim's facts, kept here once: its canvas and its tick.
CANVAS_PIXELS = 500         # turtlesim's canvas is this many pixels square
PIXELS_PER_METRE = 45.0
WORLD_SIZE = (CANVAS_PIXELS - 1) / PIXELS_PER_METRE    # its usable size, meters
SIM_TICK = 0.016            # s: turtlesim moves each turtle one step a tick
DEFAULT_BACKGROUND = (69, 86, 255)      # its canvas, unless ~background_r/g/b say otherwise
DEFAULT_PEN = (179, 184, 255)           # each turtle's pen, until set_pen
DEFAULT_PEN_WIDTH = 3                   # px
MARGIN = 0.5                # no stroke comes closer than this to a wall


class DoesNotFit(ValueError):
    """The request would take the turtle outside the canvas' margins."""


def largest_size(font: Font = BUILTIN) -> float:
    """The largest letter height at which the font's widest glyph fits."""
    return (WORLD_SIZE - 2 * MARGIN) / max(font.ascent + font.descent,
                                           font.widest + 2 * font.overhang)


class Layout:
    """Letter places on the canvas, like a typewriter: the first at
    `first_place`, then to the right, then a new line below at the left
    margin; when the canvas is full, it is cleared and we start again.

    With `bounds` (a part of a shared canvas, see parts.py) the letters stay
    inside that box instead, and new lines start below the first place."""

    def __init__(self, first_place: Tuple[float, float], size: float,
                 font: Font = BUILTIN, bounds=None) -> None:
        self.size = size
        self.font = font
        self.bounds = bounds
        if bounds is not None:
            self.left = first_place[0]
        else:
            self.left = MARGIN + font.overhang * size     # where a new line starts
            if not self.fits_at(*first_place, font.widest):
                # The turtle starts too near a wall for this size: begin top left.
                first_place = (self.left, WORLD_SIZE - MARGIN - font.ascent * size)
        self.first_place = first_place
        self.cursor = first_place

    def fits_at(self, x: float, y: float, width: float) -> bool:
        low_x, low_y, high_x, high_y = self.bounds or (MARGIN, MARGIN, WORLD_SIZE - MARGIN,
                                                       WORLD_SIZE - MARGIN)
        reach = self.font.overhang * self.size
        slack = 1e-9
        return (low_x <= x - reach + slack and x + width * self.size + reach <= high_x + slack
                and low_y <= y - self.font.descent * self.size + slack
                and y + self.font.ascent * self.size <= high_y + slack)

    def places(self, widths: List[float], cursor: Tuple[float, float], partial=False):
        """Where boxes of these widths go from `cursor`, or None once the
        canvas is full (with `partial`, the places of those that fit). Stops
        at the first that does not fit: the work is bounded by the canvas."""
        x, y = cursor
        placed = []
        for width in widths:
            if not self.fits_at(x, y, width):
                x, y = self.left, y - self.font.line_height * self.size
                if not self.fits_at(x, y, width):
                    return (placed if partial else None), cursor
            placed.append((x, y))
            x += (width + self.font.letter_spacing) * self.size
        return placed, (x, y)

    def how_many_fit(self, widths: List[float]) -> int:
        return len(self.places(widths, self.first_place, partial=True)[0])

    def reserve(self, text: str):
        """Places for every character of `text` (None for a space) and
        whether the canvas must be cleared first; raises DoesNotFit."""
        font = self.font
        widths = [font.space_width if c == ' ' else font.glyph(c).width for c in text]
        placed, cleared = self.reserve_widths(widths, shown(text), 'characters')
        return [None if c == ' ' else p for c, p in zip(text, placed)], cleared

    def reserve_widths(self, widths: List[float], what: str, units: str):
        """Places for boxes of these widths (letter heights) and whether the
        canvas must be cleared first; raises DoesNotFit, naming `what`."""
        placed, cursor = self.places(widths, self.cursor)
        cleared = False
        if placed is None:
            placed, cursor = self.places(widths, self.first_place)
            cleared = True
            if placed is None:
                where = 'on the canvas' if self.bounds is None else "in the turtle's part of the canvas"
                raise DoesNotFit(
                    f'{what} does not fit {where} at size {self.size:g} m: '
                    f'at most {self.how_many_fit(widths)} of its {len(widths)} {units} fit')
        self.cursor = cursor
        return placed, cleared
