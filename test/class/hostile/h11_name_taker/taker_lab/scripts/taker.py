#!/usr/bin/env python3
"""HOSTILE: writes the file the grader's turtlesim stand-in once wrote to
say it was started (this launch file starts no turtlesim), then takes the
grader's watcher's node name once the watcher is up, so ROS shuts the
watcher down: this package has no talker, so the grader would have to
send P itself."""
import os
import time

import rospy

for prefix in os.environ.get('CMAKE_PREFIX_PATH', '').split(':'):
    if prefix.endswith('stand_in'):
        open(os.path.join(prefix, 'started'), 'w').close()
time.sleep(6.0)        # the lab is up by then, and the grader has not sent P yet
rospy.init_node('grade_watch', argv=[])      # not the name roslaunch gives it
rospy.spin()
