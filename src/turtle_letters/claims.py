"""Who draws where on a shared turtlesim: parts of the canvas claimed on the
parameter server, the one store every machine of a ROS system shares.

Each controller writes `<turtlesim's namespace>/turtle_letters/parts/<turtle>`
= {'node': its name, 'uri': its XML-RPC URI, 'box': [x0, y0, x1, y1],
'place': [x, y] (the part's first place), 'spawned': whether the controller
spawned the turtle, 'cursor': [x, y] (where its next letter goes)}.

A part is live while the node at its URI answers (liveness.py): a crashed
controller's part is free again within a second, and a controller that
restarts under the same turtle name finds its part, its turtle and its
cursor where it left them. The URI, not the name, says whose a claim is, so
a node that the master shut down for a newcomer of its name cannot take the
newcomer's claim with it.
"""
from concurrent.futures import ThreadPoolExecutor

import rosgraph.names
import rospy

from .driver import beside
from .liveness import answers


class Claims:
    def __init__(self, turtle, name):
        self.root = beside(turtle, 'turtle_letters/parts')
        self.key = rosgraph.names.ns_join(self.root, name)
        self.name = name

    def all(self):
        """{turtle: claim} as stored, live or not."""
        try:
            parts = rospy.get_param(self.root, {})
        except KeyError:
            return {}
        return {n: p for n, p in parts.items() if _well_formed(p)} if isinstance(parts, dict) \
            else {}

    def others(self):
        """{turtle: box} of the live parts other than ours."""
        parts = {n: p for n, p in self.all().items() if n != self.name}
        with ThreadPoolExecutor(max_workers=max(1, min(16, len(parts)))) as pool:
            alive = dict(zip(parts, pool.map(lambda p: answers(p.get('uri')) is not None,
                                            parts.values())))
        return {n: tuple(p['box']) for n, p in parts.items() if alive[n]}

    def left_behind(self):
        """Our turtle's claim if a controller that is no longer alive left it (we
        take its part over), or None. Raises Held if a live one has it."""
        part = self.all().get(self.name)
        if part is None or part.get('uri') == _own_uri() or 'place' not in part:
            return None
        if answers(part.get('uri')) is not None:
            raise Held(part['node'])
        return part

    def claim(self, box, place, spawned, whole_canvas=False, cursor=None):
        part = {'node': rospy.get_name(), 'uri': _own_uri(), 'box': [float(v) for v in box],
                'place': [float(v) for v in place], 'spawned': bool(spawned),
                'whole_canvas': bool(whole_canvas)}
        if cursor is not None:
            part['cursor'] = [float(v) for v in cursor]
        rospy.set_param(self.key, part)

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


def _own_uri():
    return rospy.get_node_uri()


def _well_formed(part):
    return (isinstance(part, dict) and isinstance(part.get('box'), list)
            and len(part['box']) == 4)
