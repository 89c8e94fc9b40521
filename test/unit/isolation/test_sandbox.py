"""What the sandbox shows of the ROS environment it covers: a workspace
(and the checkout its links point into) under /tmp, /root or /home stays
visible, read-only, folder by folder: never the home or top folder that
holds it, since the sandbox covers those folders."""
import os

from turtle_letters.isolation.sandbox import underlays


def test_a_workspace_under_tmp_and_the_checkout_its_links_point_into(tmp_path):
    checkout, ws = tmp_path / 'checkout', tmp_path / 'ws'
    for folder in ('src', 'sim/turtlesim', 'secrets'):
        (checkout / folder).mkdir(parents=True)
    (checkout / 'package.xml').touch()
    for folder in ('src/turtle_letters', 'devel/lib', 'build'):
        (ws / folder).mkdir(parents=True)
    os.symlink(str(checkout / 'src'), str(ws / 'src' / 'turtle_letters' / 'src'))
    os.symlink(str(checkout / 'package.xml'), str(ws / 'src' / 'turtle_letters' / 'package.xml'))
    os.symlink(str(checkout / 'sim' / 'turtlesim'), str(ws / 'src' / 'turtlesim'))
    assert str(tmp_path).startswith('/tmp/')        # pytest's tmp_path is under /tmp
    shown = underlays({'ROS_PACKAGE_PATH': f'{ws}/src:/usr/share',
                       'CMAKE_PREFIX_PATH': f'{ws}/devel:/opt/ros/noetic:/tmp/not-there',
                       'LD_LIBRARY_PATH': f'{ws}/devel/lib'})
    assert shown == sorted(str(p) for p in (
        checkout / 'package.xml', checkout / 'sim' / 'turtlesim', checkout / 'src',
        ws / 'devel', ws / 'src'))


def test_nothing_to_show_for_a_system_install():
    assert underlays({'ROS_PACKAGE_PATH': '/opt/ros/noetic/share', 'PYTHONPATH': '/usr/lib'}) == []
