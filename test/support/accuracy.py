"""Judging a recorded turtle path against the ideal strokes. No ROS here:
the tests and the benchmark both use it."""
import math

from turtle_letters.plan import WORLD_SIZE

# The lab's ideal N from the turtle's start pose (the lab's own figures).
LAB_N_VERTICES = [(5.5444, 5.5444), (5.5444, 8.5444), (8.0193, 6.0696), (8.0193, 9.0696)]


def distance_to_segment(p, a, b):
    (px, py), (ax, ay), (bx, by) = p, a, b
    dx, dy = bx - ax, by - ay
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / length2))
    return math.hypot(px - (ax + t * dx), py - (ay + t * dy))


def distance_to_polyline(p, vertices):
    return min(distance_to_segment(p, a, b) for a, b in zip(vertices, vertices[1:]))


def worst_distance_from(path, vertices):
    return max(distance_to_polyline(p, vertices) for p in path)


def vertex_errors(path, vertices):
    """For each vertex, how close the path ever came to it."""
    return [min(math.hypot(x - vx, y - vy) for x, y in path) for vx, vy in vertices]


def touches_a_wall(path, clearance=1e-6):
    return any(not (clearance < v < WORLD_SIZE - clearance) for p in path for v in p)
