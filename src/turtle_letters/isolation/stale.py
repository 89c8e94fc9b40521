"""What a grader that could not clean up (killed outright, its session
lost, its machine stopped) left of its sandboxes: network namespaces,
cgroups, scratch folders with their tmpfs mounts. Each carries its
grader's pid in its name; the next grader removes those of graders no
longer running, and says so."""
import glob
import os
import re
import subprocess
import tempfile

from .cgroups import cgroup_roots, remove_cgroups
from .files import remove_tree

# Each name begins with its maker's pid: a sandbox's namespace and cgroups
# (+ a number), its scratch folder (+ mkdtemp's letters).
NAMESPACE = 'tlgrade{pid}n'
SCRATCH = 'turtle_letters_sandbox_{pid}_'
_PREFIXES = [name.split('{')[0] for name in (NAMESPACE, SCRATCH)]
_PID = re.compile('(?:' + '|'.join(_PREFIXES) + r')(\d+)[n_]')


def _ended(name):
    """Whether `name` is a sandbox's, made by a grader no longer running."""
    found = _PID.match(name)
    if not found:
        return False
    try:
        os.kill(int(found.group(1)), 0)
    except ProcessLookupError:
        return True
    except PermissionError:     # a live process of another user's
        return False
    return False


def left_behind():
    """(namespaces, cgroup folders, scratch folders) of graders no longer running."""
    listed = subprocess.run(['ip', 'netns', 'list'], stdout=subprocess.PIPE,
                            stderr=subprocess.DEVNULL, universal_newlines=True).stdout
    namespaces = [line.split()[0] for line in listed.splitlines()
                  if line.split() and _ended(line.split()[0])]
    cgroups = sorted({folder for root in cgroup_roots()     # where its grader's own cgroup was
                      for folder in glob.glob(os.path.join(root, '**', 'tlgrade*'), recursive=True)
                      if _ended(os.path.basename(folder))})
    scratches = [folder for folder in glob.glob(os.path.join(tempfile.gettempdir(),
                                                             _PREFIXES[1] + '*'))
                 if _ended(os.path.basename(folder))]
    return namespaces, cgroups, scratches


def sweep():
    """Removes what graders no longer running left; says what, or ''."""
    namespaces, cgroups, scratches = left_behind()
    for namespace in namespaces:
        subprocess.run(['ip', 'netns', 'delete', namespace], stderr=subprocess.DEVNULL,
                       start_new_session=True)      # Ctrl-C is the grader's to act on
    remove_cgroups(cgroups)
    for folder in scratches:
        if os.path.ismount(folder):
            subprocess.run(['umount', '--lazy', folder], stderr=subprocess.DEVNULL,
                           start_new_session=True)
        remove_tree(folder)
    found = sorted({int(_PID.match(os.path.basename(name)).group(1))
                    for name in namespaces + cgroups + scratches})
    if not found:
        return ''
    return (f'removed what graders no longer running left (pid {", ".join(map(str, found))}): '
            f'{len(namespaces)} network namespaces, {len(cgroups)} cgroups, '
            f'{len(scratches)} folders')
