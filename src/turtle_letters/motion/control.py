"""One drawing's cancel and pause: set from ROS callbacks (the draw action,
the pause service), read by the turtle at every tick. No ROS here."""
import threading
import time


class Cancelled(Exception):
    """The drawing was cancelled: the turtle has stopped."""


class Control:
    """Whether a drawing may go on, and its clock with the pauses left out
    (timed primitives on the wall clock and the ETA run on it)."""

    def __init__(self, now=time.monotonic):
        self.now = now
        self._lock = threading.Lock()
        self._cancelled = False
        self._paused_since = None
        self._paused_for = 0.0          # s, pauses already over

    def cancel(self):
        self._cancelled = True

    @property
    def cancelled(self):
        return self._cancelled

    def check(self):
        """Raises Cancelled once the drawing is cancelled (for its planning)."""
        if self._cancelled:
            raise Cancelled('cancelled while it was planned')

    def pause(self, paused):
        """Hold (True) or go on (False); whether that changed anything."""
        with self._lock:
            if paused == (self._paused_since is not None):
                return False
            if paused:
                self._paused_since = self.now()
            else:
                self._paused_for += self.now() - self._paused_since
                self._paused_since = None
            return True

    @property
    def paused(self):
        return self._paused_since is not None

    def clock(self):
        """Seconds, on a clock that stands still while the drawing is paused."""
        with self._lock:
            now = self.now()
            held = now - self._paused_since if self._paused_since is not None else 0.0
            return now - self._paused_for - held
