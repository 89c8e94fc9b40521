"""What the watcher saw of a submission's run, made sense of. No ROS here.

Events are the watcher's JSON lines as dicts: 'pose', 'cmd_vel' (a count
of commands), 'chatter', 'chatter_count', 'canvas' (turtlesim cleared or
reset), 'published' and 'graph', each with `t` (s, the grader's monotonic
clock).
Only poses from the simulator count: poses on the turtle's topic from any
other node are made up, and a step no command could make is a teleport.
A "P" counts as the trigger only from a node that does not drive the
turtle: a controller that publishes its own draws without one.
"""
import math
from typing import List, NamedTuple, Optional

from ..letters.layout import SIM_TICK as TICK

WATCHER = '/grade_watch'    # the grader's watcher's node name (watch.py)
STEP_SLACK = 0.01       # m a step may exceed what the commanded speed allows
SLOW_TICKS = 1.5        # ticks' worth of travel allowed between two poses, beyond those that came
JUMP = 0.001            # m between two poses that is a move, speed or no speed
COUNTED = 0.1           # s: the watcher counts commands and /chatter over this period
FLOOD_WINDOW = 1.0      # s over which /chatter's rate is judged


class Drawing(NamedTuple):
    path: List[tuple]           # (x, y) of the simulator's poses, from where the turtle stood
    started: Optional[float]    # t of the first move after the trigger
    ended: Optional[float]      # t the turtle stopped for good (None: still moving)
    commands: int               # cmd_vel messages from the first move to the end
    made_up: List[str]          # nodes other than the simulator that published poses
    teleports: List[tuple]      # (t, metres) of each step no command could make
    last: Optional[float] = None    # t of the last pose drawn
    wiped: List[tuple] = []     # (s into the drawing, 'clear' or 'reset') by turtlesim's word

    @property
    def seconds(self):
        """How long the turtle drew: to its end, or to the last pose seen."""
        if self.started is None:
            return 0.0
        return max((self.ended if self.ended is not None else self.last) - self.started, 0.0)


def _ever_in_graph(events, role):
    """Every node the graph reports ever held `role` (a key of a graph event)."""
    return {name for e in events if e['kind'] == 'graph' for name in e[role]}


def simulator(events):
    """The simulator's node names: the servers of /spawn, as the graph reports them."""
    return _ever_in_graph(events, 'simulator')


def last_graph(events):
    return next((e for e in reversed(events) if e['kind'] == 'graph'), None)


def poses(events, since=-math.inf):
    return [e for e in events if e['kind'] == 'pose' and e['t'] >= since]


def moving(pose, before):
    """Whether the turtle moved to `pose`: it has a speed, or it stands
    elsewhere than the pose `before` it (a teleport has no speed)."""
    jumped = before is not None and (abs(pose['x'] - before['x']) > JUMP or
                                     abs(pose['y'] - before['y']) > JUMP)
    return bool(pose['v'] or pose['w'] or jumped)


def marked(sim_poses):
    """(pose, moving) for each pose."""
    return [(p, moving(p, before)) for p, before in zip(sim_poses, [None] + sim_poses[:-1])]


def simulator_poses(events, since=-math.inf, until=math.inf):
    sim = simulator(events)
    return [p for p in poses(events, since) if p['sender'] in sim and p['t'] < until]


def moved(events, since, until=math.inf):
    """Whether the simulator's turtle moved between `since` and `until`."""
    return any(m for _, m in marked(simulator_poses(events, since, until))[1:])


def stood_for(events, since):
    """How long, by its last pose, the simulator's turtle has stood still
    since it last moved after `since`; None if it has not moved since.
    Reads back from the newest event only as far as that last move."""
    graph = last_graph(events)
    sim = set(graph['simulator']) if graph else set()
    newest = later = None
    for e in reversed(events):
        if e['t'] < since:
            break
        if e['kind'] != 'pose' or e['sender'] not in sim:
            continue
        if later is None:
            newest = e['t']
        elif moving(later, e):
            return newest - later['t']
        later = e
    return None


def controllers(events):
    """The nodes that published on the turtle's cmd_vel, as the graph reported them."""
    return _ever_in_graph(events, 'cmd_vel_publishers')


def trigger(events, since, by_grader=False):
    """t of the first "P" on /chatter after `since`, from the cadet's nodes
    that do not drive the turtle (or from the grader's watcher, `by_grader`),
    or None."""
    driving = controllers(events)
    for e in events:
        if e['kind'] == 'chatter' and e['t'] >= since and e['data'].strip() == 'P' \
                and (e['sender'] == WATCHER) == by_grader and e['sender'] not in driving:
            return e['t']
    return None


def own_triggers(events):
    """The nodes that drive the turtle and also published "P" on /chatter."""
    driving = controllers(events)
    return sorted({e['sender'] for e in events if e['kind'] == 'chatter'
                   and e['data'].strip() == 'P' and e['sender'] in driving})


def chatter_peak(events):
    """The most messages a second /chatter carried over any FLOOD_WINDOW,
    by the times the watcher counted them: each count covers `since` to `t`,
    however late a busy machine let the watcher take it."""
    counts = [e for e in events if e['kind'] == 'chatter_count']
    peak, first = 0.0, 0
    for i, count in enumerate(counts):
        while counts[first]['t'] <= count['t'] - FLOOD_WINDOW:
            first += 1
        window = counts[first:i + 1]
        covered = count['t'] - window[0].get('since', window[0]['t'] - COUNTED)
        peak = max(peak, sum(c['count'] for c in window) / max(covered, FLOOD_WINDOW))
    return peak


def wiped(events, started, ended):
    """(s into the drawing, 'clear' or 'reset') for each time turtlesim said
    it cleared or reset its canvas while the turtle drew."""
    sim = simulator(events)
    return [(e['t'] - started, e['what']) for e in events if e['kind'] == 'canvas'
            and e['sender'] in sim and started <= e['t'] <= ended]


def teleports(sim_poses):
    """Steps longer than the commanded speed could make: turtlesim moves a
    turtle at most its pose's speed times a tick each tick."""
    found = []
    for a, b in zip(sim_poses, sim_poses[1:]):
        step = math.hypot(b['x'] - a['x'], b['y'] - a['y'])
        ticks = max(1.0, (b['t'] - a['t']) / TICK) + SLOW_TICKS
        if step > max(abs(a['v']), abs(b['v'])) * TICK * ticks + STEP_SLACK:
            found.append((b['t'], step))
    return found


def drawing(events, since, settle, until=math.inf) -> Drawing:
    """The drawing that follows the trigger at `since`: from the first move
    of the simulator's turtle to when it stood still for `settle` s."""
    sim = simulator(events)
    made_up = sorted({p['sender'] for p in poses(events) if p['sender'] not in sim})
    marks = marked(simulator_poses(events, until=until))
    first = next((i for i, (p, m) in enumerate(marks) if m and p['t'] >= since and i), None)
    if first is None:
        return Drawing([], None, None, 0, made_up, [])
    last_move, end = first, None
    for i in range(first, len(marks)):
        pose, move = marks[i]
        if move:
            last_move = i
        elif pose['t'] - marks[last_move][0]['t'] >= settle:
            end = last_move
            break
    drawn = [p for p, _ in marks[first - 1:(end if end is not None else len(marks) - 1) + 1]]
    started = marks[first][0]['t']
    ended = marks[end][0]['t'] if end is not None else None
    last = drawn[-1]['t']
    commands = sum(e['count'] for e in events if e['kind'] == 'cmd_vel'
                   and started <= e['t'] <= (ended if ended is not None else last) + COUNTED)
    return Drawing([(p['x'], p['y']) for p in drawn], started, ended, commands, made_up,
                   teleports(drawn), last, wiped(events, started, last))
