#!/usr/bin/env python
# The lab's talker, as handed out: one letter, read with raw_input.
import rospy
from std_msgs.msg import String

def talker():
    pub = rospy.Publisher('chatter', String, queue_size=10)
    rospy.init_node('talker', anonymous=True)
    letter = raw_input("Enter the letter: ")
    pub.publish(letter)

if __name__ == '__main__':
    try:
        talker()
    except rospy.ROSInterruptException:
        pass
