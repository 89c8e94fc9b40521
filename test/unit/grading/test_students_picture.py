"""The class grader's picture of a student's drawing: the ink as turtlesim
drew it, every turtle's in its own colour and width, on the canvas's own
colour, and only the letters read drawn over it. Read back pixel by pixel."""
import math
import os
import subprocess
import sys
import threading

os.environ.setdefault('QT_QPA_PLATFORM', 'offscreen')
from PyQt5.QtGui import QColor, QImage  # noqa: E402

from turtle_letters.grading.picture import ZOOM_PX, draw_ink  # noqa: E402
from turtle_letters.letters.layout import CANVAS_PIXELS, PIXELS_PER_METRE  # noqa: E402

RED, WHITE, GREEN = (255, 0, 0), (255, 255, 255), (0, 128, 0)
BACKGROUND = (10, 20, 30)


def colour_at(image, x, y):
    return QColor(image.pixel(int(x), int(y))).getRgb()[:3]


def test_each_turtles_ink_in_its_colour_and_width_on_the_canvas_colour(tmp_path):
    path = str(tmp_path / 'drawing.png')
    strokes = [[(2.0, 2.0), (2.0, 5.0)], [(4.0, 2.0), (4.0, 5.0)]]
    draw_ink(path, strokes, [(*RED, 3), (*WHITE, 9)], BACKGROUND, [], 'one line')
    image = QImage(path)
    top = image.height() - CANVAS_PIXELS - 10        # the caption's lines above the canvas

    def canvas(x, y):     # a point of the world, m, on the left: the canvas as turtlesim shows it
        return 10 + x * PIXELS_PER_METRE, top + CANVAS_PIXELS - y * PIXELS_PER_METRE
    assert colour_at(image, *canvas(2.0, 3.5)) == RED
    assert colour_at(image, *canvas(4.0, 3.5)) == WHITE
    assert colour_at(image, *canvas(7.0, 7.0)) == BACKGROUND
    # widths: 9 px reaches 3 px off the line, 3 px does not
    assert colour_at(image, canvas(4.0, 3.5)[0] + 3, canvas(4.0, 3.5)[1]) == WHITE
    assert colour_at(image, canvas(2.0, 3.5)[0] + 3, canvas(2.0, 3.5)[1]) == BACKGROUND
    assert image.width() >= CANVAS_PIXELS + ZOOM_PX


def test_ink_teleports_laid_is_on_the_canvas_as_turtlesim_showed_it_not_in_the_ink_read(tmp_path):
    """A class's M laid by pen-down teleports, the dot of its i driven: the
    canvas on the left shows the M, as turtlesim did; the enlarged ink on
    the right is the dot read, without the M."""
    m = [[(1.0, 1.0), (1.0, 3.0), (2.0, 1.0), (3.0, 3.0), (3.0, 1.0)]]
    dot = [[(4.0 + 0.08 * math.cos(a / 8), 2.5 + 0.08 * math.sin(a / 8)) for a in range(51)]]
    path = str(tmp_path / 'mi.png')
    draw_ink(path, dot, [(*WHITE, 2)], BACKGROUND, [], 'teleports', (m, [(*GREEN, 2)]))
    image = QImage(path)
    top = image.height() - CANVAS_PIXELS - 10
    stem = 10 + 1.0 * PIXELS_PER_METRE, top + CANVAS_PIXELS - 2.0 * PIXELS_PER_METRE
    assert colour_at(image, *stem) == GREEN
    zoomed = [colour_at(image, x, y) for x in range(CANVAS_PIXELS + 25, image.width() - 5, 2)
              for y in range(top + 5, image.height() - 15, 2)]
    assert WHITE in zoomed and GREEN not in zoomed


def test_only_the_letters_given_are_drawn_over_the_ink(tmp_path):
    """A letter read is drawn dashed over the enlarged ink; with none
    read, nothing is drawn there but the ink."""
    strokes, looks = [[(2.0, 2.0), (2.0, 5.0), (3.5, 2.0)]], [(*GREEN, 3)]
    bare, read = str(tmp_path / 'bare.png'), str(tmp_path / 'read.png')
    draw_ink(bare, strokes, looks, BACKGROUND, [], 'nothing read')
    draw_ink(read, strokes, looks, BACKGROUND, [('L', [[(2.5, 5.0), (2.5, 2.0), (3.5, 2.0)]])],
             'an L read')
    a, b = QImage(bare), QImage(read)
    right_half = range(CANVAS_PIXELS + 25, a.width() - 5)     # inside the enlarged ink's frame
    differ = sum(a.pixel(x, y) != b.pixel(x, y) for x in right_half[::3] for y in range(0, a.height(), 3))
    same_left = all(a.pixel(x, y) == b.pixel(x, y) for x in range(10, CANVAS_PIXELS, 7)
                    for y in range(40, a.height(), 7))
    assert differ > 50 and same_left
    assert black_in_zoom(a) == 0 < black_in_zoom(b)   # the letter's outline, black under white


def test_a_letter_no_form_fits_is_named_not_drawn(tmp_path):
    """A letter OCR credits where no form of it fits the strokes: its name
    in the enlarged ink's top left, no misfit shape laid over the ink."""
    strokes, looks = [[(2.0, 2.0), (2.0, 5.0), (3.5, 2.0)]], [(*GREEN, 3)]
    bare, named = str(tmp_path / 'bare.png'), str(tmp_path / 'named.png')
    draw_ink(bare, strokes, looks, BACKGROUND, [], 'nothing read')
    draw_ink(named, strokes, looks, BACKGROUND, [('M (OCR)', [])], 'nothing read')
    a, b = QImage(bare), QImage(named)
    changed = [(x, y) for x in range(a.width()) for y in range(a.height())
               if a.pixel(x, y) != b.pixel(x, y)]
    assert changed and all(CANVAS_PIXELS + 20 <= x < CANVAS_PIXELS + 100 and y < 100
                           for x, y in changed)


def test_a_letter_at_the_edge_of_the_ink_is_named_in_full(tmp_path):
    """An A and, at the right edge of the ink, a bare stroke read as an I
    not expected (a real class's Al): the I's label, a white box as wide as
    its name, is written whole inside the enlarged ink's frame, moved in
    from the edge (it was cut off there)."""
    a = [[(1.0, 2.0), (1.5, 5.0), (2.0, 2.0)], [(1.25, 3.5), (1.75, 3.5)]]
    stroke = [[(3.0, 2.0), (3.0, 5.0)]]
    label = 'I: not expected'
    path = str(tmp_path / 'al.png')
    draw_ink(path, a + stroke, [(*GREEN, 3)] * 3, BACKGROUND,
             [('A', a), (label, stroke)], 'an A and an I read')
    image = QImage(path)
    widest = max(sum(colour_at(image, x, y) == WHITE
                     for x in range(CANVAS_PIXELS + 20, image.width()))
                 for y in range(40, image.height() - 10))
    assert widest >= 9 * len(label) + 6


def black_in_zoom(image):
    """How many black pixels the enlarged ink's frame holds, on a grid of 2 px."""
    return sum(colour_at(image, x, y) == (0, 0, 0)
               for x in range(CANVAS_PIXELS + 25, image.width() - 5, 2)
               for y in range(45, image.height() - 15, 2))


def test_a_letter_read_by_its_middle_line_is_drawn_as_its_points(tmp_path):
    """A block letter is read by its middle line, whose candidates are
    points (lines of one point each): each is drawn over the ink, and
    they cover no more of it than the same letter's lines would (a real
    XAVIERA's E, 265 points each drawn a pen's width round, was a bold
    white E over a thin one)."""
    strokes, looks = [[(2.0, 5.0), (2.0, 2.0), (3.5, 2.0)]], [(*GREEN, 3)]
    middle = [[(2.1, 2.1 + 0.1 * i)] for i in range(29)] + [[(2.2 + 0.1 * i, 2.1)] for i in range(12)]
    lines = [[(2.1, 4.9), (2.1, 2.1), (3.3, 2.1)]]
    pictures = {}
    for name, letters in (('bare', []), ('points', [('L', middle)]), ('lines', [('L', lines)])):
        pictures[name] = str(tmp_path / f'{name}.png')
        draw_ink(pictures[name], strokes, looks, BACKGROUND, letters, 'an L')
    bare, points, drawn = (QImage(pictures[name]) for name in ('bare', 'points', 'lines'))

    def covered(image):
        return sum(image.pixel(x, y) != bare.pixel(x, y)
                   for x in range(CANVAS_PIXELS + 25, image.width() - 5)
                   for y in range(45, image.height() - 5))
    assert black_in_zoom(points) > 20
    assert covered(points) <= covered(drawn)


def test_pictures_painted_in_several_threads_at_once_are_those_painted_in_the_main_one(tmp_path):
    """The class grader paints each student's picture in the student's own
    thread, two or more at once (--jobs): Qt paints a QImage, text too, off
    its main thread once its application is made in the main one."""
    from PyQt5.QtGui import QFontDatabase

    from turtle_letters.grading.picture import application
    application()
    assert QFontDatabase.supportsThreadedFontRendering()
    strokes, looks = [[(2.0, 2.0), (2.0, 5.0), (3.5, 2.0)]], [(*GREEN, 3)]
    letters = [('L', [[(2.5, 5.0), (2.5, 2.0), (3.5, 2.0)]])]
    main = str(tmp_path / 'main.png')
    draw_ink(main, strokes, looks, BACKGROUND, letters, 'an L read, in words')
    paths = [str(tmp_path / f'thread{i}.png') for i in range(4)]
    threads = [threading.Thread(target=draw_ink, args=(path, strokes, looks, BACKGROUND,
                                                       letters, 'an L read, in words'))
               for path in paths]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    expected = QImage(main)
    assert all(QImage(path) == expected for path in paths)


def test_painting_from_a_login_without_a_runtime_folder_warns_of_nothing():
    """Graded from a root shell over ssh, no XDG_RUNTIME_DIR set, Qt warned
    on the instructor's terminal ("QStandardPaths: XDG_RUNTIME_DIR not
    set") as the grader made its first picture."""
    src = os.path.join(os.path.dirname(__file__), '..', '..', '..', 'src')
    env = {k: v for k, v in os.environ.items() if k != 'XDG_RUNTIME_DIR'}
    env['PYTHONPATH'] = os.pathsep.join([src] + env.get('PYTHONPATH', '').split(os.pathsep))
    painted = subprocess.run(
        [sys.executable, '-c', 'from turtle_letters.grading.picture import application; '
                               'application()'],
        env=env, capture_output=True, text=True, timeout=120)
    assert painted.returncode == 0, painted.stderr
    assert 'XDG_RUNTIME_DIR' not in painted.stderr
