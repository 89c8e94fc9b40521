"""The controller's parameters: defaults, and one clear refusal per bad value."""
import pytest

from turtle_letters.settings import ParameterError, Settings


def settings(**given):
    return Settings(lambda name, default: given.get(name.lstrip('~'), default))


def test_defaults_are_the_labs():
    s = settings()
    assert (s.trigger, s.letter, s.size, s.mode) == ('P', 'N', 3.0, 'timed')
    assert (s.linear_speed, s.angular_speed, s.turn_direction) == (1.0, 0.25, 'ccw')
    assert (s.typing, s.text) == (False, '')


@pytest.mark.parametrize('name, value, allowed', [
    ('letter', '%', 'one of 0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ'),
    ('letter', 'NN', 'one of'),
    ('size', 0, 'a number > 0'),
    ('size', -1.5, 'a number > 0'),
    ('size', 50.0, 'up to 8.41 m'),
    ('size', 'big', 'a number > 0'),
    ('mode', 'fast', 'timed, feedback'),
    ('linear_speed', 0.0, 'a number > 0'),
    ('angular_speed', -0.25, 'a number > 0'),
    ('angular_speed', float('nan'), 'a number > 0'),
    ('turn_direction', 'cw', 'ccw, shortest'),
    ('typing', 'yes', 'true or false'),
    ('trigger', '  ', 'non-blank'),
    ('text', 'A&B', 'A-Z, 0-9, space'),
])
def test_a_bad_value_is_refused_naming_it_and_what_is_allowed(name, value, allowed):
    with pytest.raises(ParameterError) as refused:
        settings(**{name: value})
    message = str(refused.value)
    assert message.startswith(f'~{name} ')
    assert allowed in message
    if name != 'text':
        assert repr(value) in message or f'{value:g}' in message
