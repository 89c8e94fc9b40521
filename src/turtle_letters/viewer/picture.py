"""The rebuilt canvas as pixels, for /canvas/image and /canvas.png:
painted stroke by stroke as they come, with Qt (which paints into an image
from any thread, with no display). No ROS here."""
import threading

from PyQt5.QtCore import QBuffer, QIODevice, QLineF, QPointF, Qt
from PyQt5.QtGui import QColor, QImage, QPainter, QPen

from ..letters.layout import CANVAS_PIXELS
from .trails import to_pixels


class Painting:
    """The canvas of `trails`, brought up to date by `update()`."""

    def __init__(self, trails):
        self.trails = trails
        self.image = QImage(CANVAS_PIXELS, CANVAS_PIXELS, QImage.Format_RGB888)
        self.image.fill(QColor(*trails.background))
        self.clears, self.count = 0, 0
        self.lock = threading.Lock()

    def update(self):
        with self.lock:
            clears, strokes, _ = self.trails.since(self.clears, self.count)
            if clears != self.clears:
                self.image.fill(QColor(*self.trails.background))
                self.clears, self.count = clears, 0
            strokes = strokes or []     # (None: folded past it, which fold() never does to it)
            by_pen = {}         # a pen costs more to set than a line to draw
            for stroke in strokes:
                by_pen.setdefault((stroke.colour, stroke.width), []).append(
                    QLineF(QPointF(*to_pixels(stroke.x0, stroke.y0)),
                           QPointF(*to_pixels(stroke.x1, stroke.y1))))
            painter = QPainter(self.image)
            for (colour, width), lines in by_pen.items():
                painter.setPen(QPen(QColor(*colour), width, Qt.SolidLine, Qt.SquareCap))
                painter.drawLines(lines)
            painter.end()
            self.count += len(strokes)

    def painted(self):
        """(clears, strokes since that clear) the picture holds, brought up to date."""
        self.update()
        with self.lock:
            return self.clears, self.count

    def rgb(self):
        """The pixels, row after row, 3 bytes (r, g, b) each: sensor_msgs/Image's rgb8."""
        with self.lock:
            bits = self.image.constBits()
            bits.setsize(self.image.byteCount())
            return bytes(bits)

    def snapshot(self):
        """(clears, strokes painted, PNG): the canvas brought up to date, and
        where in the strokes it stands, for a page to go on from there."""
        self.update()
        with self.lock:
            buffer = QBuffer()
            buffer.open(QIODevice.WriteOnly)
            self.image.save(buffer, 'PNG')
            return self.clears, self.count, bytes(buffer.data())
