"""One run's lab (Lab): the world a submission is graded on, the
submission's roslaunch in a terminal (Terminal), and the grader's watcher
beside them (Watcher, running watch.py), with one stop for all three.

The world is the grader's own: a ROS master
(rosmaster) and the bundled simulator, started beside the sandbox in its
network namespace, as a user the submission is not (the user of the sandbox's Beside).
The submission's nodes reach them over the network, as ROS lets them; the
simulator's account of what it drew (sim/.../record.py) comes to the grader
over a pipe, which nothing in the sandbox can reach. That account is the
only evidence of a drawing.

A turtlesim_node the submission's launch file starts finds STAND_IN first:
it stays up as long as the launch wants, draws nothing, and registers no
node, so it never displaces the grader's simulator.
"""
import math
import os
import pty
import shutil
import signal
import subprocess
import termios
import threading
import time

from .processes import JsonLines, Reader
from .reports import plain
from ..isolation.sandbox import GiB, closed_folder

SIMULATOR = '/grading_turtlesim'    # a name no lab needs, so no lab's node displaces it
# What the grader's own processes for a run may hold (the rubric's limits say
# how much), whatever the submission gives them to hold, each in a cgroup.
WORLD_SAYS = {
    'memory': lambda n: f"memory limit of {n / GiB:g} GiB reached by the grader's master and "
                        f"simulator (what the submission gave them to hold)",
    'processes': lambda n: f"process limit of {n} reached by the grader's master and simulator",
}
WATCHER_SAYS = {
    'memory': lambda n: f"memory limit of {n / GiB:g} GiB reached by the grader's watcher (a "
                        f"message on /chatter that large)",
    'processes': lambda n: f"process limit of {n} reached by the grader's watcher",
}
WORLD_VARIABLES = ('PATH', 'ROS_PACKAGE_PATH', 'CMAKE_PREFIX_PATH', 'PYTHONPATH', 'LD_LIBRARY_PATH',
                   'ROS_DISTRO', 'ROS_VERSION', 'ROS_ROOT', 'ROS_ETC_DIR', 'ROS_PYTHON_VERSION')
STOP_SECONDS = 20.0         # for roslaunch to end its nodes on Ctrl-C, outside a sandbox
_REPOSITORY = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.realpath(__file__)))))
SIM_FOLDER = os.path.join(_REPOSITORY, 'sim', 'turtlesim')
STAND_IN = """#!/bin/sh
# The grader runs the simulator (turtle_letters' grade_class.py): this
# stands in for turtlesim_node, draws nothing and stays up until ended.
trap 'kill $! 2>/dev/null; exit 0' INT TERM
sleep 2147483647 &
wait $!
"""

# A launch file may start a node in a window of its own (launch-prefix="xterm -e",
# "gnome-terminal --"), as on a course's desktop, where the window opens and a TA
# types there. Graded headless, the window's command runs in roslaunch's terminal
# instead, where the grader types P (a talker in an xterm hears it).
TERMINALS = ('xterm', 'gnome-terminal', 'konsole', 'x-terminal-emulator')
TERMINAL = """#!/usr/bin/python3
import os, shlex, sys
args, command = sys.argv[1:], None
for i, arg in enumerate(args):
    if arg in ('--', '-x'):                 # the rest is the command, word by word
        command = args[i + 1:]
    elif arg in ('-e', '--command') and i + 1 < len(args):     # a command line, then its words
        command = shlex.split(args[i + 1]) + args[i + 2:]
    elif arg.startswith(('--command=', '-e=')):
        command = shlex.split(arg.split('=', 1)[1]) + args[i + 1:]
    if command is not None:
        break
name = os.path.basename(sys.argv[0])
if not command:
    sys.exit(f'{name} (the grader stands in for it): no command after -e, -x, -- or --command')
print(f"{name} (the grader stands in for it): runs {shlex.join(command)} in roslaunch's "
      f"terminal, as a window of its own would", file=sys.stderr, flush=True)
os.execvp(command[0], command)
"""


def terminal_stand_ins(folder):
    """TERMINAL, in `folder` (first on the submission's PATH), by each name of TERMINALS."""
    for name in TERMINALS:
        path = os.path.join(folder, name)
        with open(path, 'w') as f:
            f.write(TERMINAL)
        os.chmod(path, 0o755)


# The names a course's Noetic machine (Ubuntu 20.04, Python 3.8) runs ROS's
# python3 by and this one may lack: `python`, as a TA runs a script that says
# `#!/usr/bin/env python` (Noetic's is python3), and `python3.8` (a real
# class's `#!/usr/bin/env python3.8`, which Debian 12 cannot start).
INTERPRETERS = ('python', 'python3.8')


def interpreter_stand_ins(folder):
    """/usr/bin/python3 in `folder` (first on the submission's PATH), by each name of
    INTERPRETERS."""
    for name in INTERPRETERS:
        os.symlink('/usr/bin/python3', os.path.join(folder, name))


# What a course's ROS Noetic desktop machine offers a student's package that
# this machine may lay out otherwise. On /opt/ros/noetic every package's
# headers share one folder, roscpp's: a C++ package that includes
# "turtlesim/Pose.h" without naming turtlesim in its find_package builds
# there. Where roscpp's headers lie elsewhere (Debian: /usr/include) and
# turtlesim's are not beside them (the bundled simulator's are in this
# workspace), the compiler is told where they are (CPATH, which gcc
# searches as it does -I). The rest a desktop install has (numpy, tf, tf2,
# turtlesim's other executables) make deps installs or the simulator bundles.
ROSCPP_INCLUDES = ('/opt/ros/noetic/include', '/usr/include')


def course_environment(environ, shown=True):
    """Variables that give the submission what the course's machine would:
    {} where it has it already. Outside a sandbox (`shown` False) a folder
    behind one other users cannot pass is left out: gcc stops at a CPATH
    folder it cannot read (a checkout in /root, graded --no-sandbox)."""
    roscpp = next((folder for folder in ROSCPP_INCLUDES
                   if os.path.isfile(os.path.join(folder, 'ros', 'ros.h'))), None)
    if roscpp is None or os.path.isfile(os.path.join(roscpp, 'turtlesim', 'Pose.h')):
        return {}
    for prefix in filter(None, environ.get('CMAKE_PREFIX_PATH', '').split(':')):
        include = os.path.join(prefix, 'include')
        if os.path.isfile(os.path.join(include, 'turtlesim', 'Pose.h')):
            if not shown and closed_folder(include):
                return {}
            return {'CPATH': ':'.join(filter(None, [include, environ.get('CPATH', '')]))}
    return {}


def _cgroup_limits(memory_gib, processes, says):
    """A cgroup's limits (isolation.cgroups.Cgroup) for the grader's own processes: no CPU limit."""
    return {'memory': (int(memory_gib * GiB), says['memory']),
            'processes': (processes, says['processes']), 'cpu': (math.inf, lambda n: '')}


def _tail(path, size=2000):
    """The last `size` bytes of the file at `path`, as text ('' if unreadable)."""
    try:
        with open(path, 'rb') as f:
            f.seek(0, os.SEEK_END)
            f.seek(max(0, f.tell() - size))
            return f.read().decode('utf-8', 'replace')
    except OSError:
        return ''


def _read_to_end(fd, lines):
    with os.fdopen(fd, 'rb') as stream:
        lines.read(stream)


class WorldError(RuntimeError):
    """The grader's own world did not come up; the message says why."""


def stand_in(work):
    """A workspace in `work` whose turtlesim_node is the stand-in: its path,
    to be put first on the submission's CMAKE_PREFIX_PATH at launch."""
    folder = os.path.join(work, 'stand_in')
    os.makedirs(os.path.join(folder, 'lib', 'turtlesim'), exist_ok=True)
    open(os.path.join(folder, '.catkin'), 'w').close()
    script = os.path.join(folder, 'lib', 'turtlesim', 'turtlesim_node')
    with open(script, 'w') as f:
        f.write(STAND_IN)
    os.chmod(script, 0o755)
    return folder


def stand_in_started(folder, pids=None):
    """Whether roslaunch started the stand-in of `folder` (stand_in's): a
    process of it runs the stand-in, its parent roslaunch. Seen from
    outside, in the processes themselves: no file the submission can
    write (it owns its work folder) says so."""
    script = os.path.join(folder, 'lib', 'turtlesim', 'turtlesim_node').encode()
    for pid in pids if pids is not None else filter(str.isdigit, os.listdir('/proc')):
        argv, parent = _command_line(pid), _parent(pid)
        if script in argv[1:2] and any(a.endswith(b'roslaunch') for a in _command_line(parent)[:2]):
            return True
    return False


def _command_line(pid):
    try:
        with open(f'/proc/{pid}/cmdline', 'rb') as f:
            return f.read().split(b'\0')
    except OSError:
        return []


def _parent(pid):
    try:
        with open(f'/proc/{pid}/stat') as f:
            return int(f.read().rsplit(')', 1)[1].split()[1])
    except (OSError, ValueError, IndexError):
        return 0


def _world_env(master_uri, home):
    """The environment of the grader's master and simulator, at home in `home`."""
    env = {name: value for name, value in os.environ.items() if name in WORLD_VARIABLES}
    env['PYTHONPATH'] = os.path.join(SIM_FOLDER, 'src') + ':' + env.get('PYTHONPATH', '')
    env.update(HOME=home, ROS_HOME=home, TMPDIR=home, LANG='C.UTF-8',
               ROS_MASTER_URI=master_uri, ROS_IP='127.0.0.1',
               QT_QPA_PLATFORM='offscreen', PYTHONUNBUFFERED='1')
    return env


def _simulator_command(port, turtles):
    """The bundled simulator, started once the master on `port` listens: the
    simulator sets its parameters at once, and a master slow to start (a
    loaded machine) refused them."""
    return ['bash', '-c', 'for _ in $(seq 300); do (exec 3<>"/dev/tcp/127.0.0.1/$0") '
                          '2>/dev/null && break; sleep 0.1; done; exec "$@"', port,
            '/usr/bin/python3', os.path.join(SIM_FOLDER, 'scripts', 'turtlesim_node'),
            f'__name:={SIMULATOR[1:]}', f'_max_turtles:={turtles}']


class GradingWorld:
    """rosmaster and the simulator for one sandbox (`box`); `events` is the
    simulator's record as it comes, one dict a line ('k', 't', ...)."""

    def __init__(self, box, limits):
        self.box, self.limits, self.home = box, limits, None    # home: made at start, beside
        self.record = JsonLines(limits.record,
                                lambda e: isinstance(e, dict) and 'k' in e and 't' in e)
        self.events = self.record.items     # the record as it comes
        self.master = self.simulator = self.reader = self.cgroup = None

    def start(self):
        """Starts both and waits for the simulator's turtle1: the world is up."""
        if not os.path.isdir(SIM_FOLDER):
            raise WorldError(f'the bundled simulator is not at {SIM_FOLDER}: grade from the '
                             f"package's checkout (make build), not from an install space")
        self.home = self.box.beside.folder()
        if self.box.isolated:
            self.cgroup = self.box.beside.limited('w', _cgroup_limits(   # removed with the box
                self.limits.world_memory, self.limits.world_processes, WORLD_SAYS))
        log = open(os.path.join(self.home, 'world.log'), 'wb')
        port = self.box.master_uri.rsplit(':', 1)[1]
        # rosmaster itself, not roscore: roscore's roslaunch would leave its
        # children for init to reap, and none but rosmaster is needed
        self.master = self._started(['rosmaster', '--core', '-p', port, '-w', '3'], log)
        read_end, write_end = os.pipe()
        env = dict(_world_env(self.box.master_uri, self.home), TURTLESIM_RECORD_FD=str(write_end))
        self.simulator = self._started(_simulator_command(port, self.limits.turtles), log, env,
                                       (write_end,))
        os.close(write_end)
        log.close()
        self.reader = threading.Thread(target=_read_to_end, args=(read_end, self.record),
                                       daemon=True)
        self.reader.start()
        deadline = time.monotonic() + self.limits.up
        while not any(e['k'] == 'spawn' for e in self.events[:5]):
            if self.broken() or time.monotonic() > deadline or self.box.stopped:
                raise WorldError(f"the grader's master and simulator did not come up: "
                                 f"{self.broken() or 'no turtle within %g s' % self.limits.up}"
                                 f"; see {self.log_tail()!r}")
            time.sleep(0.05)

    def _started(self, argv, log, env=None, fds=()):
        joining = self.cgroup.joining() if self.cgroup is not None else []
        return self.box.started(subprocess.Popen(
            joining + self.box.beside.command(argv, True, [SIM_FOLDER], [self.home]),
            env=env or _world_env(self.box.master_uri, self.home),
            cwd=self.home, stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
            pass_fds=fds, start_new_session=True))

    @property
    def full(self):
        return self.record.full

    def broken(self):
        """Why the world is no longer whole (in words), or ''."""
        ended = next((e for e in self.events if e['k'] == 'end'), None)
        if ended is not None:
            return f"the grader's simulator was shut down: {ended.get('why', '?')}"
        if self.simulator is not None and self.simulator.poll() is not None:
            return f"the grader's simulator ended (exit {self.simulator.returncode})"
        if self.master is not None and self.master.poll() is not None:
            return f"the grader's ROS master was shut down (exit {self.master.returncode})"
        return ''

    def failed(self):
        """Whether the world broke of itself: its simulator ended, and not
        shut down (which a node of the submission's may ask, and the
        simulator records as 'end'). In a sandbox the submission runs as
        another user and cannot signal it: such an end is the grader's or
        the machine's (with --no-sandbox it could kill it, and fails alike
        when run again)."""
        return (self.simulator is not None and self.simulator.poll() is not None
                and not any(e['k'] == 'end' for e in self.events))

    def overflowed(self):
        """The limit of the world's that the submission reached, in words, or ''."""
        if self.record.full:
            return (f"more than {self.limits.record} changes in the grader's simulator: it "
                    f"stopped recording")
        if any(e['k'] == 'refused' and 'max_turtles' in e.get('why', '') for e in self.events):
            return (f"more than {self.limits.turtles} turtles at once: the grader's simulator refused "
                    f"the spawns past them")
        return self.cgroup.reached() if self.cgroup is not None else ''

    def log_tail(self):
        return _tail(os.path.join(self.home, 'world.log')) if self.home else ''

    def stop(self):
        """Ends both (and anything else of their user in the sandbox's
        namespace); the record read to its end."""
        # Their user's processes first: each bubblewrap reaps its own and
        # ends, and none is left for init to reap (a slow init shows them).
        self.box.beside.stop()
        for process in (self.simulator, self.master):
            if process is None:
                continue
            try:       # outside a sandbox it may run as the grader, whom beside.stop() spares
                process.wait(timeout=5 if self.box.isolated else 0.2)
            except subprocess.TimeoutExpired:
                try:
                    os.killpg(process.pid, signal.SIGKILL)
                except OSError:
                    pass
                process.wait()
        if self.reader is not None:
            self.reader.join(timeout=5)
        if self.cgroup is not None:
            self.cgroup.remove()


class Terminal:
    """roslaunch with a pseudo-terminal for its stdin and output, as in a
    terminal window; what it prints is kept."""

    def __init__(self, argv, box):
        self.box = box          # where nothing else ends its nodes, Ctrl-C first
        self.master, slave = pty.openpty()
        try:
            self.process = box.started(subprocess.Popen(argv, stdin=slave, stdout=slave,
                                                        stderr=slave, start_new_session=True))
        except BaseException:
            os.close(self.master)
            raise
        finally:
            os.close(slave)
        self.reader = Reader(os.dup(self.master))   # the reader's own: it closes it
        self.output = self.reader.output

    def type(self, keys):
        os.write(self.master, keys)

    def in_lines(self):
        """Whether it reads in lines, as input() does (canonical mode), not key by key."""
        return bool(termios.tcgetattr(self.master)[3] & termios.ICANON)

    def text(self, since=0):
        """What the terminal showed (from byte `since` on), as plain lines."""
        return plain(self.output.text(since))

    def stop(self):
        gentle = not (self.box.runs_as_its_user() or self.box.stopped)
        if gentle and self.process.poll() is None:
            self.process.send_signal(signal.SIGINT)
            try:
                self.process.wait(timeout=STOP_SECONDS)
            except subprocess.TimeoutExpired:
                pass
        if self.process.poll() is None:
            self.process.kill()
        self.process.wait()
        os.close(self.master)       # the reader reads its own copy to its end
        self.reader.stop()


class Watcher:
    """watch.py in the submission's network namespace: its events, as they
    come. Its ROS home and its errors are in a folder of the grader's own
    beside the sandbox, which the submission cannot reach."""

    def __init__(self, box, limits):
        self.cgroup = box.beside.limited('a', _cgroup_limits(
            limits.watcher_memory, limits.watcher_processes, WATCHER_SAYS)) if box.isolated else None
        self.most = limits.events
        self.home = box.beside.folder(as_user=False)
        env = dict(os.environ, ROS_MASTER_URI=box.master_uri, ROS_IP='127.0.0.1',
                   ROS_HOME=self.home, PYTHONUNBUFFERED='1')
        env.pop('ROS_LOG_DIR', None)
        self.errors = open(os.path.join(self.home, 'errors.txt'), 'w+')
        # Its working folder is its own: `-m` imports from there first, as
        # root, and the folder the grader was started in may hold a json.py.
        try:
            joining = self.cgroup.joining() if self.cgroup is not None else []
            self.process = box.started(subprocess.Popen(
                joining + box.beside.command(['/usr/bin/python3', '-m',
                                              'turtle_letters.autograder.watch']),
                stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=self.errors, env=env,
                cwd=self.home, start_new_session=True))
        except BaseException:
            self.errors.close()
            shutil.rmtree(self.home, ignore_errors=True)
            if self.cgroup is not None:
                self.cgroup.remove()
            raise
        self.lines = JsonLines(self.most, lambda e: isinstance(e, dict) and 'kind' in e)
        self.events = self.lines.items      # as they come
        threading.Thread(target=self.lines.read, args=(self.process.stdout,), daemon=True).start()

    @property
    def full(self):
        return self.lines.full

    def overflowed(self):
        """Why the grader stopped watching, or '': a run's events are capped,
        and what the watcher may hold (rospy takes a message of any length)."""
        if self.lines.full:
            return (f'more than {self.most} messages for the grader to watch (poses, '
                    f'/chatter): it stopped watching')
        return self.cgroup.reached() if self.cgroup is not None else ''

    def publish_p(self):
        """Publishes "P" on /chatter; False when the watcher is gone (a node
        of the submission took its name, or shut it down over XML-RPC)."""
        try:
            self.process.stdin.write(b'P\n')
            self.process.stdin.flush()
            return True
        except OSError:         # BrokenPipeError: it ended
            return False

    def stop(self):
        """Stops it; what it said on stderr, if anything (its own failure)."""
        self.process.kill()
        self.process.wait()
        if self.cgroup is not None:
            self.cgroup.remove()
        self.errors.seek(max(0, self.errors.seek(0, os.SEEK_END) - 4000))
        said = self.errors.read()
        self.errors.close()
        shutil.rmtree(self.home, ignore_errors=True)
        return said


class Lab:
    """One run's lab as the grader sets it up in `box`: its world (master
    and simulator), the submission's roslaunch (`argv`) in a terminal, and
    the watcher, started in that order; `stop` ends whatever of them was
    started, however far the start came."""

    def __init__(self, box, argv, limits):
        self.box, self.world = box, GradingWorld(box, limits)
        self.terminal = self.watcher = None
        try:
            self.world.start()
            self.terminal = Terminal(argv, box)
            self.watcher = Watcher(box, limits)
        except BaseException:
            self.stop()
            raise

    def going(self):
        """Whether the run is still worth watching, the one place a run asks:
        roslaunch runs, and the world may be watched (watchable)."""
        return self.terminal.process.poll() is None and self.watchable()

    def watchable(self):
        """Whether the world may still be watched, roslaunch running or not:
        the sandbox within its limits and not stopped, the watcher's events
        and the simulator's record within theirs and whole."""
        return self.box.going() and not self.watcher.full and not self.world.full and \
            not self.world.broken()

    def limit(self):
        """The limits reached, of the sandbox, the watcher and the world, in words, or ''."""
        return '; '.join(filter(None, [self.box.reached(), self.watcher.overflowed(),
                                       self.world.overflowed()]))

    def stop(self):
        """roslaunch ended (Ctrl-C first), then the world, then the watcher:
        what the watcher said on stderr ('' if none, or never started)."""
        if self.terminal is not None:
            self.terminal.stop()
        self.world.stop()
        return self.watcher.stop() if self.watcher is not None else ''
