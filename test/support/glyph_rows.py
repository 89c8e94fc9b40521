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
