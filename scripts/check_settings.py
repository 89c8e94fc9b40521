#!/usr/bin/python3
"""Launch-time check of the controller's parameters.

draw_letter.launch runs this as a `<param command=...>`: if a value is bad it
prints one line saying which, and exits non-zero, so roslaunch stops before
starting anything and itself exits non-zero (a node that refuses its
parameters cannot make roslaunch fail). On success it prints the settings.

Usage: check_settings.py name=HEX [...]: each launch argument's value as
roslaunch reads it (7 for 007, True for true), its Python repr in
hexadecimal, so that no quote or space can break the command line.
"""
import ast
import sys

from turtle_letters.settings import PARAMETERS, ParameterError, Settings

TYPES = {p.name: p.type for p in PARAMETERS}


def as_given(text, type_):
    """The value of one argument as the controller's <param> gets it."""
    try:
        value = ast.literal_eval(text)
    except (ValueError, SyntaxError):
        value = float(text)         # inf and nan have no literal
    if type_ == 'str' and not isinstance(value, str):   # a <param type="str">
        return str(value).lower() if isinstance(value, bool) else str(value)
    return value


def main(argv):
    values = {}
    for argument in argv:
        name, _, encoded = argument.partition('=')
        values['~' + name] = as_given(bytes.fromhex(encoded).decode('utf-8'), TYPES[name])
    try:
        settings = Settings(lambda name, default: values.get(name, default))
    except ParameterError as e:
        print(f'[FATAL] turtlebot_controller: {e}', file=sys.stderr)
        return 2
    print(f'letter={settings.letter} size={settings.size:g} mode={settings.mode}')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
