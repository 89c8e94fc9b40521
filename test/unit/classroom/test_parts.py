"""Parts of a shared canvas: where turtles may draw without crossing."""
import pytest

from turtle_letters.letters.font import BUILTIN
from turtle_letters.letters.hershey import load_font
from turtle_letters.classroom.parts import free_place, letter_bounds, on_canvas, overlaps, part_box, text_width
from turtle_letters.letters.layout import MARGIN, WORLD_SIZE, DoesNotFit, Layout


def test_a_part_holds_its_letters_with_room_all_round():
    box = part_box((2.0, 3.0), 0.6, 1.0, BUILTIN)
    inner = letter_bounds(box, 1.0, BUILTIN)
    assert inner == pytest.approx((2.0, 3.0, 2.6, 3.0 + BUILTIN.ascent))
    assert box[0] < inner[0] and box[2] > inner[2] and box[1] < inner[1] and box[3] > inner[3]


def test_parts_that_only_touch_do_not_overlap():
    a = part_box((1.0, 1.0), 0.6, 1.0, BUILTIN)
    b = (a[2], a[1], a[2] + 1.0, a[3])
    assert not overlaps(a, b)
    assert overlaps(a, (a[2] - 0.01, a[1], a[2] + 1.0, a[3]))


def test_the_first_free_place_is_top_left_then_right_then_below():
    taken = []
    places = []
    for _ in range(40):
        place = free_place(0.6, 1.0, BUILTIN, taken)
        places.append(place)
        taken.append(part_box(place, 0.6, 1.0, BUILTIN))
    assert places[0] == pytest.approx((MARGIN, WORLD_SIZE - MARGIN - BUILTIN.ascent))
    assert places[1][1] == places[0][1] and places[1][0] > places[0][0]
    rows = sorted({round(y, 6) for _, y in places}, reverse=True)
    assert len(rows) > 1, 'the second row never started'
    for i, a in enumerate(taken):
        assert on_canvas(a, 1.0, BUILTIN)
        assert not any(overlaps(a, b) for b in taken[i + 1:])


def test_a_full_canvas_has_no_free_place():
    taken = []
    while True:
        place = free_place(0.6, 3.0, BUILTIN, taken)
        if place is None:
            break
        taken.append(part_box(place, 0.6, 3.0, BUILTIN))
    assert 4 <= len(taken) <= 20


def test_places_are_found_around_a_part_in_the_middle():
    lab = part_box((5.54, 5.54), 0.6, 3.0, BUILTIN)
    taken = [lab]
    for _ in range(30):
        place = free_place(0.6, 1.0, BUILTIN, taken)
        assert place is not None
        box = part_box(place, 0.6, 1.0, BUILTIN)
        assert not overlaps(box, lab)
        taken.append(box)


def test_a_word_makes_its_part_as_wide_as_the_word():
    n = BUILTIN.glyph('N').width
    assert text_width('', BUILTIN) == BUILTIN.widest == n
    assert text_width('NN', BUILTIN) == pytest.approx(n + BUILTIN.letter_spacing + n)


def test_a_cursive_fonts_part_covers_its_overhang():
    scripts = load_font('scripts')
    place = (3.0, 3.0)
    box = part_box(place, text_width('go', scripts), 1.0, scripts)
    inner = letter_bounds(box, 1.0, scripts)
    assert inner[0] == pytest.approx(place[0] - scripts.overhang)
    assert inner[1] == pytest.approx(place[1] - scripts.descent)


def test_a_layout_in_a_part_stays_in_it_and_starts_again_when_full():
    box = part_box((1.0, 5.0), text_width('NN', BUILTIN), 1.0, BUILTIN)
    layout = Layout((1.0, 5.0), 1.0, BUILTIN, bounds=letter_bounds(box, 1.0, BUILTIN))
    second = 1.0 + BUILTIN.glyph('N').width + BUILTIN.letter_spacing
    assert layout.reserve('NN') == ([(1.0, 5.0), (pytest.approx(second), 5.0)], False)
    assert layout.reserve('N') == ([(1.0, 5.0)], True)       # full: back to its first place
    with pytest.raises(DoesNotFit, match="in the turtle's part"):
        layout.reserve('NNN')
