"""The pose stream that the drawing thread reads: ROS callbacks put poses
in while the drawing thread takes them out and drops stale ones."""
import sys
import threading
from types import SimpleNamespace

import pytest

driver = pytest.importorskip('turtle_letters.motion.driver')


def test_a_pose_arriving_while_stale_ones_are_dropped_is_never_lost():
    """Each round: the stream full (nobody read), then the drawing thread
    drops the stale poses while the callback goes on putting new ones in."""
    stream = driver.PoseStream('/turtle1/pose', lambda: True)
    errors, full, done = [], threading.Event(), threading.Event()
    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)         # threads switch often: a race shows at once

    def drop():
        while not done.is_set():
            if full.wait(0.01):
                full.clear()
                stream.drop_stale()
    dropper = threading.Thread(target=drop)
    dropper.start()
    try:
        for number in range(100 * driver.POSES_KEPT):
            try:
                stream._on_pose(SimpleNamespace(number=number))
            except Exception as e:      # raised in a callback: the pose is lost
                errors.append(e)
            if number % driver.POSES_KEPT == 0:
                full.set()
    finally:
        done.set()
        dropper.join()
        sys.setswitchinterval(interval)
    assert not errors, f'{len(errors)} poses lost: {errors[0]!r}'
    assert stream.latest.number == 100 * driver.POSES_KEPT - 1


def test_the_oldest_poses_go_when_nobody_reads():
    stream = driver.PoseStream('/turtle1/pose', lambda: True)
    for number in range(driver.POSES_KEPT + 5):
        stream._on_pose(SimpleNamespace(number=number))
    assert stream.next().number == 5


def test_a_closed_driver_is_let_go():
    """A parallel word's spare turtles each have a driver: once closed, none
    may stay behind (they used to, one shutdown hook each, word after word)."""
    import gc
    import weakref
    drivers = [driver.TurtleDriver(f'spare_{n}') for n in range(3)]
    left = [weakref.ref(d) for d in drivers]
    for d in drivers:
        d.close()
    del drivers, d
    gc.collect()
    assert [ref() for ref in left] == [None, None, None]
