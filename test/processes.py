"""Real nodes as child processes for fault tests: started, watched, stopped."""
import os
import signal
import subprocess
import tempfile
import time
import xmlrpc.client

import rosgraph
import rospy
from rosgraph_msgs.msg import Log


class NodeProcess:
    """`rosrun PKG EXE args...` with its output kept in files."""

    def __init__(self, *command, stdin=subprocess.DEVNULL, **env):
        self.dir = tempfile.mkdtemp(prefix='turtle_letters_node_')
        self.out_path = os.path.join(self.dir, 'out')
        with open(self.out_path, 'w') as out:
            self.process = subprocess.Popen(['rosrun', *command], stdin=stdin, stdout=out,
                                            stderr=subprocess.STDOUT,
                                            env=dict(os.environ, **env))

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
        if self.alive():
            self.process.send_signal(sig)
            try:
                self.process.wait(timeout)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        return self.process.returncode


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

    def wait_for(self, text, timeout, node=None):
        deadline = time.time() + timeout
        while time.time() < deadline:
            if self.count(text, node):
                return True
            time.sleep(0.05)
        return False
