"""Where the letters are on a canvas, as a TA finds them at a glance:
first the writing without a frame drawn round it, and of several lines
of writing, one above another, the top one, unless another holds a
number of letters nearer the count expected by one or more (a real
class's SNB above 002, inside a border; XAVIERA below a heart, above a
line); then the canvas whole. Each is read with a letter in each pen
colour where its ink comes in as many colours as letters expected, else
as a row. One line, chosen by its letters' count, not by what they read:
a canvas is not searched for the letters hoped for, or a student who
wrote every letter, a line each, would earn any. No ROS here.
"""
import math
from typing import List, NamedTuple

import numpy

from .ink import box, dash, ends_driven_on, flooded, led_in, poked_through, samples
from .forms import CLEAN
from .recognition import Reading, Unfinished, bounded
from .rows import apart, in_colours, read_blind, read_row, without_specks

EDGE = 0.05         # share of the ink's larger side within which a frame's points lie of its box
ON_EDGE = 0.9       # share of a line's length that lies so: it runs along the box's edges
FRAMED = 0.75       # share of each side of the box a frame's lines run along, at least
LINE_GAP = 0.15     # clear space between two lines of writing, share of the taller one's height
# The top line of writing stands at least this share as high as the tallest: a piece
# of a letter above the rest is none (a gothic K tilted 25 degrees, its flourish a sixth
# of its height, was a line of its own, read as a T).
TOP_LINE = 0.5
DRIVEN_ON = ("read with a stroke's end that ran on past the rest of its letter cut back: "
             "turtlesim drives a command on for up to a second")
LED_IN = ("read without its lead-in, the straight line its turtle drew from where it "
          "appeared to where its letter begins (lift the pen, or teleport, to get there)")
POKED = "read with a stroke's end that ran on through the line it meets cut back to that line"
LETTER_WIDTH = 0.7  # share of its height a letter is wide, to count the letters of a line by


class Writing(NamedTuple):
    """Ink read for the letters expected: its lines, each line's look (colour, width)."""
    ink: list
    looks: list


class Page(NamedTuple):
    """The letters read on a canvas, and the writing they were read in."""
    readings: List[Reading]
    writing: Writing
    where: str          # '' for the canvas whole, else which of its writing was read


def read_page(ink, looks, expected, homes=()) -> Page:
    """The readings of the letters `expected` in `ink` (its lines' `looks`,
    as the simulator recorded them, or none; `homes`, the points where
    turtles appeared), where a TA looks first: the
    writing without a frame round it, then its line of writing
    (writing_on), the first that reads them all kept; else the canvas
    whole (_read), unless one of those read more letters in place (the
    first of the most). The same letters are credited whichever is read
    first; a line read first spares reading the canvas whole, a name with
    a picture above it as one row (a real XAVIERA below a heart: 1.7 s
    read whole first, 0.8 s so). Its cost is bounded (recognition.bounded)."""
    with bounded():
        return _read_page(ink, looks, expected, homes)


def _read_page(ink, looks, expected, homes):
    """The page as read_page finds it; where it does not read every letter, the
    writing it was read in read again as a TA looks past what is not the
    letters: its lines' ends driven on cut back (ink.ends_driven_on), then
    a lead-in from where a turtle appeared (ink.led_in), then ends run on
    through the line they meet (ink.poked_through). Each is kept
    where so more letters read in place, none of them where the writing
    as drawn reads another (_unless_drawn_otherwise)."""
    drawn = page = _first_read(ink, looks, expected)
    for trim, said in ((ends_driven_on, DRIVEN_ON), (lambda lines: led_in(lines, homes), LED_IN),
                       (lambda lines: poked_through(lines, len(expected)), POKED)):
        trimmed = None if _in_place(page.readings, expected) == len(expected) else \
            trim(page.writing.ink)
        if trimmed is None:
            continue
        writing = Writing(trimmed, page.writing.looks)
        readings = _unless_drawn_otherwise(drawn, page, _read(trimmed, writing.looks, expected),
                                           expected)
        again = Page(readings, writing, ', '.join(filter(None, (page.where, said))))
        if _in_place(again.readings, expected) > _in_place(page.readings, expected):
            page = again
    return page


def _unless_drawn_otherwise(drawn, page, readings, expected):
    """`readings` of `page`'s writing trimmed (_read_page), each letter they
    gain dropped where the writing as `drawn`, read not knowing the roster
    (_blind), reads another within CLEAN in its place, or where the effort
    was spent first: a stroke that ends lower than the rest of a tilted row
    is no stroke driven on (a cadets' KB tilted 30 degrees, its K's stem cut
    back to half, read KH; as drawn, read blind, KB within 1% of its height,
    though an H fits the B within 7%), nor is a D's stem, begun where the
    turtle appeared, a lead-in to a J."""
    gained = {k for k, (now, was, e) in enumerate(zip(readings, page.readings, expected))
              if now.letter == e != was.letter}
    if not gained:
        return readings
    try:
        blind = _blind(drawn.writing, len(expected))
    except Unfinished:
        blind = None        # not checked: not credited
    return [Reading(None, r.best, r.fits) if k in gained and (
        blind is None or k >= len(blind) or _other_cleanly(blind[k], expected[k])) else r
        for k, r in enumerate(readings)]


def _other_cleanly(reading, expected):
    return reading.letter not in (None, expected) and reading.best.fit <= CLEAN


def _blind(writing, count):
    """The readings of `writing` as a TA reads it not knowing the roster:
    a letter in each pen colour (rows.in_colours), else a row of `count`
    letters (rows.read_blind), or one letter read whole."""
    letters = in_colours(writing.ink, writing.looks, count)
    if letters:
        return [read_row(part, 1)[0] for part in letters]
    return read_blind(writing.ink, count) if count > 1 else read_row(writing.ink, 1)


def _first_read(ink, looks, expected):
    best = None
    # a flood (ink.flooded) is no letter anywhere: no writing is sought on it (30 turtles'
    # flood sought its lines of writing for 0.6 s)
    parts = [] if flooded(ink, max(1, len(expected))) else writing_on(ink, looks, len(expected))
    for where, writing in parts:
        page = Page(_read(writing.ink, writing.looks, expected), writing, where)
        if _in_place(page.readings, expected) == len(expected):
            return page
        if best is None or _in_place(page.readings, expected) > \
                _in_place(best.readings, expected):
            best = page
    whole = Page(_read(ink, looks, expected), Writing(ink, looks), '')
    if best is None or _in_place(whole.readings, expected) >= _in_place(best.readings, expected):
        return whole
    return best


def _read(ink, looks, expected):
    """A letter in each pen colour read alone where the ink comes in as
    many colours as letters expected (rows.in_colours), else the row."""
    letters = in_colours(ink, looks, len(expected))
    if letters:
        return [read_row(part, letter)[0] for part, letter in zip(letters, expected)]
    return read_row(ink, expected)


def _in_place(readings, expected):
    return sum(r.letter == e for r, e in zip(readings, expected))


def writing_on(ink, looks, count=1):
    """(where, Writing) of what a TA reads on a canvas other than all of
    it: the ink less a frame round the rest (framed), then, where the rest
    stands in several lines of writing one above another (lines), the top
    one TOP_LINE as high as the tallest or more (a piece of a letter above
    the rest is none), the one of them likeliest to hold `count` letters
    (_likeliest). Nothing where there is neither."""
    every = _kept(ink)
    frame = framed(ink, every)
    kept = [i for i in every if i not in frame]
    found = [('read inside the frame drawn round it', kept)] if frame else []
    bands = lines(ink, kept)
    if len(bands) > 1 and \
            _height(ink, bands[0]) >= TOP_LINE * max(_height(ink, band) for band in bands):
        k = _likeliest(ink, bands, count)
        found.append((_line_named(k, len(bands), count), bands[k]))
    return [(where, Writing([ink[i] for i in sorted(chosen)],     # in the order drawn
                            [looks[i] for i in sorted(chosen)] if len(looks) == len(ink) else []))
            for where, chosen in found]


def _likeliest(ink, bands, count):
    """Index of the line of writing (`bands`, top first) to read for
    `count` letters: the top one, unless another holds a number of letters
    nearer `count` by a letter or more (the nearest, the top one of those
    alike). A line holds its letters set apart (rows.apart), or as many as
    its width holds, each LETTER_WIDTH as wide as high (letters touch), the
    more; a line driven level (ink.dash), an underline, holds none."""
    offs = []
    for members in bands:
        part = [ink[i] for i in members]
        _, _, w, h = box([p for line in part for p in line])
        offs.append(math.inf if dash(part, count) else
                    abs(max(len(apart(part)), w / h / LETTER_WIDTH) - count))
    nearest = min(range(len(bands)), key=offs.__getitem__)
    return nearest if offs[nearest] <= offs[0] - 1 else 0


def _line_named(k, lines_of_writing, count):
    if k == 0:
        return f'read in the top line of the {lines_of_writing} lines of its writing'
    return (f'read in line {k + 1} of the {lines_of_writing} lines of its writing, from the '
            f'top: the one nearest {count} letters side by side')


def _height(ink, chosen):
    return box([p for i in chosen for p in ink[i]])[3]


def _kept(ink):
    """Indices of `ink`'s lines that are no speck nor dot (rows.without_specks)."""
    kept = {id(line) for line in without_specks(ink)}
    return [i for i, line in enumerate(ink) if id(line) in kept]


def framed(ink, kept):
    """Indices of `ink`'s lines `kept` (indices) that frame the rest: lines
    running along the ink's box (ON_EDGE of their length within EDGE of its
    larger side of an edge) and along FRAMED of each of its four sides at
    least, round other ink that keeps EDGE clear of every edge. (An L's stem
    and foot run along its box, with nothing inside; an E's bars too, but its
    middle bar meets its stem.)"""
    if len(kept) < 2:
        return []
    x, y, w, h = box([p for i in kept for p in ink[i]])
    near = EDGE * max(w, h)
    points = {i: numpy.array(samples([ink[i]], near / 2)) for i in kept}
    edges = [i for i in kept if numpy.mean(_off_edges(points[i], x, y, w, h) <= near) >= ON_EDGE]
    inside = [p for i in kept if i not in edges for p in ink[i]]
    if not inside or not edges:
        return []
    ix, iy, iw, ih = box(inside)
    if min(ix - x, x + w - ix - iw, iy - y, y + h - iy - ih) <= near:
        return []
    along = numpy.concatenate([points[i] for i in edges])
    # each side: how far the frame's points lie off it, where they lie along it, its length
    sides = [(along[:, 1] - y, along[:, 0], w), (y + h - along[:, 1], along[:, 0], w),
             (along[:, 0] - x, along[:, 1], h), (x + w - along[:, 0], along[:, 1], h)]
    covered = all(numpy.any(off <= near) and numpy.ptp(run[off <= near]) >= FRAMED * size
                  for off, run, size in sides)
    return edges if covered else []


def _off_edges(points, x, y, w, h):
    """How far each of `points` lies from the nearest edge of the box (x, y, w, h)."""
    return numpy.minimum.reduce([points[:, 0] - x, x + w - points[:, 0],
                                 points[:, 1] - y, y + h - points[:, 1]])


def lines(ink, kept):
    """The lines of writing of `ink`'s lines `kept` (indices), top first:
    lines whose heights overlap, or lie less than LINE_GAP of the taller's
    height apart, are one line of writing's."""
    spans = sorted(((min(p[1] for p in ink[i]), max(p[1] for p in ink[i]), i)
                    for i in kept if ink[i]), reverse=True, key=lambda s: s[1])
    bands = []      # [bottom, top, indices]
    for bottom, top, i in spans:
        if bands:
            low, high, members = bands[-1]
            if top >= low - LINE_GAP * max(high - low, top - bottom):
                bands[-1] = [min(low, bottom), high, members + [i]]
                continue
        bands.append([bottom, top, [i]])
    return [members for _, _, members in bands]
