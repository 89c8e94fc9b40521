"""File names made from user text (a turtle's name, a letter, a student's
id), made safe in one place. No ROS here."""
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
