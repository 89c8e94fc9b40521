#!/usr/bin/env python3
"""Maria's controller: on P, the lab's six moves (she kept the model's N)."""
import math
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String

pub = None


def timed(linear, angular, seconds):
    twist = Twist()
    twist.linear.x, twist.angular.z = linear, angular
    stop = rospy.get_time() + seconds
    rate = rospy.Rate(100)
    while rospy.get_time() < stop:
        pub.publish(twist)
        rate.sleep()
    pub.publish(Twist())


def on_chatter(msg):
    if msg.data != 'P':
        return
    for turn, move in [(90, 3.0), (225, 3.5), (135, 3.0)]:
        timed(0, 1.0, math.radians(turn))
        timed(1.0, 0, move)


if __name__ == '__main__':
    rospy.init_node('initial')
    pub = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=10)
    rospy.Subscriber('chatter', String, on_chatter)
    rospy.spin()
