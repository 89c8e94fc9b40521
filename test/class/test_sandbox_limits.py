"""The sandbox's limits, each reached by a command of our own (never a
cadet's) in a real sandbox: memory, processes and CPU time each stop it
in words, and nothing of it is left after. Root only, as grading is."""
import os
import subprocess

import pytest

from support.grading import leftovers, sandbox_processes

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
])
def test_each_limit_stops_the_sandbox_in_words(tmp_path, command, says):
    from turtle_letters.gradebook.sandbox import LIMITS, Sandbox
    limits = dict(LIMITS, cpu=(1, LIMITS['cpu'][1]))
    before = sandbox_processes()
    with Sandbox(str(tmp_path), limits=limits) as box:
        assert box.reached() == ''
        subprocess.run(box.inside(command, {'PATH': '/usr/bin:/bin'}), timeout=120,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        assert box.reached().startswith(says)
    assert leftovers(before) == ([], [])
