import os
import sys

HERE = os.path.dirname(__file__)
# The package's pure modules, and the bundled simulator's kinematics (always
# in the repository) for closed-loop tests of the executors without ROS.
sys.path.insert(0, os.path.join(HERE, '..', '..', 'src'))
sys.path.insert(0, os.path.join(HERE, '..'))             # test/support
sys.path.insert(0, os.path.join(HERE, '..', '..', 'sim', 'turtlesim', 'src'))

# Where the package is built and its workspace sourced, its generated
# messages (turtle_letters.msg, .srv) live beside the built copy: the
# source's package must find them there too.
import turtle_letters  # noqa: E402

for folder in sys.path[3:]:
    built = os.path.join(folder, 'turtle_letters')
    if os.path.isdir(os.path.join(built, 'msg')) and built not in turtle_letters.__path__:
        turtle_letters.__path__.append(built)
