"""A drawing's plan: where a request goes on the sheet, its strokes, and
the primitives that draw them. No ROS here.

plan_request() is the one place a request (a text, or an SvgFile) is
planned: it finds the request its place on the sheet (sheet.py), takes the
strokes (a font's glyphs, or an SVG file's line art), orders them, and
turns them into primitives (primitives.py). What it returns is handed down
as it is: a mode (motion/modes.py) carries the plan out on a turtle.
"""
import math
from typing import List, NamedTuple, Optional

from . import svgart
from .font import shown
from .geometry import PlannedPose
from .layout import DEFAULT_PEN as TURTLESIM_PEN, DEFAULT_PEN_WIDTH
from .primitives import Pen, Turn, Written, plan_strokes
from .route import ink_length, order_strokes, travel_length

DEFAULT_PEN = (*TURTLESIM_PEN, DEFAULT_PEN_WIDTH)    # turtlesim's own: r, g, b, width in pixels


class Plan(NamedTuple):
    start: tuple            # where the turtle is when it begins
    strokes: List[list]     # in the order and direction they are drawn, meters
    primitives: list        # what timed and feedback modes carry out
    ink: float              # m drawn
    travel: float           # m with the pen up
    seconds: float          # how long it should take
    colours: Optional[list] = None  # a picture's: each stroke's pen colour (None: ~pen)
    schedule: list = ()     # (ink drawn, seconds) wherever a mode tells its progress


class SvgFile(NamedTuple):
    """A request to draw an SVG file's line art (a text request is a str)."""
    path: str


class Planned(NamedTuple):
    plan: Plan
    chars: list             # (character, place) of a text: a parallel word's
    must_clear: bool        # the canvas (or part) is full: start again
    label: str              # what is drawn, for the log
    note: str               # something to say about it, or ''
    letters: list = ()      # in parallel: each character's plan, for a turtle of its own

    def summary(self, settings):
        """What the drawing's first log line says after "Drawing"."""
        p = self.plan
        return (f'{self.label} ({settings.mode} mode{", in parallel" * settings.parallel}): '
                f'ink {p.ink:.2f} m, travel {p.travel:.2f} m, about {p.seconds:.0f} s')


def plan_request(request, sheet, start, settings, check=lambda: None) -> Planned:
    """A text's or a picture's plan, at the next free place on `sheet`;
    raises layout.DoesNotFit or svgart.SvgError (then nothing is reserved).
    `check()` is called every so often while a large request is ordered,
    and may raise to stop it (a cancel)."""
    if isinstance(request, SvgFile):
        picture = svgart.picture(svgart.read(request.path, settings.svg_dirs), settings.size)
        name = shown(request.path.rsplit('/', 1)[-1])
        place, must_clear = sheet.reserve_picture(picture.width / settings.size, name, start)
        note = (f'{name}: {picture.texts} text element(s) not drawn (text in an SVG is not '
                'line art)' if picture.texts else '')
        return Planned(plan_picture(picture, place, start, settings, check), [], must_clear,
                       f'{name}, {len(picture.strokes)} strokes', note)
    places, must_clear = sheet.reserve(request, start)
    chars = [(c, p) for c, p in zip(request, places) if p is not None]
    plan = plan_text(request, places, start, settings, check)
    letters = parallel_plans(chars, start, settings) if settings.parallel and len(chars) > 1 else []
    if letters:             # as long as its slowest letter, its ink at an even pace
        seconds = max(p.seconds for p in letters)
        plan = plan._replace(seconds=seconds, schedule=[(plan.ink, seconds)])
    return Planned(plan, chars, must_clear, repr(request), '', letters)


def parallel_plans(chars, start, settings):
    """Each character's plan for a turtle of its own, all drawn at once: the
    first by ours from `start`, each other by a spare turtle spawned at its
    place, facing +x."""
    return [plan_text(char, [place], start if i == 0 else PlannedPose(*place, 0.0), settings)
            for i, (char, place) in enumerate(chars)]


def glyph_strokes(glyph, origin, size):
    """The glyph's strokes in meters, its lower-left corner at `origin`."""
    return [[(origin[0] + size * x, origin[1] + size * y) for x, y in stroke]
            for stroke in glyph.strokes]


def text_strokes(text, places, size, font, start, check=lambda: None):
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
    return order_strokes(strokes, (start.x, start.y), check), [None] * len(strokes)


def plan_text(text, places, start, settings, check=lambda: None) -> Plan:
    """The strokes of `text` at `places` and the primitives that draw them
    from `start` (a geometry.PlannedPose)."""
    strokes, writers = text_strokes(text, places, settings.size, settings.font, start, check)
    return _plan(strokes, None, writers, start, settings)


def plan_picture(picture, place, start, settings, check=lambda: None) -> Plan:
    """A picture (svgart.Picture) with its lower left corner at `place`: its
    strokes a colour at a time, each colour's in the order that travels least.
    A ~pen other than turtlesim's own overrides the file's colours."""
    if settings.pen != DEFAULT_PEN:
        picture = picture._replace(colours=[None] * len(picture.strokes))
    here, strokes, colours = (start.x, start.y), [], []
    for colour in dict.fromkeys(picture.colours):        # in the order they come
        mine = [[(place[0] + x, place[1] + y) for x, y in stroke]
                for stroke, c in zip(picture.strokes, picture.colours) if c == colour]
        mine = order_strokes(mine, here, check)
        strokes += mine
        colours += [colour] * len(mine)
        here = mine[-1][-1]
    return _plan(strokes, colours, None, start, settings)


def _plan(strokes, colours, writers, start, settings):
    here = (start.x, start.y)
    primitives, _ = plan_strokes(strokes, start, settings.turn_direction, colours, writers,
                                 settings.size)
    times = schedule(primitives, strokes, here, settings)
    return Plan(here, strokes, primitives, ink_length(strokes), travel_length(strokes, here),
                times[-1][1] if times else 0.0, colours, times)


def schedule(primitives, strokes, here, settings):
    """(ink drawn, seconds from the start) wherever a mode tells its progress
    (motion/modes.py), the whole drawing's last: smooth mode glides each
    stroke, and the travel to it, at the linear speed; the others carry out
    every turn and line at their speeds, and tell each line drawn."""
    ink, seconds, times = 0.0, 0.0, []
    if settings.mode == 'smooth':
        for stroke in strokes:
            drawn = ink_length([stroke])
            seconds += (math.dist(here, stroke[0]) + drawn) / settings.linear_speed
            ink, here = ink + drawn, stroke[-1]
            times.append((ink, seconds))
        return times
    pen_down = True
    for step in (s for p in primitives for s in (p.steps if isinstance(p, Written) else [p])):
        if isinstance(step, Pen):
            pen_down = step.down
        elif isinstance(step, Turn):
            seconds += abs(step.angle) / settings.angular_speed
        else:
            seconds += step.length / settings.linear_speed
            ink += step.length if pen_down else 0.0
            times.append((ink, seconds))
    return times + [(ink, seconds)]
