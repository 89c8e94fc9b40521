"""Is a node alive? Asked of the node itself, not of the master.

The master keeps a node's name and URI after the node has died (kill -9, a
laptop closed, power lost), so `lookupNode` answers for the dead too. A live
node answers its own XML-RPC `getPid` within a moment; a dead one's port
refuses or times out. The same question, asked before this node registers,
keeps a second node of the same name from making the master shut the first
one down.
"""
import ast
import sys
import xmlrpc.client

import rosgraph
import rosgraph.names

from ..settings import student_name_problem

ANSWER_SECONDS = 1.0    # s a live node takes, at most, to answer over a classroom's network


class _Patient(xmlrpc.client.Transport):
    """An XML-RPC transport that gives up after `seconds`."""

    def __init__(self, seconds):
        super().__init__()
        self.seconds = seconds

    def make_connection(self, host):
        connection = super().make_connection(host)
        connection.timeout = self.seconds
        return connection


def answers(uri, seconds=ANSWER_SECONDS):
    """The pid a node at `uri` gives, or None if nothing answers there in time."""
    if not uri:
        return None
    try:
        code, _, pid = xmlrpc.client.ServerProxy(uri, transport=_Patient(seconds)).getPid(
            '/turtle_letters')
    except (OSError, xmlrpc.client.Error, ValueError):
        return None
    return pid if code == 1 else None


def running(node, caller='/turtle_letters'):
    """(uri, pid) of a live node named `node`, or None."""
    try:
        uri = rosgraph.Master(caller).lookupNode(node)
    except (rosgraph.MasterError, OSError):
        return None
    pid = answers(uri)
    return None if pid is None else (uri, pid)


def own_name(default, argv=None):
    """The name rospy.init_node(default) will give this node: its namespace
    and any __name:= remap, before it registers."""
    argv = sys.argv if argv is None else argv
    name = rosgraph.names.load_mappings(argv).get('__name', default)
    return rosgraph.names.ns_join(rosgraph.names.get_ros_namespace(argv=argv), name)


def refuse_a_second(default, argv=None):
    """Exit with one line if a node of this node's name is alive already:
    registering would make the master shut that one down."""
    name = own_name(default, argv)
    live = running(name, name)
    if live:
        print(f'[FATAL] {name} is already running (pid {live[1]} at {live[0]}); starting it again '
              'would stop that one. Stop it first, or give this one another name '
              '(name:= or __ns:=).', file=sys.stderr, flush=True)
        raise SystemExit(2)


def check_student_launch(argv):
    """student.launch's check of name:=, run as a `<param command=...>`
    before any node starts: a bad name, or one whose controller is alive
    already (a second launch would make the master shut the first one down),
    prints one line and exits non-zero, so roslaunch stops before starting
    anything. `argv[0]`: the Python repr of the value roslaunch read (it
    reads name:=true as True), in hexadecimal (no quote or space can break
    the command)."""
    value = ast.literal_eval(bytes.fromhex(argv[0]).decode('utf-8'))
    raw = str(value).lower() if isinstance(value, bool) else str(value)
    problem = student_name_problem(raw, type(value).__name__)
    if problem:
        print(f'[FATAL] student.launch: name:={raw}: {problem}', file=sys.stderr)
        return 2
    controller = f'/{raw}/turtlebot_controller'
    live = running(controller)
    if live:
        print(f'[FATAL] student.launch: name:={raw} is in use: {controller} is running (pid '
              f'{live[1]} at {live[0]}); stop it first, or choose another name', file=sys.stderr)
        return 2
    print(raw)
    return 0
