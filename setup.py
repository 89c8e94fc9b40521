from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(
    packages=['turtle_letters'] + [f'turtle_letters.{folder}' for folder in (
        'actions', 'autograder', 'classroom', 'grading', 'isolation', 'letters', 'motion',
        'reading', 'viewer')],
    package_dir={'': 'src'},
))
