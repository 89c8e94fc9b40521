"""The rebuilt canvas as pixels: each stroke in its colour, the background
again after a clear."""
from support.ticks import drive
from turtle_letters.viewer.picture import Painting
from turtle_letters.viewer.trails import DEFAULT_BACKGROUND, Trails, to_pixels

RED = (255, 0, 0)


def test_the_painting_shows_each_stroke_in_its_colour_and_starts_over_after_a_clear():
    trails = Trails()
    drive(trails, 't', [(1.0, 1.0), (3.0, 1.0)], RED)
    painting = Painting(trails)
    painting.update()
    pixels = painting.rgb()
    x, y = (round(v) for v in to_pixels(2.0, 1.0))
    assert pixels[3 * (500 * y + x):3 * (500 * y + x) + 3] == bytes(RED)
    assert pixels[:3] == bytes(DEFAULT_BACKGROUND) and len(pixels) == 500 * 500 * 3
    trails.clear()
    painting.update()
    assert painting.rgb() == bytes(DEFAULT_BACKGROUND) * 500 * 500
    clears, count, png = painting.snapshot()
    assert (clears, count) == (1, 0) and png.startswith(b'\x89PNG')
