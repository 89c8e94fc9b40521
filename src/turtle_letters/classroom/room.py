"""The room: the classroom's one authority for parts of the shared canvas.

classroom.launch starts it beside turtlesim. A controller asks it for a part
(`turtle_letters/claim_part`, turtle_letters/ClaimPart); it grants one at a
time, under one lock, so two controllers that want the same place at the
same instant can never both have it, however slow their links. The parts
stay on the parameter server (claims.py), where every controller reads them.
"""
import threading

import rosgraph
import rospy
from rosgraph.names import ns_join

from ..srv import ClaimPart, ClaimPartResponse
from .claims import PARTS, live, record, stored_parts
from .parts import contenders


class Room:
    def __init__(self):
        self.root = rospy.resolve_name(PARTS)
        self._lock = threading.Lock()
        rospy.Service('turtle_letters/claim_part', ClaimPart, self.on_claim)

    def on_claim(self, request):
        """Granted unless a live part of another turtle (or a live controller
        of this turtle other than the caller) crosses the box."""
        caller = request._connection_header['callerid']
        with self._lock:
            # one request at a time, and one master proxy per request (they are not thread-safe)
            uri = rosgraph.Master(rospy.get_name()).lookupNode(caller)
            parts = stored_parts(self.root)
            crossed = sorted(live(contenders(parts, request.turtle, uri, request.box)))
            if crossed:
                rospy.loginfo('%s asked for a part for %s that crosses that of %s: refused',
                              caller, request.turtle, ', '.join(crossed))
                return ClaimPartResponse(False, crossed)
            rospy.set_param(ns_join(self.root, request.turtle),
                            record(caller, uri, request.box, request.place, spawned=False))
            rospy.loginfo('The part x %.2f-%.2f, y %.2f-%.2f is now %s\'s (%s)',
                          *request.box[0::2], *request.box[1::2], request.turtle, caller)
            return ClaimPartResponse(True, [])


def main():
    rospy.init_node('turtle_letters_room')
    Room()
    rospy.loginfo('The room grants parts of the canvas: %s',
                  rospy.resolve_name('turtle_letters/claim_part'))
    rospy.spin()
