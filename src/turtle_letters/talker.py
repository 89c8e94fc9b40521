"""The keyboard talker node: a key press becomes a message on `chatter`.

On a terminal it reads single key presses (cbreak mode: no Enter needed, and
Ctrl-C still works) and puts the terminal back as it was when it ends, however
it ends. Without a terminal it reads its input the same way, a character a
press and a newline an Enter, so `echo P | rosrun ...` works.
"""
import os
import select
import signal
import sys
import termios
import threading
import time
import tty

import rospy
from std_msgs.msg import String

from .actions.jobs import TYPED_AHEAD
from .classroom.liveness import refuse_a_second
from .keys import READY, SHUTDOWN, TIMED_OUT, message_for, pass_keys
from .settings import ParameterError, quote_unreadable, read_parameter

WAKE_UP = 0.5   # s: how often a blocked wait looks whether ROS shut the node down
KEPT_PRESSES = 32   # presses kept while nobody subscribes; later ones are dropped


class SignalPipe:
    """SIGINT and SIGTERM, turned into a readable pipe.

    rospy's own handler would shut the node down wherever the main thread
    happens to be, even inside publish(), where shutdown then waits for a lock
    the interrupted publish holds. Here the handler only writes a byte; the
    main loop sees it in select() and shuts down from a clean point.
    """

    def __init__(self):
        self.fd, self._write_fd = os.pipe()
        os.set_blocking(self._write_fd, False)
        for sig in (signal.SIGINT, signal.SIGTERM):
            signal.signal(sig, self._on_signal)

    def _on_signal(self, number, _frame):
        try:
            os.write(self._write_fd, bytes([number]))
        except BlockingIOError:
            pass

    def wait(self, fd=None, timeout=None):
        """Block until fd is readable (READY), `timeout` seconds have passed
        (TIMED_OUT) or shutdown is due (SHUTDOWN)."""
        watched = [self.fd] if fd is None else [fd, self.fd]
        deadline = None if timeout is None else time.monotonic() + timeout
        while not rospy.is_shutdown():
            wait = WAKE_UP if deadline is None else max(0.0, deadline - time.monotonic())
            readable, _, _ = select.select(watched, [], [], min(wait, WAKE_UP))
            if self.fd in readable:
                rospy.signal_shutdown(f'signal {os.read(self.fd, 1)[0]}')
                return SHUTDOWN
            if readable:
                return READY
            if deadline is not None and time.monotonic() >= deadline:
                return TIMED_OUT
        return SHUTDOWN


class Talker(rospy.SubscribeListener):
    """Publishes `chatter` (std_msgs/String).

    ~trigger (str, default "P"): what the trigger key publishes. The key is
        the trigger's character, either case; a longer trigger is sent by Enter.
    ~typing (bool, default false): publish every letter, digit and space
        typed, not only the trigger.
    Presses made while nobody subscribes (up to KEPT_PRESSES) are kept and
    sent to the first subscriber, so a press made before the controller is
    up is not lost.
    """

    def __init__(self, typing=False, trigger='P'):
        super().__init__()
        self.typing = typing
        self.trigger = trigger
        self._lock = threading.Lock()
        self._pending = []
        self._dropping = False
        self._publisher = rospy.Publisher('chatter', String, queue_size=TYPED_AHEAD,
                                          subscriber_listener=self)

    def press(self, key):
        message = message_for(key, self.typing, self.trigger)
        if message is None:
            return
        with self._lock:
            # Kept ones go first, and under the lock: a press made while the
            # first subscriber connects must not overtake them.
            if self._publisher.get_num_connections() == 0 or self._pending:
                self._keep(message)
                return
            self._publisher.publish(String(message))
        rospy.loginfo('Published %r on %s', message, self._publisher.resolved_name)

    def _keep(self, message):
        if len(self._pending) >= KEPT_PRESSES:
            if not self._dropping:
                rospy.logwarn('Nobody listens on %s and %d presses are kept already: '
                              'further presses are dropped until someone does',
                              self._publisher.resolved_name, KEPT_PRESSES)
            self._dropping = True
            return
        self._pending.append(message)
        rospy.loginfo('Nobody listens on %s yet: %r is kept until someone does',
                      self._publisher.resolved_name, message)

    def peer_subscribe(self, topic_name, topic_publish, peer_publish):
        with self._lock:
            pending, self._pending = self._pending, []
            self._dropping = False
            for message in pending:
                peer_publish(String(message))
        for message in pending:
            rospy.loginfo('Published kept %r on %s', message, topic_name)


def read_terminal(talker, fd, prompt, signals):
    """Key presses from a terminal, in cbreak mode, restored however we leave."""
    saved = termios.tcgetattr(fd)
    try:
        tty.setcbreak(fd, termios.TCSANOW)
        prompt()
        pass_keys(talker, fd, signals.wait)
    finally:
        termios.tcsetattr(fd, termios.TCSADRAIN, saved)


def main():
    refuse_a_second('talker')
    rospy.init_node('talker', argv=quote_unreadable(sys.argv), disable_signals=True)
    signals = SignalPipe()
    try:
        typing = read_parameter('typing', rospy.get_param)
        trigger = read_parameter('trigger', rospy.get_param)
    except ParameterError as e:
        rospy.logfatal('%s: %s', rospy.get_name(), e)
        raise SystemExit(2)
    talker = Talker(typing, trigger)
    if typing:
        what = 'a letter or digit to draw it (no Enter needed)'
    elif len(trigger) == 1:
        what = f'{trigger.upper()} to draw the letter (no Enter needed)'
    else:
        what = f'Enter to send {trigger!r} and draw the letter'

    try:
        fd = sys.stdin.fileno() if sys.stdin is not None else -1
        os.fstat(fd)
    except (OSError, ValueError):
        fd = -1

    if fd < 0:
        rospy.logwarn('No standard input: nothing to read keys from. '
                      'Publish on %s instead.', rospy.resolve_name('chatter'))
    elif os.isatty(fd):
        def prompt():
            sys.stdout.write(f'talker: press {what}; Ctrl-C quits\n')
            sys.stdout.flush()
        read_terminal(talker, fd, prompt, signals)
    else:
        pass_keys(talker, fd, signals.wait)
        if not rospy.is_shutdown():
            rospy.loginfo('End of input: no more keys to read; the talker stays up '
                          'until shut down (kept presses still go out)')
    signals.wait()
