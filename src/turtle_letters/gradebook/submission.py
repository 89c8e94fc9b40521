"""A cadet's submission as handed in: the catkin package somewhere inside
their folder, its name, and the launch file the lab runs. No ROS here: the
files are read as plain XML, never run (a launch file's $(eval) is Python).
"""
import os
import shutil
import xml.etree.ElementTree as ElementTree
from typing import List, NamedTuple, Optional

SKIPPED = {'.git', 'build', 'devel', 'install', 'logs', '__pycache__'}


class Package(NamedTuple):
    name: str
    folder: str             # where package.xml is
    launch: Optional[str]   # the launch file, relative to `folder`
    problem: str            # why it cannot be run, or ''


def package_folders(top):
    """Folders under `top` holding a package.xml, shallowest first."""
    found = []
    for folder, folders, files in os.walk(top):
        folders[:] = sorted(f for f in folders if f not in SKIPPED)
        if 'package.xml' in files:
            found.append(folder)
    return sorted(found, key=lambda f: (f.count(os.sep), f))


def _xml(path):
    try:
        return ElementTree.parse(path).getroot()
    except (ElementTree.ParseError, OSError):
        return None


def launch_files(folder):
    found = []
    for here, folders, files in os.walk(folder):
        folders[:] = sorted(f for f in folders if f not in SKIPPED)
        found += [os.path.relpath(os.path.join(here, f), folder) for f in files
                  if f.endswith(('.launch', '.launch.xml'))]
    return sorted(found)


def nodes(launch_root) -> List[tuple]:
    """(pkg, type) of every <node> in a launch file's XML."""
    return [(n.get('pkg', ''), n.get('type', '')) for n in launch_root.iter('node')]


def lab_launch(folder):
    """The launch file that starts turtlesim and a node of another package
    (the cadet's controller); else one with turtlesim; else the first."""
    candidates = [(f, _xml(os.path.join(folder, f))) for f in launch_files(folder)]
    ranked = []
    for name, root in candidates:
        started = nodes(root) if root is not None else []
        has_sim = any(pkg == 'turtlesim' for pkg, _ in started)
        has_other = any(pkg != 'turtlesim' for pkg, _ in started)
        ranked.append((-(2 * has_sim + has_other + (has_sim and has_other)), name))
    return min(ranked)[1] if ranked else None


def find(top) -> Package:
    """The submission's package: the shallowest package.xml under `top`."""
    folders = package_folders(top)
    if not folders:
        return Package('', '', None, f'no package.xml in {top}')
    folder = folders[0]
    root = _xml(os.path.join(folder, 'package.xml'))
    name = root.findtext('name', '').strip() if root is not None else ''
    if not name:
        return Package('', folder, None, f'{os.path.join(folder, "package.xml")} names no package')
    launch = lab_launch(folder)
    problem = '' if launch else f'no launch file in {folder}'
    return Package(name, folder, launch, problem)


def copy(package: Package, workspace):
    """The package copied into `workspace`/src (links copied as links, never followed)."""
    target = os.path.join(workspace, 'src', package.name)
    shutil.copytree(package.folder, target, symlinks=True,
                    ignore=shutil.ignore_patterns(*SKIPPED))
    return target
