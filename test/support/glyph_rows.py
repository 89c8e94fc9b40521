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
    font, ink, x = load_font(family), [], 0.0
    for letter in text:
        strokes = font.glyph(letter).strokes
        left = min(px for s in strokes for px, _ in s)
        ink += [[((px - left + x) * aspect, py) for px, py in s] for s in strokes]
        x += max(px for s in strokes for px, _ in s) - left + gap
    return ink
