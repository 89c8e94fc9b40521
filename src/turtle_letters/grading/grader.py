"""The grader node (grade.py): watches one turtle draw and scores the drawing
against the ideal letter (grading.py), whoever's controller drew it.

Each drawing's report is logged in a few lines with its verdict, published
as JSON on `~report` (std_msgs/String, latched), and saved in `~out` as
TURTLE-LETTER-N.json and .png (the ideal letter and the path, each vertex
enlarged). The controller's CPU share and cmd_vel rate are measured when its
node, the publisher of TURTLE/cmd_vel, runs on this machine."""
import json
import os
import socket
import sys
import time
import urllib.parse

import rosgraph
import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String
from turtlesim.msg import Pose

from ..classroom.liveness import answers
from ..letters.geometry import PlannedPose
from ..settings import (Parameter, ParameterError, Settings, positive, read_parameter,
                        writable_folder)
from ..isolation.files import report_stem
from .procstat import cpu_seconds
from .scoring import SETTLE, DrawingWatch, Tolerances, ideal_letter, score

NEVER_MOVED = 60.0      # s without a move before the grader says so, once

# The grader's and the scoreboard's own parameters (the grader also reads
# the controller's, settings.PARAMETERS, to know what is drawn).
GRADING = {p.name: p for p in (
    Parameter('tolerance', 'float', '0.02', 'm', 'how far a vertex may be from the ideal one',
              positive),
    Parameter('settle', 'float', str(SETTLE), 's', 'standing still this long ends a drawing',
              positive),
    Parameter('timeout', 'float', '300.0', 's', 'a drawing not ended by then fails', positive),
    Parameter('out', 'str', '~/.ros/turtle_letters_grades', '',
              "where each drawing's report and picture are saved", writable_folder),
)}


def read_grading(name):
    """One of GRADING, read and checked; raises ParameterError."""
    return read_parameter(name, rospy.get_param, table=GRADING)


class ControllerUse:
    """The CPU share of the node that publishes a turtle's cmd_vel, while it draws."""

    def __init__(self, topic):
        self.node, self.pid, self.note = None, None, ''
        master = rosgraph.Master(rospy.get_name())
        try:
            state = master.getSystemState()
            nodes = [n for t, ns in state[0] if t == topic for n in ns if n != rospy.get_name()]
            uri = master.lookupNode(nodes[0]) if len(nodes) == 1 else None
        except (OSError, rosgraph.MasterException) as e:
            self.note = f'the master did not say who publishes {topic}: {e}'
            return
        if uri is None:
            self.note = f'{len(nodes)} nodes publish {topic}: {", ".join(nodes) or "none"}'
            return
        self.node = nodes[0]
        host = urllib.parse.urlparse(uri).hostname
        if not _here(host):
            self.note = f'{self.node} runs on {host}, not on this machine'
            return
        self.pid = answers(uri)
        if self.pid is None:
            self.note = f'{self.node} did not answer at {uri}'
            return
        self.started, self.cpu0 = time.monotonic(), cpu_seconds(self.pid)

    def share(self):
        """% of a core since the drawing started, or None."""
        if self.pid is None:
            return None
        try:
            used = cpu_seconds(self.pid) - self.cpu0
        except OSError:
            self.note = f'{self.node} (pid {self.pid}) has exited'
            return None
        return 100 * used / max(time.monotonic() - self.started, 1e-6)


def _here(host):
    """Whether `host` is this machine (so its processes' CPU can be read)."""
    try:
        address = socket.gethostbyname(host)
        return address.startswith('127.') or address in socket.gethostbyname_ex(
            socket.gethostname())[2]
    except OSError:
        return False


class TurtleGrader:
    """Grades each drawing of one turtle against `ideal(start)`: (what it
    should have drawn, its strokes), or (why it cannot say, None), from the
    turtle's pose before it moved. `tell(report, strokes, path)` gets every report."""

    def __init__(self, turtle, ideal, tolerances, tell, settle=SETTLE, timeout=300.0):
        self.ideal, self.tolerances, self.tell = ideal, tolerances, tell
        self.turtle = rospy.resolve_name(turtle)
        self.watch, self.timeout = DrawingWatch(settle), timeout
        self.commands, self.use, self.count = 0, None, 0
        self.heard_since = time.monotonic()
        rospy.Subscriber(f'{self.turtle}/pose', Pose, self._on_pose, queue_size=200)
        rospy.Subscriber(f'{self.turtle}/cmd_vel', Twist, self._on_cmd_vel, queue_size=200)

    def _on_cmd_vel(self, _):
        self.commands += 1

    def _on_pose(self, pose):
        now = time.monotonic()
        event = self.watch.feed(now, pose)
        if event == 'started':
            self.commands, self.use = 0, ControllerUse(f'{self.turtle}/cmd_vel')
        elif event == 'ended':
            self._grade('')
        elif self.watch.started_at is not None and now - self.watch.started_at > self.timeout:
            self._grade(f'the drawing did not end within {self.timeout:g} s')
        elif self.watch.started_at is None and now - self.heard_since > NEVER_MOVED:
            self.heard_since = float('inf')
            rospy.logwarn('%s has not moved in %g s: is its controller running, and was it '
                          'triggered?', self.turtle, NEVER_MOVED)

    def _grade(self, unfinished):
        watch, stood = self.watch, self.watch.stood
        start = PlannedPose(stood.x, stood.y, stood.theta) if stood else \
            PlannedPose(*watch.path[0], 0.0)
        label, strokes = self.ideal(start)
        path, seconds = watch.path, watch.seconds
        watch.reset()
        self.heard_since = time.monotonic()
        if strokes is None:
            rospy.logwarn('%s drew something, not graded: %s', self.turtle, label)
            return
        graded = score(path, strokes, path[0], self.tolerances)
        self.count += 1
        report = dict(turtle=self.turtle, letter=label, number=self.count,
                      verdict='pass' if graded.passed and not unfinished else 'fail',
                      reason=unfinished or graded.reason,
                      tolerance_mm=self.tolerances.vertex * 1000,
                      worst_vertex_mm=graded.worst_vertex * 1000,
                      vertex_mm=[e * 1000 for e in graded.vertex_errors],
                      off_mm=graded.off * 1000, ink_off_m=graded.ink_off,
                      missing_strokes=[i + 1 for i in graded.missing],
                      end_mm=graded.end_error * 1000, drawing_s=seconds,
                      commands_per_s=self.commands / max(seconds, 1e-6),
                      controller=self.use.node, cpu_pct=self.use.share(), cpu_note=self.use.note)
        self.tell(report, strokes, path)


def report_lines(report):
    """The report in three lines, the verdict first."""
    r = report
    cpu = (f"{r['controller']}: {r['cpu_pct']:.1f}% of a core" if r['cpu_pct'] is not None
           else f"CPU not measured: {r['cpu_note']}")
    missing = ', '.join(map(str, r['missing_strokes'])) or 'none'
    return [f"{r['turtle']} drew {r['letter']!r} (drawing {r['number']}): "
            f"{r['verdict'].upper()}: {r['reason']}",
            f"  worst vertex {r['worst_vertex_mm']:.2f} mm, off the letter {r['off_mm']:.2f} mm, "
            f"ink off {r['ink_off_m']:.2f} m, missing strokes {missing}, ended "
            f"{r['end_mm']:.2f} mm from a stroke's end",
            f"  {r['drawing_s']:.2f} s, {r['commands_per_s']:.0f} cmd_vel/s; {cpu}"]


class Saver:
    """Each report as JSON and as a picture in `folder`."""

    def __init__(self, folder):
        self.folder = folder
        os.makedirs(folder, exist_ok=True)

    def __call__(self, report, strokes, path):
        from .picture import draw  # Qt: only once there is something to draw
        stem = os.path.join(self.folder, report_stem(report['turtle'], report['letter'],
                                                     report['number']))
        with open(stem + '.json', 'w') as f:
            json.dump(dict(report, path=path, ideal=strokes), f, indent=1)
        half_box = min(0.1, max(0.01, 1.5 * report['worst_vertex_mm'] / 1000))
        draw(stem + '.png', strokes, {report['turtle']: [path]},
             {report['turtle']: (178, 24, 43)}, half_box)
        return stem


def main():
    rospy.init_node('grader')
    try:
        settings = Settings(rospy.get_param)
        tolerances = Tolerances(read_grading('tolerance'))
        settle, timeout = read_grading('settle'), read_grading('timeout')
        folder = read_grading('out')
    except ParameterError as e:
        rospy.logfatal('%s: %s', rospy.get_name(), e)
        sys.exit(2)
    save = Saver(folder)
    published = rospy.Publisher('~report', String, queue_size=10, latch=True)

    def tell(report, strokes, path):
        for line in report_lines(report):
            (rospy.loginfo if report['verdict'] == 'pass' else rospy.logwarn)('%s', line)
        stem = save(report, strokes, path)
        rospy.loginfo('  saved %s.json and .png', stem)
        published.publish(String(json.dumps(report)))
    def ideal(start):
        return settings.letter, ideal_letter(settings.letter, settings.size, settings.font, start)
    grader = TurtleGrader(settings.turtle, ideal, tolerances, tell,
                          settle=settle, timeout=timeout)
    rospy.loginfo('Grading %s: %r at %g m in font %s, vertices within %.0f mm; waiting for it '
                  'to move', grader.turtle, settings.letter, settings.size, settings.font.name,
                  tolerances.vertex * 1000)
    rospy.spin()
