"""`make test`'s rostest phase as it goes: catkin's run_tests output on
stdin (tee'd whole to the log), and on stdout a line as each rostest starts,
`[n/N] rostest PACKAGE FILE (m:ss in)`, so that twelve quiet minutes say
which test runs and how far the phase is."""
import sys
import time


def started(line):
    """(package, file) of the rostest a line of run_tests starts, or None."""
    words = line.split()
    if '--results-filename' not in words:
        return None
    package = next((w.split('=', 1)[1] for w in words if w.startswith('--package=')), '?')
    test = next((w for w in reversed(words) if w.endswith('.test')), '?')
    return package, test.rsplit('/', 1)[-1]


def main(total, lines=sys.stdin, out=sys.stdout, clock=time.monotonic):
    begun, count = clock(), 0
    for line in lines:
        test = started(line)
        if test:
            count += 1
            minutes, seconds = divmod(int(clock() - begun), 60)
            out.write(f'  [{count}/{total}] rostest {test[0]} {test[1]} '
                      f'({minutes}:{seconds:02d} in)\n')
            out.flush()


if __name__ == '__main__':
    main(int(sys.argv[1]))
