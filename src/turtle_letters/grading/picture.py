"""Pictures of drawings, Qt offscreen, no ROS: the benchmark's (the ideal
strokes in grey, recorded paths in colour, each vertex enlarged in a box
of its own; and the whole canvas) and the class grader's (a student's ink
as turtlesim drew it, the letters read over it)."""
import contextlib
import math
import os
import tempfile

os.environ.setdefault('QT_QPA_PLATFORM', 'offscreen')
from PyQt5.QtCore import QPointF, QRectF, Qt  # noqa: E402
from PyQt5.QtGui import QColor, QFont, QImage, QPainter, QPen  # noqa: E402
from PyQt5.QtWidgets import QApplication  # noqa: E402

from ..letters.layout import (CANVAS_PIXELS, DEFAULT_PEN, DEFAULT_PEN_WIDTH,  # noqa: E402
                              WORLD_SIZE)
from .scoring import distance_to_lines  # noqa: E402

_APPLICATION = []      # kept: Qt's application must outlive every painting


def application():
    """Qt's application, which painting needs: made once, in the thread
    that first asks (the main one: the class grader asks before its
    students' threads paint, each on a QImage of its own). Where the
    login set no runtime folder (root over ssh, `env -i`), the one Qt
    would pick is made first, or Qt warns on the instructor's terminal."""
    if not _APPLICATION:
        runtime = os.environ.setdefault(
            'XDG_RUNTIME_DIR', os.path.join(tempfile.gettempdir(), f'runtime-{os.getuid()}'))
        with contextlib.suppress(OSError):      # not made: Qt only warns
            os.makedirs(runtime, mode=0o700, exist_ok=True)
        _APPLICATION.append(QApplication.instance() or QApplication([]))
    return _APPLICATION[0]


MAIN_SCALE = 90.0          # px per m in the overview
INSET_SIZE = 240           # px: a box's side


def draw(path_png, strokes, paths, colours, half_box=0.01):
    """strokes: ideal polylines in m; paths: {label: [[(x, y), ...], ...]}
    drawn in colours[label] (r, g, b); a box shows +-half_box m around a vertex."""
    application()
    colours = {label: QColor(*rgb) for label, rgb in colours.items()}
    vertices = [v for s in strokes for v in s]
    xs, ys = [v[0] for v in vertices], [v[1] for v in vertices]
    margin = 0.4
    x0, y1 = min(xs) - margin, max(ys) + margin
    main_w = int((max(xs) - min(xs) + 2 * margin) * MAIN_SCALE)
    main_h = int((max(ys) - min(ys) + 2 * margin) * MAIN_SCALE)
    columns = 2
    rows = (len(vertices) + columns - 1) // columns
    width = main_w + 20 + columns * (INSET_SIZE + 10) + 10
    height = max(main_h, rows * (INSET_SIZE + 30)) + 60

    image = QImage(width, height, QImage.Format_RGB32)
    image.fill(QColor('white'))
    painter = QPainter(image)
    painter.setRenderHint(QPainter.Antialiasing)
    painter.setFont(QFont('Sans', 9))

    def overview(p):
        return QPointF(10 + (p[0] - x0) * MAIN_SCALE, 40 + (y1 - p[1]) * MAIN_SCALE)

    painter.setPen(QColor('black'))
    painter.drawText(10, 20, f'Ideal strokes (grey) and recorded paths; boxes: '
                             f'+-{half_box * 1000:g} mm around each vertex')
    for stroke in strokes:
        _polyline(painter, stroke, overview, QPen(QColor(200, 200, 200), 6))
    for key, runs in paths.items():
        for run in runs:
            _polyline(painter, run, overview, QPen(colours[key], 1))
    for i, vertex in enumerate(vertices):
        corner = (main_w + 20 + (i % columns) * (INSET_SIZE + 10),
                  40 + (i // columns) * (INSET_SIZE + 30))
        _inset(painter, corner, i, vertex, strokes, paths, colours, half_box)
    _legend(painter, height - 15, colours, paths)
    painter.end()
    image.save(path_png, 'PNG')


def _polyline(painter, points, to_px, pen):
    painter.setPen(pen)
    for a, b in zip(points, points[1:]):
        painter.drawLine(to_px(a), to_px(b))


def _inset(painter, corner, i, vertex, strokes, paths, colours, half_box):
    """The box of vertex i, its top left at `corner` (px): the ideal strokes
    and the paths within 3 half_box of it, enlarged, with a scale bar."""
    left, top = corner
    vx, vy = vertex
    scale = INSET_SIZE / (2 * half_box)                  # px per m in the boxes
    bar = 10 ** math.floor(math.log10(half_box / 2))     # m: the scale bar's length
    box = QRectF(left, top, INSET_SIZE, INSET_SIZE)
    painter.setClipRect(box)
    painter.fillRect(box, QColor(250, 250, 250))

    def inset(p):
        return QPointF(left + INSET_SIZE / 2 + (p[0] - vx) * scale,
                       top + INSET_SIZE / 2 - (p[1] - vy) * scale)
    for stroke in strokes:
        _polyline(painter, stroke, inset, QPen(QColor(200, 200, 200), 3))
    for key, runs in paths.items():
        for run in runs:
            near = [p for p in run
                    if abs(p[0] - vx) < 3 * half_box and abs(p[1] - vy) < 3 * half_box]
            _polyline(painter, near, inset, QPen(colours[key], 1.5))
            painter.setBrush(colours[key])
            for p in near:
                painter.drawEllipse(inset(p), 1.5, 1.5)
    painter.setClipping(False)
    painter.setBrush(Qt.NoBrush)
    painter.setPen(QColor('black'))
    painter.drawRect(box)
    painter.drawLine(QPointF(left + 10, top + INSET_SIZE - 10),
                     QPointF(left + 10 + bar * scale, top + INSET_SIZE - 10))
    painter.drawText(int(left + 10), int(top + INSET_SIZE - 14), f'{bar * 1000:g} mm')
    painter.drawText(int(left), int(top + INSET_SIZE + 16),
                     f'vertex {i + 1} ({vx:.3f}, {vy:.3f})')


def _legend(painter, y, colours, paths):
    """Each path's colour and label, along the foot of the picture at `y` (px)."""
    x = 10
    for key in paths:
        painter.setPen(QPen(colours[key], 3))
        painter.drawLine(x, y - 4, x + 20, y - 4)
        painter.setPen(QColor('black'))
        painter.drawText(x + 25, y, key)
        x += 140


CANVAS_SCALE = 120.0        # px per m


def draw_canvas(path_png, drawings, tolerance=0.02):
    """The whole canvas: for each (strokes, path, label, passed), the ideal
    strokes in grey, the path in green (passed) or red where it is within
    `tolerance` m of them and dotted elsewhere (pen-up moves, mistakes), the
    label's lines above."""
    application()
    side = int(WORLD_SIZE * CANVAS_SCALE)
    image = QImage(side, side, QImage.Format_RGB32)
    image.fill(QColor('white'))
    painter = QPainter(image)
    painter.setRenderHint(QPainter.Antialiasing)
    painter.setFont(QFont('Sans', 7))
    line_height = painter.fontMetrics().height()

    def px(p):
        return QPointF(p[0] * CANVAS_SCALE, (WORLD_SIZE - p[1]) * CANVAS_SCALE)

    for strokes, path, label, passed in drawings:
        painter.setPen(QPen(QColor(200, 200, 200), 5))
        for stroke in strokes:
            for a, b in zip(stroke, stroke[1:]):
                painter.drawLine(px(a), px(b))
        colour = QColor(27, 120, 55) if passed else QColor(178, 24, 43)
        on, off = QPen(colour, 1.5), QPen(colour, 1, Qt.DotLine)
        for a, b in zip(path, path[1:]):
            middle = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
            painter.setPen(on if distance_to_lines(middle, strokes) <= tolerance else off)
            painter.drawLine(px(a), px(b))
        left = min(v[0] for s in strokes for v in s)
        top = max(v[1] for s in strokes for v in s)
        painter.setPen(QColor('black'))
        corner = px((left, top))
        lines = label.split('\n')
        for i, line in enumerate(lines):
            painter.drawText(QPointF(corner.x(), corner.y() - 6 - (len(lines) - 1 - i) * line_height),
                             line)
    painter.end()
    image.save(path_png, 'PNG')


ZOOM_PX = 500       # px: the side of the ink's own box, beside the canvas


def draw_ink(path_png, strokes, looks, background, letters, caption, unread=((), ())):
    """A student's drawing as a TA sees it: on the left, the canvas as
    turtlesim showed it (500 px, each stroke in its colour and width, and
    the ink on it that is not read, (strokes, looks): teleports', and ink
    from before the drawing began); on the right, the ink
    read, its box enlarged (the ink not read left out:
    with none driven, an empty frame), with each of `letters` (label,
    strokes), the letters read, drawn thin and dashed over the ink and
    named; `caption` (lines) above. Nothing expected is drawn: a guess's
    shape laid over the ink misleads."""
    application()
    lines = caption.split('\n')
    top = 16 * len(lines) + 10
    image = QImage(CANVAS_PIXELS + ZOOM_PX + 30, CANVAS_PIXELS + top + 10, QImage.Format_RGB32)
    image.fill(QColor('white'))
    painter = QPainter(image)
    painter.setRenderHint(QPainter.Antialiasing)
    painter.setFont(QFont('Sans', 9))
    painter.setPen(QColor('black'))
    for i, line in enumerate(lines):
        painter.drawText(10, 16 * (i + 1), line)
    points = [p for s in strokes for p in s] or [(0.0, 0.0)]
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    side = max(max(xs) - min(xs), max(ys) - min(ys), 0.05) * 1.15
    middle = ((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2)
    canvas = (10, top, CANVAS_PIXELS / WORLD_SIZE, (0.0, 0.0), WORLD_SIZE)
    zoom = (CANVAS_PIXELS + 20, top, ZOOM_PX / side,
            (middle[0] - side / 2, middle[1] - side / 2), side)
    for view, inks in ((canvas, [unread, (strokes, looks)]), (zoom, [(strokes, looks)])):
        left, upper, scale, corner, size = view
        area = QRectF(left, upper, size * scale, size * scale)
        painter.setClipRect(area)
        painter.fillRect(area, QColor(*background))
        for ink, ink_looks in inks:
            _inked(painter, ink, ink_looks, view)
        painter.setClipping(False)
        painter.setPen(QColor('black'))
        painter.drawRect(area)
    _letters_over(painter, letters, zoom)
    painter.end()
    image.save(path_png, 'PNG')


def _on(view):
    """The pixel a point of the world (m) is at in `view`, (left, upper,
    scale, corner, size): y up in the world, down on the image."""
    left, upper, scale, corner, size = view

    def px(p):
        return QPointF(left + (p[0] - corner[0]) * scale,
                       upper + (size - (p[1] - corner[1])) * scale)
    return px


def _inked(painter, strokes, looks, view):
    """Each stroke in its look, (r, g, b, width px) or () for the default
    pen, as turtlesim drew it on `view`, its width widened as it is enlarged."""
    px = _on(view)
    widen = max(1.0, min(4.0, view[2] * WORLD_SIZE / CANVAS_PIXELS))
    for stroke, look in zip(strokes, looks):
        colour = QColor(*look[:3]) if len(look) >= 3 else QColor(*DEFAULT_PEN)
        width = (look[3] if len(look) > 3 else DEFAULT_PEN_WIDTH) * widen
        painter.setPen(QPen(colour, width, Qt.SolidLine, Qt.RoundCap, Qt.RoundJoin))
        for a, b in zip(stroke, stroke[1:]):
            painter.drawLine(px(a), px(b))


def _letters_over(painter, letters, view):
    """Each (label, strokes) thin and dashed, in black under white so it
    shows on any ink, named at its top left; a label without strokes (a
    letter OCR reads that no form fits) in the view's top left, in turn."""
    left, upper, scale, corner, size = view
    px = _on(view)
    painter.setClipRect(QRectF(left, upper, size * scale, size * scale))
    for k, (label, strokes) in enumerate(letters):
        for pen in (QPen(QColor('black'), 3), QPen(QColor('white'), 1.5, Qt.DashLine)):
            painter.setPen(pen)
            for i, stroke in enumerate(strokes):
                for a, b in zip(stroke, stroke[1:]):
                    painter.drawLine(px(a), px(b))
                # a block letter's middle line is points: dots as wide as a line, every
                # other one white, dashed as a line is
                if len(stroke) == 1 and not (pen.style() == Qt.DashLine and i % 2):
                    painter.drawPoint(px(stroke[0]))
        corner_px = px((min(x for s in strokes for x, _ in s), max(y for s in strokes for _, y in s))
                       ) if any(strokes) else QPointF(left + 2, upper + 18 * (k + 1))
        box = label_box(corner_px, label, view)
        painter.fillRect(box, QColor('white'))
        painter.setPen(QColor('black'))
        painter.drawText(QPointF(box.left() + 3, box.bottom() - 3), label)
    painter.setClipping(False)


def label_box(corner_px, label, view):
    """Where a letter's `label` is written: a box above its top left corner
    (`corner_px`), moved in as far as the view's edges need (a letter at
    the right edge, an l beside an A, had its label cut off there)."""
    left, upper, scale, _, size = view
    width = 9 * len(label) + 6
    x = max(left, min(corner_px.x(), left + size * scale - width))
    y = max(upper, corner_px.y() - 16)
    return QRectF(x, y, width, 15)
