"""A cgroup of its own for a set of processes (a submission's, or the
grader's beside it): memory and tasks capped by the kernel, cores as a
cpuset with a core's worth of time on each, CPU time counted, every
process in it killed at the end; on cgroup v2, or v1 where v2 lacks the
controllers."""
import os
import signal
import time

CPU_PERIOD = 100000     # us: the scheduler's period, of which a submission has a core's worth


class CgroupError(OSError):
    """No cgroup with the memory and pids controllers can be made here."""


def _mounts():
    with open('/proc/self/mounts') as f:
        return [line.split()[1:4] for line in f]     # (where, type, options)


def _own_path(controller):
    """The grader's own cgroup in a v1 hierarchy (its children nest in it,
    within whatever limits the grader itself runs under)."""
    with open('/proc/self/cgroup') as f:
        for line in f:
            _, controllers, path = line.rstrip('\n').split(':', 2)
            if controller in controllers.split(','):
                return path
    return '/'


def cgroup_roots():
    """Where each cgroup hierarchy is mounted."""
    return sorted({where for where, kind, _ in _mounts() if kind in ('cgroup', 'cgroup2')})


def cgroup_parents():
    """('v2', {controller: folder}) or ('v1', ...): where a submission's
    cgroups are made: at the top of cgroup v2, when it has V2_CONTROLLERS,
    else in the grader's own cgroups of V1_CONTROLLERS."""
    for where, kind, _ in _mounts():
        if kind == 'cgroup2':
            try:
                with open(os.path.join(where, 'cgroup.subtree_control')) as f:
                    enabled = f.read().split()
            except OSError:
                continue
            if set(V2_CONTROLLERS) <= set(enabled):
                return 'v2', {c: where for c in V2_CONTROLLERS}
    found = {}
    for where, kind, options in _mounts():
        for controller in set(options.split(',')) & set(V1_CONTROLLERS):
            if kind == 'cgroup':
                found[controller] = where + _own_path(controller).rstrip('/')
    if len(found) < len(V1_CONTROLLERS):
        raise CgroupError(f'no cgroup with the {", ".join(V1_CONTROLLERS)} controllers here '
                          f'(neither cgroup v2 with {", ".join(V2_CONTROLLERS)}, nor v1 with all)')
    return 'v1', found


# What each version needs, and where it sets a limit and says how much was used or refused.
V2_CONTROLLERS = ('memory', 'pids', 'cpu', 'cpuset')
V1_CONTROLLERS = ('memory', 'pids', 'cpuacct', 'cpu', 'cpuset')
V2_FILES = dict(memory='memory.max', processes='pids.max', oom='memory.events',
                refused='pids.events', cpu='cpu.stat')
V1_FILES = dict(memory='memory.limit_in_bytes', processes='pids.max', oom='memory.oom_control',
                refused='pids.events', cpu='cpuacct.usage')


class Cgroup:
    """A cgroup of its own for one submission: its memory and tasks capped
    by the kernel, its cores (`cpus`: all of the grader's if None) a cpuset
    it cannot widen, a core's worth of time on each, its CPU time counted,
    and every process in it killed at the end (with the PID namespace, this
    catches what double-forked)."""

    def __init__(self, name, limits, cpus=None):
        self.version, parents = cgroup_parents()
        self.limits = limits
        self.folders = {c: os.path.join(p, name) for c, p in parents.items()}
        self.files = V2_FILES if self.version == 'v2' else V1_FILES
        for folder in sorted(set(self.folders.values())):
            os.makedirs(folder, exist_ok=True)
        self._write('memory', 'memory', limits['memory'][0])
        swap = 'memory.swap.max' if self.version == 'v2' else 'memory.memsw.limit_in_bytes'
        if os.path.exists(os.path.join(self.folders['memory'], swap)):
            self._write('memory', swap, limits['memory'][0] if self.version == 'v1' else 0)
        self._write('pids', 'processes', limits['processes'][0])
        self._share(cpus)

    def _share(self, cpus):
        """The cpuset of `cpus` and a core's worth of each per CPU_PERIOD."""
        if self.version == 'v1':    # a v1 cpuset starts empty: no task may join it before
            with open(os.path.join(os.path.dirname(self.folders['cpuset']),
                                   'cpuset.effective_mems')) as f:
                self._write('cpuset', 'cpuset.mems', f.read().strip())
        if cpus is None:
            if self.version == 'v1':
                with open(os.path.join(os.path.dirname(self.folders['cpuset']),
                                       'cpuset.effective_cpus')) as f:
                    self._write('cpuset', 'cpuset.cpus', f.read().strip())
            return
        self._write('cpuset', 'cpuset.cpus', ','.join(map(str, cpus)))
        if self.version == 'v2':
            self._write('cpu', 'cpu.max', f'{CPU_PERIOD * len(cpus)} {CPU_PERIOD}')
        else:
            self._write('cpu', 'cpu.cfs_period_us', CPU_PERIOD)
            self._write('cpu', 'cpu.cfs_quota_us', CPU_PERIOD * len(cpus))

    def _path(self, controller, entry):
        return os.path.join(self.folders[controller], self.files.get(entry, entry))

    def _write(self, controller, entry, value):
        with open(self._path(controller, entry), 'w') as f:
            f.write(str(value))

    def _field(self, controller, entry, field):
        with open(self._path(controller, entry)) as f:
            for line in f:
                words = line.split()
                if len(words) == 2 and words[0] == field:
                    return int(words[1])
        return 0

    def joining(self):
        """A command prefix that puts itself, and so what it runs, in this cgroup."""
        procs = [os.path.join(f, 'cgroup.procs') for f in sorted(set(self.folders.values()))]
        return ['sh', '-c', 'while [ "$1" != -- ]; do echo $$ > "$1" || exit 125; shift; done; '
                            'shift; exec "$@"', 'join'] + procs + ['--']

    def cpu_seconds(self):
        if self.version == 'v2':
            return self._field('cpu', 'cpu', 'usage_usec') / 1e6
        with open(self._path('cpuacct', 'cpu')) as f:
            return int(f.read()) / 1e9

    def reached(self):
        """The words of the first limit the submission reached, or ''."""
        if self._field('memory', 'oom', 'oom_kill'):
            return self.limits['memory'][1](self.limits['memory'][0])
        if self._field('pids', 'refused', 'max'):
            return self.limits['processes'][1](self.limits['processes'][0])
        if self.cpu_seconds() >= self.limits['cpu'][0]:
            return self.limits['cpu'][1](self.limits['cpu'][0])
        return ''

    def kill(self):
        """Kills every process in it (those it forks meanwhile too)."""
        kill_in(set(self.folders.values()))

    def remove(self):
        """Kills every process in it, then removes it."""
        remove_cgroups(set(self.folders.values()))


def _processes(folders):
    pids = set()
    for folder in folders:
        with open(os.path.join(folder, 'cgroup.procs')) as f:
            pids.update(int(pid) for pid in f.read().split())
    return pids


def kill_in(folders):
    """Kills every process in the cgroups at `folders`, until none is left."""
    for _ in range(100):
        try:
            left = _processes(folders)
        except OSError:         # removed meanwhile: nothing is left in it
            return
        if not left:
            return
        for pid in left:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        time.sleep(0.05)


def remove_cgroups(folders):
    """Kills every process in the cgroups at `folders`, then removes them."""
    kill_in(folders)
    for folder in sorted(folders):
        for _ in range(100):
            try:
                os.rmdir(folder)
                break
            except FileNotFoundError:
                break
            except OSError:
                time.sleep(0.05)
