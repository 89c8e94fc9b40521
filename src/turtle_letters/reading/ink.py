"""Ink as the grader reads it: unbroken lines of (x, y), m. Its box,
points along it, thinned to a bounded count, turned, and, for a letter
drawn round its edge, its middle line. No ROS here."""
import math

import numpy
from scipy.ndimage import distance_transform_edt, maximum_filter

CELL = 0.01         # share of the height: the grid distances are measured on
WIDEST = 12.0       # width-to-height of ink past which no letter is fitted (a dash)
THIN = 0.2          # half the width, share of the height, of an outline's band at most
AS_BOX = 0.97       # share of its box a closed line fills: a box (a D with cut corners 0.91)
CLOSED = 0.03       # share of the height within which a line's ends meet: a contour
# A loop this share of its height from top and bottom narrower than TAPERED of its middle's
# width narrows to its ends: an O drawn narrow, no letter's edge (a rowmans O 0.39 as
# wide as high banded like an outline, and its middle line read as an I within 4%).
TAPER_AT, TAPERED = 0.1, 0.7
MAX_POINTS = 600    # points of ink read at most: the cost of a reading is bounded
LONGEST = 50        # heights of ink a letter is drawn with, at most: more is a flood (flooded)
STRAIGHT = 0.03     # share of its length within which ink lies along one line: a bare stroke
RUN_TURN = 10       # degrees a line's last straight run strays from its last heading, at most
OVERSHOOT = 1 / 3   # share of that run that may stick out past the rest of the ink: driven on
LONG_RUN = 0.5      # ... where the run is this share of the rest's larger side long, at least
HOME_NEAR = 0.01    # m: a line begun this near where a turtle appeared begins there
LEAD_IN = 0.05      # share of the ink's height a lead-in is long, at least: less is a nub
POKE = 0.15         # ... an end may run on past a line it crosses, at most: poked through


def box(points):
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    return min(xs), min(ys), max(xs) - min(xs), max(ys) - min(ys)


def length(lines):
    """How long the polylines are, all together (in numpy: a row's cuts ask
    it of every piece they leave)."""
    return sum(float(numpy.hypot(*numpy.diff(numpy.asarray(line, dtype=float).reshape(-1, 2),
                                             axis=0).T).sum()) for line in lines)


def sampled(lines, step):
    """samples() as an array of (x, y): the same points, made by numpy for
    all the lines at once (a gothic row cut in two is a hundred short runs)."""
    arrays = [numpy.asarray(line, dtype=float).reshape(-1, 2) for line in lines if len(line)]
    if not arrays:
        return numpy.zeros((0, 2))
    points = numpy.concatenate(arrays)
    sizes = numpy.array([len(a) for a in arrays])
    firsts = numpy.cumsum(sizes) - sizes
    first = numpy.zeros(len(points), dtype=int)
    first[firsts] = 1
    onward = numpy.ones(len(points), dtype=bool)    # the segment to the next point is a line's
    onward[firsts + sizes - 1] = False
    step_to = points[numpy.minimum(numpy.arange(len(points)) + 1, len(points) - 1)] - points
    counts = numpy.where(onward, numpy.maximum(1, numpy.ceil(numpy.hypot(*step_to.T) / step)),
                         0).astype(int)
    # each point gives itself where it starts its line, then its segment's samples
    given = first + counts
    where = numpy.repeat(numpy.arange(len(points)), given)
    along = numpy.arange(given.sum()) - numpy.repeat(numpy.cumsum(given) - given, given) + 1 \
        - first[where]      # 0: the line's first point itself
    fraction = along / numpy.maximum(counts[where], 1)
    return points[where] + step_to[where] * fraction[:, None]


def samples(lines, step):
    """Points along polylines, at most `step` apart."""
    points = []
    for line in lines:
        points.append(line[0])
        for a, b in zip(line, line[1:]):
            n = max(1, math.ceil(math.dist(a, b) / step))
            points.extend((a[0] + (b[0] - a[0]) * i / n, a[1] + (b[1] - a[1]) * i / n)
                          for i in range(1, n + 1))
    return points


def thinned(ink, spacing):
    """`ink` with points closer than `spacing` to the one kept before them
    dropped (each line's ends kept), and at most MAX_POINTS in all: longer
    ink (a flood of turtles) is thinned more coarsely. A dropped point lies
    within the spacing of a kept one."""
    spacing = max(spacing, length(ink) / MAX_POINTS)
    kept = []
    for line in ink:
        if not line:
            continue
        points = [line[0]]
        for p in line[1:-1]:
            if math.dist(p, points[-1]) >= spacing:
                points.append(p)
        kept.append(points + list(line[-1:]) if len(line) > 1 else points)
    while sum(len(line) for line in kept) > MAX_POINTS:     # many short lines
        kept = [line[::2] + line[-1:] if len(line) > 2 else line for line in kept]
        kept = kept[::2] if all(len(line) <= 2 for line in kept) else kept
    return kept


def flooded(ink, letters=1):
    """Whether `ink` is longer than LONGEST times its height for each of
    `letters`: a flood of turtles, no letters. Thinned to MAX_POINTS, its
    lines would become chords across it that may draw anything (thirty
    turtles wandering for a minute, cut as a row of two, fit an M within
    5% of its height). The benchmark's longest letter is a gothic W, 13
    heights of ink (26 at twice its width)."""
    points = [p for line in ink for p in line]
    if len(points) < 2:
        return False
    _, _, w, h = box(points)
    return length(ink) > LONGEST * letters * max(h, w / WIDEST)


def dash(ink, letters=1):
    """Whether `ink` is a dash or less, no row of `letters`: no height, or
    more than WIDEST times as wide as high for each letter. (A turtle
    driven straight from its start, heading 0, lays a line of no height
    at all; after a turn, a millionth of a metre. Read as a row, such a
    line was sampled a share of its height apart: no end to the cost.)"""
    points = [p for line in ink for p in line]
    if not points:
        return True
    _, _, w, h = box(points)
    return h <= 0 or w > WIDEST * letters * h


def straight(ink):
    """Whether all of `ink` lies within STRAIGHT of its length of one line
    (its principal axis), whatever its slope: a bare stroke."""
    points = numpy.array([p for line in ink for p in line], dtype=float).reshape(-1, 2)
    if len(points) < 2:
        return True
    centred = points - points.mean(axis=0)
    axes = numpy.linalg.svd(centred, full_matrices=False)[2]
    return numpy.ptp(centred @ axes[1]) <= STRAIGHT * numpy.ptp(centred @ axes[0])


def turns_along(line):
    """The turn, degrees from -180 to 180 (counter-clockwise above 0), at
    each point of `line` (an array of points) between its first and last."""
    steps = numpy.diff(line, axis=0)
    heading = numpy.degrees(numpy.arctan2(steps[:, 1], steps[:, 0]))
    return (numpy.diff(heading) + 180.0) % 360.0 - 180.0


def ends_driven_on(ink):
    """`ink` with the end of each line cut back where its last straight run
    (within RUN_TURN) is LONG_RUN of the rest of the ink or longer and goes
    on past the rest's span, along the run's own axis (across or up), by
    OVERSHOOT of itself or less: turtlesim drives a command on for up to a
    second, and a timed zigzag M's last leg ran a third past its other
    feet. None where no end is so."""
    trimmed, changed = [list(line) for line in ink], False
    for k, line in enumerate(ink):
        run = _last_run(line)
        if run is None:
            continue
        rest = [p for other in ink[:k] + ink[k + 1:] for p in other] + list(line[:run + 1])
        if len(rest) < 2:
            continue
        x0, y0, w, h = box(rest)
        start, end = numpy.asarray(line[run], float), numpy.asarray(line[-1], float)
        long = math.dist(start, end)
        # how far along the run it leaves the rest's span on the run's own axis (1: it does not)
        axis = int(abs(end[1] - start[1]) > abs(end[0] - start[0]))
        lo, hi = (x0, x0 + w) if axis == 0 else (y0, y0 + h)
        edge = lo if end[axis] < lo else hi if end[axis] > hi else None
        leaves = 1.0 if edge is None else (edge - start[axis]) / (end[axis] - start[axis])
        if long >= LONG_RUN * max(w, h) and 1 - OVERSHOOT <= leaves < 1 - CLOSED:
            cut = tuple(start + (end - start) * leaves)
            kept = [p for p in line[run:] if numpy.dot(numpy.subtract(p, start), end - start)
                    < leaves * long * long]
            trimmed[k], changed = list(line[:run]) + kept + [cut], True
    return trimmed if changed else None


def led_in(ink, homes):
    """`ink` less each lead-in: the first straight run (within RUN_TURN of
    its first heading) of a line begun where a turtle appeared (`homes`),
    where the line turns on past it: the way a turtle drove, its pen
    down, to where its letter begins (a real class's B, drawn by
    `rostopic pub` alone, began with a 4 m line from turtlesim's centre).
    None where no line begins so, or its run is under LEAD_IN of the
    ink's height: the first steps of a curve begun there (a real R's
    bowl, 3% of the height: reading the ink again without them cost
    0.7 s and found nothing)."""
    trimmed, changed = [list(line) for line in ink], False
    height = box([p for line in ink for p in line])[3] if any(ink) else 0.0
    for k, line in enumerate(ink):
        if not line or not any(math.dist(line[0], home) <= HOME_NEAR for home in homes):
            continue
        back = _last_run(line[::-1])
        end = None if back is None else len(line) - 1 - back   # where the first run ends
        if end is not None and 0 < end < len(line) - 1 and \
                length([line[:end + 1]]) >= LEAD_IN * height:
            trimmed[k], changed = list(line[end:]), True
    return trimmed if changed else None


def poked_through(ink, letters=1):
    """`ink` with each end of a line cut back to the last line its straight
    run (within RUN_TURN) crosses, where it runs on past that line by
    LEAD_IN to POKE of the ink's height, and no farther than it ran up to
    it: a TA looks past a bar driven on through the stem it meets (a real
    class's B, drawn by `rostopic pub`, its middle bar run on about 0.12 of
    its height past its stem in one run, read as no letter). Less is a nub
    the fits pass over. None where no end is so, or where the ink is a
    flood for `letters` (flooded: each end is compared with all the ink,
    and thirty turtles' 300,000 points took 8 s)."""
    if flooded(ink, letters):
        return None
    height = box([p for line in ink for p in line])[3] if any(ink) else 0.0
    trimmed, changed = [list(line) for line in ink], False
    for k in range(len(trimmed)):
        for backwards in (False, True):
            line = trimmed[k][::-1] if backwards else trimmed[k]
            cut = _cut_at_crossing(line, trimmed[:k] + trimmed[k + 1:], height)
            if cut is not None:
                trimmed[k], changed = cut[::-1] if backwards else cut, True
    return trimmed if changed else None


def _cut_at_crossing(line, others, height):
    """`line` cut back to where its last straight run last crosses `others`
    or its own earlier part, where it runs on past there by LEAD_IN to POKE
    of `height`, and no farther than the run reached there; None where it
    does not."""
    run = _last_run(line)
    if run is None or len(line) - run < 2:
        return None
    points = numpy.asarray(line, dtype=float)
    steps = numpy.hypot(*numpy.diff(points, axis=0).T)
    to_end = numpy.r_[numpy.cumsum(steps[::-1])[::-1], 0.0]    # from each point to the end
    first = max(run, int(numpy.flatnonzero(to_end <= POKE * height)[0]) - 1)
    tail = points[first:]
    segments = [numpy.asarray(other, dtype=float) for other in others if len(other) > 1]
    if first > 1:
        segments.append(points[:first])       # its own earlier part, but the step into the tail
    if not segments:
        return None
    starts = numpy.concatenate([s[:-1] for s in segments])
    ends = numpy.concatenate([s[1:] for s in segments])
    low, high = tail.min(axis=0), tail.max(axis=0)      # only segments by the tail may cross it
    near = (numpy.minimum(starts, ends) <= high).all(axis=1) & \
        (numpy.maximum(starts, ends) >= low).all(axis=1)
    starts, ends = starts[near], ends[near]
    r, q = numpy.diff(tail, axis=0)[:, None, :], (ends - starts)[None, :, :]
    gap = starts[None, :, :] - tail[:-1, None, :]
    denominator = r[..., 0] * q[..., 1] - r[..., 1] * q[..., 0]
    with numpy.errstate(divide='ignore', invalid='ignore'):
        t = (gap[..., 0] * q[..., 1] - gap[..., 1] * q[..., 0]) / denominator
        u = (gap[..., 0] * r[..., 1] - gap[..., 1] * r[..., 0]) / denominator
    hit = (denominator != 0) & (t >= 0) & (t <= 1) & (u >= 0) & (u <= 1)
    if not hit.any():
        return None
    i, j = numpy.nonzero(hit)
    left = to_end[first + i] - t[i, j] * steps[first + i]    # from each crossing to the end
    nearest = int(numpy.argmin(left))
    # a bar poked through runs up to the line longer than past it: a G's short
    # bar crossing the K beside it is a stroke of its own, and cut back it was a C
    if not LEAD_IN * height <= left[nearest] <= min(POKE * height, to_end[run] - left[nearest]):
        return None
    k = first + int(i[nearest])
    at = points[k] + t[i[nearest], j[nearest]] * (points[k + 1] - points[k])
    return list(line[:k + 1]) + [(float(at[0]), float(at[1]))]


def _last_run(line):
    """Index of the point where `line`'s last straight run begins (its heading
    within RUN_TURN of its last); None where the line has no length."""
    points = numpy.asarray(line, dtype=float).reshape(-1, 2)
    steps = numpy.diff(points, axis=0)
    moved = numpy.flatnonzero(numpy.hypot(*steps.T) > 0)
    if not len(moved):
        return None
    heading = numpy.arctan2(steps[moved, 1], steps[moved, 0])
    off = numpy.abs((numpy.degrees(heading - heading[-1]) + 180.0) % 360.0 - 180.0)
    bent = numpy.flatnonzero(off > RUN_TURN)
    return int(moved[bent[-1]] + 1) if len(bent) else 0


def turned(lines, degrees, centre):
    """`lines` turned by `degrees` counter-clockwise about `centre`."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return [[(centre[0] + (x - centre[0]) * c - (y - centre[1]) * s,
              centre[1] + (x - centre[0]) * s + (y - centre[1]) * c) for x, y in line]
            for line in lines]


def squarest_turn(ink):
    """Degrees, within 45 of level in steps of 2.5, that `ink` turned back
    by leaves its box least in area: a letter's stems and bars lie along
    the sides of its box (a wide H 20 degrees off is read 5 off at best
    in 15-degree steps, and to OCR it is then no H)."""
    points = numpy.array([p for line in ink for p in line], dtype=float)
    if len(points) < 3:
        return 0.0
    turns = numpy.arange(-45, 47.5, 2.5)
    widths, heights = _spans(points, turns)
    return round(float(turns[int(numpy.argmin(widths * heights))]), 1)


def _spans(points, turns):
    """The width and height of `points` (an array of (x, y)) turned back by
    each of `turns`, degrees."""
    angles = numpy.radians(turns)[:, None]
    c, s = numpy.cos(angles), numpy.sin(angles)
    xs, ys = points[:, 0], points[:, 1]
    return numpy.ptp(xs * c + ys * s, axis=1), numpy.ptp(ys * c - xs * s, axis=1)


def inside(points, line, share=0.5):
    """Whether more than `share` of `points` lie inside the closed `line`
    (even-odd, by a ray from each to the right): an edge that touches
    another, overlapping it a little, is not inside it."""
    points = numpy.asarray(points, dtype=float).reshape(-1, 2)[::max(1, len(points) // 24)]
    edge = numpy.asarray(line, dtype=float).reshape(-1, 2)
    a, b = edge[:-1], edge[1:]
    x, y = points[:, :1], points[:, 1:]
    spans = (a[:, 1] > y) != (b[:, 1] > y)
    with numpy.errstate(divide='ignore', invalid='ignore'):
        crossing = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return float(numpy.mean((spans & (x < crossing)).sum(axis=1) % 2 == 1)) > share


def closed(line, height):
    """Whether a line of ink comes back where it began: a contour."""
    return len(line) > 3 and math.dist(line[0], line[-1]) <= CLOSED * height


def outline(ink):
    """Where `ink` is a letter's outline (a block letter drawn round its
    edge, or a duplex font's letter of two parallel lines): its closed
    lines, filled even-odd, make a band nowhere thicker than THIN of the
    height (nor thinner than a fifth of it), and are most of its ink. The
    band's middle line, as points (lines of one point each); else None.
    (A loop drawn as a letter, an O or a D, fills a wide shape, or narrows
    to its ends (tapered): no outline.)"""
    points = [p for line in ink for p in line]
    x, y, w, h = box(points)
    contours = [line for line in ink if closed(line, h)]
    if not contours or h <= 0 or w > WIDEST * h or \
            (len(contours) == 1 and tapered(contours[0])):
        return None
    if length(contours) < length(ink) / 2:
        return None
    from PIL import Image, ImageChops, ImageDraw
    size = (int(w / h / CELL) + 3, int(1 / CELL) + 3)
    inside = Image.new('1', size, 0)
    for line in contours:
        shape = Image.new('1', size, 0)
        ImageDraw.Draw(shape).polygon([((px - x) / h / CELL + 1, (py - y) / h / CELL + 1)
                                       for px, py in line], fill=1)
        inside = ImageChops.logical_xor(inside, shape)
    band = numpy.array(inside, dtype=bool)
    depth = distance_transform_edt(band)
    # a path retraced back to its start closes too, round no band: slivers
    if not band.any() or not THIN / 5 <= depth.max() * CELL <= THIN:
        return None
    ridge = band & (depth >= maximum_filter(depth, size=3))
    ridge &= depth >= numpy.median(depth[ridge]) / 2      # the spurs to its corners cut short
    rows, cols = numpy.nonzero(ridge)
    return [[(x + (c - 1) * CELL * h, y + (r - 1) * CELL * h)] for r, c in zip(rows, cols)]


def tapered(line):
    """Whether the closed `line`, stood up (turned back by its squarest turn),
    is at TAPER_AT of its height from top and bottom less than TAPERED as
    wide as at its middle: an ellipse is 0.6 as wide there, lying or
    standing; a block I's edge as wide (a stadium's, 0.87), a serif I's
    wider, and a V's or a T's edge, wide at its top. (Measured along its
    longer side, the edges of DejaVu's T, U, V and Y drawn wide read as no
    letter, and four Y's earned OCR's A.)"""
    points = numpy.array(turned([line], -squarest_turn([line]), (0.0, 0.0))[0] + line[:1],
                         dtype=float)
    a, b = points[:-1], points[1:]

    def width(y):
        crossed = (a[:, 1] > y) != (b[:, 1] > y)
        xs = a[crossed, 0] + (y - a[crossed, 1]) * (b[crossed, 0] - a[crossed, 0]) / \
            (b[crossed, 1] - a[crossed, 1])
        return float(numpy.ptp(xs)) if len(xs) > 1 else 0.0
    low, length = points[:, 1].min(), numpy.ptp(points[:, 1])
    middle = width(low + length / 2)
    return middle > 0 and all(width(low + length * at) < TAPERED * middle
                              for at in (TAPER_AT, 1 - TAPER_AT))


def boxed(ink):
    """Width-to-height of `ink` where it is a box: one closed line that
    fills AS_BOX of its box or more, turned back to its squarest (to an
    eighth of a degree); else None."""
    if len(ink) != 1 or len(ink[0]) < 4:
        return None
    line = numpy.array(ink[0], dtype=float)
    if not closed(ink[0], max(numpy.ptp(line, axis=0))):
        return None
    xs, ys = line[:, 0], line[:, 1]
    area = abs(numpy.dot(xs, numpy.roll(ys, 1)) - numpy.dot(ys, numpy.roll(xs, 1))) / 2
    widths, heights = _spans(line, squarest_turn(ink) + numpy.arange(-1.25, 1.3, 0.125))
    least = int(numpy.argmin(widths * heights))
    width, height = widths[least], heights[least]
    return width / height if height > 0 and area >= AS_BOX * width * height else None
