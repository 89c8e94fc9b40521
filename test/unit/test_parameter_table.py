"""One parameter table: the launch file and the README follow it. Adding a
parameter means editing the table, the launch file and the README; this test
says what is missing where."""
import os
import re
import xml.etree.ElementTree as ET

import pytest

from turtle_letters.settings import PARAMETERS, Settings, launch_value


ROOT = os.path.join(os.path.dirname(__file__), '..', '..')
LAUNCH = ET.parse(os.path.join(ROOT, 'launch', 'draw_letter.launch')).getroot()
CONTROLLER = LAUNCH.find("node[@type='turtle_controller.py']")
ARGS = {a.get('name'): a for a in LAUNCH.findall('arg')}
PARAMS = {p.get('name'): p for p in CONTROLLER.findall('param')}
CHECK = PARAMS['checked_settings'].get('command')
with open(os.path.join(ROOT, 'doc', 'reference.md')) as f:
    README = f.read()


def readme_rows(first_column):
    """Table rows of the README whose first cell matches, as {name: cells}."""
    rows = {}
    for line in README.splitlines():
        cells = [c.strip() for c in line.strip().strip('|').split('|')]
        match = re.fullmatch(first_column, cells[0]) if line.startswith('|') else None
        if match:
            rows[match.group(1)] = [c.strip('`') for c in cells[1:]]
    return rows


LAUNCH_ROWS = readme_rows(r'`([a-z_]+)`')
PARAMETER_ROWS = readme_rows(r'`~([a-z_]+)`')


def test_the_defaults_are_valid():
    Settings(lambda name, default: default)


@pytest.mark.parametrize('p', PARAMETERS, ids=lambda p: p.name)
def test_the_launch_file_has_an_argument_and_a_checked_parameter(p):
    assert ARGS[p.name].get('default') == p.default
    assert p.name in ARGS['parameters'].get('value').split()
    param = PARAMS[p.name]
    assert param.get('value') == f'$(arg {p.name})'
    assert param.get('type') == ('str' if p.type == 'str' else None)


def test_the_check_is_given_every_parameter_and_nothing_else():
    assert "map(arg, arg('parameters').split())" in CHECK
    assert sorted(ARGS['parameters'].get('value').split()) == sorted(p.name for p in PARAMETERS)


def test_the_controller_has_no_parameter_outside_the_table():
    assert set(PARAMS) - {'checked_settings'} == {p.name for p in PARAMETERS}


@pytest.mark.parametrize('p', PARAMETERS, ids=lambda p: p.name)
def test_the_readme_lists_it_with_its_type_and_default(p):
    shown_default = p.default if p.default else '""'
    assert PARAMETER_ROWS[p.name][:2] == [p.type, shown_default]
    assert LAUNCH_ROWS[p.name][0] == shown_default


def test_the_readme_lists_no_parameter_outside_the_table():
    assert set(PARAMETER_ROWS) == {p.name for p in PARAMETERS}


def test_launch_values_are_read_as_roslaunch_reads_them():
    assert launch_value('3', 'float') == 3
    assert launch_value('2.5', 'float') == 2.5
    assert launch_value('True', 'bool') is True
    assert launch_value('007', 'str') == '007'
    assert launch_value('big', 'float') == 'big'


STUDENT = ET.parse(os.path.join(ROOT, 'launch', 'student.launch')).getroot()
# A classroom's own defaults: the student's initial, small enough for a room.
STUDENT_DEFAULTS = {'letter': "$(eval str(arg('name'))[:1].upper())", 'size': '1.0'}


def test_student_launch_passes_every_argument_on_and_sets_two_defaults_of_its_own():
    include = STUDENT.find('include')
    assert include.get('pass_all_args') == 'true'
    assert {a.get('name'): a.get('value') for a in include.findall('arg')} == {
        'simulator': 'false', 'turtle': '/$(arg name)'}
    declared = {a.get('name'): a.get('default') for a in STUDENT.findall('arg')}
    assert declared == dict(STUDENT_DEFAULTS, name=None)
