"""draw.py: a command-line client of the controller's `draw` action.

    rosrun turtle_letters draw.py TEXT          draw a letter, word or line
    rosrun turtle_letters draw.py --svg FILE    draw an SVG file's line art
    --ns NAME                                   a student's turtle (/NAME/draw)

A progress bar in a terminal, one line per 10 % otherwise; the result line
at the end. Ctrl-C cancels the goal (the turtle stops) before it exits.
Exit status: 0 drawn, 1 not drawn, 2 bad arguments or no server, 130 Ctrl-C.
"""
import argparse
import os
import socket
import sys

import actionlib
import rosgraph
import rospy
from actionlib_msgs.msg import GoalStatus

from ..msg import DrawAction, DrawGoal

SERVER_WAIT = 5.0       # s for the action server to show up
CANCEL_WAIT = 5.0       # s for a cancelled goal to end


class Bar:
    """A tqdm progress bar, on a terminal."""

    def __init__(self, what):
        from tqdm import tqdm           # only a terminal needs it
        self.bar = tqdm(total=100, desc=what, unit='%', file=sys.stdout,
                        bar_format='{desc}: {percentage:3.0f}%|{bar}| [{elapsed}{postfix}]')

    def show(self, feedback):
        self.bar.n = round(100 * feedback.progress, 1)
        self.bar.set_postfix_str(status(feedback))

    def close(self):
        self.bar.close()


class Lines:
    """One line for each 10 % step, for a log or a pipe."""

    def __init__(self, what):
        self.what, self.shown = what, -1

    def show(self, feedback):
        step = int(10 * feedback.progress + 1e-6)
        if step > self.shown:
            self.shown = step
            print(f'{self.what}: {10 * step}%, {status(feedback)}', flush=True)

    def close(self):
        pass


def status(feedback):
    paused = ', paused' if feedback.paused else ''
    return (f'stroke {feedback.stroke}/{feedback.strokes}, about {feedback.eta:.0f} s to go'
            f'{paused}')


def parse(argv):
    parser = argparse.ArgumentParser(prog='draw.py', description='Draw with the controller '
                                     "of turtle_letters, through its action 'draw'.")
    parser.add_argument('text', nargs='?', default='', help='a letter, word or line to draw')
    parser.add_argument('--svg', default='', metavar='FILE', help="an SVG file's line art")
    parser.add_argument('--ns', default='', metavar='NAME',
                        help="a student's turtle: the action NAME/draw")
    args = parser.parse_args(argv)
    if bool(args.text) == bool(args.svg):
        parser.error('give exactly one of TEXT and --svg FILE')
    return args


def main(argv=None):
    args = parse(rospy.myargv(sys.argv)[1:] if argv is None else argv)
    try:
        return draw(args)
    except KeyboardInterrupt:       # while it starts: nothing was sent (follow() cancels)
        print('draw.py: interrupted before a goal was sent', file=sys.stderr)
        return 130


def draw(args):
    """Find the action server, then send the goal and follow it."""
    try:
        rosgraph.Master('/draw_client').getPid()
    except (OSError, socket.error):
        print(f'draw.py: no ROS master at {rosgraph.get_master_uri()}: start the controller '
              '(roslaunch turtle_letters draw_letter.launch), or set ROS_MASTER_URI',
              file=sys.stderr)
        return 2
    rospy.init_node('draw_client', anonymous=True, disable_signals=True)
    name = rospy.resolve_name(f'{args.ns}/draw' if args.ns else 'draw')
    client = actionlib.SimpleActionClient(name, DrawAction)
    if not client.wait_for_server(rospy.Duration(SERVER_WAIT)):
        print(f'draw.py: no action server {name} answered within {SERVER_WAIT:g} s: is the '
              'controller running, and is --ns its namespace? (rostopic list | grep draw)',
              file=sys.stderr)
        return 2
    svg = os.path.abspath(args.svg) if args.svg else ''
    what = args.text or os.path.basename(args.svg)
    view = Bar(what) if sys.stdout.isatty() else Lines(what)
    try:
        return follow(client, DrawGoal(text=args.text, svg=svg), view)
    finally:
        view.close()


def follow(client, goal, view):
    """Send the goal and wait for its end; Ctrl-C cancels it first."""
    try:
        client.send_goal(goal, feedback_cb=view.show)
        while not client.wait_for_result(rospy.Duration(0.1)):
            pass
    except KeyboardInterrupt:
        client.cancel_goal()        # nothing, if the goal was not sent yet
        try:
            ended = client.wait_for_result(rospy.Duration(CANCEL_WAIT))
        except KeyboardInterrupt:   # a second Ctrl-C: the cancel is sent, go
            ended = False
        view.close()
        print(f'draw.py: cancelled: {result_line(client) if ended else "no answer to the cancel"}')
        return 130
    view.close()
    print(result_line(client))
    result = client.get_result()
    return 0 if result is not None and result.drawn else 1


def result_line(client):
    result = client.get_result()
    if result is None and client.get_state() == GoalStatus.LOST:
        # cancelled before the controller acknowledged it (ros/actionlib#126):
        # the controller recalls it, or cancels it as it comes
        return 'cancelled before the controller had answered'
    if result is None:
        return client.get_goal_status_text() or 'no result'
    if result.drawn:
        return (f'{result.message} ({result.seconds:.1f} s, ink {result.ink:.2f} m, '
                f'travel {result.travel:.2f} m)')
    return result.message
