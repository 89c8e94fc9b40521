"""Carrying a plan out on a turtle, tick by tick: the modes, the executors, pause and cancel, and the turtle's ROS plumbing."""
