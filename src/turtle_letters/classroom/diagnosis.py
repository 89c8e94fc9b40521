"""What to say when a turtle does not do as told: what was seen, and what
to check. Every line here is one a user reads, so each ends in advice."""
import math
import traceback

import rosgraph
import rospy

from ..motion.driver import DrawingAborted, NoPoses
from .network import advertised_host

STALL_SECONDS = 1.0         # s a turtle may disobey before the drawing stops
CONNECT_SECONDS = 5.0       # s a turtle's topics may take to connect


def reach_advice():
    """What to check when turtlesim's machine does not hear this one."""
    host, source = advertised_host()
    made_by = f'{source}={host}' if source.startswith('ROS_') else f'{source}: {host}'
    return (f"Check that the simulator's host can resolve and reach this machine as it "
            f'advertises itself, {rospy.get_node_uri()} ({made_by}); set ROS_IP or '
            'ROS_HOSTNAME to an address it can reach; rosrun turtle_letters check_network.py '
            'checks this machine')


def stall_diagnosis(driver, pose, latency=None):
    """A turtle that did not move as commanded although its poses arrive;
    how late its commands act, when that is known, or that none has shown."""
    linear_x, linear_y, angular = driver.commanded
    late = ''
    if latency is not None and latency.lag >= 2:
        late = f' (commands take about {1000 * latency.seconds():.0f} ms to act)'
    seen = (f'turtle {driver.name} did not move as commanded for {STALL_SECONDS:g} s although '
            f'its poses arrive{late}: it moves at {pose.linear_velocity:.2f} m/s and '
            f'{pose.angular_velocity:.2f} rad/s, we command {math.hypot(linear_x, linear_y):.2f} '
            f'm/s and {angular:.2f} rad/s on {driver.cmd_vel_topic}')
    others = other_publishers(driver.cmd_vel_topic)
    if others:
        return f'{seen}; {", ".join(others)} publish there too: only one node may drive a turtle'
    if driver.cmd_vel_connections() == 0:
        return f'{seen}; turtlesim has not connected to it. {reach_advice()}'
    if latency is not None and not latency.lags:
        return (f'{seen}; turtlesim hears it, but none of our commands has shown in its poses '
                f'yet: the network delays them more than {STALL_SECONDS:g} s, or the remaps of '
                f'cmd_vel and pose are wrong')
    return f'{seen}; turtlesim hears it: check the remaps of cmd_vel and pose'


def not_connected_diagnosis(driver):
    """A turtle whose topics did not connect within CONNECT_SECONDS."""
    if driver.cmd_vel_connections():
        return (f'no pose of turtle {driver.name} reached us on {driver.poses.topic} within '
                f'{CONNECT_SECONDS:g} s, although turtlesim publishes them. {reach_advice()}')
    return (f'turtlesim has not connected to {driver.cmd_vel_topic} within {CONNECT_SECONDS:g} s, '
            f'so turtle {driver.name} will not move. {reach_advice()}')


def why_stopped(error, driver):
    """A drawing's failure, in a few words, with what to check."""
    if isinstance(error, NoPoses):
        return (f'no pose on {driver.poses.topic} for {error.args[0]:g} s although turtlesim '
                f'publishes it. {reach_advice()}')
    if isinstance(error, DrawingAborted):
        return str(error)
    if isinstance(error, rospy.ServiceException):
        return f'a turtlesim service failed: {error}'
    if isinstance(error, rospy.ROSInterruptException):     # Ctrl-C mid-call
        return 'this node is shutting down'
    rospy.logerr('The drawing failed on an error of turtle_letters itself; please report '
                 'it with this traceback:\n%s', traceback.format_exc())
    return f'{type(error).__name__}: {error}'


def spawn_refusal(driver, error, what=''):
    """Why turtlesim would not spawn a turtle, in words (the real one says b'')."""
    if driver.exists():
        return (f'turtlesim would not spawn {what}{driver.name}: a turtle of that name is '
                'on the canvas already')
    return f'turtlesim would not spawn {what}{driver.name}: {error}'


def other_publishers(topic):
    """The nodes other than this one that publish on `topic`."""
    try:
        publishers, _, _ = rosgraph.Master(rospy.get_name()).getSystemState()
    except Exception:  # the master is gone: nothing more to say
        return []
    return [n for t, nodes in publishers if t == topic for n in nodes if n != rospy.get_name()]
