"""SVG line art: read with svgelements, flattened within the tolerance, fitted
to a height, planned a colour at a time; bad files refused in one line."""
import math
import os
from types import SimpleNamespace

import pytest

svgelements = pytest.importorskip('svgelements')   # Debian's python3-svgelements (make deps)

from turtle_letters.letters import svgart  # noqa: E402
from turtle_letters.letters.font import shown  # noqa: E402
from turtle_letters.motion.modes import MODES  # noqa: E402
from turtle_letters.letters.plan import plan_picture  # noqa: E402
from turtle_letters.letters.geometry import PlannedPose  # noqa: E402
from turtle_letters.settings import Settings  # noqa: E402

DOC = os.path.realpath(os.path.join(os.path.dirname(__file__), '..', '..', '..', 'doc'))
FLOWER = os.path.join(DOC, 'flower.svg')


def write(tmp_path, body, name='art.svg'):
    path = tmp_path / name
    path.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100" '
                    f'viewBox="0 0 100 100">{body}</svg>')
    return str(path)


def distance_to_polyline(q, points):
    best = math.inf
    for a, b in zip(points, points[1:]):
        dx, dy = b[0] - a[0], b[1] - a[1]
        length2 = dx * dx + dy * dy or 1e-30
        t = max(0.0, min(1.0, ((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / length2))
        best = min(best, math.hypot(q[0] - a[0] - t * dx, q[1] - a[1] - t * dy))
    return best


@pytest.mark.parametrize('tolerance', [0.5, 0.05, 0.005])
def test_every_curve_stays_within_the_tolerance_of_the_librarys_own_points(tolerance):
    shapes = svgart.read(os.path.abspath(FLOWER), [DOC])
    for path in shapes.paths:
        polylines = svgart.flatten(path, tolerance)
        for segment in path:
            if isinstance(segment, (svgelements.Move, svgelements.Close, svgelements.Line)):
                continue
            for k in range(201):        # the library's sampling of the true curve
                q = segment.point(k / 200)
                off = min(distance_to_polyline((q[0], q[1]), p) for p in polylines)
                assert off <= tolerance * 1.01, (type(segment).__name__, k, off)


def test_a_finer_tolerance_takes_more_points_but_not_wildly_more():
    path = svgart.read(os.path.abspath(FLOWER), [DOC]).paths[0]        # the circle, r = 12
    coarse = sum(len(p) for p in svgart.flatten(path, 0.5))
    fine = sum(len(p) for p in svgart.flatten(path, 0.005))
    assert coarse < fine < 20 * coarse


def test_the_picture_is_scaled_to_its_height_with_its_aspect_and_transforms(tmp_path):
    path = write(tmp_path, '<g transform="translate(10,20) scale(2)">'
                 '<rect x="0" y="0" width="20" height="10" stroke="#ff0000" fill="none"/></g>')
    picture = svgart.picture(svgart.read(path, [str(tmp_path)]), 1.0)
    points = [p for stroke in picture.strokes for p in stroke]
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    assert (min(xs), min(ys)) == pytest.approx((0.0, 0.0))
    assert (max(xs), max(ys), picture.width) == pytest.approx((2.0, 1.0, 2.0))
    assert picture.colours == [(255, 0, 0)]


def test_y_points_up_on_the_canvas(tmp_path):
    path = write(tmp_path, '<line x1="0" y1="0" x2="0" y2="10" stroke="black"/>'
                 '<line x1="5" y1="0" x2="10" y2="0"/>')
    picture = svgart.picture(svgart.read(path, [str(tmp_path)]), 1.0)
    assert picture.strokes[0] == [pytest.approx((0.0, 1.0)), pytest.approx((0.0, 0.0))]
    assert picture.colours == [(0, 0, 0), None]     # no stroke: the node's own pen


def test_text_is_counted_not_drawn(tmp_path):
    path = write(tmp_path, '<text x="0" y="10">hi</text><circle cx="50" cy="50" r="5"/>')
    shapes = svgart.read(path, [str(tmp_path)])
    assert (shapes.texts, len(shapes.paths)) == (1, 1)


@pytest.mark.parametrize('body, says', [
    ('', 'no shapes to draw'),
    ('<text x="0" y="10">only words</text>', 'only text'),
    ('<circle cx="5" cy="5" r="0"/>', 'no shapes to draw'),
])
def test_a_picture_with_nothing_to_draw_is_refused(tmp_path, body, says):
    with pytest.raises(svgart.SvgError, match=says):
        svgart.picture(svgart.read(write(tmp_path, body), [str(tmp_path)]), 1.0)


def test_bad_files_are_refused_in_one_line(tmp_path):
    cases = {str(tmp_path / 'missing.svg'): 'no such file', 'flower.svg': 'absolute path'}
    garbage = tmp_path / 'garbage.svg'
    garbage.write_bytes(b'\x89PNG\r\n\x1a\n not xml at all <<<')
    cases[str(garbage)] = 'not an SVG file'
    html = tmp_path / 'page.svg'
    html.write_text('<html><body>a page</body></html>')
    cases[str(html)] = r'not an SVG file \(its root: <html>\)'
    for path, says in cases.items():
        with pytest.raises(svgart.SvgError, match=says) as refused:
            svgart.picture(svgart.read(path, [str(tmp_path)]), 1.0)
        assert '\n' not in str(refused.value)


def test_too_many_points_are_refused(tmp_path):
    dots = ''.join(f'<line x1="{i % 100}" y1="{i // 100}" x2="{i % 100}.5" y2="{i // 100}"/>'
                   for i in range(svgart.MAX_POINTS // 2 + 1))
    with pytest.raises(svgart.SvgError, match='more than'):
        svgart.picture(svgart.read(write(tmp_path, dots), [str(tmp_path)]), 1.0)


def test_a_picture_is_drawn_a_colour_at_a_time_with_its_colours():
    picture = svgart.Picture([[(0, 0), (1, 0)], [(0, 1), (1, 1)], [(2, 0), (2, 1)]],
                             [(255, 0, 0), (0, 0, 255), (255, 0, 0)], 2.0, 0)
    settings = Settings(lambda name, default: {'~mode': 'smooth'}.get(name, default))
    plan = plan_picture(picture, (3.0, 4.0), PlannedPose(3.0, 4.0, 0.0), settings)
    assert plan.colours == [(255, 0, 0), (255, 0, 0), (0, 0, 255)]
    assert plan.strokes[0][0] == (3.0, 4.0)
    pens = []
    turtle = SimpleNamespace(pen=lambda down, colour=None: pens.append((down, colour)),
                             glide=lambda points: None)
    MODES['smooth'].carry_out(plan, turtle, lambda drawn, ink: None)
    assert [colour for down, colour in pens if down] == [(255, 0, 0), (255, 0, 0), (0, 0, 255)]


def test_a_pen_of_ones_own_overrides_the_files_colours():
    picture = svgart.Picture([[(0, 0), (1, 0)], [(0, 1), (1, 1)]], [(255, 0, 0), (0, 0, 255)],
                             1.0, 0)
    settings = Settings(lambda name, default: {'~pen': '10 20 30 2'}.get(name, default))
    plan = plan_picture(picture, (3.0, 4.0), PlannedPose(3.0, 4.0, 0.0), settings)
    assert plan.colours == [None, None]         # the node's ~pen for every stroke


def test_a_file_outside_the_folders_allowed_is_refused_alike_whether_it_exists_or_not(tmp_path):
    allowed = tmp_path / 'mine'
    allowed.mkdir()
    (allowed / 'art.svg').symlink_to(FLOWER)        # a link out of the folder
    refusals = []
    for path in ('/etc/passwd', '/etc/no-such-file', FLOWER, str(allowed / 'art.svg'),
                 str(allowed / '..' / '..' / 'etc' / 'passwd')):
        with pytest.raises(svgart.SvgError) as refused:
            svgart.read(path, [str(allowed)])
        refusals.append(str(refused.value).replace(shown(path), 'PATH'))
    assert set(refusals) == {'PATH: only files under the folders of ~svg_dirs are read'}


def test_a_file_too_large_is_refused_unread(tmp_path):
    big = tmp_path / 'big.svg'
    big.write_text('<svg xmlns="http://www.w3.org/2000/svg">' + ' ' * svgart.MAX_BYTES + '</svg>')
    with pytest.raises(svgart.SvgError, match='larger than 5 MB'):
        svgart.read(str(big), [str(tmp_path)])


def test_the_file_in_a_folder_allowed_is_read(tmp_path):
    assert svgart.read(write(tmp_path, '<line x1="0" y1="0" x2="9" y2="9"/>'),
                       [str(tmp_path)]).paths
