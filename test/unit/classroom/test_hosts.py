"""check_network.py's verdict on the host name this machine advertises."""
from turtle_letters.classroom.hosts import host_verdict

LOCAL = ['127.0.0.1', '198.51.100.2']


def test_a_name_for_one_of_our_addresses_passes():
    passed, line = host_verdict('alice', 'ROS_HOSTNAME', ['198.51.100.2'], LOCAL, True)
    assert passed and "'alice'" in line


def test_a_name_that_does_not_resolve_fails_saying_what_to_set():
    passed, line = host_verdict('alice', 'ROS_HOSTNAME', [], LOCAL, True)
    assert not passed and 'does not resolve' in line and 'ROS_IP' in line


def test_another_machines_address_fails():
    passed, line = host_verdict('bob', 'ROS_HOSTNAME', ['198.51.100.3'], LOCAL, True)
    assert not passed and 'not to any of its own addresses' in line


def test_loopback_passes_alone_and_fails_when_others_must_reach_us():
    assert host_verdict('127.0.0.1', 'ROS_IP', ['127.0.0.1'], LOCAL, False)[0]
    passed, line = host_verdict('127.0.0.1', 'ROS_IP', ['127.0.0.1'], LOCAL, True)
    assert not passed and '198.51.100.2' in line
