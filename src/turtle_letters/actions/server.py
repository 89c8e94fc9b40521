"""A drawing as a ROS action: the controller serves `draw`
(turtle_letters/Draw: goal, feedback, result, cancel) and the service
`pause` (std_srvs/SetBool), both in its namespace.

Every drawing is an Order, whatever asked for it: a goal of the action, or
a trigger, key or ~text (which have no goal: their end goes to the log
only). All of them go through the controller's one Jobs, so a goal sent
while anything else is drawn is refused at once, and pause works on any
drawing."""
import threading

import actionlib
import rospy
from std_srvs.srv import SetBool, SetBoolResponse

from ..letters.font import shown
from ..letters.layout import DoesNotFit
from ..letters.plan import SvgFile
from ..letters.svgart import SvgError
from ..motion.control import Cancelled, Control
from ..msg import DrawAction, DrawFeedback, DrawResult
from .jobs import goal_request
from .progress import Progress

FEEDBACK_PERIOD = 1.0       # s: feedback at least this often, and at each stroke


def describe(request):
    """A request as the log and the result say it."""
    return shown(request.path) if isinstance(request, SvgFile) else repr(request)


class Order:
    """One drawing from its request to its end; `handle` is its goal's, or None."""

    def __init__(self, request, handle=None):
        self.request, self.handle = request, handle
        # read now: actionlib takes its own lock to say it, and no call into
        # actionlib may be made under the server's (a cancel takes them the other way)
        self.goal_id = handle.get_goal_id().id if handle is not None else None
        self.control = Control()
        self.planned = None             # drawing.Planned, once planned
        self.progress = Progress(rospy.loginfo, now=self.control.clock)

    def started(self, planned):
        """Planned and about to move (unless it was cancelled while waiting)."""
        if self.control.cancelled:
            raise Cancelled('cancelled before it began')
        self.planned = planned
        self.progress = Progress(rospy.loginfo, planned.plan, now=self.control.clock)
        self.feedback()

    def advanced(self, ink_drawn, ink):
        """A line or stroke drawn: the log every few seconds, the goal's feedback now."""
        self.progress(ink_drawn, ink)
        self.feedback()

    def feedback(self):
        if self.handle is None or self.planned is None:
            return
        share, to_go, strokes = self.progress.report()
        self.handle.publish_feedback(DrawFeedback(
            progress=share, eta=to_go, stroke=strokes, strokes=len(self.planned.plan.strokes),
            paused=self.control.paused))

    def finished(self, drawn, message):
        """The end, said in the log (a cancel asked for is no error) and (a
        goal's) as its result."""
        (rospy.loginfo if drawn or self.control.cancelled else rospy.logerr)('%s', message)
        if self.handle is None:
            return
        plan = self.planned.plan if self.planned else None
        result = DrawResult(drawn=drawn, message=message,
                            seconds=self.control.clock() - self.progress.started,
                            ink=plan.ink if drawn else self.progress.ink_drawn,
                            travel=plan.travel if drawn else 0.0)
        if drawn:
            self.handle.set_succeeded(result, message)
        elif self.control.cancelled:
            self.handle.set_canceled(result, message)
        else:
            self.handle.set_aborted(result, message)


class DrawServer:
    """The `draw` action and the `pause` service of one controller."""

    def __init__(self, jobs, font):
        self.jobs, self.font = jobs, font
        self.current = None             # the Order being drawn
        self._lock = threading.Lock()
        self._orders = {}               # goal id -> Order, accepted and not ended
        self.server = actionlib.ActionServer('draw', DrawAction, self._on_goal, self._on_cancel,
                                             auto_start=False)
        rospy.Service('pause', SetBool, self._on_pause)
        rospy.Timer(rospy.Duration(FEEDBACK_PERIOD), lambda _: self._feedback())
        self.server.start()

    def begin(self, request):
        """The Order of a request the drawing thread takes."""
        order = request if isinstance(request, Order) else Order(request)
        with self._lock:
            self.current = order
        return order

    def carry_out(self, request, draw, abandon):
        """Draw a request the drawing thread took, with `draw(order)` (which
        says how it ended), and end it: the job done first, so that whoever
        hears the result can send the next goal at once. `abandon(request,
        error)` stops the turtle after a failure and says why."""
        order = self.begin(request)
        try:
            drawn, message = True, draw(order)
        except Cancelled as e:
            drawn, message = False, f'Drawing of {describe(order.request)} {e}'
        except (DoesNotFit, SvgError) as e:
            drawn, message = False, f'Refused: {e}'
        except Exception as e:  # whatever it was, the drawing thread must live on
            drawn, message = False, abandon(order.request, e)
        with self._lock:
            self.current = None
            self._orders.pop(order.goal_id, None)
        self.jobs.done()
        order.finished(drawn, message)

    def _feedback(self):
        order = self.current
        if order is not None:
            order.feedback()

    def _on_goal(self, handle):
        goal = handle.get_goal()
        request, why = goal_request(goal.text, goal.svg, self.font)
        if why is None:
            order = Order(request, handle)
            if self.jobs.offer(order, accept=lambda: self._accept(order)):
                return
            why = f'busy: {self._under_way()}; send it again once that has ended'
        rospy.logwarn('Goal refused: %s', why)
        handle.set_rejected(DrawResult(drawn=False, message=why), why)

    def _accept(self, order):
        with self._lock:
            self._orders[order.goal_id] = order
        order.handle.set_accepted(f'drawing {describe(order.request)}')

    def _under_way(self):
        order = self.current
        if order is None:
            return 'a drawing is about to start'
        return f'{describe(order.request)} is being drawn'

    def _on_cancel(self, handle):
        goal_id = handle.get_goal_id().id       # actionlib's lock, then ours: never the other way
        with self._lock:
            order = self._orders.get(goal_id)
        if order is not None:
            rospy.loginfo('Cancelling the drawing of %s', describe(order.request))
            order.control.cancel()

    def _on_pause(self, request):
        order = self.current
        if order is None:
            return SetBoolResponse(False, 'no drawing is under way')
        changed = order.control.pause(request.data)
        what = describe(order.request)
        if changed:
            message = f"{'paused' if request.data else 'resumed'} the drawing of {what}"
            rospy.loginfo('%s', message)
        else:
            message = f"the drawing of {what} {'was already' if request.data else 'was not'} paused"
        order.feedback()
        return SetBoolResponse(True, message)
