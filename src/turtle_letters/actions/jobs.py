"""Which drawing requests are taken, and in what order. No ROS here.

The lab draws one letter per trigger: a trigger (or a word) that comes while a
drawing is waiting or under way is refused, not queued, so a burst of triggers
draws once. Typed keys are different: like a typewriter, keys typed ahead of
the turtle wait their turn, up to TYPED_AHEAD of them.
"""
import collections
import threading
from typing import Optional

from ..letters.plan import SvgFile

TYPED_AHEAD = 32


class Jobs:
    """Requests in, one drawing at a time out. Every decision is taken under
    one lock, so a request can never slip in between a drawing's end and the
    check of whether another one waits."""

    def __init__(self, typed_ahead: int = TYPED_AHEAD) -> None:
        self.typed_ahead = typed_ahead
        self._changed = threading.Condition()
        self._waiting = collections.deque()
        self._drawing = False

    def offer(self, request, accept=lambda: None) -> bool:
        """A trigger, a word or a goal: taken only when nothing waits or is
        drawn. `accept()` is called once it is taken, before anyone can take
        it to draw (an action goal must be accepted before it ends)."""
        with self._changed:
            if self._drawing or self._waiting:
                return False
            accept()
            return self._append(request)

    def offer_key(self, char: str) -> bool:
        """A typed key: waits its turn unless `typed_ahead` keys already wait."""
        with self._changed:
            if len(self._waiting) >= self.typed_ahead:
                return False
            return self._append(char)

    def _append(self, text: str) -> bool:
        self._waiting.append(text)
        self._changed.notify()
        return True

    def take(self, timeout: float) -> Optional[str]:
        """The next thing to draw (it is then being drawn until done()), or
        None if nothing came within `timeout` seconds."""
        with self._changed:
            if not self._changed.wait_for(lambda: self._waiting, timeout):
                return None
            self._drawing = True
            return self._waiting.popleft()

    def each(self, stopped, timeout: float = 0.5):
        """Each request in turn (call done() after each), until `stopped()`."""
        while not stopped():
            request = self.take(timeout)
            if request is not None:
                yield request

    def done(self) -> None:
        with self._changed:
            self._drawing = False


def chatter_request(data: str, trigger: str, typing: bool, font):
    """What a message on chatter asks for: ('key', character) in typing mode,
    ('trigger', None), or ('ignored', why)."""
    if typing:
        if data == ' ' or (len(data) == 1 and font.glyph(data) is not None):
            return 'key', data if font.case_sensitive else data.upper()
        return 'ignored', 'typing mode draws single letters or digits'
    if data == trigger:
        return 'trigger', None
    return 'ignored', f'the trigger is {trigger!r}'


def text_request(data: str, font):
    """(text to draw, None), or (None, why not) for a text on ~text."""
    text = data if font.case_sensitive else data.upper()
    if not text.strip() or font.undrawable(text):
        return None, (f'font {font.name} has no glyph for '
                      f'{font.undrawable(text)[:10] or "a blank text"}')
    return text, None


def goal_request(text: str, svg: str, font):
    """(text or SvgFile to draw, None), or (None, why not) for a draw goal."""
    if bool(text) == bool(svg):
        given = 'both were given' if text else 'neither was given'
        return None, f'a goal has exactly one of text and svg ({given})'
    if svg:
        return SvgFile(svg), None
    return text_request(text, font)
