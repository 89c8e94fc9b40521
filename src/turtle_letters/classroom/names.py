"""The names of a parallel word's spare turtles: beside the turtle's own
name (motion.driver.beside), in turtlesim's namespace."""
import re

from ..motion.driver import beside


def spare_name(name, number):
    """The spare turtle that draws character `number` (2, 3...) of a parallel word."""
    return f'{name}_{number}'


def spare_pose_pattern(turtle, name):
    """A regular expression for the pose topics of `name`'s spare turtles."""
    return re.escape(beside(turtle, spare_name(name, ''))) + r'([0-9]+)/pose$'
