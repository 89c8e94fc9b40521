"""File names from user text: a Hershey letter such as '/' is valid, and
its report must still be saved (it crashed the grader and the scoreboard)."""
import os

import pytest

from turtle_letters.isolation.files import report_stem, safe_name


@pytest.mark.parametrize('text', ['/', '1/2', '..', '.', '', 'a b', '%2F', '/alice/2', '~x'])
def test_a_safe_name_is_one_plain_file_name(text):
    name = safe_name(text)
    assert name and '/' not in name and not name.startswith('.') and ' ' not in name


def test_distinct_texts_keep_distinct_names():
    texts = ['/', '_', '%2F', '1/2', '1_2', '1%2F2', '.a', '%2Ea', 'a', 'A']
    assert len({safe_name(t) for t in texts}) == len(texts)


def test_plain_names_stay_as_they_are():
    assert report_stem('/turtle1', 'N', 3) == 'turtle1-N-3'


def test_the_grader_saves_the_report_of_a_slash(tmp_path):
    grader = pytest.importorskip('turtle_letters.grading.grader')
    report = dict(turtle='/alice', letter='/', number=1, worst_vertex_mm=1.0)
    stem = grader.Saver(str(tmp_path))(report, [[(1.0, 1.0), (2.0, 2.0)]], [(1.0, 1.0), (2.0, 2.0)])
    assert os.path.dirname(stem) == str(tmp_path)
    assert sorted(os.listdir(tmp_path)) == ['alice-%2F-1.json', 'alice-%2F-1.png']


def test_text_shown_is_one_safe_line_of_bounded_length():
    from turtle_letters.isolation.files import LINE_MOST, shown
    assert shown('a\nb\tc\x1b[2J\x0c\u202e\x7f') == 'a b c [2J   '
    assert shown(b'M\xfcller') == shown('M\udcfcller') == 'M\ufffdller'
    assert shown('\ud800x') == '\ufffd\ufffd\ufffdx'     # a lone surrogate, as JSON can give one
    assert len(shown('x' * 10000)) == LINE_MOST and shown('ok') == 'ok'


def test_a_file_name_keeps_a_folder_names_undecodable_bytes_distinct():
    assert safe_name('M\udcfcller') == 'M%FCller' != safe_name('Müller') == 'M%C3%BCller'


def test_a_tree_deeper_than_python_recurses_is_removed(tmp_path):
    from support.grading import nest
    from turtle_letters.isolation.files import remove_tree
    nest(tmp_path, 1200)
    remove_tree(str(tmp_path / 'd'))
    assert os.listdir(str(tmp_path)) == []
