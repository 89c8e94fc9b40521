"""Carrying a plan out, tick by tick: modes, executors, pause and cancel, the ROS driver."""
