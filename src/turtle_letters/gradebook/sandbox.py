"""Where a submission's code runs, and nothing of it outside: a network
namespace of its own with loopback only (so its roscore is its own, on the
usual port), and in it Debian's bubblewrap with the rules in RULES. The
grader's watcher (watch.py) joins the namespace, not the sandbox.

Needs root, for the namespace (CI runs as root); `problem()` says in one
line what is missing, and the grader then refuses to grade.
"""
import itertools
import os
import shutil
import subprocess

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
    (['--unshare-pid'], 'its own process tree, gone when the sandbox ends'),
    (['--unshare-ipc', '--unshare-uts'], 'no shared memory or host name of the machine'),
    (['--die-with-parent'], 'ends when the grader ends'),
    (['--new-session'], 'cannot type into the terminal the grader runs in'),
]
_NUMBERS = itertools.count(1)


def problem():
    """What keeps the sandbox from being made here, in one line, or None."""
    if os.geteuid() != 0:
        return 'grading needs root: each submission runs in a network namespace of its own'
    for tool in ('bwrap', 'ip'):
        if shutil.which(tool) is None:
            return f'{tool} is not installed (make deps installs bubblewrap and iproute2)'
    return None


class Sandbox:
    """A network namespace with loopback up, and commands to run in it:
    `inside` for the submission's, in bubblewrap; `beside` for the grader's."""

    def __init__(self, work, hidden=()):
        self.work = os.path.abspath(work)
        self.hidden = [os.path.abspath(h) for h in hidden if os.path.exists(h)]
        self.namespace = f'tlgrade{os.getpid()}n{next(_NUMBERS)}'

    def __enter__(self):
        subprocess.run(['ip', 'netns', 'add', self.namespace], check=True)
        subprocess.run(['ip', '-n', self.namespace, 'link', 'set', 'lo', 'up'], check=True)
        return self

    def __exit__(self, *_):
        subprocess.run(['ip', 'netns', 'delete', self.namespace], check=False)

    def beside(self, argv):
        return ['ip', 'netns', 'exec', self.namespace] + list(argv)

    def inside(self, argv, env):
        """`argv` in the sandbox, with only `env` set."""
        rules = [option for options, _ in RULES for option in options]
        for path in self.hidden:
            rules += ['--tmpfs', path] if os.path.isdir(path) else ['--ro-bind', '/dev/null', path]
        rules += ['--bind', self.work, self.work, '--chdir', self.work, '--clearenv']
        for name, value in sorted(env.items()):
            rules += ['--setenv', name, value]
        return self.beside(['bwrap'] + rules + ['--'] + list(argv))
