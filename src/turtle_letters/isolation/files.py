"""User text made safe, in one place: as file names (a turtle's name, a
letter, a student's id), as a line to show (a submission's output, a
folder's name), and files a user made, read and removed. No ROS here."""
import os
import stat
import subprocess
import unicodedata
import urllib.parse

LINE_MOST = 500         # characters of one line shown: a fallback's own words take up to about 280
# Unicode's control, format, surrogate, unassigned and line-separator
# characters: a terminal acts on some, XML forbids others, and a bidi
# override makes a line read other than it is.
UNSHOWN = {'Cc', 'Cf', 'Cs', 'Cn', 'Zl', 'Zp'}


def _utf8(text):
    """`text`'s bytes: a file name's undecodable bytes (surrogate escapes) as they were."""
    try:
        return text.encode('utf-8', 'surrogateescape')
    except UnicodeEncodeError:
        return text.encode('utf-8', 'surrogatepass')


def safe_name(text: str) -> str:
    """`text` as one file name: letters, digits and _ . - ~ kept, anything
    else (a '/', a space) percent-encoded, so distinct texts stay distinct;
    a leading '.' is encoded too, so no name is hidden, '.' or '..'."""
    name = urllib.parse.quote(_utf8(str(text)), safe='')
    return '%2E' + name[1:] if name.startswith('.') else name or '%00'


def report_stem(turtle: str, letter: str, number: int) -> str:
    """The file name, less its suffix, of a turtle's graded drawing."""
    return f"{safe_name(turtle.strip('/'))}-{safe_name(letter)}-{number}"


def read_plain(path, most, from_end=False):
    """Up to `most` bytes of a plain file (its last ones if `from_end`), or
    None: never through a link, from a pipe or from a device, as a user's
    file could be any of them."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError:
        return None
    with os.fdopen(fd, 'rb') as f:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            return None
        if from_end:
            f.seek(max(0, info.st_size - most))
        return f.read(most)


def shown(text, most=LINE_MOST) -> str:
    """A user's text as one line that is safe anywhere (a terminal, XML,
    JSON, HTML): undecodable bytes as U+FFFD, every character of UNSHOWN
    (a newline, an ESC, a form feed) as a space, at most `most` characters."""
    if not isinstance(text, bytes):
        text = _utf8(str(text))
    line = ''.join(' ' if unicodedata.category(c) in UNSHOWN else c
                   for c in text.decode('utf-8', 'replace'))
    return line if len(line) <= most else line[:most - 1] + '\u2026'


def remove_tree(path):
    """Removes a folder a user's code wrote in, however deep it nests
    (Python's own rmtree recurses, and fails past about 1,000 levels)."""
    subprocess.run(['rm', '-rf', '--one-file-system', '--', path], check=False,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   start_new_session=True)     # a Ctrl-C meant for its caller must not stop it
