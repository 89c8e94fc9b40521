"""The canvas: pen lines, the colour sensor, the saved picture (Qt offscreen)."""
import os

import pytest

os.environ.setdefault('QT_QPA_PLATFORM', 'offscreen')
from PyQt5.QtGui import QColor, QImage  # noqa: E402
from PyQt5.QtWidgets import QApplication  # noqa: E402

from turtlesim_compat.canvas import Canvas  # noqa: E402
from turtlesim_compat.world import DEFAULT_BACKGROUND, Segment, Turtle, to_pixels  # noqa: E402

APP = QApplication.instance() or QApplication([])


def pixel(image, x, y):
    c = QColor(image.pixel(*(int(round(v)) for v in to_pixels(x, y))))
    return (c.red(), c.green(), c.blue())


def test_lines_in_the_pen_colour_and_the_sensor_sees_them(tmp_path):
    canvas = Canvas(DEFAULT_BACKGROUND)
    assert canvas.colour_at(2.0, 2.0) == DEFAULT_BACKGROUND
    canvas.draw([Segment(1.0, 2.0, 4.0, 2.0, (255, 0, 0), 3)])
    assert canvas.colour_at(2.0, 2.0) == (255, 0, 0)
    assert canvas.colour_at(2.0, 2.5) == DEFAULT_BACKGROUND
    path = str(tmp_path / 'c.png')
    assert canvas.save(path, [])
    saved = QImage(path)
    assert (saved.width(), saved.height()) == (500, 500)
    assert pixel(saved, 3.0, 2.0) == (255, 0, 0)


def test_turtles_are_drawn_on_the_frame_but_leave_no_mark():
    canvas = Canvas(DEFAULT_BACKGROUND)
    frame = canvas.frame([Turtle('t', 5.0, 5.0, 0.0)])
    assert pixel(frame, 5.0, 5.0) != DEFAULT_BACKGROUND
    assert canvas.colour_at(5.0, 5.0) == DEFAULT_BACKGROUND


@pytest.mark.parametrize('colour', [(0, 0, 0), (10, 200, 30)])
def test_clear_fills_with_the_background(colour):
    canvas = Canvas(DEFAULT_BACKGROUND)
    canvas.draw([Segment(1.0, 1.0, 3.0, 3.0, (255, 0, 0), 3)])
    canvas.clear(colour)
    assert canvas.colour_at(2.0, 2.0) == colour


def test_a_save_replaces_its_own_picture_and_nothing_else(tmp_path):
    canvas = Canvas(DEFAULT_BACKGROUND)
    picture = str(tmp_path / 'canvas.png')
    assert canvas.save(picture, [])
    canvas.draw([Segment(1.0, 2.0, 4.0, 2.0, (255, 0, 0), 3)])
    assert canvas.save(picture, [])            # ours: replaced
    assert pixel(QImage(picture), 3.0, 2.0) == (255, 0, 0)

    bashrc = tmp_path / '.bashrc'
    bashrc.write_text('export PATH\n')
    foreign_png = tmp_path / 'photo.png'
    foreign_png.write_bytes(b'\x89PNG\r\n\x1a\n' + b'\0' * 100)
    link = tmp_path / 'link.png'
    link.symlink_to(picture)
    for path in (bashrc, foreign_png, link, tmp_path):
        before = path.read_bytes() if path.is_file() else None
        assert not canvas.save(str(path), []), path
        assert (path.read_bytes() if path.is_file() else None) == before
