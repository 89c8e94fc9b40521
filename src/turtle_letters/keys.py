"""From key presses to what the talker publishes. No ROS here.

A terminal sends some keys as escape sequences: the arrows are ESC [ A..D,
F1 is ESC O P, Alt+p is ESC p. Read byte by byte they would look like
letters (F1 would send the trigger), so KeyDecoder drops every sequence, and
a bare Esc too, before a key is looked up.
"""
import codecs
import os
import string
from typing import List, Optional

TYPEABLE = set(string.ascii_letters + string.digits + ' ')
ENTER = '\n'
ESC = '\x1b'
# Seconds to wait for the rest of an escape sequence before taking a lone
# ESC as the Esc key: terminals send a sequence in one write.
ESCAPE_WAIT = 0.05
READ_SIZE = 4096    # bytes read at once; each read is handled before the next
READY, TIMED_OUT, SHUTDOWN = 'ready', 'timed out', 'shutdown'    # what a wait says


def bindings(trigger: str) -> dict:
    """The lab's key table: the trigger's own key (either case) publishes the
    trigger; a trigger longer than one character, which no key can type, is
    published by Enter."""
    if len(trigger) == 1:
        return {trigger.lower(): trigger, trigger.upper(): trigger}
    return {ENTER: trigger}


def message_for(key: str, typing: bool = False, trigger: str = 'P') -> Optional[str]:
    """The string to publish on chatter for `key`, or None to publish nothing.

    In typing mode every letter, digit and space is published (letters in
    upper case), so the controller draws what is typed.
    """
    if typing:
        return key.upper() if key in TYPEABLE else None
    return bindings(trigger).get(key)


class KeyDecoder:
    """Text read from a terminal, in chunks, to single keys, without the
    escape sequences. Feed it what each read returned; when it says a
    sequence is pending and nothing more comes within ESCAPE_WAIT, call
    timeout(): the ESC was the Esc key, which is no key we publish."""

    def __init__(self) -> None:
        self._utf8 = codecs.getincrementaldecoder('utf-8')(errors='replace')
        self._sequence = ''      # an escape sequence read so far

    @property
    def pending(self) -> bool:
        return bool(self._sequence)

    def feed(self, data: bytes) -> List[str]:
        keys = []
        for char in self._utf8.decode(data):
            if self._sequence == ESC and char == ESC:
                pass                    # a bare Esc, then another sequence
            elif self._sequence:
                self._sequence += char
                if _sequence_complete(self._sequence):
                    self._sequence = ''
            elif char == ESC:
                self._sequence = char
            else:
                keys.append(char)
        return keys

    def timeout(self) -> None:
        self._sequence = ''


def _sequence_complete(sequence: str) -> bool:
    if len(sequence) == 2:
        return sequence[1] not in '[O'          # ESC x: Alt+x
    if sequence[1] == 'O':
        return True                             # ESC O x: F1-F4
    if sequence[:3] == ESC + '[[':
        return len(sequence) == 4               # ESC [ [ x: the Linux console's F1-F5
    return '\x40' <= sequence[-1] <= '\x7e'     # ESC [ parameters final: arrows, F5...


def pass_keys(talker, fd, wait):
    """Hand every key read from fd to the talker, escape sequences dropped.
    `wait(fd, timeout)` (talker.SignalPipe.wait in the node) says when fd is READY
    to read, or that the timeout passed or shutdown is due. Returns at the
    end of input or at shutdown."""
    decoder = KeyDecoder()
    while True:
        event = wait(fd, ESCAPE_WAIT if decoder.pending else None)
        if event == SHUTDOWN:
            return
        if event == TIMED_OUT:
            decoder.timeout()
            continue
        data = os.read(fd, READ_SIZE)
        if not data:
            return
        for key in decoder.feed(data):
            talker.press(key)
