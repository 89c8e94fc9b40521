"""`make bench`'s viewer group: view.py beside the bench's turtlesim, with 1
and with 30 turtles driving circles, pen down.

- Latency, measured in the browser: headless Chromium opens the page, and a
  WebSocket of the browser's own on /room notes when each update showing
  turtle1 arrives (the browser's clock); the bench notes when each of
  turtle1's poses arrives at it (the same machine's clock). A pose's latency
  is from the bench having it to the browser having it.
- The viewer's CPU, with 30 turtles and 10 pages open (the browser's, and
  nine of the bench's own WebSocket clients, which read every update).
- Bytes a second each page is sent, while 30 turtles draw.
- The floor under the viewer's CPU: a node that only subscribes to the
  same pose and color_sensor topics, unread (rospy.AnyMsg), its callbacks
  empty: what rospy alone costs for that many messages.
"""
import asyncio
import math
import socket
import statistics
import tempfile
import threading
import time
import urllib.request

import rospy
import tornado.websocket
from geometry_msgs.msg import Twist
from std_srvs.srv import Empty
from turtlesim.msg import Pose
from turtlesim.srv import SetPen, Spawn

from support.browser import browser
from turtle_letters.grading.procstat import cpu_seconds, rss_mb
from turtle_letters.viewer.trails import to_pixels

LATENCY_TARGET_MS, CPU_TARGET_PCT, BYTES_TARGET = 100.0, 10.0, 100_000
WINDOW = 20.0           # s each figure is measured over
PAGES = 10
SOAK_SAMPLE = 60.0     # s between looks at the viewer's memory in a soak
LISTEN = """
window.arrivals = [];
const ws = new WebSocket('ws://' + location.host + '/room');
ws.onmessage = (e) => {
  const m = JSON.parse(e.data);
  const t = m.turtles && m.turtles.turtle1;
  if (t) window.arrivals.push([performance.timeOrigin + performance.now(), t[0], t[1]]);
};
"""


def _free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def _spawn_turtles(count):
    spawn = rospy.ServiceProxy('/spawn', Spawn)
    for i in range(2, count + 1):
        spawn(1.0 + (i % 6) * 1.8, 1.0 + (i // 6) * 1.8, 0.0, f'turtle{i}')


def _park(name='parked'):
    """A turtle that travels 1 m with its pen up, then stands on the
    background for the rest of the soak (the pose path read one reading a
    tick of it, for good, until issue 44)."""
    rospy.ServiceProxy('/spawn', Spawn)(9.5, 0.5, math.pi / 2, name)
    rospy.ServiceProxy(f'/{name}/set_pen', SetPen)(255, 255, 255, 3, 1)
    publisher = rospy.Publisher(f'/{name}/cmd_vel', Twist, queue_size=1)
    twist = Twist()
    twist.linear.x = 1.0
    for _ in range(10):         # 1 s at 1 m/s, a command every 0.1 s
        publisher.publish(twist)
        time.sleep(0.1)
    publisher.publish(Twist())


def _drive(count, stop):
    """Every turtle in circles of 0.5 m, pen down, until `stop` is set."""
    publishers = [rospy.Publisher(f'/turtle{i}/cmd_vel', Twist, queue_size=1)
                  for i in range(1, count + 1)]
    twist = Twist()
    twist.linear.x, twist.angular.z = 1.0, 2.0
    while not stop.is_set():
        for publisher in publishers:
            publisher.publish(twist)
        time.sleep(0.1)


class PoseTimes:
    """When each of turtle1's poses came to the bench, by where it shows on
    the page (a circle comes back to a place: each time it came is kept)."""

    def __init__(self):
        self.times = {}
        self.subscriber = rospy.Subscriber('/turtle1/pose', Pose, self._on_pose, queue_size=100)

    def _on_pose(self, pose):
        x, y = to_pixels(pose.x, pose.y)
        self.times.setdefault((round(x, 1), round(y, 1)), []).append(time.time() * 1000)

    def latency(self, at, x, y):
        """ms from the latest time the bench had a pose at (x, y) before `at`, or None."""
        before = [t for t in self.times.get((x, y), []) if t <= at]
        return at - before[-1] if before else None


FLOOR = """
import rospy
rospy.init_node('bench_rospy_floor')
for i in range(1, {turtles} + 1):
    for topic in ('pose', 'color_sensor'):
        rospy.Subscriber(f'/turtle{{i}}/{{topic}}', rospy.AnyMsg, lambda m: None, queue_size=100)
rospy.spin()
"""


def _cpu_pct(pid, seconds):
    used, started = cpu_seconds(pid), time.monotonic()
    time.sleep(seconds)
    return 100 * (cpu_seconds(pid) - used) / (time.monotonic() - started)


def _rospy_floor(processes, turtles):
    floor = processes.start('rospy_floor', '/usr/bin/python3', '-c', FLOOR.format(turtles=turtles))
    try:
        time.sleep(3.0)
        return _cpu_pct(floor.pid, WINDOW / 2)
    finally:
        processes.stop(floor)


def _latencies(driver, poses):
    arrivals = driver.execute_script('return window.arrivals')
    return sorted(filter(lambda v: v is not None, (poses.latency(*a) for a in arrivals)))


def _reader(url, counts, stop):
    """A page of the bench's own: reads every update, counting its bytes."""
    async def read():
        connection = await tornado.websocket.websocket_connect(url)
        while not stop.is_set():
            message = await connection.read_message()
            if message is None:
                return
            counts.append((time.monotonic(), len(message)))
    asyncio.run(read())


def _wait_serving(url):
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        try:
            urllib.request.urlopen(url, timeout=1)
            return
        except OSError:
            time.sleep(0.2)


def viewer_run(processes, turtles, pages=PAGES):
    """Latency with `turtles` turtles; with `pages` pages, the viewer's CPU,
    its memory and the bytes per page."""
    rospy.ServiceProxy('/reset', Empty)()
    _spawn_turtles(turtles)
    port = _free_port()
    viewer = processes.start('view', 'rosrun', 'turtle_letters', 'view.py', f'_port:={port}',
                             f'_max_pages:={max(pages, 120)}')
    url = f'http://127.0.0.1:{port}/'
    _wait_serving(url)
    stop, profile = threading.Event(), tempfile.mkdtemp(prefix='bench_chromium_')
    driving = threading.Thread(target=_drive, args=(turtles, stop), daemon=True)
    driving.start()
    driver = browser(profile)
    readers, counts = [], [[] for _ in range(pages - 1)]
    try:
        driver.get(url)
        poses = PoseTimes()
        driver.execute_script(LISTEN)
        for page_counts in counts:
            readers.append(threading.Thread(target=_reader, args=(
                url.replace('http', 'ws') + 'room', page_counts, stop), daemon=True))
            readers[-1].start()
        time.sleep(3.0)         # every turtle's circle under way, every page reading
        started = time.monotonic()
        cpu_pct = _cpu_pct(viewer.pid, WINDOW)
        memory_mb = rss_mb(viewer.pid)
        latencies = _latencies(driver, poses)
        bytes_per_s = [sum(n for t, n in c if t >= started) / WINDOW for c in counts]
        poses.subscriber.unregister()
        processes.stop(viewer)      # the turtles still drive, for the floor
        floor_pct = _rospy_floor(processes, turtles)
    finally:
        stop.set()
        driver.quit()
        processes.stop(viewer)
    return dict(turtles=turtles, pages=pages, cpu_pct=cpu_pct, rospy_floor_pct=floor_pct,
                memory_mb=memory_mb,
                latency_median_ms=statistics.median(latencies) if latencies else math.nan,
                latency_p95_ms=latencies[int(0.95 * (len(latencies) - 1))] if latencies else math.nan,
                latency_samples=len(latencies),
                bytes_per_s_median=statistics.median(bytes_per_s),
                bytes_per_s_worst=max(bytes_per_s))


SOAK_VIEWERS = {'ink': [], 'poses': ['_ink:=false']}   # from the simulator's ink; as with turtlesim


def soak_run(processes, turtles, seconds, pages=PAGES):
    """The memory of two viewers side by side while `turtles` turtles draw
    and one stands parked for `seconds`: one drawing the simulator's ink, one rebuilding from
    poses and color sensors as it does with the real turtlesim; each with
    `pages` pages of the bench's own reading every update. Their resident
    size each SOAK_SAMPLE s, and their CPU over the whole."""
    rospy.ServiceProxy('/reset', Empty)()
    _spawn_turtles(turtles)
    _park()
    viewers, stop = {}, threading.Event()
    for name, extra in SOAK_VIEWERS.items():
        port = _free_port()
        viewers[name] = processes.start(f'view_soak_{name}', 'rosrun', 'turtle_letters', 'view.py',
                                        f'__name:=view_{name}', f'_port:={port}', *extra)
        url = f'http://127.0.0.1:{port}/'
        _wait_serving(url)
        for _ in range(pages):
            threading.Thread(target=_reader, args=(url.replace('http', 'ws') + 'room', [], stop),
                             daemon=True).start()
    threading.Thread(target=_drive, args=(turtles, stop), daemon=True).start()
    samples = {name: [] for name in viewers}
    try:
        used = {name: cpu_seconds(v.pid) for name, v in viewers.items()}
        started = time.monotonic()
        while True:
            elapsed = time.monotonic() - started
            for name, viewer in viewers.items():
                samples[name].append((elapsed, rss_mb(viewer.pid)))
            if elapsed >= seconds:
                break
            time.sleep(min(SOAK_SAMPLE, seconds - elapsed))
        cpu_pct = {name: 100 * (cpu_seconds(v.pid) - used[name]) / (time.monotonic() - started)
                   for name, v in viewers.items()}
    finally:
        stop.set()
        for viewer in viewers.values():
            processes.stop(viewer)
    return dict(turtles=turtles, pages=pages, seconds=seconds, cpu_pct=cpu_pct, rss_mb=samples)


SOAK_WORDS = {'ink': "from the simulator's ink", 'poses': 'from poses, as with turtlesim'}


def soak_lines(results):
    soak = results.get('viewer_soak')
    if not soak:
        return []
    lines = []
    for name, samples in soak['rss_mb'].items():
        sizes = [mb for _, mb in samples]
        tenth = max(1, len(sizes) // 10)
        lines.append(
            f"viewer {SOAK_WORDS[name]}, {soak['turtles']} turtles drawing and one parked for "
            f"{soak['seconds'] / 60:g} min, {soak['pages']} pages: resident {sizes[0]:.0f} MB "
            f"at the start, {max(sizes[:tenth]):.0f} MB at most in the first tenth, "
            f"{max(sizes):.0f} MB at most, {sizes[-1]:.0f} MB at the end; "
            f"CPU {soak['cpu_pct'][name]:.1f}%")
    return lines


def viewer_lines(results):
    runs = results.get('viewer')
    if not runs:
        return soak_lines(results)
    lines = ['']
    for r in runs:
        late = r['latency_p95_ms'] > LATENCY_TARGET_MS
        lines.append(
            f"viewer, {r['turtles']} turtles drawing, {r['pages']} pages: pose to page median "
            f"{r['latency_median_ms']:.0f} ms, 95th percentile {r['latency_p95_ms']:.0f}"
            f"{'!' if late else ''} ms ({r['latency_samples']} poses); viewer CPU "
            f"{r['cpu_pct']:.1f}{'!' if r['cpu_pct'] > CPU_TARGET_PCT and r['turtles'] >= 30 else ''}"
            f"% (rospy alone, subscribed to the same topics: {r['rospy_floor_pct']:.1f}%), "
            f"{r.get('memory_mb', math.nan):.0f} MB resident; "
            f"per page {r['bytes_per_s_median'] / 1000:.1f} kB/s (worst "
            f"{r['bytes_per_s_worst'] / 1000:.1f}"
            f"{'!' if r['bytes_per_s_worst'] > BYTES_TARGET else ''})")
    lines.append(f'Viewer targets: pose to page <= {LATENCY_TARGET_MS:g} ms (95th percentile); '
                 f'<= {CPU_TARGET_PCT:g}% of a core for 30 turtles and {PAGES} pages; '
                 f'memory bounded however long they draw; '
                 f'<= {BYTES_TARGET / 1000:g} kB/s per page.')
    return lines + soak_lines(results)
