"""The grader from a checkout in a home folder: Debian makes homes 0700,
and /root is, so the users the grader runs its world as cannot pass
through it. A copy of this checkout under such a folder, built there as a
user builds it, grades Lena's L as the class tests do. Root only, as
grading is."""
import os
import subprocess

import pytest

from support.grading import leftovers, sandbox_processes

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.abspath(os.path.join(HERE, '..', '..'))
pytestmark = pytest.mark.skipif(os.geteuid() != 0, reason='grading makes network namespaces: '
                                                          'root only')


def bash(script, timeout=900):
    """`script` in a clean bash, as a new terminal of the instructor's."""
    clean = {'PATH': '/usr/bin:/bin:/usr/sbin:/sbin', 'HOME': '/root', 'LANG': 'C.UTF-8'}
    noetic = '/opt/ros/noetic/setup.bash'
    prelude = f'source {noetic}\n' if os.path.exists(noetic) else ''
    return subprocess.run(['bash', '-c', 'set -e\n' + prelude + script], env=clean,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=timeout)


def checkout_in(home):
    """This checkout's files (as git has them, uncommitted work too) at
    HOME/turtle_letters, with its workspace built there."""
    files = subprocess.run(['git', '-C', REPO, 'ls-files', '-z', '--cached', '--others',
                            '--exclude-standard'], stdout=subprocess.PIPE, check=True).stdout
    copy = os.path.join(home, 'turtle_letters')
    os.mkdir(copy)
    subprocess.run(['tar', '-C', REPO, '--null', '-T', '-', '-cf', '-'], input=files,
                   stdout=open(os.path.join(home, 'files.tar'), 'wb'), check=True)
    subprocess.run(['tar', '-C', copy, '-xf', os.path.join(home, 'files.tar')], check=True)
    built = bash(f'cd {copy} && bash tools/build.sh')
    assert built.returncode == 0, built.stdout[-3000:]
    return copy


def test_a_checkout_in_a_0700_home_grades_as_any_other(tmp_path):
    home = tmp_path / 'home'
    home.mkdir(mode=0o700)
    os.chmod(home, 0o700)       # as Debian 12 makes a home, and /root is
    copy = checkout_in(str(home))
    before = sandbox_processes()
    graded = bash(f'source {copy}/.ws/devel/setup.bash\n'
                  f'rosrun turtle_letters grade_class.py --one {copy}/test/class/submissions/'
                  f'c03_lena --name "Lena Ortiz" --rubric {copy}/test/class/rubric.yaml '
                  f'--out {home}/out')
    assert graded.returncode == 0, graded.stdout[-3000:]
    assert 'drew L, expected L' in graded.stdout and 'PASS' in graded.stdout, graded.stdout
    assert os.stat(home).st_mode & 0o777 == 0o700, 'the home was loosened'
    assert leftovers(before) == ([], []), 'the grading left something behind'
