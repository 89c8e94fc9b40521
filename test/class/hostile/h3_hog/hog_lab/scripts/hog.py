#!/usr/bin/env python3
"""A hostile cadet: on P it fills 8 GB of memory, then would draw an I."""
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String


def draw_i(pub):
    for linear, angular, seconds in ((0, 1.0, 1.5708), (1.0, 0, 2.0)):
        twist = Twist()
        twist.linear.x, twist.angular.z = linear, angular
        end = rospy.get_time() + seconds
        while rospy.get_time() < end:
            pub.publish(twist)
            rospy.sleep(0.02)
    pub.publish(Twist())


def on_chatter(message):
    if message.data == 'P':
        hoard = b'x' * (8 * 1024 ** 3)
        draw_i(cmd)
        print(len(hoard))


rospy.init_node('hog')
cmd = rospy.Publisher('turtle1/cmd_vel', Twist, queue_size=1)
rospy.Subscriber('chatter', String, on_chatter)
rospy.spin()
