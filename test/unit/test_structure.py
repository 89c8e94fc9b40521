"""How the package reads: the lab on top, a folder per concern, each module
importing only what sits below it, the pure folders with no ROS, nothing too
long to read at once."""
import ast
import os

import pytest

SRC = os.path.join(os.path.dirname(__file__), '..', '..', 'src', 'turtle_letters')
MODULES = sorted(os.path.relpath(os.path.join(folder, f), SRC)[:-3].replace(os.sep, '.')
                 for folder, _, files in os.walk(SRC) for f in files
                 if f.endswith('.py') and f != '__init__.py')
FOLDERS = sorted(f for f in os.listdir(SRC) if os.path.isdir(os.path.join(SRC, f))
                 and f != '__pycache__')
# Bottom to top: a module imports only from its own layer or those below.
LAYERS = [
    {'lab', 'keys'},                    # the lab's N and the talker's keys: pure, the ground
    {'letters'},                        # strokes, layout, plans: pure
    {'reading'},                        # letters read from ink: pure
    {'motion'},                         # carrying a plan out on a turtle
    {'settings'},                       # the nodes' parameters
    {'isolation'},                      # untrusted code and files kept in their place
    {'classroom'},                      # many students on one turtlesim
    {'turtle', 'actions', 'grading'},   # the lab's turtle; requests; scoring
    {'controller', 'talker'},           # the lab's nodes
    {'viewer'},                         # the room seen from any seat: a live page, an image
    {'autograder'},                     # the instructor's: a class graded as handed in
]
PURE = {'lab', 'keys', 'letters', 'settings', 'motion.modes', 'motion.executors', 'motion.control',
        'motion.latency',
        'classroom.names',
        'classroom.parts', 'classroom.hosts', 'grading.scoring', 'grading.picture', 'reading',
        'autograder.observations', 'autograder.rubric', 'autograder.roster',
        'autograder.reports', 'autograder.submission', 'autograder.failures', 'isolation.files',
        'grading.procstat', 'actions.jobs', 'actions.progress', 'viewer.trails', 'viewer.pens', 'viewer.picture',
        'viewer.server'}
ROS = ('rospy', 'rosgraph', 'actionlib', 'geometry_msgs', 'std_msgs', 'std_srvs', 'turtlesim')


def tree(module):
    with open(os.path.join(SRC, *module.split('.')) + '.py') as f:
        return ast.parse(f.read())


def resolve(module, node):
    """The module of ours that a relative import names (None for another package's)."""
    if node.level == 0:
        return None
    here = module.split('.')[:len(module.split('.')) - node.level]
    return '.'.join(here + ([node.module] if node.module else []))


def imports(module):
    """(our modules, other top-level packages) that `module` imports."""
    ours, others = set(), set()
    for node in ast.walk(tree(module)):
        if isinstance(node, ast.ImportFrom) and node.level:
            base = resolve(module, node)
            named = [f'{base}.{a.name}' if base else a.name for a in node.names]
            modules = {n for n in named if n in MODULES}       # from . import svgart
            ours.update(modules or {base})
        elif isinstance(node, ast.ImportFrom):
            others.add(node.module.split('.')[0])
        elif isinstance(node, ast.Import):
            others.update(a.name.split('.')[0] for a in node.names)
    return {m for m in ours if m.split('.')[0] not in ('msg', 'srv')}, others


def layer(module):
    top = module.split('.')[0]
    return next(i for i, names in enumerate(LAYERS) if top in names)


def is_pure(module):
    return any(module == p or module.startswith(p + '.') for p in PURE)


def test_the_top_level_holds_the_lab_and_each_folder_one_concern():
    top = [m for m in MODULES if '.' not in m]
    assert len(top) <= 6, top
    for folder in FOLDERS:
        assert len([m for m in MODULES if m.startswith(folder + '.')]) <= 12, folder
        with open(os.path.join(SRC, folder, '__init__.py')) as f:
            doc = ast.get_docstring(ast.parse(f.read()))
        assert doc and '\n' not in doc, f'{folder}/__init__.py: a one-line docstring'
    assert {top for names in LAYERS for top in names} == set(top) | set(FOLDERS)


@pytest.mark.parametrize('module', MODULES)
def test_a_module_imports_only_what_sits_below_it(module):
    for other in imports(module)[0]:
        assert layer(other) <= layer(module), f'{module} imports {other}, from a layer above'


@pytest.mark.parametrize('module', sorted(m for m in MODULES if is_pure(m)))
def test_a_pure_module_has_no_ros_in_it_nor_below_it(module):
    seen, todo = set(), [module]
    while todo:
        current = todo.pop()
        seen.add(current)
        ours, others = imports(current)
        assert not others & set(ROS), f'{current} (below {module}) imports {others & set(ROS)}'
        assert is_pure(current), f'{module} imports {current}, which is not pure'
        todo += [m for m in ours if m not in seen]


@pytest.mark.parametrize('module', MODULES)
def test_no_class_or_function_is_over_120_lines(module):
    for node in ast.walk(tree(module)):
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            length = node.end_lineno - node.lineno + 1
            assert length <= 120, f'{module}.{node.name}: {length} lines'


def test_the_node_module_stays_short():
    with open(os.path.join(SRC, 'controller.py')) as f:
        assert len(f.readlines()) <= 150


def test_the_unit_tests_mirror_the_folders():
    here = os.path.dirname(__file__)
    tests = sorted(f for f in os.listdir(here) if os.path.isdir(os.path.join(here, f))
                   and f != '__pycache__')
    assert tests == FOLDERS
