"""Turtle kinematics and bookkeeping, as the real turtlesim does them.

No ROS and no Qt here: this module is the simulator's behaviour, tested on its
own. Every number below is a fact of the real turtlesim (see the contract).
"""
import math
import re
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

CANVAS_PIXELS = 500
PIXELS_PER_METER = 45.0
# The last pixel column/row is at 499, so the usable size is (500 - 1) / 45 m.
WORLD_SIZE = (CANVAS_PIXELS - 1) / PIXELS_PER_METER
CENTRE = WORLD_SIZE / 2.0
TICK_SECONDS = 0.016          # fixed simulated step, however late a tick comes
COMMAND_TIMEOUT = 1.0         # wall-clock seconds before velocities drop to zero
DEFAULT_BACKGROUND = (69, 86, 255)
DEFAULT_PEN_COLOUR = (179, 184, 255)
DEFAULT_PEN_WIDTH = 3

# What roscpp's ros::names::validate takes, and so the real node: a letter,
# / or ~ first, then letters, digits, _ and /; 'lab/alice' is a turtle whose
# topics are lab/alice/pose...
_NAME_PATTERN = re.compile(r'^[A-Za-z/~][A-Za-z0-9_/]*$')


class RequestError(ValueError):
    """A request the simulator refuses; the message says why."""


@dataclass
class Pen:
    r: int = DEFAULT_PEN_COLOUR[0]
    g: int = DEFAULT_PEN_COLOUR[1]
    b: int = DEFAULT_PEN_COLOUR[2]
    width: int = DEFAULT_PEN_WIDTH
    down: bool = True

    @property
    def colour(self) -> Tuple[int, int, int]:
        return (self.r, self.g, self.b)


@dataclass
class Segment:
    """A line the pen leaves on the canvas, in meters."""
    x0: float
    y0: float
    x1: float
    y1: float
    colour: Tuple[int, int, int]
    width: int


def wrap_angle(theta: float) -> float:
    """Wrap into [-pi, pi)."""
    return (theta + math.pi) % (2.0 * math.pi) - math.pi


def require_finite(**values: float) -> None:
    bad = [f'{k}={v}' for k, v in values.items() if not math.isfinite(v)]
    if bad:
        raise RequestError('refused non-finite number(s): ' + ', '.join(bad))


@dataclass
class Turtle:
    name: str
    x: float
    y: float
    theta: float
    pen: Pen = field(default_factory=Pen)
    linear_x: float = 0.0
    linear_y: float = 0.0
    angular: float = 0.0
    last_command_time: float = -math.inf
    # ('absolute', x, y, theta) or ('relative', linear, angular), applied in order
    pending_teleports: List[tuple] = field(default_factory=list)

    def command(self, linear_x: float, linear_y: float, angular: float, now: float) -> None:
        require_finite(linear_x=linear_x, linear_y=linear_y, angular=angular)
        self.linear_x, self.linear_y, self.angular = linear_x, linear_y, angular
        self.last_command_time = now

    def teleport_absolute(self, x: float, y: float, theta: float) -> None:
        require_finite(x=x, y=y, theta=theta)
        self.pending_teleports.append(('absolute', x, y, theta))

    def teleport_relative(self, linear: float, angular: float) -> None:
        require_finite(linear=linear, angular=angular)
        self.pending_teleports.append(('relative', linear, angular))

    def set_pen(self, r: int, g: int, b: int, width: int, off: int) -> None:
        if off:
            self.pen.down = False
            return
        # a new pen, as turtle.cpp makes one: width 0 is Qt's default, 1 px
        self.pen = Pen(r, g, b, width if width else 1, True)

    @property
    def linear_speed(self) -> float:
        return math.hypot(self.linear_x, self.linear_y)

    def step(self, now: float, dt: float = TICK_SECONDS
             ) -> Tuple[List[Segment], Optional[Tuple[float, float]]]:
        """Advance one tick: its teleports, then its move.

        Returns the lines the pen drew and, if the turtle hit a wall, the
        position it was clamped from (else None).
        """
        teleported = self.teleport()
        moved, hit_wall = self.move(now, dt)
        return teleported + moved, hit_wall

    def teleport(self) -> List[Segment]:
        """A tick's first part: the teleports asked for, in order; their lines."""
        drawn: List[Segment] = []
        for request in self.pending_teleports:
            old = (self.x, self.y)
            if request[0] == 'absolute':
                _, self.x, y, self.theta = request
                # The real node keeps y in screen coordinates (height - y),
                # clamped at >= 0: a y above the top is pulled down here, at
                # once; one below 0 hits the wall in the step below.
                self.y = min(y, WORLD_SIZE)
            else:
                _, linear, angular = request
                self.theta += angular
                self.x += math.cos(self.theta) * linear
                self.y += math.sin(self.theta) * linear
            self._draw_from(old, drawn)
        self.pending_teleports = []
        return drawn

    def move(self, now: float, dt: float = TICK_SECONDS
             ) -> Tuple[List[Segment], Optional[Tuple[float, float]]]:
        """A tick's second part: the move commanded; its line, and where it
        hit a wall from (or None). turtlesim reads the colour sensor between
        the two parts, so it senses a teleport's line but not this one."""
        drawn: List[Segment] = []
        if now - self.last_command_time > COMMAND_TIMEOUT:
            self.linear_x = self.linear_y = self.angular = 0.0

        old = (self.x, self.y)
        self.theta = wrap_angle(self.theta + self.angular * dt)
        cos_t, sin_t = math.cos(self.theta), math.sin(self.theta)
        self.x += (cos_t * self.linear_x - sin_t * self.linear_y) * dt
        self.y += (sin_t * self.linear_x + cos_t * self.linear_y) * dt

        hit_wall = None
        if not (0.0 <= self.x <= WORLD_SIZE and 0.0 <= self.y <= WORLD_SIZE):
            hit_wall = (self.x, self.y)
            self.x = min(max(self.x, 0.0), WORLD_SIZE)
            self.y = min(max(self.y, 0.0), WORLD_SIZE)
        self._draw_from(old, drawn)
        return drawn, hit_wall

    def _draw_from(self, old: Tuple[float, float], drawn: List[Segment]) -> None:
        if self.pen.down and old != (self.x, self.y):
            drawn.append(Segment(old[0], old[1], self.x, self.y, self.pen.colour, self.pen.width))


class World:
    """The set of turtles, with the real node's naming rules."""

    def __init__(self, max_turtles: int = 0) -> None:
        self.turtles: Dict[str, Turtle] = {}
        self._name_counter = 0
        self.max_turtles = max_turtles      # 0: as many as are spawned (the real node's way)

    def spawn(self, x: float, y: float, theta: float, name: str = '') -> Turtle:
        require_finite(x=x, y=y, theta=theta)
        if self.max_turtles and len(self.turtles) >= self.max_turtles:
            raise RequestError(f'this simulator holds at most {self.max_turtles} turtles '
                               f'(its ~max_turtles)')
        if not name:
            name = self.free_name()
        elif not _NAME_PATTERN.match(name):
            raise RequestError(
                f'invalid turtle name [{name}]: use a letter, / or ~, then letters, digits, _ or /')
        elif name in self.turtles:
            raise RequestError(f'a turtle named [{name}] already exists')
        turtle = Turtle(name, x, y, theta)
        self.turtles[name] = turtle
        return turtle

    def kill(self, name: str) -> None:
        if name not in self.turtles:
            raise RequestError(f'no turtle named [{name}]')
        del self.turtles[name]

    def free_name(self) -> str:
        # Like the real node: a counter that only goes up until reset.
        while True:
            self._name_counter += 1
            name = f'turtle{self._name_counter}'
            if name not in self.turtles:
                return name

    def reset(self) -> Turtle:
        self.turtles.clear()
        self._name_counter = 0
        return self.spawn(CENTRE, CENTRE, 0.0)

    def get(self, name: str) -> Optional[Turtle]:
        return self.turtles.get(name)


def to_pixels(x: float, y: float) -> Tuple[float, float]:
    """World meters to canvas pixels (pixel y grows downwards)."""
    return x * PIXELS_PER_METER, (CANVAS_PIXELS - 1) - y * PIXELS_PER_METER
