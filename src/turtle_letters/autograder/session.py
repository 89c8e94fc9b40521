"""One submission run as the lab runs it, in its sandbox: the package built
in a workspace of its own over this one, its launch file started with
roslaunch in a pseudo-terminal against the grader's own master and
simulator, with its watcher (world.py's Lab), P and Enter typed for its talker, and the drawing
watched from the launch on, until every turtle stands still. What happened
is a Run, for the rubric to score; nothing here decides points.
"""
import itertools
import os
import re
import signal
import subprocess
import tempfile
import time
from typing import NamedTuple
from xml.sax.saxutils import quoteattr

from ..isolation.sandbox import GiB, Caps, Sandbox
from . import observations as seen
from .failures import RLEXCEPTION, sources, talker_failure, why_not_launched, why_still
from .processes import ControllerCpu, Reader, RunningScripts, reading_input
from .rubric import Limits
from .submission import (LOOSE, MAX_NODES, Package, bare_shell, copy, made_executable,
                         nodes, scripts, sources_built_by_nothing, started_packages,
                         turtles_named, unbuilt_scripts, unstartable, waiting_publishers,
                         wrap)
from .world import (Lab, course_environment, interpreter_stand_ins, stand_in, stand_in_started,
                    terminal_stand_ins)

POLL = 0.1                  # s between looks at what the watcher saw
BASH = ' launch-prefix="bash"'  # a shell script without #! is run with bash, as a TA types it
# ... and a script exec cannot start, with the program its kind runs with (unstartable)
PREFIXES = {'bash': BASH, 'python3': ' launch-prefix="python3"'}
REFUSAL = 'cannot launch node'  # what roslaunch says of a node of its launch file it cannot start
# catkin's words for an include folder a package names and lacks (catkin_package.cmake)
MISSING_INCLUDE = re.compile(r"catkin_package\(\) include dir '([^']+)' does not exist "
                             r"relative to '([^']+)'")
MKDIR_S = 10       # s a mkdir in the sandbox may take
FIGHT_SEEN = 15    # s of the record looked at for a fight: turns A B A, a `rostopic pub -1` 3 s
NO_TURTLESIM = 'its launch file does not start turtlesim'   # nor does the grader's, by design
ROS_VARIABLES = ('ROS_PACKAGE_PATH', 'CMAKE_PREFIX_PATH', 'PYTHONPATH', 'LD_LIBRARY_PATH',
                 'PKG_CONFIG_PATH', 'ROS_DISTRO', 'ROS_VERSION', 'ROS_PYTHON_VERSION',
                 'ROS_ETC_DIR', 'ROS_ROOT', 'ROSLISP_PACKAGE_DIRECTORIES')


class Step(NamedTuple):
    ok: bool
    says: str               # one line: what happened, or why it failed
    seconds: float = 0.0


class Run:
    """What happened to one submission, step by step (None: not reached)."""

    def __init__(self, package: Package, letters=''):
        self.package = package
        self.build = self.launch = self.waited = self.talker = None
        self.events, self.trigger, self.cpu_pct = [], None, None
        self.record = []        # what the grader's simulator did (world.py)
        self.broken = ''        # how the grader's world was broken during the run, if it was
        self.world_failed = False   # ... of itself, not by the submission (GradingWorld.failed)
        self.since = None       # t from which the drawing is looked for
        self.stuck = ''         # why the turtle never moved after the trigger, if it did not
        self.still_from = None  # where in the terminal's text the wait for a first move began
        self.limit = ''         # the sandbox's limit the submission reached, in words
        self.generated = ''     # the executables the grader started, for want of a launch file
        self.executables = []   # ... each by name
        self.unstartable = {}   # ... those exec could not start (no usable #!): {name: run with}
        self.letters = letters  # the roster's: typed where P drew nothing and a prompt waits
        self.passed_over = None  # why the package's launch file was not run, if it was not
        self.fell_short = ''    # '; why': the lab of the executables the grader started fell short
        self.log = []           # (title, lines)
        self.finished = None    # t the run stopped watching
        self.limit_s = None     # s the drawing was watched for at most (limits.drawing)
        self.script_until = None    # t a shell script it started was last seen running
        self.gone = None        # t roslaunch was seen ended (every process of its sandbox with it)
        self.waiting = ''       # where a script it started stops at a rostopic pub, in words
        self.fought = ''        # how the executables started together fought, if they did
        self.typed = ''         # the letters the grader typed at a prompt, if it did

    def watched_for(self):
        """s the drawing was watched for, from the trigger (or the launch) on."""
        return self.finished - self.since if self.since is not None and self.finished else 0.0


def caps(limits: Limits) -> Caps:
    """The sandbox's caps, of the rubric's limits."""
    return Caps(memory=int(limits.memory * GiB), processes=limits.processes, cpu=limits.cpu,
                disk=int(limits.disk * GiB), files=limits.files)


def _env(work, master_uri, isolated=True):
    env = {name: os.environ[name] for name in ROS_VARIABLES if name in os.environ}
    env.update(course_environment(os.environ, isolated))
    env.update(HOME=os.path.join(work, 'home'), ROS_HOME=os.path.join(work, 'home', '.ros'),
               TMPDIR=os.path.join(work, 'tmp'),       # its own, with or without a sandbox
               PATH=f"{os.path.join(work, 'bin')}:/usr/bin:/bin:{os.environ.get('PATH', '')}",
               ROS_MASTER_URI=master_uri, ROS_IP='127.0.0.1', QT_QPA_PLATFORM='offscreen',
               LANG='C.UTF-8', TERM='xterm', PYTHONUNBUFFERED='1')
    return env


def prepare(package, work):
    """The work folder: the package's copy in a workspace, a home, a folder
    for temporary files, the names Noetic's python3 goes by
    (world.INTERPRETERS) and the terminals a launch-prefix may open
    (world.TERMINALS). The scripts handed in
    without the execute bit, made executable (a TA's fallback)."""
    for folder in ('ws/src', 'home', 'tmp', 'bin'):
        os.makedirs(os.path.join(work, folder), exist_ok=True)
    copied = copy(package, os.path.join(work, 'ws'))
    if package.loose:
        wrap(copied)
    interpreter_stand_ins(os.path.join(work, 'bin'))
    terminal_stand_ins(os.path.join(work, 'bin'))
    return made_executable(copied)


def build(box, limits):
    """catkin_make in the sandbox, a job a core it was given: its Step and
    what it printed (capped)."""
    jobs = len(box.cpus or os.sched_getaffinity(0))
    command = ['bash', '-c', 'cd "$0/ws" && catkin_make -j"$1" '
                             '-DPYTHON_EXECUTABLE=/usr/bin/python3', box.work, str(jobs)]
    started = time.monotonic()
    process = box.started(subprocess.Popen(
        box.inside(command, _env(box.work, box.master_uri, box.isolated)),
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True))
    reader = Reader(os.dup(process.stdout.fileno()))
    process.stdout.close()
    ended = wait_until(lambda: process.poll() is not None, limits.build, box.going)
    if not ended:
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except ProcessLookupError:      # it ended as its time ran out
            pass
    process.wait()
    reader.stop()
    text, limit = reader.output.text(), box.reached()
    if not ended:
        return Step(False, f'the build was stopped: {limit}' if limit else
                    f'the build did not end within {limits.build:g} s'), text
    if process.returncode != 0:
        error = first_error(text).replace(sources(box.work), '')
        return Step(False, f'catkin_make failed: {error}', time.monotonic() - started), text
    return Step(True, f'built in {time.monotonic() - started:.1f} s',
                time.monotonic() - started), text


def first_error(text):
    """The build's first error, in its own words: a compiler's line, or
    CMake's message under its "CMake Error at" line, or catkin's reasons
    under its "Error(s) in package" line (make's "Error 2" is only its
    echo)."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.startswith('Error(s) in package'):     # catkin_pkg: one reason a line below
            reasons = itertools.takewhile(bool, (m.strip() for m in lines[i + 1:i + 6]))
            return ' '.join([line.strip(), *reasons])
        if line.startswith('CMake Error'):
            message = ' '.join(m.strip() for m in itertools.takewhile(
                lambda m: m.startswith(' ') or not m, lines[i + 1:i + 6]) if m.strip())
            return f'{line.strip()} {message}'.strip()
        if 'error' in line.lower() and 'Error ' not in line:
            return line.strip()
    return 'see log.txt'


def wait_until(condition, seconds, alive=lambda: True):
    """Polls `condition` until it holds (True), `seconds` pass or `alive()` fails."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline and alive():
        if condition():
            return True
        time.sleep(POLL)
    return bool(condition())


def run(package: Package, limits: Limits, box: Sandbox, letters='') -> Run:
    """Copy, build, launch, type P, watch: the whole run of one submission,
    in `box`; with a TA's fallbacks, each costing `launches` alone and said
    there: scripts handed in without the execute bit run all the same, and
    a launch file that cannot start its nodes (a wrong pkg or type, a
    launch-prefix of a program the machine lacks) gives way to the
    package's executables, started as without a launch file (_launch_or_fall_back).
    Scripts handed in without a package.xml are wrapped in one and run,
    and an include folder the package names and lacks is made (_built),
    each costing `builds` alone. A prompt that waits for a line where P drew
    nothing is typed the roster's `letters` (_typed_letters). Where the
    grader's own world fails under the run, it is run again (_again)."""
    result = Run(package, letters)
    made = prepare(package, box.work)
    stand_in(box.work)
    box.hand_over()
    folder_made = _built(box, limits, result)
    result.limit = box.reached()
    if not box.going():
        return result
    if not result.build.ok:
        if folder_made:
            result.build = result.build._replace(says=f'{folder_made}; then {result.build.says}')
        return _unbuilt(box, limits, result)
    result = _launch_or_fall_back(box, limits, result)
    failed = result.broken if result.world_failed and box.going() else ''
    if failed:
        result = _again(box, limits, package, result)
    if made and result.launch is not None and result.launch.ok:
        result.launch = Step(False, f'{", ".join(made)} handed in without the execute bit: '
                                    f'the grader made {"them" if len(made) > 1 else "it"} '
                                    f'executable, as a TA would', result.launch.seconds)
    if folder_made and result.build.ok:
        result.build = Step(False, f'{folder_made}, and it built', result.build.seconds)
    if package.loose and result.build.ok:
        result.build = Step(False, f'{package.loose}; the grader wrapped its files in a package '
                                   f'({LOOSE}) and ran its scripts, as a TA would',
                            result.build.seconds)
    if failed and result.launch is not None:
        result.launch = result.launch._replace(
            says=f"{result.launch.says}; {failed} in the first run, not by the submission's "
                 f"doing: the grader ran it again in a fresh world")
    return result


def _launch_or_fall_back(box, limits, result) -> Run:
    """`result` with the lab launched and watched; where its launch file
    cannot start its nodes, a fresh Run of the package's executables
    instead, in a fresh world on the same build. A package with no
    executable to run is said so (_never_built), and nothing is run."""
    package = result.package
    if not (package.launch or executables(box, package)):
        result.launch = Step(False, f'no launch file, and {package.name} has no executable to '
                                    f'run{_never_built(box, package)}')
        return result
    _launch_and_watch(box, limits, result)
    if not _refused(result, box) or not box.going():
        return result
    if not executables(box, package):
        result.launch = Step(False, f'{result.launch.says}; {package.name} has no executable '
                                    f'to run instead{_never_built(box, package)}')
        return result
    first, says = result, result.launch.says
    result = Run(package._replace(launch=None), first.letters)
    result.build, result.log = first.build, first.log
    _launch_and_watch(box, limits, result)
    result.launch = Step(False, f'{says}; the grader ran its executables instead '
                                f'({result.generated}), as a TA would{result.fell_short}')
    return result


def _again(box, limits, package, first):
    """A TA's next try where the grader's own world failed under the run
    (Run.world_failed): the package launched again, as at first, in a fresh
    world on the same build. It costs the student nothing (run() says it
    in the launch step); a second failure is the row's, in its own words."""
    result = Run(package, first.letters)
    result.build = first.build
    result.log = first.log + [("the grader's own failure", f'{first.broken}: run again')]
    return _launch_or_fall_back(box, limits, result)


def _built(box, limits, result):
    """catkin_make (build), and a TA's fallback where catkin_package() names
    an include folder the package lacks (catkin_create_pkg makes one, and
    git keeps no empty folder: the build fails so on every machine but the
    student's): the folder made, empty, in the package's copy, and the
    workspace built again. What failed and was made, for `builds`, or ''."""
    result.build, output = build(box, limits)
    result.log.append(('catkin_make', output))
    folder = None if result.build.ok else missing_include(box.work, output)
    if folder is None or not box.going():
        return ''
    failed = result.build
    # made inside the sandbox: the build ran the package's CMake code, which may have
    # left a process to swap the path for a link out of it since
    subprocess.run(box.inside(['mkdir', '-p', '--', folder],
                              _env(box.work, box.master_uri, box.isolated)),
                   stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, timeout=MKDIR_S, check=False)
    if not os.path.isdir(folder):
        return ''
    result.build, output = build(box, limits)
    result.log.append(('catkin_make', output))
    made = os.path.relpath(folder, os.path.realpath(os.path.join(box.work, 'ws', 'src')))
    return (f'{failed.says}; git keeps no empty folder: the grader made {made}/, empty, '
            f'as a TA would')


def missing_include(work, output):
    """The folder catkin_package() said a package of the workspace in
    `work` lacks, in that package's copy; None where it said none, or
    named one outside the package or there already."""
    said = MISSING_INCLUDE.search(' '.join(output.split()))
    if said is None:
        return None
    source = os.path.realpath(os.path.join(work, 'ws', 'src'))
    package = os.path.realpath(said.group(2))
    folder = os.path.realpath(os.path.join(package, said.group(1)))
    inside = package.startswith(source + os.sep) and folder.startswith(package + os.sep)
    return folder if inside and not os.path.lexists(folder) else None


def _unbuilt(box, limits, result):
    """A TA's fallback for a package whose build failed (its CMakeLists.txt
    names another project, or it has none) but whose nodes are scripts
    (Python, or shell scripts of rosservice and rostopic calls): they are
    run from their folder, unbuilt, as a TA runs them by hand. Only
    `builds` is lost for the failure."""
    if not unbuilt_scripts(os.path.join(box.work, 'ws', 'src', result.package.name)):
        return result
    failed = result.build
    _launch_and_watch(box, limits, result, unbuilt=True)
    result.build = failed._replace(says=f'{failed.says}; the grader ran its scripts '
                                        f'unbuilt, from their folder, as a TA would')
    return result


def _refused(result, box):
    """Whether roslaunch refused to start a node of the package's launch
    file, or ended on its own exception (a launch-prefix of a program the
    machine lacks, XML it cannot read: failures.roslaunch_exception), or the
    lab failed where the launch file starts a Python script exec cannot
    start (its #! line ends in a carriage return: env finds no `python3\\r`)."""
    if not (result.package.launch and result.launch is not None and not result.launch.ok):
        return False
    copied = _copied(box, result.package)
    started = {kind for _, kind in nodes(os.path.join(copied, result.package.launch),
                                         {result.package.name: copied})}
    return result.launch.says.startswith((REFUSAL, RLEXCEPTION)) or \
        bool(started & set(unstartable(copied)))


def _never_built(box, package):
    """': why', where the package's C++ sources are built by nothing, or ''."""
    sources = sources_built_by_nothing(_copied(box, package))
    if not sources:
        return ''
    return (f': its CMakeLists.txt builds no program of {", ".join(sources)} '
            f'(add_executable(name {sources[0]}) builds one)')


def alone(first: Run, name, limits: Limits, box: Sandbox) -> Run:
    """A TA's next try where a package's executables, started together,
    drew nothing worth its letter (they fought over one turtle): `name`
    alone, in a fresh world, on the same build."""
    result = Run(first.package._replace(launch=None), first.letters)
    result.build, result.log = first.build, list(first.log)
    _launch_and_watch(box, limits, result, only=name)
    if result.launch is not None:      # why the first run started them, as it said
        stopped = f' ({first.fought}: stopped there)' if first.fought else ''
        result.launch = Step(False, f'{first.passed_over or "no launch file"}: the grader '
                                    f'started its executables ({first.generated}) '
                                    f'together{stopped}, then {name} alone in a fresh world, '
                                    f'as a TA would{result.fell_short}')
    return result


def untried(launch: Step, names, limits: Limits) -> Step:
    """The launch step of the run kept, where `names` were not run alone:
    the alone runs had used the one drawing limit they share."""
    return launch._replace(says=f'{launch.says}; {", ".join(names)} not run alone: the alone '
                                f'runs had used the {limits.drawing:g} s they share')


def executables(box, package):
    """The package's executables, by name: its scripts (made executable) and
    what its build made."""
    built = os.path.join(box.work, 'ws', 'devel', 'lib', package.name)
    return sorted(set(scripts(_copied(box, package))) | set(scripts(built, 0)))[:MAX_NODES]


def _copied(box, package):
    return os.path.join(box.work, 'ws', 'src', package.name)


def generated_launch(box, package, names):
    """The launch file the grader writes where a package has none that
    starts its nodes: each executable of `names` started as rosrun would,
    all in roslaunch's terminal (a shell script without #!, with bash; a
    script whose #! exec cannot follow, with python3 or bash: unstartable).
    Its path.
    (The grader runs turtlesim itself: a launch file of turtlesim and
    its teleop alone adds nothing, and a real class's failed to parse.)"""
    prefix = {name: BASH for name in bare_shell(_copied(box, package))}
    prefix.update((name, PREFIXES[program])
                  for name, program in unstartable(_copied(box, package)).items())
    lines = [f'  <node pkg={quoteattr(package.name)} type={quoteattr(name)} '
             f'name="{_node(name, i)}" output="screen"{prefix.get(name, "")}/>\n'
             for i, name in enumerate(names)]
    # a name of its own: the submission's build could have left a link anywhere in `work`
    fd, path = tempfile.mkstemp(prefix='grader_', suffix='.launch', dir=box.work)
    with os.fdopen(fd, 'w') as f:
        f.write('<launch>\n' + ''.join(lines) + '</launch>\n')
    os.chmod(path, 0o644)
    return path


def drivers_first(run, box):
    """The executables a run started for want of a launch file, in the order
    a TA tries them alone: those whose node acted on the turtles first (the
    simulator's account: the controllers before a keyboard); within each
    part, those whose text (the package's copy in `box`) names more
    turtles first (turtles_named: a course's two scripts, one of turtle1
    for the first letter, one spawning turtle2 for the second, are tried
    the whole drawing first), then in name order."""
    acted = seen.actors(run.record)
    named = turtles_named(_copied(box, run.package), run.executables)

    def order(place):
        i, name = place
        return f'/{_node(name, i)}' not in acted, -named.get(name, 0)
    return [name for _, name in sorted(enumerate(run.executables), key=order)]


def _node(executable, i):
    """The name of the node the generated launch file starts `executable` as,
    the i-th: of its file name, and unique."""
    stem = re.sub(r'[^A-Za-z0-9_]', '_', os.path.splitext(executable)[0])
    return f'{stem}{i}' if stem[:1].isalpha() else f'n_{stem}{i}'


def passed_over(launch, started, name):
    """Why the package's `launch` file was passed over for its executables:
    the packages whose nodes it `started`, none of them `name`."""
    if not started:     # it may include another package's (gazebo_ros's world): no node of its own
        return f'{launch} starts no node of {name}'
    return f'{launch} starts nodes of {", ".join(started)} only, none of {name}'


def _launch_and_watch(box, limits, result, only=None, unbuilt=False):
    work, package = box.work, result.package
    names = [only] if only else executables(box, package)
    started, own = started_packages(package) if package.launch else ([], False)
    if package.launch and (not names or own):
        launch = [package.name, os.path.basename(package.launch)]
    else:
        launch = [generated_launch(box, package, names)]
        result.executables, result.generated = names, ', '.join(names) or 'none'
        result.unstartable = {name: program for name, program in
                              unstartable(_copied(box, package)).items() if name in names}
        result.passed_over = package.launch and passed_over(package.launch, started,
                                                            package.name)
    # Sourced first: the stand-in's workspace goes before the package's own.
    # Unbuilt, the package is found in its source folder, as rosrun finds scripts.
    setup = ('export ROS_PACKAGE_PATH="$0/ws/src:$ROS_PACKAGE_PATH"' if unbuilt else
             'source "$0/ws/devel/setup.bash"')
    command = ['bash', '-c', f'{setup} && '
               'export CMAKE_PREFIX_PATH="$1:$CMAKE_PREFIX_PATH" && shift && '
               'exec roslaunch "$@"', work, os.path.join(work, 'stand_in')] + launch
    lab = Lab(box, box.inside(command, _env(work, box.master_uri, box.isolated)), limits)
    try:
        _watch(lab, limits, result)
    finally:
        result.finished = time.monotonic()
        result.limit, result.broken = lab.limit(), lab.world.broken()
        result.world_failed = lab.world.failed() and not result.limit
        watcher_said = lab.stop()
        result.events, result.record = list(lab.watcher.events), list(lab.world.events)
        result.log.append((f'roslaunch {" ".join(launch)}', lab.terminal.text()))
        result.log.append(("the grader's master and simulator", lab.world.log_tail()))
        if watcher_said.strip():
            result.log.append(("the grader's watcher (not the submission's)", watcher_said))
    _explain(result, lab.terminal, work)
    if result.generated and result.launch is not None:
        result.fell_short, result.launch = started_instead(result)


def started_instead(run):
    """('; what was done and why the lab fell short' or '', the launch step)
    of a `run` of the executables the grader started for want of a launch
    file that starts them: how it came to, the scripts run with python3 or
    bash (_run_with), and what the lab said where it did not come up (a node
    that died is the student's to mend, whoever started it), and where they
    fought over a turtle, that the grader stopped them (_fought). The launch
    file the grader writes starts no turtlesim: the grader runs its own."""
    fell_short = '' if run.launch.ok or run.launch.says == NO_TURTLESIM else \
        f'; {run.launch.says}'
    fell_short = _run_with(run.unstartable) + fell_short
    how = (f'{run.passed_over}: the grader started its executables ({run.generated}) instead, '
           f'as a TA would' if run.passed_over else
           f'no launch file: the grader started its executables ({run.generated}) as a launch '
           f'file would')
    stopped = f'; {run.fought}: the grader stopped them' if run.fought else ''
    return fell_short, Step(False, how + fell_short + stopped)


def _run_with(unstartable):
    """'; words' for each program the scripts exec could not start were
    run with ({name: 'python3' or 'bash'}), or ''."""
    said = ''
    for program, line in (('python3', '#!/usr/bin/env python3'), ('bash', '#!/bin/bash')):
        names = [name for name, used in unstartable.items() if used == program]
        if names:
            them = 'them' if len(names) > 1 else 'it'
            said += (f'; {", ".join(names)}: no #! line exec can follow ({line} is one), '
                     f'so the grader ran {them} with {program}, as a TA would')
    return said


class Refused:
    """A TA's patience with a launch that roslaunch refused a node of
    (REFUSAL): the others get `seconds` more to come up."""

    def __init__(self, output, seconds):
        self.output, self.seconds, self.said = output, seconds, None

    def waited_out(self):
        if self.said is None and self.output.has(REFUSAL.encode()):
            self.said = time.monotonic()
        return self.said is not None and time.monotonic() - self.said >= self.seconds


def _watch(lab, limits, result):
    """Launched at `started`: up once a node listens on /chatter, a turtle
    moves or a prompt waits (_up); P typed after the turtle stood for
    limits.stand (_trigger); the drawing watched from the launch (a turtle
    that did not wait), the trigger, or the letters typed at a prompt."""
    terminal, watcher, alive = lab.terminal, lab.watcher, lab.going
    events, record = watcher.events, lab.world.events
    started = time.monotonic()
    refused = Refused(terminal.output, limits.start)
    if not wait_until(lambda: _up(lab, started, refused, limits), limits.launch,
                      lambda: alive() and not refused.waited_out()):
        result.launch = Step(False, 'the lab did not come up')
        return
    up = time.monotonic()
    result.launch = _launched(events, os.path.join(terminal.box.work, 'stand_in'), up - started,
                              seen.moved(record, started))
    scripts = RunningScripts(terminal.process.pid, os.path.join(terminal.box.work, 'ws'),
                             programs=bool(result.executables))
    alive = _noting(scripts, alive)
    wait_until(lambda: False, limits.stand, alive)
    result.waited = _waited(record, started, limits.stand)
    cpu, shown = ControllerCpu(terminal.process.pid, events), terminal.output.size
    asked = _trigger(lab, limits, result, started, shown, alive)
    since = result.since = asked or seen.looked_for_from(record, started, result.trigger)
    result.limit_s = limits.drawing
    if wait_until(lambda: seen.moved(record, since), limits.start, alive):
        wait_until(lambda: _fought(result, record, since, scripts) or
                   _stood(record, since, limits.settle, scripts), limits.drawing, alive)
        if not result.fought and terminal.process.poll() is not None:
            # roslaunch ended with its last node (a script of `rostopic pub -1`s): the
            # turtle's last command plays out, and it is seen to stand; in bubblewrap's
            # PID namespace, nothing of the submission outlives roslaunch
            result.gone = time.monotonic() if lab.box.isolated else None
            wait_until(lambda: _stood(record, since, limits.settle, scripts, result.gone),
                       limits.settle + 1, lab.watchable)
    else:
        result.still_from = shown
    result.cpu_pct, result.script_until = cpu.share(), scripts.until


def _trigger(lab, limits, result, started, shown, alive):
    """P and Enter typed on the lab's terminal (launched at `started`, its
    text `shown` so far), as a TA triggers it: the talker's "P" on /chatter
    is the trigger, else the grader's own, published after limits.talker;
    where a prompt waits, the roster's letters are typed (_typed_letters).
    Returns when those were typed, else None."""
    terminal, watcher, typed = lab.terminal, lab.watcher, time.monotonic()
    events = watcher.events
    terminal.type(b'P')
    time.sleep(0.2)
    terminal.type(b'\r')
    early = seen.unprompted(events, started, typed)
    if wait_until(lambda: seen.trigger(events, typed) is not None, limits.talker, alive):
        result.trigger = seen.trigger(events, typed)
        result.talker = Step(not early, f'"P" on /chatter {result.trigger - typed:.1f} s after '
                                        f'the key' if not early else
                             f'{", ".join(early)} published "P" on /chatter before any key was '
                             f'typed: the talker does not wait for the key')
    else:
        result.talker = Step(False, f'no "P" on /chatter within {limits.talker:g} s of P and '
                                    f'Enter')
        if not watcher.publish_p():
            result.talker = result.talker._replace(says=(
                f'{result.talker.says}, and the grader could not send "P" itself: its watcher '
                f'({seen.WATCHER}) was shut down (a node took its name, or shut it down)'))
        wait_until(lambda: seen.trigger(events, typed, by_grader=True) is not None, 5.0)
        result.trigger = seen.trigger(events, typed, by_grader=True) or time.monotonic()
    asked = _typed_letters(lab, limits, result, typed, shown)
    result.trigger = asked or result.trigger
    return asked


def _noting(scripts, alive):
    """`alive`, noting at each look what the scripts run so far have started
    (RunningScripts.owner: a fight told by script sees their first lines)."""
    def noted():
        scripts.running()
        return alive()
    return noted


def _up(lab, started, refused, limits):
    """Whether the lab launched at `started` is up: a node listens on
    /chatter or a turtle moved; or, neither after limits.start and no node
    refused by roslaunch (a TA's fallback runs then), a prompt waits for a
    line (_prompting: a talker waits so too, before its controller listens)."""
    return _listening(lab.watcher.events) or seen.moved(lab.world.events, started) or (
        time.monotonic() - started >= limits.start and refused.said is None and
        _prompting(lab.terminal))


def _typed_letters(lab, limits, result, typed, shown):
    """A TA's fallback where no talker answered P and no turtle moved since:
    a node waits for a line on the terminal (a prompt's input(), the
    terminal in line mode), so the roster's letters are typed, and Enter,
    as the prompt asks (a real class's "enter a letter (A,B)"). When they
    were typed, where a turtle moved within limits.start of it (the drawing
    is looked for from then), else None (one drawn at the launch stands)."""
    terminal, record = lab.terminal, lab.world.events
    if result.talker.ok or not result.letters or seen.moved(record, typed) or \
            not _prompting(terminal):
        return None
    prompt = ([line.strip() for line in terminal.text(shown).splitlines() if line.strip()]
              or [''])[-1][:80]
    asked, result.typed = time.monotonic(), result.letters
    terminal.type(result.letters.encode() + b'\r')
    moved = wait_until(lambda: seen.moved(record, asked), limits.start, lab.going)
    result.talker = result.talker._replace(says=(
        f'{result.talker.says}; a node waited for a line on the terminal ({prompt!r}): the '
        f'grader typed {result.letters} and Enter, as a TA would'
        f'{"" if moved else ", and no turtle moved"}'))
    return asked if moved else None


def _prompting(terminal):
    """Whether a node waits for a line on the terminal: it reads its input
    there, and the terminal is in line mode (a talker reads key by key)."""
    return terminal.in_lines() and reading_input(terminal.process.pid)


def _waited(record, started, stand):
    """The waits step, before the trigger: moves that laid no ink set up."""
    if seen.drew(record, started):
        return Step(False, 'a turtle drew before the trigger')
    setup = ' (it was set up first, laying no ink)' if seen.moved(record, started) else ''
    return Step(True, f'the turtle stood still for {stand:g} s until the trigger{setup}')


def _listening(events):
    graph = seen.last_graph(events)
    return bool(graph and graph['chatter_subscribers'])


def _launched(events, stand_in_folder, seconds, moved):
    """The launch step, once the lab is up: it started turtlesim (the
    stand-in) and a node that listens on /chatter (else a turtle `moved`,
    or a node waits for a line on the terminal)."""
    listeners = seen.last_graph(events)['chatter_subscribers'] if seen.last_graph(events) else []
    if not stand_in_started(stand_in_folder):
        return Step(False, NO_TURTLESIM, seconds)
    if not listeners:
        return Step(False, 'no node subscribed to /chatter: ' + (
            'a turtle moved without the trigger' if moved else
            'a node waits for a line on the terminal'), seconds)
    return Step(True, f'turtlesim up, {", ".join(listeners)} listening on /chatter, in '
                      f'{seconds:.1f} s', seconds)


def _explain(result, terminal, work):
    """The failures' lines that read the submission's files (its nodes'
    logs): made only once none of its processes runs, so that none can
    swap a file for a link or a pipe while the grader reads it."""
    text = terminal.text()
    if result.launch is not None and result.launch.says == 'the lab did not come up':
        result.launch = result.launch._replace(says=why_not_launched(text, result.events, work))
    if result.talker is not None and not result.talker.ok:
        why = talker_failure(text, work, talked=not _no_talker(result),
                             said=seen.other_words(result.events))
        if why:
            result.talker = result.talker._replace(says=f'{result.talker.says}: {why}')
    result.waiting = waiting_publishers(*_started_scripts(result, work))
    if result.still_from is not None:
        graph = seen.last_graph(result.events)
        result.stuck = why_still(terminal.text(result.still_from), work,
                                 graph['chatter_subscribers'] if graph else [],
                                 graph.get('offered') if graph else None, result.events,
                                 result.waiting)


def _no_talker(result):
    """Whether the graph, watched past the trigger, saw no node of the run
    publish on /chatter, and no prompt was typed letters instead: why no P
    came (not where the grader's watcher was shut down before it)."""
    watched = result.trigger is not None and any(
        e['kind'] == 'graph' and e['t'] >= result.trigger for e in result.events)
    return watched and not result.typed and not seen.talkers(result.events)


def _started_scripts(result, work):
    """(the package's copy, the names of the executables its run started)."""
    copied = os.path.join(work, 'ws', 'src', result.package.name)
    if result.executables or not result.package.launch:
        return copied, result.executables
    return copied, [kind for _, kind in nodes(os.path.join(copied, result.package.launch),
                                              {result.package.name: copied})]


def _fought(result, record, since, scripts):
    """Whether the executables the grader started together drove one turtle
    at once or by turns (seen.fight; each node a script started is the
    script's), as a TA watching stops them; result.fought says so. Only the
    last FIGHT_SEEN s are looked at: the record grows as it is watched."""
    recent = max(since, time.monotonic() - FIGHT_SEEN)
    found = len(result.executables) > 1 and seen.fight(record, recent, scripts.owner)
    if found:
        t, turtle, how = found
        did = f'drove {turtle} at once' if how == 'at once' else f'took turns driving {turtle}'
        result.fought = f'they {did} {t - since:.0f} s into the drawing'
    return bool(found)


def _stood(record, since, settle, scripts, gone=None):
    """Whether the turtles have stood long enough to end the drawing (a
    shell script of the submission that still runs makes it longer; all of
    it gone, at `gone`, shorter)."""
    now = time.monotonic()
    still = seen.stood_for(record, since, now)
    scripts.running()      # notes when one was last seen running
    return still is not None and seen.pause_ends(now - still, now, settle, scripts.until, gone)
