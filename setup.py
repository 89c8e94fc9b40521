from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(
    packages=['turtle_letters', 'turtle_letters.actions', 'turtle_letters.classroom',
              'turtle_letters.grading', 'turtle_letters.letters', 'turtle_letters.motion'],
    package_dir={'': 'src'},
))
