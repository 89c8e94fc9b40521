"""The turtle controller node: draws letters when it hears the trigger.

Pose messages are the clock: turtlesim publishes one per 16 ms tick, and the
drawing thread decides one command per pose it receives (sent when it
changes, see driver.py), so nothing ever waits in a loop of its own.

The drawing runs on its own thread, one primitive after the other, so that it
reads like the lab: rotate(90); move(3.0); ... Stepping a state machine from
the pose callback instead (as turtlesim's draw_square does) would need the
sequence cut into states; the thread keeps it a plain sequence.
"""
import math
import re
import sys
import threading
import time
import traceback

import rosgraph
import rospy
from std_msgs.msg import String

from .claims import Claims, Held
from .driver import DrawingAborted, TurtleDriver, beside
from .drawing import LetterDrawer
from .jobs import TYPED_AHEAD, Jobs
from .liveness import refuse_a_second
from .network import reach_advice
from .motion import EXECUTORS, STOP, SmoothExecutor, StallWatch, TimedExecutor
from .parts import fits_a_line, free_place, letter_bounds, on_canvas, overlaps, part_box, text_width
from .plan import DoesNotFit, Line, PlannedPose, Turn, shown, wrap
from .settings import ParameterError, Settings, quote_unreadable

# Ignored messages can come at any rate (the tutorial talker sends "hello
# world" at 10 Hz on chatter): the first is said, then one per period.
IGNORED_LOG_PERIOD = 10.0
THROTTLED = f' (said at most every {IGNORED_LOG_PERIOD:g} s)'
PROGRESS_PERIOD = 5.0       # s between two progress lines of a drawing
STALL_SECONDS = 1.0         # s a turtle may disobey before the drawing stops
CONNECT_SECONDS = 5.0       # s a new turtle's topics may take to connect
POSE_PATIENCE = 3.0         # s without a pose that turtlesim publishes: we cannot hear it
CLAIM_ATTEMPTS = 20


class Refused(RuntimeError):
    """This controller cannot have a turtle or a place: it says why and exits."""


class TurtleDrawer(LetterDrawer):
    """The lab's primitives on one turtle, through a TurtleDriver: the
    controller's own turtle, or a spare one of a parallel word."""

    def __init__(self, settings: Settings, driver: TurtleDriver, label=''):
        super().__init__(settings)
        self.driver = driver
        self.label = label          # said before each line of a spare turtle

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

    def pen(self, down):
        self.driver.set_pen(self.settings.pen, down)

    def draw_one(self, char, place):
        """One character at its place, from where the turtle stands (a parallel word's part)."""
        pose = self.driver.wait_for_pose()
        start = PlannedPose(pose.x, pose.y, pose.theta)
        self.trace(self.plan(char, [place], start), must_clear=False)

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
        """One command per pose until the executor is done, then a stop.
        A turtle that does not do as told for STALL_SECONDS stops the drawing."""
        driver = self.driver
        rospy.loginfo('%s%s: start at %s', self.label, description, _pose_text(driver.latest_pose))
        watch = StallWatch(STALL_SECONDS)
        command = executor.start(driver.latest_pose)
        while command is not None:
            driver.publish(command)
            watch.sent(command)
            pose = driver.next_pose()
            if watch.stalled(pose, time.monotonic()):
                raise DrawingAborted(stall_diagnosis(driver, pose))
            command = executor.update(pose)
        driver.publish(STOP)
        rospy.loginfo('%s%s: end at %s', self.label, description, _pose_text(driver.latest_pose))


class TurtleController(TurtleDrawer):
    """The lab's class. Subscribes `chatter` (the trigger, or typed keys) and
    `~text` (std_msgs/String: a word to draw); drives the turtle `~turtle`
    through a TurtleDriver, spawning it if turtlesim has none of that name.
    Parameters: see settings.PARAMETERS."""

    def __init__(self, settings: Settings):
        super().__init__(settings, TurtleDriver(settings.turtle))
        self.jobs = Jobs()
        self.claims = Claims(settings.turtle, self.driver.name)
        self.spawned = False            # we spawned our turtle: we kill it when we go
        self._spares = []               # a parallel word's spare turtles, while they live
        self._placed = threading.Event()
        self._started = self._last_progress = 0.0
        rospy.on_shutdown(self._leave)
        rospy.Subscriber('chatter', String, self._on_chatter, queue_size=TYPED_AHEAD)
        rospy.Subscriber('~text', String, self._on_text, queue_size=10)
        self._worker = threading.Thread(target=self._work, name='drawing', daemon=True)
        self._worker.start()
        if settings.text:
            self.request(settings.text, 'the ~text parameter')

    # -- the turtle and its place ---------------------------------------------
    def take_place(self):
        """Find our turtle, or spawn it at a place of its own; then drawings
        may start. A part our name left behind (a crash) is taken back with
        its turtle and where its letters had got to. Raises Refused."""
        waited = self._wait_for_simulator()
        try:
            left = self.claims.left_behind()
        except Held as e:
            raise Refused(f'turtle {self.driver.name} is already driven by {e}, which is alive; '
                          'give another name (turtle:= or name:=)') from None
        self._remove_spares_left_behind()
        exists = self.driver.exists(wait=0.5)   # turtlesim offers spawn a moment before turtle1
        if exists and (left is None or left['whole_canvas']):
            self._adopt_for_the_lab(say_wait=not waited)
        else:
            self._take_a_part(left, exists)
        self._placed.set()

    def _adopt_for_the_lab(self, say_wait):
        """The lab: the whole canvas from where the turtle stands. Its first
        letter's place is claimed so that no one spawns there."""
        s = self.settings
        self._connect()
        pose = self.driver.wait_for_pose(say=say_wait)
        if s.x is not None:
            rospy.logwarn('Turtle %s already exists: ~x and ~y are ignored; its first letter '
                          'starts where it stands', self.driver.name)
        place = (pose.x, pose.y)
        self.claims.claim(part_box(place, s.font.widest, s.size, s.font), place, spawned=False,
                          whole_canvas=True)

    def _take_a_part(self, left, exists):
        """A part of our own: the one our name left behind if it is still
        free, else a new one; our turtle is spawned there (or kept there)."""
        s = self.settings
        width = text_width(s.text, s.font)
        if not fits_a_line(width, s.size, s.font):
            raise Refused(f'~text {shown(s.text)} ({len(s.text)} characters) is wider than the '
                          f'canvas at size {s.size:g} m; give a shorter text or a smaller size:=')
        place, box = self._claim_a_part(width, left)
        spawned = bool(left and left.get('spawned'))
        back = left is not None and list(place) == list(left['place'])
        if exists and not back:
            if not spawned:
                raise Refused(f'turtle {self.driver.name} stands in a part that is no longer free, '
                              'and it is not ours to move; give another name')
            _call_briefly(self.driver.kill)     # ours, in a part now someone else's
            exists = False
        cursor = left.get('cursor') if back else None
        self.claims.claim(box, place, spawned=spawned or not exists, cursor=cursor)
        if exists:
            self.spawned = spawned
            self._connect()
            self.driver.wait_for_pose()
        else:
            self._spawn(place)
        self.part = (place, letter_bounds(box, s.size, s.font))
        if cursor:
            self.resume_at = tuple(cursor)
        rospy.loginfo('Turtle %s %s the part x %.2f-%.2f, y %.2f-%.2f of the canvas',
                      self.driver.name, 'takes back' if back else 'has', *box[0::2], *box[1::2])

    def _remove_spares_left_behind(self):
        """Spare turtles of a parallel word that a crash of ours left on the canvas."""
        for spare in spares_on_canvas(self.driver, self.claims):
            rospy.loginfo('Removing %s, a spare turtle left behind by an earlier run', spare)
            _call_briefly(lambda n=spare: self.driver.kill_named(n))

    def _wait_for_simulator(self):
        """Whether we had to wait (and said so)."""
        spawn = self.driver.spawn_service
        try:
            rospy.wait_for_service(spawn, timeout=2.0)
            return False
        except rospy.ROSException:
            rospy.loginfo('Waiting for turtlesim: no %s service yet; drawings start when it comes',
                          spawn)
            rospy.wait_for_service(spawn)
            return True

    def _claim_a_part(self, width, left=None):
        """A part no live controller has, claimed: the part our name `left`
        behind if it is still free, else at ~x, ~y, else the first free one.
        Of controllers that want one place at once, one gets it (claims.take);
        the others look again."""
        s = self.settings
        for _ in range(CLAIM_ATTEMPTS):
            taken = self.claims.others()
            if left is not None and not any(overlaps(left['box'], b) for b in taken.values()):
                place, box = tuple(left['place']), tuple(left['box'])
            elif s.x is not None:
                place = (s.x, s.y)
                box = part_box(place, width, s.size, s.font)
                if not on_canvas(box, s.size, s.font):
                    raise Refused(f'~x {s.x:g}, ~y {s.y:g}: letters of size {s.size:g} m '
                                  'there would leave the canvas; choose another place')
            else:
                place = free_place(width, s.size, s.font, taken.values())
                if place is None:
                    raise Refused(f'no free part of the canvas is left for letters of size '
                                  f'{s.size:g} m ({len(taken)} turtles have one); '
                                  'try a smaller size:=')
                box = part_box(place, width, s.size, s.font)
            crossed = sorted(n for n, b in taken.items() if overlaps(box, b))
            if crossed:
                raise Refused(f'~x {s.x:g}, ~y {s.y:g}: the part there would cross that of '
                              f'{", ".join(crossed)}; choose another place or give none')
            try:
                rivals = self.claims.take(box, place)
            except rospy.ServiceException as e:
                raise Refused(f'the room would not grant a part: {e}') from None
            if not rivals:
                return place, box
            left = None
            if s.x is not None:
                raise Refused(f'~x {s.x:g}, ~y {s.y:g}: {rivals[0]} has just claimed a part '
                              'there; choose another place or give none')
        raise Refused('no part could be agreed on with the other controllers; try again')

    def _spawn(self, place):
        try:
            self.driver.spawn(place[0], place[1], 0.0)
        except rospy.ServiceException as e:
            raise Refused(spawn_refusal(self.driver, e)) from None
        self.spawned = True
        rospy.loginfo('Spawned turtle %s at x=%.2f y=%.2f, facing +x', self.driver.name, *place)
        self._connect()

    def _connect(self):
        """Listen to our turtle; say what to check if its topics do not connect."""
        self.driver.listen()
        if not self.driver.wait_connected(CONNECT_SECONDS):
            rospy.logwarn('%s', not_connected_diagnosis(self.driver))

    def _leave(self):
        """On shutdown (Ctrl-C, SIGTERM, the master's word): give the part
        back, and the turtles we spawned, unless a newcomer of our name has
        taken them over."""
        ours = self.claims.ours()
        self.claims.release()
        if self.spawned and ours:
            _call_briefly(self.driver.kill)
        for spare in list(self._spares):
            _remove_spare(spare)

    # -- requests --------------------------------------------------------------
    def _on_chatter(self, msg):
        data = msg.data
        said = shown(data)
        if self.settings.typing:
            font = self.settings.font
            if data == ' ' or (len(data) == 1 and font.glyph(data) is not None):
                self.type_key(data if font.case_sensitive else data.upper())
            else:
                rospy.loginfo_throttle(IGNORED_LOG_PERIOD, 'chatter %s ignored: typing mode draws '
                                       'single letters or digits' + THROTTLED, said)
        elif data == self.settings.trigger:
            self.request(self.settings.letter, f'trigger {said}')
        else:
            rospy.loginfo_throttle(IGNORED_LOG_PERIOD, 'chatter %s ignored: the trigger is %r'
                                   + THROTTLED, said, self.settings.trigger)

    def _on_text(self, msg):
        font = self.settings.font
        text = msg.data if font.case_sensitive else msg.data.upper()
        if not text.strip() or font.undrawable(text):
            rospy.logwarn('~text %s refused: font %s has no glyph for %s', shown(msg.data),
                          font.name, font.undrawable(text)[:10] or 'a blank text')
            return
        self.request(text, '~text')

    def request(self, text, source):
        """Draw `text` unless a drawing is waiting or under way (then it is ignored, not queued)."""
        if not self.jobs.offer(text):
            rospy.loginfo_throttle(IGNORED_LOG_PERIOD, '%s ignored: a drawing is waiting or '
                                   'under way' + THROTTLED, source)

    def type_key(self, char):
        """Typing mode: like a typewriter, keys typed ahead wait their turn."""
        if not self.jobs.offer_key(char):
            rospy.logwarn_throttle(IGNORED_LOG_PERIOD, 'Key %r ignored: %d keys are already '
                                   'waiting' + THROTTLED, char, self.jobs.typed_ahead)

    def progress(self, ink_drawn, ink):
        """Every few seconds of a drawing: how far it is, and how long to go."""
        now = time.monotonic()
        if now - self._last_progress < PROGRESS_PERIOD or not 0 < ink_drawn < ink - 1e-6:
            return
        self._last_progress = now
        elapsed = now - self._started
        rospy.loginfo('%.0f%% of the ink drawn (%.2f of %.2f m); about %.0f s to go',
                      100 * ink_drawn / ink, ink_drawn, ink, elapsed * (ink - ink_drawn) / ink_drawn)

    def clear(self):
        """The canvas (or our part) is full. A shared canvas is never cleared:
        that would wipe everyone's drawing."""
        others = self.claims.others()
        if self.part is not None or others:
            rospy.loginfo("Turtle %s's part of the canvas is full: starting again at its first "
                          'place (the canvas is shared%s, so it is not cleared)', self.driver.name,
                          f' with {", ".join(sorted(others))}' if others else '')
            return
        rospy.loginfo('The canvas is full: clearing it and starting again at the first place')
        self.driver.clear()

    # -- the drawing thread ----------------------------------------------------
    def _work(self):
        self._placed.wait()
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
        if self.spawned and not self.driver.exists():
            self._respawn()
        pose = self.driver.wait_for_pose(patience=POSE_PATIENCE)
        start = PlannedPose(pose.x, pose.y, pose.theta)
        places, must_clear = self.reserve(text, start)
        if self.part is not None:   # a restart of ours carries on from here
            self.claims.mark(cursor=[float(v) for v in self.cursor])
        if self.settings.parallel and sum(p is not None for p in places) > 1:
            self._draw_parallel(text, places, must_clear, start)
            return
        plan = self.plan(text, places, start)
        rospy.loginfo('Drawing %r (%s mode): ink %.2f m, travel %.2f m, about %.0f s', text,
                      self.settings.mode, plan.ink, plan.travel, plan.seconds)
        self._started = self._last_progress = time.monotonic()
        self.trace(plan, must_clear)
        rospy.loginfo('Done drawing %r; the turtle is at %s', text,
                      _pose_text(self.driver.latest_pose))

    def _respawn(self):
        """turtlesim came back without our turtle: it starts again at its part's first place."""
        self.driver.forget_poses()
        self.spawned = False
        self._spawn(self.part[0])

    def _draw_parallel(self, text, places, must_clear, start):
        """One turtle per character, all at once: ours draws the first, a
        spare turtle spawned at each other character's place draws that one."""
        chars = [(c, p) for c, p in zip(text, places) if p is not None]
        rospy.loginfo('Drawing %r in parallel: %d turtles (%s mode)', text, len(chars),
                      self.settings.mode)
        if must_clear:
            self.clear()
        spares = self._spares
        try:
            for number, (char, place) in enumerate(chars[1:], 2):
                spares.append(self._spare_turtle(number, place))
            drawers = [self] + spares
            self._started = self._last_progress = time.monotonic()
            errors = _all_at_once([lambda d=d, c=c, p=p: d.draw_one(c, p)
                                   for d, (c, p) in zip(drawers, chars)])
            if errors:
                raise errors[0]
        finally:
            while spares:
                _remove_spare(spares.pop())
        rospy.loginfo('Done drawing %r; the turtle is at %s', text,
                      _pose_text(self.driver.latest_pose))

    def _spare_turtle(self, number, place):
        driver = TurtleDriver(beside(self.settings.turtle, f'{self.driver.name}_{number}'))
        try:
            driver.spawn(place[0], place[1], 0.0)
        except rospy.ServiceException as e:
            driver.close()
            raise DrawingAborted(spawn_refusal(driver, e, 'the spare turtle ')) from None
        driver.listen()
        spare = TurtleDrawer(self.settings, driver, label=f'{driver.name}: ')
        if not driver.wait_connected(CONNECT_SECONDS):
            _remove_spare(spare)
            raise DrawingAborted(not_connected_diagnosis(driver))
        return spare

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


def _remove_spare(spare):
    """A spare turtle stops, leaves the canvas, and lets go of its topics."""
    spare.driver.stop()
    _call_briefly(spare.driver.kill)
    spare.driver.close()


def spares_on_canvas(driver, claims):
    """Turtles named like our parallel words' spares (NAME_2, NAME_3...) that
    no live controller claims: an earlier run of ours left them."""
    prefix = beside(driver.turtle, driver.name + '_')
    pattern = re.compile(re.escape(prefix) + r'([0-9]+)/pose$')
    try:
        topics = rosgraph.Master(rospy.get_name()).getPublishedTopics('')
    except Exception:  # the master is gone: nothing to tidy
        return []
    spares = {f'{driver.name}_{m.group(1)}' for t, _ in topics for m in [pattern.match(t)] if m}
    return sorted(spares - set(claims.others()))


def spawn_refusal(driver, error, what=''):
    """Why turtlesim would not spawn a turtle, in words (the real one says b'')."""
    if driver.exists():
        return (f'turtlesim would not spawn {what}{driver.name}: a turtle of that name is '
                'on the canvas already')
    return f'turtlesim would not spawn {what}{driver.name}: {error}'


def _all_at_once(calls):
    """Run the calls on threads of their own; the exceptions they raised."""
    errors = []

    def run(call):
        try:
            call()
        except Exception as e:  # handed to the drawing thread
            errors.append(e)
    threads = [threading.Thread(target=run, args=(c,), daemon=True) for c in calls]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return errors


def _call_briefly(call, timeout=2.0):
    """A service call that must not hold up a shutdown: at most `timeout` s."""
    thread = threading.Thread(target=lambda: _quietly(call), daemon=True)
    thread.start()
    thread.join(timeout)


def _quietly(call):
    try:
        call()
    except Exception:   # the turtle or turtlesim is gone already: nothing to undo
        pass


def stall_diagnosis(driver, pose):
    """What was seen when a turtle did not move as commanded, and what to check."""
    linear_x, linear_y, angular = driver.commanded
    seen = (f'turtle {driver.name} did not move as commanded for {STALL_SECONDS:g} s although '
            f'its poses arrive: it moves at {pose.linear_velocity:.2f} m/s and '
            f'{pose.angular_velocity:.2f} rad/s, we command {math.hypot(linear_x, linear_y):.2f} '
            f'm/s and {angular:.2f} rad/s on {driver.cmd_vel_topic}')
    others = _other_publishers(driver.cmd_vel_topic)
    if others:
        return f'{seen}; {", ".join(others)} publish there too: only one node may drive a turtle'
    if driver.cmd_vel_connections() == 0:
        return f'{seen}; turtlesim has not connected to it. {reach_advice()}'
    return f'{seen}; turtlesim hears it: check the remaps of cmd_vel and pose'


def not_connected_diagnosis(driver):
    if driver.cmd_vel_connections():
        return (f'no pose of turtle {driver.name} reached us on {driver.pose_topic} within '
                f'{CONNECT_SECONDS:g} s, although turtlesim publishes them. {reach_advice()}')
    return (f'turtlesim has not connected to {driver.cmd_vel_topic} within {CONNECT_SECONDS:g} s, '
            f'so turtle {driver.name} will not move. {reach_advice()}')


def _other_publishers(topic):
    try:
        publishers, _, _ = rosgraph.Master(rospy.get_name()).getSystemState()
    except Exception:  # the master is gone: nothing more to say
        return []
    return [n for t, nodes in publishers if t == topic for n in nodes if n != rospy.get_name()]


def _describe(primitive):
    if isinstance(primitive, Turn):
        return f'rotate {math.degrees(primitive.angle):.1f} deg'
    return f'move {primitive.length:.3f} m'


def _pose_text(pose):
    if pose is None:
        return '(no pose)'
    return f'x={pose.x:.4f} y={pose.y:.4f} theta={pose.theta:.4f}'


def main():
    refuse_a_second('turtlebot_controller')
    rospy.init_node('turtlebot_controller', argv=quote_unreadable(sys.argv))
    try:
        settings = Settings(rospy.get_param)
    except ParameterError as e:
        rospy.logfatal('%s: %s', rospy.get_name(), e)
        raise SystemExit(2)
    controller = TurtleController(settings)
    try:
        controller.take_place()
    except Refused as e:
        rospy.logfatal('%s: %s', rospy.get_name(), e)
        raise SystemExit(2)
    except rospy.ROSInterruptException:
        return
    rospy.loginfo('Ready: publish %r on %s to draw %r with turtle %s (%s mode)', settings.trigger,
                  rospy.resolve_name('chatter'), settings.letter, controller.driver.name,
                  settings.mode)
    rospy.spin()
