"""The controller's parameters, read and checked in one place. No ROS here:
the node passes rospy.get_param in, and the launch file's check passes the
launch arguments, so a bad value is refused before anything starts."""
import math

import yaml

from .font import FONT
from .motion import EXECUTORS
from .plan import LARGEST_SIZE, TURN_DIRECTIONS, glyph_for, undrawable


DEFAULT_PEN = (179, 184, 255, 3)    # turtlesim's own: r, g, b, width in pixels


class ParameterError(ValueError):
    pass


class Settings:
    """The controller's private parameters.

    ~trigger (str, default "P"): the /chatter message that starts a drawing.
    ~letter (str, default "N"): the character drawn on a trigger (A-Z, 0-9).
    ~size (float, default 3.0, m): letter height; the lab's N is 3.0 m.
    ~mode (str, default "timed"): "timed" (the lab's open-loop primitives,
        timed on the simulator's clock) or "feedback" (closed loop on the pose).
    ~linear_speed (float, default 1.0, m/s), ~angular_speed (float, default
        0.25, rad/s): the lab's speeds; in feedback mode, the caps.
    ~turn_direction (str, default "ccw"): "ccw" turns counter-clockwise only,
        as the lab does; "shortest" turns whichever way is shorter.
    ~typing (bool, default false): draw every letter or digit heard on
        /chatter, like a typewriter, instead of ~letter on ~trigger.
    ~text (str, default ""): if set, drawn once as soon as the turtle's pose
        is known.
    ~pen (str "r g b width" or a list of 4 integers, default "179 184 255 3",
        turtlesim's own pen): colour 0-255 and width 1-255 px of the ink.
    """

    def __init__(self, get):
        """`get(name, default)` reads one parameter (rospy.get_param in the node)."""
        self.trigger = self._string(get, '~trigger', 'P')
        if not self.trigger.strip():
            raise ParameterError(f'~trigger is {self.trigger!r}; allowed: a non-blank string')
        self.letter = self._string(get, '~letter', 'N').upper()
        self.size = self._positive(get, '~size', 3.0, 'm')
        if self.size > LARGEST_SIZE:
            raise ParameterError(f'~size is {self.size:g}; allowed: up to {LARGEST_SIZE:.2f} m, '
                                 'the largest letter that fits the canvas')
        self.mode = self._choice(get, '~mode', 'timed', tuple(EXECUTORS))
        self.linear_speed = self._positive(get, '~linear_speed', 1.0, 'm/s')
        self.angular_speed = self._positive(get, '~angular_speed', 0.25, 'rad/s')
        self.turn_direction = self._choice(get, '~turn_direction', 'ccw', TURN_DIRECTIONS)
        self.typing = get('~typing', False)
        self.text = self._string(get, '~text', '').upper()
        if not isinstance(self.typing, bool):
            raise ParameterError(f'~typing is {self.typing!r}; allowed: true or false')
        if glyph_for(self.letter) is None or len(self.letter) != 1:
            raise ParameterError(
                f'~letter is {self.letter!r}; allowed: one of {"".join(sorted(FONT))}')
        self.pen = self._pen(get, '~pen', DEFAULT_PEN)
        bad = undrawable(self.text)
        if bad:
            raise ParameterError(f'~text has characters with no glyph {bad}; allowed: A-Z, 0-9, space')

    @staticmethod
    def _string(get, name, default):
        value = get(name, default)
        if not isinstance(value, str):
            raise ParameterError(f'{name} is {value!r}; allowed: a string')
        return value

    @staticmethod
    def _positive(get, name, default, unit):
        value = get(name, default)
        if isinstance(value, bool) or not isinstance(value, (int, float)) \
                or not math.isfinite(value) or value <= 0:
            raise ParameterError(f'{name} is {value!r}; allowed: a number > 0 ({unit})')
        return float(value)

    @staticmethod
    def _pen(get, name, default):
        value = get(name, ' '.join(map(str, default)))
        parts = value.split() if isinstance(value, str) else value
        numbers = [_integer(p) for p in parts] if isinstance(parts, list) else []
        if len(numbers) == 4 and None not in numbers:
            *colour, width = numbers
            if all(0 <= c <= 255 for c in colour) and 1 <= width <= 255:
                return tuple(numbers)
        raise ParameterError(f'{name} is {value!r}; allowed: "r g b width", '
                             'r g b integers 0-255 and width 1-255 (px)')

    @staticmethod
    def _choice(get, name, default, allowed):
        value = get(name, default)
        if value not in allowed:
            raise ParameterError(f'{name} is {value!r}; allowed: {", ".join(allowed)}')
        return value



def _integer(value):
    if isinstance(value, int) and not isinstance(value, bool):
        return value
    if isinstance(value, str) and value.strip().isdigit():
        return int(value)
    return None


def quote_unreadable(argv):
    """Command-line arguments with `_name:=value` values that ROS cannot
    store as a parameter made into strings.

    rospy reads such a value as YAML and hands it to the parameter server,
    which cannot take every YAML value: `_letter:=?` is a mapping {None: None}
    and stops init_node with a traceback. As a string it reaches the checks
    above, which name the parameter and what is allowed.
    """
    quoted = []
    for argument in argv:
        name, sep, value = argument.partition(':=')
        if name.startswith('_') and sep and not _storable_yaml(value):
            argument = f"{name}:='{value.replace(chr(39), chr(39) * 2)}'"
        quoted.append(argument)
    return quoted


def _storable_yaml(text):
    try:
        return _storable(yaml.safe_load(text))
    except yaml.YAMLError:
        return False


def _storable(value):
    """What the parameter server (XML-RPC) takes."""
    if isinstance(value, (str, bool, float)):
        return True
    if isinstance(value, int):
        return -2 ** 31 <= value < 2 ** 31
    if isinstance(value, list):
        return all(_storable(v) for v in value)
    if isinstance(value, dict):
        return all(isinstance(k, str) and _storable(v) for k, v in value.items())
    return False
