"""A drawing's plan: where a request goes on the sheet, its strokes, and
the primitives that draw them. No ROS here.

plan_request() is the one place a request (a text, or an SvgFile) is
planned: it finds the request its place on the sheet (sheet.py), takes the
strokes (a font's glyphs, or an SVG file's line art), orders them, and
turns them into primitives (primitives.py). What it returns is handed down
as it is: a mode (motion/modes.py) carries the plan out on a turtle.
"""
from typing import List, NamedTuple, Optional

from . import svgart
from .font import shown
from .primitives import Line, Turn, Written, plan_strokes
from .route import ink_length, order_strokes, travel_length

DEFAULT_PEN = (179, 184, 255, 3)    # turtlesim's own: r, g, b, width in pixels


class Plan(NamedTuple):
    start: tuple            # where the turtle is when it begins
    strokes: List[list]     # in the order and direction they are drawn, meters
    primitives: list        # what timed and feedback modes carry out
    ink: float              # m drawn
    travel: float           # m with the pen up
    seconds: float          # how long it should take
    colours: Optional[list] = None  # a picture's: each stroke's pen colour (None: ~pen)


class SvgFile(NamedTuple):
    """A request to draw an SVG file's line art (a text request is a str)."""
    path: str


class Planned(NamedTuple):
    plan: Plan
    chars: list             # (character, place) of a text: a parallel word's
    must_clear: bool        # the canvas (or part) is full: start again
    label: str              # what is drawn, for the log
    note: str               # something to say about it, or ''

    def summary(self, settings):
        """What the drawing's first log line says after "Drawing"."""
        p = self.plan
        return (f'{self.label} ({settings.mode} mode{", in parallel" * settings.parallel}): '
                f'ink {p.ink:.2f} m, travel {p.travel:.2f} m, about {p.seconds:.0f} s')


def plan_request(request, sheet, start, settings) -> Planned:
    """A text's or a picture's plan, at the next free place on `sheet`;
    raises layout.DoesNotFit or svgart.SvgError (then nothing is reserved)."""
    if isinstance(request, SvgFile):
        picture = svgart.picture(svgart.read(request.path, settings.svg_dirs), settings.size)
        name = shown(request.path.rsplit('/', 1)[-1])
        place, must_clear = sheet.reserve_picture(picture.width / settings.size, name, start)
        note = (f'{name}: {picture.texts} text element(s) not drawn (text in an SVG is not '
                'line art)' if picture.texts else '')
        return Planned(plan_picture(picture, place, start, settings), [], must_clear,
                       f'{name}, {len(picture.strokes)} strokes', note)
    places, must_clear = sheet.reserve(request, start)
    chars = [(c, p) for c, p in zip(request, places) if p is not None]
    return Planned(plan_text(request, places, start, settings), chars, must_clear,
                   repr(request), '')


def glyph_strokes(glyph, origin, size):
    """The glyph's strokes in meters, its lower-left corner at `origin`."""
    return [[(origin[0] + size * x, origin[1] + size * y) for x, y in stroke]
            for stroke in glyph.strokes]


def text_strokes(text, places, size, font, start):
    """Every stroke of `text` at `places` (from layout.Layout) in meters, in
    the order and direction it is drawn from `start`, with each one's
    font.Writer (or None): in reading order if the font says so (the
    builtin font, so that every N is the lab's N), else in the order and
    direction that travels least with the pen up."""
    glyphs = [(font.glyph(char), place) for char, place in zip(text, places) if place is not None]
    strokes = [stroke for glyph, place in glyphs for stroke in glyph_strokes(glyph, place, size)]
    writers = [glyph.writer for glyph, _ in glyphs for _ in glyph.strokes]
    if font.in_reading_order:
        return strokes, writers
    return order_strokes(strokes, (start.x, start.y)), [None] * len(strokes)


def plan_text(text, places, start, settings) -> Plan:
    """The strokes of `text` at `places` and the primitives that draw them
    from `start` (a geometry.PlannedPose)."""
    strokes, writers = text_strokes(text, places, settings.size, settings.font, start)
    return _plan(strokes, None, writers, start, settings)


def plan_picture(picture, place, start, settings) -> Plan:
    """A picture (svgart.Picture) with its lower left corner at `place`: its
    strokes a colour at a time, each colour's in the order that travels least.
    A ~pen other than turtlesim's own overrides the file's colours."""
    if settings.pen != DEFAULT_PEN:
        picture = picture._replace(colours=[None] * len(picture.strokes))
    here, strokes, colours = (start.x, start.y), [], []
    for colour in dict.fromkeys(picture.colours):        # in the order they come
        mine = [[(place[0] + x, place[1] + y) for x, y in stroke]
                for stroke, c in zip(picture.strokes, picture.colours) if c == colour]
        mine = order_strokes(mine, here)
        strokes += mine
        colours += [colour] * len(mine)
        here = mine[-1][-1]
    return _plan(strokes, colours, None, start, settings)


def _plan(strokes, colours, writers, start, settings):
    here = (start.x, start.y)
    primitives, _ = plan_strokes(strokes, start, settings.turn_direction, colours, writers,
                                 settings.size)
    ink, travel = ink_length(strokes), travel_length(strokes, here)
    return Plan(here, strokes, primitives, ink, travel,
                seconds(primitives, ink + travel, settings), colours)


def seconds(primitives, length, settings):
    """How long a plan should take: smooth mode glides `length` m at the
    linear speed; the others carry out every turn and line at their speeds."""
    if settings.mode == 'smooth':
        return length / settings.linear_speed
    steps = [s for p in primitives for s in (p.steps if isinstance(p, Written) else [p])]
    return sum(abs(s.angle) / settings.angular_speed if isinstance(s, Turn)
               else s.length / settings.linear_speed for s in steps if isinstance(s, (Turn, Line)))
