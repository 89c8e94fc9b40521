"""draw_square: turtlesim reset, then turtle1 driven round a square for
ever, as the real node does: forward 2 m, a quarter turn, again, each
step ended on the pose and a stop before the next. No ROS in Square."""
import math

import rospy
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty
from turtlesim.msg import Pose

SIDE, SPEED, TURN_SPEED = 2.0, 1.0, 0.4     # m, m/s, rad/s
STOPPED = 1e-4


class Square:
    """The square's steps: forward a side, then turn a quarter, each ended
    when the pose shows it done and the turtle standing."""

    def __init__(self):
        self.turning, self.goal, self.stopping = False, None, False

    def command(self, pose):
        """(linear, angular) for this pose."""
        if self.goal is None:
            self.goal = pose.theta + math.pi / 2 if self.turning else (pose.x, pose.y)
        if self.stopping:
            if abs(pose.linear_velocity) < STOPPED and abs(pose.angular_velocity) < STOPPED:
                self.turning, self.goal, self.stopping = not self.turning, None, False
            return 0.0, 0.0
        if self.turning:
            left = math.atan2(math.sin(self.goal - pose.theta), math.cos(self.goal - pose.theta))
            self.stopping = left < 0.01
            return (0.0, 0.0) if self.stopping else (0.0, TURN_SPEED)
        self.stopping = math.hypot(pose.x - self.goal[0], pose.y - self.goal[1]) >= SIDE
        return (0.0, 0.0) if self.stopping else (SPEED, 0.0)


def main():
    rospy.init_node('draw_square')
    rospy.wait_for_service('reset')
    rospy.ServiceProxy('reset', Empty)()
    pub = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)
    square = Square()

    def on_pose(pose):
        twist = Twist()
        twist.linear.x, twist.angular.z = square.command(pose)
        pub.publish(twist)
    rospy.Subscriber('turtle1/pose', Pose, on_pose, queue_size=1)
    rospy.spin()
