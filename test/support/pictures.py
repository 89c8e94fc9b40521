"""Reading a saved turtlesim picture: the colour at a point of the canvas."""
from PyQt5.QtGui import QColor


def pixel(image, x, y):
    """(r, g, b) of a QImage of the 500-pixel canvas at (x, y) m."""
    c = QColor(image.pixel(int(round(x * 45)), int(round(499 - y * 45))))
    return (c.red(), c.green(), c.blue())
