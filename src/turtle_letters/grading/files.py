"""File names made from user text (a turtle's name, a letter, a student's
id), and files a user made, read safely, in one place. No ROS here."""
import os
import stat
import urllib.parse


def safe_name(text: str) -> str:
    """`text` as one file name: letters, digits and _ . - ~ kept, anything
    else (a '/', a space) percent-encoded, so distinct texts stay distinct;
    a leading '.' is encoded too, so no name is hidden, '.' or '..'."""
    name = urllib.parse.quote(str(text), safe='')
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
