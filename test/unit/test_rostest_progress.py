"""`make test` names each rostest as it ends, with its result and how far
the phase is, from catkin's run_tests output (which is the log's, unchanged;
make groups each test's lines, which come together as it ends: rostest's
summary before its command where run_tests.py's output is buffered, after
it where not, and run_tests.py's `verify result` last)."""
import io
import os
import subprocess
import sys

TOOL = os.path.join(os.path.dirname(__file__), '..', '..', 'tools', 'rostest_progress.py')
RUN_TESTS = '''Scanning dependencies of target run_tests_turtle_letters_rostest_test_faults.test
... logging to /ws/build/test_results/ros_home/log/rostest-vm-1.log
[ROSTEST]-----------------------------------------------------------------------
SUMMARY
\x1b[32m * RESULT: SUCCESS\x1b[0m
 * TESTS: 12
-- run_tests.py: execute commands
  /usr/bin/rostest --pkgdir=/ws/src/turtle_letters --package=turtle_letters --results-filename test_faults.xml --results-base-dir "/ws/build/test_results" /ws/src/turtle_letters/test/faults.test
-- run_tests.py: verify result "/ws/build/test_results/turtle_letters/rostest-test_faults.xml"
Built target _run_tests_turtle_letters_rostest_test_faults.test
-- run_tests.py: execute commands
  /usr/bin/rostest --pkgdir=/ws/src/turtlesim --package=turtlesim --results-filename test_turtlesim.xml --results-base-dir "/ws/build/test_results" /ws/src/turtlesim/test/turtlesim.test
\x1b[1;31m * RESULT: FAIL\x1b[0m
-- run_tests.py: verify result "/ws/build/test_results/turtlesim/rostest-test_turtlesim.xml"
Traceback (most recent call last):
-- run_tests.py: execute commands
  /usr/bin/rostest --pkgdir=/ws/src/turtle_letters --package=turtle_letters --results-filename test_svg.xml --results-base-dir "/ws/build/test_results" /ws/src/turtle_letters/test/svg.test
-- run_tests.py: verify result "/ws/build/test_results/turtle_letters/rostest-test_svg.xml"
'''


def test_a_line_as_each_rostest_ends_with_its_result():
    sys.path.insert(0, os.path.dirname(TOOL))
    import rostest_progress
    out, times = io.StringIO(), iter([0.0, 5.0, 754.0, 760.0])
    rostest_progress.main(3, io.StringIO(RUN_TESTS), out, clock=lambda: next(times))
    assert out.getvalue() == ('  [1/3] rostest turtle_letters faults.test: SUCCESS (0:05 in)\n'
                              '  [2/3] rostest turtlesim turtlesim.test: FAIL (12:34 in)\n'
                              '  [3/3] rostest turtle_letters svg.test: no result (12:40 in)\n')


def test_as_make_test_runs_it_each_line_comes_as_it_is_read():
    tool = subprocess.Popen([sys.executable, TOOL, '3'], stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, universal_newlines=True)
    tool.stdin.write(RUN_TESTS.split('Built target')[0])
    tool.stdin.flush()
    assert tool.stdout.readline().startswith('  [1/3] rostest turtle_letters faults.test: SUCCESS')
    tool.stdin.close()
    assert tool.wait(timeout=10) == 0
