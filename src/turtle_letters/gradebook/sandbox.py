"""Where a submission's code runs, and nothing of it outside: a network
namespace of its own with loopback only (so its roscore is its own, on the
usual port), and in it Debian's bubblewrap with the rules in RULES. The
grader's watcher (watch.py) joins the namespace, not the sandbox.

`problem()` tries the sandbox out and says in one line what keeps it from
being made here (no root for the namespace, no bubblewrap, a container that
forbids namespaces); the grader then refuses to grade. Only `isolated=False`
(grade_class.py --no-sandbox, for a container that is a sandbox already,
as Gradescope's is) runs a submission without one: then each gets a master
port of its own, and nothing more.
"""
import itertools
import os
import shutil
import socket
import subprocess
import tempfile

MASTER_PORT = 11311
# What the sandbox sees. The system is read-only; only the work folder
# (the submission's copy, its build and its home) and a private /tmp are
# writable; the folders given as `hidden` (the class, the roster, the
# results) are covered by empty ones.
RULES = [
    (['--ro-bind', '/', '/'], 'the system, read-only'),
    (['--dev', '/dev'], 'a private /dev'),
    (['--proc', '/proc'], 'its own processes only'),
    (['--tmpfs', '/tmp'], 'a private /tmp'),
    (['--tmpfs', '/root'], "nothing of root's home"),
    (['--tmpfs', '/home'], "nothing of the users' homes"),
    (['--cap-drop', 'ALL'], 'no capability of root (bubblewrap keeps them for root)'),
    (['--unshare-pid'], 'its own process tree, gone when the sandbox ends'),
    (['--unshare-ipc', '--unshare-uts'], 'no shared memory or host name of the machine'),
    (['--die-with-parent'], 'ends when the grader ends'),
    (['--new-session'], 'cannot type into the terminal the grader runs in'),
]
_NUMBERS = itertools.count(1)
COVERED = ('/tmp', '/root', '/home')     # the folders RULES covers with empty ones
ENVIRONMENT = ('CMAKE_PREFIX_PATH', 'ROS_PACKAGE_PATH', 'PYTHONPATH', 'LD_LIBRARY_PATH')


def underlays(environ):
    """The folders under COVERED that the ROS environment needs (this
    package's workspace, and the checkout its links point into), as the
    top folders holding them: shown read-only in the sandbox."""
    tops = set()
    for name in ENVIRONMENT:
        for entry in filter(None, environ.get(name, '').split(':')):
            for path in {os.path.abspath(entry), os.path.realpath(entry)} | _link_targets(entry):
                for covered in COVERED:
                    if path.startswith(covered + '/'):
                        tops.add(os.path.join(covered, path[len(covered) + 1:].split('/')[0]))
    return sorted(t for t in tops if os.path.isdir(t))


def _link_targets(folder):
    """Where the links in `folder`'s packages point (build.sh links this package's parts)."""
    targets = set()
    for package in (os.listdir(folder) if os.path.isdir(folder) else []):
        inside = os.path.join(folder, package)
        if os.path.isdir(inside) and not os.path.islink(inside):
            targets.update(os.path.realpath(os.path.join(inside, part))
                           for part in os.listdir(inside)
                           if os.path.islink(os.path.join(inside, part)))
    return targets


def problem():
    """What keeps the sandbox from being made here, in one line, or None."""
    if os.geteuid() != 0:
        return 'grading needs root: each submission runs in a network namespace of its own'
    for tool, package in (('bwrap', 'bubblewrap'), ('ip', 'iproute2')):
        if shutil.which(tool) is None:
            return f'{tool} is not installed (make deps installs {package})'
    work = tempfile.mkdtemp(prefix='turtle_letters_sandbox_check_')
    try:
        with Sandbox(work) as box:
            tried = subprocess.run(box.inside(['true'], {}), stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, universal_newlines=True)
        if tried.returncode != 0:
            return f'bubblewrap cannot make a sandbox here: {tried.stdout.strip()}'
    except subprocess.CalledProcessError as e:
        return f'no network namespace can be made here: {e.stderr.strip() if e.stderr else e}'
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return None


def _free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


class Sandbox:
    """A network namespace with loopback up, and commands to run in it:
    `inside` for the submission's, in bubblewrap; `beside` for the grader's."""

    def __init__(self, work, hidden=(), isolated=True, cpu=None):
        self.work, self.isolated = os.path.abspath(work), isolated
        # One core of its own for the submission and its watcher, alone or
        # beside others: a busy loop beside it cannot slow its simulator.
        self.pinned = ['taskset', '-c', str(cpu)] if cpu is not None else []
        self.hidden = [os.path.abspath(h) for h in hidden if os.path.exists(h)]
        self.namespace = f'tlgrade{os.getpid()}n{next(_NUMBERS)}'
        port = MASTER_PORT if isolated else _free_port()
        self.master_uri = f'http://127.0.0.1:{port}'

    def __enter__(self):
        if self.isolated:
            for command in (['ip', 'netns', 'add', self.namespace],
                            ['ip', '-n', self.namespace, 'link', 'set', 'lo', 'up']):
                subprocess.run(command, check=True, stderr=subprocess.PIPE,
                               universal_newlines=True)
        return self

    def __exit__(self, *_):
        if self.isolated:
            subprocess.run(['ip', 'netns', 'delete', self.namespace], check=False)

    def beside(self, argv):
        if not self.isolated:
            return self.pinned + list(argv)
        return self.pinned + ['ip', 'netns', 'exec', self.namespace] + list(argv)

    def inside(self, argv, env):
        """`argv` in the sandbox, with only `env` set."""
        if not self.isolated:
            return self.pinned + ['env', '-i'] + [f'{k}={v}' for k, v in sorted(env.items())] + \
                list(argv)
        rules = [option for options, _ in RULES for option in options]
        for path in underlays(os.environ):
            rules += ['--ro-bind', path, path]
        for path in self.hidden:
            rules += ['--tmpfs', path] if os.path.isdir(path) else ['--ro-bind', '/dev/null', path]
        rules += ['--bind', self.work, self.work, '--chdir', self.work, '--clearenv']
        for name, value in sorted(env.items()):
            rules += ['--setenv', name, value]
        return self.beside(['bwrap'] + rules + ['--'] + list(argv))
