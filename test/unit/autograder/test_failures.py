"""Why a step failed, in one line, from what roslaunch's terminal showed
and from the nodes' log files."""
import os

from turtle_letters.autograder.failures import talker_failure, why_not_launched, why_still

# roslaunch's terminal as the lab's talker dies under Python 3
DIED = '''process[sim-2]: started with pid [34]
process[talker-3]: started with pid [35]
process[turtlebot_controller-4]: started with pid [40]
Traceback (most recent call last):
  File "/tmp/w/ws/src/turtlebot_lab/scripts/talker.py", line 9, in talker
    letter = raw_input("Enter the letter: ")
NameError: name 'raw_input' is not defined
[talker-3] process has died [pid 35, exit code 1, cmd /tmp/w/ws/src/turtlebot_lab/scripts/talker.py].
log file: /tmp/w/home/.ros/log/x/talker-3*.log
[turtlebot_controller-4] process has died [pid 40, exit code 1].
ZeroDivisionError: division by zero
'''


def test_the_first_node_to_die_and_its_last_error_line(tmp_path):
    assert talker_failure(DIED, str(tmp_path)) == "talker died: NameError: name 'raw_input' is not defined"


def test_its_own_log_file_first(tmp_path):
    logs = tmp_path / 'home' / '.ros' / 'log' / 'run'
    logs.mkdir(parents=True)
    (logs / 'talker-3-stdout.log').write_text('Traceback:\nEOFError: EOF when reading a line\n')
    (logs / 'sim-2.log').write_text('RuntimeError: not the talker\n')
    os.mkfifo(str(logs / 'talker-3-trap.log'))          # never opened: it would block
    assert talker_failure(DIED, str(tmp_path)) == 'talker died: EOFError: EOF when reading a line'


def test_where_no_node_published_on_chatter_that_is_why_not_another_error(tmp_path):
    """A real class's package had no talker, and the row named a rosservice
    call's error, the last error line anywhere, as the talker's. Where the
    graph saw no node publish on /chatter, that is why; a death still is."""
    called = "ERROR: service [/kill] responded with an error: b'no turtle named [turtle2]'\n"
    assert talker_failure(called, str(tmp_path)) == called.strip()
    assert talker_failure(called, str(tmp_path), talked=False) == (
        'no node of the run published on /chatter (a talker publishes "P" there when P is '
        'typed)')
    assert talker_failure(DIED, str(tmp_path), talked=False) == \
        "talker died: NameError: name 'raw_input' is not defined"


def test_no_death_the_last_error_anywhere_or_nothing(tmp_path):
    assert talker_failure('ValueError: bad\nall fine\n', str(tmp_path)) == 'ValueError: bad'
    assert talker_failure('all fine\n', str(tmp_path)) == ''


def test_why_the_lab_did_not_come_up():
    refused = 'ERROR: cannot launch node of type [p/controler.py]: Cannot locate node\n'
    graph = dict(kind='graph', t=0, simulator=['/sim'], chatter_subscribers=[])
    assert why_not_launched(refused, [], '').startswith('cannot launch node of type [p/controler.py]')
    assert why_not_launched('', [], '') == "the grader's watcher saw no ROS graph"
    assert 'no node subscribed to /chatter' in why_not_launched('', [graph], '')
    assert why_not_launched(DIED, [graph], '') == \
        "talker died: NameError: name 'raw_input' is not defined"
    # roslaunch ends on a launch-prefix this machine lacks: its words, and what it ran
    lacking = ("RLException: Roslaunch got a 'No such file or directory' error while "
               "attempting to run:\n\ngdb -ex run --args /w/ws/src/p/draw.py __name:=draw "
               "__log:=/w/home/.ros/log/1/draw-1.log\n"
               "The traceback for the exception was written to the log file\n")
    assert why_not_launched(lacking, [graph], '/w') == (
        "roslaunch: Roslaunch got a 'No such file or directory' error while attempting to "
        "run: gdb -ex run --args p/draw.py")


def test_a_launch_file_roslaunch_names_is_named_as_the_student_knows_it():
    """A launch file that wants an argument no one gives: roslaunch names
    it by its path in the sandbox; the row, by its path in the package."""
    unset = ('RLException: [/w/ws/src/lab1/launch/start.launch] requires the \'letter\' arg '
             'to be set\nThe traceback for the exception was written to the log file\n')
    graph = dict(kind='graph', t=0, simulator=['/sim'], chatter_subscribers=[])
    assert why_not_launched(unset, [graph], '/w') == (
        "roslaunch: [lab1/launch/start.launch] requires the 'letter' arg to be set")


def test_why_the_turtle_never_moved(tmp_path):
    logs = tmp_path / 'home' / '.ros' / 'log' / 'run'
    logs.mkdir(parents=True)
    (logs / 'k_drawer-4.log').write_text('[rospy] bad callback\nTypeError: unsupported operand\n')
    assert why_still('', str(tmp_path), ['/k_drawer']) == 'TypeError: unsupported operand'
    died = '[k_drawer-4] process has died [pid 9, exit code 1].\n'
    assert why_still('KeyError: 3\n' + died, str(tmp_path), []) == \
        'k_drawer died: TypeError: unsupported operand'


def test_of_a_flood_of_log_files_only_some_are_read_and_none_deeper_than_roslaunch_writes(
        tmp_path):
    """A node may write any number of log files, in folders nested at will:
    the grader reads LOGS_READ at most, LOG_DEPTH folders down."""
    from turtle_letters.autograder import failures
    logs = tmp_path / 'home' / '.ros' / 'log' / 'run'
    logs.mkdir(parents=True)
    for n in range(500):
        (logs / f'spam-{n:03}.log').write_text(f'RuntimeError: log {n:03}\n')
    deep = logs / 'a' / 'b'
    deep.mkdir(parents=True)
    (deep / 'hidden.log').write_text('RuntimeError: too deep\n')
    read = failures.node_logs(str(tmp_path))
    assert read.count('RuntimeError') == failures.LOGS_READ
    assert 'too deep' not in read


def test_a_package_that_draws_only_on_its_own_service_call_says_so(tmp_path):
    said = why_still('', str(tmp_path), ['/listener'], {'/writer': ['/turtle_write']})
    assert said == ('/writer waits for a call of /turtle_write: the package draws only when it '
                    'is called, not on P')


def test_a_lab_that_never_came_up_but_offers_a_service_says_so(tmp_path):
    graph = dict(kind='graph', t=1.0, chatter_subscribers=[], offered={'/server': ['/draw']})
    assert why_not_launched('', [graph], str(tmp_path)) == (
        'no node subscribed to /chatter, and no turtle moved: /server waits for a call of '
        '/draw: the package draws only when it is called, not on P')


def test_a_client_that_died_wanting_arguments_beside_a_server_waiting_says_both(tmp_path):
    """A real class's package without a launch file: its client prints its
    usage and exits, its server waits for a call of its own service. The
    row says both, and the usage line names the script as the student's
    workspace holds it, not the sandbox's path."""
    work = str(tmp_path)
    usage = (f'process[client0-1]: started with pid [21]\n'
             f'{work}/ws/devel/lib/letters/draw_letter_client.py [x y]\n'
             f'[client0-1] process has died [pid 21, exit code 1].\n')
    graph = dict(kind='graph', t=1.0, chatter_subscribers=[],
                 offered={'/server': ['/draw_letter']})
    assert why_not_launched(usage, [graph], work) == (
        'client0 died just after this line was printed: devel/lib/letters/draw_letter_client.py '
        '[x y]; /server waits for a call of /draw_letter: the package draws only when it is '
        'called, not on P')
    graph['offered'] = {}
    assert why_not_launched(usage, [graph], work) == (
        'client0 died just after this line was printed: devel/lib/letters/draw_letter_client.py '
        '[x y]')


def test_a_death_says_where_in_the_package_its_error_was_raised(tmp_path):
    """The last frame of the student's own code in the traceback, as a
    path in their workspace: a runtime error's, and a Python 2 print's
    SyntaxError (no frame of the grader's or of rospy's is named)."""
    work = str(tmp_path)
    runtime = DIED.replace('/tmp/w/', work + '/').replace(
        'NameError', '  File "/usr/lib/python3/dist-packages/rospy/x.py", line 3, in f\nNameError')
    assert talker_failure(runtime, work) == ("talker died: NameError: name 'raw_input' is not "
                                             "defined (turtlebot_lab/scripts/talker.py, line 9)")
    python2 = (f'  File "{work}/ws/src/VS/src/initials.py", line 20\n    print "x"\n    ^\n'
               "SyntaxError: Missing parentheses in call to 'print'. Did you mean print(...)?\n"
               '[sagar_initial-2] process has died [pid 23, exit code 1].\n')
    assert talker_failure(python2, work) == (
        "sagar_initial died: SyntaxError: Missing parentheses in call to 'print'. Did you mean "
        "print(...)? (VS/src/initials.py, line 20); that is Python 2's print, and ROS Noetic "
        "runs Python 3: call print(...)")
    caught = python2.replace('print "x"', 'except rospy.ServiceException, e:').replace(
        "Missing parentheses in call to 'print'. Did you mean print(...)?",
        'multiple exception types must be parenthesized')
    assert talker_failure(caught, work) == (
        'sagar_initial died: SyntaxError: multiple exception types must be parenthesized '
        "(VS/src/initials.py, line 20); that is Python 2's `except Error, e`, and ROS Noetic "
        'runs Python 3: write `except Error as e`')


def test_a_script_that_wants_its_arguments_says_so(tmp_path):
    """A real class's H: its script passes float(sys.argv[1]) and [2] on.
    Started by roslaunch, its first argument is roslaunch's own __name:=,
    and it died of a ValueError; with none (rosrun) of an IndexError. The
    row says it wants arguments; another IndexError says only where."""
    work = str(tmp_path)
    died = (f'Traceback (most recent call last):\n'
            f'  File "{work}/ws/src/h_lab/scripts/draw_h.py", line 151, in <module>\n'
            f'    move_turtle(float(sys.argv[1]),float(sys.argv[2]))\n'
            f"ValueError: could not convert string to float: '__name:=draw_h0'\n"
            f'[draw_h0-1] process has died [pid 20, exit code 1].\n')
    wants = ('(h_lab/scripts/draw_h.py, line 151): it reads command-line arguments (sys.argv), '
             'and a node started as rosrun or roslaunch starts it has none but theirs '
             '(__name:=, __log:=)')
    assert talker_failure(died, work) == ("draw_h0 died: ValueError: could not convert string "
                                          f"to float: '__name:=draw_h0' {wants}")
    none = died.replace("ValueError: could not convert string to float: '__name:=draw_h0'",
                        'IndexError: list index out of range')
    assert talker_failure(none, work) == \
        f'draw_h0 died: IndexError: list index out of range {wants}'
    other = none.replace('float(sys.argv[1]),float(sys.argv[2])', 'corners[4]')
    assert talker_failure(other, work) == ('draw_h0 died: IndexError: list index out of '
                                           'range (h_lab/scripts/draw_h.py, line 151)')


def test_a_death_with_no_error_line_says_the_line_printed_just_before_it(tmp_path):
    """A real package's talker wants arguments, says so and exits 1: the
    row quotes that line; a line roslaunch printed itself is no reason."""
    asked = ('process[talker-1]: started with pid [21]\n'
             'Please enter position [x, y, angle], letter and colour...\n'
             '[talker-1] process has died [pid 21, exit code 1, cmd /w/talker.py].\n')
    assert talker_failure(asked, str(tmp_path)) == (
        'talker died just after this line was printed: Please enter position [x, y, angle], '
        'letter and colour...')
    silent = asked.replace('Please enter position [x, y, angle], letter and colour...\n', '')
    assert talker_failure(silent, str(tmp_path)) == 'talker died'


def test_a_script_whose_bang_names_a_program_the_machine_lacks_says_so(tmp_path):
    """`#!/usr/bin/env python2`: env's own line, printed before roslaunch
    says the process started, is why it died."""
    output = ('/usr/bin/env: \u2018python2\u2019: No such file or directory\n'
              'process[s0-1]: started with pid [21]\n'
              '[s0-1] process has died [pid 21, exit code 127, cmd /w/s.py].\n')
    assert talker_failure(output, str(tmp_path)) == \
        's0 died: /usr/bin/env: \u2018python2\u2019: No such file or directory; ' \
        'ROS Noetic runs Python 3: name python3 in its #! line'


def test_commands_no_turtle_hears_are_why_nothing_moved(tmp_path):
    """A real class's node published its T on /cmd_vel, a turtlebot's
    topic, and exited: the lab never came up, and the row said to check
    the launch file (the grader's own, the package having none)."""
    graph = dict(kind='graph', t=0, simulator=[], chatter_subscribers=[],
                 unheard={'/cmd_vel': ['/my_initials_1']})
    said = ("/my_initials_1 published on /cmd_vel, which no turtle hears (turtlesim's turtle1 "
            "hears /turtle1/cmd_vel)")
    assert why_not_launched('', [graph], str(tmp_path)) == \
        f'no node subscribed to /chatter, and no turtle moved: {said}'
    assert why_still('', str(tmp_path), ['/l'], None, [graph]) == said


def test_a_node_that_imports_ros_2_is_told_what_to_do(tmp_path):
    """Noetic has no rclpy: the bare error line reads as if a module were
    missing to install."""
    ros2 = ("ModuleNotFoundError: No module named 'rclpy'\n"
            '[writer-2] process has died [pid 35, exit code 1].\n')
    assert talker_failure(ros2, str(tmp_path)) == (
        "writer died: ModuleNotFoundError: No module named 'rclpy'; that is ROS 2, and this lab "
        'is ROS 1 (Noetic): write it with rospy')


def test_a_script_stopped_at_a_rostopic_pub_that_waits_says_where_and_what_to_type(tmp_path):
    waiting = ('scripts/draw.sh line 1: rostopic pub without -1 publishes once and waits to '
               'be stopped (Ctrl-C), so no line after it ran; -1 publishes once and exits')
    assert why_still('', str(tmp_path), [], {'/writer': ['/turtle_write']}, [], waiting) == \
        waiting


def test_nodes_that_die_together_each_get_their_own_traceback(tmp_path):
    """A real class's three Python 2 scripts, started together: each
    traceback is printed before roslaunch says any died, so the last error
    line before the first death was the third script's. The first to die
    is named with its own error, and what Python 3 wants instead."""
    work = str(tmp_path)
    src = f'{work}/ws/src/m_lab/src'
    output = (f'  File "{src}/turn.py", line 30\n    print "turning"\n    ^^^^^\n'
              "SyntaxError: Missing parentheses in call to 'print'. Did you mean print(...)?\n"
              f'  File "{src}/draw_m.py", line 12\n    turn(40, 90)\n'
              'TabError: inconsistent use of tabs and spaces in indentation\n'
              f'[turn0-1] process has died [pid 21, exit code 1, cmd {src}/turn.py '
              f'__name:=turn0 __log:={work}/home/.ros/log/1/turn0-1.log].\n'
              f'[draw_m1-2] process has died [pid 22, exit code 1, cmd {src}/draw_m.py '
              f'__name:=draw_m1].\n')
    assert talker_failure(output, work) == (
        "turn0 died: SyntaxError: Missing parentheses in call to 'print'. Did you mean "
        "print(...)? (m_lab/src/turn.py, line 30); that is Python 2's print, and ROS Noetic "
        "runs Python 3: call print(...)")
    turn, draw = (line + '\n' for line in output.splitlines()[-2:])
    draw_first = output.replace(turn + draw, draw + turn)
    assert talker_failure(draw_first, work) == (
        'draw_m1 died: TabError: inconsistent use of tabs and spaces in indentation '
        '(m_lab/src/draw_m.py, line 12); Python 2 took tabs and spaces mixed, and ROS Noetic '
        'runs Python 3: indent with spaces only')


def test_a_talker_of_other_words_is_why_no_p_came_before_any_death(tmp_path):
    """A real package handed in ROS's tutorial talker beside its letter's
    script: it published "hello world ..." on /chatter, never "P", and the
    row named an unrelated node's death (a Python 2 client) as the
    talker's. The words come first; a death is still said after them."""
    said = ('/talker_12_34', 'hello world 1796590302.46876 and a long tail of words')
    assert talker_failure(DIED, str(tmp_path), said=said) == (
        "/talker_12_34 published 'hello world 1796590302.46876 and a long' there, never \"P\"; "
        "talker died: NameError: name 'raw_input' is not defined")
    assert talker_failure('all fine\n', str(tmp_path), said=said).endswith('never "P"')
