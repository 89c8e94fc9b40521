"""Every command the README and doc/ pages show, run as a reader would type
it: each launch comes up ready and stops on Ctrl-C, each trigger is heard.
The few that another test runs (the classroom, on machines of its own; the
own-workspace recipe; `make test` itself) are named here with that test, and
a command that neither this test nor another runs fails it."""
import glob
import os
import re
import signal
import subprocess
import time

import pytest

from support.children import readable_env

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..'))
PAGES = ['README.md'] + sorted(os.path.relpath(p, REPO) for p in glob.glob(f'{REPO}/doc/*.md'))
# Run elsewhere, and where.
ELSEWHERE = {
    'make test': 'make test is what runs this test',
    'rostest turtle_letters draw_letter.test': 'make test runs every rostest',
    'make bench': 'the benchmark, by hand (about 20 minutes)',
    'make bench ARGS="--reps 5 --letter K --modes feedback --loads idle --words= --classroom="':
        'the benchmark, by hand',
    'make bench ARGS="--modes= --loads idle --words= --classroom 1,10,30"': 'the benchmark, by hand',
    'export ROS_IP=192.168.1.10 ROS_MASTER_URI=http://192.168.1.10:11311':
        'test/network: the instructor on a machine of its own',
    'export ROS_IP=192.168.1.23 ROS_MASTER_URI=http://192.168.1.10:11311':
        'test/network: a student on a machine of their own',
    'roslaunch turtle_letters classroom.launch': 'test/network',
    'roslaunch turtle_letters student.launch name:=alice': 'test/network',
    "rostopic pub -1 /alice/chatter std_msgs/String \"data: 'P'\"": 'test/network',
    'rostopic echo /draw/feedback': 'test/action.test follows the same feedback with a client',
    'rosservice call /pause true': 'test/action.test pauses a drawing mid-move, then resumes it',
    'roslaunch turtle_letters grade.launch': 'test/grade.test includes it and sends the P',
    'rostest turtle_letters grade.test': 'make test runs every rostest',
    'rostest turtle_letters grade.test controller:="turtle_letters lab_n.py" '
    'params:="{second_turn: 200}"': 'test/grade_wrong.test: the same controller and parameters',
    'rostest turtle_letters grade.test controller:="my_lab my_controller.py"':
        "a student's package: test/grade.test with this package's controller",
    'roslaunch turtle_letters classroom.launch grade:=true': 'test/classroom.test',
    'rosrun turtle_letters delay_relay.py in:=/slow/turtle1/cmd_vel out:=/turtle1/cmd_vel '
    '_delay:=0.05 _jitter:=0.03': 'test/latency.test runs two such relays, one each way',
    'rosrun turtle_letters grade_class.py SUBMISSIONS --roster ROSTER.csv --out OUT --jobs 2':
        'test/class/test_grade_class.py grades a class so, with --jobs 2',
    'rosrun turtle_letters grade_class.py --one FOLDER --name "Kofi Mensah" --out OUT':
        'test/class/test_grade_class.py: one submission, exit 0 on pass and 1 on fail',
    'rosrun turtle_letters grade_class.py test/class/submissions --roster test/class/roster.csv '
    '--rubric test/class/rubric.yaml --out /tmp/grades --jobs 2':
        'test/class/test_grade_class.py runs exactly this, into a folder of its own',
    'rosrun turtle_letters grade_class.py --reread OUT':
        'test/class/test_grade_class.py reads the class it graded again so',
}
RECIPE = 'doc/install.md'       # test/workspace/test_workspaces.py runs it line by line
# Sent to a launch, in this order, each with what its controller then says
# (None: nothing sent, the launch draws by itself).
LAB = 'roslaunch turtle_letters draw_letter.launch'
TRIGGERS = {
    LAB: [("rostopic pub -1 /chatter std_msgs/String \"data: 'P'\"", "Drawing 'N'"),
          ("rostopic pub -1 /turtlebot_controller/text std_msgs/String \"data: 'HI'\"",
           '~text ignored: a drawing is waiting or under way')],
    'make run ARGS="svg:=doc/flower.svg mode:=smooth"': [(None, "Done drawing 'flower.svg'")],
    'make run ARGS="letter:=K"': [('rosrun turtle_letters draw.py L', "Done drawing 'L'")],
    f'{LAB} view:=true': [(None, 'View: the room at http://127.0.0.1:8080/')],
    f'{LAB} mode:=feedback': [
        ("rostopic pub -1 /turtlebot_controller/svg std_msgs/String "
         "\"data: '$PWD/doc/flower.svg'\"", "Drawing 'flower.svg', 9 strokes")],
}


def commands():
    """(page, command) for every line of every bash block, comments cut."""
    found = []
    for page in PAGES:
        with open(os.path.join(REPO, page)) as f:
            text = f.read()
        for block in re.finditer(r'(<!-- recipe: [^>]*-->\n)?```bash\n(.*?)```', text, re.S):
            if block.group(1) and page == RECIPE:
                continue
            for line in block.group(2).strip().splitlines():
                command = re.sub(r'\s+#.*$', '', line).strip()
                if command:
                    found.append((page, command))
    return found


LAUNCHES = sorted({c for _, c in commands()
                   if c.startswith(('roslaunch turtle_letters draw_letter.launch', 'make run'))})


def test_every_command_is_run_here_or_by_the_test_named_for_it():
    sent = {trigger for triggers in TRIGGERS.values() for trigger, _ in triggers if trigger}
    ours = set(LAUNCHES) | sent | {'source .ws/devel/setup.bash'}
    orphans = [(page, c) for page, c in commands() if c not in ours and c not in ELSEWHERE]
    assert orphans == [], 'commands that no test runs'


@pytest.fixture
def master_port():
    """A master of the test's own (roslaunch starts one), so runs cannot meet."""
    return 11411 + os.getpid() % 500


def environment(port, home):
    env = readable_env(ROS_MASTER_URI=f'http://127.0.0.1:{port}', ROS_IP='127.0.0.1',
                       ROS_HOME=str(home))
    env.pop('DISPLAY', None)        # headless, as in CI
    return env


def start(command, env, out_path):
    """`command` started in its own session, its output to `out_path` (the
    test's own folder: nothing is left in /tmp)."""
    with open(out_path, 'w') as out:
        process = subprocess.Popen(['bash', '-c', command], cwd=REPO, env=env, stdout=out,
                                   stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                   start_new_session=True)
    process.out_path = out_path
    return process


def output(process):
    with open(process.out_path, errors='replace') as f:
        return f.read()


def wait_for(process, text, timeout):
    deadline = time.time() + timeout
    while time.time() < deadline and process.poll() is None:
        if text in output(process):
            return
        time.sleep(0.2)
    pytest.fail(f'no {text!r} within {timeout} s:\n{output(process)[-3000:]}')


def ctrl_c(process):
    os.killpg(process.pid, signal.SIGINT)
    try:
        return process.wait(30)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.wait()
        pytest.fail(f'did not stop on Ctrl-C:\n{output(process)[-3000:]}')


@pytest.mark.parametrize('command', LAUNCHES)
def test_the_launch_comes_up_ready_and_stops_on_ctrl_c(command, master_port, tmp_path):
    env = environment(master_port, tmp_path)
    launch = start(command, env, tmp_path / 'launch.out')
    try:
        wait_for(launch, 'Ready: publish', 240)
        for trigger, heard in TRIGGERS.get(command, []):
            if trigger:
                sent = subprocess.run(['bash', '-c', trigger], cwd=REPO,
                                      env=env, stdout=subprocess.PIPE,
                                      stderr=subprocess.STDOUT, universal_newlines=True,
                                      timeout=180)
                assert sent.returncode == 0, sent.stdout
            wait_for(launch, heard, 60)
    finally:
        ctrl_c(launch)
    said = output(launch)
    assert 'Traceback' not in said and '[FATAL]' not in said, said[-3000:]


def test_the_workspace_setup_can_be_sourced():
    done = subprocess.run(['bash', '-c', 'source .ws/devel/setup.bash && rospack find turtle_letters'],
                          cwd=REPO, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True)
    assert done.returncode == 0 and done.stdout.strip().endswith('turtle_letters'), done.stdout
