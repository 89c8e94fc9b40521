"""Builds as users make them, each in a workspace of its own: a turtlesim in
an underlay workspace, switching simulators both ways, doc/install.md's recipe
for your own catkin workspace, and launching from its install space.

Slow (several catkin builds), so `make test` runs these last. They need the
ROS build tools that `make deps` installs, and nothing else of this machine:
every command runs in a clean environment with only the system ROS.
"""
import os
import re
import shutil
import signal
import socket
import subprocess
import time

import pytest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..'))
NOETIC_SETUP = '/opt/ros/noetic/setup.bash'
CATKIN_MAKE = 'catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3'


def bash(script, home, timeout=900, check=True, **env):
    """Run `script` in a clean login-less bash, as a user's new terminal."""
    clean = {'PATH': '/usr/bin:/bin', 'HOME': str(home), 'LANG': 'C.UTF-8',
             'ROS_IP': '127.0.0.1', 'QT_QPA_PLATFORM': 'offscreen', **env}
    prelude = f'source {NOETIC_SETUP}\n' if os.path.exists(NOETIC_SETUP) else ''
    run = subprocess.run(['bash', '-c', 'set -e\n' + prelude + script], env=clean,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         universal_newlines=True, timeout=timeout)
    if check and run.returncode != 0:
        pytest.fail(f'exit {run.returncode}:\n{script}\n--- output (end) ---\n{run.stdout[-4000:]}')
    return run.stdout


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def installed_turtlesim(home):
    return bash('rospack find turtlesim', home, check=False).strip().startswith('/')


@pytest.fixture(scope='module')
def home(tmp_path_factory):
    return tmp_path_factory.mktemp('home')


@pytest.fixture(scope='module')
def underlay(home):
    """A turtlesim built from source in a workspace of its own (the bundled
    one, copied out of this repository, stands in for the real one)."""
    root = home / 'underlay_ws'
    shutil.copytree(os.path.join(REPO, 'sim', 'turtlesim'), root / 'src' / 'turtlesim')
    bash(f'cd {root} && {CATKIN_MAKE}', home)
    return root


def make_build(home, underlay, workspace, bundled=False):
    env = {'TURTLE_LETTERS_WS': str(workspace)}
    if bundled:
        env['TURTLE_LETTERS_BUNDLED_SIM'] = '1'
    return bash(f'source {underlay}/devel/setup.bash\nbash {REPO}/tools/build.sh', home, **env)


def where_turtlesim(home, workspace):
    """The turtlesim package, its node and its messages, as roslaunch finds
    them for a user of the workspace."""
    out = bash(f'source {workspace}/devel/setup.bash\n' + "python3 -c '"
               'import rospkg, roslib.packages, turtlesim.msg\n'
               'print(rospkg.RosPack().get_path("turtlesim"))\n'
               'print(roslib.packages.find_node("turtlesim", "turtlesim_node")[0])\n'
               "print(turtlesim.msg.__file__)'", home)
    return out.split()[-3:]


def test_a_turtlesim_in_an_underlay_is_used_and_switching_leaves_nothing_stale(home, underlay):
    workspace = home / 'project_ws'
    said = make_build(home, underlay, workspace)
    assert f'turtlesim: the one installed at {underlay}/src/turtlesim' in said
    assert not os.path.lexists(workspace / 'src' / 'turtlesim')
    package, node, messages = where_turtlesim(home, workspace)
    assert package == f'{underlay}/src/turtlesim'
    assert node.startswith(f'{underlay}/devel/'), node
    assert messages.startswith(f'{underlay}/devel/'), messages

    said = make_build(home, underlay, workspace, bundled=True)
    assert 'turtlesim: the bundled one (TURTLE_LETTERS_BUNDLED_SIM=1)' in said
    package, node, messages = where_turtlesim(home, workspace)
    assert os.path.realpath(package) == os.path.join(REPO, 'sim', 'turtlesim')
    assert node.startswith(f'{workspace}/devel/'), node
    assert messages.startswith(f'{workspace}/devel/'), messages

    said = make_build(home, underlay, workspace)
    assert 'building afresh' in said
    package, node, messages = where_turtlesim(home, workspace)
    assert package == f'{underlay}/src/turtlesim'
    assert node.startswith(f'{underlay}/devel/'), node
    assert messages.startswith(f'{underlay}/devel/'), messages
    assert not list((workspace / 'devel').glob('**/turtlesim*')), 'a stale bundled turtlesim'


def recipe():
    """doc/install.md's own-workspace recipe, line by line."""
    with open(os.path.join(REPO, 'doc', 'install.md')) as f:
        text = f.read()
    block = re.search(r'<!-- recipe: own workspace -->\n```bash\n(.*?)```', text, re.S)
    assert block, 'doc/install.md has no own-workspace recipe'
    return block.group(1).strip().splitlines()


class Launch:
    """roslaunch in the background on a master of its own, output in a file."""

    def __init__(self, home, setup, arguments):
        self.log = home / f'launch_{time.monotonic_ns()}.log'
        # Unbuffered: the nodes' log lines reach the file as they are written.
        clean = {'PATH': '/usr/bin:/bin', 'HOME': str(home), 'LANG': 'C.UTF-8',
                 'ROS_IP': '127.0.0.1', 'ROS_MASTER_URI': f'http://127.0.0.1:{free_port()}',
                 'PYTHONUNBUFFERED': '1'}
        with open(self.log, 'w') as out:
            self.process = subprocess.Popen(
                ['bash', '-c', f'source {setup}\nexec roslaunch turtle_letters '
                               f'draw_letter.launch {arguments}'],
                env=clean, stdout=out, stderr=subprocess.STDOUT, start_new_session=True)

    def output(self):
        return self.log.read_text()

    def wait_for(self, text, timeout):
        deadline = time.time() + timeout
        while time.time() < deadline and self.process.poll() is None:
            if text in self.output():
                return True
            time.sleep(0.2)
        return text in self.output()

    def stop(self):
        if self.process.poll() is None:
            os.killpg(self.process.pid, signal.SIGINT)
            try:
                self.process.wait(30)
            except subprocess.TimeoutExpired:
                os.killpg(self.process.pid, signal.SIGKILL)
                self.process.wait()


DRAW = 'headless:=true talker:=false mode:=feedback linear_speed:=3 angular_speed:=3 text:=HI'


def draws_hi(home, setup):
    launch = Launch(home, setup, DRAW)
    try:
        assert launch.wait_for("Done drawing 'HI'", 120), launch.output()[-4000:]
    finally:
        launch.stop()
    assert 'Traceback' not in launch.output()


@pytest.fixture(scope='module')
def own_workspace(home):
    lines = recipe()
    assert lines[-1] == 'roslaunch turtle_letters draw_letter.launch'
    script = []
    for line in lines[:-1]:
        if line.startswith('ln -s') and installed_turtlesim(home):
            continue        # the README says: only where turtlesim is not installed
        script.append(line.replace('REPOSITORY', REPO))
    bash('\n'.join(script), home)
    return home / 'catkin_ws'


def test_the_readme_recipe_for_your_own_workspace_draws(home, own_workspace):
    draws_hi(home, own_workspace / 'devel' / 'setup.bash')


def test_the_install_space_launches_and_checks_parameters(home, own_workspace):
    bash(f'cd {own_workspace} && {CATKIN_MAKE} install', home)
    setup = own_workspace / 'install' / 'setup.bash'
    found = bash(f'source {setup}\nrospack find turtle_letters', home).split()[-1]
    assert found == f'{own_workspace}/install/share/turtle_letters'

    refused = Launch(home, setup, 'headless:=true talker:=false size:=0')
    refused.process.wait(60)
    fatal = [line for line in refused.output().splitlines() if '[FATAL]' in line]
    assert refused.process.returncode != 0
    assert len(fatal) == 1 and '~size is 0' in fatal[0], refused.output()[-3000:]

    draws_hi(home, setup)
