"""The controller's parameters: one table (PARAMETERS), read and checked in
one place. No ROS here: the node passes rospy.get_param in, and the launch
file's check passes the launch arguments, so a bad value is refused before
anything starts."""
import ast
import math
import os
import re
import sys
from typing import Callable, NamedTuple

import yaml

from .letters.font import BUILTIN
from .letters.geometry import TURN_DIRECTIONS
from .letters.hershey import FontError, load_font
from .letters.layout import MARGIN, WORLD_SIZE, largest_size
from .letters.svgart import allowed
from .motion.executors import CLOCKS
from .motion.modes import MODES




class ParameterError(ValueError):
    pass


# -- what a value may be: each check gets the value and the font chosen
# (the builtin one until ~font is read), and returns the value to use or raises
def _string(value, font=None):
    if not isinstance(value, str):
        raise ValueError('a string')
    return value


def _trigger(value, font=None):
    if not isinstance(value, str) or not value.strip():
        raise ValueError('a non-blank string')
    return value


def _font(value, font=None):
    try:
        return load_font(_string(value))
    except FontError as e:
        raise ValueError(str(e)) from None


def _characters(font):
    return 'A-Z, 0-9' if font is BUILTIN else f'a character of {font.name}'


def _letter(value, font):
    if isinstance(value, int) and not isinstance(value, bool) and 0 <= value <= 9:
        value = str(value)          # _letter:=7 on a command line comes as a number
    letter = _string(value) if font.case_sensitive else _string(value).upper()
    if len(letter) != 1 or font.glyph(letter) is None:
        raise ValueError(f'one of {"".join(sorted(font.glyphs))}')
    return letter


def _text(value, font):
    text = _string(value) if font.case_sensitive else _string(value).upper()
    if font.undrawable(text):
        raise ValueError(f'{_characters(font)} and space (no glyph for {font.undrawable(text)})')
    return text


# A turtle's name becomes part of its topic names, so turtlesim itself would
# fail on one that is not a valid ROS name.
# No two _ in a row: that marks a parallel word's spare turtles (classroom/names.py).
TURTLE_NAME = re.compile(r'(?!.*__)/?([A-Za-z][A-Za-z0-9_]*/)*[A-Za-z][A-Za-z0-9_]*')


def _turtle(value, font=None):
    if not isinstance(value, str) or not TURTLE_NAME.fullmatch(value):
        raise ValueError('a ROS name such as turtle1 or /alice: letters, digits and _, '
                         'starting with a letter, with no __ (a parallel word\'s spare turtles '
                         'are NAME__2, NAME__3...)')
    return value


STUDENT_NAME = re.compile(r'(?!.*__)[A-Za-z][A-Za-z0-9_]*')


def student_name_problem(name, read_as='str'):
    """What is wrong with student.launch's name:= (None when nothing is):
    it names the turtle and the namespace, so it is one ROS base name, and
    turtlesim's spawn lives at the root beside it. `read_as`: the type
    roslaunch gave the value."""
    if read_as != 'str':
        kind = {'bool': 'a boolean', 'int': 'a number', 'float': 'a number'}.get(read_as, read_as)
        return (f'roslaunch reads it as {kind}, not a name; '
                'give a name that starts with a letter')
    if not STUDENT_NAME.fullmatch(name):
        return ('a name is letters (a-z, A-Z), digits and _, starting with a letter, '
                'with no / or accents (the turtle and the namespace are named after it) and '
                'no __ (a parallel word\'s spare turtles are NAME__2, NAME__3...)')
    return None


def _svg(value, font=None):
    """'' or an SVG file that exists, by an absolute path: roslaunch starts a
    node in ROS_HOME, so a relative path would be looked for there."""
    if value == '':
        return ''
    if not isinstance(value, str) or not os.path.isabs(value):
        raise ValueError('"" or the absolute path of an SVG file (nodes do not run where '
                         'roslaunch was started: give $PWD/FILE)')
    if not os.path.isfile(value):
        raise ValueError('"" or the path of an SVG file that exists')
    return value


# The package's own pictures (in the source or devel space; an install has none).
PACKAGE_DOC = os.path.realpath(os.path.join(os.path.dirname(os.path.realpath(__file__)), '..', '..',
                                            'doc'))


def _folders(value, font=None):
    """'' (the package's doc/ and the folder roslaunch was started in: nodes
    inherit its PWD), or folders separated by ':'; as real paths."""
    if value == '':
        return tuple(os.path.realpath(f) for f in (PACKAGE_DOC, os.environ.get('PWD', ''))
                     if f and os.path.isdir(f))
    folders = value.split(':') if isinstance(value, str) else []
    if not folders or not all(os.path.isabs(f) and os.path.isdir(f) for f in folders):
        raise ValueError('"" or absolute paths of folders that exist, separated by ":"')
    return tuple(os.path.realpath(f) for f in folders)


def _place(value, font=None):
    if value == '':
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)) \
            or not MARGIN <= value <= WORLD_SIZE - MARGIN:
        raise ValueError(f'"" (a free place) or a number from {MARGIN:g} to '
                         f'{WORLD_SIZE - MARGIN:.2f}')
    return float(value)


def positive(value, font=None):
    if isinstance(value, bool) or not isinstance(value, (int, float)) \
            or not math.isfinite(value) or value <= 0:
        raise ValueError('a number > 0')
    return float(value)


def writable_folder(value, font=None):
    """A folder this node can create, or write in: its path, made absolute."""
    if not isinstance(value, str) or not value.strip():
        raise ValueError('the path of a folder')
    folder = existing = os.path.abspath(os.path.expanduser(value))
    while not os.path.exists(existing):
        existing = os.path.dirname(existing)
    if not os.path.isdir(existing) or not os.access(existing, os.W_OK | os.X_OK):
        raise ValueError('a folder this node can create or write in')
    return folder


def _size(value, font):
    size = positive(value)
    if size > largest_size(font):
        raise ValueError(f'up to {largest_size(font):.2f}, the largest letter that fits the canvas')
    return size


def boolean(value, font=None):
    if not isinstance(value, bool):
        raise ValueError('true or false')
    return value


def _one_of(*allowed):
    def check(value, font=None):
        if value not in allowed:
            raise ValueError(', '.join(allowed))
        return value
    return check


def _pen(value, font=None):
    parts = value.split() if isinstance(value, str) else value
    numbers = [_integer(p) for p in parts] if isinstance(parts, list) else []
    if len(numbers) == 4 and None not in numbers:
        *colour, width = numbers
        if all(0 <= c <= 255 for c in colour) and 1 <= width <= 255:
            return tuple(numbers)
    raise ValueError('"r g b width", r g b integers 0-255 and width 1-255')


class Parameter(NamedTuple):
    name: str
    type: str           # str, float or bool; only str is given as type="str" in the launch file
    default: str        # as the launch argument's default
    unit: str
    meaning: str
    check: Callable[[object, object], object]


# The controller's private parameters: the one table. The launch file has an
# argument for each (same name and default), the README a row for each, and
# test/unit/test_parameter_table.py fails when they disagree.
PARAMETERS = (
    Parameter('trigger', 'str', 'P', '', 'the chatter message that starts a drawing', _trigger),
    Parameter('font', 'str', 'builtin', '',
              'builtin (A-Z, 0-9; the lab\'s N) or a Hershey font of hershey-fonts-data', _font),
    Parameter('letter', 'str', 'N', '', 'what a trigger draws: A-Z or 0-9', _letter),
    Parameter('size', 'float', '3.0', 'm', "letter height (the lab's N: 3.0)", _size),
    Parameter('mode', 'str', 'timed', '',
              "timed (the lab's open-loop primitives), feedback (closed loop on the pose) or "
              "smooth (closed loop, each stroke traced without stopping)", _one_of(*MODES)),
    Parameter('clock', 'str', 'sim', '',
              "timed mode's clock: sim (the simulator's ticks: exact) or wall (the lab's "
              "rospy.Time.now(): short when the machine is busy)", _one_of(*CLOCKS)),
    Parameter('linear_speed', 'float', '1.0', 'm/s', 'driving speed (feedback: the cap)',
              positive),
    Parameter('angular_speed', 'float', '0.25', 'rad/s', 'turning speed (feedback: the cap)',
              positive),
    Parameter('turn_direction', 'str', 'ccw', '',
              "ccw: always counter-clockwise, as the lab; shortest: the shorter way",
              _one_of(*TURN_DIRECTIONS)),
    Parameter('typing', 'bool', 'false', '', 'draw every letter or digit heard on chatter',
              boolean),
    Parameter('text', 'str', '', '', 'a word drawn once, as soon as the pose is known', _text),
    Parameter('pen', 'str', '179 184 255 3', 'px',
              "ink: r g b (0-255) and width; turtlesim's own pen by default", _pen),
    Parameter('turtle', 'str', 'turtle1', '',
              'the turtle to drive (spawned if it does not exist); /NAME for one outside '
              "the controller's namespace", _turtle),
    Parameter('x', 'float', '', 'm', 'where a spawned turtle starts; "": a free place', _place),
    Parameter('y', 'float', '', 'm', 'where a spawned turtle starts; "": a free place', _place),
    Parameter('parallel', 'bool', 'false', '',
              'a word is drawn by one turtle per character, all at once', boolean),
    Parameter('svg_dirs', 'str', '', '',
              'the folders whose SVG files may be drawn, separated by ":"; "": the '
              "package's doc/ and the folder roslaunch was started in", _folders),
    Parameter('svg', 'str', '', '', 'an SVG file whose line art is drawn once at start', _svg),
)

TABLE = {p.name: p for p in PARAMETERS}


def launch_value(text, type_):
    """A launch argument's text as the controller's <param> gets it: verbatim
    for a str parameter (type="str"), else read as roslaunch reads an untyped
    value (a number if it is one, true/false as booleans, else the text)."""
    if type_ == 'str':
        return text
    try:
        return float(text) if '.' in text else int(text)
    except ValueError:
        pass
    if text.lower() in ('true', 'false'):
        return text.lower() == 'true'
    return text


def read_parameter(name, get, font=BUILTIN, table=None):
    """One parameter of `table` (by default the controller's), read with
    `get(name, default)` and checked (against `font`, for the characters and
    sizes it has); a bad value raises ParameterError saying what was given
    and what is allowed."""
    p = (table or TABLE)[name]
    value = get('~' + name, launch_value(p.default, p.type))
    try:
        return p.check(value, font)
    except ValueError as e:
        unit = f' ({p.unit})' if p.unit else ''
        raise ParameterError(f'~{name} is {value!r}; allowed: {e}{unit}') from None


class Settings:
    """The controller's private parameters, one attribute each: see PARAMETERS."""

    def __init__(self, get):
        """`get(name, default)` reads one parameter (rospy.get_param in the node)."""
        self.font = BUILTIN
        for p in PARAMETERS:      # ~font comes before what depends on it
            setattr(self, p.name, read_parameter(p.name, get, self.font))
        if (self.x is None) != (self.y is None):
            raise ParameterError(f'~x is {self.x!r} and ~y is {self.y!r}; '
                                 'allowed: both numbers, or both "" for a free place')
        if self.svg and not allowed(self.svg, self.svg_dirs):
            raise ParameterError(f'~svg is {self.svg!r}; allowed: a file under the folders of '
                                 f'~svg_dirs, {":".join(self.svg_dirs)}')
        if self.text and self.svg:
            raise ParameterError(f'~text is {self.text!r} and ~svg is {self.svg!r}; '
                                 'allowed: one of them, or neither')


def check_launch(argv):
    """draw_letter.launch's check, run as a `<param command=...>` before any
    node starts: a bad value prints one line saying which, and a non-zero
    exit makes roslaunch stop and itself exit non-zero (a node that refuses
    its parameters cannot). `argv`: name=HEX for each launch argument, its
    value as roslaunch reads it (7 for 007, True for true) as a Python repr
    in hexadecimal, so that no quote or space can break the command line."""
    values = {}
    for argument in argv:
        name, _, encoded = argument.partition('=')
        values['~' + name] = _as_given(bytes.fromhex(encoded).decode('utf-8'), TABLE[name].type)
    try:
        settings = Settings(lambda name, default: values.get(name, default))
    except ParameterError as e:
        print(f'[FATAL] turtlebot_controller: {e}', file=sys.stderr)
        return 2
    print(f'letter={settings.letter} size={settings.size:g} mode={settings.mode}')
    return 0


def _as_given(text, type_):
    """The value of one argument as the controller's <param> gets it."""
    try:
        value = ast.literal_eval(text)
    except (ValueError, SyntaxError):
        value = float(text)         # inf and nan have no literal
    if type_ == 'str' and not isinstance(value, str):   # a <param type="str">
        return str(value).lower() if isinstance(value, bool) else str(value)
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
