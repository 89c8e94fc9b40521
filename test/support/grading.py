"""What the class tests look at around a grading: the tree of files a
submission could reach, and whatever a grading could leave behind. No ROS
here."""
import glob
import hashlib
import os
import pathlib
import subprocess
import tempfile
import threading
import time

from support.children import readable_env

# turtle_letters.isolation.sandbox.USER(S): the submissions' users, then the grader's beside them
SANDBOX_USERS = range(2000000000, 2000000000 + 2 * 256)
CGROUPS = '/sys/fs/cgroup'
# The folders a grading makes in /tmp (a submission's work folder, and the
# grader's folders beside it, are in its sandbox's)
KINDS_OF_FOLDER = ('turtle_letters_sandbox_', 'turtle_letters_gradescope_')


def package_caps():
    """The sandbox's caps of the package rubric's limits, as the grader uses them."""
    from turtle_letters.autograder.cli import default_limits
    from turtle_letters.autograder.session import caps
    return caps(default_limits())


def tree_hash(top):
    """A hash of every file under `top`: its path, mode and bytes."""
    digest = hashlib.sha256()
    for folder, folders, files in sorted(os.walk(top)):
        folders.sort()
        for name in sorted(files):
            path = os.path.join(folder, name)
            digest.update(path.encode() + oct(os.lstat(path).st_mode).encode())
            if os.path.isfile(path) and not os.path.islink(path):
                with open(path, 'rb') as f:
                    digest.update(f.read())
    return digest.hexdigest()


def grade_class(*args, timeout=900, cwd=None, **env):
    return subprocess.run(['rosrun', 'turtle_letters', 'grade_class.py', *args],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, cwd=cwd,
                          universal_newlines=True, env=readable_env(**env), timeout=timeout)


def started_grading(*args):
    """grade_class.py started as from a terminal: in a session of its own,
    so that a test can send its process group Ctrl-C as the terminal would."""
    return subprocess.Popen(['rosrun', 'turtle_letters', 'grade_class.py', *args],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, env=readable_env(), start_new_session=True)


def peak_memory_kb(process):
    """Waits for `process` to end; the most memory it held (VmHWM, kB) and what it printed."""
    printed, peak = [], 0
    reader = threading.Thread(target=lambda: printed.extend(process.stdout), daemon=True)
    reader.start()
    while process.poll() is None:
        try:
            with open(f'/proc/{process.pid}/status') as f:
                peak = max([peak] + [int(line.split()[1]) for line in f
                                     if line.startswith('VmHWM:')])
        except (OSError, ValueError):
            pass
        time.sleep(0.2)
    reader.join(timeout=10)
    return peak, ''.join(printed)


def sandbox_processes():
    """pid: command line of each process run by the sandbox's user."""
    found = {}
    for pid in filter(str.isdigit, os.listdir('/proc')):
        try:
            if os.stat(f'/proc/{pid}').st_uid in SANDBOX_USERS:
                with open(f'/proc/{pid}/cmdline', 'rb') as f:
                    found[int(pid)] = f.read().replace(b'\0', b' ').decode().strip()
        except OSError:
            continue
    return found


def leftovers(before=None):
    """What a grading left: processes from its work folders or of the
    sandbox's users (but those in `before`); network namespaces, cgroups,
    the sandboxes' tmpfs mounts, and work or scratch folders."""
    processes = subprocess.run(['pgrep', '-af', '|'.join(KINDS_OF_FOLDER)], stdout=subprocess.PIPE,
                               universal_newlines=True).stdout.splitlines()
    processes += [f'{pid} {line}' for pid, line in sandbox_processes().items()
                  if pid not in (before or {})]
    namespaces = subprocess.run(['ip', 'netns', 'list'], stdout=subprocess.PIPE,
                                universal_newlines=True).stdout
    cgroups = glob.glob(f'{CGROUPS}/**/tlgrade*', recursive=True)
    folders = [folder for kind in KINDS_OF_FOLDER
               for folder in glob.glob(os.path.join(tempfile.gettempdir(), f'{kind}*'))]
    with open('/proc/mounts') as f:
        folders += [line.split()[1] for line in f if line.startswith('turtle_letters_sandbox ')]
    return processes, [n for n in namespaces.split() if n.startswith('tlgrade')] + cgroups + \
        folders


def nest(top, depth):
    """`depth` folders one in another under `top`, each made relative to the
    last (a path that long is refused), as a hostile zip may hold them."""
    here = os.open(str(top), os.O_RDONLY)
    for _ in range(depth):
        os.mkdir('d', dir_fd=here)
        deeper = os.open('d', os.O_RDONLY, dir_fd=here)
        os.close(here)
        here = deeper
    os.close(here)


def container(writable):
    """A bubblewrap container of a test's own, as Gradescope's is one, for
    --no-sandbox runs: the system read-only, no network but its loopback,
    `writable` writable, the ROS environment's folders under /tmp shown (a
    checkout there, as CI's may be); the folders above each made 0755, so a
    cadet's user reaches them (bubblewrap would make them 0700)."""
    from turtle_letters.isolation.sandbox import underlays
    box = ['bwrap', '--ro-bind', '/', '/', '--dev', '/dev', '--proc', '/proc', '--tmpfs', '/tmp']
    for path in underlays(os.environ):
        box += _reachable(path) + ['--ro-bind', path, path]
    return box + _reachable(writable) + ['--bind', str(writable), str(writable),
                                         '--unshare-net', '--unshare-pid', '--die-with-parent',
                                         '--']


def _reachable(path):
    """bubblewrap's --dir for each folder between /tmp and `path`, outermost first."""
    folders = []
    for parent in pathlib.Path(path).parents:
        if str(parent) in ('/tmp', '/'):
            break
        folders = ['--dir', str(parent)] + folders
    return folders if str(path).startswith('/tmp/') else []
