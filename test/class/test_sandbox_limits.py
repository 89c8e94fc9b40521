"""The sandbox's limits, each reached by a command of our own (never a
cadet's) in a real sandbox: memory, processes, CPU time and disk each stop
it in words, and nothing of it is left after; the core it is given, it
cannot widen; two graded at once are different users. Root only, as
grading is."""
import os
import subprocess

import pytest

from support.grading import leftovers, package_caps, sandbox_processes

pytestmark = pytest.mark.skipif(os.geteuid() != 0, reason='the sandbox needs root')
FORKS = ('import os, time\n'
         'for n in range(400):\n'
         '    try:\n'
         '        if os.fork() == 0:\n'
         '            time.sleep(60)\n'
         '            os._exit(0)\n'
         '    except OSError:\n'
         '        print("refused after", n)\n'
         '        break\n')


@pytest.mark.parametrize('command, says', [
    (['python3', '-c', 'b"x" * (3 * 1024 ** 3)'], 'memory limit of 2 GiB reached'),
    (['python3', '-c', FORKS], 'process limit of 256 reached'),
    (['bash', '-c', '(while :; do :; done) & (while :; do :; done) & sleep 3'],
     'CPU time limit of 1 s reached'),
    (['bash', '-c', 'head -c 700M /dev/zero > /tmp/fill; head -c 700M /dev/zero > fill'],
     'disk limit of 1 GiB reached (its files, /tmp and /dev/shm together)'),
])
def test_each_limit_stops_the_sandbox_in_words(command, says):
    from turtle_letters.isolation.sandbox import Sandbox
    before = sandbox_processes()
    with Sandbox(package_caps()._replace(cpu=1)) as box:
        assert box.reached() == ''
        subprocess.run(box.inside(command, {'PATH': '/usr/bin:/bin'}), timeout=120,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        assert box.reached().startswith(says)
    assert leftovers(before) == ([], [])


def test_the_core_given_holds_and_two_at_once_are_different_users():
    """Given core 0, a command that widens its own affinity still runs on
    core 0 alone (a cgroup's cpuset, not taskset); its work folder is its
    user's alone, and the one graded beside it is another user."""
    from turtle_letters.isolation.sandbox import USER, Sandbox
    probe = ('taskset -pc 0-63 $$ >/dev/null 2>&1; grep Cpus_allowed_list /proc/self/status; '
             'id -u')
    before = sandbox_processes()
    with Sandbox(package_caps(), cpu=0, slot=0) as first, \
            Sandbox(package_caps(), cpu=0, slot=1) as second:
        seen = [subprocess.run(box.inside(['bash', '-c', probe], {'PATH': '/usr/bin:/bin'}),
                               stdout=subprocess.PIPE, universal_newlines=True).stdout.split()
                for box in (first, second)]
        owners = [(os.stat(box.work).st_uid, oct(os.stat(box.work).st_mode & 0o777))
                  for box in (first, second)]
    assert seen == [['Cpus_allowed_list:', '0', str(USER)],
                    ['Cpus_allowed_list:', '0', str(USER + 1)]]
    assert owners == [(USER, '0o700'), (USER + 1, '0o700')]
    assert leftovers(before) == ([], [])


def test_nothing_a_command_started_outlives_it_while_the_sandbox_stands():
    """A command that leaves a process running behind it (`&`, as a
    cadet's script may) takes it along when it ends, the sandbox still
    open: the grader ends a drawing soon after roslaunch ends on this
    (observations.GONE_STILL)."""
    import time
    from turtle_letters.isolation.sandbox import Sandbox
    before = sandbox_processes()
    with Sandbox(package_caps()) as box:
        ran = subprocess.run(box.inside(['bash', '-c', '(sleep 60 &); echo left'],
                                        {'PATH': '/usr/bin:/bin'}),
                             stdout=subprocess.PIPE, universal_newlines=True, timeout=30)
        deadline = time.monotonic() + 5
        while leftovers(before)[0] and time.monotonic() < deadline:
            time.sleep(0.05)
        left = leftovers(before)[0]
    assert ran.stdout.strip() == 'left' and left == []


def test_a_trial_of_the_sandbox_that_never_ends_says_so_and_leaves_nothing(monkeypatch):
    """The grader's trial of the sandbox (sandbox.problem) runs `true` in a
    real one; here it runs `sleep 60` instead, which never ends in time:
    the trial gives up in words, and its sandbox is removed whole (on CI,
    a trial once kept the grader waiting over 120 s)."""
    import time
    from turtle_letters.isolation import sandbox
    before = sandbox_processes()
    inside = sandbox.Sandbox.inside
    monkeypatch.setattr(sandbox.Sandbox, 'inside',
                        lambda box, argv, env: inside(box, ['sleep', '60'], env))
    monkeypatch.setattr(sandbox, 'TRIAL_SECONDS', 2)
    started = time.monotonic()
    assert sandbox.problem() == \
        'bubblewrap ran no command within 2 s: the sandbox is not usable here'
    assert time.monotonic() - started < 30
    assert leftovers(before) == ([], [])
