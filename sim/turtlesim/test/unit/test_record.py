"""The simulator's record, as a tick writes it: what the grader counts and
the viewer draws. No ROS here."""
import json
import os

from turtlesim_compat.record import FD_VARIABLE, Record, where
from turtlesim_compat.world import World


def tick(record, turtle, now):
    """One tick of turtlesim_node's, for one turtle, in its order."""
    before, teleports = where(turtle), len(turtle.pending_teleports)
    teleported = turtle.teleport()
    after_jump = where(turtle)
    moved, _ = turtle.move(now)
    record.turtle_ticked(turtle, before, after_jump, teleported, moved, teleports)


def lines_of(read_end):
    with os.fdopen(read_end) as f:
        return [json.loads(line) for line in f]


def test_teleports_that_come_back_where_they_began_are_told_with_their_ink():
    read_end, write_end = os.pipe()
    record = Record({FD_VARIABLE: str(write_end)})
    turtle = World().spawn(5.0, 5.0, 0.0)
    turtle.teleport_absolute(7.0, 5.0, 0.0)
    turtle.teleport_absolute(5.0, 5.0, 0.0)        # back where it began, in the same tick
    tick(record, turtle, 0.0)
    tick(record, turtle, 0.016)                     # nothing asked: nothing told
    record.account.out.close()
    jumps = [line for line in lines_of(read_end) if line['k'] == 'jump']
    assert len(jumps) == 1 and jumps[0]['n'] == 2 and len(jumps[0]['ink']) == 2
    assert jumps[0]['to'] == [5.0, 5.0, 0.0]


def test_each_node_that_acted_is_told_once():
    read_end, write_end = os.pipe()
    record = Record({FD_VARIABLE: str(write_end)})
    for node in ('/controller', '/controller', '/rosservice_1', '/controller'):
        record.acted(node)
    record.account.out.close()
    assert [line['node'] for line in lines_of(read_end) if line['k'] == 'by'] == \
        ['/controller', '/rosservice_1']


def test_each_count_of_commands_names_the_nodes_that_sent_them():
    """The grader tells executables that fight over one turtle by who sent
    its commands: each count (about 0.1 s of ticks) names its senders."""
    read_end, write_end = os.pipe()
    record = Record({FD_VARIABLE: str(write_end)})
    for node in ('/b', '/a', '/b'):
        record.command('turtle1', node)
    record.command('turtle2', '/a')
    for _ in range(6):          # COMMANDS_EVERY ticks
        record.tick_ended()
    record.command('turtle1', '/a')
    for _ in range(6):
        record.tick_ended()
    record.account.out.close()
    counts = [(line['turtle'], line['n'], line['by'])
              for line in lines_of(read_end) if line['k'] == 'cmd']
    assert counts == [('turtle1', 3, ['/a', '/b']), ('turtle2', 1, ['/a']),
                      ('turtle1', 1, ['/a'])]
