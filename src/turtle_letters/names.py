"""Names beside a turtle's: turtlesim keeps its own services (spawn, kill,
clear), its other turtles and our parts of its canvas in the namespace that
holds the turtle's name."""
import re

import rosgraph.names
import rospy


def beside(turtle, name):
    """`name` in the namespace that holds the turtle's name (/spawn for turtle1 or /alice)."""
    return rosgraph.names.ns_join(rosgraph.names.namespace(rospy.resolve_name(turtle)), name)


def spare_name(name, number):
    """The spare turtle that draws character `number` (2, 3...) of a parallel word."""
    return f'{name}_{number}'


def spare_pose_pattern(turtle, name):
    """A regular expression for the pose topics of `name`'s spare turtles."""
    return re.escape(beside(turtle, spare_name(name, ''))) + r'([0-9]+)/pose$'
