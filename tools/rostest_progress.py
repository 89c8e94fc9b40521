"""`make test`'s rostest phase as it goes: catkin's run_tests output on
stdin (tee'd whole to the log), and on stdout a line as each rostest ends,
`[n/N] rostest PACKAGE FILE: RESULT (m:ss in)`. The rostests run two at a
time with make's output grouped by test (-Otarget), so a test's lines come
together once it ends: rostest's command and its ` * RESULT:`, in either
order (run_tests.py's own lines are buffered where PYTHONUNBUFFERED is
unset), then run_tests.py's `verify result`, which ends the test's lines."""
import re
import sys
import time

RESULT = re.compile(r'\* RESULT: (\w+)')


def command_of(line):
    """(package, file) of the rostest whose command a line of run_tests is, or None."""
    words = line.split()
    if '--results-filename' not in words:
        return None
    package = next((w.split('=', 1)[1] for w in words if w.startswith('--package=')), '?')
    test = next((w for w in reversed(words) if w.endswith('.test')), '?')
    return package, test.rsplit('/', 1)[-1]


def main(total, lines=sys.stdin, out=sys.stdout, clock=time.monotonic):
    begun, count, test, result = clock(), 0, None, 'no result'
    for line in lines:
        found = RESULT.search(line)
        if found:
            result = found.group(1)
        elif command_of(line):
            test = command_of(line)
        elif 'run_tests.py: verify result' in line and test:
            count += 1
            minutes, seconds = divmod(int(clock() - begun), 60)
            out.write(f'  [{count}/{total}] rostest {test[0]} {test[1]}: {result} '
                      f'({minutes}:{seconds:02d} in)\n')
            out.flush()
            test, result = None, 'no result'


if __name__ == '__main__':
    main(int(sys.argv[1]))
