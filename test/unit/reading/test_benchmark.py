"""The recognition benchmark (tools/bench_recognition.py) grades each
drawing against what the readers take it for: a confusion of the
readers' counts as the wrong credit it would be in a class."""
import os
import subprocess
import sys

from turtle_letters.letters.outlines import DEJAVU_BOLD, outline_glyphs
from turtle_letters.reading.ink import turned

sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', '..', '..', 'tools'))
import bench_recognition  # noqa: E402  (a tool, not a module of the package)


def wide_outline(letter, wide=1.5, tilt=15):
    glyph = outline_glyphs(DEJAVU_BOLD[0])[letter]
    return turned([[(3.8 * wide * x, 3.8 * y) for x, y in line] for line in glyph], tilt, (0, 0))


def test_a_drawing_is_graded_against_the_letter_the_strokes_take_it_for():
    """DejaVu Sans Bold's D outline half as wide again: its middle line
    fits an O best, 11% of its height off (a D 12%). The benchmark grades
    it as an O too (a grade against a letter at random would have tried
    the O once in 25), and the O is not credited: the strokes read no
    letter they cannot tell from another (recognition.RIVAL; before, this
    O was credited), and OCR reads no O."""
    ink = wide_outline('D')
    _, _, _, _, taken = bench_recognition.readers(ink, 'D')
    assert 'O' in taken
    assert bench_recognition.credited_wrongly(ink, 'D', 'O') == (False, False, False)


def test_a_drawing_is_graded_against_each_place_swapped_for_its_next_best_fit():
    """A row EP both readers read right, taken for nothing else: the
    benchmark grades it as TP and EV too, each place's letter swapped for
    the one that fits the ink there next best (graded against a row at
    random, each would come once in 676 rows)."""
    from support.glyph_rows import row
    read, _, ocr, _, taken = bench_recognition.readers(row('EP'), 'EP')
    assert (read, ocr) == ('EP', True) and {'TP', 'EV'} <= taken


def test_a_letter_credited_in_place_where_another_was_drawn_is_wrong():
    assert bench_recognition.wrong_in_place('ZF', 'ZT', 'ZF')
    assert not bench_recognition.wrong_in_place('Z?', 'ZT', 'ZF')
    assert not bench_recognition.wrong_in_place('ZT', 'ZT', 'ZT')


def test_two_runs_of_the_corpus_are_compared_drawing_by_drawing():
    """--against names the drawings whose verdict moved, and the drawings
    that are no longer the same (a form added after a letter's last one
    changes the cadets' drawings, and every figure with them)."""
    first, again, other_seed = [], [], []
    bench_recognition.recognition_run(2, 1, drawings=first)
    bench_recognition.recognition_run(2, 1, drawings=again)
    bench_recognition.recognition_run(2, 1, seed=2, drawings=other_seed)
    assert [d['texts'] for d in first] == [d['texts'] for d in again]
    assert bench_recognition.changes(first, again) == []
    moved = [dict(d, both=dict(d['both'], right=not d['both']['right'])) if d['n'] == 1 else d
             for d in again]
    lines = bench_recognition.changes(first, moved)
    assert len(lines) == 1 and lines[0].startswith('drawing 1, ') and '(was ' in lines[0]
    changed = bench_recognition.changes(first, other_seed)
    assert changed and all('the corpus changed' in line for line in changed)


def test_a_file_of_no_drawings_to_compare_against_is_refused_before_the_run(tmp_path):
    path = tmp_path / 'drawings.jsonl'
    path.write_text('{"n": 0}\n')
    tool = os.path.join(os.path.dirname(bench_recognition.__file__), 'bench_recognition.py')
    done = subprocess.run([sys.executable, tool, '1', '0', '--against', str(path)],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 2 and "line 1 is not a drawing's record" in done.stderr
    assert 'recognition,' not in done.stdout


def test_a_drawings_file_that_cannot_be_written_is_refused_before_the_run(tmp_path):
    tool = os.path.join(os.path.dirname(bench_recognition.__file__), 'bench_recognition.py')
    done = subprocess.run([sys.executable, tool, '1', '0', '--drawings',
                           str(tmp_path / 'no such folder' / 'drawings.jsonl')],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 2 and '--drawings' in done.stderr
    assert 'recognition,' not in done.stdout
