"""Capitals of a TrueType font as their outlines: each contour a closed
line, its curves walked in 8 steps, 1 high (fontTools). The recognition
benchmark's block letters, and its tests'. No ROS here."""
import string

DEJAVU_BOLD = ('/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf',
               '/usr/share/fonts/truetype/dejavu/DejaVuSerif-Bold.ttf')


def outline_glyphs(path):
    """{letter: strokes} of a TrueType font's capitals, as outlines (each
    contour a closed line; curves walked in 8 steps), 1 high."""
    from fontTools.pens.basePen import BasePen
    from fontTools.ttLib import TTFont
    font = TTFont(path)
    cap = getattr(font['OS/2'], 'sCapHeight', 0) or font['head'].unitsPerEm * 0.73
    glyph_set, names = font.getGlyphSet(), font.getBestCmap()

    class Outline(BasePen):     # fontTools' way to walk a glyph: its pen protocol
        def __init__(self):
            super().__init__(glyph_set)
            self.lines = []

        def _moveTo(self, p):
            self.lines.append([p])

        def _lineTo(self, p):
            self.lines[-1].append(p)

        def _curveToOne(self, a, b, c):
            start = self.lines[-1][-1]
            for i in range(1, 9):
                t = i / 8
                self.lines[-1].append(tuple(
                    (1 - t) ** 3 * s + 3 * (1 - t) ** 2 * t * p + 3 * (1 - t) * t ** 2 * q +
                    t ** 3 * e for s, p, q, e in zip(start, a, b, c)))

        def _closePath(self):
            self.lines[-1].append(self.lines[-1][0])
    glyphs = {}
    for letter in string.ascii_uppercase:
        pen = Outline()
        glyph_set[names[ord(letter)]].draw(pen)
        glyphs[letter] = [[(x / cap, y / cap) for x, y in line] for line in pen.lines]
    return glyphs
