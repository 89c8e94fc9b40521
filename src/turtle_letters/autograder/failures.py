"""Why a step of a run failed, in one line, from what the run printed:
roslaunch's terminal and the nodes' log files in the sandbox's home. The
files are the submission's: read as plain files only (no link, no pipe),
and only their last part."""
import os
import re

from ..isolation.files import read_plain
from . import observations as seen

# a Python exception's line, roslaunch's, or env's where a #! names a program the machine lacks
ERROR_LINE = re.compile(r'^\s*(\w+(Error|Exception)\b.*|ERROR: .*|/usr/bin/env: .+)$')
FRAME_LINE = re.compile(r'^\s*File "([^"]+)", line (\d+)')    # a Python traceback's
RLEXCEPTION = 'roslaunch: '    # how a reason roslaunch_exception gives begins
LOG_TAIL = 20000        # bytes read of a node's log file, from its end
LOGS_READ = 40          # log files read at most
LOG_DEPTH = 2           # folders under ~/.ros/log looked in
LOG_ENTRIES = 1000      # entries of a folder looked at
SAID_CHARS = 200        # characters of a line a node printed, shown at most
# An error line whose cause is another ROS or Python than the course's, and what to do.
OTHER_WORLD = ((re.compile(r"env: .python2.: No such file"),
                'ROS Noetic runs Python 3: name python3 in its #! line'),
               (re.compile(r"No module named .rcl(py|cpp)."),
                'that is ROS 2, and this lab is ROS 1 (Noetic): write it with rospy'),
               (re.compile(r"^SyntaxError: Missing parentheses in call to .print."),
                "that is Python 2's print, and ROS Noetic runs Python 3: call print(...)"),
               (re.compile(r"^SyntaxError: multiple exception types must be parenthesized"),
                "that is Python 2's `except Error, e`, and ROS Noetic runs Python 3: write "
                "`except Error as e`"),
               (re.compile(r"^TabError: "),
                'Python 2 took tabs and spaces mixed, and ROS Noetic runs Python 3: indent '
                'with spaces only'))
NO_TALKER = 'no node of the run published on /chatter (a talker publishes "P" there when P is typed)'
OTHER_WORDS = 40    # characters of another message than "P" on /chatter a row shows
ARGUMENT_ERRORS = ('IndexError', 'ValueError')    # of a line that reads sys.argv: no arguments
# how the lines roslaunch prints of its own begin
ROSLAUNCH_LINES = ('process[', '[', 'setting /', 'ROS_MASTER_URI', '...', 'started roslaunch',
                   'auto-starting', 'SUMMARY', 'PARAMETERS', 'NODES', '* ', 'log file:')


def why_not_launched(output, events, work):
    """Why the lab's graph did not come up, in one line."""
    refused = [line for line in output.splitlines() if line.startswith('ERROR: cannot launch')]
    graph = seen.last_graph(events)
    exception = roslaunch_exception(output, work)
    if refused or exception:
        return refused[0][len('ERROR: '):] if refused else exception
    died = first_death(output, work)
    if died and graph is not None:     # and a server of the package's waits, if one does
        return f'{died}; {waits_for_calls(graph)}' if graph.get('offered') else died
    if graph is None:
        return last_error(output) or "the grader's watcher saw no ROS graph"
    if seen.unheard(events):
        return f'no node subscribed to /chatter, and no turtle moved: {unheard_said(events)}'
    if graph.get('offered'):
        return f'no node subscribed to /chatter, and no turtle moved: {waits_for_calls(graph)}'
    return ('no node subscribed to /chatter, and no turtle moved: is the controller started by '
            'the launch file?')


def unheard_said(events):
    """Words for the commands no turtle heard (observations.unheard), or ''."""
    topics = seen.unheard(events)
    said = '; '.join(f'{", ".join(nodes)} published on {topic}, which no turtle hears'
                     for topic, nodes in sorted(topics.items()))
    return f"{said} (turtlesim's turtle1 hears /turtle1/cmd_vel)" if said else ''


def roslaunch_exception(output, work=''):
    """roslaunch's own reason for ending ('RLException: ...'), with the
    command it names on the line below, or '' (a launch-prefix of a program
    the machine lacks: 'No such file or directory' ... 'gdb -ex run'); the
    command as the student knows it: its node's path in their package, no
    remappings roslaunch adds."""
    lines = output.splitlines()
    for i, line in enumerate(lines):
        if line.startswith('RLException: '):
            said = theirs(line[len('RLException: '):].strip(), work)    # a launch file it names
            below = [m.strip() for m in lines[i + 1:i + 4] if m.strip()]
            if not (said.endswith(':') and below):
                return f'{RLEXCEPTION}{said}'
            words = [w for w in theirs(below[0], work).split() if not w.startswith('__')]
            return f'{RLEXCEPTION}{said} {" ".join(words)}'
    return ''


def sources(work):
    """The sandbox's workspace sources, a path prefix: what follows is as the student knows it."""
    return os.path.join(work, 'ws', 'src', '')


def theirs(text, work):
    """`text` with the paths into the sandbox's workspace as the student
    knows them: a source by its path in their src, what the build made by
    its path in their workspace (devel/lib/...); unchanged without `work`."""
    if not work:
        return text
    return text.replace(sources(work), '').replace(os.path.join(work, 'ws', ''), '')


def waits_for_calls(graph):
    """The package's nodes that offer services of their own, in words."""
    return '; '.join(f'{node} waits for a call of {", ".join(services)}'
                     for node, services in sorted(graph['offered'].items())) + \
        ': the package draws only when it is called, not on P'


def last_error(*texts):
    """The last line that reads as an error (a Python exception's, or roslaunch's)."""
    lines = [line.strip() for text in texts for line in text.splitlines()
             if ERROR_LINE.match(line)]
    return lines[-1] if lines else ''


def node_logs(work, node=''):
    """The text of the log files of every node (or of `node`) in the sandbox's
    home, if that lies in the work folder (its folders could be links): at
    most LOGS_READ files, LOG_DEPTH folders down (roslaunch writes log/RUN/NODE.log)."""
    texts, top = [], os.path.join(work, 'home', '.ros', 'log')
    if not os.path.realpath(top).startswith(os.path.realpath(work) + os.sep):
        return ''
    for path in _log_files(top):
        name = os.path.basename(path)
        if not name.startswith(('master', 'roslaunch', 'rosout')) and name.startswith(node):
            texts.append(_tail(path))
            if len(texts) == LOGS_READ:
                break
    return '\n'.join(texts)


def _log_files(top):
    """The .log files under `top`, no link followed, sorted, LOG_DEPTH folders down at most."""
    found, folders = [], [(top, 0)]
    while folders:
        folder, depth = folders.pop()
        try:
            entries = sorted(os.scandir(folder), key=lambda e: e.name)[:LOG_ENTRIES]
        except OSError:
            continue
        for entry in entries:
            if entry.is_dir(follow_symlinks=False) and depth < LOG_DEPTH:
                folders.append((entry.path, depth + 1))
            elif entry.name.endswith('.log') and entry.is_file(follow_symlinks=False):
                found.append(entry.path)
    return sorted(found)


def _tail(path):
    """The end of a plain file; nothing from a link, a pipe or a device."""
    return (read_plain(path, LOG_TAIL, from_end=True) or b'').decode('utf-8', 'replace')


def first_death(output, work):
    """'NODE died: its last error line (where in the package)', for the
    first node roslaunch saw die (the line from its log, else from its
    traceback in the terminal, traceback_of, else from the terminal before
    it died); with no error line, the line printed just before it died
    (last_said); or ''."""
    died = re.search(r'^\[(\S+?)(-\d+)?\] process has died(.*)$', output, re.MULTILINE)
    if not died:
        return ''
    node, before = died.group(1), output[:died.start()]
    program = re.search(r'\bcmd (\S+)', died.group(3))
    own = traceback_of(before, program.group(1)) if program else ''
    for text in (node_logs(work, node), own, before):
        why = last_error(text)
        if why:
            return f'{node} died: {why}{in_package(text, work)}{_other_world(why)}'
    said = theirs(last_said(output[:died.start()]), work)   # a usage line names its script
    return f'{node} died' + (f' just after this line was printed: {said}' if said else '')


def traceback_of(output, program):
    """The traceback in roslaunch's terminal `output` that names the file
    `program`, to its error line, or '': nodes that die together print
    theirs one after another, and the last error line before a death may
    be another node's (a real class's three Python 2 scripts)."""
    lines, start = output.splitlines(), None
    for i, line in enumerate(lines):
        frame = FRAME_LINE.match(line)
        if start is None and frame and frame.group(1) == program:
            start = i
        elif start is not None and ERROR_LINE.match(line):
            return '\n'.join(lines[start:i + 1])
    return ''


def _other_world(why):
    """'; what to do', where an error line `why` comes of Python 2 or ROS 2 code."""
    return ''.join(f'; {hint}' for line, hint in OTHER_WORLD if line.search(why))


def last_said(output):
    """The last line of roslaunch's terminal `output`, unless roslaunch
    printed it: a node that exits on its own often says why last (a real
    package's talker wanting its arguments: 'Please enter position...')."""
    lines = [line.strip() for line in output.splitlines() if line.strip()]
    last = lines[-1] if lines else ''
    if not last or last.startswith(ROSLAUNCH_LINES):
        return ''
    return last if len(last) <= SAID_CHARS else last[:SAID_CHARS] + '...'


def in_package(text, work):
    """' (PATH, line N)': the last line of the student's own code that the
    traceback ending `text`'s last error line names, PATH as in their
    workspace's src; '' where it names none (a Python 2 print is a
    SyntaxError at its line, which a student finds so). Where that line
    reads sys.argv and the error is an IndexError or a ValueError, what it
    wanted too (a real class's H passed float(sys.argv[1]) on: roslaunch
    gives a node `__name:=` there)."""
    frame = _own_frame(text, work)
    if frame is None:
        return ''
    path, number, code = frame
    wanted = ': it reads command-line arguments (sys.argv), and a node started as rosrun ' \
             'or roslaunch starts it has none but theirs (__name:=, __log:=)' \
        if 'sys.argv' in code and last_error(text).startswith(ARGUMENT_ERRORS) else ''
    return f' ({path}, line {number}){wanted}'


def _own_frame(text, work):
    """(PATH, N, its code) of the last line of the student's own code that
    the traceback ending `text`'s last error line names, or None."""
    lines = text.splitlines()
    errors = [i for i, line in enumerate(lines) if ERROR_LINE.match(line)]
    if not errors:
        return None
    start = errors[-2] + 1 if len(errors) > 1 else 0
    inside = sources(work)
    frames = [(i, m.groups()) for i, m in enumerate(map(FRAME_LINE.match, lines))
              if start <= i < errors[-1] and m and m.group(1).startswith(inside)]
    if not frames:
        return None
    i, (path, number) = frames[-1]
    code = lines[i + 1].strip() if i + 1 < errors[-1] else ''
    return path[len(inside):], number, code


def talker_failure(output, work, talked=True, said=None):
    """Why the talker said nothing: where a node of the run `said` other
    words on /chatter ((node, words), never "P": a real package's copy of
    ROS's tutorial talker, its "hello world"), that, and any death; else the
    first node to die and its error line; else, where no node `talked`
    (published on /chatter), that none did (a real class's scripts had the
    last error line anywhere, a rosservice call's, named as the talker's);
    else that error line."""
    death = first_death(output, work)
    if said:
        words = said[1][:OTHER_WORDS].rstrip()
        return '; '.join(filter(None, [f'{said[0]} published {words!r} there, never "P"', death]))
    return death or (last_error(output, node_logs(work)) if talked else NO_TALKER)


def why_still(output, work, listeners, offered=None, events=(), waiting=''):
    """Why the turtle never moved after the trigger: a node that died after
    it, else commands published where no turtle hears them (`events`: the
    watcher's), else the last error line of the nodes that listen on
    /chatter, else a script's `rostopic pub` that never exits (`waiting`:
    submission.waiting_publishers), else the services the package's nodes
    offer (`offered`: {node: [service]}): a package that draws only when
    its own service is called."""
    found = first_death(output, work) or unheard_said(events) or last_error(
        output, *[node_logs(work, name.rsplit('/', 1)[-1]) for name in listeners]) or waiting
    if found or not offered:
        return found
    return waits_for_calls(dict(offered=offered))

