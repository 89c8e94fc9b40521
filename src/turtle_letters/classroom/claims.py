"""Who draws where on a shared turtlesim: parts of the canvas claimed on the
parameter server, the one store every machine of a ROS system shares.

Each controller writes `<turtlesim's namespace>/turtle_letters/parts/<turtle>`
= {'node': its name, 'uri': its XML-RPC URI, 'box': [x0, y0, x1, y1],
'place': [x, y] (the part's first place), 'spawned': whether the controller
spawned the turtle, 'cursor': [x, y] (where its next letter goes),
'drawing': {'text': ..., 'places': [[x, y], ...]} (the text drawn last, for
the scoreboard)}.

A part is live while the node at its URI answers (liveness.py): a crashed
controller's part is free again within a second, and a controller that
restarts under the same turtle name finds its part, its turtle and its
cursor where it left them. The URI, not the name, says whose a claim is, so
a node that the master shut down for a newcomer of its name cannot take the
newcomer's claim with it.
"""
import time
from concurrent.futures import ThreadPoolExecutor

import rosgraph
import rosgraph.names
import rospy

from ..motion.driver import beside
from .liveness import answers
from .parts import overlaps

# The parts' parameters, beside turtlesim (in its namespace): Claims finds
# them beside its turtle; the room and the scoreboard, started beside
# turtlesim, in their own namespace.
PARTS = 'turtle_letters/parts'
SETTLE_SECONDS = 0.3    # without a room: for controllers that chose at once to see each other


class Claims:
    """Our turtle's part, and the others', on the parameter server. New parts
    are granted by the room (room.py) where classroom.launch started one;
    elsewhere by the older protocol: write, wait, re-read, the lower name wins."""

    def __init__(self, turtle, name):
        self.root = beside(turtle, PARTS)
        self.key = rosgraph.names.ns_join(self.root, name)
        self.name = name
        self.room = beside(turtle, 'turtle_letters/claim_part')

    def all(self):
        """{turtle: claim} as stored, live or not."""
        return stored_parts(self.root)

    def others(self):
        """{turtle: box} of the live parts other than ours."""
        parts = {n: p for n, p in self.all().items() if n != self.name}
        return {n: tuple(parts[n]['box']) for n in live(parts)}

    def left_behind(self):
        """Our turtle's claim if a controller that is no longer alive left it (we
        take its part over), or None. Raises Held if a live one has it."""
        part = self.all().get(self.name)
        if part is None or part.get('uri') == _own_uri() or 'place' not in part:
            return None
        if answers(part.get('uri')) is not None:
            raise Held(part['node'])
        return part

    def take(self, box, place):
        """Claim the part `box` unless a live part crosses it: the turtles
        whose parts it crosses ([] when it is ours now)."""
        if self.has_room():
            from ..srv import ClaimPart     # generated: only where the package is built
            answer = rospy.ServiceProxy(self.room, ClaimPart)(
                turtle=self.name, box=list(box), place=list(place))
            return [] if answer.granted else list(answer.crossed)
        self.claim(box, place, spawned=False)
        time.sleep(SETTLE_SECONDS)
        rivals = sorted(n for n, b in self.others().items() if overlaps(box, b) and n < self.name)
        if rivals:
            self.release()
        return rivals

    def has_room(self):
        try:
            rosgraph.Master(rospy.get_name()).lookupService(self.room)
            return True
        except (rosgraph.MasterError, OSError):
            return False

    def claim(self, box, place, spawned, whole_canvas=False, cursor=None):
        rospy.set_param(self.key, record(rospy.get_name(), _own_uri(), box, place, spawned,
                                         whole_canvas, cursor))

    def mark(self, **fields):
        """Change fields of our claim (the cursor, say), if it is still ours."""
        if self.ours():
            rospy.set_param(self.key, dict(rospy.get_param(self.key), **fields))

    def ours(self):
        try:
            return rospy.get_param(self.key, {}).get('uri') == _own_uri()
        except (KeyError, OSError, rospy.ROSException, AttributeError):
            return False

    def release(self):
        """Give the part back, unless someone else has claimed it since."""
        try:
            if self.ours():
                rospy.delete_param(self.key)
        except (KeyError, OSError, rospy.ROSException):
            pass


class Held(RuntimeError):
    """A live controller has this turtle already."""


def record(node, uri, box, place, spawned, whole_canvas=False, cursor=None):
    """A claim as stored on the parameter server."""
    part = {'node': node, 'uri': uri, 'box': [float(v) for v in box],
            'place': [float(v) for v in place], 'spawned': bool(spawned),
            'whole_canvas': bool(whole_canvas)}
    if cursor:
        part['cursor'] = [float(v) for v in cursor]
    return part


def stored_parts(root):
    try:
        parts = rospy.get_param(root, {})
    except KeyError:
        return {}
    if not isinstance(parts, dict):
        return {}
    return {n: p for n, p in parts.items() if _well_formed(p)}


def live(parts):
    """The names among {turtle: claim} whose controllers answer, asked all at once."""
    if not parts:
        return set()
    with ThreadPoolExecutor(max_workers=min(16, len(parts))) as pool:
        alive = pool.map(lambda p: answers(p.get('uri')) is not None, parts.values())
        return {name for name, yes in zip(parts, alive) if yes}


def _own_uri():
    return rospy.get_node_uri()


def _well_formed(part):
    return (isinstance(part, dict) and isinstance(part.get('box'), list)
            and len(part['box']) == 4)
