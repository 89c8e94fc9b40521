"""The roster against the submissions folder."""
import pytest

from turtle_letters.autograder.roster import RosterError, expected, first_letter, read


def setup_class(tmp_path, roster_text, folders):
    for name in folders:
        (tmp_path / 'subs' / name).mkdir(parents=True)
    (tmp_path / 'subs').mkdir(exist_ok=True)
    (tmp_path / 'roster.csv').write_text(roster_text, encoding='utf-8')
    return str(tmp_path / 'roster.csv'), str(tmp_path / 'subs')


def test_roster_order_the_expected_letter_and_the_folders_it_lacks(tmp_path):
    roster, subs = setup_class(tmp_path, 'id,name,letter\nb2,Émile Zola,\na1,Kofi,x\nc3,Ann,\n',
                               ['a1', 'b2', 'late'])
    students, warnings = read(roster, subs)
    assert [(s.id, s.expected, s.folder is not None) for s in students] == [
        ('b2', 'E', True), ('a1', 'X', True), ('c3', 'A', False), ('late', '', True)]
    assert warnings == ['late: a submission the roster lacks: graded, with no name and no '
                        'expected letter']


@pytest.mark.parametrize('text, says', [
    ('student,name\na,b\n', 'header with id,name'),
    ('id,name\n', 'header with id,name'),
    ('id,name\na,Ann\na,Bob\n', "id 'a' given twice"),
    ('id,name,letter\na,Ann,A B\n', "letter 'A B' is not 1 to 8 letters of A-Z"),
    ('id,name,letter\na,Ann,ABCDEFGHI\n', "letter 'ABCDEFGHI' is not 1 to 8 letters"),
    ('id,name,letter\na,Ann,A\nb\n', r'line 3: 1 fields, where the header has 3 \(id,name,letter\)'),
    ('id,name\na,Ann,A,x\n', 'line 2: 4 fields, where the header has 2'),
])
def test_a_roster_that_cannot_be_used(tmp_path, text, says):
    roster, subs = setup_class(tmp_path, text, [])
    with pytest.raises(RosterError, match=says):
        read(roster, subs)


def test_a_missing_roster(tmp_path):
    with pytest.raises(RosterError, match='No such file'):
        read(str(tmp_path / 'none.csv'), str(tmp_path))


def test_first_letters():
    assert [first_letter(n) for n in ('nadia', ' Øystein', '3 Zoë', '李', '')] == \
        ['N', 'O', 'Z', '', '']


def test_a_text_in_the_roster_or_the_initials_of_the_name(tmp_path):
    roster, subs = setup_class(tmp_path, 'id,name,letter\na,Anna-Lena de Vries,\nb,Bo Li,jd\n',
                               [])
    assert [s.expected for s in read(roster, subs)[0]] == ['A', 'JD']
    assert [s.expected for s in read(roster, subs, 'initials')[0]] == ['ALDV', 'JD']
    assert expected(' Émile  Zola ', mode='initials') == 'EZ'


def test_letters_that_unicode_does_not_decompose_read_as_a_reader_sees_them(tmp_path):
    assert [first_letter(n) for n in ('Øystein', 'Łukasz', 'Đorđe', 'Æsa', 'Þóra')] == \
        ['O', 'L', 'D', 'A', 'T']
    roster, subs = setup_class(tmp_path, 'id,name,letter\na,Øystein Berg,\nb,Łukasz Nowak,\n'
                                         'c,Mei 李 Wang,\nd,Mei 李 Wang,MW\n', [])
    students, warnings = read(roster, subs, 'initials')
    assert [s.expected for s in students] == ['OB', 'LN', 'MW', 'MW']
    assert warnings == ["c: in the name 'Mei 李 Wang', '李' has no letter of A-Z: expected 'MW'; "
                        "give the letters in the roster's letter column"]


def test_a_column_of_letters_under_another_name_is_warned_of_not_read(tmp_path):
    """A TA's roster with its letters under `expected`: each student is
    expected their name's first letter, as without the column, and the
    warning says so; a roster with a letter column keeps its other columns
    (an email) without a word."""
    roster, subs = setup_class(tmp_path, 'id,name,expected\na,Shreya,D\n', [])
    students, warnings = read(roster, subs)
    assert [s.expected for s in students] == ['S']
    assert warnings == [f'{roster}: no letter column, so each student is expected to draw the '
                        f'first letter of their name; its column expected is not read (name a '
                        f'column of letters "letter")']
    roster, subs = setup_class(tmp_path, 'id,name,letter,email\na,Shreya,D,s@x\n', [])
    students, warnings = read(roster, subs)
    assert [s.expected for s in students] == ['D'] and warnings == []
