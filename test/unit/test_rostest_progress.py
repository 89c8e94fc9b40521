"""`make test` names each rostest as it starts, with how far the phase is,
from catkin's run_tests output (which is the log's, unchanged)."""
import io
import os
import subprocess
import sys

TOOL = os.path.join(os.path.dirname(__file__), '..', '..', 'tools', 'rostest_progress.py')
RUN_TESTS = '''Scanning dependencies of target run_tests_turtle_letters_rostest_test_faults.test
-- run_tests.py: execute commands
  /usr/bin/rostest --pkgdir=/ws/src/turtle_letters --package=turtle_letters --results-filename test_faults.xml --results-base-dir "/ws/build/test_results" /ws/src/turtle_letters/test/faults.test
[ROSTEST]-----------------------------------------------------------------------
-- run_tests.py: execute commands
  /usr/bin/rostest --pkgdir=/ws/src/turtlesim --package=turtlesim --results-filename test_turtlesim.xml --results-base-dir "/ws/build/test_results" /ws/src/turtlesim/test/turtlesim.test
'''


def test_a_line_as_each_rostest_starts():
    sys.path.insert(0, os.path.dirname(TOOL))
    import rostest_progress
    out, times = io.StringIO(), iter([0.0, 5.0, 754.0])
    rostest_progress.main(2, io.StringIO(RUN_TESTS), out, clock=lambda: next(times))
    assert out.getvalue() == ('  [1/2] rostest turtle_letters faults.test (0:05 in)\n'
                              '  [2/2] rostest turtlesim turtlesim.test (12:34 in)\n')


def test_as_make_test_runs_it_each_line_comes_as_it_is_read():
    tool = subprocess.Popen([sys.executable, TOOL, '2'], stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, universal_newlines=True)
    tool.stdin.write(RUN_TESTS.split('[ROSTEST]')[0])
    tool.stdin.flush()
    assert tool.stdout.readline().startswith('  [1/2] rostest turtle_letters faults.test (0:0')
    tool.stdin.close()
    assert tool.wait(timeout=10) == 0
