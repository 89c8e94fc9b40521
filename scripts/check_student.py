#!/usr/bin/python3
"""student.launch's check of name:=, before any node starts:
turtle_letters.classroom.liveness.check_student_launch."""
import sys

from turtle_letters.classroom.liveness import check_student_launch

if __name__ == '__main__':
    sys.exit(check_student_launch(sys.argv[1:]))
