"""The room's rule for granting parts (parts.contenders), under adversarial
interleavings: many controllers choosing at once, each pausing at random
between looking and asking, some parts left by controllers that died."""
import random
import threading
import time

import pytest

from turtle_letters.letters.font import BUILTIN
from turtle_letters.classroom.parts import contenders, free_place, overlaps, part_box


class RoomModel:
    """What room.Room does per request, over a dict instead of the parameter
    server: one lock, the contenders that are alive refuse, else the record."""

    def __init__(self, parts, dead=()):
        self.parts = dict(parts)
        self.dead = set(dead)
        self.lock = threading.Lock()

    def alive(self, part):
        return part['uri'] not in self.dead

    def take(self, turtle, uri, box):
        with self.lock:
            standing = contenders(self.parts, turtle, uri, box)
            crossed = sorted(n for n, p in standing.items() if self.alive(p))
            if not crossed:
                self.parts[turtle] = {'uri': uri, 'box': list(box)}
            return crossed

    def live_others(self, turtle):
        with self.lock:
            return {n: p['box'] for n, p in self.parts.items()
                    if n != turtle and self.alive(p)}


def controller(room, name, rng, width=0.6):
    """The controller's loop: look at the free parts, pause, ask; again if refused."""
    for _ in range(50):
        place = free_place(width, 1.0, BUILTIN, room.live_others(name).values())
        assert place is not None
        time.sleep(rng.random() * 0.002)        # the adversary: anything may happen here
        box = part_box(place, width, 1.0, BUILTIN)
        if not room.take(name, f'uri-{name}', box):
            return box
    raise AssertionError(f'{name} never got a part')


@pytest.mark.parametrize('seed', range(20))
def test_controllers_choosing_at_once_never_share_a_part(seed):
    dead = {'zed': {'uri': 'uri-dead', 'box': list(part_box((0.5, 9.39), 0.6, 1.0, BUILTIN))}}
    room = RoomModel(dead, dead={'uri-dead'})
    rng = random.Random(seed)
    got = {}
    names = [f's{i:02d}' for i in range(12)]
    threads = [threading.Thread(target=lambda n=n, r=random.Random(rng.random()):
                                got.__setitem__(n, controller(room, n, r))) for n in names]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert sorted(got) == names
    for a in names:
        for b in names:
            assert a == b or not overlaps(got[a], got[b]), (a, b)
    # the dead controller's part was free to take
    assert any(overlaps(box, dead['zed']['box']) for box in got.values())


def test_a_live_controller_of_the_same_turtle_keeps_it():
    box = part_box((0.5, 9.39), 0.6, 1.0, BUILTIN)
    room = RoomModel({'alice': {'uri': 'uri-first', 'box': list(box)}})
    assert room.take('alice', 'uri-second', box) == ['alice']
    assert room.parts['alice']['uri'] == 'uri-first'


def test_a_restarted_controller_takes_its_own_part_back():
    box = part_box((0.5, 9.39), 0.6, 1.0, BUILTIN)
    room = RoomModel({'alice': {'uri': 'uri-crashed', 'box': list(box)}}, dead={'uri-crashed'})
    assert room.take('alice', 'uri-restarted', box) == []
    assert room.parts['alice']['uri'] == 'uri-restarted'
