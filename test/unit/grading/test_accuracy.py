import pytest

from support.accuracy import (distance_to_polyline, distance_to_segment, touches_a_wall,
                                     vertex_errors, worst_distance_from)


def test_distance_to_a_segment_clamps_to_its_ends():
    assert distance_to_segment((1, 1), (0, 0), (2, 0)) == pytest.approx(1)
    assert distance_to_segment((3, 0), (0, 0), (2, 0)) == pytest.approx(1)
    assert distance_to_segment((0, 5), (0, 0), (0, 0)) == pytest.approx(5)


def test_path_against_a_polyline():
    corner = [(0, 0), (0, 1), (1, 1)]
    assert distance_to_polyline((0.5, 1.2), corner) == pytest.approx(0.2)
    assert worst_distance_from([(0, 0.5), (0.5, 1.0), (1.1, 1.0)], corner) == pytest.approx(0.1)
    assert vertex_errors([(0, 0.001), (0, 1), (0.9, 1)], corner) == pytest.approx([0.001, 0, 0.1])


def test_walls():
    assert touches_a_wall([(0.0, 5.0)])
    assert touches_a_wall([(5.0, 499 / 45.0)])
    assert not touches_a_wall([(0.5, 10.5)])
