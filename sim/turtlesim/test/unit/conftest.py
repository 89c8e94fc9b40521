import os
import sys

# The simulator's pure modules, importable without a catkin workspace.
sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', '..', 'src'))
