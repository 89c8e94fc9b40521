"""The processes a run started, seen from outside its sandbox through
/proc: the controller's, for the CPU it used while it drew."""
import os
import time

from ..grading.procstat import cpu_seconds
from . import observations as seen


def controller_processes(root, node):
    """pids of the processes under `root` that roslaunch started as `node`."""
    wanted, found = f'__name:={node.rsplit("/", 1)[-1]}'.encode(), []
    for pid in filter(str.isdigit, os.listdir('/proc')):
        try:
            with open(f'/proc/{pid}/cmdline', 'rb') as f:
                if wanted in f.read().split(b'\0'):
                    found.append(int(pid))
        except OSError:
            continue
    return [pid for pid in found if _descends(pid, root)]


def _descends(pid, root):
    while pid > 1:
        if pid == root:
            return True
        try:
            with open(f'/proc/{pid}/stat') as f:
                pid = int(f.read().rsplit(')', 1)[1].split()[1])
        except OSError:
            return False
    return False


class ControllerCpu:
    """The CPU time of the node that publishes cmd_vel, from the trigger on."""

    def __init__(self, root, events):
        graph = seen.last_graph(events)
        names = graph['cmd_vel_publishers'] if graph else []
        self.pids = controller_processes(root, names[0]) if len(names) == 1 else []
        self.started, self.used = time.monotonic(), self._used()

    def _used(self):
        total = 0.0
        for pid in self.pids:
            try:
                total += cpu_seconds(pid)
            except OSError:
                pass
        return total

    def share(self):
        """% of a core since the trigger, or None when no one node publishes cmd_vel."""
        if not self.pids:
            return None
        return 100 * (self._used() - self.used) / max(time.monotonic() - self.started, 1e-6)
