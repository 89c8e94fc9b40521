"""The controller's parameters: defaults, and one clear refusal per bad value."""
import pytest

from turtle_letters.settings import ParameterError, Settings, quote_unreadable, student_name_problem


def settings(**given):
    return Settings(lambda name, default: given.get(name.lstrip('~'), default))


def test_defaults_are_the_labs():
    s = settings()
    assert (s.trigger, s.letter, s.size, s.mode) == ('P', 'N', 3.0, 'timed')
    assert (s.linear_speed, s.angular_speed, s.turn_direction) == (1.0, 0.25, 'ccw')
    assert (s.typing, s.text, s.clock) == (False, '', 'sim')


@pytest.mark.parametrize('name, value, allowed', [
    ('letter', '%', 'one of 0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ'),
    ('letter', 'NN', 'one of'),
    ('size', 0, 'a number > 0'),
    ('size', -1.5, 'a number > 0'),
    ('size', 50.0, 'up to 8.41'),
    ('size', 'big', 'a number > 0'),
    ('mode', 'fast', 'timed, feedback'),
    ('linear_speed', 0.0, 'a number > 0'),
    ('angular_speed', -0.25, 'a number > 0'),
    ('angular_speed', float('nan'), 'a number > 0'),
    ('turn_direction', 'cw', 'ccw, shortest'),
    ('typing', 'yes', 'true or false'),
    ('trigger', '  ', 'non-blank'),
    ('text', 'A&B', "A-Z, 0-9 and space (no glyph for ['&'])"),
    ('clock', 'cpu', 'sim, wall'),
])
def test_a_bad_value_is_refused_naming_it_and_what_is_allowed(name, value, allowed):
    with pytest.raises(ParameterError) as refused:
        settings(**{name: value})
    message = str(refused.value)
    assert message.startswith(f'~{name} ')
    assert allowed in message
    assert repr(value) in message


def test_the_pen_defaults_to_turtlesims_and_takes_a_string_or_a_list():
    assert settings().pen == (179, 184, 255, 3)
    assert settings(pen='255 0 0 5').pen == (255, 0, 0, 5)
    assert settings(pen=[0, 128, 0, 1]).pen == (0, 128, 0, 1)


@pytest.mark.parametrize('value', ['255 0 0', '256 0 0 3', '0 0 0 0', 'red', [1, 2, 3, 4.5],
                                   [1, 2, 3, True], '-1 0 0 3', 7])
def test_a_bad_pen_is_refused(value):
    with pytest.raises(ParameterError) as refused:
        settings(pen=value)
    assert str(refused.value).startswith(f'~pen is {value!r}; allowed: "r g b width"')


def test_command_line_values_ros_cannot_store_become_strings():
    argv = ['node', '_letter:=?', '_size:=~', '_text:=IT\'S', '_mode:=timed', '_size:=2.5',
            '_when:=2024-01-01', '_n:=99999999999', 'chatter:=other', '__name:=x']
    assert quote_unreadable(argv) == [
        'node', "_letter:='?'", "_size:='~'", '_text:=IT\'S', '_mode:=timed', '_size:=2.5',
        "_when:='2024-01-01'", "_n:='99999999999'", 'chatter:=other', '__name:=x']


def test_a_quoted_value_reads_back_as_what_was_typed():
    import yaml
    for typed in ['?', "it's", '{a', '[1,', '~', ': x']:
        argument = quote_unreadable([f'_text:={typed}'])[0]
        assert yaml.safe_load(argument.partition(':=')[2]) == typed


@pytest.mark.parametrize('name', ['turtle1', '/alice', 'class/bob_2'])
def test_a_turtle_is_a_ros_name(name):
    assert settings(turtle=name).turtle == name


@pytest.mark.parametrize('name', ['', '1st', 'al ice', 'alice/', '/', 'a-b', 7])
def test_a_turtle_name_turtlesim_could_not_take_is_refused(name):
    with pytest.raises(ParameterError, match='~turtle '):
        settings(turtle=name)


def test_a_place_is_both_coordinates_or_neither():
    assert (settings().x, settings().y) == (None, None)
    assert (settings(x=2, y=3.5).x, settings(x=2, y=3.5).y) == (2.0, 3.5)
    with pytest.raises(ParameterError, match='both'):
        settings(x=2.0)
    with pytest.raises(ParameterError, match='~y '):
        settings(x=2.0, y=11.0)


def test_a_digit_given_as_a_number_is_that_digit():
    assert settings(letter=7).letter == '7'


@pytest.mark.parametrize('name, read_as, wanted', [
    ('alice', 'str', None),
    ('Bob_2', 'str', None),
    ('true', 'bool', 'roslaunch reads it as a boolean'),
    ('7', 'int', 'roslaunch reads it as a number'),
    ('élodie', 'str', 'no / or accents'),
    ('lab/alice', 'str', 'no / or accents'),
    ('2pac', 'str', 'starting with a letter'),
    ('', 'str', 'starting with a letter'),
])
def test_student_names_are_one_ros_base_name(name, read_as, wanted):
    problem = student_name_problem(name, read_as)
    if wanted is None:
        assert problem is None
    else:
        assert wanted in problem


@pytest.mark.parametrize('name', ['alice', 'turtle1', 'Bob_2', 'x'])
def test_no_student_and_no_turtle_can_be_named_as_a_spare_turtle(name):
    from turtle_letters.classroom.names import spare_name
    for number in (2, 3, 12):
        assert 'no __' in student_name_problem(spare_name(name, number))
        with pytest.raises(ParameterError, match='no __'):
            settings(turtle=spare_name(name, number))
