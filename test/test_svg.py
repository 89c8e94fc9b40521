#!/usr/bin/python3
"""An SVG file's line art, sent on the controller's ~svg topic and drawn in
smooth mode: every vertex of the flattened strokes reached, the path on the
strokes and the pen-up travel (a stray only where a late command ran on,
as in test_words), and the picture in the file's stroke colours."""
import math
import os
import time
import unittest

import rospy
import rostest
from PyQt5.QtGui import QImage
from std_msgs.msg import String
from std_srvs.srv import Trigger
from turtlesim.msg import Pose as PoseMsg

from support.accuracy import strays, touches_a_wall, vertex_errors
from support.nodes import LogWatch, PoseRecorder, wait_until
from support.pictures import pixel
from turtle_letters.letters import svgart
from turtle_letters.letters.plan import plan_picture
from turtle_letters.letters.geometry import PlannedPose
from turtle_letters.settings import Settings
from turtle_letters.letters.sheet import Sheet

TOLERANCE = 0.001           # m: the target, for every vertex and every pose
CONTROLLER = '/turtlebot_controller'


class SvgLineArt(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('svg_test')
        path = rospy.get_param('~svg')
        settings = Settings(lambda name, default:
                            rospy.get_param(f'{CONTROLLER}/{name[1:]}', default))
        logs = LogWatch()
        first = rospy.wait_for_message('/turtle1/pose', PoseMsg, timeout=30)
        poses = PoseRecorder()
        poses.wait_connected()
        pub = rospy.Publisher(CONTROLLER + '/svg', String, queue_size=1, latch=True)
        pub.publish(String(path))

        start = PlannedPose(first.x, first.y, first.theta)
        picture = svgart.picture(svgart.read(path, settings.svg_dirs), settings.size)
        place, _ = Sheet(settings.size, settings.font).reserve_picture(
            picture.width / settings.size, 'flower', start)
        cls.plan = plan_picture(picture, place, start, settings)
        cls.travel, here = [], cls.plan.start
        for stroke in cls.plan.strokes:
            cls.travel.append([here, stroke[0]])
            here = stroke[-1]
        wait_until(lambda: logs.count('Done drawing', CONTROLLER)
                   or logs.count('Refused', CONTROLLER), 250, "the controller's Done line")
        cls.refused = logs.count('Refused', CONTROLLER)
        poses.wait_until_still(0, 10, still_for=0.5)
        cls.poses_drawn = poses.since(0)
        cls.path = [(p.x, p.y) for p in cls.poses_drawn]
        cls.logs, cls.poses, cls.pub = logs, poses, pub

    def test_the_file_is_drawn(self):
        self.assertEqual(self.refused, 0)

    def test_a_file_that_is_no_svg_or_is_not_ours_to_read_is_refused_in_one_line(self):
        t0 = time.time()
        picture = os.path.join(os.path.dirname(rospy.get_param('~svg')), 'lab-n.png')
        for path, count in ((picture, 1), ('/etc/hostname', 2)):     # a PNG in doc/; not ours
            self.pub.publish(String(path))
            wait_until(lambda: self.logs.count('Refused', CONTROLLER) == count, 20, 'the refusal')
        rospy.sleep(1.0)
        refusals = [m.msg for m in self.logs.messages if 'Refused' in m.msg]
        self.assertEqual(len(refusals), 2)
        self.assertIn('not an SVG file (its root: not XML', refusals[0])
        self.assertIn("'/etc/hostname': only files under the folders of ~svg_dirs are read",
                      refusals[1])
        self.assertEqual(self.poses.moving_since(t0), [])

    def test_every_vertex_is_reached(self):
        vertices = [v for stroke in self.plan.strokes for v in stroke]
        errors = vertex_errors(self.path, vertices)
        missed = [(v, round(e * 1000, 2)) for v, e in zip(vertices, errors) if e >= TOLERANCE]
        self.assertEqual(missed, [], 'vertices missed (m) by mm')

    def test_the_path_keeps_to_the_strokes_and_travel_moves(self):
        found = strays(self.poses_drawn, self.plan.strokes + self.travel, TOLERANCE)
        own = [(round(p.x, 3), round(p.y, 3), round(worst * 1000, 2))
               for p, worst, late in found if not late]
        self.assertEqual(own, [], 'strays (m, worst mm off) begun by a new command')
        vertices = sum(len(stroke) for stroke in self.plan.strokes)
        self.assertLess(len(found), vertices / 4, f'{len(found)} strays, {vertices} vertices')
        self.assertFalse(touches_a_wall(self.path))

    def test_the_picture_has_the_files_stroke_colours(self):
        saved = rospy.ServiceProxy('/turtlesim/save_canvas', Trigger)()
        self.assertTrue(saved.success, saved.message)
        image = QImage(saved.message)
        turtle = self.path[-1]          # its icon covers the ink under it
        for stroke, colour in zip(self.plan.strokes, self.plan.colours):
            a, b = max(zip(stroke, stroke[1:]), key=lambda ab: math.dist(*ab))   # its longest edge
            mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
            if math.dist(mid, turtle) > 0.5:
                with self.subTest(stroke=stroke[0]):
                    self.assertEqual(pixel(image, *mid), colour)


if __name__ == '__main__':
    rostest.rosrun('turtle_letters', 'svg', SvgLineArt)
