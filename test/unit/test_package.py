"""package.xml names every package the code needs at run time, so that
rosdep installs it before a user meets a refusal."""
import ast
import importlib.util
import os
import xml.etree.ElementTree as ElementTree

HERE = os.path.dirname(__file__)
PACKAGE = os.path.join(HERE, '..', '..')
SRC = os.path.join(PACKAGE, 'src', 'turtle_letters')
# The rosdep key of each package the code imports that is not Python's own.
KEYS = {'rospy': 'rospy', 'rosgraph': 'rosgraph', 'actionlib': 'actionlib',
        'geometry_msgs': 'geometry_msgs', 'std_msgs': 'std_msgs', 'std_srvs': 'std_srvs',
        'turtlesim': 'turtlesim', 'actionlib_msgs': 'actionlib_msgs', 'yaml': 'python3-yaml',
        'tqdm': 'python3-tqdm', 'PyQt5': 'python3-pyqt5', 'svgelements': 'python3-svgelements',
        'numpy': 'python3-numpy', 'scipy': 'python3-scipy', 'fontTools': 'python3-fonttools', 'tesserocr': 'python3-tesserocr', 'PIL': 'python3-pil',
        'rospkg': 'python3-rospkg', 'rosgraph_msgs': 'rosgraph_msgs', 'roslib': 'roslib',
        'sensor_msgs': 'sensor_msgs', 'tornado': 'python3-tornado',
        'catkin_pkg': 'python3-catkin-pkg'}


def run_dependencies():
    root = ElementTree.parse(os.path.join(PACKAGE, 'package.xml')).getroot()
    return {e.text for e in root if e.tag in ('depend', 'exec_depend')}


def imported_packages():
    """The top-level packages that the code imports, other than Python's own."""
    found = set()
    for folder, _, files in os.walk(SRC):
        for name in (f for f in files if f.endswith('.py')):
            with open(os.path.join(folder, name)) as f:
                tree = ast.parse(f.read())
            for node in ast.walk(tree):
                if isinstance(node, ast.Import):
                    found.update(a.name.split('.')[0] for a in node.names)
                elif isinstance(node, ast.ImportFrom) and node.level == 0:
                    found.add(node.module.split('.')[0])
    return {name for name in found if not standard(name)}


def standard(name):
    """Python's own module (3.8 has no sys.stdlib_module_names): not from site- or dist-packages."""
    spec = importlib.util.find_spec(name)
    return spec is not None and 'packages' not in (spec.origin or '')


def test_every_imported_package_is_a_run_dependency():
    imported = imported_packages()
    assert imported <= set(KEYS), f'imported, with no rosdep key here: {imported - set(KEYS)}'
    missing = {KEYS[name] for name in imported} - run_dependencies()
    assert not missing, f'package.xml lacks {missing}'


def test_the_hershey_fonts_files_are_a_run_dependency():
    with open(os.path.join(SRC, 'letters', 'hershey.py')) as f:
        assert '/usr/share/hershey-fonts' in f.read()
    assert 'hershey-fonts-data' in run_dependencies()


def test_no_test_submission_shadows_one_of_our_executables():
    """rosrun and roslaunch look for a node's executable anywhere under the
    package's folder, test/class/submissions included: a cadet's talker.py
    there would make `rosrun turtle_letters talker.py` ask which one."""
    def executables(top, skip=None):
        found = {}
        for folder, folders, files in os.walk(top):
            folders[:] = [f for f in folders if os.path.join(folder, f) != skip]
            for name in files:
                if os.access(os.path.join(folder, name), os.X_OK):
                    found.setdefault(name, []).append(os.path.join(folder, name))
        return found
    submissions = os.path.join(PACKAGE, 'test', 'class', 'submissions')
    ours = executables(os.path.join(PACKAGE, 'scripts'))
    ours.update(executables(os.path.join(PACKAGE, 'test'), skip=submissions))
    theirs = executables(submissions)
    assert sorted(set(ours) & set(theirs)) == []
