#!/usr/bin/python3
"""The viewer in a real browser (headless Chromium through Selenium): the
page's canvas against the simulator's own saved canvas, each turtle's name,
the drawings table and the scoreboard's, canvas/image (as image_view's
image_saver saves it) and /canvas.png, the
page reconnecting by itself after the viewer restarts, and no error in the
browser's console."""
import base64
import os
import shutil
import signal
import socket
import tempfile
import unittest
import urllib.request

import actionlib
import rospy
import rostest
from PyQt5.QtGui import QColor, QImage
from geometry_msgs.msg import Twist, Vector3
from sensor_msgs.msg import Image
from std_msgs.msg import String
from std_srvs.srv import Empty, Trigger
from turtlesim.msg import Pose
from turtlesim.srv import SetPen, TeleportAbsolute

from support.browser import browser, have_browser
from support.nodes import NodeProcess, connections, wait_until
from turtle_letters.msg import DrawAction, DrawGoal

BACKGROUND = (69, 86, 255)
NEAR = 2            # px: a stroke's edge may fall a pixel or two either way
AGREE = 0.97        # share of ink pixels that must have ink near them in the other picture
ICON = 20           # px around the turtle: its icon covers the saved canvas there
TABLE = 'student  letter  verdict\nturtle1  L       pass'     # as the scoreboard publishes it


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def ink(image, skip=None):
    """The pixels of a 500-pixel canvas that are not the background, but those near `skip`."""
    found = set()
    for y in range(image.height()):
        for x in range(image.width()):
            if skip and (x - skip[0]) ** 2 + (y - skip[1]) ** 2 < ICON ** 2:
                continue
            c = QColor(image.pixel(x, y))
            if (c.red(), c.green(), c.blue()) != BACKGROUND:
                found.add((x, y))
    return found


def near_share(pixels, others):
    """The share of `pixels` with one of `others` within NEAR px."""
    near = sum(1 for x, y in pixels if any((x + dx, y + dy) in others
                                           for dx in range(-NEAR, NEAR + 1)
                                           for dy in range(-NEAR, NEAR + 1)))
    return near / max(len(pixels), 1)


def drive(publisher, speed, seconds):
    """Straight ahead at `speed` for `seconds`, commanded at 50 Hz, then stop."""
    end = rospy.get_time() + seconds
    while rospy.get_time() < end:
        publisher.publish(Twist(linear=Vector3(speed, 0, 0)))
        rospy.sleep(0.02)
    publisher.publish(Twist())
    rospy.sleep(0.2)


def draw_lines(lines, rest=0.0):
    """Each ((x, y), colour, width, speed): 3 m from (x, y) along x, with that
    pen, reached with the pen up (and `rest` s there); turtle1's pen and
    teleport services, for what a test does next."""
    pen = rospy.ServiceProxy('/turtle1/set_pen', SetPen)
    teleport = rospy.ServiceProxy('/turtle1/teleport_absolute', TeleportAbsolute)
    cmd_vel = rospy.Publisher('/turtle1/cmd_vel', Twist, queue_size=10)
    wait_until(lambda: cmd_vel.get_num_connections() > 0, 10, 'turtlesim on cmd_vel')
    for (x, y), rgb, width, speed in lines:
        pen(0, 0, 0, 3, 1)
        teleport(x, y, 0.0)
        rospy.sleep(rest)
        pen(*rgb, width, 0)
        drive(cmd_vel, speed, 3.0 / speed)
    return pen, teleport


@unittest.skipUnless(have_browser(), 'no chromium-driver here (make deps installs it)')
class ViewerInABrowser(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('viewer_test')
        cls.port = free_port()
        cls.url = f'http://127.0.0.1:{cls.port}/'
        cls.viewer = cls.start_viewer()
        cls.profile = tempfile.mkdtemp(prefix='turtle_letters_chromium_')
        cls.driver = browser(cls.profile)
        cls.driver.get(cls.url)
        cls.wait_for_page(lambda: cls.status() == 'live' and cls.names() == ['turtle1'],
                          'the page live, with turtle1')
        client = actionlib.SimpleActionClient('/draw', DrawAction)
        assert client.wait_for_server(rospy.Duration(30)), 'no draw action'
        # A goal is not latched: the viewer sees its text only once it hears the goal
        # topic, and that holds once this client's publisher counts it (the viewer can
        # count the connection first, and a goal sent then reached nobody but the server).
        wait_until(lambda: connections('/view', '/draw/goal', 'i') and
                   client.action_client.pub_goal.get_num_connections() >= 2, 30,
                   "the viewer connected to the draw action's goal topic", cls.viewer.output)
        client.send_goal(DrawGoal(text='L'))
        assert client.wait_for_result(rospy.Duration(120)), 'the L was not drawn in 120 s'
        cls.result = client.get_result()
        cls.pose = rospy.wait_for_message('/turtle1/pose', Pose, timeout=10)
        cls.scoreboard = rospy.Publisher('/scoreboard', String, queue_size=1, latch=True)
        cls.scoreboard.publish(String(TABLE))

    @classmethod
    def tearDownClass(cls):
        cls.driver.quit()
        cls.viewer.stop()
        shutil.rmtree(cls.profile, ignore_errors=True)

    @classmethod
    def start_viewer(cls):
        viewer = NodeProcess('turtle_letters', 'view.py', f'_port:={cls.port}')
        wait_until(lambda: cls.serving(viewer, cls.port), 30, 'the viewer serving its page',
                   viewer.output)
        return viewer

    @staticmethod
    def serving(viewer, port):
        """Whether `viewer` (a NodeProcess) says it serves on `port`, and a
        page is there: a port found free may be taken by another test's
        server before the viewer binds it (the viewer then says so, and ends)."""
        if f':{port}/' not in viewer.output():
            return False
        try:
            return urllib.request.urlopen(f'http://127.0.0.1:{port}/', timeout=1).status == 200
        except OSError:
            return False

    @classmethod
    def status(cls):
        return cls.driver.find_element('id', 'status').text

    @classmethod
    def names(cls):
        return [item.text for item in cls.driver.find_elements('css selector', '#turtle-names li')]

    @classmethod
    def wait_for_page(cls, condition, what, timeout=30):
        wait_until(condition, timeout, what, lambda: f'status {cls.status()!r}, names {cls.names()}')

    def page_canvas(self):
        url = self.driver.execute_script(
            "return document.getElementById('canvas').toDataURL('image/png')")
        image = QImage()
        image.loadFromData(base64.b64decode(url.split(',', 1)[1]), 'PNG')
        return image

    def errors(self):
        return [entry['message'] for entry in self.driver.get_log('browser')
                if entry['level'] == 'SEVERE']

    def test_1_no_error_in_the_console(self):
        self.assertEqual(self.errors(), [])

    def test_2_the_page_shows_what_turtlesim_drew(self):
        saved = rospy.ServiceProxy('/turtlesim/save_canvas', Trigger)()
        self.assertTrue(saved.success, saved.message)
        turtle = (self.pose.x * 45, 499 - self.pose.y * 45)
        wait_until(lambda: len(ink(self.page_canvas(), turtle)) > 100, 10, 'ink on the page')
        page, simulator = ink(self.page_canvas(), turtle), ink(QImage(saved.message), turtle)
        self.assertGreater(len(simulator), 100)
        self.assertGreater(near_share(simulator, page), AGREE, 'turtlesim ink missing on the page')
        self.assertGreater(near_share(page, simulator), AGREE, 'page ink turtlesim has not')

    def test_2b_fast_thin_lines_and_a_pen_up_teleport_as_turtlesim_drew_them(self):
        """The bundled simulator says what ink it laid: a 1-px line at 2.5 m/s,
        a 3-px one at 1 m/s, and a pen-up teleport that lands on ink and jumps
        away (no line), each on the page as on turtlesim's own canvas."""
        if ['/turtlesim/ink', 'std_msgs/String'] not in rospy.get_published_topics():
            self.skipTest('the real turtlesim publishes no ink; the page rebuilds from poses')
        pen, teleport = draw_lines((((1.0, 1.0), (255, 0, 0), 1, 2.5),
                                    ((1.0, 2.0), (0, 160, 0), 3, 1.0)))
        pen(0, 0, 0, 3, 1)
        teleport(2.0, 1.0, 0.0)         # onto the red line
        teleport(9.0, 9.0, 0.0)         # and away
        rospy.sleep(1.0)
        saved = rospy.ServiceProxy('/turtlesim/save_canvas', Trigger)()
        self.assertTrue(saved.success, saved.message)
        turtle = (9.0 * 45, 499 - 9.0 * 45)
        simulator = ink(QImage(saved.message), turtle)
        wait_until(lambda: near_share(simulator, ink(self.page_canvas(), turtle)) > AGREE, 10,
                   "turtlesim's ink on the page")
        page = ink(self.page_canvas(), turtle)
        self.assertGreater(near_share(page, simulator), AGREE, 'page ink turtlesim has not')
        red = {(x, y) for x, y in page if 45 < x < 180 and abs(y - (499 - 45)) <= 1}
        self.assertGreater(len(red), 120, 'the 1-px line at 2.5 m/s, whole')

    def test_2c_rebuilt_from_poses_as_for_the_real_turtlesim(self):
        """A viewer that does not take the simulator's ink (~ink false) reads
        the pens from poses and the colour under the turtle, as it must with
        the real turtlesim: a 3-px line at 2.5 m/s, a 2-px one at 1 m/s, a
        pen-up teleport onto ink and away, and a pen-down one, on its
        /canvas.png as on turtlesim's own canvas."""
        port = free_port()
        posed = NodeProcess('turtle_letters', 'view.py', f'_port:={port}', '_ink:=false',
                            '__name:=posed_view')
        try:
            wait_until(lambda: self.serving(posed, port) and connections(
                '/posed_view', '/turtle1/color_sensor', 'i'), 30,
                'the viewer from poses serving, and on the colour sensor', posed.output)
            rospy.ServiceProxy('/clear', Empty)()
            pen, teleport = draw_lines((((1.0, 6.0), (255, 0, 0), 3, 2.5),
                                        ((1.0, 7.0), (0, 160, 0), 2, 1.0)), rest=0.3)
            pen(0, 0, 0, 3, 1)
            teleport(2.0, 6.0, 0.0)         # onto the red line, pen up
            rospy.sleep(0.3)
            teleport(9.0, 9.0, 0.0)         # and away
            rospy.sleep(0.3)
            pen(255, 255, 255, 3, 0)
            teleport(9.0, 4.0, 0.0)         # pen down: a white line
            rospy.sleep(1.0)
            saved = rospy.ServiceProxy('/turtlesim/save_canvas', Trigger)()
            self.assertTrue(saved.success, saved.message)
            turtle = (9.0 * 45, 499 - 4.0 * 45)
            simulator = ink(QImage(saved.message), turtle)

            def rebuilt():
                png = QImage()
                png.loadFromData(urllib.request.urlopen(
                    f'http://127.0.0.1:{port}/canvas.png', timeout=5).read(), 'PNG')
                return ink(png, turtle)
            wait_until(lambda: near_share(simulator, rebuilt()) > AGREE, 10,
                       "turtlesim's ink rebuilt from poses", lambda: near_share(simulator,
                                                                                rebuilt()))
            self.assertGreater(near_share(rebuilt(), simulator), AGREE,
                               'ink rebuilt from poses that turtlesim has not')
        finally:
            posed.stop()

    def test_3_each_turtle_by_name_and_each_drawing_in_the_table(self):
        self.assertEqual(self.names(), ['turtle1'])
        rows = [[cell.text for cell in row.find_elements('css selector', 'td')]
                for row in self.driver.find_elements('css selector', '#drawings tbody tr')]
        self.assertTrue(self.result.drawn, self.result.message)
        self.assertEqual(len(rows), 1)
        self.assertEqual(rows[0][:2], ['/', 'L'])
        self.assertEqual(rows[0][4], self.result.message)
        done = self.driver.execute_script(
            "return document.querySelector('#drawings progress').value")
        self.assertEqual(done, 1)
        self.wait_for_page(lambda: self.driver.find_element('id', 'scoreboard').text == TABLE,
                           "the scoreboard's table on the page")

    def test_4_the_canvas_as_an_image_topic_and_a_png(self):
        message = rospy.wait_for_message('/canvas/image', Image, timeout=10)
        self.assertEqual((message.width, message.height, message.encoding, message.step),
                         (500, 500, 'rgb8', 1500))
        image = QImage(message.data, 500, 500, 1500, QImage.Format_RGB888)
        png = QImage()
        png.loadFromData(urllib.request.urlopen(self.url + 'canvas.png', timeout=5).read(), 'PNG')
        self.assertEqual(ink(image), ink(png))
        self.assertGreater(near_share(ink(image), ink(self.page_canvas())), AGREE)
        folder = tempfile.mkdtemp(prefix='turtle_letters_image_saver_')
        saver = NodeProcess('image_view', 'image_saver', 'image:=/canvas/image',
                            f'_filename_format:={folder}/frame%04i.png')
        try:
            wait_until(lambda: len(os.listdir(folder)) >= 2, 20, "image_view's image_saver to "
                       'save the canvas', saver.output)
        finally:
            saver.stop()
        saved = QImage(os.path.join(folder, sorted(os.listdir(folder))[-1]))
        self.assertGreater(near_share(ink(saved), ink(png)), AGREE)
        self.assertGreater(near_share(ink(png), ink(saved)), AGREE)
        shutil.rmtree(folder, ignore_errors=True)

    def test_5_the_page_reconnects_by_itself_after_the_viewer_restarts(self):
        self.driver.execute_script('window.sameLoad = true')
        type(self).viewer.stop(signal.SIGINT)
        self.wait_for_page(lambda: self.status().startswith('reconnecting'), 'reconnecting')
        type(self).viewer = self.start_viewer()
        self.wait_for_page(lambda: self.status() == 'live', 'live again')
        self.assertTrue(self.driver.execute_script('return window.sameLoad === true'),
                        'the page was reloaded')
        rospy.ServiceProxy('/turtle1/teleport_absolute', TeleportAbsolute)(2.0, 3.0, 0.0)
        self.wait_for_page(lambda: self.driver.execute_script('return turtles.turtle1')[:2]
                           == [90.0, 364.0], 'turtle1 where it was put, on the page')
        unexpected = [e for e in self.errors() if 'WebSocket connection' not in e]
        self.assertEqual(unexpected, [])

    def test_6_a_page_past_the_most_is_told_why_and_backs_off(self):
        port = free_port()
        crowded = NodeProcess('turtle_letters', 'view.py', f'_port:={port}', '_max_pages:=1',
                              '__name:=crowded_view')
        first = self.driver.current_window_handle
        try:
            wait_until(lambda: self.serving(crowded, port), 30,
                       'the second viewer serving', crowded.output)
            self.driver.switch_to.new_window('tab')
            self.driver.get(f'http://127.0.0.1:{port}/')
            self.wait_for_page(lambda: self.status() == 'live', 'the first page live')
            taken = self.driver.current_window_handle
            self.driver.switch_to.new_window('tab')
            self.driver.get(f'http://127.0.0.1:{port}/')
            said = []
            wait_until(lambda: said.append(self.status()) or 'in 4 s' in said[-1], 30,
                       'the refused page backing off to 4 s', lambda: sorted(set(said)))
            refusals = [s for s in said if s.startswith('refused')]
            self.assertTrue(refusals, sorted(set(said)))
            self.assertTrue(refusals[0].startswith('refused (the viewer shows 1 pages already): '
                                                   'trying again in'), refusals[0])
            self.assertNotIn('live', said, sorted(set(said)))
            refused = self.driver.current_window_handle
            self.driver.switch_to.window(taken)
            self.driver.close()                         # a seat frees
            self.driver.switch_to.window(refused)
            # retried 4 s on, then 8 s more if the viewer had not yet seen the seat free
            self.wait_for_page(lambda: self.status() == 'live', 'the refused page in, once a '
                               'place was free', timeout=30)
            self.driver.close()
        finally:
            self.driver.switch_to.window(first)
            crowded.stop()


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'viewer', ViewerInABrowser)
