"""The turtle controller node: the lab's class, TurtleController.

From a trigger to a command: "P" on `chatter` (or a goal of the draw
action, actions/server.py) becomes a job (actions/jobs.py); the drawing
thread plans it in one place (letters/plan.py) and has its mode
(motion/modes.py) carry the plan out on the turtle (turtle.py). In timed
mode, the lab's N is the six calls of lab.py, run as they are written."""
import sys
import threading

import rospy
from std_msgs.msg import String

from .actions.jobs import TYPED_AHEAD, Jobs, chatter_request, text_request
from .actions.server import DrawServer, describe
from .classroom.diagnosis import why_stopped
from .classroom.liveness import refuse_a_second
from .classroom.placement import Placement, Refused, waited_at_most
from .classroom.spares import Spares, draw_in_parallel
from .letters.font import shown
from .letters.geometry import PlannedPose
from .letters.plan import SvgFile, plan_request
from .letters.sheet import Sheet
from .motion.control import Cancelled
from .motion.driver import DrawingAborted, TurtleDriver, init_node_shut_down_beside_main
from .motion.modes import MODES
from .settings import ParameterError, Settings, quote_unreadable
from .turtle import Turtle, pose_text

IGNORED_LOG_PERIOD = 10.0   # s: an ignored message is said once, then at most this often
THROTTLED = f' (said at most every {IGNORED_LOG_PERIOD:g} s)'


class TurtleController:
    """The lab's class. On the trigger ("P" on `chatter`) its turtle draws
    `~letter` (N: lab.draw_the_labs_n), in `~mode` (timed: the lab's rotate
    and move). Also draws `~text` and `~svg` (std_msgs/String), goals of the
    action `draw` and, in typing mode, every key. Parameters:
    settings.PARAMETERS."""

    def __init__(self, settings: Settings):
        self.settings = settings
        self.driver = TurtleDriver(settings.turtle)
        self.turtle = Turtle(self.driver, settings)
        self.sheet = Sheet(settings.size, settings.font)
        self.placement = Placement(self.driver, settings, self.sheet)
        self.spares = Spares(settings, self.driver.name, Turtle, self.placement.note_spares)
        self.jobs = Jobs()
        self.actions = DrawServer(self.jobs, settings.font)
        rospy.on_shutdown(waited_at_most(self.leave))
        rospy.Subscriber('chatter', String, self._on_chatter, queue_size=TYPED_AHEAD)
        rospy.Subscriber('~text', String, self._on_text, queue_size=10)
        rospy.Subscriber('~svg', String, lambda m: self.request(SvgFile(m.data), '~svg'),
                         queue_size=10)
        threading.Thread(target=self._work, name='drawing', daemon=True).start()
        if settings.text:
            self.request(settings.text, 'the ~text parameter')
        if settings.svg:
            self.request(SvgFile(settings.svg), 'the ~svg parameter')

    def _on_chatter(self, msg):
        s = self.settings
        kind, detail = chatter_request(msg.data, s.trigger, s.typing, s.font)
        if kind == 'trigger':
            self.request(s.letter, f'trigger {shown(msg.data)}')
        elif kind == 'key' and not self.jobs.offer_key(detail):
            rospy.logwarn_throttle(IGNORED_LOG_PERIOD, 'Key %r ignored: %d keys are already '
                                   'waiting' + THROTTLED, detail, self.jobs.typed_ahead)
        elif kind == 'ignored':
            rospy.loginfo_throttle(IGNORED_LOG_PERIOD, 'chatter %s ignored: %s' + THROTTLED,
                                   shown(msg.data), detail)

    def _on_text(self, msg):
        text, refusal = text_request(msg.data, self.settings.font)
        if refusal:
            rospy.logwarn('~text %s refused: %s', shown(msg.data), refusal)
        else:
            self.request(text, '~text')

    def request(self, text, source):
        """Draw `text` unless a drawing is waiting or under way (then it is ignored, not queued)."""
        if not self.jobs.offer(text):
            rospy.loginfo_throttle(IGNORED_LOG_PERIOD, '%s ignored: a drawing is waiting or '
                                   'under way' + THROTTLED, source)

    def leave(self):
        """On shutdown: the part given back, our turtles gone (placement.leave)."""
        self.placement.leave()
        self.spares.remove_all(closing=True)

    def _work(self):
        self.placement.placed.wait()
        for request in self.jobs.each(rospy.is_shutdown):
            self.actions.carry_out(request, self.draw, self._abandon)

    def draw(self, order):
        """Draw a text, or an SVG file, at the next free place on the canvas (or our part)."""
        self.placement.respawn_if_gone()
        pose = self.driver.poses.wait(cancelled=lambda: order.control.cancelled)
        start = PlannedPose(pose.x, pose.y, pose.theta)
        mark = self.sheet.mark()
        try:
            job = plan_request(order.request, self.sheet, start, self.settings, order.control.check)
            order.started(job)
        except Cancelled:       # before it began: it takes no place on the sheet
            self.sheet.undo(mark)
            raise
        self.placement.note_cursor(job.chars)
        if job.note:
            rospy.logwarn('%s', job.note)
        rospy.loginfo('Drawing %s', job.summary(self.settings))
        self.turtle.control = order.control
        if job.must_clear:
            self.placement.make_room(self.turtle)
        if job.letters:
            draw_in_parallel(self.turtle, self.spares, job, order.advanced)
        else:
            self.turtle.pen_down()
            MODES[self.settings.mode].carry_out(job.plan, self.turtle, order.advanced)
        return f'Done drawing {job.label}; the turtle is at {pose_text(self.driver.poses.latest)}'

    def _abandon(self, request, error):
        """Stop the turtle, and forget the layout and the pen: the simulator may
        come back with a fresh canvas, so the next drawing starts afresh."""
        self.driver.stop()
        self.sheet.forget()
        self.turtle.pen_is_down = False
        return (f'Drawing of {describe(request)} stopped: {why_stopped(error, self.driver)}. '
                'The next trigger starts a new one.')


def main():
    refuse_a_second('turtlebot_controller')
    init_node_shut_down_beside_main('turtlebot_controller', quote_unreadable(sys.argv))
    try:
        settings = Settings(rospy.get_param)
        controller = TurtleController(settings)
        controller.placement.take_place()
    except (ParameterError, Refused) as e:
        rospy.logfatal('%s: %s', rospy.get_name(), e)
        raise SystemExit(2)
    except rospy.ROSInterruptException:
        return
    except DrawingAborted:          # Ctrl-C while waiting for the turtle's first pose
        rospy.loginfo("Shut down before turtle %s's first pose came", settings.turtle)
        return
    rospy.loginfo('Ready: publish %r on %s to draw %r with turtle %s (%s mode)', settings.trigger,
                  rospy.resolve_name('chatter'), settings.letter, controller.driver.name,
                  settings.mode)
    rospy.spin()
