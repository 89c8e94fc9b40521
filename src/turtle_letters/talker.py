"""The keyboard talker node: a key press becomes a message on `chatter`.

On a terminal it reads single key presses (cbreak mode: no Enter needed, and
Ctrl-C still works) and puts the terminal back as it was when it ends, however
it ends. Without a terminal it reads lines, so `echo P | rosrun ...` works.
"""
import os
import select
import signal
import sys
import termios
import threading
import tty

import rospy
from std_msgs.msg import String

from .keys import message_for

WAKE_UP = 0.5   # s: how often a blocked wait looks whether ROS shut the node down


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

    def wait(self, fd=None):
        """Block until fd is readable (True) or shutdown is due (False)."""
        watched = [self.fd] if fd is None else [fd, self.fd]
        while not rospy.is_shutdown():
            readable, _, _ = select.select(watched, [], [], WAKE_UP)
            if self.fd in readable:
                rospy.signal_shutdown(f'signal {os.read(self.fd, 1)[0]}')
                return False
            if readable:
                return True
        return False


class Talker(rospy.SubscribeListener):
    """Publishes `chatter` (std_msgs/String).

    ~typing (bool, default false): publish every letter, digit and space
        typed, not only P.
    Presses made while nobody subscribes are kept and sent to the first
    subscriber, so a press made before the controller is up is not lost.
    """

    def __init__(self, typing=False):
        super().__init__()
        self.typing = typing
        self._lock = threading.Lock()
        self._pending = []
        self._publisher = rospy.Publisher('chatter', String, queue_size=10,
                                          subscriber_listener=self)

    def press(self, key):
        message = message_for(key, self.typing)
        if message is None:
            return
        with self._lock:
            if self._publisher.get_num_connections() == 0:
                self._pending.append(message)
                rospy.loginfo('Nobody listens on %s yet: %r is kept until someone does',
                              self._publisher.resolved_name, message)
                return
        self._publisher.publish(String(message))
        rospy.loginfo('Published %r on %s', message, self._publisher.resolved_name)

    def peer_subscribe(self, topic_name, topic_publish, peer_publish):
        with self._lock:
            pending, self._pending = self._pending, []
        for message in pending:
            peer_publish(String(message))
            rospy.loginfo('Published kept %r on %s', message, topic_name)


def read_keys(talker, fd, prompt, signals):
    """Key presses from a terminal, in cbreak mode, restored however we leave."""
    saved = termios.tcgetattr(fd)
    try:
        tty.setcbreak(fd, termios.TCSANOW)
        prompt()
        while signals.wait(fd):
            data = os.read(fd, 64)
            if not data:
                break
            for key in data.decode('utf-8', errors='replace'):
                talker.press(key)
    finally:
        termios.tcsetattr(fd, termios.TCSADRAIN, saved)


def read_lines(talker, fd, signals):
    """Lines from a pipe or file; each character of a line counts as a press."""
    buffered = b''
    while signals.wait(fd):
        data = os.read(fd, 4096)
        if not data:
            return
        buffered += data
        *lines, buffered = buffered.split(b'\n')
        for line in lines:
            for key in line.decode('utf-8', errors='replace').strip():
                talker.press(key)


def main():
    rospy.init_node('talker', disable_signals=True)
    signals = SignalPipe()
    typing = rospy.get_param('~typing', False)
    if not isinstance(typing, bool):
        rospy.logfatal('%s: ~typing is %r; allowed: true or false', rospy.get_name(), typing)
        raise SystemExit(2)
    talker = Talker(typing)
    what = 'a letter or digit to draw it' if typing else 'P to draw the letter'

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
            sys.stdout.write(f'talker: press {what} (no Enter needed); Ctrl-C quits\n')
            sys.stdout.flush()
        read_keys(talker, fd, prompt, signals)
    else:
        read_lines(talker, fd, signals)
        if not rospy.is_shutdown():
            rospy.loginfo('End of input: no more keys to read; the talker stays up '
                          'until shut down (kept presses still go out)')
    signals.wait()
