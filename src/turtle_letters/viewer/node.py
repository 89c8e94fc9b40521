"""Node view (view.py): the shared canvas, live, for any seat in the room.

It rebuilds the canvas (trails.py) from the ink the bundled simulator says
it laid (its `ink` topic), or, with the real turtlesim, which publishes no
ink, from every turtle's pose and color_sensor (pens.py); and it
serves it (server.py) as a page at http://ADDRESS:PORT/, with each turtle,
each student's drawing from their draw action's feedback, and the room's
scoreboard when there is one. It publishes the canvas on `canvas/image`
(sensor_msgs/Image, rgb8) for image_view, rqt_image_view and rviz.

Parameters (VIEWING): ~port (int, 8080), ~address (str, '127.0.0.1'; ''
for every interface), ~image_rate (Hz, 5.0), ~max_pages (int, 120), ~ink
(bool, true; false rebuilds from poses even where the simulator says its ink).
"""

import json
import os
import struct

import rosgraph
import rospkg
import rospy
import tornado.ioloop
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import Image
from std_msgs.msg import String

from ..motion.driver import CANVAS_WORDS
from ..letters.layout import CANVAS_PIXELS
from ..settings import Parameter, ParameterError, boolean, positive, read_parameter
from .picture import Painting
from .server import application
from .trails import DEFAULT_BACKGROUND, Trails
from .drawings import Drawings

LOOK_PERIOD = 1.0       # s between looks for turtles and drawings come or gone
POSE = struct.Struct('<4f')     # turtlesim/Pose begins x, y, theta, linear_velocity (float32)
COLOR = struct.Struct('<3B')    # turtlesim/Color: r, g, b (uint8)


def _port(value, font=None):
    if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= 65535:
        raise ValueError('a port number, 1 to 65535')
    return value


def _address(value, font=None):
    if not isinstance(value, str):
        raise ValueError("an address of this machine's, or '' for all of them")
    return value


def _pages(value, font=None):
    if isinstance(value, bool) or not isinstance(value, int) or value < 1:
        raise ValueError('a whole number of pages, 1 or more')
    return value


VIEWING = {p.name: p for p in (
    Parameter('port', 'int', '8080', '', 'the port the page is served on', _port),
    Parameter('address', 'str', '127.0.0.1', '', "the address it is served on ('': every one)",
              _address),
    Parameter('image_rate', 'float', '5.0', 'Hz', 'how often canvas/image is published',
              positive),
    Parameter('max_pages', 'int', '120', '', 'pages open at once; past it, a polite refusal',
              _pages),
    Parameter('ink', 'bool', 'true', '', "draw the ink the bundled simulator says it laid "
              "(false: rebuild it from poses, as for the real turtlesim)", boolean),
)}


class View:
    """What the page shows: the trails, their painting, the drawings and the scoreboard."""

    def __init__(self, background, use_ink=True):
        self.trails = Trails(background)
        self.use_ink = use_ink
        self.painting = Painting(self.trails)
        self.drawings = Drawings()
        self.scoreboard = ''
        self.turtles = {}           # name: its subscribers
        self.simulators = set()     # nodes that serve /spawn
        self.ink = None             # the subscriber to a simulator's ink, when it has one
        self.master = rosgraph.Master(rospy.get_name())

    def room(self):
        return dict(drawings=self.drawings.table(), scoreboard=self.scoreboard)

    def look(self):
        """Subscribes to turtles and drawings that came; forgets turtles gone."""
        try:
            topics = dict(rospy.get_published_topics())
            services = self.master.getSystemState()[2]
        except (OSError, rosgraph.MasterException):
            return
        self.simulators = set(dict(services).get('/spawn', []))
        for simulator in sorted(self.simulators):
            if (topics.get(f'{simulator}/ink') == 'std_msgs/String' and self.ink is None
                    and self.use_ink):
                self.ink = rospy.Subscriber(f'{simulator}/ink', String, lambda m: self.trails.ink(
                    _lines(m.data)), queue_size=1000)
        for topic, kind in topics.items():
            turtle = topic[:-len('/pose')]
            if kind == 'turtlesim/Pose' and topic.endswith('/pose') and turtle not in self.turtles:
                self._follow(turtle)
        for name in [n for n in self.turtles if f'{n}/pose' not in topics]:
            for subscriber in self.turtles.pop(name):
                subscriber.unregister()
            self.trails.gone(name)
        self.drawings.look(topics)

    def _follow(self, name):
        # Read unparsed (rospy.AnyMsg): with 30 turtles, 3,750 messages a
        # second come, and their fixed layouts unpack at a fraction of the cost.
        # With the simulator's ink, the colour under a turtle tells nothing
        # more: not subscribing spares the simulator half the messages.
        self.turtles[name] = [
            rospy.Subscriber(f'{name}/pose', rospy.AnyMsg, lambda m: self.trails.pose(
                name, *POSE.unpack_from(m._buff)), queue_size=100)]
        if self.ink is None:
            self.turtles[name].append(rospy.Subscriber(
                f'{name}/color_sensor', rospy.AnyMsg, lambda m: self.trails.colour(
                    name, COLOR.unpack_from(m._buff)), queue_size=100))

    def on_log(self, message):
        """turtlesim's own word that it cleared or reset its canvas."""
        what = CANVAS_WORDS.get(message.msg)
        if self.trails.inked:       # the ink says so itself, with the background
            return
        if what and message._connection_header.get('callerid') in self.simulators:
            background = _background(self.master)   # a clear re-reads it, as turtlesim does
            (self.trails.clear if what == 'clear' else self.trails.reset)(background)


def _lines(text):
    """A tick of the simulator's ink (a JSON list of its record's lines); [] if it is not one."""
    try:
        lines = json.loads(text)
    except ValueError:
        return []
    return [line for line in lines if isinstance(line, dict)] if isinstance(lines, list) else []


def _background(master):
    """The simulator's background colour, from its parameters (turtlesim's default if unset)."""
    try:
        simulators = dict(master.getSystemState()[2]).get('/spawn', [])
    except (OSError, rosgraph.MasterException):
        simulators = []
    if not simulators:
        return DEFAULT_BACKGROUND
    return tuple(rospy.get_param(f'{simulators[0]}/background_{c}', d)
                 for c, d in zip('rgb', DEFAULT_BACKGROUND))


def _publish_image(view, publisher):
    if not publisher.get_num_connections():     # painting and a 750 kB message cost
        return
    view.painting.update()
    publisher.publish(Image(height=CANVAS_PIXELS, width=CANVAS_PIXELS, encoding='rgb8',
                            is_bigendian=0, step=3 * CANVAS_PIXELS, data=view.painting.rgb()))


def main():
    rospy.init_node('view')
    try:
        settings = {name: read_parameter(name, rospy.get_param, table=VIEWING) for name in VIEWING}
    except ParameterError as e:
        rospy.logfatal('%s: %s', rospy.get_name(), e)
        raise SystemExit(2)
    view = View(_background(rosgraph.Master(rospy.get_name())), settings['ink'])
    web = os.path.join(rospkg.RosPack().get_path('turtle_letters'), 'web')
    app, _ = application(view, web, settings['max_pages'])
    try:
        app.listen(settings['port'], settings['address'])
    except OSError as e:
        rospy.logfatal('%s: cannot serve on %s:%d (%s): choose another with view_port:=',
                       rospy.get_name(), settings['address'] or '*', settings['port'], e.strerror)
        raise SystemExit(2)
    rospy.Subscriber('/rosout', Log, view.on_log, queue_size=100)
    rospy.Subscriber('scoreboard', String, lambda m: setattr(view, 'scoreboard', m.data),
                     queue_size=1)
    image = rospy.Publisher('canvas/image', Image, queue_size=1)
    rospy.Timer(rospy.Duration(1.0 / settings['image_rate']), lambda _: _publish_image(view, image))
    view.look()
    rospy.Timer(rospy.Duration(LOOK_PERIOD), lambda _: view.look())
    loop = tornado.ioloop.IOLoop.current()
    rospy.on_shutdown(lambda: loop.add_callback(loop.stop))
    rospy.loginfo('View: the room at http://%s:%d/ and on %s', settings['address'] or 'THIS_HOST',
                  settings['port'], rospy.resolve_name('canvas/image'))
    loop.start()
