"""mimic: one turtle does what another does, as the real node does: each
pose on input/pose becomes a Twist on output/cmd_vel with its speeds
(remap them to two turtles' topics)."""
import rospy
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose


def twist_of(pose):
    twist = Twist()
    twist.linear.x, twist.angular.z = pose.linear_velocity, pose.angular_velocity
    return twist


def main():
    rospy.init_node('turtle_mimic')
    pub = rospy.Publisher('output/cmd_vel', Twist, queue_size=1)
    rospy.Subscriber('input/pose', Pose, lambda pose: pub.publish(twist_of(pose)), queue_size=1)
    rospy.spin()
