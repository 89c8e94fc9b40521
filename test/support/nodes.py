"""Real nodes for tests and the benchmark: started and stopped as processes,
waited for on conditions (never for a fixed time), their poses and logs
recorded."""
import atexit
import os
import shutil
import signal
import subprocess
import tempfile
import threading
import time
import xmlrpc.client

import rosgraph
import rospy
from geometry_msgs.msg import Twist
from rosgraph_msgs.msg import Log
from turtlesim.msg import Pose

from support.children import readable_env


def wait_until(condition, timeout, what, explain=None):
    """Poll `condition` until it is true; after `timeout` s fail, saying
    what was waited for (and what `explain()` returns, if given)."""
    deadline = time.time() + timeout
    while time.time() < deadline:
        if condition():
            return
        time.sleep(0.02)
    detail = f'\n{explain()}' if explain else ''
    raise AssertionError(f'waited {timeout:g} s for {what}, in vain{detail}')


def wait_for_connections(endpoint, timeout=20, what=None):
    """A publisher or subscriber of ours is connected to someone."""
    wait_until(lambda: endpoint.get_num_connections() > 0, timeout,
               what or f'a connection on {endpoint.resolved_name}')


def connections(node, topic, direction, peer=None):
    """How many live connections `node` has on `topic`, incoming ('i') or
    outgoing ('o'), with `peer` only if given, asked of the node itself over
    its XML-RPC API."""
    try:
        uri = rosgraph.Master(rospy.get_name()).lookupNode(node)
        _, _, bus = xmlrpc.client.ServerProxy(uri).getBusInfo(rospy.get_name())
    except Exception:
        return 0
    return sum(1 for c in bus if c[2] == direction and c[4] == topic and c[5]
               and peer in (None, c[1]))


def subscribed(node, topic):
    """Whether `node` receives `topic` from someone."""
    return connections(node, topic, 'i') > 0


class NodeProcess:
    """`rosrun PKG EXE args...` with its output kept in files."""

    def __init__(self, *command, stdin=subprocess.DEVNULL, **env):
        self.dir = tempfile.mkdtemp(prefix='turtle_letters_node_')
        atexit.register(shutil.rmtree, self.dir, True)     # its output: read until the test ends
        self.out_path = os.path.join(self.dir, 'out')
        with open(self.out_path, 'w') as out:
            self.process = subprocess.Popen(['rosrun', *command], stdin=stdin, stdout=out,
                                            stderr=subprocess.STDOUT,
                                            env=readable_env(**env))

    @property
    def pid(self):
        return self.process.pid

    def output(self):
        with open(self.out_path) as f:
            return f.read()

    def alive(self):
        return self.process.poll() is None

    def send(self, sig):
        self.process.send_signal(sig)

    def stop(self, sig=signal.SIGINT, timeout=15):
        return stop_process(self.process, sig, timeout)


def stop_process(process, sig=signal.SIGINT, timeout=15):
    """Ask a child process to end; kill it if it will not."""
    if process.poll() is None:
        process.send_signal(sig)
        try:
            process.wait(timeout)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
    return process.returncode


class Processes:
    """Processes started with their output in log_dir/NAME.log, all stopped
    by stop_all() whatever happens (the bench's roscore, nodes and loads)."""

    def __init__(self, log_dir):
        self.log_dir = log_dir
        self.running = []

    def start(self, name, *command, **env):
        log = open(os.path.join(self.log_dir, f'{name}.log'), 'w')
        process = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT,
                                   stdin=subprocess.DEVNULL, env=readable_env(**env))
        self.running.append(process)
        return process

    def stop(self, process, sig=signal.SIGINT):
        stop_process(process, sig)
        if process in self.running:
            self.running.remove(process)

    def stop_all(self):
        for process in reversed(list(self.running)):
            self.stop(process)


def simulator():
    return NodeProcess('turtlesim', 'turtlesim_node', QT_QPA_PLATFORM='offscreen')


def node_pid(name):
    """The pid a running node reports for itself over its XML-RPC API."""
    uri = rosgraph.Master(rospy.get_name()).lookupNode(name)
    return xmlrpc.client.ServerProxy(uri).getPid(rospy.get_name())[2]


class LogWatch:
    """Every /rosout message, to count and search."""

    def __init__(self):
        self.messages = []
        rospy.Subscriber('/rosout', Log, self.messages.append, queue_size=5000)

    def count(self, text, node=None):
        return sum(1 for m in self.messages
                   if text in m.msg and (node is None or m.name == node))

    def wait_for(self, text, timeout, node=None, explain=None):
        """Wait for a line containing `text`; fails if none comes in time."""
        wait_until(lambda: self.count(text, node), timeout,
                   f'a log line with {text!r}' + (f' from {node}' if node else ''), explain)


class PoseRecorder:
    """Every pose of a turtle with the time it came (and, if asked, whether
    each cmd_vel moved the turtle)."""

    def __init__(self, with_commands=False, turtle='turtle1'):
        self.lock = threading.Lock()
        self.poses, self.commands = [], []
        self._subscriber = rospy.Subscriber(f'/{turtle}/pose', Pose, self._on_pose,
                                            queue_size=10000, tcp_nodelay=True)
        if with_commands:
            self._commands = rospy.Subscriber(f'/{turtle}/cmd_vel', Twist, self._on_cmd_vel,
                                              queue_size=10000, tcp_nodelay=True)

    def _on_pose(self, msg):
        with self.lock:
            self.poses.append((time.time(), msg))

    def _on_cmd_vel(self, msg):
        with self.lock:
            self.commands.append((time.time(), bool(msg.linear.x or msg.linear.y or msg.angular.z)))

    def wait_connected(self, timeout=30):
        wait_for_connections(self._subscriber, timeout, "turtlesim's poses")

    def unregister(self):
        self._subscriber.unregister()

    def reset(self):
        with self.lock:
            self.poses, self.commands = [], []

    def since(self, t0):
        with self.lock:
            return [m for t, m in self.poses if t >= t0]

    def path(self, t0=0.0):
        return [(m.x, m.y) for m in self.since(t0)]

    def last(self):
        with self.lock:
            return self.poses[-1][1]

    def moving_since(self, t0):
        return [m for m in self.since(t0) if m.linear_velocity or m.angular_velocity]

    def wait_until_commands_end(self, timeout, what, quiet_for=1.5):
        """A moving cmd_vel, then `quiet_for` s without one (with_commands)."""
        def ended():
            with self.lock:
                moving = [t for t, m in self.commands if m]
            return moving and time.time() - moving[-1] > quiet_for
        wait_until(ended, timeout, what)

    def wait_until_still(self, t0, timeout, still_for=1.5, what='the turtle to move and then stop'):
        """Motion after t0, then `still_for` s without any; fails otherwise."""
        def still():
            moved = [t for t, m in self.poses[-500:]
                     if t >= t0 and (m.linear_velocity or m.angular_velocity)]
            return moved and time.time() - moved[-1] > still_for
        wait_until(still, timeout, what)
