"""The talker's reading of its input, on a real pipe: every character a
press, escape sequences dropped, a line without end read as it comes."""
import os
import select
import threading

from turtle_letters.keys import READY, SHUTDOWN, TIMED_OUT, pass_keys


class Presses:
    def __init__(self):
        self.keys = []

    def press(self, key):
        self.keys.append(key)


def wait(fd, timeout):
    readable, _, _ = select.select([fd], [], [], 5.0 if timeout is None else timeout)
    return READY if readable else (SHUTDOWN if timeout is None else TIMED_OUT)


def read_all(data):
    read_end, write_end = os.pipe()
    os.write(write_end, data)
    os.close(write_end)
    presses = Presses()
    pass_keys(presses, read_end, wait)
    os.close(read_end)
    return presses.keys


def test_every_character_is_a_press_and_newline_is_enter():
    assert read_all(b'xP\n') == ['x', 'P', '\n']


def test_escape_sequences_are_dropped():
    assert read_all(b'\x1b[A\x1bOPp\x1b[15~q') == ['p', 'q']


def test_a_long_line_without_end_is_read_as_it_comes():
    """Far more than a pipe holds, with no newline: the writer could never
    finish if the reader held out for a line's end."""
    read_end, write_end = os.pipe()
    data = b'x' * 1_000_000 + b'P'
    writer = threading.Thread(target=lambda: (os.write(write_end, data), os.close(write_end)))
    writer.start()
    presses = Presses()
    pass_keys(presses, read_end, wait)
    writer.join(10)
    os.close(read_end)
    assert len(presses.keys) == len(data) and presses.keys[-1] == 'P'
