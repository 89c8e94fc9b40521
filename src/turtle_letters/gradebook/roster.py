"""The class: the roster (id,name and an optional letter) against the
submissions folder (one folder per student, named by their id). No ROS here."""
import csv
import os
import string
import unicodedata
from typing import List, NamedTuple, Optional, Tuple


class RosterError(ValueError):
    """A roster that cannot be read; the message says why."""


class Student(NamedTuple):
    id: str
    name: str
    expected: str           # the letter they should draw ('' when no one can say)
    folder: Optional[str]   # their submission, or None


def first_letter(name):
    """The first letter of `name` as A-Z ('Émile' gives E), or '' when it
    is none of them ('Øystein', '李')."""
    first = next((c for c in name if c.isalpha()), '')
    plain = unicodedata.normalize('NFKD', first)[:1].upper()
    return plain if plain in string.ascii_uppercase and plain else ''


def _expected(row, where):
    given = (row.get('letter') or '').strip().upper()
    if given and (len(given) != 1 or given not in string.ascii_uppercase):
        raise RosterError(f'{where}: letter {given!r} is not one letter of A-Z')
    return given or first_letter(row['name'])


def read(roster_path, submissions) -> Tuple[List[Student], List[str]]:
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
    students, seen, warnings = [], set(), []
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
        expected = _expected(row, f'{roster_path}, line {number}')
        if not expected:
            warnings.append(f'{sid}: the name {name!r} starts with no letter of A-Z: give the '
                            f'letter in the roster\'s letter column')
        students.append(Student(sid, name, expected, folder))
    for extra in folders:
        if extra not in seen:
            warnings.append(f'{extra}: a submission the roster lacks: graded, with no name '
                            f'and no expected letter')
            students.append(Student(extra, '', '', os.path.join(submissions, extra)))
    return students, warnings
