"""The turtle controller node: draws letters when it hears the trigger.

Pose messages are the clock: turtlesim publishes one per 16 ms tick, and the
drawing thread sends one command per pose it receives, so cmd_vel goes out at
the simulator's own 62.5 Hz and nothing ever waits in a loop of its own.

The drawing runs on its own thread, one primitive after the other, so that it
reads like the lab: rotate(90); move(3.0); ... Stepping a state machine from
the pose callback instead (as turtlesim's draw_square does) would need the
sequence cut into states; the thread keeps it a plain sequence.
"""
import math
import sys
import threading
import time
import traceback

import rospy
from std_msgs.msg import String

from .driver import DrawingAborted, TurtleDriver
from .drawing import LetterDrawer
from .jobs import Jobs
from .motion import EXECUTORS, STOP, SmoothExecutor, TimedExecutor
from .plan import DoesNotFit, Line, PlannedPose, Turn, wrap
from .settings import ParameterError, Settings, quote_unreadable

# Ignored messages can come at any rate (the tutorial talker sends "hello
# world" at 10 Hz on chatter): the first is said, then one per period.
IGNORED_LOG_PERIOD = 10.0
THROTTLED = f' (said at most every {IGNORED_LOG_PERIOD:g} s)'
PROGRESS_PERIOD = 5.0       # s between two progress lines of a drawing


class TurtleController(LetterDrawer):
    """The lab's class. Subscribes `chatter` (the trigger, or typed keys) and
    `~text` (std_msgs/String: a word to draw); drives the turtle through a
    TurtleDriver. Parameters: see settings.PARAMETERS."""

    def __init__(self, settings: Settings):
        super().__init__(settings)
        self.driver = TurtleDriver()
        self.jobs = Jobs()
        self._started = self._last_progress = 0.0
        rospy.Subscriber('chatter', String, self._on_chatter, queue_size=10)
        rospy.Subscriber('~text', String, self._on_text, queue_size=10)
        self._worker = threading.Thread(target=self._work, name='drawing', daemon=True)
        self._worker.start()
        if settings.text:
            self.request(settings.text, 'the ~text parameter')

    # -- requests --------------------------------------------------------------
    def _on_chatter(self, msg):
        data = msg.data
        shown = repr(data if len(data) <= 40 else data[:40] + '...')
        if self.settings.typing:
            font = self.settings.font
            if data == ' ' or (len(data) == 1 and font.glyph(data) is not None):
                self.type_key(data if font.case_sensitive else data.upper())
            else:
                rospy.loginfo_throttle(IGNORED_LOG_PERIOD, 'chatter %s ignored: typing mode draws '
                                       'single letters or digits' + THROTTLED, shown)
        elif data == self.settings.trigger:
            self.request(self.settings.letter, f'trigger {shown}')
        else:
            rospy.loginfo_throttle(IGNORED_LOG_PERIOD, 'chatter %s ignored: the trigger is %r'
                                   + THROTTLED, shown, self.settings.trigger)

    def _on_text(self, msg):
        font = self.settings.font
        text = msg.data if font.case_sensitive else msg.data.upper()
        if not text.strip() or font.undrawable(text):
            rospy.logwarn('~text %r refused: font %s has no glyph for %s', msg.data[:40],
                          font.name, font.undrawable(text)[:10] or 'a blank text')
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

    # -- the lab's primitives --------------------------------------------------
    def rotate(self, degrees):
        """Turn in place by `degrees` (counter-clockwise positive), timed."""
        pose = self._fresh_pose()
        angle = math.radians(degrees)
        self._execute(Turn(angle, wrap(pose.theta + angle)), self._timed)

    def move(self, meters):
        """Drive `meters` straight ahead, timed."""
        pose = self._fresh_pose()
        self._execute(Line(meters, pose.x + meters * math.cos(pose.theta),
                           pose.y + meters * math.sin(pose.theta), pose.theta), self._timed)

    def steer(self, primitive):
        """Reach the primitive's end, closed loop on the pose."""
        self._fresh_pose()
        self._execute(primitive, EXECUTORS['feedback'])

    def glide(self, points):
        """Smooth mode: trace the polyline through `points` without stopping."""
        if points:
            self._fresh_pose()
            self._run(SmoothExecutor(points, self.settings.linear_speed),
                      f'glide through {len(points)} points')

    def progress(self, ink_drawn, ink):
        """Every few seconds of a drawing: how far it is, and how long to go."""
        now = time.monotonic()
        if now - self._last_progress < PROGRESS_PERIOD or not 0 < ink_drawn < ink - 1e-6:
            return
        self._last_progress = now
        elapsed = now - self._started
        rospy.loginfo('%.0f%% of the ink drawn (%.2f of %.2f m); about %.0f s to go',
                      100 * ink_drawn / ink, ink_drawn, ink, elapsed * (ink - ink_drawn) / ink_drawn)

    def pen(self, down):
        self.driver.set_pen(self.settings.pen, down)

    def clear(self):
        rospy.loginfo('The canvas is full: clearing it and starting again at the first place')
        self.driver.clear()

    def _timed(self, primitive, linear_speed, angular_speed):
        return TimedExecutor(primitive, linear_speed, angular_speed, self.settings.clock)

    def _fresh_pose(self):
        pose = self.driver.wait_for_pose()
        self.driver.drop_stale_poses()
        return pose

    def _execute(self, primitive, executor_type):
        s = self.settings
        self._run(executor_type(primitive, s.linear_speed, s.angular_speed), _describe(primitive))

    def _run(self, executor, description):
        """One command per pose until the executor is done, then a stop."""
        rospy.loginfo('%s: start at %s', description, _pose_text(self.driver.latest_pose))
        command = executor.start(self.driver.latest_pose)
        while command is not None:
            self.driver.publish(command)
            command = executor.update(self.driver.next_pose())
        self.driver.publish(STOP)
        rospy.loginfo('%s: end at %s', description, _pose_text(self.driver.latest_pose))

    # -- the drawing thread ----------------------------------------------------
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

    def draw(self, text):
        """Draw `text` at the next free places on the canvas."""
        pose = self.driver.wait_for_pose()
        start = PlannedPose(pose.x, pose.y, pose.theta)
        places, must_clear = self.reserve(text, start)
        plan = self.plan(text, places, start)
        rospy.loginfo('Drawing %r (%s mode): ink %.2f m, travel %.2f m, about %.0f s', text,
                      self.settings.mode, plan.ink, plan.travel, plan.seconds)
        self._started = self._last_progress = time.monotonic()
        self.trace(plan, must_clear)
        rospy.loginfo('Done drawing %r; the turtle is at %s', text,
                      _pose_text(self.driver.latest_pose))

    def _abandon(self, text, error):
        """Stop the turtle and forget the layout: the simulator may come back
        with a fresh canvas, so the next drawing starts wherever the turtle is."""
        self.driver.stop()
        self.forget_layout()
        if isinstance(error, DrawingAborted):
            cause = str(error)
        elif isinstance(error, rospy.ServiceException):
            cause = f'a turtlesim service failed: {error}'
        else:
            cause = f'{type(error).__name__}: {error}'
            rospy.logdebug('Drawing of %r failed:\n%s', text, traceback.format_exc())
        rospy.logerr('Drawing of %r stopped: %s. The next trigger starts a new one.', text, cause)


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
