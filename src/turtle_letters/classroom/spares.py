"""A word drawn by one turtle per character, all at once: ours draws the
first character, and a spare turtle spawned at each other character's place
draws that one. The spares die with their word on every path: done, failed,
or the node shutting down (Controller.leave); a crash leaves them to the
next start, which removes those recorded with its part
(placement.remove_spares_left_behind)."""
import threading

import rospy

from ..motion.driver import DrawingAborted, TurtleDriver, beside, call_briefly
from ..motion.modes import MODES
from .diagnosis import CONNECT_SECONDS, not_connected_diagnosis, spawn_refusal
from .names import spare_name


class Spares:
    """The spare turtles of the word being drawn, while they live; each a
    `Turtle` (turtle.Turtle, the controller's own kind) on a driver of its own."""

    def __init__(self, settings, name, Turtle, note=lambda names: None):
        """`note(names)` hears the names of the spares alive, each time they change."""
        self.settings, self.name, self.Turtle, self.note = settings, name, Turtle, note
        self.live = []
        self._lock = threading.Lock()     # the drawing thread and the shutdown hook's
        self._closed = False              # the node is shutting down: no more spares

    def spawn(self, number, place):
        driver = TurtleDriver(beside(self.settings.turtle, spare_name(self.name, number)))
        with self._lock:    # noted before it exists: a kill mid-spawn leaves it on record
            self.note([s.driver.name for s in self.live] + [driver.name])
        try:
            driver.spawn(place[0], place[1], 0.0)
        except rospy.ServiceException as e:
            with self._lock:
                self.note([s.driver.name for s in self.live])
            driver.close()
            raise DrawingAborted(spawn_refusal(driver, e, 'the spare turtle ')) from None
        spare = self.Turtle(driver, self.settings, label=f'{driver.name}: ')
        with self._lock:
            self.live.append(spare)
            closed = self._closed
        if closed:                      # spawned while the node shut down
            self.remove_all()
            raise DrawingAborted('shutting down')
        driver.poses.listen()
        if not driver.wait_connected(CONNECT_SECONDS):
            raise DrawingAborted(not_connected_diagnosis(driver))
        return spare

    def remove_all(self, closing=False):
        """Each stops, leaves the canvas, and lets go of its topics; once
        `closing` (the node shuts down), a spare spawned later goes too."""
        with self._lock:
            spares, self.live = self.live, []
            self._closed = self._closed or closing
        if spares and not closing:
            self.note([])
        for spare in reversed(spares):
            spare.driver.stop()
            call_briefly(spare.driver.kill)
            spare.driver.close()


def draw_in_parallel(turtle, spares, planned, progress):
    """`planned` (letters/plan.Planned): a word's characters and each one's
    plan; `turtle` draws the first. The spares obey the same pause and
    cancel as `turtle`; `progress(ink_drawn, ink)` hears the whole word's."""
    try:
        helpers = [spares.spawn(number, place)
                   for number, (_, place) in enumerate(planned.chars[1:], 2)]
        for helper in helpers:
            helper.control = turtle.control
        told = _Inks(len(planned.letters), planned.plan.ink, progress)
        turtles = [turtle] + helpers
        errors = _all_at_once([lambda t=t, p=p, i=i: draw_one(t, p, told.by(i))
                               for i, (t, p) in enumerate(zip(turtles, planned.letters))])
        if errors:
            raise errors[0]
    finally:
        spares.remove_all()


def draw_one(turtle, plan, progress):
    """One character's plan, by its own turtle."""
    turtle.pen_down()
    MODES[turtle.settings.mode].carry_out(plan, turtle, progress)


class _Inks:
    """Each turtle's ink, told to `progress` as the word's (one at a time)."""

    def __init__(self, turtles, ink, progress):
        self.drawn, self.ink, self.progress = [0.0] * turtles, ink, progress
        self._lock = threading.Lock()

    def by(self, i):
        def told(drawn, _):
            with self._lock:
                self.drawn[i] = drawn
                self.progress(sum(self.drawn), self.ink)
        return told


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
