"""The processes a run started, seen from outside its sandbox: what they
print, kept within bounds, and through /proc the controller's CPU while it
drew."""
import json
import os
import platform
import re
import select
import threading
import time

from ..grading.procstat import cpu_seconds, stat_fields
from . import observations as seen

SHELLS = ('bash', 'sh', 'dash')
ANONYMOUS = re.compile(r'_(\d+)_\d+$')     # an anonymous node's name: NAME_PID_MS
READ = {'x86_64': '0', 'aarch64': '63'}.get(platform.machine())    # read(2)'s number here


def controller_processes(root, node):
    """pids of the processes under `root` that roslaunch started as `node`."""
    wanted = f'__name:={node.rsplit("/", 1)[-1]}'.encode()
    return [pid for pid, args in _commands() if wanted in args and _descends(pid, root)]


def script_nodes(root, folder, programs=False):
    """{pid: its file's name} of the processes under `root` that roslaunch
    started as nodes and that are shell scripts in `folder` (bash, sh or
    dash running a file there: not the grader's own stand-in for turtlesim,
    a script too); with `programs`, any node whose program or script is there."""
    inside = os.fsencode(os.path.join(folder, ''))
    found = {}
    for pid, args in _commands():
        if os.path.basename(args[0]).decode(errors='replace') in SHELLS:
            ran = args[1:2]     # the script the shell runs
        else:       # a program, or the script its interpreter runs
            ran = args[:2] if programs else []
        ran = [arg for arg in ran if arg.startswith(inside)]
        if ran and any(arg.startswith(b'__name:=') for arg in args) and _descends(pid, root):
            found[pid] = os.path.basename(os.fsdecode(ran[0]))
    return found


def reading_input(root):
    """Whether a node under `root` (roslaunch) waits in read(2) on its
    standard input, the terminal, in any of its threads (a prompt's
    input(), a talker's key)."""
    for pid, args in _commands():
        if any(arg.startswith(b'__name:=') for arg in args) and _descends(pid, root) and \
                any(_reads_stdin(f'/proc/{pid}/task/{task}') for task in _tasks(pid)):
            return True
    return False


def _tasks(pid):
    try:
        return os.listdir(f'/proc/{pid}/task')
    except OSError:
        return []


def _reads_stdin(task, looks=10):
    """Whether the thread at /proc path `task` is in read(2) of file 0. The
    kernel says "running" of a thread woken and not yet asleep again, as a
    reader is when another beside it on the terminal takes the line: such a
    thread is looked at again, for up to 0.1 s."""
    for _ in range(looks):
        try:
            with open(f'{task}/syscall') as f:
                called = f.read().split()
        except OSError:     # gone, or not ours to look at
            return False
        if called[:1] != ['running']:
            return called[:2] == [READ, '0x0']
        time.sleep(0.01)
    return False


def _commands():
    """(pid, its command line's arguments) of each process there is."""
    for pid in filter(str.isdigit, os.listdir('/proc')):
        try:
            with open(f'/proc/{pid}/cmdline', 'rb') as f:
                args = f.read().split(b'\0')
        except OSError:
            continue
        if args[0]:
            yield int(pid), args


def _descends(pid, root):
    while pid > 1:
        if pid == root:
            return True
        try:
            pid = int(stat_fields(pid)[1])
        except OSError:
            return False
    return False


class RunningScripts:
    """The submission's shell scripts (in `folder`) that a run's roslaunch
    started as nodes, found once (the lab is up), and with `programs` its
    every node (those the grader started for want of a launch file, as a
    TA runs them in a terminal and sees them end): whether one still runs,
    when one was last seen to, and which started an anonymous node (owner)."""

    def __init__(self, root, folder, programs=False):
        self.names = script_nodes(root, folder, programs)     # pid: its script's file name
        self.pids = list(self.names)
        self.until = None       # monotonic t one was last seen running; None: none was
        self.started = {}       # a pid inside the sandbox: the script whose process tree has it

    def running(self):
        """Whether one still runs (a zombie, ended and not yet reaped, does
        not); the processes each running one started are noted (started)."""
        alive = False
        for pid in self.pids:
            try:
                state = stat_fields(pid)[0]
            except OSError:
                continue
            if state != 'Z':
                alive = True
                self.started.update((inside, self.names[pid]) for inside in
                                    map(_pid_inside, _descendants(pid)) if inside)
        if alive:
            self.until = time.monotonic()
        return alive

    def owner(self, node):
        """The script that started `node`, an anonymous node whose name
        carries its pid in the sandbox (rostopic's and rosservice's:
        /rostopic_PID_MS), as seen while it ran; else `node` itself."""
        found = ANONYMOUS.search(node)
        return self.started.get(int(found.group(1)), node) if found else node


def _descendants(pid):
    """The pids of the processes under `pid` (its children's, and theirs)."""
    found, todo = [], [pid]
    while todo:
        parent = todo.pop()
        for task in _tasks(parent):
            try:
                with open(f'/proc/{parent}/task/{task}/children') as f:
                    children = [int(child) for child in f.read().split()]
            except OSError:
                continue
            found += children
            todo += children
    return found


def _pid_inside(pid):
    """Process `pid`'s pid in the innermost pid namespace it is in (the
    sandbox's: what its node's anonymous name carries), or None."""
    try:
        with open(f'/proc/{pid}/status') as f:
            line = next((line for line in f if line.startswith('NSpid:')), '')
    except OSError:
        return None
    return int(line.split()[-1]) if line.split()[1:] else None


class ControllerCpu:
    """The CPU time of the node that publishes cmd_vel, from the trigger on."""

    def __init__(self, root, events):
        graph = seen.last_graph(events)
        names = graph['cmd_vel_publishers'] if graph else []
        self.started = time.monotonic()
        self.pids = controller_processes(root, names[0]) if len(names) == 1 else []
        self.used = self._used()

    def _used(self):
        """Each process's CPU seconds; None where it has ended (its time is gone with it)."""
        used = {}
        for pid in self.pids:
            try:
                used[pid] = cpu_seconds(pid)
            except OSError:
                used[pid] = None
        return used

    def share(self):
        """% of a core since the trigger; None when no one node publishes
        cmd_vel, or its process ended before this was asked (what it used
        ended with it: counting it as nothing made the figure negative)."""
        now = self._used()
        if not self.pids or None in now.values() or None in self.used.values():
            return None
        spent = sum(now[pid] - self.used[pid] for pid in self.pids)
        return 100 * max(0.0, spent) / max(time.monotonic() - self.started, 1e-6)


class Capped:
    """What a process prints, as it comes: its first HEAD and last TAIL
    bytes kept, the rest only counted, so that nothing a submission prints
    (a build that runs `yes`) can fill the grader's memory."""
    HEAD, TAIL = 64 * 1024, 256 * 1024

    def __init__(self):
        self.head, self.tail, self.size = bytearray(), bytearray(), 0
        self.lock = threading.Lock()

    def add(self, data):
        with self.lock:
            self.size += len(data)
            room = max(0, self.HEAD - len(self.head))
            self.head += data[:room]
            self.tail += data[room:]
            if len(self.tail) > 2 * self.TAIL:
                del self.tail[:-self.TAIL]

    def read_all(self, stream, chunk=65536, stopping=None):
        """Adds what `stream` (a file descriptor) gives until it ends, or
        (`stopping`, an Event) until it is set and nothing more comes."""
        while True:
            if stopping is not None:
                if not select.select([stream], [], [], 0.1)[0]:
                    if stopping.is_set():
                        return
                    continue
            try:
                data = os.read(stream, chunk)
            except OSError:
                return
            if not data:
                return
            self.add(data)

    def has(self, data):
        """Whether `data` is in what is kept."""
        with self.lock:
            return data in self.head or data in self.tail

    def text(self, since=0):
        """What was printed from byte `since` on, what was left out said in a line."""
        with self.lock:
            head, tail = bytes(self.head), bytes(self.tail[-self.TAIL:])
            tail_from = self.size - len(tail)
        gap = tail_from - max(since, len(head))
        middle = f'\n... {gap} bytes left out ...\n'.encode() if gap > 0 else b''
        kept = head[since:] + middle + tail[max(0, since - tail_from):]
        return kept.decode('utf-8', 'replace')


class Reader:
    """A thread that keeps what a file descriptor gives (a pipe, a
    pseudo-terminal's master) in `output`, a Capped. It alone closes the
    descriptor, once it has read its last: closed under a reader still
    reading it, its number goes to the next file opened (another student's
    pipe, with --jobs 2), and the reader reads that instead."""

    def __init__(self, fd):
        self.fd, self.output, self.stopping = fd, Capped(), threading.Event()
        self.thread = threading.Thread(target=self._read, daemon=True)
        self.thread.start()

    def _read(self):
        try:
            self.output.read_all(self.fd, stopping=self.stopping)
        finally:
            os.close(self.fd)

    def stop(self, seconds=5.0):
        """Reads what is left for up to `seconds` (a process that keeps the
        other end open keeps it from ending), then ends, its descriptor closed."""
        self.thread.join(timeout=seconds)
        self.stopping.set()
        self.thread.join()


class JsonLines:
    """What a process tells in JSON lines, as they come: those `wanted`
    kept in `items`, at most `cap` of them (past it `full`, and the rest
    read and dropped, so that the teller never blocks on a full pipe)."""

    def __init__(self, cap, wanted=lambda item: True):
        self.cap, self.wanted = cap, wanted
        self.items, self.full = [], False

    def read(self, lines):
        """Reads `lines` (a file of bytes, or any lines) to their end."""
        for line in lines:
            if len(self.items) >= self.cap:
                self.full = True
                continue
            try:
                item = json.loads(line)
            except ValueError:
                continue
            if self.wanted(item):
                self.items.append(item)
