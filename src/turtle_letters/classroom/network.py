"""`check_network.py`: is this machine set up to take part in a ROS system
spread over several machines? A few pass/fail lines, each with what to fix.

1. The master (ROS_MASTER_URI) answers.
2. The host name this machine advertises (ROS_IP, else ROS_HOSTNAME, else
   its host name) resolves to one of its own addresses, and not to loopback
   when other machines must reach it.
3. A message goes round through the master: this check subscribes, then
   publishes, so the master must call this machine back at its advertised
   URI to tell the subscriber (what turtlesim's machine must do too).

The lines go to stderr; stdout gets "ok" or "failed" (launch files run this
as a <param command=...>). A failure exits 1, which stops roslaunch before
anything starts, except with --warn: student.launch goes on, so that the
controller can say again, when a drawing fails, what to check.
"""
import os
import socket
import sys
import threading
import time
import urllib.parse

import rosgraph
import rosgraph.network
import rospy
from std_msgs.msg import String

from .hosts import host_verdict

TIMEOUT = 3.0       # s for each check


def advertised_host():
    """The host name other nodes are told to reach this one at, and which setting gave it."""
    for variable in ('ROS_IP', 'ROS_HOSTNAME'):
        if os.environ.get(variable):
            return os.environ[variable], variable
    return rosgraph.network.get_host_name(), 'the host name (neither ROS_IP nor ROS_HOSTNAME is set)'


def _resolve(host):
    try:
        return sorted({info[4][0] for info in socket.getaddrinfo(host, None, socket.AF_INET)})
    except socket.gaierror:
        return []


def check_master(uri):
    host = urllib.parse.urlparse(uri).hostname or ''
    if not _resolve(host):
        return False, f'ROS_MASTER_URI={uri}: {host!r} does not resolve on this machine'
    socket.setdefaulttimeout(TIMEOUT)
    started = time.monotonic()
    try:
        rosgraph.Master('/check_network').getPid()
    except Exception as e:  # refused, timed out, unreachable: all say the same to the user
        return False, f'ROS_MASTER_URI={uri} does not answer ({e}): is roscore running there?'
    finally:
        socket.setdefaulttimeout(None)
    return True, f'the master at {uri} answers ({1000 * (time.monotonic() - started):.0f} ms)'


def check_round_trip():
    rospy.init_node('check_network', anonymous=True, disable_signals=True,
                    disable_rosout=True)
    topic = rospy.resolve_name('~round_trip')
    received = threading.Event()
    subscriber = rospy.Subscriber(topic, String, lambda _msg: received.set(), queue_size=1)
    publisher = rospy.Publisher(topic, String, queue_size=1)
    started = time.monotonic()
    deadline = started + TIMEOUT
    while time.monotonic() < deadline and not received.is_set():
        if publisher.get_num_connections():
            publisher.publish(String('ping'))
        received.wait(0.05)
    subscriber.unregister()
    publisher.unregister()
    if not received.is_set():
        return False, (f'no message went round through the master on {topic} within '
                       f'{TIMEOUT:g} s: the master\'s machine (or this one) cannot reach this node '
                       f'at {rospy.get_node_uri()}; turtlesim will not hear this machine either')
    return True, (f'a message went round through the master in '
                  f'{1000 * (time.monotonic() - started):.0f} ms ({rospy.get_node_uri()})')


def main(argv=None):
    """`--serving`: this machine serves others (the instructor's, where
    roslaunch is about to start the master): only the host name is checked,
    and loopback fails there too."""
    argv = sys.argv[1:] if argv is None else argv
    serving = '--serving' in argv
    uri = rosgraph.get_master_uri()
    master_host = urllib.parse.urlparse(uri).hostname or ''
    master_is_remote = not any(a.startswith('127.') for a in _resolve(master_host))
    host, source = advertised_host()
    results = [] if serving else [check_master(uri)]
    results.append(host_verdict(host, source, _resolve(host), rosgraph.network.get_local_addresses(),
                                others_must_reach=master_is_remote or serving))
    if not serving and all(passed for passed, _ in results):
        results.append(check_round_trip())
    for passed, line in results:
        print(f'[{"PASS" if passed else "FAIL"}] {line}', file=sys.stderr, flush=True)
    ok = all(passed for passed, _ in results)
    print('ok' if ok else 'failed')
    rospy.signal_shutdown('checked')
    if not ok and '--warn' in argv:
        print('[WARN] going on: drawings will fail until the lines above pass', file=sys.stderr)
        return 0
    return 0 if ok else 1
