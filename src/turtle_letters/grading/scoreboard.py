"""The room's scoreboard (classroom.launch grade:=true): grades every
student's turtle on the shared canvas as it draws, each against the text its
controller drew at its places (recorded in its part's claim, claims.py), and
keeps a table: name, letter, verdict, worst vertex, time. The table is
logged and published on `scoreboard` (std_msgs/String, latched) whenever a
grade changes, and saved in `~out` as scoreboard.json and scoreboard.png
(the canvas: every letter's ideal strokes and path, its score beside it)."""
import json
import os
import threading

import rospy
from std_msgs.msg import String

from ..classroom.claims import PARTS, stored_parts
from ..settings import ParameterError, Settings
from .grader import Saver, TurtleGrader, read_grading
from .scoring import Tolerances, ideal_text

LOOK_PERIOD = 2.0           # s between looks for new students' turtles


class Scoreboard:
    def __init__(self, tolerances, folder):
        self.tolerances, self.folder = tolerances, folder
        self.save = Saver(folder)           # each drawing's report and picture
        self.graders, self.rows, self.drawings = {}, {}, {}
        self._lock = threading.Lock()
        self.table = rospy.Publisher('scoreboard', String, queue_size=10, latch=True)
        self._look()
        rospy.Timer(rospy.Duration(LOOK_PERIOD), lambda _: self._look())

    def _look(self):
        """A grader for each turtle that has a part and none yet."""
        for name in stored_parts(rospy.resolve_name(PARTS)):
            if name not in self.graders:
                self.graders[name] = TurtleGrader(f'/{name}', self._ideal_of(name),
                                                  self.tolerances, self._tell)
                rospy.loginfo('Scoreboard: grading /%s', name)

    @staticmethod
    def _ideal_of(name):
        def ideal(start):
            claim = stored_parts(rospy.resolve_name(PARTS)).get(name, {})
            drawing = claim.get('drawing') or {}
            if not drawing.get('text'):
                return 'its controller recorded no text in its part', None
            try:
                params = rospy.get_param(claim['node'], {})
                # ~svg names a file on the student's machine, not this one,
                # and a picture is not graded: a letter's settings suffice
                params.pop('svg', None)
                settings = Settings(lambda key, default: params.get(key[1:], default))
            except (KeyError, ParameterError) as e:
                return f"{claim.get('node')}'s parameters: {e}", None
            text = drawing['text']
            if settings.font.undrawable(text):
                return f'font {settings.font.name} has no glyph for {text!r}', None
            return text, ideal_text(text, drawing['places'], settings.size, settings.font, start)
        return ideal

    def _tell(self, report, strokes, path):
        """A drawing graded (on a turtle's own thread): the table and the
        files anew, one turtle at a time."""
        name = report['turtle'].strip('/')
        with self._lock:
            self.save(report, strokes, path)
            self.rows[name] = report
            self.drawings[name] = (strokes, path)
            lines = table_lines(self.rows)
            rospy.loginfo('Scoreboard:\n%s', '\n'.join(lines))
            self.table.publish(String('\n'.join(lines)))
            self._write()

    def _write(self):
        from .picture import draw_canvas  # Qt: only once there is something to draw
        json_path = os.path.join(self.folder, 'scoreboard.json')
        with open(json_path + '.new', 'w') as f:
            json.dump(self.rows, f, indent=1)
        os.replace(json_path + '.new', json_path)       # a reader never sees half of it
        draw_canvas(os.path.join(self.folder, 'scoreboard.png'),
                    [(strokes, path, score_label(name, self.rows[name]),
                      self.rows[name]['verdict'] == 'pass')
                     for name, (strokes, path) in sorted(self.drawings.items())],
                    self.tolerances.vertex)


def table_lines(rows):
    lines = [f"{'name':16} {'letter':8} {'verdict':7} {'worst mm':>9} {'time s':>7}"]
    for name, r in sorted(rows.items()):
        lines.append(f"{name:16} {r['letter']:8} {r['verdict'].upper():7} "
                     f"{r['worst_vertex_mm']:9.2f} {r['drawing_s']:7.1f}")
    return lines


def score_label(name, report):
    return (f"{name} {report['letter']}\n{report['verdict'].upper()} "
            f"{report['worst_vertex_mm']:.1f} mm {report['drawing_s']:.0f} s")


def main():
    rospy.init_node('scoreboard')
    try:
        tolerances = Tolerances(read_grading('tolerance'))
        folder = read_grading('out')
    except ParameterError as e:
        rospy.logfatal('%s: %s', rospy.get_name(), e)
        raise SystemExit(2)
    Scoreboard(tolerances, folder)
    rospy.loginfo('Scoreboard: grading every student turtle with a part of the canvas, vertices '
                  'within %.0f mm; the table goes to %s and %s/scoreboard.png',
                  tolerances.vertex * 1000, rospy.resolve_name('scoreboard'), folder)
    rospy.spin()
