"""The picture: pen lines on a background, with the turtles drawn on top.

Qt but no ROS. Pen lines go into one image that persists (as in the real
node); the turtles are painted over a copy of it whenever a frame is shown or
saved, so they never leave marks.
"""
import math
from typing import Iterable, Tuple

from PyQt5.QtCore import QLineF, QPointF, QRectF, Qt
from PyQt5.QtGui import QColor, QImage, QPainter, QPainterPath, QPen, QPolygonF

from .files import SIGNATURE, ours_to_replace
from .world import CANVAS_PIXELS, Segment, Turtle, to_pixels

# The icon's colours stay clear of the default pen and background colours.
_SHELL = QColor(46, 125, 50)
_SHELL_EDGE = QColor(27, 67, 30)
_SKIN = QColor(139, 195, 74)


def qt_round(value: float) -> int:
    """A pixel position as Qt's QPointF.toPoint() gives it, as turtlesim
    reads its colour sensor: half away from zero (Python's round() gives
    half to even: 22.5 is 22 there, 23 here)."""
    return int(value + 0.5) if value >= 0 else -int(-value + 0.5)


class Canvas:
    def __init__(self, background: Tuple[int, int, int]) -> None:
        self._paths = QImage(CANVAS_PIXELS, CANVAS_PIXELS, QImage.Format_RGB32)
        self.clear(background)

    def clear(self, background: Tuple[int, int, int]) -> None:
        self._paths.fill(QColor(*background))

    def draw(self, segments: Iterable[Segment]) -> None:
        """One tick's lines of every turtle, one pen at a time (a pen costs
        more to set than a line to draw)."""
        by_pen = {}
        for s in segments:
            by_pen.setdefault((s.colour, s.width), []).append(
                QLineF(QPointF(*to_pixels(s.x0, s.y0)), QPointF(*to_pixels(s.x1, s.y1))))
        painter = QPainter(self._paths)
        for (colour, width), lines in by_pen.items():
            # Square caps join consecutive short segments without gaps.
            painter.setPen(QPen(QColor(*colour), width, Qt.SolidLine, Qt.SquareCap))
            painter.drawLines(lines)
        painter.end()

    def colour_at(self, x: float, y: float) -> Tuple[int, int, int]:
        px, py = (qt_round(v) for v in to_pixels(x, y))
        px = min(max(px, 0), CANVAS_PIXELS - 1)
        py = min(max(py, 0), CANVAS_PIXELS - 1)
        c = QColor(self._paths.pixel(px, py))
        return (c.red(), c.green(), c.blue())

    def frame(self, turtles: Iterable[Turtle]) -> QImage:
        """The pen lines with every turtle painted on top."""
        image = self._paths.copy()
        painter = QPainter(image)
        painter.setRenderHint(QPainter.Antialiasing)
        for turtle in turtles:
            paint_turtle(painter, turtle)
        painter.end()
        return image

    def save(self, path: str, turtles: Iterable[Turtle]) -> bool:
        """False, and nothing written, where `path` holds anything but a picture of ours."""
        if not ours_to_replace(path):
            return False
        image = self.frame(turtles)
        image.setText('Software', SIGNATURE)
        return image.save(path, 'PNG')


def paint_turtle(painter: QPainter, turtle: Turtle) -> None:
    """A top view of a turtle, head towards its heading, about 30 px long."""
    painter.save()
    painter.translate(*to_pixels(turtle.x, turtle.y))
    painter.rotate(-math.degrees(turtle.theta))  # canvas y points down
    painter.setPen(QPen(_SHELL_EDGE, 1.2))
    painter.setBrush(_SKIN)
    for fx, fy in ((6, 8), (6, -8), (-7, 8), (-7, -8)):
        painter.drawEllipse(QRectF(fx - 3, fy - 3, 6, 6))          # feet
    painter.drawEllipse(QRectF(9, -4, 9, 8))                        # head
    tail = QPolygonF([QPointF(-10, -2), QPointF(-16, 0), QPointF(-10, 2)])
    painter.drawPolygon(tail)
    painter.setBrush(_SHELL)
    painter.drawEllipse(QRectF(-12, -9, 23, 18))                    # shell
    pattern = QPainterPath()
    pattern.addRect(QRectF(-4, -3.5, 7, 7))
    painter.setBrush(Qt.NoBrush)
    painter.drawPath(pattern)
    painter.restore()
