"""turtle_teleop_key: the arrow keys drive turtle1, as the real node does:
each key press publishes one Twist on turtle1/cmd_vel (up and down move,
left and right turn, scaled by ~scale_linear and ~scale_angular, 2.0
each); 'q' quits. It reads the terminal it was started in, key by key."""
import os
import select
import sys
import termios
import tty

import rospy
from geometry_msgs.msg import Twist

# The arrow keys' escape sequences: (linear, angular) before scaling.
ARROWS = {b'\x1b[A': (1.0, 0.0), b'\x1b[B': (-1.0, 0.0),
          b'\x1b[D': (0.0, 1.0), b'\x1b[C': (0.0, -1.0)}
QUIT = b'q'
BANNER = ('Reading from keyboard\n---------------------------\n'
          "Use arrow keys to move the turtle. 'q' to quit.")


def presses(data):
    """The moves `data` (bytes read from the terminal) asks for, in order,
    and whether it asks to quit; other bytes are ignored."""
    moves, i = [], 0
    while i < len(data):
        if data[i:i + 1] == QUIT:
            return moves, True
        move = ARROWS.get(data[i:i + 3])
        if move is not None:
            moves.append(move)
            i += 3
        else:
            i += 1
    return moves, False


def _read_keys(fd, publish):
    while not rospy.is_shutdown():
        if not select.select([fd], [], [], 0.1)[0]:
            continue
        data = os.read(fd, 64)
        if not data:            # no terminal left to read: stay up, as a node does
            rospy.spin()
            return
        moves, quit_ = presses(data)
        for move in moves:
            publish(move)
        if quit_:
            return


def main():
    rospy.init_node('teleop_turtle')
    linear_scale = rospy.get_param('~scale_linear', 2.0)
    angular_scale = rospy.get_param('~scale_angular', 2.0)
    pub = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)

    def publish(move):
        twist = Twist()
        twist.linear.x, twist.angular.z = linear_scale * move[0], angular_scale * move[1]
        pub.publish(twist)
    print(BANNER, flush=True)
    fd = sys.stdin.fileno()
    saved = termios.tcgetattr(fd) if os.isatty(fd) else None
    try:
        if saved is not None:
            tty.setcbreak(fd)
        _read_keys(fd, publish)
    finally:
        if saved is not None:
            termios.tcsetattr(fd, termios.TCSADRAIN, saved)
