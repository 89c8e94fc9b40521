"""What a run showed, made sense of. No ROS here.

Two accounts, each a list of dicts with `t` (s, the grader's monotonic clock):
- the record of the grader's own simulator (world.py; 'k': spawn, kill,
  pen, clear, reset, jump, move, cmd, end): the only evidence of what was
  drawn, and by what;
- the watcher's events ('kind': chatter, chatter_count, published, graph):
  who listens and talks on /chatter, and who poses as the simulator.
A "P" counts as the trigger only from a node that does not drive a turtle:
a controller that publishes its own draws without one.
"""
import math
from typing import List, NamedTuple, Optional

from ..letters.layout import DEFAULT_BACKGROUND

WATCHER = '/grade_watch'    # the grader's watcher's node name (watch.py)
POSE_TYPE = 'turtlesim/Pose'    # what a turtle's pose is published as
TWIST_TYPE = 'geometry_msgs/Twist'  # what a turtle is commanded by
TURTLESIM_SERVICES = ('/spawn', '/kill', '/clear', '/reset')
COUNTED = 0.1           # s: the watcher counts /chatter over this period
FLOOD_WINDOW = 1.0      # s over which /chatter's rate is judged
MOVES = ('move', 'jump')    # record lines of a turtle changing place or heading
INK = 1e-6          # m: a segment shorter than this is a pen turned in place, not ink
# While a shell script of the submission runs, a pause ends the drawing only
# this many times `settle` long: each `rostopic pub -1` line starts a node,
# and on a slow machine the next came more than `settle` after the last
# (a real class's scripts were judged ended halfway, or before their first move).
SCRIPT_PAUSE = 4
BACKGROUND = DEFAULT_BACKGROUND     # the grader's simulator's, until a clear or reset says
FULLEST = 3         # canvases a drawing that never ended wiped, read at most (the fullest)
COMMAND_TIMEOUT = 1.0   # s turtlesim follows a command for, unless another comes (the contract)
# s every turtle stands, once every process of the submission has ended, that end its
# drawing: no command can come after, and the last one's COMMAND_TIMEOUT has played out
# (its moves are recorded each 16 ms frame: a pause this long is no stall of the simulator)
GONE_STILL = COMMAND_TIMEOUT


class Drawing(NamedTuple):
    """What the grader's simulator drew, from the first move after `since`
    to when every turtle stood still for `settle` s."""
    strokes: List[list]         # the driven ink: [(x, y), ...] of each unbroken line
    started: Optional[float]    # t of the first move
    ended: Optional[float]      # t the last turtle stopped for good (None: still moving)
    commands: int               # commands the simulator took on cmd_vel meanwhile
    impostors: List[str]        # the submission's nodes that posed as the simulator
    jumps: int = 0              # teleports
    jump_ink: int = 0           # ... of them with the pen down: ink never credited
    last: Optional[float] = None    # t of the last move seen
    wiped: List[tuple] = []     # (s into the drawing, 'clear' or 'reset')
    turtles: List[str] = []     # the turtles that moved, in the order they first did
    pen_lifts: int = 0          # set_pen calls that lifted a pen
    pens: int = 0               # set_pen calls, from the launch on
    spawns: int = 0             # turtles spawned or killed, from the launch on
    looks: List[tuple] = []     # (r, g, b, width px) of each stroke, as turtlesim drew it
    background: tuple = BACKGROUND  # the canvas's colour after the last clear or reset
    teleported: List[list] = []     # the ink teleports laid on the canvas left: never read
    teleported_looks: List[tuple] = []  # ... the look of each of its lines
    earlier: List[list] = []        # ink left on the canvas from before the drawing: never read
    earlier_looks: List[tuple] = []     # ... the look of each of its lines
    shown: tuple = ()           # (s, s) into the drawing the canvas stood, where not the one left
    fullest: List[int] = []     # canvases (drawing()'s) it wiped, never ended: the fullest first
    homes: List[tuple] = []     # (x, y) where each turtle appeared (spawned, or reset)

    @property
    def seconds(self):
        """How long the turtles drew: to the end, or to the last move seen."""
        if self.started is None:
            return 0.0
        return max((self.ended if self.ended is not None else self.last) - self.started, 0.0)

    @property
    def points(self):
        return [p for stroke in self.strokes for p in stroke]


def of_run(run, settle, canvas=None):
    """The drawing of a run (session.Run) from its trigger on, on `canvas`
    (drawing()); None if it never reached the trigger."""
    if run.trigger is None:
        return None
    return drawing(run.record, run.events, run.since, settle, run.finished, run.script_until,
                   canvas, run.gone)


def _ever_in_graph(events, role):
    """Every node the graph reports ever held `role` (a key of a graph event)."""
    return {name for e in events if e['kind'] == 'graph' for name in e.get(role, [])}


def impostors(events):
    """The nodes that published a turtle's pose or served /spawn, where only
    the grader's simulator should: nothing they say is evidence."""
    return sorted(_ever_in_graph(events, 'pose_publishers') | _ever_in_graph(events, 'simulator'))


def moves(record, since=-math.inf, until=math.inf):
    return [e for e in record if e['k'] in MOVES and since <= e['t'] < until]


def moved(record, since, until=math.inf):
    """Whether any turtle moved between `since` and `until`."""
    return bool(moves(record, since, until))


def drew(record, since, until=math.inf):
    """Whether any turtle laid ink between `since` and `until` (a turn in
    place or pen-up travel lays none: a setup move is no drawing)."""
    return any(math.hypot(s[2] - s[0], s[3] - s[1]) > INK
               for e in moves(record, since, until) for s in e['ink'])


def looked_for_from(record, launched, trigger):
    """When the drawing is looked for from: the launch, for a turtle that
    drew before the trigger (it did not wait), else the trigger (moves
    that laid no ink before it, a pen-up teleport or a turn, only set up)."""
    return launched if drew(record, launched, trigger) else trigger


def stood_for(record, since, now):
    """How long every turtle has stood still, at `now`, since the last
    move after `since`; None if none moved since."""
    last = next((e['t'] for e in reversed(record) if e['k'] in MOVES), None)
    return None if last is None or last < since else now - last


def pause_ends(start, end, settle, script_until=None, gone=None):
    """Whether the turtles standing from `start` to `end` ends the drawing:
    `settle` s, counted from when the submission's shell scripts last ran
    (`script_until`, None: none ran) or SCRIPT_PAUSE times as long; or
    GONE_STILL s from `gone`, t every process of the submission had ended
    (None: not seen so)."""
    ran = -math.inf if script_until is None else script_until
    return end - max(start, ran) >= settle or end - start >= SCRIPT_PAUSE * settle or (
        gone is not None and end - max(start, gone) >= GONE_STILL)


def strokes(lines):
    """Unbroken lines of ink: each turtle's segments joined while each
    starts where the one before it ended, in the same pen (a segment None
    breaks its line); and the look of each line, (r, g, b, width) or ()
    where the record gave none."""
    joined, looks, open_end = [], [], {}     # turtle: (the stroke its last segment ended, look)
    for turtle, segment in lines:
        if segment is None:
            open_end.pop(turtle, None)
            continue
        a, b, look = (segment[0], segment[1]), (segment[2], segment[3]), tuple(segment[4:8])
        stroke, was = open_end.get(turtle, (None, None))
        if stroke is None or stroke[-1] != a or was != look:
            stroke = [a]
            joined.append(stroke)
            looks.append(look)
        stroke.append(b)
        open_end[turtle] = stroke, look
    return joined, looks


def _end(record, first, settle, until, script_until=None, gone=None):
    """t of the last move before a pause that ends the drawing (pause_ends),
    once a turtle has been driven, or None. (Teleports before the first drive are set-up: a
    real class's script teleported with its pen down, cleared, spawned and
    set pens, one rosservice call at a time, for more than `settle` s before
    its first rostopic pub.)"""
    last, driven = first['t'], first['k'] == 'move'
    for e in record:
        if e['t'] <= first['t'] or e['k'] not in MOVES:
            continue
        if driven and pause_ends(last, e['t'], settle, script_until):
            return last
        last, driven = e['t'], driven or e['k'] == 'move'
    return last if pause_ends(last, until, settle, script_until, gone) else None


def drawing(record, events, since, settle, until=math.inf, script_until=None,
            canvas=None, gone=None) -> Drawing:
    """The drawing that begins with the first move at or after `since`
    (the record's first line is the simulator's own turtle1), to a pause
    that ends it (pause_ends: `script_until`, t a shell script of the
    submission was last seen running; `gone`, t all of it had ended). Its
    ink is what a canvas showed: the one left (`canvas` None), else the one
    begun by the drawing's clear or reset numbered `canvas` (-1: the first
    canvas, before any), one of those a drawing that never ended wiped
    (Drawing.fullest)."""
    first = next(iter(moves(record, since, until)), None)
    if first is None:
        return Drawing([], None, None, 0, impostors(events))
    ended = _end(record, first, settle, until, script_until, gone)
    stop = ended if ended is not None else until
    during = [e for e in record if first['t'] <= e['t'] <= stop]
    canvases = _canvases(during)
    k = len(canvases) - 2 if canvas is None else canvas     # -1: before the first wipe
    wipes, kept = [e for e in during if e['k'] in ('clear', 'reset')], canvases[k + 1]
    background = _background(wipes, k)
    driven = _inked(kept, 'move', background)
    jumps = [e for e in during if e['k'] == 'jump']
    turtles = list(dict.fromkeys(e['turtle'] for e in during if e['k'] in MOVES))
    commands = sum(e['n'] for e in record if e['k'] == 'cmd'
                   and first['t'] <= e['t'] <= stop + 2 * COUNTED)
    wiped = [(e['t'] - first['t'], e['k']) for e in wipes]
    lines, looks = strokes(driven)
    teleported, teleported_looks = strokes(_inked(kept, 'jump', background))
    left = k == len(wipes) - 1
    earlier, earlier_looks = _left_before(record, first['t'], stop if left else first['t'],
                                          background) if k < 0 or left else ([], [])
    shown = () if left else (0.0 if k < 0 else wiped[k][0], wiped[k + 1][0])
    fullest = _fullest(canvases, wipes) if ended is None and canvas is None else []
    return Drawing(lines, first['t'], ended, commands, impostors(events),
                   sum(e.get('n', 1) for e in jumps),
                   sum(1 for e in kept if e['k'] == 'jump' and e['ink']),
                   [e for e in during if e['k'] in MOVES][-1]['t'],
                   wiped, turtles, sum(1 for e in during if e['k'] == 'pen' and e['off']),
                   sum(1 for e in record[1:] if e['k'] == 'pen'),
                   sum(1 for e in record[1:] if e['k'] in ('spawn', 'kill')), looks, background,
                   teleported, teleported_looks, earlier, earlier_looks, shown, fullest,
                   _homes(record, stop))


def _homes(record, stop):
    """(x, y) of each spawn by `stop` (turtle1's own, and a reset's, at
    turtlesim's centre): where a turtle began, its pen down (page.read_page
    reads past a lead-in from there)."""
    return sorted({(e['x'], e['y']) for e in record
                   if e['k'] == 'spawn' and e['t'] <= stop})


def _canvases(during):
    """The record `during` a drawing cut at each clear or reset: the lines
    of each canvas it showed, in turn (the last: the one left)."""
    canvases = [[]]
    for e in during:
        if e['k'] in ('clear', 'reset'):
            canvases.append([])
        else:
            canvases[-1].append(e)
    return canvases


def _fullest(canvases, wipes):
    """The canvases (as drawing() numbers them) a clear or reset wiped,
    the most driven ink first, FULLEST at most: a writer that never ends
    wipes its canvas and writes again, and the time limit stops it
    mid-word (a real class's USI, written whole 72 s in, cleared 152 times
    in 188 s; another's chase after an offender, its pen down, left more
    ink than its word)."""
    def ink(k):
        return sum(math.hypot(s[2] - s[0], s[3] - s[1])
                   for _, s in _inked(canvases[k + 1], 'move', _background(wipes, k))
                   if s is not None)
    inks = sorted(((ink(k), k) for k in range(-1, len(canvases) - 2)), key=lambda i: -i[0])
    return [k for amount, k in inks if amount > 0][:FULLEST]


def _background(wipes, k):
    """The canvas's colour after wipe k (-1: none yet, the simulator's own)."""
    return tuple(wipes[k].get('background', BACKGROUND)) if k >= 0 else BACKGROUND


def _left_before(record, start, stop, background):
    """(lines, looks) of the ink laid before `start`, driven or teleported,
    that no clear or reset wiped by `stop`: turtlesim still showed it (a
    real class's script drove its turtle a metre before asking at a prompt
    for the letter to draw)."""
    wiped = max((e['t'] for e in record if e['k'] in ('clear', 'reset') and e['t'] <= stop),
                default=-math.inf)
    left = [e for e in record if wiped < e['t'] < start]
    driven, driven_looks = strokes(_inked(left, 'move', background))
    jumped, jumped_looks = strokes(_inked(left, 'jump', background))
    return driven + jumped, driven_looks + jumped_looks


def _inked(record, kind, background):
    """(turtle, segment) of the ink the record's moves of `kind` ('move':
    driven, 'jump': teleports) laid, a None where a move of the other kind
    breaks a turtle's line. A pen of the `background`'s colour erases: it
    lays no ink, and breaks its line."""
    return [(e['turtle'], s if s is not None and tuple(s[4:7]) != background else None)
            for e in record if e['k'] in MOVES
            for s in (e['ink'] if e['k'] == kind else [None])]


def roles(state, types, ours):
    """The graph event's roles, from the master's system state and topic
    types: who publishes a turtle's pose (a turtlesim/Pose, on a topic
    named .../pose) or a cmd_vel, who talks and listens on /chatter, and
    who serves /spawn; the grader's own nodes (`ours`) left out."""
    publishers, subscribers, services = state
    types = dict(types)

    def publishing(suffix, kind=None):
        return sorted({n for topic, nodes in publishers if topic.endswith(suffix)
                       and (kind is None or types.get(topic) == kind)
                       for n in nodes if n not in ours})
    return dict(pose_publishers=publishing('/pose', POSE_TYPE),
                cmd_vel_publishers=publishing('/cmd_vel'),
                chatter_publishers=[n for n in dict(publishers).get('/chatter', [])
                                    if n not in ours],
                chatter_subscribers=[n for n in dict(subscribers).get('/chatter', [])
                                     if n not in ours],
                simulator=[n for n in dict(services).get('/spawn', []) if n not in ours],
                offered=_offered(services, ours),
                unheard=_unheard(publishers, subscribers, types, ours))


def _unheard(publishers, subscribers, types, ours):
    """{topic: [nodes]}: the Twist topics nodes not ours publish and no node
    subscribes to: commands no turtle hears (a turtlebot's /cmd_vel)."""
    heard = {topic for topic, nodes in subscribers if nodes}
    return {topic: sorted(n for n in nodes if n not in ours) for topic, nodes in publishers
            if types.get(topic) == TWIST_TYPE and topic not in heard
            and any(n not in ours for n in nodes)}


def unheard(events):
    """{topic: [nodes]} of every graph event's unheard commands (_unheard)."""
    found = {}
    for e in events:
        for topic, nodes in e.get('unheard', {}).items() if e['kind'] == 'graph' else ():
            found[topic] = sorted(set(found.get(topic, [])) | set(nodes))
    return found


def _offered(services, ours):
    """{node: [its services]} of the nodes not ours, but what every rospy
    and roscpp node serves (its loggers)."""
    offered = {}
    for service, nodes in services:
        for node in nodes:
            if node not in ours and not service.endswith(('/get_loggers', '/set_logger_level')) \
                    and service not in TURTLESIM_SERVICES:
                offered.setdefault(node, []).append(service)
    return {node: sorted(found) for node, found in offered.items()}


def other_words(events):
    """(node, words) of the first message on /chatter from a node not the
    grader's, where none of theirs was "P"; None otherwise."""
    said = [e for e in events if e['kind'] == 'chatter' and e['sender'] != WATCHER]
    if any(e['data'].strip() == 'P' for e in said):
        return None
    return (said[0]['sender'], said[0]['data']) if said else None


def talkers(events):
    """Every node not the grader's that the graph saw publish on /chatter."""
    return _ever_in_graph(events, 'chatter_publishers')


def last_graph(events):
    return next((e for e in reversed(events) if e['kind'] == 'graph'), None)


def controllers(events):
    """The nodes that published on the turtle's cmd_vel, as the graph reported them."""
    return _ever_in_graph(events, 'cmd_vel_publishers')


def actors(record):
    """The nodes that commanded a turtle or changed the world by a call,
    as the grader's simulator told it (its `by` lines)."""
    return {e['node'] for e in record if e['k'] == 'by'}


def fight(record, since, owner=lambda node: node):
    """(t, turtle, how) where, after `since`, a turtle first took commands
    from two of the executables that sent them (`owner` of each node the
    `cmd` lines name): 'at once', within COMMAND_TIMEOUT of each other,
    both still driving it as turtlesim obeys a command; or 'by turns',
    from one, another, then the first again, as a handoff never does;
    else None. A package's executables started together that fight so draw
    no letter: a TA stops them and runs each alone (a real class's two
    scripts of `rostopic pub -1` lines ran 40 to 115 s together; lines of
    two scripts that stay more than the timeout apart take turns)."""
    start = len(record)
    while start and record[start - 1]['t'] >= since:   # the record is in time order
        start -= 1
    latest, turns = {}, {}     # turtle: {owner: t of its latest command}; [owners in turn]
    for e in record[start:]:
        if e['k'] != 'cmd':
            continue
        owners = sorted({owner(node) for node in e.get('by', ())})
        senders = latest.setdefault(e['turtle'], {})
        senders.update((who, e['t']) for who in owners)
        if sum(e['t'] - t <= COMMAND_TIMEOUT for t in senders.values()) > 1:
            return e['t'], e['turtle'], 'at once'
        taken = turns.setdefault(e['turtle'], [])     # one owner here: two are 'at once'
        if owners and taken[-1:] != owners:
            if owners[0] in taken:
                return e['t'], e['turtle'], 'by turns'
            taken.append(owners[0])
    return None


def one_driver(record):
    """Whether one node alone acted on the turtles: the simulator took
    commands and calls from it only (others may have offered a cmd_vel and
    sent nothing: a node that waits for typed goals). Run alone, that node
    would draw what it drew."""
    return len(actors(record)) == 1


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


def unprompted(events, since, typed):
    """The cadet's nodes (not the turtle's drivers) that published "P" on
    /chatter after `since` and before the key was typed at `typed`: a
    talker that publishes by itself, whatever is typed."""
    driving = controllers(events)
    return sorted({e['sender'] for e in events if e['kind'] == 'chatter'
                   and since <= e['t'] < typed and e['data'].strip() == 'P'
                   and e['sender'] != WATCHER and e['sender'] not in driving})


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


