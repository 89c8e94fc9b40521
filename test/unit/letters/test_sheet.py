"""The sheet: where a turtle's letters go, like a typewriter."""
import pytest

from support.recorder import CENTRE, settings
from turtle_letters.letters.geometry import PlannedPose
from turtle_letters.letters.layout import DoesNotFit
from turtle_letters.letters.sheet import Sheet


def test_a_full_canvas_is_started_again_at_the_first_place():
    sheet = Sheet(3.0, settings().font)
    start = PlannedPose(CENTRE, CENTRE, 0.0)
    first, must_clear = sheet.reserve('N', start)
    assert not must_clear
    for _ in range(3):                          # the N at 3 m: four places a canvas
        assert not sheet.reserve('N', start)[1]
    places, must_clear = sheet.reserve('N', start)
    assert must_clear and places == first


def test_a_word_that_does_not_fit_is_refused_and_reserves_nothing():
    sheet = Sheet(3.0, settings().font)
    start = PlannedPose(CENTRE, CENTRE, 0.0)
    with pytest.raises(DoesNotFit, match='at most .* of its 12 characters fit'):
        sheet.reserve('NNNNNNNNNNNN', start)
    assert sheet.reserve('N', start) == ([(CENTRE, CENTRE)], False)


def test_a_part_carries_on_from_its_cursor_and_after_a_failure_past_it():
    from turtle_letters.classroom.parts import letter_bounds, part_box
    font = settings().font
    sheet = Sheet(1.0, font)
    box = part_box((1.0, 5.0), 5.0, 1.0, font)      # five letter heights wide
    sheet.give_part((1.0, 5.0), letter_bounds(box, 1.0, font), cursor=(2.0, 5.0))
    assert sheet.reserve('N', None)[0] == [(2.0, 5.0)]
    after = sheet.cursor
    sheet.forget()              # the drawing failed: its place is not used again
    assert sheet.reserve('N', None)[0] == [after]


@pytest.mark.parametrize('earlier', [0, 1, 3])
def test_what_is_undone_takes_no_place_even_where_it_wrapped_the_canvas(earlier):
    sheet = Sheet(3.0, settings().font)
    start = PlannedPose(CENTRE, CENTRE, 0.0)
    for _ in range(earlier):
        sheet.reserve('N', start)
    mark = sheet.mark()
    expected = sheet.reserve('N', start)
    sheet.undo(mark)
    assert sheet.reserve('N', start) == expected
