"""A cadet's submission as handed in: the catkin package somewhere inside
their folder (or, scripts handed in without one, a package the grader
wraps them in), its name, and the launch file the lab runs. No ROS here: the
files are read as plain XML, never run (a launch file's $(eval) is Python);
a package.xml's conditions as catkin reads them (catkin_pkg, pure Python).
"""
import os
import re
import shutil
import stat
import xml.etree.ElementTree as ElementTree
from typing import List, NamedTuple, Optional

from catkin_pkg.condition import evaluate_condition

from ..isolation.files import read_plain, remove_tree

SKIPPED = {'.git', 'build', 'devel', 'install', 'logs', '__pycache__'}
MAX_BYTES = 1 << 20      # a package.xml or launch file larger than this is not read
MAX_DEPTH = 40           # folders within folders a submission may nest
MAX_ENTRIES = 20000      # files and folders a submission may hold
MAX_NODES = 20           # executables the grader starts for a package without a launch file
INCLUDE_DEPTH = 8        # launch files within launch files followed
DEPENDS = ('depend', 'build_depend', 'build_export_depend', 'exec_depend', 'run_depend',
           'test_depend')      # package.xml's tags naming a package it needs
SIMULATOR = 'turtlesim'  # a package of this name is the grader's to run, not the submission's
LOOSE = 'handed_in'      # the package the grader wraps scripts handed in without a package.xml in
# What a package.xml's conditions (format 3) are evaluated with on the course's machine
NOETIC = {'ROS_VERSION': '1', 'ROS_PYTHON_VERSION': '3', 'ROS_DISTRO': 'noetic'}


class Package(NamedTuple):
    name: str
    folder: str             # where package.xml is
    launch: Optional[str]   # the launch file, relative to `folder`
    problem: str            # why it cannot be run, or ''
    others: List[str] = []  # the submission's other packages' folders, built beside it
    notes: List[str] = []   # what of the submission was left out, and why
    loose: str = ''         # why its scripts are wrapped in a package (wrap), where they are
    left: List[str] = []    # folders of `folder` not copied (a course's other projects)


def survey(top):
    """(problem, special files) of the tree under `top`, walked without
    recursion or following a link: a problem ('' if none) when it nests
    deeper than MAX_DEPTH or holds more than MAX_ENTRIES (Python's own
    walks fail past about 1,000 levels); its FIFOs, sockets and devices,
    relative to `top`, which no copy may open."""
    stack, count, special = [(top, 0)], 0, []
    while stack:
        folder, depth = stack.pop()
        if depth > MAX_DEPTH:
            return f'its folders nest more than {MAX_DEPTH} deep: not graded', special
        try:
            entries = list(os.scandir(folder))
        except OSError as e:
            return f'{os.path.relpath(folder, top)} cannot be read: {e.strerror}', special
        count += len(entries)
        if count > MAX_ENTRIES:
            return f'it holds more than {MAX_ENTRIES} files and folders: not graded', special
        for entry in entries:
            if entry.is_dir(follow_symlinks=False):
                stack.append((entry.path, depth + 1))
            elif not (entry.is_symlink() or entry.is_file(follow_symlinks=False)):
                special.append(os.path.relpath(entry.path, top))
    return '', sorted(special)


def package_folders(top):
    """Folders under `top` holding a package.xml (not those inside one, as
    catkin looks), shallowest first."""
    found = []
    for folder, folders, files in os.walk(top):
        folders[:] = sorted(f for f in folders if f not in SKIPPED)
        if 'package.xml' in files:
            found.append(folder)
            folders[:] = []
    return sorted(found, key=lambda f: (f.count(os.sep), f))


def _xml(path):
    """A plain file's XML; None for a link, a pipe, a device, a file over
    MAX_BYTES or bad XML (a submission's links could point anywhere)."""
    text = read_plain(path, MAX_BYTES + 1)
    if text is None or len(text) > MAX_BYTES:
        return None
    try:
        return ElementTree.fromstring(text)
    except ElementTree.ParseError:
        return None


def launch_files(folder):
    found = []
    for here, folders, files in os.walk(folder):
        folders[:] = sorted(f for f in folders if f not in SKIPPED)
        found += [os.path.relpath(os.path.join(here, f), folder) for f in files
                  if f.endswith(('.launch', '.launch.xml'))]
    return sorted(found)


def nodes(launch_file, packages, depth=0) -> List[tuple]:
    """(pkg, type) of every <node> a launch file starts: in <group>s, and
    in the files it <include>s from the submission's own packages
    (`packages`: name: folder), to INCLUDE_DEPTH files deep. Read as XML,
    never run: an include's `$(find pkg)` and `$(dirname)` are resolved
    here, and one whose path needs anything else is not followed."""
    root = _xml(launch_file)
    if root is None:
        return []
    found = [(n.get('pkg', ''), n.get('type', '')) for n in root.iter('node')]
    for include in root.iter('include'):
        path = _included(include.get('file', ''), launch_file, packages)
        if path and depth < INCLUDE_DEPTH:
            found += nodes(path, packages, depth + 1)
    return found


def _included(path, launch_file, packages):
    """The file an <include> names, inside one of `packages`, or None."""
    path = path.replace('$(dirname)', os.path.dirname(launch_file))
    found = re.fullmatch(r'\$\(find ([\w-]+)\)(/.*)', path)
    if found:
        if found.group(1) not in packages:
            return None
        path = packages[found.group(1)] + found.group(2)
    if '$(' in path or not os.path.isabs(path):
        return None
    path = os.path.normpath(path)
    inside = any(path.startswith(folder.rstrip('/') + '/') for folder in packages.values())
    return path if inside and os.path.isfile(path) else None


def lab_launch(folder, packages=None, skipped=()):
    """(rank, file): the launch file whose whole tree starts turtlesim and a
    node of the submission's own packages (`packages`: name: folder; the
    cadet's controller), rank 0; else one with turtlesim, or with an own
    node; else the first; (4, None) for none. (rosbag's or rqt_graph's nodes
    are no controller: a real class's launch that replayed a bag from its
    author's home was taken over the one that started turtlesim.) Those in
    the folders of `folder` named in `skipped` are none of them."""
    packages = packages or {package_name(folder): folder}
    ranked = [(4, None)]
    for name in launch_files(folder):
        if name.split(os.sep)[0] in skipped:
            continue
        started = nodes(os.path.join(folder, name), packages)
        has_sim = any(pkg == 'turtlesim' for pkg, _ in started)
        has_own = any(pkg in packages for pkg, _ in started)
        ranked.append((3 - 2 * has_sim - has_own, name))
    return min(ranked, key=lambda r: (r[0], r[1] or ''))


def started_packages(package: 'Package'):
    """(the packages whose nodes the package's launch file starts, sorted;
    whether one is the submission's own): a course's cadets may start only
    turtlesim with roslaunch, and then run their script by hand."""
    folders = [package.folder] + list(package.others)
    packages = {package_name(f): f for f in reversed(folders)}
    started = sorted({pkg for pkg, _ in nodes(os.path.join(package.folder, package.launch),
                                              packages)})
    return started, any(pkg in packages for pkg in started)


def package_name(folder):
    root = _xml(os.path.join(folder, 'package.xml'))
    return root.findtext('name', '').strip() if root is not None else ''


def ros2_build(folder):
    """The ROS 2 build type (ament_python, ament_cmake) a package's
    package.xml builds it with, or '': catkin builds none of them. A tool
    named under a condition false on Noetic (`$ROS_VERSION == 2`, in a
    package written for both ROS 1 and ROS 2) is none of its tools there."""
    root = _xml(os.path.join(folder, 'package.xml'))
    if root is None:
        return ''
    named = [tool.text or '' for tool in root.findall('export/build_type') +
             root.findall('buildtool_depend') if _on_noetic(tool.get('condition'))]
    return next((tool.strip() for tool in named if tool.strip().startswith('ament')), '')


def _on_noetic(condition):
    """Whether a package.xml's `condition` holds on Noetic (catkin_pkg's
    reading of it); one that does not parse counts, as nothing says it does not."""
    try:
        return evaluate_condition(condition, NOETIC)
    except ValueError:
        return True


def find(top) -> Package:
    """The submission's package: of the package.xml under `top`, the
    likeliest (_likeliest: the one whose launch file starts turtlesim and
    a controller, the shallowest first); the other packages it needs are
    built beside it; those it does not need, a second copy of a package, a
    package named turtlesim and a ROS 2 package (ros2_build) are left out
    and noted. Where no package names turtlesim and scripts beside them
    do, the scripts (_scripts_beside)."""
    problem, special = survey(top)
    if problem:
        return Package('', '', None, problem)
    notes = [f'left out {path}: not a plain file, folder or link (a FIFO, socket or device)'
             for path in special]
    named = [(f, package_name(f)) for f in package_folders(top)]
    if not named:
        return _without_package_xml(top, notes)
    ros2 = {f: ros2_build(f) for f, _ in named}
    ours = [(f, n) for f, n in named if n != SIMULATOR and not ros2[f]]
    if not ours:
        return Package('', named[0][0], None, _none_built(named, ros2), notes=notes)
    beside = _scripts_beside(top, ours)
    if beside:
        return beside._replace(notes=notes + beside.notes)
    packages = {n: f for f, n in reversed(ours) if n}     # the shallowest of a name
    folder, name = min(ours, key=lambda fn: _likeliest(fn[0], packages))
    if not name:
        return Package('', folder, None, f'{os.path.join(folder, "package.xml")} names no package',
                       notes=notes)
    launch = lab_launch(folder, packages)[1]
    wanted = needed(name, packages, launch and os.path.join(folder, launch))
    others = _built_beside(top, named, ros2, (folder, name), wanted, notes)
    return Package(name, folder, launch, '', others, notes)


def _likeliest(folder, packages):
    """How likely `folder`'s package is the lab, the likeliest least: one
    whose launch file starts turtlesim (lab_launch's rank 0 or 1) or whose
    files name it, before one that does neither (a real repository's Gazebo
    package, its launch file of its own node, was run for the turtlesim
    script beside it); then by its launch file's rank; the shallowest."""
    rank = lab_launch(folder, packages)[0]
    return rank > 1 and not _names_turtlesim(folder), rank, folder.count(os.sep), folder


def _without_package_xml(top, notes):
    """A folder handed in with no package.xml: ROS 2 scripts said so, else
    its scripts run as a TA runs them (`bash turtleletterstwo.sh`, as a real
    class's instructions said), else nothing to grade."""
    ros2 = _ros2_script(top)
    if ros2:
        return Package('', '', None, f'{ros2} imports rclpy: it is ROS 2 code, and this lab '
                       f'is ROS 1 (Noetic), where no ROS 2 node runs; write it with rospy, '
                       f'in a catkin package', notes=notes)
    if not _runnable(top):
        return Package('', '', None, f'no package.xml in {top}', notes=notes)
    launch = lab_launch(top, {LOOSE: top})[1]
    return Package(LOOSE, top, launch, '', notes=notes,
                   loose=f'no package.xml in {top}: nothing a catkin workspace builds')


def _built_beside(top, named, ros2, graded, wanted, notes):
    """The folders of the other packages (`named`) that the `graded` one
    (folder, name) needs (`wanted`), built beside it; each left out is
    noted in `notes`, with why."""
    folder, name = graded
    others, kept = [], {name: folder}
    for other, other_name in named:
        where = os.path.relpath(other, top)
        if other == folder or not other_name:
            continue
        if ros2[other]:
            notes.append(f'left out {where}: {other_name}, a ROS 2 package ({ros2[other]}), '
                         f'which catkin does not build')
        elif other_name == SIMULATOR:
            notes.append(f'left out {where}: its own {SIMULATOR} (the grader runs {SIMULATOR})')
        elif other_name in kept:
            notes.append(f'left out {where}: a second package named {other_name} (graded the '
                         f'one in {os.path.relpath(kept[other_name], top)})')
        elif other_name not in wanted:
            notes.append(f'left out {where}: {other_name}, which {name} neither depends on nor '
                         f'launches (not built: its failures cost nothing)')
        else:
            kept[other_name] = other
            others.append(other)
    return others


def _scripts_beside(top, ours):
    """A course's repository of every project, handed in whole: the lab's
    script loose in it, and the packages (`ours`: (folder, name)) of other
    projects (a real one's turtlebot package), none of which names
    turtlesim. A TA grades the scripts, as handed in without a package.xml;
    the folders of `top` that name no turtlesim are left out. None where a
    package names turtlesim, or nothing does."""
    if any(_names_turtlesim(folder) for folder, _ in ours):
        return None
    try:
        folders = sorted(e.name for e in os.scandir(top) if e.is_dir(follow_symlinks=False)
                         and e.name not in SKIPPED and not e.name.startswith('.'))
    except OSError:
        return None
    left = [name for name in folders if not _names_turtlesim(os.path.join(top, name))]
    if not _names_turtlesim(top, skipped=left) or not _runnable(top, skipped=left):
        return None
    names = ', '.join(f'{os.path.relpath(folder, top)} ({name})' for folder, name in ours)
    return Package(LOOSE, top, lab_launch(top, {LOOSE: top}, left)[1], '', left=left,
                   notes=[f'left out {name}: nothing in it names turtlesim (another project, '
                          f'not the lab)' for name in left],
                   loose=f'no package of {top} names turtlesim ({names}), and its scripts '
                         f'beside them do: the lab is those scripts, with no package.xml')


def _names_turtlesim(folder, skipped=()):
    """Whether a plain file in `folder` (to rosrun's depth; its folders
    `skipped` aside) names turtlesim or its turtle1, as a lab's code does."""
    files = _plain_files(folder, 3, lambda found: False, skipped)
    return any(re.search(rb'turtlesim|turtle1', read_plain(e.path, MAX_BYTES) or b'')
               for e in files)


def _none_built(named, ros2):
    """Why a submission whose packages ((folder, name), shallowest first)
    hold none the grader builds is not run: a ROS 2 package, or only its
    own turtlesim."""
    for folder, name in named:
        if ros2[folder]:
            return (f'{name} is a ROS 2 package (its package.xml builds it with {ros2[folder]}): '
                    f'this lab is ROS 1 (Noetic), where catkin builds packages and no ROS 2 '
                    f'package builds or runs; write it as a catkin package, with rospy or roscpp')
    return (f'its only package is named {SIMULATOR}, as the simulator is: the grader runs '
            f'{SIMULATOR} itself')


def needed(name, packages, launch_file):
    """The names of `packages` (name: folder) that package `name` needs:
    those its package.xml depends on, or its launch file starts a node of
    or includes a file of, and theirs in turn."""
    wanted, todo = {name}, [name]
    if launch_file:
        text = (read_plain(launch_file, MAX_BYTES) or b'').decode('utf-8', 'replace')
        todo += [pkg for pkg, _ in nodes(launch_file, packages)] + \
            re.findall(r'\$\(find ([\w-]+)\)', text)
    while todo:
        current = todo.pop()
        if current not in packages:
            continue
        wanted.add(current)
        root = _xml(os.path.join(packages[current], 'package.xml'))
        todo += [e.text.strip() for e in (root if root is not None else [])
                 if e.tag in DEPENDS and e.text and e.text.strip() not in wanted]
    return wanted


def _plain_files(folder, depth, enough, skipped=()):
    """The plain files in a package's folders, as rosrun walks them (links
    not followed, SKIPPED and hidden folders left out, and those of
    `folder` named in `skipped`), to `depth` folders deep, in name order
    within a folder; `enough(found)` stops the walk."""
    found, stack = [], [(folder, 0)]
    while stack and not enough(found):
        here, level = stack.pop()
        try:
            entries = sorted(os.scandir(here), key=lambda e: e.name)
        except OSError:
            continue
        for entry in entries:
            if entry.is_dir(follow_symlinks=False) and entry.name not in SKIPPED \
                    and not entry.name.startswith('.') and level < depth and \
                    not (level == 0 and entry.name in skipped):
                stack.append((entry.path, level + 1))
            elif entry.is_file(follow_symlinks=False) and not entry.name.startswith('.'):
                found.append(entry)
    return found


def scripts(folder, depth=3):
    """The names of the executable plain files in a package's folders, as
    rosrun finds them, to `depth` folders deep."""
    files = _plain_files(folder, depth, lambda found: len(_executable(found)) >= MAX_NODES)
    return sorted({entry.name for entry in _executable(files)})[:MAX_NODES]


def unbuilt_scripts(folder, depth=3):
    """The names of the executable scripts in a package's folders (_script:
    a #!, a .sh, a .py): what a TA can run without a build."""
    files = _executable(_plain_files(folder, depth, lambda found: False))
    return sorted({entry.name for entry in files if _script(entry)})[:MAX_NODES]


def sources_built_by_nothing(folder, depth=3):
    """The C++ sources in a package's folders (paths in it), where its
    CMakeLists.txt builds no program (no add_executable outside a comment):
    a node written and never built, so rosrun finds none. [] otherwise."""
    cmake = (read_plain(os.path.join(folder, 'CMakeLists.txt'), MAX_BYTES) or b'').decode(
        'utf-8', 'replace')
    if re.search(r'^[^#\n]*\badd_executable\s*\(', cmake, re.MULTILINE):
        return []
    return sorted(os.path.relpath(entry.path, folder)
                  for entry in _plain_files(folder, depth, lambda found: False)
                  if entry.name.endswith(('.cpp', '.cc', '.cxx')))[:MAX_NODES]


def _executable(entries):
    return [entry for entry in entries if os.access(entry.path, os.X_OK)]


def made_executable(folder, depth=3):
    """A TA's fallback: the plain files under `folder` (the package's copy)
    that are scripts (_script: a #!, a .sh, a .py that starts a node) but
    were handed in without the execute bit (mode 644), made executable, as
    a TA would before running them. Their paths in the package."""
    made, files = [], _plain_files(folder, depth, lambda found: False)
    modules = _modules(files)
    for entry in files:
        if not os.access(entry.path, os.X_OK) and _script(entry, modules) and \
                len(made) < MAX_NODES:
            os.chmod(entry.path, entry.stat(follow_symlinks=False).st_mode | 0o111)
            made.append(os.path.relpath(entry.path, folder))
    return sorted(made)


def started_together(package: Package, depth=3):
    """Whether the grader will start several of the package's scripts
    together, as it does where no launch file starts a node of its own:
    then each may be run again alone (driver.each_alone), and the row is
    among a class's longest. Read from the files as handed in, before
    any build, as the copy will hold them (its executable files and the
    scripts made so): a C++ program, built later, is not counted."""
    if package.problem or (package.launch and started_packages(package)[1]):
        return False
    files = _plain_files(package.folder, depth, lambda found: False, package.left)
    modules = _modules(files)
    return len({entry.name for entry in files
                if os.access(entry.path, os.X_OK) or _script(entry, modules)}) > 1


def _runnable(folder, depth=3, skipped=()):
    """Whether `folder` holds a script a TA could run (_script), its
    folders `skipped` aside."""
    files = _plain_files(folder, depth, lambda found: False, skipped)
    modules = _modules(files)
    return any(_script(entry, modules) for entry in files)


def _script(entry, modules=frozenset()):
    """Whether a plain file is a script a TA runs: it starts with #!, ends
    in .sh, or is a .py that is executable or starts a rospy node (a TA
    types `python3 draw.py`; the grader runs it so: unstartable).
    A .py that another file imports (`modules`) is a helper, no node:
    it needs no #! line, and no TA runs it."""
    if _starts_with_shebang(entry.path) or entry.name.endswith('.sh'):
        return True
    if not entry.name.endswith('.py'):
        return False
    return os.access(entry.path, os.X_OK) or \
        (entry.name[:-3] not in modules and _starts_node(_python(entry.path)))


def _starts_node(text):
    """Whether a Python file's `text` imports rospy and calls its init_node."""
    return 'rospy' in _imported(text) and re.search(rb'\binit_node\s*\(', text) is not None


def _modules(files):
    """The names an import statement of a .py among `files` names (whatever
    else it names: a name of no file matches none)."""
    names = set()
    for entry in files:
        if entry.name.endswith('.py'):
            text = _python(entry.path)
            for statement in re.findall(rb'^[ \t]*(?:from[ \t]+[\w.]+[ \t]+)?import[ \t][^\n#]*',
                                        text, re.MULTILINE):
                names.update(word.decode() for word in re.findall(rb'\w+', statement))
    return frozenset(names)


def _python(path):
    """A Python file's text, its first MAX_BYTES (b'' where it cannot be read)."""
    return read_plain(path, MAX_BYTES) or b''


def _imported(text):
    """Which of rospy and rclpy (ROS 2's) a Python file's `text` imports."""
    return {module for module in ('rospy', 'rclpy')
            if re.search(rb'^\s*(import|from)\s+' + module.encode() + rb'\b', text, re.MULTILINE)}


def _ros2_script(folder, depth=3):
    """The name of the first Python file under `folder` that imports
    rclpy, where none imports rospy: ROS 2 code, which Noetic cannot run;
    else ''."""
    found = {}
    for entry in _plain_files(folder, depth, lambda found: False):
        if entry.name.endswith('.py'):
            for module in _imported(_python(entry.path)):
                found.setdefault(module, entry.name)
    return '' if 'rospy' in found else found.get('rclpy', '')


def wrap(copied):
    """The copy of a submission handed in without a package.xml made a
    catkin package named LOOSE, so that its scripts run as rosrun runs a
    package's: its own package.xml and CMakeLists.txt written in the
    grader's copy, in place of whatever stood there (a link is removed,
    never followed: the grader writes before the sandbox starts)."""
    _written(os.path.join(copied, 'package.xml'),
             f'<?xml version="1.0"?>\n<package format="2">\n  <name>{LOOSE}</name>\n'
             '  <version>0.0.0</version>\n  <description>Scripts handed in without a '
             'package.xml, wrapped by the grader</description>\n  <maintainer email='
             '"grader@example.org">grader</maintainer>\n  <license>none</license>\n'
             '  <buildtool_depend>catkin</buildtool_depend>\n</package>\n')
    _written(os.path.join(copied, 'CMakeLists.txt'),
             f'cmake_minimum_required(VERSION 3.0.2)\nproject({LOOSE})\n'
             'find_package(catkin REQUIRED)\ncatkin_package()\n')


def _written(path, text):
    """`text` in a new plain file at `path`, whatever stood there removed first."""
    if os.path.isdir(path) and not os.path.islink(path):
        remove_tree(path)
    elif os.path.lexists(path):
        os.unlink(path)
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o644)
    with os.fdopen(fd, 'w') as f:
        f.write(text)


def bare_shell(folder, depth=3):
    """The names of the plain files in a package's folders that end in .sh
    and do not start with #!: shell scripts a TA runs with bash, as such a
    course's instructions say (`bash turtleletterstwo.sh`)."""
    return sorted(entry.name for entry in _plain_files(folder, depth, lambda found: False)
                  if entry.name.endswith('.sh') and not _starts_with_shebang(entry.path))


def turtles_named(folder, names, depth=3):
    """{name: how many turtles (turtle1, turtle2, ...) its text names}, of the
    files of `names` in a package's folders: what a TA sees in a script
    before running it (a course's script that draws its second letter with
    a turtle of its own names turtle2; a compiled node, 0)."""
    named = {}
    for entry in _plain_files(folder, depth, lambda found: False):
        if entry.name in names and entry.name not in named:
            text = read_plain(entry.path, MAX_BYTES) or b''
            named[entry.name] = len(set(re.findall(rb'\bturtle\d+\b', text)))
    return named


def waiting_publishers(folder, names, depth=3):
    """Where the shell scripts of `names` in a package's folders run a `rostopic pub`
    that never exits, in words ('scripts/draw.sh line 1: ...'; '' if none),
    the first of each: without -1 (once), -r (a rate) or -f (a file), rostopic pub
    publishes once, latched, and waits to be stopped, so a script's lines
    after it never run (`-l`, latch, is easily typed for `-1`)."""
    found = []
    for entry in _plain_files(folder, depth, lambda found: False):
        if entry.name not in names or not _shell_script(entry.path):
            continue
        text = (read_plain(entry.path, MAX_BYTES) or b'').decode('utf-8', 'replace')
        for number, line in enumerate(text.splitlines(), 1):
            if _waits(line):
                found.append(f'{os.path.relpath(entry.path, folder)} line {number}: rostopic '
                             f'pub without -1 publishes once and waits to be stopped (Ctrl-C), '
                             f'so no line after it ran; -1 publishes once and exits')
                break
    return '; '.join(found)


def _shell_script(path):
    """Whether a plain file is a shell script: .sh, or a #! naming sh or bash."""
    first = (read_plain(path, 200) or b'').split(b'\n')[0]
    return path.endswith('.sh') or (first.startswith(b'#!') and
                                    re.search(rb'\b(ba|da)?sh\s*$', first.strip()) is not None)


def _waits(line):
    """Whether a shell line runs `rostopic pub` in the foreground without
    -1, -r or -f (nor under `timeout`): it then waits to be stopped."""
    words = line.split('#', 1)[0].split()
    if 'rostopic' not in words or words[-1].endswith('&') or 'timeout' in words:
        return False
    at = words.index('rostopic')
    if words[at + 1:at + 2] != ['pub']:
        return False
    options = []
    for word in words[at + 2:]:
        if word == '--':
            break
        options.append(word)
    return not any(word in ('--once', '--file') or word.startswith(('--rate', '--file=')) or
                   (word.startswith('-') and not word.startswith('--') and
                    set(word[1:]) & set('1rf'))
                   for word in options)


def unstartable(folder, depth=3):
    """{name: the program a TA runs it with} for the executable scripts in
    a package's folders that exec cannot start as handed in: a .py with no
    #! line, and a .py or a shell script (.sh, or a #! naming sh or bash)
    whose #! line names no program by its path (`#!usr/bin/env python`, or
    a line ending in a carriage return, written on Windows) or names a
    program this machine lacks (`#!/usr/bin/python`, which Ubuntu 20.04
    has only where python-is-python3 is installed; a Mac's
    /opt/homebrew/bin/python3). A .py runs with python3, a shell script
    with bash. (A shell script with no #! is bare_shell's.)"""
    found = {}
    for entry in _executable(_plain_files(folder, depth, lambda found: False)):
        if len(found) == MAX_NODES:
            break
        if _startable(entry.path):
            continue
        if entry.name.endswith('.py'):
            found[entry.name] = 'python3'
        elif _starts_with_shebang(entry.path) and _shell_script(entry.path):
            found[entry.name] = 'bash'
    return dict(sorted(found.items()))


def _startable(path):
    """Whether a script's first line is a #! that exec can follow: a path from /,
    of a program this machine has (the sandbox sees its system), no CR."""
    first = (read_plain(path, 200) or b'').split(b'\n')[0]
    named = re.match(rb'#!\s*(/\S*)', first)
    if named is None or first.endswith(b'\r'):
        return False
    program = os.fsdecode(named.group(1))
    return os.path.isfile(program) and os.access(program, os.X_OK)


def _starts_with_shebang(path):
    try:
        with open(path, 'rb') as f:
            return f.read(2) == b'#!'
    except OSError:
        return False


def _left_out(folder, names):
    """What copytree leaves out of `folder`: SKIPPED, and any file that is
    not plain, a folder or a link (copying a FIFO would block on it)."""
    def special(name):
        try:
            mode = os.lstat(os.path.join(folder, name)).st_mode
        except OSError:
            return True
        return not (stat.S_ISDIR(mode) or stat.S_ISREG(mode) or stat.S_ISLNK(mode))
    return {n for n in names if n in SKIPPED or special(n)}


def copy(package: Package, workspace):
    """The package, and the submission's others, copied into `workspace`/src
    (links copied as links, never followed)."""
    targets = [package.name] + [f'other{i}' for i in range(1, len(package.others) + 1)]
    def left_out(folder, names):
        here = folder == package.folder
        return _left_out(folder, names) | {n for n in names if here and n in package.left}
    for folder, target in zip([package.folder] + package.others, targets):
        shutil.copytree(folder, os.path.join(workspace, 'src', target), symlinks=True,
                        ignore=left_out)
    return os.path.join(workspace, 'src', package.name)
