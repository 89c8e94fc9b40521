"""Where the letters are on a canvas (reading/page.py): read past a frame
drawn round them and past another line of writing, as a TA reads them,
and nothing read there that is not drawn. The ink is the builtin font's,
placed by the tests' own helpers."""
import math

import pytest

from support.glyph_rows import row
from turtle_letters.reading.page import read_page, writing_on


def frame(left, bottom, right, top, gap=0.3):
    """A border driven round the writing as one line, its last side stopping `gap` short."""
    return [[(left, bottom), (right, bottom), (right, top), (left, top), (left, bottom + gap)]]


def framed_page(top_text='SNB', bottom_text='002', border=True):
    """`top_text` above `bottom_text` (each 2 m high, 1 m apart), a border round both."""
    ink = row(top_text, bottom=6.0) + (row(bottom_text, bottom=3.0) if bottom_text else [])
    return (frame(0.3, 2.2, 10.5, 9.5) if border else []) + ink


def letters(page):
    return ''.join(r.letter or '?' for r in page.readings)


@pytest.mark.parametrize('border', [True, False])
def test_letters_above_a_line_of_digits_read_in_their_line(border):
    """SNB above 002, framed or not (a real class's snb.py): as one row
    nothing reads; its top line of writing reads SNB, and the row says where."""
    page = read_page(framed_page(border=border), [], 'SNB')
    assert letters(page) == 'SNB'
    assert page.where == 'read in the top line of the 2 lines of its writing'
    assert len(page.writing.ink) == len(row('SNB'))


def test_letters_inside_a_frame_read_inside_it():
    page = read_page(framed_page(bottom_text=''), [], 'SNB')
    assert letters(page) == 'SNB'
    assert page.where == 'read inside the frame drawn round it'


@pytest.mark.parametrize('bottom_text, expected, credited', [
    ('002', 'SNE', 'SN?'), ('002', 'XYZ', '???'), ('002', 'NBS', '???'), ('LIT', 'LIT', '???')])
def test_only_letters_in_their_places_in_the_top_line_are_credited(bottom_text, expected,
                                                                 credited):
    """Graded against letters the page does not draw in their places in
    its top line, none of them is credited: the letters drawn read as
    themselves or not at all, and a lower line is never searched (a
    student who wrote every letter, a line each, would earn any)."""
    page = read_page(framed_page(bottom_text=bottom_text), [], expected)
    assert ''.join(r.letter if r.letter == e else '?'
                   for r, e in zip(page.readings, expected)) == credited


def heart(middle=4.5, bottom=7.0, size=2.5):
    """A heart `size` high: two lobes, each a round arc, and a point below."""
    import math
    lobes = [[(middle + side * size / 4 + size / 4 * math.cos(math.radians(a)),
               bottom + size * 3 / 4 + size / 4 * math.sin(math.radians(a)))
              for a in range(*((-45, 181, 15) if side > 0 else (0, 226, 15)))]
             for side in (1, -1)]
    point = [lobes[1][-1], (middle, bottom), lobes[0][0]]
    return lobes + [point]


@pytest.mark.parametrize('height', [2.5, 5.0])
def test_letters_below_a_picture_above_an_underline_read_in_their_line(height):
    """SARA below a heart, as high as it or two and a half times, and
    underlined (a real class's XAVIERA): read as one, nothing; the line of
    writing with as many letters side by side as expected reads SARA, not
    the picture above it, nor the line below."""
    ink = heart(bottom=5.9, size=height) + row('SARA') + [[(1.0, 2.5), (7.5, 2.5)]]
    page = read_page(ink, [], 'SARA')
    assert letters(page) == 'SARA'
    assert page.where == ('read in line 2 of the 3 lines of its writing, from the top: '
                          'the one nearest 4 letters side by side')


def test_each_line_is_read_in_its_pen_colours():
    """Each letter of the top line in its own colour, the border and the
    digits in others: the line's three colours are its three letters."""
    pink, grey = (255, 0, 255, 3), (128, 128, 128, 3)
    own = [look for look, letter in zip([(200, 0, 0, 3), (0, 200, 0, 3), (0, 0, 200, 3)], 'SNB')
           for _ in row(letter)]
    page = read_page(framed_page(), [pink] + own + [grey] * len(row('002')), 'SNB')
    assert letters(page) == 'SNB' and page.writing.looks == own


@pytest.mark.parametrize('text', ['L', 'E', 'H', 'O', 'LE', 'SNB', 'U'])
def test_a_letter_along_its_own_box_is_no_frame_and_one_line_no_lines(text):
    """An L's stem and foot, an E's bars, a square O run along the ink's
    box, but nothing lies inside them clear of every edge: no frame; a
    row of letters is one line of writing."""
    assert writing_on(row(text), []) == []


def test_a_square_o_round_a_letter_is_a_frame_and_a_ring_is_not():
    """Ink round the rest, along its box, is a frame (a letter in a box);
    a ring round it is a letter's, an O's, and stays."""
    import math
    inside = row('I', bottom=3.0, left=3.0)
    ring = [[(3.2 + 2.5 * math.cos(a / 20 * math.tau), 4.0 + 2.5 * math.sin(a / 20 * math.tau))
             for a in range(21)]]
    assert [where for where, _ in writing_on(frame(0.0, 0.0, 6.5, 8.0) + inside, [])] == \
        ['read inside the frame drawn round it']
    assert writing_on(ring + inside, []) == []


def test_a_piece_of_a_letter_above_the_rest_is_no_line_of_writing():
    """A gothic K half as wide again, tilted 25 degrees, has its flourish
    clear above the rest: a sixth of its height, no line of writing (read
    as one, it was a T, and a K graded against T earned it)."""
    import string
    from support.glyph_rows import touching
    from turtle_letters.reading.ink import box, turned
    ink = touching('gothiceng', 'K', aspect=1.5)
    x, y, w, h = box([p for line in ink for p in line])
    ink = turned(ink, -25, (x + w / 2, y + h / 2))
    assert writing_on(ink, []) == []
    assert [c for c in string.ascii_uppercase if read_page(ink, [], c).readings[0].letter == c] \
        == ['K']


@pytest.fixture
def rows_afresh():
    """No Row worked out before (rows.row_of keeps the last few, and a Row
    its fits): each reading builds every fitting it needs."""
    from turtle_letters.reading import rows
    rows._row.cache_clear()
    yield rows
    rows._row.cache_clear()


def test_a_line_of_writing_that_reads_is_read_before_the_canvas_whole(rows_afresh,
                                                                       monkeypatch):
    """Where a TA looks first: SARA below a heart, underlined, reads in its
    line within the fittings (recognition.FITTINGS) its line alone takes,
    the canvas whole never read as one row (it took a real XAVIERA below a
    heart 1.7 s). Bounded so and graded against another name, the line's
    cuts for it are cut short, and so is the canvas whole, read next: no
    letter is credited that was not read."""
    from turtle_letters.reading import recognition
    from turtle_letters.reading.rows import read_row
    with recognition.bounded(10 ** 6) as effort:
        assert ''.join(r.letter for r in read_row(row('SARA'), 'SARA')) == 'SARA'
    monkeypatch.setattr(recognition, 'FITTINGS', 10 ** 6 - effort.left)
    page = heart() + row('SARA') + [[(1.0, 2.5), (7.5, 2.5)]]
    rows_afresh._row.cache_clear()
    assert letters(read_page(page, [], 'SARA')) == 'SARA'
    rows_afresh._row.cache_clear()
    assert letters(read_page(page, [], 'SAMA')) == '????'


def test_a_row_read_in_fewer_fittings_than_it_takes_reads_none_it_did_not_finish(rows_afresh):
    """A roman triplex ZT, its letters touching, is cut to be read: over a
    hundred fittings. Bounded by the count it took, it reads the same;
    bounded by a quarter of it, the reading stops there and reads no
    letter it did not finish, and nothing escapes it."""
    from support.glyph_rows import touching
    from turtle_letters.reading.recognition import bounded
    ink = touching('rowmant', 'ZT')

    def read(fittings):
        rows_afresh._row.cache_clear()
        with bounded(fittings) as effort:
            return ''.join(r.letter or '?' for r in rows_afresh.read_row(ink, 'ZT')), effort.left
    whole, left = read(10 ** 6)
    taken = 10 ** 6 - left
    assert whole == 'ZT' and taken > 100
    assert read(taken) == ('ZT', 0)
    assert read(taken // 4) == ('??', 0)


def test_past_its_bound_a_canvas_reads_no_letter_by_either_reader(rows_afresh, monkeypatch):
    """read_page and OCR's read_text each bound their reading by
    recognition.FITTINGS: the touching ZT that both read, set to 3, reads
    no letter by the strokes, and OCR, whose cuts the strokes make and
    check, reads none either; neither raises."""
    from support.glyph_rows import touching
    from turtle_letters.reading import recognition
    from turtle_letters.reading.ocr import read_text
    ink = touching('rowmant', 'ZT')
    assert letters(read_page(ink, [], 'ZT')) == 'ZT' and read_text(ink, 'ZT').text == 'ZT'
    rows_afresh._row.cache_clear()
    monkeypatch.setattr(recognition, 'FITTINGS', 3)
    assert letters(read_page(ink, [], 'ZT')) == '??'
    assert read_text(ink, 'ZT').text == ''


def driven(start, moves, step=0.016):
    """One line driven from `start` by `moves` ((dx, dy) m, each at 1 m/s),
    a point each of turtlesim's steps: a holonomic timed drawing."""
    x, y = start
    line = [(x, y)]
    for dx, dy in moves:
        n = max(1, round(math.hypot(dx, dy) / step))
        line += [(x + dx * i / n, y + dy * i / n) for i in range(1, n + 1)]
        x, y = x + dx, y + dy
    return line


def m_on_f(run_on=0.0, short=0.0):
    """An F (stem down from its top bar, `short` m short of the bar's end; middle
    bar there and back), then a zigzag M drawn leftwards from the stem's foot,
    its valleys on the baseline, its last leg driven on `run_on` of a leg's
    length past its foot: a real class's MF, whose last command ran on, and
    whose top bar came back a tenth of a metre short in one run."""
    leg = (-0.9, 3.0)
    return [driven((5.5, 5.5), [(2, 0), (-2 + short, 0), (0, -2), (2, 0), (-2, 0), (0, -2),
                                leg, (leg[0], -leg[1]), leg,
                                (leg[0] * (1 + run_on), -leg[1] * (1 + run_on))])]


@pytest.mark.parametrize('run_on, short', [(0.0, 0.0), (0.3, 0.0), (0.0, 0.1), (0.3, 0.1)])
def test_a_zigzag_m_run_into_its_f_reads_cut_at_their_corner_and_cut_back(rows_afresh, run_on,
                                                                          short):
    """Cut on a tenth of an even share, the M lost its last leg's foot or the F
    its stem: the corner they meet at is the cut. Its last leg driven on a
    third past the other feet (a second of turtlesim's), the M's box is no
    M's: read with that end cut back, and the row says so. The nub of a bar
    driven back short of the stem, cut off the bar, is neither letter's."""
    page = read_page(m_on_f(run_on, short), [], 'MF')
    assert letters(page) == 'MF'
    assert ('ran on past the rest' in page.where) == (run_on > 0)
    for other in ('NF', 'AF', 'MP', 'WE'):
        read = letters(read_page(m_on_f(run_on, short), [], other))
        assert all(r != o or o == d for r, o, d in zip(read, other, 'MF')), (other, read)


@pytest.mark.parametrize('letter, line, cut_back', [
    ('zigzag M', [(0, 0), (0.9, 3), (1.8, 0), (2.7, 3), (3.9, -1)], True),
    ('P, stem last', [(0, 1.5), (1, 1.5), (1, 3), (0, 3), (0, 0)], False),
    ('L, foot last', [(0, 3), (0, 0), (2, 0)], False),
    ('J, stem last', [(0, 1), (0, 0), (1, 0), (1, 3)], False),
    ('M, its leg run on 60% more', [(0, 0), (0.9, 3), (1.8, 0), (2.7, 3), (4.14, -1.8)], False)])
def test_only_a_stroke_run_on_a_third_of_itself_or_less_is_cut_back(letter, line, cut_back):
    """A stroke that goes on a third of its length or less past the rest of
    the ink, along its own axis, was driven on; a P's stem, an L's foot and a
    J's stem go on farther, and are their letters."""
    from turtle_letters.reading.ink import ends_driven_on
    trimmed = ends_driven_on([driven(line[0], [(b[0] - a[0], b[1] - a[1])
                                               for a, b in zip(line, line[1:])])])
    assert (trimmed is not None) == cut_back, letter
    if cut_back:
        assert min(y for _, y in trimmed[0]) == pytest.approx(0.0, abs=0.02)


def test_a_letter_the_ink_cut_back_gains_where_the_ink_as_drawn_reads_another_is_not_credited(
        rows_afresh):
    """A cadets' KB, squeezed to 0.55 of its width and tilted 30 degrees, as
    the recognition benchmark draws it: its K's stem ends lower than the
    rest of the row, along its own axis, and cut back as a stroke driven on
    it leaves half a K, and the B beside it an H's place (the benchmark's
    drawing 2168). As drawn, the row reads KB plainly: no H is credited."""
    from support.glyph_rows import cadets
    from test_ocr import as_the_benchmark_draws
    ink = as_the_benchmark_draws(cadets('KB', aspect=0.55, gap=0.068), longest=2.74, tilt=30,
                                 step=1.32 * 0.016)
    assert letters(read_page(ink, [], 'KB')) == 'KB'
    read = letters(read_page(ink, [], 'KH'))
    assert read[1] != 'H', read


HOME = (5.544445, 5.544445)     # where turtlesim puts turtle1 (the contract)


def begun_at(strokes, start, lead_in=True, size=3.0, at=(1.0, 2.0)):
    """A letter's `strokes` (letter units) `size` m high, each driven as
    turtlesim leaves it: its first stroke begun at `start`, after a
    straight lead-in from there to the letter's lower left at `at`
    (`lead_in`), or the letter placed to begin there."""
    xs, ys = [p[0] for s in strokes for p in s], [p[1] for s in strokes for p in s]
    k = size / (max(ys) - min(ys))
    origin = at if lead_in else (start[0] - (strokes[0][0][0] - min(xs)) * k,
                                 start[1] - (strokes[0][0][1] - min(ys)) * k)
    placed = [[(origin[0] + (x - min(xs)) * k, origin[1] + (y - min(ys)) * k) for x, y in s]
              for s in strokes]
    first = [start] + placed[0] if lead_in else placed[0]
    return [driven(s[0], [(b[0] - a[0], b[1] - a[1]) for a, b in zip(s, s[1:])])
            for s in [first] + placed[1:]]


def glyph(family, letter):
    from turtle_letters.letters.font import FONT
    from turtle_letters.reading.forms import VARIANTS
    return FONT[letter].strokes if family == 'font' else dict(VARIANTS)[letter]


@pytest.mark.parametrize('family, letter', [('font', 'B'), ('font', 'Z'), ('cadets', 'S'),
                                            ('cadets', 'M')])
def test_a_letter_begun_by_a_lead_in_from_where_its_turtle_appeared_reads_past_it(
        family, letter):
    """A turtle driven with its pen down from turtlesim's centre to where
    its letter begins (a real class's B, by `rostopic pub` alone) left a
    straight line into the letter's first stroke: read with it, no letter;
    read past it, the letter, and the row says so. Nothing else earns."""
    import string
    from turtle_letters.reading.page import LED_IN
    ink = begun_at(glyph(family, letter), HOME)
    assert letters(read_page(ink, [], letter)) == '?'
    page = read_page(ink, [], letter, [HOME])
    assert letters(page) == letter and page.where == LED_IN
    assert [c for c in string.ascii_uppercase
            if letters(read_page(ink, [], c, [HOME])) == c] == [letter]


@pytest.mark.parametrize('family, letter, other', [
    ('font', 'D', 'J'), ('font', 'N', 'V'), ('font', 'Y', 'F'), ('cadets', 'W', 'N'),
    ('cadets', 'C', 'L')])
def test_a_first_stroke_begun_where_the_turtle_appeared_is_no_lead_in_to_another_letter(
        family, letter, other):
    """A letter begun where its turtle appeared has no lead-in: its first
    stroke cut off leaves another letter (a D's stem, a J), which the ink
    as drawn, read not knowing the roster, denies."""
    ink = begun_at(glyph(family, letter), HOME, lead_in=False)
    assert letters(read_page(ink, [], letter, [HOME])) == letter
    assert letters(read_page(ink, [], other, [HOME])) != other


def test_only_a_straight_run_from_where_a_turtle_appeared_into_more_ink_is_a_lead_in():
    from turtle_letters.reading.ink import led_in
    into_l = driven(HOME, [(-2, 0), (0, 3)])
    assert led_in([into_l], [HOME]) == [into_l[round(2 / 0.016):]]
    assert led_in([into_l], [(1.0, 1.0)]) is None       # begun elsewhere: no turtle appeared there
    assert led_in([driven(HOME, [(-2, 0)])], [HOME]) is None    # all one run: a stroke
    # an R's bowl begun there, and its stem: the bowl's first steps run straight 9 cm of 4 m
    bowl = [(HOME[0] + 0.5 * math.sin(k * math.tau / 200),
             HOME[1] + 0.5 - 0.5 * math.cos(k * math.tau / 200)) for k in range(201)]
    stem = [(HOME[0], HOME[1] - 3 * k / 100) for k in range(1, 101)]
    assert led_in([bowl + stem], [HOME]) is None


def round_b(poke):
    """A B 4 m high, its stem and two round bowls, the bowls meeting right
    of the stem, and its middle bar driven from there leftwards through
    the stem, `poke` m past it (a real class's B, by `rostopic pub`, ran
    its bar on past its stem in one run of two); the lower bowl a line
    of its own."""
    def arc(centre_y, x=0.65):
        return [(x + math.sin(k * math.pi / 60), centre_y + math.cos(k * math.pi / 60))
                for k in range(1, 61)]
    upper = [(0, 0), (0, 4), (0.65, 4)] + arc(3) + [(-poke, 2)]
    lower = [(0.65, 2)] + arc(1) + [(0, 0)]
    return [driven(line[0], [(b[0] - a[0], b[1] - a[1]) for a, b in zip(line, line[1:])])
            for line in (upper, lower)]


def test_a_bar_driven_on_through_the_stem_it_meets_reads_cut_back_to_the_stem():
    """A B's middle bar run on an eighth of its height past its stem: as
    drawn, no letter; read with the bar cut back to the stem, a B, and the
    row says so. Nothing else earns."""
    import string
    from turtle_letters.reading.page import POKED
    ink = round_b(0.5)
    assert letters(read_page([ink[0][:-round(0.5 / 0.016)]] + ink[1:], [], 'B')) == 'B'
    page = read_page(ink, [], 'B')
    assert letters(page) == 'B' and page.where == POKED
    assert [c for c in string.ascii_uppercase if letters(read_page(ink, [], c)) == c] == ['B']


@pytest.mark.parametrize('poke, cut_back', [(0.1, False), (0.5, True), (0.8, False)])
def test_only_an_end_run_on_past_a_line_it_crosses_by_a_twentieth_to_three_twentieths_is_cut(
        poke, cut_back):
    """Past the stem by less than a twentieth of the height, a nub the fits
    pass over; by more than three twentieths, a stroke of its own (an A's
    bar run on is a leg's foot)."""
    from turtle_letters.reading.ink import poked_through
    trimmed = poked_through(round_b(poke))
    assert (trimmed is not None) == cut_back
    if cut_back:
        assert trimmed[0][-1] == pytest.approx((0.0, 2.0), abs=1e-9)
        assert trimmed[1] == round_b(poke)[1]


@pytest.mark.parametrize('start, cut_back', [(1.0, True), (0.1, False)])
def test_only_a_bar_longer_before_the_line_it_crosses_than_past_it_is_cut_back(start, cut_back):
    """A bar from `start` m right of a 4 m stem, run 0.5 m past it: a bar
    poked through where more of it lies before the stem than past it; else
    a short stroke of its own that crosses a line (a G's bar crossing the
    K beside it, cut away all but its last 2%, left a C). Its start, 0.1 m
    right of the stem, is a nub: no end is cut."""
    from turtle_letters.reading.ink import poked_through
    stem = driven((0.0, 0.0), [(0.0, 4.0)])
    bar = driven((start, 2.0), [(-start - 0.5, 0.0)])
    trimmed = poked_through([stem, bar])
    assert (trimmed is not None) == cut_back
    if cut_back:
        assert trimmed[1][-1] == pytest.approx((0.0, 2.0), abs=1e-9)


def test_a_flood_of_ink_is_not_looked_into_for_ends_poked_through():
    """Each end is compared with all the ink: beside a flood (a loop driven
    round 24 times, 75 heights of ink), a poked B's bar is left as it is
    (thirty turtles' 300,000 points took 8 s)."""
    from turtle_letters.reading.ink import poked_through
    loop = [(10 + 2 * math.cos(k * 0.05), 2 + 2 * math.sin(k * 0.05)) for k in range(3000)]
    assert poked_through(round_b(0.5)) is not None
    assert poked_through(round_b(0.5) + [loop]) is None
