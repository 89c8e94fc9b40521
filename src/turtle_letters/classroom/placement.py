"""Where our turtle draws on a shared turtlesim, and leaving it tidy.

The lab's turtle (turtle1, already there) has the whole canvas, from where
it stands. Any other turtle gets a part of the canvas of its own (parts.py,
claims.py) and is spawned there; a part our name left behind (a crash) is
taken back with its turtle and where its letters had got to. On the way out
the part is given back and the turtles we spawned are killed.
"""
import threading

import rospy

from ..letters.font import shown
from ..motion.driver import DrawingAborted, call_briefly
from .claims import Claims, Held
from .diagnosis import CONNECT_SECONDS, not_connected_diagnosis, spawn_refusal
from .parts import fits_a_line, free_place, letter_bounds, on_canvas, overlaps, part_box, text_width

LEAVE_SECONDS = 5.0     # s a shutdown waits for our hook at most (waited_at_most)
CLAIM_ATTEMPTS = 20


class Refused(DrawingAborted):
    """This controller cannot have a turtle or a place: it says why, and
    exits at start; later (a failed respawn) the drawing stops, no more."""


class Placement:
    def __init__(self, driver, settings, sheet):
        self.driver, self.settings, self.sheet = driver, settings, sheet
        self.claims = Claims(settings.turtle, driver.name)
        self.spawned = False        # we spawned our turtle: we kill it when we go
        self.placed = threading.Event()

    def make_room(self, turtle):
        """The canvas (or our part) is full. A shared canvas is never cleared:
        that would wipe everyone's drawing; the lab's is, by its turtle."""
        others = self.claims.others()
        if self.sheet.part is not None or others:
            rospy.loginfo("Turtle %s's part of the canvas is full: starting again at its first "
                          'place (the canvas is shared%s, so it is not cleared)', self.driver.name,
                          f' with {", ".join(sorted(others))}' if others else '')
            return
        rospy.loginfo('The canvas is full: clearing it and starting again at the first place')
        turtle.clear()

    def take_place(self):
        """Our turtle, found or spawned, and our place; raises Refused."""
        waited = self.driver.wait_for_simulator()
        try:
            left = self.claims.left_behind()
        except Held as e:
            raise Refused(f'turtle {self.driver.name} is already driven by {e}, which is alive; '
                          'give another name (turtle:= or name:=)') from None
        remove_spares_left_behind(self.driver, left)
        exists = self.driver.exists(wait=0.5)   # turtlesim offers spawn a moment before turtle1
        if exists and (left is None or left['whole_canvas']):
            self._adopt_for_the_lab(say_wait=not waited)
        else:
            self._take_a_part(left, exists)
        self.placed.set()

    def respawn_if_gone(self):
        """turtlesim came back without our turtle: it starts again at its part's
        first place. Until a spawn succeeds (else Refused), it is ours to spawn."""
        if self.spawned and not self.driver.exists():
            self.driver.poses.forget()
            self._spawn(self.sheet.part[0])

    def note_spares(self, names):
        """Our parallel word's spares, kept with our part: a restart removes these only."""
        self.claims.mark(spares=sorted(names))

    def note_cursor(self, chars):
        """A restart of ours carries on from where the next letter goes; the
        room's scoreboard grades the text being drawn, at its places
        (`chars`: (character, place) pairs)."""
        if self.sheet.part is not None:
            drawing = {'text': ''.join(c for c, _ in chars),
                       'places': [[float(v) for v in place] for _, place in chars]}
            self.claims.mark(cursor=[float(v) for v in self.sheet.cursor], drawing=drawing)

    def leave(self):
        """On shutdown (Ctrl-C, SIGTERM, the master's word): give the part
        back, and our turtle if we spawned it, unless a newcomer of our name
        has taken them over."""
        ours = self.claims.ours()
        self.claims.release()
        if self.spawned and ours:
            call_briefly(self.driver.kill)

    def _adopt_for_the_lab(self, say_wait):
        """The lab: the whole canvas from where the turtle stands. Its first
        letter's place is claimed so that no one spawns there."""
        s = self.settings
        self._connect()
        pose = self.driver.poses.wait(patience=None, say=say_wait)
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
        place, box = claim_a_part(self.claims, s, width, left)
        spawned = bool(left and left.get('spawned'))
        back = left is not None and list(place) == list(left['place'])
        if exists and not back:
            if not spawned:
                raise Refused(f'turtle {self.driver.name} stands in a part that is no longer free, '
                              'and it is not ours to move; give another name')
            call_briefly(self.driver.kill)     # ours, in a part now someone else's
            exists = False
        cursor = left.get('cursor') if back else None
        self.claims.claim(box, place, spawned=spawned or not exists, cursor=cursor)
        if exists:
            self.spawned = spawned
            self._connect()
            self.driver.poses.wait(patience=None)
        else:
            self._spawn(place)
        self.sheet.give_part(place, letter_bounds(box, s.size, s.font), cursor)
        rospy.loginfo('Turtle %s %s the part x %.2f-%.2f, y %.2f-%.2f of the canvas',
                      self.driver.name, 'takes back' if back else 'has', *box[0::2], *box[1::2])

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
        self.driver.poses.listen()
        if not self.driver.wait_connected(CONNECT_SECONDS):
            rospy.logwarn('%s', not_connected_diagnosis(self.driver))

def claim_a_part(claims, settings, width, left):
    """A part no live controller has, claimed: the part our name `left`
    behind if it is still free, else at ~x, ~y, else the first free one.
    Of controllers that want one place at once, one gets it (claims.take);
    the others look again."""
    s = settings
    for _ in range(CLAIM_ATTEMPTS):
        taken = claims.others()
        place, box = _choose(s, width, left, taken)
        try:
            rivals = claims.take(box, place)
        except rospy.ServiceException as e:
            raise Refused(f'the room would not grant a part: {e}') from None
        if not rivals:
            return place, box
        left = None
        if s.x is not None:
            raise Refused(f'~x {s.x:g}, ~y {s.y:g}: {rivals[0]} has just claimed a part '
                          'there; choose another place or give none')
    raise Refused('no part could be agreed on with the other controllers; try again')


def _choose(settings, width, left, taken):
    """(place, box) to ask for, given the live parts `taken`; raises Refused."""
    s = settings
    if left is not None and not any(overlaps(left['box'], b) for b in taken.values()):
        return tuple(left['place']), tuple(left['box'])
    if s.x is None:
        place = free_place(width, s.size, s.font, taken.values())
        if place is None:
            raise Refused(f'no free part of the canvas is left for letters of size '
                          f'{s.size:g} m ({len(taken)} turtles have one); try a smaller size:=')
        return place, part_box(place, width, s.size, s.font)
    place = (s.x, s.y)
    box = part_box(place, width, s.size, s.font)
    if not on_canvas(box, s.size, s.font):
        raise Refused(f'~x {s.x:g}, ~y {s.y:g}: letters of size {s.size:g} m '
                      'there would leave the canvas; choose another place')
    crossed = sorted(n for n, b in taken.items() if overlaps(box, b))
    if crossed:
        raise Refused(f'~x {s.x:g}, ~y {s.y:g}: the part there would cross that of '
                      f'{", ".join(crossed)}; choose another place or give none')
    return place, box


def remove_spares_left_behind(driver, left):
    """The spare turtles of a parallel word that a crash of ours left on the
    canvas: those our claim `left` behind records, and no other turtle."""
    for spare in (left or {}).get('spares', []):
        try:
            driver.kill(spare)
        except rospy.ServiceException:      # gone already, with an earlier turtlesim
            continue
        rospy.loginfo('Removed %s, a spare turtle left behind by an earlier run', spare)


def waited_at_most(hook, seconds=LEAVE_SECONDS):
    """`hook`, for rospy.on_shutdown, run on a thread of its own and waited
    for at most `seconds`: a master that stopped answering its calls
    holds the shutdown up no longer than that."""
    def run():
        leaving = threading.Thread(target=hook, name='leave')
        leaving.start()
        leaving.join(seconds)
    return run
