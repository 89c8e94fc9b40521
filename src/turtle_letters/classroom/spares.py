"""A word drawn by one turtle per character, all at once: ours draws the
first character, and a spare turtle spawned at each other character's place
draws that one. The spares die with their word on every path: done, failed,
or the node shutting down (Controller.leave); a crash leaves them to the
next start (placement.spares_on_canvas)."""
import threading

import rospy

from ..letters.geometry import PlannedPose
from ..letters.plan import plan_text
from ..motion.driver import DrawingAborted, TurtleDriver, beside, call_briefly
from ..motion.modes import MODES
from .diagnosis import CONNECT_SECONDS, not_connected_diagnosis, spawn_refusal
from .names import spare_name


class Spares:
    """The spare turtles of the word being drawn, while they live; each a
    `Turtle` (turtle.Turtle, the controller's own kind) on a driver of its own."""

    def __init__(self, settings, name, Turtle):
        self.settings, self.name, self.Turtle = settings, name, Turtle
        self.live = []

    def spawn(self, number, place):
        driver = TurtleDriver(beside(self.settings.turtle, spare_name(self.name, number)))
        try:
            driver.spawn(place[0], place[1], 0.0)
        except rospy.ServiceException as e:
            driver.close()
            raise DrawingAborted(spawn_refusal(driver, e, 'the spare turtle ')) from None
        spare = self.Turtle(driver, self.settings, label=f'{driver.name}: ')
        self.live.append(spare)
        driver.poses.listen()
        if not driver.wait_connected(CONNECT_SECONDS):
            raise DrawingAborted(not_connected_diagnosis(driver))
        return spare

    def remove_all(self):
        """Each stops, leaves the canvas, and lets go of its topics."""
        while self.live:
            spare = self.live.pop()
            spare.driver.stop()
            call_briefly(spare.driver.kill)
            spare.driver.close()


def draw_in_parallel(turtle, spares, chars):
    """`chars`: (character, place) pairs; `turtle` draws the first. The
    spares obey the same pause and cancel as `turtle`."""
    try:
        helpers = [spares.spawn(number, place) for number, (_, place) in enumerate(chars[1:], 2)]
        for helper in helpers:
            helper.control = turtle.control
        errors = _all_at_once([lambda t=t, c=c, p=p: draw_one(t, c, p)
                               for t, (c, p) in zip([turtle] + helpers, chars)])
        if errors:
            raise errors[0]
    finally:
        spares.remove_all()


def draw_one(turtle, char, place):
    """One character at its place, from where the turtle stands."""
    pose = turtle.driver.poses.wait(cancelled=lambda: turtle.control.cancelled)
    plan = plan_text(char, [place], PlannedPose(pose.x, pose.y, pose.theta), turtle.settings)
    turtle.pen_down()
    MODES[turtle.settings.mode].carry_out(plan, turtle, lambda drawn, ink: None)


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
