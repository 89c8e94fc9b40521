"""A class of cadets' packages of our own (submissions/), graded end to end
by grade_class.py as an instructor runs it: each row held against what a
careful instructor concludes, the files handed back, and nothing left
behind: the submissions unchanged, no process, no network namespace.
Needs root (each submission gets a network namespace); skipped elsewhere."""
import csv
import json
import os
import shutil
import subprocess
import xml.etree.ElementTree as ElementTree
from concurrent.futures import ThreadPoolExecutor

import pytest

from support.children import readable_env
from support.grading import (container, grade_class, leftovers, package_caps, sandbox_processes,
                             tree_hash)

HERE = os.path.dirname(os.path.abspath(__file__))
SUBMISSIONS = os.path.join(HERE, 'submissions')
ROSTER = os.path.join(HERE, 'roster.csv')
RUBRIC = os.path.join(HERE, 'rubric.yaml')
pytestmark = pytest.mark.skipif(os.geteuid() != 0, reason='grading makes network namespaces: '
                                                          'root only')

# id: (expected, drawn, verdict, words in the reason)
CONCLUSIONS = {
    'c01_nadia': ('N', 'N', 'pass', "NameError: name 'raw_input' is not defined "
                                    "(turtlebot_lab/scripts/lab_talker.py, line 9)"),
    'c02_kofi': ('K', 'K', 'pass', ''),
    'c03_lena': ('L', 'L', 'pass', 'every criterion met'),
    'c04_maria': ('M', 'N', 'fail', 'drew N, expected M'),
    # his CMakeLists.txt names turtle_sim: his Python nodes run unbuilt, as a TA
    # would run them, and draw the lab's N
    'c05_omar': ('O', 'N', 'fail', "It builds: catkin_make failed"),
    # a misspelt type in his launch file: his executables run instead, as a TA would
    'c06_pavel': ('P', 'N', 'fail', 'Cannot locate node of type [controler.py]'),
    'c07_quinn': ('Q', 'O', 'fail', 'drew O, expected Q'),
    'c08_tariq': ('T', '', 'fail', 'no ink was driven: 3 teleports laid all there is'),
    'c09_fatima': ('F', '', 'fail', 'nothing was drawn'),
    # a script and no package.xml: wrapped in a package of the grader's and run, as a
    # TA runs it; it prints, and draws nothing
    'c10_sam': ('S', '', 'fail', f'no package.xml in {SUBMISSIONS}/c10_sam: nothing a catkin'),
    'c11_zoe': ('Z', '', 'fail', 'no submission'),
    'c12_ursula': ('U', 'I', 'fail', 'turtlesim was cleared'),     # the canvas left: one stroke
    'c13_victor': ('V', 'V', 'pass', 'drives the turtle and published "P"'),    # a lead-in
    # a pause of 3 s between strokes; his talker in an xterm, his turtlesim in a
    # gnome-terminal (launch-prefix), as on his desktop
    'c14_lars': ('L', 'L', 'pass', 'every criterion met'),
    'c15_carmen': ('C', 'C', 'pass', 'a turtle moved without the trigger'),    # draws at launch
    'c16_noah': ('N', 'N', 'pass', 'no launch file: the grader started its executables '
                                   '(keyboard.py, n_controller.py)'),
    'c17_ivan': ('I', 'I', 'pass', 'every criterion met'),     # launch files included, one I
    'c18_theo': ('T', 'T', 'pass', 'every criterion met'),     # his own turtle, turtle1 killed
    # the pen lifted to travel; rqt_graph, which Debian lacks, opened beside the lab
    'c19_farah': ('F', 'F', 'pass', 'every criterion met'),
    'c20_jonas': ('JD', 'JD', 'pass', 'every criterion met'),  # initials, given in the roster
    'c21_hana': ('H', 'H', 'pass', 'every criterion met'),     # C++ (roscpp)
    # C++ including turtlesim/Pose.h without naming turtlesim, tf, numpy and
    # turtle_teleop_key, as a course's Noetic machine has them; no talker
    'c22_kenji': ('K', 'K', 'pass', 'no "P" on /chatter within 5 s of P and Enter'),
    'x_late': ('', 'I', 'fail', 'no letter is expected'),
}


@pytest.fixture(scope='module')
def graded(tmp_path_factory):
    out = str(tmp_path_factory.mktemp('grades'))
    before = tree_hash(SUBMISSIONS), sandbox_processes()
    done = grade_class(SUBMISSIONS, '--roster', ROSTER, '--rubric', RUBRIC, '--out', out,
                       '--jobs', '2')
    return done, out, before


def test_every_student_gets_the_row_a_careful_instructor_would(graded):
    done, out, _ = graded
    assert done.returncode == 0, done.stdout[-3000:]
    with open(os.path.join(out, 'grades.csv')) as f:
        rows = list(csv.DictReader(f))
    assert [r['id'] for r in rows] == list(CONCLUSIONS)
    for row in rows:
        expected, drawn, verdict, words = CONCLUSIONS[row['id']]
        assert (row['expected'], row['drawn'], row['verdict']) == (expected, drawn, verdict), row
        assert words in row['reason'], row
    assert 'x_late: a submission the roster lacks' in done.stdout


def test_each_criterion_says_what_happened(graded):
    _, out, _ = graded

    def tests(student):
        with open(os.path.join(out, student, 'results.json')) as f:
            data = json.load(f)
        # Gradescope shows both to the cent: the total is the rounded sum of the parts
        assert data['score'] == round(sum(t['score'] for t in data['tests']), 2)
        return {t['name']: t for t in data['tests']}
    nadia, lena = tests('c01_nadia'), tests('c03_lena')
    assert nadia['The talker publishes P on a key press']['status'] == 'failed'
    assert nadia['The letter drawn is the expected one']['status'] == 'passed'
    assert lena['The talker publishes P on a key press']['status'] == 'passed'  # a key, no Enter
    assert 'never ended' in tests('c07_quinn')['The drawing ends, the turtle standing still'][
        'output']
    assert '/f_drawer' in tests('c09_fatima')['The turtle was driven over cmd_vel']['output']
    assert tests('c02_kofi')['Its accuracy']['score'] > 10
    # Victor drove to where his V begins with his pen down: read past that lead-in
    assert 'read without its lead-in' in tests('c13_victor')[
        'The letter drawn is the expected one']['output']


def test_the_files_handed_back(graded):
    _, out, _ = graded
    page = open(os.path.join(out, 'report.html')).read()
    # a picture of each canvas with ink on it: Tariq's T, laid by teleports, is shown, never read
    inked = {student for student, (_, drawn, _, _) in CONCLUSIONS.items() if drawn} | {'c08_tariq'}
    for student in CONCLUSIONS:
        assert f'id="{student}"' in page
        assert os.path.exists(os.path.join(out, student, 'drawing.png')) == (student in inked), \
            student
    log = open(os.path.join(out, 'c01_nadia', 'log.txt')).read()
    assert 'catkin_make' in log and "NameError: name 'raw_input' is not defined" in log
    # Kenji's heading.py imports what a course's machine has (numpy, tf, matplotlib), and runs
    log = open(os.path.join(out, 'c22_kenji', 'log.txt')).read()
    assert 'quaternion' in log and 'ModuleNotFoundError' not in log, log[-3000:]
    suite = ElementTree.parse(os.path.join(out, 'junit.xml')).getroot()
    assert suite.get('tests') == '23' and suite.get('failures') == '10'


def test_each_drawing_kept_reads_again_as_it_was_graded(graded):
    """grade_class.py --reread OUT, as an instructor runs it on a class graded: the ink
    of each student who drove some (Tariq's teleports laid all his: none
    kept) read again, no student's code run, says each letter line as
    results.json does."""
    _, out, _ = graded
    done = subprocess.run(['rosrun', 'turtle_letters', 'grade_class.py', '--reread', out],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, env=readable_env(), timeout=600)
    assert done.returncode == 0, done.stdout[-3000:]
    lines = done.stdout.splitlines()
    drove = sorted(student for student, (_, drawn, _, _) in CONCLUSIONS.items() if drawn)
    assert [line.split(': as graded: ')[0] for line in lines[:-1]] == drove, done.stdout
    assert lines[-1] == f'{len(drove)} drawings read again, 0 read differently now'


def test_nothing_is_left_behind(graded):
    _, _, (files, processes) = graded
    assert tree_hash(SUBMISSIONS) == files
    assert leftovers(processes) == ([], [])


def test_the_sandbox_is_as_its_rules_say(tmp_path):
    """What a command inside sees: an unprivileged user with no capability,
    the system read-only, root's files unreadable, the class hidden, only
    its work folder and /tmp writable, a cgroup of its own, no service's
    socket in /run, loopback only."""
    from turtle_letters.isolation.sandbox import USER, Sandbox
    before = sandbox_processes()
    probe = ('id -u; grep CapEff /proc/self/status; ls "$0" | wc -l; touch /usr/x 2>&1; '
             'head -c1 /etc/shadow 2>&1; touch "$1/mine" /tmp/mine && echo wrote; '
             'grep -c tlgrade /proc/self/cgroup; ls /run | wc -l; ls /sys/class/net')
    with Sandbox(package_caps(), hidden=[SUBMISSIONS]) as box:
        seen = subprocess.run(box.inside(['bash', '-c', probe, SUBMISSIONS, box.work],
                                         {'PATH': '/usr/bin:/bin'}),
                              stdout=subprocess.PIPE, universal_newlines=True).stdout.split('\n')
        wrote = os.path.exists(os.path.join(box.work, 'mine'))
    assert seen[0] == str(USER) and seen[1].split() == ['CapEff:', '0000000000000000']
    assert seen[2] == '0' and 'Read-only file system' in seen[3]
    assert 'Permission denied' in seen[4] and seen[5] == 'wrote' and int(seen[6]) >= 1
    assert seen[7] == '0' and seen[8:] == ['lo', '']
    assert wrote and leftovers(before) == ([], [])


def test_the_sandbox_shows_a_workspace_in_a_home_but_not_the_home(tmp_path, monkeypatch):
    """An instructor's ~/catkin_ws on the ROS path: the sandbox shows that
    workspace's folders, read-only, and nothing else of the home (a key in
    ~/.ssh, another class's grades)."""
    from turtle_letters.isolation.sandbox import Sandbox
    home = f'/home/turtle_letters_test_{os.getpid()}'
    devel = os.path.join(home, 'catkin_ws', 'devel', 'lib', 'python3', 'dist-packages')
    try:
        os.makedirs(devel)
        os.makedirs(os.path.join(home, '.ssh'))
        for path in (os.path.join(devel, 'shown.py'), os.path.join(home, '.ssh', 'id_rsa')):
            with open(path, 'w') as f:
                f.write('seen\n')
        monkeypatch.setenv('PYTHONPATH', f"{devel}:{os.environ.get('PYTHONPATH', '')}")
        with Sandbox(package_caps()) as box:
            seen = subprocess.run(box.inside(['bash', '-c', 'cat "$0/shown.py"; ls -A "$1"',
                                              devel, home], {'PATH': '/usr/bin:/bin'}),
                                  stdout=subprocess.PIPE, universal_newlines=True).stdout
    finally:
        shutil.rmtree(home, ignore_errors=True)
    assert seen.split() == ['seen', 'catkin_ws'], seen


def test_one_submission_exits_0_on_pass_and_1_on_fail(tmp_path):
    """Two graders at once, as two CI jobs on one machine: the same slot, so
    the same users, and neither ends the other's world."""
    with ThreadPoolExecutor(2) as pool:
        passing = pool.submit(grade_class, '--one', os.path.join(SUBMISSIONS, 'x_late'),
                              '--letter', 'I', '--rubric', RUBRIC, '--out', str(tmp_path / 'a'))
        failing = pool.submit(grade_class, '--one', os.path.join(SUBMISSIONS, 'c08_tariq'),
                              '--name', 'Tariq', '--rubric', RUBRIC, '--out', str(tmp_path / 'b'))
    passed, failed = passing.result(), failing.result()
    assert passed.returncode == 0, passed.stdout[-2000:]
    assert failed.returncode == 1 and 'teleports laid all there is' in failed.stdout


def test_gradescope_mode_writes_its_results_where_gradescope_reads_them(tmp_path):
    root = tmp_path / 'autograder'
    shutil.copytree(os.path.join(SUBMISSIONS, 'x_late'), str(root / 'submission'), symlinks=True)
    (root / 'submission_metadata.json').write_text(json.dumps(
        {'users': [{'name': 'Ida Wells', 'email': 'ida@example.edu'}]}))
    done = grade_class('--gradescope', '--autograder', str(root), '--rubric', RUBRIC)
    assert done.returncode == 0, done.stdout[-2000:]
    results = json.loads((root / 'results' / 'results.json').read_text())
    assert results['output'].startswith('PASS') and len(results['tests']) == 8
    assert {'drawing time (s)', 'cmd_vel rate (/s)'} <= {b['name'] for b in results['leaderboard']}


def test_no_sandbox_in_a_container_that_is_one_already(tmp_path):
    """--no-sandbox as in Gradescope's container."""
    out = tmp_path / 'out'
    out.mkdir()
    done = subprocess.run(container(out) + [
        'rosrun', 'turtle_letters', 'grade_class.py', '--one', os.path.join(SUBMISSIONS, 'x_late'),
        '--letter', 'I', '--rubric', RUBRIC, '--out', str(out), '--no-sandbox'],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True,
        env=readable_env(), timeout=300)
    assert done.returncode == 0, done.stdout[-2000:]
    assert '[no sandbox: nothing isolated] x_late' in done.stdout


def test_no_sandbox_still_runs_the_cadet_as_a_user_of_its_own_ended_before_the_grade(tmp_path):
    """Gradescope's recipe (--gradescope --no-sandbox) on a hostile cadet
    (hostile/h8_overwriter) whose double-forked process outlives its nodes
    and writes over results.json once it appears: it runs as a user of its
    own, which cannot, and it is ended before the grade is written."""
    root = tmp_path / 'autograder'
    shutil.copytree(os.path.join(HERE, 'hostile', 'h8_overwriter'), str(root / 'submission'))
    (root / 'submission_metadata.json').write_text(json.dumps({'users': [{'name': 'Ida Wells'}]}))
    beats, results = tmp_path / 'beats', root / 'results' / 'results.json'
    beats.mkdir()
    os.chmod(str(tmp_path), 0o711)      # the cadet's user may reach beats/, and write there only
    os.chmod(str(beats), 0o1777)
    (root / 'submission' / 'overwriter_lab' / 'targets.txt').write_text(
        f'results {results}\nheartbeat {beats}/heartbeat\n')
    done = subprocess.run(container(tmp_path) + [
        'rosrun', 'turtle_letters', 'grade_class.py', '--gradescope', '--autograder', str(root),
        '--rubric', RUBRIC, '--no-sandbox'], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
        universal_newlines=True, env=readable_env(), timeout=300)
    assert done.returncode == 0, done.stdout[-2000:]
    graded = json.loads(results.read_text())
    assert graded['output'].startswith('PASS'), graded['output']
    heartbeat = beats / 'heartbeat'
    assert heartbeat.exists()       # it ran, and lingered past its nodes
    assert heartbeat.stat().st_mtime < results.stat().st_mtime


@pytest.mark.parametrize('args, says', [
    (['--roster', '/nonexistent.csv'], 'No such file'),
    (['--roster', __file__], 'header with id,name'),
    (['--roster', ROSTER, '--rubric', __file__], 'rubric'),
])
def test_bad_input_stops_before_anything_runs(tmp_path, args, says):
    done = grade_class(SUBMISSIONS, '--out', str(tmp_path / 'out'), *args, timeout=60)
    assert done.returncode == 2 and says in done.stdout
    assert not os.path.exists(tmp_path / 'out' / 'c01_nadia')
