"""Who draws where on a shared turtlesim: parts of the canvas claimed on the
parameter server, the one store every machine of a ROS system shares.

Each controller writes `<turtlesim's namespace>/turtle_letters/parts/<turtle>`
= {'node': its node name, 'box': [x0, y0, x1, y1]}. A part whose node is no
longer known to the master is free again, so a controller that died does not
keep its place.
"""
import rosgraph
import rosgraph.names
import rospy

from .driver import beside


class Claims:
    def __init__(self, turtle, name):
        self.root = beside(turtle, 'turtle_letters/parts')
        self.key = rosgraph.names.ns_join(self.root, name)
        self.name = name
        self._master = rosgraph.Master(rospy.get_name())

    def others(self):
        """{turtle: box} of the live parts other than ours."""
        try:
            parts = rospy.get_param(self.root, {})
        except KeyError:
            return {}
        live = {}
        for name, part in parts.items() if isinstance(parts, dict) else ():
            if name != self.name and self._alive(part):
                live[name] = tuple(part['box'])
        return live

    def holder(self):
        """The live node other than this one that claims our turtle, if any."""
        part = rospy.get_param(self.key, None)
        if part and part.get('node') != rospy.get_name() and self._alive(part):
            return part['node']
        return None

    def claim(self, box):
        rospy.set_param(self.key, {'node': rospy.get_name(), 'box': [float(v) for v in box]})

    def release(self):
        """Give the part back, unless someone else has claimed it since."""
        try:
            if rospy.get_param(self.key, {}).get('node') == rospy.get_name():
                rospy.delete_param(self.key)
        except (KeyError, OSError, rospy.ROSException):
            pass

    def _alive(self, part):
        try:
            self._master.lookupNode(part['node'])
            return True
        except (rosgraph.MasterError, KeyError, TypeError):
            return False
