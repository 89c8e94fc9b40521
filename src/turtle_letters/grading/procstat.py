"""CPU time and memory of a process, from /proc (Linux). No ROS here: the
grader, the fault tests and the benchmark measure nodes with it."""
import os


def stat_fields(pid):
    """The fields of /proc/PID/stat after the command's name (which may hold
    spaces and parentheses): [0] the state, [1] the parent's pid, ..."""
    with open(f'/proc/{pid}/stat') as f:
        return f.read().rsplit(')', 1)[1].split()


def cpu_seconds(pid):
    """User + system CPU time the process has used so far."""
    fields = stat_fields(pid)
    return (int(fields[11]) + int(fields[12])) / os.sysconf('SC_CLK_TCK')


def rss_mb(pid):
    """Resident memory, MB."""
    with open(f'/proc/{pid}/status') as f:
        for line in f:
            if line.startswith('VmRSS:'):
                return int(line.split()[1]) / 1024.0
    return 0.0
