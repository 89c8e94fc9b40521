"""The viewer's web server, with Debian's tornado: the page and its script
and style (this package's web/ folder), the canvas as /canvas.png, and
/room, a WebSocket that gives each page the room's state. No ROS here.

Read-only: no request changes anything; what a page sends is ignored.
Unknown paths get 404 and other methods 405, with no traceback ever. Each
page gets a snapshot when it connects (the canvas as a PNG, every turtle),
then every SEND_PERIOD only what changed since what it was sent, never a
backlog: a page whose last update is still unread is skipped (and dropped
after STALLED s), and one too far behind gets a snapshot again. A quiet
room still sends each page a word every ALIVE s, so a page can tell a
quiet room from a lost one; a page that answers no ping within PING_TIMEOUT
s (a laptop gone to sleep) is dropped, and its place freed. The strokes
every page and the painting have are folded away (Trails.fold): memory
stays bounded for as long as the room draws."""
import base64
import json
import math
import os
import time

import tornado.ioloop
import tornado.web
import tornado.websocket

from .trails import to_pixels

SEND_PERIOD = 0.04      # s between updates to a page: a pose is on it within about this
STALLED = 10.0          # s a page may leave an update unread before it is dropped
CATCH_UP = 5000         # strokes behind past which a page gets a snapshot instead
ALIVE = 2.0             # s of quiet after which a page is sent a word that the viewer is there
PING_PERIOD, PING_TIMEOUT = 5.0, 15.0   # s: dead connections found by WebSocket pings
FOLD_EVERY = 25         # ticks (1 s) between folds of the strokes every reader has
REFUSED = 1013          # WebSocket close code "try again later": the page backs off
FILES = {'/': ('index.html', 'text/html; charset=utf-8'),
         '/viewer.js': ('viewer.js', 'text/javascript; charset=utf-8'),
         '/viewer.css': ('viewer.css', 'text/css; charset=utf-8')}
SAFE_HEADERS = {'X-Content-Type-Options': 'nosniff', 'Cache-Control': 'no-store',
                'Content-Security-Policy': "default-src 'self'; img-src 'self' data:; "
                                           "connect-src 'self'; frame-ancestors 'none'"}


def _colour(rgb):
    return '#%02x%02x%02x' % tuple(rgb)


def _set_safe_headers(handler):
    for name, value in SAFE_HEADERS.items():
        handler.set_header(name, value)


def _json(value):
    """`value` as JSON a browser can parse: a NaN or an infinity anywhere in
    it (which JSON cannot hold) as null."""
    return json.dumps(_finite(value), allow_nan=False)


def _finite(value):
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(v) for v in value]
    return value


def strokes_message(strokes):
    """Strokes as {"colour/width": [x0, y0, x1, y1, ...]} in canvas pixels, 0.1 px apart."""
    by_pen = {}
    for s in strokes:
        (x0, y0), (x1, y1) = to_pixels(s.x0, s.y0), to_pixels(s.x1, s.y1)
        by_pen.setdefault(f'{_colour(s.colour)}/{s.width}', []).extend(
            round(v, 1) for v in (x0, y0, x1, y1))
    return by_pen


def turtles_message(turtles):
    """{name: [x, y (pixels), theta (rad)]}."""
    return {name.strip('/'): [*(round(v, 1) for v in to_pixels(t.x, t.y)), round(t.theta, 2)]
            for name, t in turtles.items()}


class Base(tornado.web.RequestHandler):
    def set_default_headers(self):
        _set_safe_headers(self)

    def write_error(self, status_code, **_):
        """The status and its reason, never a traceback."""
        self.set_header('Content-Type', 'text/plain; charset=utf-8')
        self.finish(f'{status_code}: {self._reason}\n')


class NotFound(Base):
    def prepare(self):
        raise tornado.web.HTTPError(404)


class PageFile(Base):
    def initialize(self, folder):
        self.folder = folder

    def get(self):
        name, kind = FILES[self.request.path]
        with open(os.path.join(self.folder, name), 'rb') as f:
            self.set_header('Content-Type', kind)
            self.finish(f.read())


class CanvasPng(Base):
    def initialize(self, view):
        self.view = view

    def get(self):
        self.set_header('Content-Type', 'image/png')
        self.finish(self.view.painting.snapshot()[2])


class Page(tornado.websocket.WebSocketHandler):
    """One open page: what it was sent, so that it is sent only what changed."""

    def initialize(self, view, pages):
        self.view, self.pages = view, pages
        self.clears = self.count = 0
        self.sent_turtles, self.sent_room = {}, {}
        self.pending, self.since = None, 0.0

    def set_default_headers(self):
        _set_safe_headers(self)

    def open(self):
        if len(self.pages.open) >= self.pages.most:
            self.close(REFUSED, f'the viewer shows {self.pages.most} pages already')
            return
        self.pages.open.add(self)
        self.send(_json(self.snapshot()))

    def on_message(self, message):
        """Read-only: whatever a page sends changes nothing."""

    def on_close(self):
        self.pages.open.discard(self)

    def snapshot(self):
        clears, count, png = self.view.painting.snapshot()
        self.clears, self.count = clears, count
        self.sent_turtles = turtles_message(self.view.trails.turtles_now())
        self.sent_room = self.view.room()
        return dict(kind='snapshot', background=_colour(self.view.trails.background),
                    canvas='data:image/png;base64,' + base64.b64encode(png).decode(),
                    turtles=self.sent_turtles, room=self.sent_room)

    def update(self, shared):
        """What changed since this page was last sent anything, as JSON, or
        None. `shared` holds what this tick has worked out already: pages
        that were sent the same are sent the same, worked out once."""
        key = (self.clears, self.count)
        if key not in shared:
            clears, strokes, turtles = self.view.trails.since(*key)
            shared[key] = (clears, len(strokes) if strokes is not None else CATCH_UP + 1,
                           _json(strokes_message(strokes or [])))
        if 'turtles' not in shared:
            shared['turtles'] = turtles_message(self.view.trails.turtles_now())
            shared['room'] = self.view.room()
        clears, new, strokes_json = shared[key]
        if clears != self.clears or new > CATCH_UP:
            return _json(self.snapshot())
        self.count += new
        now, room = shared['turtles'], shared['room']
        moved = {n: t for n, t in now.items() if self.sent_turtles.get(n) != t}
        gone = sorted(set(self.sent_turtles) - set(now))
        changed = {k: v for k, v in room.items() if self.sent_room.get(k) != v}
        self.sent_turtles, self.sent_room = now, room
        if not (new or moved or gone or changed):
            return '{"kind": "alive"}' if time.monotonic() - self.since > ALIVE else None
        return (f'{{"kind": "update", "strokes": {strokes_json}, "turtles": {_json(moved)}, '
                f'"gone": {_json(gone)}, "room": {_json(changed)}}}')

    def send(self, text):
        try:
            self.pending, self.since = self.write_message(text), time.monotonic()
        except tornado.websocket.WebSocketClosedError:
            self.pages.open.discard(self)

    def tick(self, shared):
        """Sends what changed, unless the last update is still unread."""
        if self.pending is not None and not self.pending.done():
            if time.monotonic() - self.since > STALLED:
                self.close(1008, 'this page stopped reading the room')
                self.pages.open.discard(self)
            return
        message = self.update(shared)
        if message is not None:
            self.send(message)


class Pages:
    """The open pages, at most `most`, each sent what changed every SEND_PERIOD."""

    def __init__(self, most):
        self.most, self.open = most, set()
        self.ticks = 0

    def tick(self, view):
        shared = {}
        for page in list(self.open):
            page.tick(shared)
        self.ticks += 1
        if self.ticks % FOLD_EVERY == 0:    # the picture brought up to date, then folded
            clears, painted = view.painting.painted()
            view.trails.fold(clears, min([page.count for page in self.open
                                          if page.clears == clears] + [painted]))


def application(view, web_folder, most_pages):
    """The server's routes; `view` has .trails, .painting and .room()."""
    pages = Pages(most_pages)
    routes = [(path, PageFile, dict(folder=web_folder)) for path in FILES]
    routes += [('/canvas.png', CanvasPng, dict(view=view)),
               ('/room', Page, dict(view=view, pages=pages))]
    app = tornado.web.Application(routes, default_handler_class=NotFound,
                                  websocket_max_message_size=1024, serve_traceback=False,
                                  websocket_ping_interval=PING_PERIOD,
                                  websocket_ping_timeout=PING_TIMEOUT)
    tornado.ioloop.PeriodicCallback(lambda: pages.tick(view), SEND_PERIOD * 1000).start()
    return app, pages
