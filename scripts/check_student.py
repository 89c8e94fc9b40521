#!/usr/bin/python3
"""Launch-time check of student.launch's name:=, before any node starts.

student.launch runs this as a `<param command=...>`, like check_settings.py:
a bad name, or a name whose controller is alive already (a second launch
would make the master shut the first one down), prints one line and exits
non-zero, so roslaunch stops before starting anything.

Usage: check_student.py HEX: the Python repr of the value roslaunch read
(roslaunch reads name:=true as True), in hexadecimal (no quote or space can
break the command).
"""
import ast
import sys

from turtle_letters.classroom.liveness import running
from turtle_letters.settings import student_name_problem


def main(argv):
    value = ast.literal_eval(bytes.fromhex(argv[0]).decode('utf-8'))
    raw = str(value).lower() if isinstance(value, bool) else str(value)
    problem = student_name_problem(raw, type(value).__name__)
    if problem:
        print(f'[FATAL] student.launch: name:={raw}: {problem}', file=sys.stderr)
        return 2
    controller = f'/{raw}/turtlebot_controller'
    live = running(controller)
    if live:
        print(f'[FATAL] student.launch: name:={raw} is in use: {controller} is running (pid '
              f'{live[1]} at {live[0]}); stop it first, or choose another name', file=sys.stderr)
        return 2
    print(raw)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
