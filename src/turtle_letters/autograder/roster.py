"""The class: the roster (id,name and an optional letter) against the
submissions folder (one folder per student, named by their id). No ROS here.

What a student is expected to draw: the roster's letter column when it is
given (one letter, or a text such as initials), else what the rubric's
`expected` says of their name: its first letter (the lab's) or its initials."""
import csv
import os
import string
import unicodedata
from typing import List, NamedTuple, Optional, Tuple


class RosterError(ValueError):
    """A roster that cannot be read; the message says why."""


MAX_TEXT = 8        # letters a student may be asked to draw
EXPECTED = ('first', 'initials')


class Student(NamedTuple):
    id: str
    name: str
    expected: str           # the letters they should draw, left to right ('' when no one can say)
    folder: Optional[str]   # their submission, or None


# Latin letters that are no accented letter to Unicode (NFKD leaves them
# whole), read as the plain letter a reader of the name sees in them.
PLAIN = {'Ø': 'O', 'Ł': 'L', 'Đ': 'D', 'Æ': 'A', 'Œ': 'O', 'Þ': 'T', 'Ħ': 'H', 'Ŧ': 'T',
         'Ɖ': 'D', 'Ŋ': 'N', 'ẞ': 'S'}


def first_letter(name):
    """The first letter of `name` as A-Z ('Émile' gives E, 'Øystein' O),
    or '' when it is none of them ('李')."""
    first = next((c for c in name if c.isalpha()), '').upper()
    plain = unicodedata.normalize('NFKD', first)[:1]
    plain = PLAIN.get(plain, plain)
    return plain if plain in string.ascii_uppercase and plain else ''


def _words(name):
    return name.replace('-', ' ').split()


def initials(name):
    """The first letter of each word of `name` ('Anna-Lena de Vries' gives ALDV)."""
    return ''.join(first_letter(word) for word in _words(name))


def lost_words(name):
    """The words of `name` whose initial cannot be read as A-Z ('李')."""
    return [word for word in _words(name)
            if any(c.isalpha() for c in word) and not first_letter(word)]


def expected(name, given='', mode='first'):
    """What a student is to draw: `given` (checked), else `mode` of their name."""
    given = given.strip().upper()
    if given:
        if len(given) > MAX_TEXT or not set(given) <= set(string.ascii_uppercase):
            raise ValueError(f'letter {given!r} is not 1 to {MAX_TEXT} letters of A-Z')
        return given
    return initials(name) if mode == 'initials' else first_letter(name)


def _expected(row, where, mode):
    try:
        return expected(row['name'] or '', row.get('letter') or '', mode)
    except ValueError as e:
        raise RosterError(f'{where}: {e}') from None


def _unread_columns(roster_path, header, mode):
    """A warning where the roster has no letter column but others than id
    and name: a column of letters under another name (`expected`) would
    otherwise be passed over without a word, the names' letters taken."""
    unread = [column for column in header if column not in ('id', 'name', 'letter')]
    if 'letter' in header or not unread:
        return []
    return [f'{roster_path}: no letter column, so each student is expected to draw '
            f'{"the initials" if mode == "initials" else "the first letter"} of their name; '
            f'its column{"s" if len(unread) > 1 else ""} {", ".join(unread)} '
            f'{"are" if len(unread) > 1 else "is"} not read (name a column of letters '
            f'"letter")']


def read(roster_path, submissions, mode='first') -> Tuple[List[Student], List[str]]:
    """The students in roster order, then folders the roster lacks; and warnings."""
    try:
        with open(roster_path, newline='', encoding='utf-8-sig') as f:
            reader = csv.DictReader(f)
            rows, header = list(reader), reader.fieldnames
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise RosterError(f'{roster_path}: {e}') from None
    if not rows or not {'id', 'name'} <= set(header or []):
        raise RosterError(f'{roster_path}: expected a header with id,name (and optionally '
                          f'letter) and a row per student')
    try:
        folders = sorted(f for f in os.listdir(submissions)
                         if os.path.isdir(os.path.join(submissions, f)))
    except OSError as e:
        raise RosterError(f'{submissions}: {e}') from None
    students, seen, warnings = [], set(), _unread_columns(roster_path, header, mode)
    for number, row in enumerate(rows, start=2):
        if None in row or None in row.values():     # DictReader's marks of a short or long row
            given = sum(k is not None and v is not None for k, v in row.items()) + \
                len(row.get(None) or [])
            raise RosterError(f'{roster_path}, line {number}: {given} fields, where the header '
                              f'has {len(header)} ({",".join(header)})')
        sid = (row['id'] or '').strip()
        if not sid or sid in seen:
            raise RosterError(f'{roster_path}, line {number}: '
                              + ('no id' if not sid else f'id {sid!r} given twice'))
        seen.add(sid)
        folder = os.path.join(submissions, sid) if sid in folders else None
        name = (row['name'] or '').strip()
        wanted = _expected(row, f'{roster_path}, line {number}', mode)
        lost = lost_words(name) if mode == 'initials' and not (row.get('letter') or '').strip() \
            else []
        if not wanted:
            warnings.append(f'{sid}: the name {name!r} starts with no letter of A-Z: give the '
                            f'letter in the roster\'s letter column')
        elif lost:
            warnings.append(f'{sid}: in the name {name!r}, {", ".join(map(repr, lost))} '
                            f'{"has" if len(lost) == 1 else "have"} no letter of A-Z: expected '
                            f'{wanted!r}; give the letters in the roster\'s letter column')
        students.append(Student(sid, name, wanted, folder))
    for extra in folders:
        if extra not in seen:
            warnings.append(f'{extra}: a submission the roster lacks: graded, with no name '
                            f'and no expected letter')
            students.append(Student(extra, '', '', os.path.join(submissions, extra)))
    return students, warnings
