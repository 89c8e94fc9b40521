"""Finding a cadet's package in their folder, and the launch file the lab runs."""
import os

from turtle_letters.autograder import submission
from support.grading import nest
from turtle_letters.isolation.files import remove_tree
from turtle_letters.autograder.submission import copy, find
from turtle_letters.autograder.session import passed_over

PACKAGE = '<package format="2"><name>{}</name></package>'
LAB = ('<launch><node pkg="turtlesim" type="turtlesim_node" name="sim"/>'
       '<node pkg="my_lab" type="controller.py" name="c"/></launch>')


def make(root, files):
    for path, text in files.items():
        full = os.path.join(root, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        with open(full, 'w') as f:
            f.write(text)


def test_the_package_at_any_depth_and_the_launch_file_with_turtlesim_and_a_controller(tmp_path):
    make(tmp_path, {'zip/catkin_ws/src/my_lab/package.xml': PACKAGE.format('my_lab'),
                    'zip/catkin_ws/src/my_lab/launch/a_sim.launch':
                        '<launch><node pkg="turtlesim" type="turtlesim_node" name="s"/></launch>',
                    'zip/catkin_ws/src/my_lab/launch/lab.launch': LAB,
                    'zip/catkin_ws/src/my_lab/launch/broken.launch': '<launch><node',
                    'zip/catkin_ws/build/other/package.xml': PACKAGE.format('other')})
    package = find(str(tmp_path))
    assert package.name == 'my_lab' and package.problem == ''
    assert package.folder.endswith('src/my_lab') and package.launch == 'launch/lab.launch'


def test_the_launch_file_is_chosen_by_its_whole_tree_of_includes_and_groups(tmp_path):
    sim = '<launch><group ns="x"><node pkg="turtlesim" type="turtlesim_node" name="s"/></group>' \
          '</launch>'
    make(tmp_path, {'ws/a_lab/package.xml': PACKAGE.format('a_lab'),
                    'ws/a_lab/launch/a_controller.launch':
                        '<launch><node pkg="a_lab" type="c.py" name="c"/></launch>',
                    'ws/a_lab/launch/lab.launch':
                        '<launch><include file="$(find common)/launch/sim.launch"/>'
                        '<include file="$(dirname)/a_controller.launch"/></launch>',
                    'ws/a_lab/launch/outside.launch':
                        '<launch><include file="/etc/x.launch"/><node pkg="a_lab" type="c.py"/>'
                        '<include file="$(eval 1)"/></launch>',
                    'ws/common/package.xml': PACKAGE.format('common'),
                    'ws/common/launch/sim.launch': sim})
    os.symlink('lab.launch', str(tmp_path / 'ws/a_lab/launch/loop.launch'))
    make(tmp_path, {'ws/a_lab/launch/self.launch': '<launch><include file="$(dirname)/self.'
                                                   'launch"/></launch>'})
    package = find(str(tmp_path))
    assert (package.name, package.launch) == ('a_lab', 'launch/lab.launch')
    lab = str(tmp_path / 'ws/a_lab')
    assert submission.nodes(lab + '/launch/self.launch', {'a_lab': lab}) == []    # ends


def test_a_bag_replayed_or_a_graph_drawn_is_no_controller(tmp_path):
    """A real class's package: a launch file that starts turtlesim and its
    teleop, and one that replays a bag and draws rqt_graph. Neither starts a
    node of the package: the one with turtlesim is the lab's, and starts none
    of its own (its cadets run their script by hand)."""
    sim = ('<launch><node pkg="turtlesim" type="turtlesim_node" name="s"/>'
           '<node pkg="turtlesim" type="turtle_teleop_key" name="t"/></launch>')
    bag = ('<launch><node pkg="turtlesim" type="turtlesim_node" name="s"/>'
           '<node pkg="rosbag" type="play" name="p"/><node pkg="rqt_graph" type="rqt_graph" '
           'name="g"/></launch>')
    make(tmp_path, {'hw/package.xml': PACKAGE.format('hw'), 'hw/launch/turtle.launch': sim,
                    'hw/launch/turtle_remap.launch': bag,
                    'hw/scripts/letters.sh': 'rosservice call /clear\n'})
    package = find(str(tmp_path))
    assert package.launch == 'launch/turtle.launch'
    assert submission.started_packages(package) == (['turtlesim'], False)
    assert submission.bare_shell(package.folder) == ['letters.sh']
    own = '<node pkg="hw" type="letters.sh" name="l"/></launch>'
    make(tmp_path, {'hw/launch/turtle.launch': sim.replace('</launch>', own),
                    'hw/scripts/letters.sh': '#!/bin/bash\nrosservice call /clear\n'})
    assert submission.started_packages(find(str(tmp_path))) == (['hw', 'turtlesim'], True)
    assert submission.bare_shell(package.folder) == []


def test_a_launch_file_of_no_node_of_its_own_is_passed_over_in_plain_words(tmp_path):
    """A real class's launch file that only includes Gazebo's empty world:
    it starts no node the grader can see, and the row said it started
    "nodes of no package only"."""
    world = ('<launch><include file="$(find gazebo_ros)/launch/empty_world.launch">'
             '<arg name="world_name" value="$(find hw)/worlds/happy.world"/></include></launch>')
    make(tmp_path, {'hw/package.xml': PACKAGE.format('hw'), 'hw/launch/happy.launch': world,
                    'hw/scripts/letters.sh': 'rosservice call /clear\n'})
    package = find(str(tmp_path))
    started, _ = submission.started_packages(package)
    assert passed_over(package.launch, started, package.name) == \
        'launch/happy.launch starts no node of hw'
    assert passed_over('launch/turtle.launch', ['turtlesim'], 'hw') == \
        'launch/turtle.launch starts nodes of turtlesim only, none of hw'


def test_several_scripts_started_together_are_told_from_the_files_handed_in(tmp_path):
    """The rows a class grades first (cli.grading_order): the grader will
    start several scripts together, here a course's two shell scripts,
    handed in without the execute bit, beside a launch file of turtlesim
    alone; not one script, nor a launch file that starts its own node."""
    sim = '<launch><node pkg="turtlesim" type="turtlesim_node" name="s"/></launch>'
    make(tmp_path, {'two/package.xml': PACKAGE.format('two'), 'two/launch/t.launch': sim,
                    'two/scripts/first.sh': 'rosservice call /clear\n',
                    'two/scripts/second.sh': 'rosservice call /clear\n'})
    make(tmp_path, {'one/package.xml': PACKAGE.format('one'), 'one/launch/t.launch': sim,
                    'one/scripts/only.sh': 'rosservice call /clear\n'})
    make(tmp_path, {'my_lab/package.xml': PACKAGE.format('my_lab'),
                    'my_lab/launch/lab.launch': LAB,
                    'my_lab/scripts/controller.py': '#!/usr/bin/env python3\n',
                    'my_lab/scripts/talker.py': '#!/usr/bin/env python3\n'})
    node = 'import rospy\nimport shapes\nrospy.init_node("n")\n'
    make(tmp_path, {'bare/package.xml': PACKAGE.format('bare'), 'bare/src/draw.py': node,
                    'bare/src/shapes.py': 'import rospy\n'})
    told = {name: submission.started_together(find(str(tmp_path / name)))
            for name in ('two', 'one', 'my_lab', 'bare')}
    assert told == {'two': True, 'one': False, 'my_lab': False, 'bare': False}
    make(tmp_path, {'bare/src/write.py': node})     # a second node: no launch file starts either
    assert submission.started_together(find(str(tmp_path / 'bare')))


def test_no_package_no_name_no_launch_file(tmp_path):
    assert find(str(tmp_path)).problem == f'no package.xml in {tmp_path}'
    make(tmp_path, {'a/package.xml': '<package format="2"></package>'})
    assert 'names no package' in find(str(tmp_path)).problem
    make(tmp_path, {'a/package.xml': PACKAGE.format('a')})
    package = find(str(tmp_path))      # graded all the same: the grader starts its executables
    assert (package.problem, package.launch) == ('', None)


def test_scripts_handed_in_without_a_package_xml_are_wrapped_in_a_package_of_the_graders(
        tmp_path):
    """A real class's folder of a shell script, its launch file and no
    package.xml or CMakeLists.txt: a TA runs the script. The grader wraps
    its copy in a package of its own (named LOOSE) that catkin builds;
    the folder handed in is left as it was. Notes and no script: nothing
    to run, and the row says there is no package.xml."""
    make(tmp_path, {'notes/README.md': 'my letters'})
    assert find(str(tmp_path / 'notes')).problem == f'no package.xml in {tmp_path / "notes"}'
    make(tmp_path, {'hw/scripts/letters.sh': 'rosservice call /clear\n',
                    'hw/launch/turtle.launch':
                        '<launch><node pkg="turtlesim" type="turtlesim_node" name="s"/></launch>'})
    package = find(str(tmp_path / 'hw'))
    assert (package.name, package.problem, bool(package.loose)) == (submission.LOOSE, '', True)
    assert package.launch == 'launch/turtle.launch'
    copied = copy(package, str(tmp_path / 'ws'))
    submission.wrap(copied)
    assert submission.package_name(copied) == submission.LOOSE
    assert 'project(handed_in)' in open(os.path.join(copied, 'CMakeLists.txt')).read()
    assert sorted(os.listdir(tmp_path / 'hw')) == ['launch', 'scripts']


def test_wrapping_loose_scripts_follows_no_link_they_hold(tmp_path):
    """A hostile folder of loose scripts whose CMakeLists.txt is a link to
    a file of the instructor's, and whose package.xml is a folder: the
    grader writes its own in the copy, before the sandbox starts, and the
    file linked to is left as it was."""
    make(tmp_path, {'secret': 'the instructor\'s', 'hw/draw.sh': 'rostopic list\n',
                    'hw/package.xml/inside': 'x'})
    os.symlink(str(tmp_path / 'secret'), str(tmp_path / 'hw' / 'CMakeLists.txt'))
    copied = copy(find(str(tmp_path / 'hw')), str(tmp_path / 'ws'))
    submission.wrap(copied)
    assert open(tmp_path / 'secret').read() == 'the instructor\'s'
    written = os.path.join(copied, 'CMakeLists.txt')
    assert not os.path.islink(written) and 'project(handed_in)' in open(written).read()
    assert submission.package_name(copied) == submission.LOOSE


def test_the_copy_keeps_links_as_links_and_leaves_builds_behind(tmp_path):
    make(tmp_path, {'sub/p/package.xml': PACKAGE.format('p'), 'sub/p/launch/x.launch': LAB,
                    'sub/p/build/junk': 'x', 'secret': 'the instructor\'s'})
    os.symlink(str(tmp_path / 'secret'), str(tmp_path / 'sub' / 'p' / 'link'))
    target = copy(find(str(tmp_path / 'sub')), str(tmp_path / 'ws'))
    assert os.path.islink(os.path.join(target, 'link'))
    assert not os.path.exists(os.path.join(target, 'build'))
    assert os.path.exists(os.path.join(target, 'launch', 'x.launch'))


def test_of_several_packages_the_lab_and_those_it_needs_are_built(tmp_path):
    """Its messages (a dependency of a dependency) and a package its launch
    file starts a node of are built beside it; an unrelated sibling (a
    Gazebo package that does not build here) is left out, in words."""
    lab = ('<launch><node pkg="turtlesim" type="turtlesim_node" name="sim"/>'
           '<node pkg="b_talker" type="talker.py" name="t"/></launch>')
    make(tmp_path, {'src/a_msgs/package.xml': PACKAGE.format('a_msgs'),
                    'src/a_common/package.xml':
                        '<package format="2"><name>a_common</name><depend>a_msgs</depend></package>',
                    'src/b_talker/package.xml': PACKAGE.format('b_talker'),
                    'src/c_gazebo/package.xml': PACKAGE.format('c_gazebo'),
                    'src/c_gazebo/CMakeLists.txt': 'find_package(gazebo REQUIRED)',
                    'src/my_lab/package.xml': '<package format="2"><name>my_lab</name>'
                                              '<build_depend>a_common</build_depend></package>',
                    'src/my_lab/launch/lab.launch': lab,
                    'src/my_lab/inner/package.xml': PACKAGE.format('inner')})
    package = find(str(tmp_path))
    assert package.name == 'my_lab'
    assert sorted(os.path.basename(f) for f in package.others) == ['a_common', 'a_msgs', 'b_talker']
    assert package.notes == ['left out src/c_gazebo: c_gazebo, which my_lab neither depends on '
                             'nor launches (not built: its failures cost nothing)']
    copy(package, str(tmp_path / 'ws'))
    assert sorted(os.listdir(tmp_path / 'ws' / 'src')) == ['my_lab', 'other1', 'other2', 'other3']


def test_of_several_packages_one_whose_code_names_turtlesim_is_the_lab(tmp_path):
    """A real repository of a course's projects: a Gazebo package whose
    launch file starts its own node, and the letter's package, with no
    launch file, its script (mode 644) naming turtle1. The letter's is
    graded; the Gazebo one was, its launch file ranked above none."""
    node = '#!/usr/bin/env python\nimport rospy\nrospy.init_node("n")\n'
    make(tmp_path, {'repo/pursuit/package.xml': PACKAGE.format('pursuit'),
                    'repo/pursuit/launch/chase.launch':
                        '<launch><node pkg="pursuit" type="chase.py" name="c"/></launch>',
                    'repo/pursuit/scripts/chase.py': node + 'topic = "/tb3_1/cmd_vel"\n',
                    'repo/nodes/package.xml': PACKAGE.format('turtle_description'),
                    'repo/nodes/my_initials.py': node + 'topic = "/turtle1/cmd_vel"\n'})
    package = find(str(tmp_path / 'repo'))
    assert (package.name, package.launch, package.problem) == ('turtle_description', None, '')
    assert package.notes == ['left out pursuit: pursuit, which turtle_description neither '
                             'depends on nor launches (not built: its failures cost nothing)']


def test_a_tree_too_deep_or_too_large_is_refused_in_words(tmp_path):
    make(tmp_path, {'lab/package.xml': PACKAGE.format('lab'), 'lab/launch/x.launch': LAB})
    nest(tmp_path / 'lab', 1100)        # deeper than Python's own walks can go
    try:
        assert find(str(tmp_path)).problem == \
            f'its folders nest more than {submission.MAX_DEPTH} deep: not graded'
    finally:
        remove_tree(str(tmp_path / 'lab' / 'd'))      # pytest's own clean-up recurses
    wide = tmp_path / 'wide'
    wide.mkdir()
    for i in range(submission.MAX_ENTRIES + 1):
        (wide / str(i)).touch()
    assert 'more than 20000 files and folders' in find(str(wide)).problem


def test_a_fifo_is_left_out_of_the_copy_and_said(tmp_path):
    make(tmp_path, {'lab/package.xml': PACKAGE.format('lab'), 'lab/launch/x.launch': LAB})
    os.mkfifo(str(tmp_path / 'lab' / 'pipe'))
    package = find(str(tmp_path))
    assert package.problem == '' and package.notes == [
        'left out lab/pipe: not a plain file, folder or link (a FIFO, socket or device)']
    target = copy(package, str(tmp_path / 'ws'))      # would block on the FIFO, were it opened
    assert sorted(os.listdir(target)) == ['launch', 'package.xml']


def test_a_second_copy_of_the_package_and_a_turtlesim_of_its_own_are_left_out(tmp_path):
    make(tmp_path, {'src/lab/package.xml': PACKAGE.format('lab'), 'src/lab/launch/x.launch': LAB,
                    'src/lab (copy)/package.xml': PACKAGE.format('lab'),
                    'src/ros_tutorials/turtlesim/package.xml': PACKAGE.format('turtlesim'),
                    'src/ros_tutorials/turtlesim/launch/sim.launch': LAB})
    package = find(str(tmp_path))
    assert (package.name, package.others, package.problem) == ('lab', [], '')
    assert package.notes == [
        'left out src/lab (copy): a second package named lab (graded the one in src/lab)',
        'left out src/ros_tutorials/turtlesim: its own turtlesim (the grader runs turtlesim)']


def test_a_package_named_turtlesim_alone_is_not_run(tmp_path):
    make(tmp_path, {'turtlesim/package.xml': PACKAGE.format('turtlesim'),
                    'turtlesim/launch/x.launch': LAB})
    assert find(str(tmp_path)).problem == ('its only package is named turtlesim, as the '
                                           'simulator is: the grader runs turtlesim itself')


ROS2 = ('<package format="3"><name>{}</name><buildtool_depend>{}</buildtool_depend>'
        '<export><build_type>{}</build_type></export></package>')


def test_a_ros_2_package_alone_is_refused_in_words_a_cadet_can_act_on(tmp_path):
    """A cadet who followed a ROS 2 tutorial hands in an ament package:
    catkin_make would only say the workspace is "non-homogeneous" and
    suggest catkin_make_isolated, which cannot build it on Noetic either."""
    make(tmp_path, {'letter_l/package.xml': ROS2.format('letter_l', 'ament_python',
                                                        'ament_python'),
                    'letter_l/setup.py': ''})
    assert find(str(tmp_path)).problem == (
        'letter_l is a ROS 2 package (its package.xml builds it with ament_python): this lab '
        'is ROS 1 (Noetic), where catkin builds packages and no ROS 2 package builds or runs; '
        'write it as a catkin package, with rospy or roscpp')


def test_a_ros_2_package_beside_the_lab_is_left_out_and_said(tmp_path):
    make(tmp_path, {'src/lab/package.xml': PACKAGE.format('lab'), 'src/lab/launch/x.launch': LAB,
                    'ros2/draw_cpp/package.xml': ROS2.format('draw_cpp', 'ament_cmake',
                                                             'ament_cmake')})
    package = find(str(tmp_path))
    assert (package.name, package.others, package.problem) == ('lab', [], '')
    assert package.notes == ['left out ros2/draw_cpp: draw_cpp, a ROS 2 package (ament_cmake), '
                             'which catkin does not build']


def test_a_package_written_for_both_ros_1_and_ros_2_is_a_catkin_package_on_noetic(tmp_path):
    """A package.xml of format 3 may name catkin where $ROS_VERSION is 1
    and ament where it is 2: catkin builds it on Noetic. (It was refused
    as a ROS 2 package: a scratch cadet's L, 0/100.)"""
    make(tmp_path, {'lab/package.xml': (
        '<package format="3"><name>lab</name>'
        '<buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>'
        '<buildtool_depend condition="$ROS_VERSION == 2">ament_cmake</buildtool_depend>'
        '<export><build_type condition="$ROS_VERSION == 2">ament_cmake</build_type>'
        '<build_type condition="$ROS_VERSION == 1">catkin</build_type></export></package>'),
        'lab/launch/x.launch': LAB})
    assert submission.ros2_build(str(tmp_path / 'lab')) == ''
    package = find(str(tmp_path))
    assert (package.name, package.problem) == ('lab', '')
    make(tmp_path, {'two/package.xml': ROS2.format('two', 'ament_cmake', 'ament_cmake').replace(
        '<buildtool_depend>', '<buildtool_depend condition="$ROS_VERSION == 2">')})
    assert submission.ros2_build(str(tmp_path / 'two')) == 'ament_cmake'


def test_loose_ros_2_scripts_are_refused_in_words_and_a_rospy_one_without_its_line_is_run(
        tmp_path):
    """Scripts handed in without a package.xml: one that imports rclpy (a
    real class's turtlesim_ros2.py, executable, no #! line) is ROS 2 code,
    said so rather than 'no package.xml'; one that imports rospy, a TA
    runs with python3 (submission.unstartable), so it is wrapped."""
    make(tmp_path, {'two/turtlesim_ros2.py': 'import rclpy\nfrom rclpy.node import Node\n',
                    'two/README.md': 'draws a house',
                    'one/draw.py': 'import rospy\nrospy.init_node("d")\n'})
    for script in ('two/turtlesim_ros2.py', 'one/draw.py'):
        os.chmod(tmp_path / script, 0o755)
    assert find(str(tmp_path / 'two')).problem == (
        'turtlesim_ros2.py imports rclpy: it is ROS 2 code, and this lab is ROS 1 (Noetic), '
        'where no ROS 2 node runs; write it with rospy, in a catkin package')
    package = find(str(tmp_path / 'one'))
    assert (package.name, package.problem, bool(package.loose)) == (submission.LOOSE, '', True)


def test_a_rospy_script_handed_in_without_its_line_or_mode_is_run_with_python3(tmp_path):
    """A node written on a machine where it was run as `python3 draw.py`:
    no #! line, mode 644. A TA runs it so; the grader makes it executable
    and starts it with python3. Helper modules are left as they are: one
    that imports no rospy, one that starts no node, and one that another
    file imports (it starts the node in a class the script makes); and
    so is a plain text file."""
    make(tmp_path, {'lab/scripts/draw.py': 'import math\nimport rospy\n'
                                           'from moves import Mover\nrospy.init_node("d")\n',
                    'lab/scripts/moves.py': 'import rospy\nclass Mover:\n'
                                            '    def __init__(self):\n'
                                            '        rospy.init_node("m")\n',
                    'lab/scripts/pens.py': 'import rospy\ndef pen():\n    return 1\n',
                    'lab/scripts/shapes.py': 'import math\nSQUARE = 4\n',
                    'lab/scripts/notes.txt': 'import rospy\n'})
    folder = str(tmp_path / 'lab')
    assert submission.made_executable(folder) == ['scripts/draw.py']
    assert submission.unstartable(folder) == {'draw.py': 'python3'}
    assert submission.scripts(folder) == ['draw.py']


def test_an_executable_script_whose_interpreter_this_machine_lacks_is_run_with_python3(
        tmp_path):
    """A #! line exec can follow names a program this machine has: a real
    class's `#!/usr/bin/python` (absent from Debian 12 and from a Noetic
    machine without python-is-python3) and a Mac's Homebrew python3 name
    none, and such scripts are run with python3; `#!/usr/bin/env python`
    (python is a stand-in in the sandbox) and a folder named by #! are
    told apart from them."""
    make(tmp_path, {'lab/scripts/mac.py': '#!/opt/homebrew/bin/python3\nimport rospy\n',
                    'lab/scripts/env.py': '#!/usr/bin/env python\nimport rospy\n',
                    'lab/scripts/folder.py': '#!/usr/bin\nimport rospy\n'})
    for name in ('mac.py', 'env.py', 'folder.py'):
        os.chmod(tmp_path / 'lab' / 'scripts' / name, 0o755)
    assert submission.unstartable(str(tmp_path / 'lab')) == {'folder.py': 'python3',
                                                             'mac.py': 'python3'}


def test_a_shell_script_whose_line_exec_cannot_follow_is_run_with_bash(tmp_path):
    """A shell script saved on Windows, its #!/bin/bash line ending in a
    carriage return (exec looks for `bash\\r`), and one whose #! names a
    shell this machine lacks, are run with bash, as a TA types `bash
    letters.sh`; a sound one, and one with no #! (bare_shell's: its
    course's instructions say to run it with bash), are not named."""
    make(tmp_path, {'lab/scripts/windows.sh': '#!/bin/bash\r\nrosservice call /clear\r\n',
                    'lab/scripts/draw': '#!/opt/homebrew/bin/bash\nrosservice call /clear\n',
                    'lab/scripts/sound.sh': '#!/bin/bash\nrosservice call /clear\n',
                    'lab/scripts/bare.sh': 'rosservice call /clear\n'})
    for name in ('windows.sh', 'draw', 'sound.sh', 'bare.sh'):
        os.chmod(tmp_path / 'lab' / 'scripts' / name, 0o755)
    assert submission.unstartable(str(tmp_path / 'lab')) == {'draw': 'bash', 'windows.sh': 'bash'}


def test_cpp_sources_no_add_executable_builds_are_named(tmp_path):
    """A C++ node written and never built: catkin_create_pkg's CMakeLists.txt
    keeps its add_executable commented out, and rosrun finds no node. Its
    sources are named; where an add_executable stands, none is."""
    template = ('cmake_minimum_required(VERSION 3.0.2)\nproject(drawer)\n'
                'find_package(catkin REQUIRED COMPONENTS roscpp)\ncatkin_package()\n'
                '# add_executable(${PROJECT_NAME}_node src/drawer_node.cpp)\n')
    make(tmp_path, {'drawer/CMakeLists.txt': template, 'drawer/src/draw.cpp': 'int main() {}\n',
                    'drawer/src/shapes.h': '#pragma once\n'})
    assert submission.sources_built_by_nothing(str(tmp_path / 'drawer')) == ['src/draw.cpp']
    make(tmp_path, {'drawer/CMakeLists.txt': template + 'add_executable(draw src/draw.cpp)\n'})
    assert submission.sources_built_by_nothing(str(tmp_path / 'drawer')) == []


def test_a_rostopic_pub_that_waits_is_found_in_the_scripts_started(tmp_path):
    """waiting_publishers: a shell script's first `rostopic pub` with no -1,
    -r or -f (a latched -l typed for -1) waits to be stopped; a backgrounded
    one, one under timeout, a script not started, a Python file, do not count."""
    scripts = {
        'scripts/draw.sh': "rostopic pub -1 /turtle1/cmd_vel geometry_msgs/Twist -- "
                           "'[1.0, 0, 0]' '[0, 0, 0]'\n"
                           "# rostopic pub /turtle1/cmd_vel geometry_msgs/Twist\n"
                           "rostopic pub -l /turtle1/cmd_vel geometry_msgs/Twist -- "
                           "'[-1.0, 0, 0]' '[0, 0, 0]'\n"
                           "rostopic pub /turtle1/cmd_vel geometry_msgs/Twist -- '[1, 0, 0]'\n",
        'scripts/loop': "#!/bin/bash\nrostopic pub -r 1 /turtle1/cmd_vel geometry_msgs/Twist\n"
                        "rostopic pub --once /chatter std_msgs/String P\n"
                        "rostopic pub /turtle1/cmd_vel geometry_msgs/Twist &\n"
                        "timeout 2 rostopic pub /turtle1/cmd_vel geometry_msgs/Twist\n",
        'scripts/plain': "#!/bin/sh\nrostopic pub -f moves.yaml /turtle1/cmd_vel\n"
                         "rostopic pub -s /chatter std_msgs/String 'data: P'\n",
        'scripts/draw.py': "#!/usr/bin/env python3\n# rostopic pub /chatter std_msgs/String\n",
        'old/unused.sh': "rostopic pub /turtle1/cmd_vel geometry_msgs/Twist\n",
    }
    for path, text in scripts.items():
        (tmp_path / path).parent.mkdir(exist_ok=True)
        (tmp_path / path).write_text(text)
    assert submission.waiting_publishers(str(tmp_path), ['draw.sh', 'loop', 'plain', 'draw.py']) \
        == ('scripts/draw.sh line 3: rostopic pub without -1 publishes once and waits to be '
            'stopped (Ctrl-C), so no line after it ran; -1 publishes once and exits; '
            'scripts/plain line 3: rostopic pub without -1 publishes once and waits to be '
            'stopped (Ctrl-C), so no line after it ran; -1 publishes once and exits')


def test_a_course_repository_whose_package_names_no_turtlesim_is_graded_by_its_script(tmp_path):
    """A course's repository of every project, handed in whole (a real
    one's): the initials script loose at its top, and a package of another
    project (a turtlebot's) that names no turtlesim. A TA grades the
    script: it is wrapped as scripts handed in without a package.xml are,
    and the folders that name no turtlesim are left out of the copy, and
    noted. Where the package names turtlesim, it is the lab, as before."""
    node = '#!/usr/bin/env python3\nimport rospy\nrospy.init_node("n")\n'
    make(tmp_path, {'repo/my_initials.py': node + 'topic = "/turtle1/cmd_vel"\n',
                    'repo/README.md': 'every project',
                    'repo/project_2/task_1.py': node + 'topic = "/cmd_vel"\n',
                    'repo/project_3/nodes/package.xml': PACKAGE.format('turtle_description'),
                    'repo/project_3/nodes/detection.py': node})
    repo = str(tmp_path / 'repo')
    package = find(repo)
    assert (package.name, package.problem, package.left) == \
        (submission.LOOSE, '', ['project_2', 'project_3'])
    assert package.loose == (f'no package of {repo} names turtlesim (project_3/nodes '
                             f'(turtle_description)), and its scripts beside them do: the lab '
                             f'is those scripts, with no package.xml')
    assert package.notes == [f'left out {name}: nothing in it names turtlesim (another project, '
                             f'not the lab)' for name in ('project_2', 'project_3')]
    assert sorted(os.listdir(copy(package, str(tmp_path / 'ws')))) == ['README.md',
                                                                       'my_initials.py']
    make(tmp_path, {'repo/project_3/nodes/package.xml': PACKAGE.format('turtle_description')
                    .replace('</package>', '<depend>turtlesim</depend></package>')})
    assert find(repo).name == 'turtle_description' and find(repo).left == []
