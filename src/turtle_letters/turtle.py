"""One turtle and the lab's calls on it: rotate(degrees) and move(meters),
the lab's timed primitives; steer(primitive) and glide(points) for the other
modes; pen(down) and clear(). Each runs one command per pose that turtlesim publishes
(its 16 ms tick is the clock), through a TurtleDriver, and ends with a stop.
At every tick the turtle's control may hold it (pause) or stop the drawing
(cancel)."""
import math
import time

import rospy

from .classroom.diagnosis import STALL_SECONDS, stall_diagnosis
from .letters.geometry import wrap
from .letters.plan import DEFAULT_PEN
from .letters.primitives import Line, Turn
from .motion.control import Cancelled, Control
from .motion.driver import DrawingAborted
from .motion.executors import STOP, FeedbackExecutor, SmoothExecutor, StallWatch, TimedExecutor
from .motion.latency import Deadline, Latency


class Turtle:
    """The controller's own turtle, or a spare one of a parallel word
    (`label` is said before each of its log lines)."""

    def __init__(self, driver, settings, label=''):
        self.driver = driver
        self.settings = settings
        self.label = label
        self.control = Control()        # the drawing's: set for each drawing
        self.latency = Latency()        # how late its commands act, kept from stroke to stroke
        # turtlesim's pen starts down in its default colour: a call is needed
        # only for another colour, or once the pen may have been left up
        self.pen_is_down = settings.pen == DEFAULT_PEN

    def rotate(self, degrees):
        """Turn in place by `degrees` (counter-clockwise positive), timed."""
        pose = self._fresh_pose()
        angle = math.radians(degrees)
        self._timed(Turn(angle, wrap(pose.theta + angle)), f'rotate {degrees:.1f} deg',
                    abs(angle) / self.settings.angular_speed)

    def move(self, meters):
        """Drive `meters` straight ahead, timed."""
        pose = self._fresh_pose()
        self._timed(Line(meters, pose.x + meters * math.cos(pose.theta),
                         pose.y + meters * math.sin(pose.theta), pose.theta),
                    f'move {meters:.3f} m', abs(meters) / self.settings.linear_speed)

    def steer(self, primitive):
        """Reach the primitive's end, closed loop on the pose."""
        self._fresh_pose()
        s = self.settings
        turning = isinstance(primitive, Turn)
        what = (f'rotate {math.degrees(primitive.angle):.1f} deg' if turning
                else f'move {primitive.length:.3f} m')
        seconds = (abs(primitive.angle) / s.angular_speed if turning
                   else abs(primitive.length) / s.linear_speed)
        self._run(FeedbackExecutor(primitive, s.linear_speed, s.angular_speed, self.latency),
                  what, seconds)

    def glide(self, points):
        """Smooth mode: trace the polyline through `points` without stopping."""
        if points:
            pose = self._fresh_pose()
            path = [(pose.x, pose.y)] + list(points)
            length = sum(math.dist(a, b) for a, b in zip(path, path[1:]))
            self._run(SmoothExecutor(points, self.settings.linear_speed, self.latency),
                      f'glide through {len(points)} points',
                      length / self.settings.linear_speed + len(points) * math.pi / 3.1)

    def pen(self, down, colour=None):
        """Down (in `colour`, r g b, or else ~pen's) or up; ~pen's width always."""
        pen = self.settings.pen if colour is None else tuple(colour) + self.settings.pen[3:]
        self.driver.set_pen(pen, down)
        self.pen_is_down = down and colour is None

    def clear(self):
        """Wipe turtlesim's canvas (the lab's whole canvas, when it is full)."""
        self.driver.clear()

    def pen_down(self):
        """Before a drawing: the pen down in our colour, unless it surely is."""
        if not self.pen_is_down:
            self.pen(True)

    def _timed(self, primitive, description, seconds):
        s = self.settings
        self._run(TimedExecutor(primitive, s.linear_speed, s.angular_speed, s.clock,
                                now=self.control.clock, latency=self.latency),
                  description, seconds)

    def _fresh_pose(self):
        pose = self.driver.poses.wait(cancelled=lambda: self.control.cancelled)
        self.driver.poses.drop_stale()      # they would count ticks that are not ours
        return pose

    def _run(self, executor, description, seconds):
        """One command per pose until the executor is done, then a stop. A
        turtle that does not do as told for STALL_SECONDS, or has not done
        the stroke (`seconds` long) by its deadline, stops the drawing.
        Paused, the turtle is told to stand while the executor goes on
        reading poses (so a timed primitive counts the tick a late stop
        took), and the deadline waits."""
        driver, control, latency = self.driver, self.control, self.latency
        rospy.loginfo('%s%s: start at %s', self.label, description, pose_text(driver.poses.latest))
        watch = StallWatch(STALL_SECONDS)
        deadline = Deadline(seconds, time.monotonic(), latency)
        command = executor.start(driver.poses.latest)
        while command is not None:
            if control.cancelled:
                driver.stop()
                raise Cancelled(f'cancelled during {description}, '
                                f'at {pose_text(driver.poses.latest)}')
            sent = STOP if control.paused else command
            driver.publish(sent)
            watch.sent(sent)
            latency.sending(sent, time.monotonic())
            pose = driver.poses.next()
            latency.seen(pose, time.monotonic())
            watch.remembered = max(8, latency.lag + 8)     # a late command still counts
            now = time.monotonic()
            if watch.stalled(pose, now):
                raise DrawingAborted(stall_diagnosis(driver, pose, latency))
            if deadline.passed(now, control.paused):
                driver.stop()
                raise DrawingAborted(deadline.says(driver.name, description, latency))
            command = executor.update(pose)
        driver.publish(STOP)
        rospy.loginfo('%s%s: end at %s', self.label, description, pose_text(driver.poses.latest))


def pose_text(pose):
    if pose is None:
        return '(no pose)'
    return f'x={pose.x:.4f} y={pose.y:.4f} theta={pose.theta:.4f}'
