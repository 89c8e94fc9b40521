import os
import sys

HERE = os.path.dirname(__file__)
# The package's pure modules, and the bundled simulator's kinematics (always
# in the repository) for closed-loop tests of the executors without ROS.
sys.path.insert(0, os.path.join(HERE, '..', '..', 'src'))
sys.path.insert(0, os.path.join(HERE, '..'))             # test/support
sys.path.insert(0, os.path.join(HERE, '..', '..', 'sim', 'turtlesim', 'src'))
