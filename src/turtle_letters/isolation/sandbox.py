"""Where a submission's code runs, and nothing of it outside: a network
namespace of its own with loopback only (so the master the grader runs
for it is its own, on the usual port), and in it Debian's bubblewrap
with the rules in RULES, run as an unprivileged user of its own (as_user), in a cgroup of its own with
its Caps and the cores it was given. Beside it, in its namespace but not
its sandbox, the grader may run processes of its own (Beside): as
itself, or as a user of the grader's that is never the submission's,
with folders and cgroups of their own; `stop` ends them with the rest.
The sandbox knows nothing of what they are.

`problem()` tries the sandbox out and says in one line what keeps it from
being made here (no root for the namespace, no bubblewrap, no cgroup with
memory and pids, a container that forbids namespaces); the grader then
refuses to grade. Only `isolated=False` (grade_class.py --no-sandbox, for a
container that is a sandbox already, as Gradescope's is) runs a submission
without one: then each gets a master port of its own, and nothing more.
"""
import contextlib
import itertools
import os
import shutil
import signal
import socket
import stat
import subprocess
import tempfile
import time
from typing import NamedTuple

from .cgroups import Cgroup, CgroupError
from .files import remove_tree
from .stale import NAMESPACE, SCRATCH

MASTER_PORT = 11311
# The users submissions run as, one for each graded at once: ids far above
# those a system gives out (under 65534) and the usual subuid ranges (100000 on).
USER = 2000000000
USERS = 256
GiB = 1024 ** 3
# What the sandbox sees. The system is read-only; only the work folder
# (the submission's copy, its build and its home, bound after these rules)
# and a private /tmp and /dev/shm ({scratch}: folders of the sandbox's own)
# are writable; the folders given as `hidden` (the class, the roster, the
# results) are covered by empty ones. (No --perms or --size: Ubuntu 20.04's
# bubblewrap 0.4 lacks them.)
RULES = [
    (['--ro-bind', '/', '/'], 'the system, read-only'),
    (['--dev', '/dev'], 'a private /dev'),
    (['--bind', '{scratch}/shm', '/dev/shm'], 'a private /dev/shm, writable'),
    (['--proc', '/proc'], 'its own processes only'),
    (['--bind', '{scratch}/tmp', '/tmp'], 'a private /tmp, writable'),
    (['--tmpfs', '/root'], "nothing of root's home"),
    (['--tmpfs', '/home'], "nothing of the users' homes"),
    (['--tmpfs', '/run'], "none of the machine's service sockets (D-Bus, systemd)"),
    (['--unshare-pid'], 'its own process tree, gone when the sandbox ends'),
    (['--unshare-ipc', '--unshare-uts'], 'no shared memory or host name of the machine'),
    (['--die-with-parent'], 'ends when the grader ends'),
    (['--new-session'], 'cannot type into the terminal the grader runs in'),
]

# What a user of the grader's beside the sandbox sees: the system
# read-only, and no one's home, the grader's included.
BESIDE_RULES = [
    (['--ro-bind', '/', '/'], 'the system, read-only'),
    (['--dev', '/dev'], 'a /dev of its own (/dev/null writable)'),
    (['--tmpfs', '/root'], "nothing of root's home"),
    (['--tmpfs', '/home'], "nothing of the users' homes"),
    (['--die-with-parent'], 'ends when the grader ends'),
]


def as_user(user):
    """Who runs the command inside: an unprivileged user, with no capability
    (bubblewrap run as root keeps them) and no way to gain one."""
    return ['setpriv', f'--reuid={user}', f'--regid={user}', '--clear-groups',
            '--inh-caps=-all', '--bounding-set=-all', '--no-new-privs', '--']


class Caps(NamedTuple):
    """What all of a submission's processes may use together (the grader's
    rubric file declares how much, and why): memory (bytes, the files in
    its /tmp included) and tasks, held by the kernel in a cgroup of its
    own; CPU seconds, watched, the run stopped at them; its writable space,
    a tmpfs of its own (bytes; its pages count in its memory too), and the
    files it may make there."""
    memory: int
    processes: int
    cpu: float
    disk: int
    files: int


# What each limit reached says.
SAYS = {
    'memory': lambda n: f'memory limit of {n / GiB:g} GiB reached',
    'processes': lambda n: f'process limit of {n} reached (threads count)',
    'cpu': lambda n: f'CPU time limit of {n:g} s reached',
    'disk': lambda n: f'disk limit of {n / GiB:g} GiB reached (its files, /tmp and /dev/shm '
                      f'together)',
}
PROBE = Caps(memory=GiB // 4, processes=64, cpu=10, disk=GiB // 64, files=1000)  # `problem`'s try
TRIAL_SECONDS = 60     # for `problem`'s try to run `true` (it takes well under 1 s)
FULL = 1 << 20          # bytes free under which its space counts as full
_NUMBERS = itertools.count(1)
COVERED = ('/tmp', '/root', '/home', '/run')     # the folders RULES covers with empty ones
ENVIRONMENT = ('CMAKE_PREFIX_PATH', 'ROS_PACKAGE_PATH', 'PYTHONPATH', 'LD_LIBRARY_PATH')


def underlays(environ, also=()):
    """What the ROS environment needs (and `also`) that a user of ours could
    not reach as it lies: under COVERED, or under a folder closed to other
    users (a 0700 home holding the checkout). Shown read-only in the
    sandbox, folder by folder, never the home or top folder holding it:
    each entry of ENVIRONMENT (this package's workspace), and where the
    links of its package path lead (the checkout's parts that build.sh links)."""
    needed = {os.path.abspath(path) for path in also}
    for name in ENVIRONMENT:
        for entry in filter(None, environ.get(name, '').split(':')):
            needed |= {os.path.abspath(entry), os.path.realpath(entry)} | _link_targets(entry)
    needed = {path for path in needed if _cover(path) and os.path.exists(path)}
    return sorted(path for path in needed
                  if not any(path.startswith(other + '/') for other in needed))


def closed_folder(path):
    """The outermost folder above `path` that other users cannot pass
    through (no execute bit for them: a 0700 home), or None."""
    parent = '/'
    for part in os.path.abspath(path).strip('/').split('/')[:-1]:
        parent = os.path.join(parent, part)
        try:
            if not os.stat(parent).st_mode & stat.S_IXOTH:
                return parent
        except OSError:
            return None
    return None


def _cover(path, covered=COVERED):
    """The folder above `path` that is covered with an empty one: of
    `covered`, else the closed folder above it; None if neither."""
    return next((folder for folder in covered if path.startswith(folder + '/')),
                closed_folder(path))


def _covered_parents(path, covered=COVERED):
    """The folders between the folder that covers `path` and it, outermost first."""
    top, parents = _cover(path, covered), []
    parent = os.path.dirname(path)
    while top is not None and parent != top:
        parents.insert(0, parent)
        parent = os.path.dirname(parent)
    return parents


def _link_targets(folder):
    """Where the links in `folder` and in its packages point (build.sh
    links this package's parts, and the bundled turtlesim whole)."""
    targets = set()
    for package in (os.listdir(folder) if os.path.isdir(folder) else []):
        inside = os.path.join(folder, package)
        if os.path.islink(inside):
            targets.add(os.path.realpath(inside))
        elif os.path.isdir(inside):
            targets.update(os.path.realpath(os.path.join(inside, part))
                           for part in os.listdir(inside)
                           if os.path.islink(os.path.join(inside, part)))
    return targets


def problem():
    """What keeps the sandbox from being made here, in one line, or None."""
    if os.geteuid() != 0:
        return 'grading needs root: each submission runs in a network namespace of its own'
    for tool, package in (('bwrap', 'bubblewrap'), ('ip', 'iproute2'), ('setpriv', 'util-linux')):
        if shutil.which(tool) is None:
            return f'{tool} is not installed (make deps installs {package})'
    try:
        with Sandbox(PROBE, cpu=min(os.sched_getaffinity(0))) as box:
            # its own session, as _run's, and bounded: on CI, two Ctrl-C
            # as it ran once left the grader waiting here over 120 s
            tried = subprocess.run(box.inside(['true'], {}), stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, universal_newlines=True,
                                   start_new_session=True, timeout=TRIAL_SECONDS)
        if tried.returncode != 0:
            return f'bubblewrap cannot make a sandbox here: {tried.stdout.strip()}'
    except CgroupError as e:
        return str(e)
    except OSError as e:
        return f'no cgroup for the sandbox\'s limits can be made here: {e}'
    except subprocess.CalledProcessError as e:
        return f'no tmpfs or network namespace can be made here: ' \
               f'{e.stderr.strip() if e.stderr else e}'
    except subprocess.TimeoutExpired:
        return f'bubblewrap ran no command within {TRIAL_SECONDS} s: the sandbox is not usable here'
    return None


def _all_pids():
    return filter(str.isdigit, os.listdir('/proc'))


def _namespace_pids(namespace):
    return subprocess.run(['ip', 'netns', 'pids', namespace], stdout=subprocess.PIPE,
                          stderr=subprocess.DEVNULL, universal_newlines=True,
                          start_new_session=True).stdout.split()     # not the grader's Ctrl-C


def kill_user(user, pids=_all_pids):
    """Kills every process of `user` among `pids()` (a submission's outside
    a sandbox, or those beside it: double forks and setsid included, as no process
    of it can change user)."""
    killed = set()
    for _ in range(100):
        for pid in pids():
            try:
                if os.stat(f'/proc/{pid}').st_uid == user:
                    os.kill(int(pid), signal.SIGKILL)
                    killed.add(pid)
            except OSError:
                continue
        # gone once reaped: a zombie has left its namespace's list, not /proc
        killed = {pid for pid in killed if os.path.exists(f'/proc/{pid}')}
        if not killed and not any(_owned_by(pid, user) for pid in pids()):
            return
        time.sleep(0.05)


def wait_reaped(users, seconds=10.0):
    """Waits until no process of `users` is ending or ended unreaped: ones
    killed while a parent of theirs was dying went to init to reap, which
    takes a second or more on some machines (a forced exit that leaves
    at once left one so on CI)."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline and any(_ending(pid, users) for pid in _all_pids()):
        time.sleep(0.05)


def _ending(pid, users):
    """Whether `pid` is of `users` and a zombie or ending (its command line is gone)."""
    try:
        if os.stat(f'/proc/{pid}').st_uid not in users:
            return False
        with open(f'/proc/{pid}/stat') as f:
            state = f.read().rsplit(')', 1)[1].split()[0]
        with open(f'/proc/{pid}/cmdline', 'rb') as f:
            return state in 'ZX' or not f.read(1)
    except (OSError, IndexError):
        return False


def _owned_by(pid, user):
    try:
        return os.stat(f'/proc/{pid}').st_uid == user
    except OSError:
        return False


def _run(command, check=True):
    """A command of the grader's, in a session of its own (Ctrl-C is the grader's to act on)."""
    subprocess.run(command, check=check, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                   universal_newlines=True, start_new_session=True)


def _free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


class Sandbox:
    """A network namespace with loopback up, a cgroup with its `caps`, a work
    folder, and commands to run in them: `inside` for the submission's, in
    bubblewrap as its own user; `beside` (a Beside) for the grader's. Its work
    folder, /tmp and /dev/shm are on a tmpfs of `caps.disk` bytes of its own.
    slot: which of those graded at once (its user is USER + slot); cpu: its core."""

    def __init__(self, caps: Caps, hidden=(), isolated=True, cpu=None, slot=0):
        self.isolated, self.caps = isolated, caps
        self.cpus = [cpu] if cpu is not None else None
        self.user = USER + slot % USERS
        self.hidden = [os.path.abspath(h) for h in hidden if os.path.exists(h)]
        self.namespace = NAMESPACE.format(pid=os.getpid()) + str(next(_NUMBERS))
        port = MASTER_PORT if isolated else _free_port()
        self.master_uri = f'http://127.0.0.1:{port}'
        self.cgroup = self.scratch = self.work = self.beside = None
        self.stopped = False    # grading was stopped (Ctrl-C): what runs in it is ended
        self.sessions = []      # process groups started for it

    def __enter__(self):
        self.scratch = tempfile.mkdtemp(prefix=SCRATCH.format(pid=os.getpid()))
        self.work = os.path.join(self.scratch, 'work')
        self.beside = Beside(self.scratch, self.namespace, self.user + USERS, self.isolated,
                             self.cpus)
        if not self.isolated:       # the user reaches its work folder, and no more of it
            os.chmod(self.scratch, 0o711)
            os.mkdir(self.work, 0o700)
            return self
        try:
            _writable_space(self.scratch, self.user, self.caps)
            os.chmod(self.scratch, 0o711)    # the folders beside it are here
            _run(['ip', 'netns', 'add', self.namespace])
            _run(['ip', '-n', self.namespace, 'link', 'set', 'lo', 'up'])
            self.cgroup = Cgroup(self.namespace, _cgroup_limits(self.caps), self.cpus)
        except (OSError, subprocess.CalledProcessError):
            self.__exit__()
            raise
        return self

    def runs_as_its_user(self):     # in a sandbox, or outside one as root
        return self.isolated or os.geteuid() == 0

    def hand_over(self):
        """The work folder, as the grader filled it, made the submission's user's."""
        if self.runs_as_its_user():
            _run(['chown', '-R', '-h', f'{self.user}:{self.user}', self.work])

    def __exit__(self, *_):
        if self.cgroup is not None:
            self.cgroup.remove()
        self.beside.remove()
        if not self.isolated and self.runs_as_its_user():     # no PID namespace: by its user
            kill_user(self.user)
        if self.isolated:
            _run(['ip', 'netns', 'delete', self.namespace], check=False)
            _run(['umount', '--lazy', self.scratch], check=False)
        remove_tree(self.scratch)

    def users(self):
        """Whom its processes run as: the submission's user and the one beside it."""
        return {self.user, self.beside.user}

    def started(self, process):
        """`process`, which the grader started for it in a session of its
        own, to be ended by `stop` (at once, if it came too late)."""
        self.sessions.append(process.pid)
        if self.stopped:
            self.stop()
        return process

    def stop(self):
        """Ends everything it runs, for good (the grader was stopped)."""
        self.stopped = True
        self.beside.stop()      # first: a session's bubblewrap reaps its user's processes
        for pid in self.sessions:
            with contextlib.suppress(OSError):
                os.killpg(pid, signal.SIGKILL)
        if self.cgroup is not None:
            self.cgroup.kill()
        if not self.isolated and self.runs_as_its_user():
            kill_user(self.user)

    def going(self):
        """Whether what runs in it may go on: not stopped, and no limit reached."""
        return not self.stopped and not self.reached()

    def reached(self):
        """The words of the first limit the submission reached, or ''."""
        if self.cgroup is None:
            return ''
        return SAYS['disk'](self.caps.disk) if _full(self.scratch) else self.cgroup.reached()

    def inside(self, argv, env):
        """`argv` in the sandbox, with only `env` set."""
        if not self.isolated:
            return _pinned(self.cpus) + ['env', '-i'] + \
                [f'{k}={v}' for k, v in sorted(env.items())] + \
                (as_user(self.user) if self.runs_as_its_user() else []) + list(argv)
        rules = _rules(self.scratch, self.work, self.hidden) + ['--clearenv'] + \
            [option for name, value in sorted(env.items()) for option in ('--setenv', name, value)]
        return self.cgroup.joining() + ['ip', 'netns', 'exec', self.namespace, 'bwrap'] + \
            rules + ['--'] + as_user(self.user) + list(argv)


class Beside:
    """What the grader runs beside a sandbox, in its network namespace but
    not its sandbox: commands as the grader, or as `user`, a user of the
    grader's that is never the submission's; folders for them; cgroups of
    their own. `stop` ends that user's processes; `remove` all of it."""

    def __init__(self, scratch, namespace, user, isolated, cpus):
        self.scratch, self.namespace, self.user = scratch, namespace, user
        self.isolated, self.cpus = isolated, cpus
        self.folders, self.cgroups = itertools.count(1), []

    def command(self, argv, as_user=False, readable=(), writable=()):
        """`argv` in the namespace: as the grader, or as its user (_as_user_beside)."""
        run = _as_user_beside(self.user, argv, readable, writable, self.isolated) if as_user \
            else list(argv)
        return _pinned(self.cpus) + (['ip', 'netns', 'exec', self.namespace] if self.isolated
                                     else []) + run

    def folder(self, as_user=True):
        """A new folder, gone with the sandbox (a forced exit's too): its
        user's alone, or the grader's alone."""
        folder = os.path.join(self.scratch, f'beside{next(self.folders)}')
        os.mkdir(folder, 0o700)
        if as_user:
            os.chown(folder, self.user, self.user)
        return folder

    def limited(self, suffix, limits):
        """A cgroup of `limits` for processes beside it, removed with it."""
        self.cgroups.append(Cgroup(self.namespace + suffix, limits))
        return self.cgroups[-1]

    def stop(self):
        """Ends its user's processes: those in the namespace, as another
        grader's sandbox of the same slot has the same user beside it."""
        kill_user(self.user, lambda: _namespace_pids(self.namespace) if self.isolated
                  else _all_pids())
        for cgroup in self.cgroups:
            cgroup.kill()

    def remove(self):
        for cgroup in self.cgroups:
            cgroup.remove()
        self.stop()


def _cgroup_limits(caps):
    """What its cgroup holds (Cgroup's limits): memory, tasks and CPU, each with its words."""
    return {name: (getattr(caps, name), SAYS[name]) for name in ('memory', 'processes', 'cpu')}


def _full(folder):
    """Whether the space `folder` is on is full: under FULL bytes or no file left."""
    space = os.statvfs(folder)
    return space.f_bavail * space.f_frsize < FULL or space.f_favail == 0


def _pinned(cpus):
    """The core given, by taskset (in a sandbox, its cgroup's cpuset holds it)."""
    return ['taskset', '-c', str(cpus[0])] if cpus else []


def _writable_space(scratch, user, caps):
    """At `scratch`, a tmpfs of caps.disk bytes and caps.files files holding
    the submission's work folder, /tmp and /dev/shm, all `user`'s."""
    _run(['mount', '-t', 'tmpfs', '-o', f'size={caps.disk},nr_inodes={caps.files},mode=0700',
          'turtle_letters_sandbox', scratch])
    for name, mode in (('work', 0o700), ('tmp', 0o1777), ('shm', 0o1777)):
        os.mkdir(os.path.join(scratch, name))
        os.chown(os.path.join(scratch, name), user, user)
        os.chmod(os.path.join(scratch, name), mode)


def _shown(binds, covered):
    """bubblewrap's options that show each (path, bind option) of `binds`,
    in a view where `covered` are empty already, and not the folders that
    hold them: a closed folder above one covered with an empty one, the
    folders between made (bubblewrap would make them 0700)."""
    rules = []
    for closed in sorted({_cover(path, covered) for path, _ in binds} - {None} - set(covered)):
        rules += ['--tmpfs', closed]
    for path, bind in binds:
        rules += [option for parent in _covered_parents(path, covered)
                  for option in ('--dir', parent)]
        rules += [bind, path, path]
    return rules


def _as_user_beside(user, argv, readable, writable, isolated):
    """`argv` as `user` beside a sandbox, in a bubblewrap of BESIDE_RULES
    that also shows the `readable` and `writable` folders: so it reaches
    what it runs wherever the package lies (a checkout in a 0700 home),
    and no one's home. Without a sandbox (a container that is one already),
    no bubblewrap: as `user` where it reaches what it runs, else as the
    grader (a checkout in /root, graded --no-sandbox), whom the submission's
    user cannot signal either."""
    if not isolated:
        return list(argv) if any(closed_folder(path) for path in readable) else \
            as_user(user) + list(argv)
    return ['bwrap'] + _beside_rules(readable, writable) + ['--'] + as_user(user) + list(argv)


def _beside_rules(readable, writable):
    """bubblewrap's options for a user beside the sandbox: BESIDE_RULES,
    what the ROS environment and `readable` need, and `writable`."""
    binds = [(path, '--ro-bind') for path in underlays(os.environ, readable)] + \
        [(path, '--bind') for path in writable]
    return [option for options, _ in BESIDE_RULES for option in options] + \
        _shown(binds, ('/root', '/home'))


def _rules(scratch, work, hidden):
    """bubblewrap's options: RULES, what the ROS environment needs under
    the folders they cover, `hidden` covered, and `work`, writable."""
    rules = [option.format(scratch=scratch) for options, _ in RULES for option in options]
    rules += _shown([(path, '--ro-bind') for path in underlays(os.environ)] +
                    [(work, '--bind')], COVERED)
    for path in hidden:
        rules += ['--tmpfs', path] if os.path.isdir(path) else ['--ro-bind', '/dev/null', path]
    return rules + ['--chdir', work]
