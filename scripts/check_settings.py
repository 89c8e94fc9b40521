#!/usr/bin/python3
"""Launch-time check of the controller's parameters.

draw_letter.launch runs this as a `<param command=...>`: if a value is bad it
prints one line saying which, and exits non-zero, so roslaunch stops before
starting anything and itself exits non-zero (a node that refuses its
parameters cannot make roslaunch fail). On success it prints the settings.

Usage: check_settings.py name=HEX [...]: each launch argument as given, after
the "str:" the launch file puts before it, in hexadecimal, so that no quote
or space can break the command line. The parameter table says how each value
is read.
"""
import sys

from turtle_letters.settings import PARAMETERS, ParameterError, Settings, launch_value

TYPES = {p.name: p.type for p in PARAMETERS}


def main(argv):
    values = {}
    for argument in argv:
        name, _, encoded = argument.partition('=')
        raw = bytes.fromhex(encoded).decode('utf-8')
        raw = raw[len('str:'):] if raw.startswith('str:') else raw
        values['~' + name] = launch_value(raw, TYPES[name])
    try:
        settings = Settings(lambda name, default: values.get(name, default))
    except ParameterError as e:
        print(f'[FATAL] turtlebot_controller: {e}', file=sys.stderr)
        return 2
    print(f'letter={settings.letter} size={settings.size:g} mode={settings.mode}')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
