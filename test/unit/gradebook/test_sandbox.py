"""What the sandbox shows of the ROS environment it covers: a workspace
(and the checkout its links point into) under /tmp, /root or /home stays
visible, read-only, since the sandbox covers those folders."""
import os

from turtle_letters.gradebook.sandbox import underlays


def test_a_workspace_under_tmp_and_the_checkout_its_links_point_into(tmp_path):
    checkout, ws = tmp_path / 'checkout', tmp_path / 'ws'
    (checkout / 'src').mkdir(parents=True)
    (ws / 'src' / 'turtle_letters').mkdir(parents=True)
    os.symlink(str(checkout / 'src'), str(ws / 'src' / 'turtle_letters' / 'src'))
    top = '/' + str(tmp_path).strip('/').split('/')[0]
    assert top in ('/tmp', '/root', '/home')        # pytest's tmp_path is under /tmp
    shown = underlays({'ROS_PACKAGE_PATH': f'{ws}/src:/usr/share',
                       'CMAKE_PREFIX_PATH': '/opt/ros/noetic:/tmp/not-there'})
    assert shown == [os.path.join(top, str(tmp_path)[len(top) + 1:].split('/')[0])]


def test_nothing_to_show_for_a_system_install():
    assert underlays({'ROS_PACKAGE_PATH': '/opt/ros/noetic/share', 'PYTHONPATH': '/usr/lib'}) == []
