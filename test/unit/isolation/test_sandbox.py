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


def test_a_zombie_is_waited_for_until_reaped_and_a_live_process_is_not():
    """wait_reaped: a forced exit waits for the killed processes init has to
    reap (a zombie here: one of ours not yet waited for), not for those
    that still run."""
    import subprocess
    import threading
    import time
    from turtle_letters.isolation.sandbox import wait_reaped
    user = 1999999999 if os.geteuid() == 0 else os.geteuid()   # root's has kernel threads
    as_user = ['setpriv', f'--reuid={user}', f'--regid={user}', '--clear-groups', '--'] \
        if os.geteuid() == 0 else []
    running = subprocess.Popen(as_user + ['sleep', '30'])
    ended = subprocess.Popen(as_user + ['true'])
    while open(f'/proc/{ended.pid}/stat').read().rsplit(')', 1)[1].split()[0] != 'Z':
        time.sleep(0.01)
    threading.Timer(1.0, ended.wait).start()      # reaped a second on, as a slow init does
    started = time.monotonic()
    wait_reaped({user}, seconds=20)
    took = time.monotonic() - started
    running.kill()
    running.wait()
    assert 0.9 < took < 15, took
