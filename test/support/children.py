"""The environment of a process whose output a test reads. No ROS here."""
import os


def readable_env(base=None, **extra):
    """`base` (this process's environment by default) with `extra`, for a
    child whose output goes to a file or pipe that a test reads while it
    runs: Python output there is block-buffered, so without
    PYTHONUNBUFFERED a line would come only at exit, and a test waiting for
    it would wait in vain wherever the caller's shell does not set it."""
    return dict(os.environ if base is None else base, PYTHONUNBUFFERED='1', **extra)
