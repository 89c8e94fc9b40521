"""How the package reads: one concern a module, each importing only what
sits below it, the pure ones with no ROS, nothing too long to read at once."""
import ast
import os

import pytest

SRC = os.path.join(os.path.dirname(__file__), '..', '..', 'src', 'turtle_letters')
MODULES = sorted(f[:-3] for f in os.listdir(SRC) if f.endswith('.py') and f != '__init__.py')
PURE = {'control', 'drawing', 'grading', 'picture', 'procstat', 'font', 'hershey', 'hosts', 'jobs', 'keys', 'motion', 'parts', 'plan',
        'route', 'settings', 'sheet', 'svgart'}
ROS = ('rospy', 'rosgraph', 'geometry_msgs', 'std_msgs', 'std_srvs', 'turtlesim')


def tree(module):
    with open(os.path.join(SRC, module + '.py')) as f:
        return ast.parse(f.read())


def imports(module):
    """(our modules, other top-level packages) that `module` imports."""
    ours, others = set(), set()
    for node in ast.walk(tree(module)):
        if isinstance(node, ast.ImportFrom) and node.level == 1 and node.module:
            ours.add(node.module.split('.')[0])
        elif isinstance(node, ast.ImportFrom) and node.level == 1:     # from . import x
            ours.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            others.add(node.module.split('.')[0])
        elif isinstance(node, ast.Import):
            others.update(a.name.split('.')[0] for a in node.names)
    return ours - {'srv', 'msg'}, others     # the generated service and action types


def test_the_modules_import_in_layers_with_no_cycle():
    below = {m: imports(m)[0] for m in MODULES}
    done, visiting = set(), []

    def visit(module):
        assert module not in visiting, 'an import cycle: ' + ' -> '.join(visiting + [module])
        if module in done:
            return
        visiting.append(module)
        for other in below[module]:
            visit(other)
        visiting.pop()
        done.add(module)
    for module in MODULES:
        visit(module)


@pytest.mark.parametrize('module', sorted(PURE))
def test_a_pure_module_has_no_ros_in_it_nor_below_it(module):
    seen, todo = set(), [module]
    while todo:
        current = todo.pop()
        seen.add(current)
        ours, others = imports(current)
        assert not others & set(ROS), f'{current} (below {module}) imports {others & set(ROS)}'
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
