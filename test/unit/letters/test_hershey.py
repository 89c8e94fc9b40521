"""Hershey fonts, parsed from the files Debian's hershey-fonts-data installs."""
import string

import pytest

from turtle_letters.letters.hershey import FOLDER, FontError, installed, load_font, parse_jhf
from turtle_letters.settings import ParameterError, Settings


@pytest.fixture(scope='module', autouse=True)
def package():
    assert {'futural', 'scripts'} <= set(installed()), \
        f'hershey-fonts-data is not installed (no fonts in {FOLDER}): make deps installs it'


@pytest.mark.parametrize('name', ['futural', 'scripts'])
def test_every_printable_character_has_a_glyph_inside_its_box(name):
    font = load_font(name)
    assert font.overhang < 0.5          # cursive tails and joins reach past the edges
    for char in string.printable.strip():
        glyph = font.glyph(char)
        assert glyph is not None, char
        for stroke in glyph.strokes:
            assert len(stroke) >= 1
            for x, y in stroke:
                assert -font.overhang <= x <= glyph.width + font.overhang, (char, x)
                assert -font.descent <= y <= font.ascent, (char, y)
    assert font.glyph('H').strokes and font.glyph('h').strokes != font.glyph('H').strokes


def test_capitals_are_one_letter_height_tall():
    h = load_font('futural').glyph('H')
    ys = [y for stroke in h.strokes for _, y in stroke]
    assert (min(ys), max(ys)) == (0.0, 1.0)


def test_a_record_may_go_on_over_the_next_line():
    # one glyph: edges -5..5, a stroke (0,-12)-(0,9), pen up, a dot at (3,9)
    record = '  100  5LWRFR[ RU['
    assert parse_jhf(record[:12] + '\n' + record[12:] + '\n') == [
        (-6, 5, [[(0, -12), (0, 9)], [(3, 9)]])]


def test_an_unknown_font_names_the_installed_ones():
    with pytest.raises(FontError) as refused:
        load_font('comic')
    assert str(refused.value).startswith('builtin, ') and 'futural' in str(refused.value)


def test_settings_take_any_printable_text_in_a_hershey_font():
    s = Settings(lambda name, default: {'~font': 'scripts', '~text': 'Hello, World!',
                                        '~letter': 'g'}.get(name, default))
    assert (s.font.name, s.text, s.letter) == ('scripts', 'Hello, World!', 'g')


def test_a_bad_font_name_is_one_line_listing_the_fonts():
    with pytest.raises(ParameterError) as refused:
        Settings(lambda name, default: {'~font': 'comic'}.get(name, default))
    message = str(refused.value)
    assert message.startswith("~font is 'comic'; allowed: builtin, ") and '\n' not in message
