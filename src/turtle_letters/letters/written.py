"""Letters written as the lab writes them: a function that calls
rotate(degrees) and move(meters) on the turtle it is given (lab.py). No ROS here.

record() runs one on a turtle that only notes the calls: from them come the
letter's stroke for the font and the steps feedback mode steers
(primitives.written_steps). In timed mode the function itself runs on the
real turtle (motion/modes.py), through Scaled, at the letter's size.
"""
from typing import Callable, List, Tuple


class _Recorder:
    def __init__(self):
        self.calls = []

    def rotate(self, degrees):
        self.calls.append(('rotate', float(degrees)))

    def move(self, meters):
        self.calls.append(('move', float(meters)))


def record(program: Callable) -> List[Tuple[str, float]]:
    """The calls `program` makes: ('rotate', degrees) and ('move', meters)."""
    recorder = _Recorder()
    program(recorder)
    return recorder.calls


def turn_as_told(degrees: float, direction: str) -> float:
    """A written rotate as ~turn_direction has it: ccw, as written; shortest,
    the shorter way round."""
    return (degrees + 180.0) % 360.0 - 180.0 if direction == 'shortest' else degrees


class Scaled:
    """A real turtle as a written letter sees it: moves times `scale` (the
    letter's size over the size it was written at), turns as ~turn_direction
    says, and each move's ink told to `drew(meters)`."""

    def __init__(self, turtle, scale: float, direction: str, drew: Callable[[float], None]):
        self.turtle, self.scale, self.direction, self.drew = turtle, scale, direction, drew

    def rotate(self, degrees):
        self.turtle.rotate(turn_as_told(degrees, self.direction))

    def move(self, meters):
        self.turtle.move(meters * self.scale)
        self.drew(meters * self.scale)
