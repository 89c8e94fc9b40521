"""A cadet's submission as handed in: the catkin package somewhere inside
their folder, its name, and the launch file the lab runs. No ROS here: the
files are read as plain XML, never run (a launch file's $(eval) is Python).
"""
import os
import shutil
import xml.etree.ElementTree as ElementTree
from typing import List, NamedTuple, Optional

from ..grading.files import read_plain

SKIPPED = {'.git', 'build', 'devel', 'install', 'logs', '__pycache__'}
MAX_BYTES = 1 << 20      # a package.xml or launch file larger than this is not read


class Package(NamedTuple):
    name: str
    folder: str             # where package.xml is
    launch: Optional[str]   # the launch file, relative to `folder`
    problem: str            # why it cannot be run, or ''
    others: List[str] = []  # the submission's other packages' folders, built beside it


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


def nodes(launch_root) -> List[tuple]:
    """(pkg, type) of every <node> in a launch file's XML."""
    return [(n.get('pkg', ''), n.get('type', '')) for n in launch_root.iter('node')]


def lab_launch(folder):
    """(rank, file): the launch file that starts turtlesim and a node of
    another package (the cadet's controller), rank 0; else one with
    turtlesim, or with another node; else the first; (4, None) for none."""
    ranked = [(4, None)]
    for name in launch_files(folder):
        root = _xml(os.path.join(folder, name))
        started = nodes(root) if root is not None else []
        has_sim = any(pkg == 'turtlesim' for pkg, _ in started)
        has_other = any(pkg != 'turtlesim' for pkg, _ in started)
        ranked.append((3 - 2 * has_sim - has_other, name))
    return min(ranked, key=lambda r: (r[0], r[1] or ''))


def package_name(folder):
    root = _xml(os.path.join(folder, 'package.xml'))
    return root.findtext('name', '').strip() if root is not None else ''


def find(top) -> Package:
    """The submission's package: of the package.xml under `top`, the one
    whose launch file starts turtlesim and a controller, the shallowest
    first; its other packages are built beside it."""
    folders = package_folders(top)
    if not folders:
        return Package('', '', None, f'no package.xml in {top}')
    folder = min(folders, key=lambda f: (lab_launch(f)[0], f.count(os.sep), f))
    others = [f for f in folders if f != folder and package_name(f)]
    name = package_name(folder)
    if not name:
        return Package('', folder, None, f'{os.path.join(folder, "package.xml")} names no package')
    launch = lab_launch(folder)[1]
    problem = '' if launch else f'no launch file in {folder}'
    return Package(name, folder, launch, problem, others)


def copy(package: Package, workspace):
    """The package, and the submission's others, copied into `workspace`/src
    (links copied as links, never followed)."""
    targets = [package.name] + [f'other{i}' for i in range(1, len(package.others) + 1)]
    for folder, target in zip([package.folder] + package.others, targets):
        shutil.copytree(folder, os.path.join(workspace, 'src', target), symlinks=True,
                        ignore=shutil.ignore_patterns(*SKIPPED))
    return os.path.join(workspace, 'src', package.name)
