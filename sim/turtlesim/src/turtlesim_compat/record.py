"""What the simulator did to its world, told to whoever started it: one
JSON line per change, on the file descriptor named by TURTLESIM_RECORD_FD
(none: nothing is told). The grader (turtle_letters' grade_class.py) reads
it from a pipe no node of ROS can reach, so it is the one account of what
was drawn that no submission can forge. No ROS and no Qt here.

Lines ('k' is the kind, 't' time.monotonic() when it happened):
    spawn  turtle x y theta        kill   turtle
    pen    turtle r g b width off  clear, reset (reset: every turtle gone, turtle1 anew)
    jump   turtle to=[x, y, theta] ink=[segments] n   n teleports in a tick
    move   turtle to=[x, y, theta] ink=[segments]   a tick's move, driven by cmd_vel
    cmd    turtle n by             commands that came on cmd_vel since the last such line,
                                   and the nodes that sent them (sorted)
    by     node                    a node's first command or call that changed the world
    refused call why               a request refused (a spawn past ~max_turtles, a bad name)
    end    why                     the simulator shuts down
A segment is [x0, y0, x1, y1, r, g, b, width]: a line the pen left.

The lines that change the picture (ink laid, clear, reset, spawn, kill)
are also kept for the tick's end, when the node publishes them on `~ink`
(std_msgs/String, a JSON list a tick) for pages that show the canvas.
"""
import json
import os
import time

FD_VARIABLE = 'TURTLESIM_RECORD_FD'
COMMANDS_EVERY = 6      # ticks between counts of commands (about 0.1 s)
PICTURE = ('clear', 'reset', 'spawn', 'kill')     # beside ink, what a page of the canvas needs


def ink(segments):
    return [[round(s.x0, 6), round(s.y0, 6), round(s.x1, 6), round(s.y1, 6), *s.colour, s.width]
            for s in segments]


def where(turtle):
    return [round(turtle.x, 6), round(turtle.y, 6), round(turtle.theta, 6)]


class Account:
    """The grader's evidence: each line written to TURTLESIM_RECORD_FD as it
    happens, and nothing kept; a no-op when nobody asked for it."""

    def __init__(self, environ):
        fd = environ.get(FD_VARIABLE, '')
        self.out = os.fdopen(int(fd), 'w', buffering=1) if fd.isdigit() else None

    def write(self, line):
        if self.out is None:
            return
        try:
            self.out.write(json.dumps(line) + '\n')
        except (OSError, ValueError):   # the reader is gone: nobody to tell
            self.out = None


class InkFeed:
    """The lines that change the picture (ink laid, clear, reset, spawn,
    kill), kept for the tick's end while a page listens on ~ink."""

    def __init__(self):
        self.showing = False    # whether anyone listens
        self.shown = []         # this tick's lines

    def keep(self, line):
        if self.showing and (line.get('ink') or line['k'] in PICTURE):
            self.shown.append(line)

    def take(self):
        """This tick's lines, as JSON ('' for none)."""
        shown, self.shown = self.shown, []
        return json.dumps(shown) if shown else ''


class Record:
    """What the simulator did, told as it happens to both who may listen:
    the grader's account and the pages' ink feed (each its own job)."""

    def __init__(self, environ=os.environ):
        self.account, self.feed = Account(environ), InkFeed()
        self.commands = {}      # turtle: commands since the last count (the account's)
        self.commanders = {}    # turtle: the nodes that sent them
        self.actors = set()     # the nodes told of in `by` lines
        self.ticks = 0

    @property
    def showing(self):
        return self.feed.showing

    @showing.setter
    def showing(self, listened):
        self.feed.showing = listened

    def __call__(self, kind, **fields):
        if self.account.out is None and not self.feed.showing:
            return
        line = dict(k=kind, t=time.monotonic(), **fields)
        self.feed.keep(line)
        self.account.write(line)

    def take_shown(self):
        """This tick's lines that change the picture, as JSON ('' for none)."""
        return self.feed.take()

    def acted(self, node):
        """`node` (its name) commanded a turtle or changed the world by a
        call: told the first time (the grader runs a package's nodes alone
        only where more than one acted)."""
        if node not in self.actors:
            self.actors.add(node)
            self('by', node=node)

    def command(self, turtle, node):
        if self.account.out is not None:
            self.commands[turtle] = self.commands.get(turtle, 0) + 1
            self.commanders.setdefault(turtle, set()).add(node)

    def turtle_ticked(self, turtle, before, after_jump, jumped, moved, teleports=0):
        """A turtle's tick: its `teleports` (their ink `jumped`) and its
        move's changes, if any. Teleports that come back where they began
        are told too: their ink is on the canvas, and they were asked for."""
        if self.account.out is None and not self.feed.showing:
            return
        if after_jump != before or jumped or teleports:
            self('jump', turtle=turtle.name, to=list(after_jump), ink=ink(jumped),
                 n=max(teleports, 1))
        now = where(turtle)
        if now != after_jump:
            self('move', turtle=turtle.name, to=now, ink=ink(moved))

    def tick_ended(self):
        self.ticks += 1
        if self.ticks % COMMANDS_EVERY == 0 and self.commands:
            for turtle, count in sorted(self.commands.items()):
                self('cmd', turtle=turtle, n=count, by=sorted(self.commanders[turtle]))
            self.commands, self.commanders = {}, {}
