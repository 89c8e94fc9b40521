"""What a course's Noetic machine offers, offered here: turtlesim's headers
found where roscpp's are, whichever workspace built them. No ROS here."""
import os

from turtle_letters.autograder import world as machine


def headers(folder):
    os.makedirs(os.path.join(folder, 'turtlesim'), exist_ok=True)
    open(os.path.join(folder, 'turtlesim', 'Pose.h'), 'w').close()


def test_turtlesim_headers_of_a_workspace_are_offered_where_roscpp_has_none(tmp_path,
                                                                           monkeypatch):
    roscpp, ws = tmp_path / 'usr_include', tmp_path / 'ws' / 'devel'
    (roscpp / 'ros').mkdir(parents=True)
    (roscpp / 'ros' / 'ros.h').touch()
    headers(str(ws / 'include'))
    monkeypatch.setattr(machine, 'ROSCPP_INCLUDES', (str(roscpp),))
    environ = {'CMAKE_PREFIX_PATH': f'/nowhere:{ws}:/usr', 'CPATH': '/mine'}
    assert machine.course_environment(environ) == {'CPATH': f'{ws}/include:/mine'}
    headers(str(roscpp))        # as on /opt/ros/noetic: beside roscpp's already
    assert machine.course_environment(environ) == {}
