"""The turtle controller node: draws letters when it hears the trigger.

Pose messages are the clock: turtlesim publishes one per 16 ms tick, and the
drawing thread sends one command per pose it receives, so cmd_vel goes out at
the simulator's own 62.5 Hz and nothing ever waits in a loop of its own.
"""
import math
import queue
import sys
import threading
import time
import traceback

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String
from std_srvs.srv import Empty
from turtlesim.msg import Pose as PoseMsg
from turtlesim.srv import SetPen

from .jobs import Jobs
from .motion import EXECUTORS, STOP, PoseSample
from .plan import DoesNotFit, Layout, Line, Pen, Pose, Turn, glyph_for, plan_glyph, undrawable, wrap
from .settings import ParameterError, Settings, quote_unreadable

POSE_TIMEOUT = 1.0                  # s without a pose: the simulator is gone
POSES_KEPT = 1000                   # 16 s of ticks: the drawing thread reads far faster
# Ignored messages can come at any rate (the tutorial talker sends "hello
# world" at 10 Hz on chatter): the first is said, then one per period.
IGNORED_LOG_PERIOD = 10.0
THROTTLED = f' (said at most every {IGNORED_LOG_PERIOD:g} s)'


class DrawingAborted(RuntimeError):
    pass


class TurtleController:
    """Subscribes `chatter` and `turtle1/pose`; publishes `turtle1/cmd_vel`;
    calls `turtle1/set_pen` and `clear`. Subscribes `~text` (std_msgs/String):
    a word to draw. Parameters: see Settings."""

    def __init__(self, settings: Settings):
        self.settings = settings
        self._poses = queue.Queue(maxsize=POSES_KEPT)
        self._latest_pose = None
        self.jobs = Jobs()
        self._layout = None
        self._pen_known_down = True
        self._publish_lock = threading.Lock()
        self._stopping = False                 # once set, only the stop goes out
        self._cmd_vel = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=10)
        self._set_pen = rospy.ServiceProxy('turtle1/set_pen', SetPen)
        self._clear = rospy.ServiceProxy('clear', Empty)
        rospy.Subscriber('turtle1/pose', PoseMsg, self._on_pose, queue_size=100, tcp_nodelay=True)
        rospy.Subscriber('chatter', String, self._on_chatter, queue_size=10)
        rospy.Subscriber('~text', String, self._on_text, queue_size=10)
        rospy.on_shutdown(self._on_shutdown)
        self._worker = threading.Thread(target=self._work, name='drawing', daemon=True)
        self._worker.start()
        if settings.text:
            self.request(settings.text, 'the ~text parameter')

    # -- inputs ----------------------------------------------------------------
    def _on_pose(self, msg):
        sample = PoseSample(msg.x, msg.y, msg.theta, msg.linear_velocity, msg.angular_velocity)
        self._latest_pose = sample
        if self._poses.full():          # idle: nobody reads; keep only the newest
            self._poses.get_nowait()
        self._poses.put_nowait(sample)

    def _on_chatter(self, msg):
        data = msg.data
        shown = repr(data if len(data) <= 40 else data[:40] + '...')
        if self.settings.typing:
            if data == ' ' or (len(data) == 1 and glyph_for(data) is not None):
                self.type_key(data.upper())
            else:
                rospy.loginfo_throttle(IGNORED_LOG_PERIOD, 'chatter %s ignored: typing mode draws '
                                       'single letters or digits' + THROTTLED, shown)
        elif data == self.settings.trigger:
            self.request(self.settings.letter, f'trigger {shown}')
        else:
            rospy.loginfo_throttle(IGNORED_LOG_PERIOD, 'chatter %s ignored: the trigger is %r'
                                   + THROTTLED, shown, self.settings.trigger)

    def _on_text(self, msg):
        text = msg.data.upper()
        if not text.strip() or undrawable(text):
            rospy.logwarn('~text %r refused: only A-Z, 0-9 and spaces can be drawn', msg.data[:40])
            return
        self.request(text, '~text')

    def request(self, text, source):
        """Draw `text` unless a drawing is under way (then it is ignored, not queued)."""
        if not self.jobs.offer(text):
            rospy.loginfo_throttle(IGNORED_LOG_PERIOD, '%s ignored: a drawing is under way'
                                   + THROTTLED, source)

    def type_key(self, char):
        """Typing mode: like a typewriter, keys typed ahead wait their turn."""
        if not self.jobs.offer_key(char):
            rospy.logwarn_throttle(IGNORED_LOG_PERIOD, 'Key %r ignored: %d keys are already '
                                   'waiting' + THROTTLED, char, self.jobs.typed_ahead)

    # -- primitives ------------------------------------------------------------------
    def rotate(self, degrees):
        """Turn in place by `degrees` (counter-clockwise positive), timed."""
        pose = self._wait_for_pose()
        self._drop_stale_poses()
        angle = math.radians(degrees)
        self._run(Turn(angle, wrap(pose.theta + angle)), 'timed')

    def move(self, meters):
        """Drive `meters` straight ahead, timed."""
        pose = self._wait_for_pose()
        self._drop_stale_poses()
        self._run(Line(meters, pose.x + meters * math.cos(pose.theta),
                       pose.y + meters * math.sin(pose.theta), pose.theta), 'timed')

    def _run(self, primitive, mode):
        s = self.settings
        executor = EXECUTORS[mode](primitive, s.linear_speed, s.angular_speed)
        rospy.loginfo('%s: start at %s', _describe(primitive), _pose_text(self._latest_pose))
        command = executor.start(self._latest_pose)
        while command is not None:
            self._publish(command)
            command = executor.update(self._next_pose())
        self._publish(STOP)
        rospy.loginfo('%s: end at %s', _describe(primitive), _pose_text(self._latest_pose))

    def _drop_stale_poses(self):
        """Poses from before now would count ticks that are not ours."""
        while not self._poses.empty():
            self._poses.get_nowait()

    def _next_pose(self):
        try:
            pose = self._poses.get(timeout=POSE_TIMEOUT)
        except queue.Empty:
            raise DrawingAborted(f'no pose from turtlesim for {POSE_TIMEOUT:g} s') from None
        if rospy.is_shutdown():
            raise DrawingAborted('shutting down')
        return pose

    def _publish(self, command):
        twist = Twist()
        twist.linear.x, twist.linear.y, twist.angular.z = command
        with self._publish_lock:
            if not self._stopping:
                self._cmd_vel.publish(twist)

    def stop(self):
        """Stop the turtle now rather than let it coast for turtlesim's 1 s timeout."""
        try:
            self._publish(STOP)
        except rospy.ROSException:
            pass    # already shut down: the shutdown hook sent the stop

    def _on_shutdown(self):
        """The last word on cmd_vel is a stop, even with a drawing under way."""
        with self._publish_lock:
            self._stopping = True
            self._cmd_vel.publish(Twist())
        # The publisher's queue thread sends it; give it a moment before
        # rospy closes the topic (the turtle is at most one tick away).
        time.sleep(0.1)

    def _pen(self, down):
        # Lowering the pen sets its colour too: the user's, not turtlesim's default.
        self._set_pen(*self.settings.pen, 0 if down else 1)
        self._pen_known_down = down

    # -- drawing ---------------------------------------------------------------------
    def _wait_for_pose(self):
        if self._latest_pose is None:
            rospy.loginfo('Waiting for turtlesim: no pose on %s yet; the drawing starts when it comes',
                          rospy.resolve_name('turtle1/pose'))
        while self._latest_pose is None and not rospy.is_shutdown():
            try:
                self._poses.get(timeout=0.5)
            except queue.Empty:
                pass
        if self._latest_pose is None:
            raise DrawingAborted('shutting down')
        return self._latest_pose

    def _work(self):
        while not rospy.is_shutdown():
            text = self.jobs.take(timeout=0.5)
            if text is None:
                continue
            try:
                self.draw(text)
            except DoesNotFit as e:
                rospy.logerr('Refused: %s', e)
            except Exception as e:  # whatever it was, this thread must live on
                self._abandon(text, e)
            finally:
                self.jobs.done()

    def _abandon(self, text, error):
        """Stop the turtle and forget the layout: the simulator may come back
        with a fresh canvas, so the next drawing starts wherever the turtle is."""
        self.stop()
        self._layout = None
        self._pen_known_down = False
        if isinstance(error, DrawingAborted):
            cause = str(error)
        elif isinstance(error, rospy.ServiceException):
            cause = f'a turtlesim service failed: {error}'
        else:
            cause = f'{type(error).__name__}: {error}'
            rospy.logdebug('Drawing of %r failed:\n%s', text, traceback.format_exc())
        rospy.logerr('Drawing of %r stopped: %s. The next trigger starts a new one.', text, cause)

    def draw(self, text):
        """Draw `text` at the next free places on the canvas."""
        s = self.settings
        pose = self._wait_for_pose()
        if self._layout is None:
            self._layout = Layout((pose.x, pose.y), s.size)
        places, must_clear = self._layout.reserve(text)
        self._drop_stale_poses()
        if must_clear:
            rospy.loginfo('The canvas is full: clearing it and starting again at the first place')
            self._clear()
        self._pen(True)
        rospy.loginfo('Drawing %r (%s mode)', text, s.mode)
        start = Pose(pose.x, pose.y, pose.theta)
        for char, place in zip(text, places):
            if place is None:
                continue
            primitives, start = plan_glyph(glyph_for(char), place, s.size, start, s.turn_direction)
            for primitive in primitives:
                if isinstance(primitive, Pen):
                    self._pen(primitive.down)
                else:
                    self._run(primitive, s.mode)
        rospy.loginfo('Done drawing %r; the turtle is at %s', text, _pose_text(self._latest_pose))


def _describe(primitive):
    if isinstance(primitive, Turn):
        return f'rotate {math.degrees(primitive.angle):.1f} deg'
    return f'move {primitive.length:.3f} m'


def _pose_text(pose):
    if pose is None:
        return '(no pose)'
    return f'x={pose.x:.4f} y={pose.y:.4f} theta={pose.theta:.4f}'


def main():
    rospy.init_node('turtlebot_controller', argv=quote_unreadable(sys.argv))
    try:
        settings = Settings(rospy.get_param)
    except ParameterError as e:
        rospy.logfatal('%s: %s', rospy.get_name(), e)
        raise SystemExit(2)
    TurtleController(settings)
    rospy.loginfo('Ready: publish %r on %s to draw %r (%s mode)', settings.trigger,
                  rospy.resolve_name('chatter'), settings.letter, settings.mode)
    rospy.spin()
