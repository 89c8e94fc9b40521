#!/usr/bin/env python3
"""HOSTILE: once the I is drawn, shuts the simulator down over XML-RPC,
as any node may (the server of /spawn is the simulator)."""
import xmlrpc.client

import rosgraph
import rospy
from std_msgs.msg import String


def shut_the_simulator_down(_):
    rospy.sleep(4.0)        # the I takes about 3.6 s
    master = rosgraph.Master('/killer')
    simulator = dict(master.getSystemState()[2])['/spawn'][0]
    xmlrpc.client.ServerProxy(master.lookupNode(simulator)).shutdown('/killer', 'HOSTILE')


rospy.init_node('killer')
rospy.Subscriber('chatter', String, shut_the_simulator_down)
rospy.spin()
