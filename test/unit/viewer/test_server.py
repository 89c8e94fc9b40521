"""The viewer's web server, for real on a loopback port (no ROS: the room it
shows is a Trails fed here): what it serves and refuses, the snapshot and
the changes a page gets, the most pages it takes, and a page that stops
reading, dropped while the others go on."""
import asyncio
import json
import socket
import threading
import time
import types
import urllib.error
import urllib.request

import pytest
import tornado.ioloop
import tornado.websocket

from turtle_letters.viewer import server
from turtle_letters.viewer.picture import Painting
from turtle_letters.viewer.trails import Trails

PEN = (179, 184, 255)
WEB = __file__.rsplit('/test/', 1)[0] + '/web'


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


@pytest.fixture
def room():
    """A server on a free port, in a thread of its own, showing a Trails."""
    trails = Trails()
    view = types.SimpleNamespace(trails=trails, painting=Painting(trails),
                                 room=lambda: dict(drawings={}, scoreboard=''))
    port, started = free_port(), threading.Event()
    loops = []

    def serve():
        asyncio.set_event_loop(asyncio.new_event_loop())
        app, pages = server.application(view, WEB, most_pages=2)
        app.listen(port, '127.0.0.1')
        loops.append((tornado.ioloop.IOLoop.current(), pages))
        started.set()
        tornado.ioloop.IOLoop.current().start()
    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    started.wait(5)
    yield types.SimpleNamespace(trails=trails, view=view, port=port, pages=loops[0][1],
                                url=f'http://127.0.0.1:{port}')
    loops[0][0].add_callback(loops[0][0].stop)
    thread.join(5)


def fetch(url, method='GET'):
    try:
        with urllib.request.urlopen(urllib.request.Request(url, method=method), timeout=5) as r:
            return r.status, r.headers, r.read()
    except urllib.error.HTTPError as e:
        return e.code, e.headers, e.read()


def raw_get(port, path):
    """The status line of a GET of `path` exactly as written (no client tidies it)."""
    with socket.create_connection(('127.0.0.1', port), timeout=5) as s:
        s.sendall(f'GET {path} HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n'.encode())
        return s.makefile('rb').readline().decode()


def test_the_page_its_files_and_the_canvas_are_served_read_only(room):
    status, headers, body = fetch(room.url + '/')
    assert status == 200 and b'<canvas id="canvas"' in body
    assert "default-src 'self'" in headers['Content-Security-Policy']
    assert fetch(room.url + '/viewer.js')[0] == 200 and fetch(room.url + '/viewer.css')[0] == 200
    status, headers, body = fetch(room.url + '/canvas.png')
    assert status == 200 and headers['Content-Type'] == 'image/png' and body[:4] == b'\x89PNG'


@pytest.mark.parametrize('path', ['/nothing', '/index.html', '/../../etc/passwd',
                                  '/%2e%2e/%2e%2e/etc/passwd', '/..%2f..%2fetc%2fpasswd',
                                  '//etc/passwd', '/viewer.js/..', '/web/viewer.js'])
def test_any_other_path_is_not_found(room, path):
    assert ' 404 ' in raw_get(room.port, path)


@pytest.mark.parametrize('method', ['POST', 'PUT', 'DELETE', 'PATCH'])
def test_other_methods_are_refused_without_a_traceback(room, method):
    status, _, body = fetch(room.url + '/', method)
    assert status == 405 and b'Traceback' not in body and b'File "' not in body


async def _page(url, messages=1):
    connection = await tornado.websocket.websocket_connect(url.replace('http', 'ws') + '/room')
    got = [json.loads(await connection.read_message()) for _ in range(messages)]
    return connection, got


def line(room, x0, x1):
    """A stroke along y = 1 m in the default pen, as the bundled simulator says it laid it."""
    room.trails.ink([dict(k='move', turtle='/turtle1', ink=[[x0, 1.0, x1, 1.0, *PEN, 3]])])


def test_a_page_gets_a_snapshot_then_only_what_changed(room):
    room.trails.pose('/turtle1', 1.0, 1.0, 0.0)

    async def look():
        connection, (snapshot,) = await _page(room.url)
        room.trails.pose('/turtle1', 2.0, 1.0, 0.5)
        line(room, 1.0, 2.0)
        update = json.loads(await connection.read_message())
        connection.write_message('{"publish": "/turtle1/cmd_vel"}')     # read-only: ignored
        await asyncio.sleep(0.2)
        connection.close()
        return snapshot, update
    snapshot, update = asyncio.run(look())
    assert snapshot['kind'] == 'snapshot' and snapshot['canvas'].startswith('data:image/png')
    assert snapshot['turtles'] == {'turtle1': [45.0, 454.0, 0.0]}
    assert update['kind'] == 'update' and update['turtles'] == {'turtle1': [90.0, 454.0, 0.5]}
    assert update['strokes'] == {'#b3b8ff/3': [45.0, 454.0, 90.0, 454.0]}
    assert len(room.trails.strokes) == 1


def test_past_the_most_pages_a_polite_refusal(room):
    async def crowd():
        first, _ = await _page(room.url)
        second, _ = await _page(room.url)
        third = await tornado.websocket.websocket_connect(room.url.replace('http', 'ws') + '/room')
        said = await third.read_message()
        return said, third.close_code, third.close_reason
    said, code, reason = asyncio.run(crowd())
    assert said is None and code == 1013 and 'shows 2 pages already' in reason


def test_a_page_that_stops_reading_is_dropped_and_the_others_go_on(room, monkeypatch):
    monkeypatch.setattr(server, 'STALLED', 1.0)
    key = 'dGhlIHNhbXBsZSBub25jZQ=='
    stalled = socket.create_connection(('127.0.0.1', room.port))
    stalled.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    stalled.sendall((f'GET /room HTTP/1.1\r\nHost: 127.0.0.1:{room.port}\r\nUpgrade: websocket\r\n'
                     f'Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\n'
                     f'Sec-WebSocket-Version: 13\r\n\r\n').encode())

    async def read_on():
        """Updates the live page heard after the stalled one was dropped, up
        to 5, no rate asked (a slow machine strokes fewer a second). The
        drop is awaited 12 s: a page that answers no ping is dropped from
        15 s (server.PING_TIMEOUT), stalled or not."""
        connection, _ = await _page(room.url)
        rounds, after_drop, deadline = 0, 0, time.monotonic() + 12
        while after_drop < 5 and (after_drop or time.monotonic() < deadline):
            for i in range(1000):   # strokes enough to fill the stalled page's socket buffers
                x = 1 + (rounds * 1000 + i) % 900 / 100
                room.trails.pose('/turtle1', x, 1.0, 0.0)
                line(room, x - 0.01, x)
            rounds += 1
            message = await asyncio.wait_for(connection.read_message(), 10)
            assert message is not None      # the live page is never dropped
            after_drop += len(room.pages.open) == 1     # the stalled one is gone
        return after_drop
    assert asyncio.run(read_on()) == 5
    stalled.close()


def test_no_nan_or_infinity_ever_reaches_a_page(room):
    """A NaN once froze every page (a browser cannot parse it, and each
    reconnect got it again): what a page is sent is always strict JSON."""
    room.trails.pose('/turtle1', float('nan'), 1.0, 0.0)
    room.trails.pose('/turtle2', 1.0, 1.0, 0.0)
    room.view.room = lambda: dict(drawings={'/alice': dict(eta=float('inf'),
                                                           progress=float('nan'))}, scoreboard='')

    def strict(text):
        return json.loads(text, parse_constant=lambda name: pytest.fail(f'{name} sent'))

    async def look():
        connection = await tornado.websocket.websocket_connect(
            room.url.replace('http', 'ws') + '/room')
        snapshot = strict(await connection.read_message())
        connection.close()
        return snapshot
    snapshot = asyncio.run(look())
    assert list(snapshot['turtles']) == ['turtle2']
    assert snapshot['room']['drawings'] == {'/alice': dict(eta=None, progress=None)}


def test_a_quiet_room_still_says_it_is_there(room, monkeypatch):
    monkeypatch.setattr(server, 'ALIVE', 0.3)

    async def listen():
        connection, _ = await _page(room.url)
        started = time.monotonic()
        said = json.loads(await asyncio.wait_for(connection.read_message(), 3))
        connection.close()
        return said, time.monotonic() - started
    said, after = asyncio.run(listen())
    assert said == {'kind': 'alive'} and 0.2 < after < 2.0


def test_strokes_every_reader_holds_are_folded_and_a_page_behind_them_starts_again(room):
    async def draw_and_look():
        connection, _ = await _page(room.url)
        for i in range(3000):
            room.trails.pose('/turtle1', 1 + i % 900 / 100, 1.0, 0.0)
            line(room, 0.99 + i % 900 / 100, 1 + i % 900 / 100)
            if i % 100 == 0:
                await connection.read_message()
        deadline = time.monotonic() + 5
        while room.trails.strokes and time.monotonic() < deadline:
            await asyncio.sleep(0.1)
        folded = (len(room.trails.strokes), room.trails.folded)
        late, (snapshot,) = await _page(room.url)       # a page that comes after the fold
        connection.close()
        late.close()
        return folded, snapshot
    (kept, folded), snapshot = asyncio.run(draw_and_look())
    assert kept == 0 and folded > 2900          # everyone had them: all folded away
    assert snapshot['kind'] == 'snapshot'       # the picture holds them
    assert room.trails.since(room.trails.clears, 0)[1] is None
    assert room.trails.since(room.trails.clears, folded)[1] == []
