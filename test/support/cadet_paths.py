"""Paths as cadets' turtles draw letters: no pen-up moves, so every stroke
is reached along the ones already drawn (a walk that retraces), and corners
rounded as closed-loop control rounds them. For the recognition tests."""
import math
import random

from turtle_letters.letters.geometry import distance_to_segment


def _crossing(a, b, c, d):
    """Where segments ab and cd cross, or None."""
    r, s = (b[0] - a[0], b[1] - a[1]), (d[0] - c[0], d[1] - c[1])
    cross = r[0] * s[1] - r[1] * s[0]
    if abs(cross) < 1e-12:
        return None
    t = ((c[0] - a[0]) * s[1] - (c[1] - a[1]) * s[0]) / cross
    u = ((c[0] - a[0]) * r[1] - (c[1] - a[1]) * r[0]) / cross
    if 0 <= t <= 1 and 0 <= u <= 1:
        return (round(a[0] + t * r[0], 9), round(a[1] + t * r[1], 9))
    return None


def _split(strokes):
    """The strokes' segments, cut wherever another stroke ends or crosses one."""
    strokes = [[(round(x, 9), round(y, 9)) for x, y in s] for s in strokes]
    pairs = [(a, b) for s in strokes for a, b in zip(s, s[1:])]
    marks = [p for s in strokes for p in (s[0], s[-1])]
    marks += [x for i, (a, b) in enumerate(pairs) for c, d in pairs[i + 1:]
              for x in [_crossing(a, b, c, d)] if x is not None]
    segments = []
    for s in strokes:
        for a, b in zip(s, s[1:]):
            cuts = sorted((math.dist(a, p), p) for p in set(marks)
                          if math.dist(p, a) > 1e-6 and math.dist(p, b) > 1e-6
                          and distance_to_segment(p, a, b) < 1e-6)
            points = [a] + [p for _, p in cuts] + [b]
            segments += list(zip(points, points[1:]))
    return segments


def retraced(strokes):
    """One walk over every segment, going back along drawn ones to reach the
    next; parts that touch nothing drawn are reached by a straight move."""
    segments = _split(strokes)
    start = segments[0][0]
    links = {}
    for a, b in segments:
        links.setdefault(a, []).append(b)
        links.setdefault(b, []).append(a)
    done, walk = set(), []

    def visit(here):
        for there in links[here]:
            if frozenset((here, there)) not in done:
                done.add(frozenset((here, there)))
                walk.append(there)
                visit(there)
                walk.append(here)
    for here in [start] + list(links):
        if any(frozenset((here, t)) not in done for t in links[here]):
            walk.append(here)
            visit(here)
    return walk


def rounded(path, radius):
    """`path` with each corner cut by an arc-like bevel `radius` long each way."""
    out = [path[0]]
    for a, b, c in zip(path, path[1:], path[2:]):
        ab, bc = math.dist(a, b), math.dist(b, c)
        if ab < 1e-9 or bc < 1e-9:
            continue
        r = min(radius, ab / 2, bc / 2)
        p = (b[0] + (a[0] - b[0]) * r / ab, b[1] + (a[1] - b[1]) * r / ab)
        q = (b[0] + (c[0] - b[0]) * r / bc, b[1] + (c[1] - b[1]) * r / bc)
        out += [p, ((p[0] + 2 * b[0] + q[0]) / 4, (p[1] + 2 * b[1] + q[1]) / 4), q]
    return out + [path[-1]]


def placed(points, left, bottom, height, width_scale=1.0):
    """Unit-height points at (left, bottom), `height` m high, widths scaled."""
    return [(left + x * height * width_scale, bottom + y * height) for x, y in points]


def driven(commands, x=0.0, y=0.0, heading=0.0, tick=0.016):
    """The path of a turtle given `commands`, each (linear m/s, angular
    rad/s, seconds), in turtlesim's ticks from (x, y) facing `heading`: a
    turn in place lays no point, a turn while moving an arc."""
    points = [(x, y)]
    for linear, angular, seconds in commands:
        for _ in range(int(round(seconds / tick))):
            heading += angular * tick
            x, y = x + linear * math.cos(heading) * tick, y + linear * math.sin(heading) * tick
            if linear:
                points.append((x, y))
    return points


def turn(angle):
    """A turn in place by `angle` radians (counter-clockwise), in 1 s."""
    return 0.0, angle, 1.0


def forward(distance):
    return distance, 0.0, 1.0


def arc(radius, angle):
    """An arc of `radius` through `angle` radians, in 1 s: counter-clockwise
    for a positive angle, clockwise for a negative one."""
    return radius * abs(angle), angle, 1.0


def wandering(turtles=30, steps=3750, seed=3):
    """Thirty turtles each wandering a minute at 1 m/s in turtlesim's 16 ms
    steps, turning a little at random, kept on the canvas: 112,500 points."""
    rng, ink = random.Random(seed), []
    for _ in range(turtles):
        x, y, heading, line = rng.uniform(1, 10), rng.uniform(1, 10), rng.uniform(0, 6.3), []
        for _ in range(steps):
            heading += rng.uniform(-0.2, 0.25)
            x = min(11.0, max(0.0, x + 0.016 * math.cos(heading)))
            y = min(11.0, max(0.0, y + 0.016 * math.sin(heading)))
            line.append((x, y))
        ink.append(line)
    return ink
