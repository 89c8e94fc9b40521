"""The turtle's ROS plumbing: its pose stream, its cmd_vel, its pen, its
spawn and kill, and the canvas. The stop on shutdown lives here, so nothing
that moves the turtle can leave it coasting, and the way a signal starts
that shutdown."""
import collections
import signal
import threading
import time
import weakref

import rosgraph
import rosgraph.names
import rospy
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty
from turtlesim.msg import Pose
from turtlesim.srv import Kill, SetPen, Spawn

from .control import Cancelled



POSE_TIMEOUT = 1.0      # s without a pose: the simulator is gone
POSE_PATIENCE = 3.0     # s a drawing waits for its turtle's first pose
POSES_KEPT = 1000       # 16 s of ticks: the drawing thread reads far faster
# A command is sent when it changes, and repeated while it holds so that
# turtlesim (which stops a turtle after 1 s without one) keeps going. One
# command per tick from 30 turtles was most of the simulator's work.
REPEAT_PERIOD = 0.25    # s
# What turtlesim logs on /rosout when its canvas is cleared or reset.
CANVAS_WORDS = {'Clearing turtlesim.': 'clear', 'Resetting turtlesim.': 'reset'}


def beside(turtle, name):
    """`name` in the namespace that holds the turtle's name: turtlesim keeps
    its services (spawn, kill, clear) there (/spawn for turtle1 or /alice)."""
    return rosgraph.names.ns_join(rosgraph.names.namespace(rospy.resolve_name(turtle)), name)


class DrawingAborted(RuntimeError):
    pass


class NoPoses(DrawingAborted):
    """turtlesim publishes the turtle's poses, but none reach us."""


class PoseStream:
    """A turtle's poses, as turtlesim publishes them (one a tick): the latest,
    and the ones the drawing thread has not read yet."""

    def __init__(self, topic, published):
        self.topic = topic
        self.latest = None
        self._published = published     # () -> whether turtlesim publishes the topic
        # Not yet read; the oldest go when it is full (idle: nobody reads).
        # One lock for the callback and the drawing thread: no check of one
        # can be overtaken by the other.
        self._unread = collections.deque(maxlen=POSES_KEPT)
        self._arrived = threading.Condition()
        self._subscriber = None

    def listen(self):
        """Subscribe. Once the turtle exists, if we spawn it: then the master
        hands us turtlesim's publisher at once, instead of calling this machine
        back later (which a machine the master cannot reach would never hear)."""
        if self._subscriber is None:
            self._subscriber = rospy.Subscriber(self.topic, Pose, self._on_pose,
                                                queue_size=100, tcp_nodelay=True)

    def _on_pose(self, msg):
        with self._arrived:
            self.latest = msg
            self._unread.append(msg)
            self._arrived.notify_all()

    def _take(self, timeout):
        """The oldest unread pose, or None if none comes within `timeout` s."""
        with self._arrived:
            if not self._arrived.wait_for(lambda: self._unread, timeout):
                return None
            return self._unread.popleft()

    def wait(self, patience=POSE_PATIENCE, cancelled=lambda: False, say=True):
        """The latest pose, once there is one; says once that it waits (if
        `say`, and none came within a second). Every wait ends: on shutdown
        (DrawingAborted), on `cancelled()` (control.Cancelled), or after
        `patience` s (None: at start only, where Ctrl-C ends it): NoPoses if
        turtlesim publishes the poses but none reach us, else DrawingAborted."""
        deadline = None if patience is None else time.monotonic() + patience
        said_at = time.monotonic() + 1.0 if say else None
        while self.latest is None:
            if rospy.is_shutdown():
                raise DrawingAborted('shutting down')
            if cancelled():
                raise Cancelled('cancelled while waiting for its turtle')
            now = time.monotonic()
            if said_at is not None and now >= said_at:
                rospy.loginfo('Waiting for turtlesim: no pose on %s yet', self.topic)
                said_at = None
            if deadline is not None and now >= deadline:
                if self._published():
                    raise NoPoses(patience)
                raise DrawingAborted(f'no pose on {self.topic} in {patience:g} s, and turtlesim '
                                     'publishes none: the turtle is gone, or turtlesim with it')
            self._take(0.25)
        return self.latest

    def next(self):
        """The next pose: the next tick."""
        pose = self._take(POSE_TIMEOUT)
        if pose is None:
            raise DrawingAborted(f'no pose from turtlesim for {POSE_TIMEOUT:g} s: turtlesim has '
                                 'stopped, or the network to its machine is down')
        if rospy.is_shutdown():
            raise DrawingAborted('shutting down')
        return pose

    def drop_stale(self):
        """Poses from before now would count ticks that are not ours."""
        with self._arrived:
            self._unread.clear()

    def forget(self):
        """A new turtle of the same name: nothing of the old one counts."""
        self.latest = None
        self.drop_stale()

    def connected(self):
        return self._subscriber is not None and self._subscriber.get_num_connections() > 0

    def close(self):
        if self._subscriber is not None:
            self._subscriber.unregister()


class TurtleDriver:
    """Subscribes `TURTLE/pose` (its `poses`); publishes `TURTLE/cmd_vel`; calls
    `TURTLE/set_pen`, and `spawn`, `kill` and `clear` beside the turtle.
    TURTLE is a name like turtle1 (relative to the node's namespace) or /alice."""

    def __init__(self, turtle='turtle1'):
        self.turtle = turtle
        self.name = rospy.resolve_name(turtle).rsplit('/', 1)[1]    # turtlesim's name for it
        self.commanded = (0.0, 0.0, 0.0)       # the last command sent
        self._sent_at = 0.0
        self._publish_lock = threading.Lock()
        self._stopping = False                 # once set, only the stop goes out
        self._cmd_vel = rospy.Publisher(f'{turtle}/cmd_vel', Twist, queue_size=10)
        self._set_pen = rospy.ServiceProxy(f'{turtle}/set_pen', SetPen)
        self._clear = rospy.ServiceProxy(beside(turtle, 'clear'), Empty)
        self._spawn = rospy.ServiceProxy(beside(turtle, 'spawn'), Spawn)
        self._kill = rospy.ServiceProxy(beside(turtle, 'kill'), Kill)
        self.poses = PoseStream(rospy.resolve_name(f'{turtle}/pose'), self.exists)
        _stop_on_shutdown(self)

    @property
    def cmd_vel_topic(self):
        return self._cmd_vel.resolved_name

    def cmd_vel_connections(self):
        return self._cmd_vel.get_num_connections()

    def publish(self, command, repeat=False):
        """Send `command` (linear x, linear y, angular z) if it differs from
        the last one, or the last one went out REPEAT_PERIOD ago, or `repeat`."""
        command = tuple(command)
        now = time.monotonic()
        if command == self.commanded and now - self._sent_at < REPEAT_PERIOD and not repeat:
            return
        twist = Twist()
        twist.linear.x, twist.linear.y, twist.angular.z = command
        with self._publish_lock:
            if not self._stopping:
                self._cmd_vel.publish(twist)
                self.commanded, self._sent_at = command, now

    def stop(self):
        """Stop the turtle now rather than let it coast for turtlesim's 1 s timeout."""
        try:
            self.publish((0.0, 0.0, 0.0), repeat=True)
        except rospy.ROSException:
            pass    # already shut down: the shutdown hook sent the stop

    def exists(self, wait=0.0):
        """Whether turtlesim has this turtle (its pose topic is published),
        looking again for up to `wait` s."""
        master = rosgraph.Master(rospy.get_name())
        deadline = time.monotonic() + wait
        while True:
            if any(name == self.poses.topic for name, _ in master.getPublishedTopics('')):
                return True
            if time.monotonic() >= deadline or rospy.is_shutdown():
                return False
            time.sleep(0.05)

    def wait_for_simulator(self):
        """Wait for turtlesim's spawn service; whether we had to (and said so)."""
        spawn = self._spawn.resolved_name
        try:
            rospy.wait_for_service(spawn, timeout=2.0)
            return False
        except rospy.ROSException:
            rospy.loginfo('Waiting for turtlesim: no %s service yet; drawings start when it comes',
                          spawn)
            rospy.wait_for_service(spawn)
            return True

    def spawn(self, x, y, theta=0.0):
        """Spawn the turtle; raises rospy.ServiceException if turtlesim refuses."""
        self._spawn(x, y, theta, self.name)

    def kill(self, name=None):
        """Kill our turtle, or the turtle `name` of the same turtlesim."""
        self._kill(name or self.name)

    def wait_connected(self, timeout):
        """Whether turtlesim hears our cmd_vel and we hear its poses within
        `timeout` s (a new turtle's topics take a moment to connect)."""
        deadline = time.monotonic() + timeout
        while not rospy.is_shutdown() and time.monotonic() < deadline:
            if self._cmd_vel.get_num_connections() and self.poses.connected():
                return True
            time.sleep(0.02)
        return False

    def close(self):
        """Let go of the turtle's topics (a spare turtle, once killed)."""
        with self._publish_lock:
            self._stopping = True
        self._cmd_vel.unregister()
        self.poses.close()
        _OPEN.discard(self)

    def set_pen(self, pen, down):
        """Lowering the pen sets its colour and width too (turtlesim's set_pen)."""
        self._set_pen(*pen, 0 if down else 1)

    def clear(self):
        self._clear()

    def last_stop(self):
        """The last word on cmd_vel is a stop, even with a drawing under way."""
        with self._publish_lock:
            if self._stopping:          # closed
                return
            self._stopping = True
            self._cmd_vel.publish(Twist())


# The drivers not closed yet (a closed one is forgotten with it), and the
# one shutdown hook that stops them all.
_OPEN = weakref.WeakSet()
_HOOKED = []


def _stop_on_shutdown(driver):
    _OPEN.add(driver)
    if not _HOOKED:
        _HOOKED.append(True)
        rospy.on_shutdown(_stop_every_driver)


def _stop_every_driver():
    drivers = list(_OPEN)
    for driver in drivers:
        driver.last_stop()
    if drivers:
        # The publishers' queue threads send the stops; give them a moment
        # before rospy closes the topics (a turtle is at most one tick away).
        time.sleep(0.1)


def call_briefly(call, timeout=2.0):
    """A service call that must not hold up a shutdown: at most `timeout` s."""
    thread = threading.Thread(target=lambda: _quietly(call), daemon=True)
    thread.start()
    thread.join(timeout)


def _quietly(call):
    try:
        call()
    except Exception:   # the turtle or turtlesim is gone already: nothing to undo
        pass


def init_node_shut_down_beside_main(name, argv):
    """rospy.init_node, with Ctrl-C and SIGTERM starting rospy's shutdown on
    a thread of its own. rospy's handler runs it on the main thread,
    wherever that was: in the middle of a call to the master (each log line
    asks the master a parameter), rospy's own cleanup then waits for ever on
    the lock that call holds (faults test_3c hung so, stopped while saying
    it waits)."""
    rospy.init_node(name, argv=argv, disable_signals=True)

    def on_signal(number, _frame):
        threading.Thread(target=rospy.signal_shutdown, args=(f'signal-{number}',),
                         name='shutdown').start()
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, on_signal)
