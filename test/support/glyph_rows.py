"""Ink of the builtin font's letters side by side, as a cadet places them,
for the tests of the two readers. No ROS here."""
from turtle_letters.letters.font import FONT


def row(text, gap=0.1, size=2.0, left=1.0, bottom=3.0):
    """`text` in the builtin font, each letter `gap` (share of the height) after the last."""
    ink, x = [], 0.0
    for letter in text:
        ink += [[(left + (px + x) * size, bottom + py * size) for px, py in stroke]
                for stroke in FONT[letter].strokes]
        x += FONT[letter].width + gap
    return ink


def touching(family, text, aspect=1.0, gap=0.0):
    """`text` in a Hershey family, each letter's ink starting `gap` after
    where the last one's ends, all `aspect` times as wide (as the
    recognition benchmark draws its rows)."""
    from turtle_letters.letters.hershey import load_font
    font = load_font(family)
    return side_by_side([font.glyph(letter).strokes for letter in text], aspect, gap)


def cadets(text, aspect=1.0, gap=0.0):
    """touching(), in the forms cadets draw with rotate and move (each
    letter's last in forms.VARIANTS, as the benchmark draws them)."""
    from turtle_letters.reading.forms import VARIANTS
    glyphs = dict(VARIANTS)
    return side_by_side([glyphs[letter] for letter in text], aspect, gap)


def side_by_side(glyphs, aspect, gap):
    """Each glyph's strokes starting `gap` after the last one's end, all `aspect` times as wide."""
    ink, x = [], 0.0
    for strokes in glyphs:
        left = min(px for s in strokes for px, _ in s)
        ink += [[((px - left + x) * aspect, py) for px, py in s] for s in strokes]
        x += max(px for s in strokes for px, _ in s) - left + gap
    return ink
