"""Whether a submission's launch started turtlesim: roslaunch's own child
runs the grader's stand-in. Real processes, no sandbox: the stand-in and a
stand-in for roslaunch, both ours."""
import os
import subprocess
import sys
import time

from turtle_letters.autograder.world import stand_in, stand_in_started


def wait_for(condition, seconds=10.0):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if condition():
            return True
        time.sleep(0.05)
    return False


def test_the_stand_in_counts_only_as_roslaunchs_child_and_no_file_says_so(tmp_path):
    folder = stand_in(str(tmp_path))
    node = os.path.join(folder, 'lib', 'turtlesim', 'turtlesim_node')
    launcher = tmp_path / 'roslaunch'       # starts its nodes as roslaunch does: as children
    launcher.write_text(f'import subprocess, sys\nsubprocess.run([{node!r}, "__name:=sim"])\n')
    open(os.path.join(folder, 'started'), 'w').close()     # what a forger would write
    assert not stand_in_started(folder)
    alone = subprocess.Popen([node])                        # not started by roslaunch
    launched = subprocess.Popen([sys.executable, str(launcher)], start_new_session=True)
    try:
        assert wait_for(lambda: stand_in_started(folder))
        os.killpg(launched.pid, 15)
        launched.wait()
        assert wait_for(lambda: not stand_in_started(folder))
    finally:
        for process in (alone, launched):
            process.terminate()
            process.wait()
