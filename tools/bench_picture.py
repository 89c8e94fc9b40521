"""The benchmark's picture: ideal strokes, recorded paths, corners enlarged."""
import os

os.environ.setdefault('QT_QPA_PLATFORM', 'offscreen')
from PyQt5.QtCore import QPointF, QRectF, Qt  # noqa: E402
from PyQt5.QtGui import QColor, QFont, QImage, QPainter, QPen  # noqa: E402
from PyQt5.QtWidgets import QApplication  # noqa: E402

COLOURS = {('timed', 'idle'): QColor(33, 102, 172), ('timed', 'loaded'): QColor(103, 169, 207),
           ('timed-wall', 'idle'): QColor(27, 120, 55), ('timed-wall', 'loaded'): QColor(127, 191, 123),
           ('feedback', 'idle'): QColor(178, 24, 43), ('feedback', 'loaded'): QColor(239, 138, 98),
           ('smooth', 'idle'): QColor(118, 42, 131), ('smooth', 'loaded'): QColor(194, 165, 207)}
MAIN_SCALE = 90.0          # px per m in the overview
INSET_SCALE = 12000.0      # px per m in the corner boxes (12 px per mm)
INSET_SIZE = 240           # px: a box shows +-10 mm around a vertex


def draw(path_png, strokes, paths):
    """strokes: ideal polylines in m; paths: {(mode, load): [[(x, y), ...], ...]}."""
    app = QApplication.instance() or QApplication([])  # noqa: F841 (Qt needs one)
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

    def polyline(points, to_px, pen):
        painter.setPen(pen)
        for a, b in zip(points, points[1:]):
            painter.drawLine(to_px(a), to_px(b))

    def overview(p):
        return QPointF(10 + (p[0] - x0) * MAIN_SCALE, 40 + (y1 - p[1]) * MAIN_SCALE)

    painter.setPen(QColor('black'))
    painter.drawText(10, 20, 'Ideal strokes (grey) and recorded paths; '
                             'boxes: +-10 mm around each vertex, 12 px per mm')
    for stroke in strokes:
        polyline(stroke, overview, QPen(QColor(200, 200, 200), 6))
    for key, runs in paths.items():
        for run in runs:
            polyline(run, overview, QPen(COLOURS.get(key, QColor('black')), 1))

    for i, (vx, vy) in enumerate(vertices):
        left = main_w + 20 + (i % columns) * (INSET_SIZE + 10)
        top = 40 + (i // columns) * (INSET_SIZE + 30)
        box = QRectF(left, top, INSET_SIZE, INSET_SIZE)
        painter.setClipRect(box)
        painter.fillRect(box, QColor(250, 250, 250))

        def inset(p, vx=vx, vy=vy, left=left, top=top):
            return QPointF(left + INSET_SIZE / 2 + (p[0] - vx) * INSET_SCALE,
                           top + INSET_SIZE / 2 - (p[1] - vy) * INSET_SCALE)
        for stroke in strokes:
            polyline(stroke, inset, QPen(QColor(200, 200, 200), 3))
        for key, runs in paths.items():
            for run in runs:
                near = [p for p in run if abs(p[0] - vx) < 0.03 and abs(p[1] - vy) < 0.03]
                polyline(near, inset, QPen(COLOURS.get(key, QColor('black')), 1.5))
                painter.setBrush(COLOURS.get(key, QColor('black')))
                for p in near:
                    painter.drawEllipse(inset(p), 1.5, 1.5)
        painter.setClipping(False)
        painter.setBrush(Qt.NoBrush)
        painter.setPen(QColor('black'))
        painter.drawRect(box)
        painter.drawLine(QPointF(left + 10, top + INSET_SIZE - 10),
                         QPointF(left + 10 + 0.001 * INSET_SCALE, top + INSET_SIZE - 10))
        painter.drawText(int(left + 10), int(top + INSET_SIZE - 14), '1 mm')
        painter.drawText(int(left), int(top + INSET_SIZE + 16), f'vertex {i + 1} ({vx:.3f}, {vy:.3f})')

    legend_y = height - 15
    x = 10
    for key, colour in COLOURS.items():
        if key in paths:
            painter.setPen(QPen(colour, 3))
            painter.drawLine(x, legend_y - 4, x + 20, legend_y - 4)
            painter.setPen(QColor('black'))
            painter.drawText(x + 25, legend_y, f'{key[0]} {key[1]}')
            x += 140
    painter.end()
    image.save(path_png, 'PNG')
