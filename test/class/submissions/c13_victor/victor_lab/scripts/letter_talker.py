#!/usr/bin/env python3
import rospy
from std_msgs.msg import String


def talker():
    pub = rospy.Publisher('chatter', String, queue_size=10)
    rospy.init_node('talker', anonymous=True)
    while not rospy.is_shutdown():
        letter = input("Enter the letter: ")
        pub.publish(letter)


if __name__ == '__main__':
    try:
        talker()
    except (rospy.ROSInterruptException, EOFError):
        pass
