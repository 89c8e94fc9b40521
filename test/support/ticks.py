"""Ticks of a turtlesim as the viewer hears them, for its unit tests. No ROS here."""


def drive(trails, name, points, colour):
    """A tick per point: the pose, then the colour under it, as turtlesim publishes them."""
    for x, y in points:
        trails.pose(name, x, y, 0.0)
        trails.colour(name, colour)
