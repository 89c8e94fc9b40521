"""Line art from an SVG file: its shapes as polylines in meters. No ROS here.

svgelements (Debian's python3-svgelements) reads the file: paths, lines,
polylines, polygons, rectangles, circles, ellipses and arcs, with their
transforms applied. Each curve is flattened so that the polyline stays
within `tolerance` of it on the canvas; the picture is scaled to `size`
meters high (its aspect kept), its lower left corner at (0, 0), y up.
"""
import math
import os
from xml.etree import ElementTree
from typing import List, NamedTuple, Optional, Tuple

from .font import shown
from .geometry import distance_to_segment

TOLERANCE = 0.001       # m on the canvas: how far a flattened curve may be from the true one
MAX_POINTS = 20000      # points in all: more would take the turtle hours
MAX_BYTES = 5000000     # a larger file is refused unread: line art is smaller
MAX_STEPS = 4096        # chords of one curve at most

Point = Tuple[float, float]
Colour = Optional[Tuple[int, int, int]]


class SvgError(ValueError):
    """A file that cannot be drawn; the message says why, in one line."""


class Shapes(NamedTuple):
    paths: list             # svgelements.Path, transforms applied
    colours: List[Colour]   # each path's stroke colour, if it has one
    texts: int              # text elements, which are not drawn


class Picture(NamedTuple):
    strokes: List[List[Point]]      # m, lower left corner at (0, 0)
    colours: List[Colour]
    width: float                    # m
    texts: int


def read(path: str, folders) -> Shapes:
    """The shapes of the SVG file at `path`; raises SvgError. Only a file
    under one of `folders` (absolute, real paths) is read: any other path is
    refused in the same words whether it exists or not, since a request may
    come from any node."""
    try:
        import svgelements
    except ImportError:
        raise SvgError('python3-svgelements is not installed: run make deps') from None
    if not os.path.isabs(path):
        raise SvgError(f'{shown(path)}: give the absolute path (this node runs in {os.getcwd()})')
    if not allowed(path, folders):
        raise SvgError(f'{shown(path)}: only files under the folders of ~svg_dirs are read')
    real = os.path.realpath(path)
    if not os.path.isfile(real):
        raise SvgError(f'{shown(path)}: no such file')
    if os.path.getsize(real) > MAX_BYTES:
        raise SvgError(f'{shown(path)}: larger than {MAX_BYTES // 1000000} MB')
    root = _root_element(real)
    if root != '<svg>':
        raise SvgError(f'{shown(path)}: not an SVG file (its root: {root})')
    try:
        elements = list(svgelements.SVG.parse(real, reify=True).elements())
    except (ElementTree.ParseError, ValueError) as e:
        raise SvgError(f'{shown(path)}: an SVG file that cannot be read: {e}') from None
    paths, colours, texts = [], [], 0
    for element in elements:
        if isinstance(element, svgelements.Text):
            texts += 1
        elif isinstance(element, svgelements.Shape):
            line = svgelements.Path(element)
            if len(line) > 1:
                paths.append(line)
                colours.append(_colour(element.stroke))
    return Shapes(paths, colours, texts)


def allowed(path: str, folders) -> bool:
    """Whether `path`, links followed, lies under one of `folders` (real paths)."""
    real = os.path.realpath(path)
    return any(os.path.commonpath([real, folder]) == folder for folder in folders)


def _root_element(path):
    """The file's root element as '<name>', or why it has none."""
    try:
        for _, element in ElementTree.iterparse(path, events=('start',)):
            return '<' + element.tag.rsplit('}', 1)[-1] + '>'
    except ElementTree.ParseError as e:
        return f'not XML: {e}'
    return 'empty'


def picture(shapes: Shapes, size: float, tolerance: float = TOLERANCE) -> Picture:
    """The shapes as polylines in meters, `size` high; raises SvgError."""
    if not shapes.paths:
        raise SvgError('no shapes to draw' + (' (only text, which is not drawn)' if shapes.texts
                                              else ''))
    boxes = [p.bbox() for p in shapes.paths]
    x0, y0 = min(b[0] for b in boxes), min(b[1] for b in boxes)
    x1, y1 = max(b[2] for b in boxes), max(b[3] for b in boxes)
    span = max(y1 - y0, x1 - x0)
    if span <= 0:
        raise SvgError('its shapes have no extent: nothing to draw')
    scale = size / (y1 - y0 if y1 - y0 > span * 1e-6 else span)
    strokes, colours = [], []
    for path, colour in zip(shapes.paths, shapes.colours):
        for polyline in flatten(path, tolerance / scale):
            strokes.append([((x - x0) * scale, (y1 - y) * scale) for x, y in polyline])
            colours.append(colour)
            if sum(len(s) for s in strokes) > MAX_POINTS:
                raise SvgError(f'more than {MAX_POINTS} points at this size: draw a simpler '
                               'picture, or a smaller one')
    return Picture(strokes, colours, (x1 - x0) * scale, shapes.texts)


def flatten(path, tolerance: float) -> List[List[Point]]:
    """The polylines of an svgelements Path, each within `tolerance` of it."""
    import svgelements
    polylines, current = [], []
    for segment in path:
        if isinstance(segment, svgelements.Move):
            if len(current) > 1:
                polylines.append(current)
            current = [_xy(segment.end)]
        elif isinstance(segment, (svgelements.Line, svgelements.Close)):
            current.append(_xy(segment.end))
        else:
            current += _curve(segment, tolerance)
    if len(current) > 1:
        polylines.append(current)
    return [_without_repeats(p) for p in polylines if len(_without_repeats(p)) > 1]


def _curve(segment, tolerance):
    """Points after the start to the end of a curve: the fewest equal steps
    of its parameter whose chords all stay within `tolerance` of it (each
    vertex costs the turtle part of a tick, so fewer is faster)."""
    low, high = 1, 1
    while not _close(segment, high, tolerance):
        low, high = high + 1, high * 2
        if high > MAX_STEPS:
            high = MAX_STEPS
            break
    while low < high:                   # the fewest steps that are close enough
        middle = (low + high) // 2
        if _close(segment, middle, tolerance):
            high = middle
        else:
            low = middle + 1
    return [_xy(segment.point(k / high)) for k in range(1, high + 1)]


def _close(segment, steps, tolerance):
    """Whether each of `steps` equal chords stays within `tolerance` of the curve."""
    points = [_xy(segment.point(k / steps)) for k in range(steps + 1)]
    for k in range(steps):
        for f in (0.25, 0.5, 0.75):
            q = _xy(segment.point((k + f) / steps))
            if distance_to_segment(q, points[k], points[k + 1]) > tolerance:
                return False
    return True


def _without_repeats(points):
    kept = points[:1]
    for p in points[1:]:
        if math.hypot(p[0] - kept[-1][0], p[1] - kept[-1][1]) > 1e-9:
            kept.append(p)
    return kept


def _xy(point):
    return (float(point[0]), float(point[1]))


def _colour(stroke) -> Colour:
    if stroke is None or stroke.value is None:
        return None
    return (stroke.red, stroke.green, stroke.blue)
