#!/usr/bin/python3
"""Launch-time check of the controller's parameters.

draw_letter.launch runs this as a `<param command=...>`: if a value is bad it
prints one line saying which, and exits non-zero, so roslaunch stops before
starting anything and itself exits non-zero (a node that refuses its
parameters cannot make roslaunch fail). On success it prints the settings.
Usage: check_settings.py name:=value [...]; values typed `str` in the launch
file are marked name:=str:value.
"""
import sys

from roslaunch.loader import convert_value

from turtle_letters.settings import ParameterError, Settings


def main(argv):
    values = {}
    for argument in argv:
        name, _, value = argument.partition(':=')
        if value.startswith('str:'):
            values['~' + name] = value[len('str:'):]
        else:
            values['~' + name] = convert_value(value, 'auto')
    try:
        settings = Settings(lambda name, default: values.get(name, default))
    except ParameterError as e:
        print(f'[FATAL] turtlebot_controller: {e}', file=sys.stderr)
        return 2
    print(f'letter={settings.letter} size={settings.size:g} mode={settings.mode}')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
