"""Hostile cadets (hostile/), each graded in a class beside a cadet who
means well (a copy of Lena's L): what the hostile one tries outside its
sandbox fails, the limit it runs into fails it in words, nothing around
the class changes, nothing of it outlives the grading, and each neighbour
gets the grade Lena gets alone. Root only, as grading is.

The hostile submissions touch only files this test gives them (in
targets.txt), all in its own temporary folders."""
import csv
import json
import os
import shutil
import uuid

import pytest

from support.grading import grade_class, leftovers, sandbox_processes, tree_hash

HERE = os.path.dirname(os.path.abspath(__file__))
HOSTILE = os.path.join(HERE, 'hostile')
LENA = os.path.join(HERE, 'submissions', 'c03_lena')
RUBRIC = os.path.join(HERE, 'rubric.yaml')
pytestmark = pytest.mark.skipif(os.geteuid() != 0, reason='grading makes network namespaces: '
                                                          'root only')
# id: (drawn, verdict, words in the reason)
CONCLUSIONS = {
    'h1_writer': ('I', 'pass', ''),
    'h2_sleeper': ('I', 'pass', ''),
    'h3_hog': ('', 'fail', 'memory limit of 2 GiB reached'),
    'h4_forker': ('', 'fail', 'process limit of 256 reached'),
    'h5_forever': ('I', 'pass', ''),
    'h6_flood': ('I', 'pass', '/chatter was flooded'),
    'h9_forger': ('', 'fail', 'its launch file does not start turtlesim'),
    'h10_killer': ('I', 'fail', "the grader's simulator was shut down: external shutdown request "
                                "from [/killer]: [HOSTILE]: nothing drawn is credited"),
    'h11_name_taker': ('', 'fail', 'its launch file does not start turtlesim'),
    'h12_hoarder': ('', 'fail', "memory limit of 0.5 GiB reached by the grader's watcher (a "
                                "message on /chatter that large); more than 64 turtles at once: "
                                "the grader's simulator refused the spawns past them"),
}
LINGERING = ('sleep 987653', 'sleep 987654', 'sleep 987655')
PLANTED = ('json', 'rosgraph')      # modules every process of the grader's imports


@pytest.fixture(scope='module')
def room(tmp_path_factory):
    """The class folder (each hostile cadet followed by a copy of Lena), its
    roster, the grader's home, OUT, and the /tmp file the writer aims at."""
    top = tmp_path_factory.mktemp('hostile')
    room = dict(top=top, cls=top / 'class', home=top / 'home', out=top / 'out',
                tmp_file=f'/tmp/turtle_letters_hostile_{uuid.uuid4().hex}')
    room['home'].mkdir()
    rows = ['id,name,letter']
    for n, hostile in enumerate(sorted(CONCLUSIONS), 1):
        shutil.copytree(os.path.join(HOSTILE, hostile), str(room['cls'] / hostile))
        shutil.copytree(LENA, str(room['cls'] / f'n{n}_lena'))
        rows += [f'{hostile},Hugo Stile,I', f'n{n}_lena,Lena Ortiz,L']
    (top / 'roster.csv').write_text('\n'.join(rows) + '\n')
    neighbour = room['cls'] / 'n1_lena' / 'lab1' / 'scripts' / 'keys.py'
    own = room['cls'] / 'h1_writer' / 'writer_lab' / 'scripts' / 'snoop.py'
    targets = [('write', room['home'] / 'pwned.txt'), ('write', room['tmp_file']),
               ('write', room['out'] / 'grades.csv'), ('write', neighbour), ('write', own),
               ('read', neighbour), ('read', '/etc/shadow')]
    (room['cls'] / 'h1_writer' / 'writer_lab' / 'targets.txt').write_text(
        ''.join(f'{verb} {path}\n' for verb, path in targets))
    room['targets'] = targets
    return room


def planted(folder):
    """A folder with a json.py and a rosgraph.py that leave a mark when imported,
    as a folder an instructor grades from (`--one .`) may hold."""
    folder.mkdir()
    for module in PLANTED:
        (folder / f'{module}.py').write_text("open(__file__ + '.ran', 'w').close()\n")
    return str(folder)


@pytest.fixture(scope='module')
def graded(room):
    before = tree_hash(str(room['cls'])), tree_hash(str(room['home'])), sandbox_processes()
    alone = grade_class('--one', LENA, '--letter', 'L', '--rubric', RUBRIC,
                        '--out', str(room['top'] / 'alone'), cwd=planted(room['top'] / 'cwd'))
    done = grade_class(str(room['cls']), '--roster', str(room['top'] / 'roster.csv'),
                       '--rubric', RUBRIC, '--out', str(room['out']), '--jobs', '2',
                       HOME=str(room['home']))
    with open(room['out'] / 'grades.csv') as f:
        rows = {row['id']: row for row in csv.DictReader(f)}
    return done, alone, rows, before


def test_each_hostile_cadet_gets_the_row_an_instructor_would(graded):
    done, _, rows, _ = graded
    assert done.returncode == 0, done.stdout[-3000:]
    for hostile, (drawn, verdict, words) in CONCLUSIONS.items():
        row = rows[hostile]
        assert (row['drawn'], row['verdict']) == (drawn, verdict), row
        assert words in row['reason'], row


def test_a_forged_simulator_earns_nothing_it_forged(room, graded):
    written = json.loads((room['out'] / 'h9_forger' / 'results.json').read_text())
    said = {t['name']: (t['score'], t['output']) for t in written['tests']}
    assert said['The letter drawn is the expected one'] == (0, 'nothing was drawn')
    assert said['The turtle was driven over cmd_vel'] == (
        0, '/turtlesim posed as turtlesim (published poses or served /spawn): nothing it says '
           'is evidence, and it is not credited')


def test_a_watcher_whose_name_was_taken_costs_the_submission_its_talker_not_its_row(room,
                                                                                   graded):
    written = json.loads((room['out'] / 'h11_name_taker' / 'results.json').read_text())
    said = {t['name']: (t['score'], t['output']) for t in written['tests']}
    assert said['It builds'][1].startswith('built in')     # not "the grader failed on ..."
    assert said['It launches'] == (0, 'its launch file does not start turtlesim')
    assert said['The talker publishes P on a key press'][1].endswith(
        'and the grader could not send "P" itself: its watcher (/grade_watch) was shut down '
        '(a node took its name, or shut it down)')


def test_each_neighbour_gets_the_grade_lena_gets_alone(room, graded):
    _, alone, rows, _ = graded
    assert alone.returncode == 0, alone.stdout[-2000:]
    with open(room['top'] / 'alone' / 'grades.csv') as f:
        lena = next(csv.DictReader(f))
    neighbours = [row for name, row in rows.items() if name.endswith('_lena')]
    assert len(neighbours) == len(CONCLUSIONS)
    for row in neighbours:
        assert (row['drawn'], row['score'], row['verdict'], row['reason']) == \
            (lena['drawn'], lena['score'], lena['verdict'], lena['reason']), row


def test_what_the_writer_tried_outside_its_sandbox_failed(room, graded):
    log = (room['out'] / 'h1_writer' / 'log.txt').read_text()
    for verb, path in room['targets']:
        if path != room['tmp_file']:
            assert f'HOSTILE {verb} {path}: refused' in log, (verb, path)
    # its own home and /tmp are its own: what it wrote there went with the sandbox
    assert 'mine.txt: done' in log and f'{room["tmp_file"]}: done' in log
    assert not os.path.exists(room['tmp_file'])
    assert not (room['home'] / 'pwned.txt').exists()


def test_nothing_around_the_class_changed_and_nothing_is_left(room, graded):
    _, _, rows, (cls, home, processes) = graded
    assert (tree_hash(str(room['cls'])), tree_hash(str(room['home']))) == (cls, home)
    written = json.loads((room['out'] / 'h1_writer' / 'results.json').read_text())
    assert len(written['tests']) == 8 and len(rows) == 2 * len(CONCLUSIONS)    # the grader's
    assert leftovers(processes) == ([], [])
    lingering = [line for line in os.popen('ps -eo args').read().splitlines()
                 if line.startswith(LINGERING)]
    assert lingering == []


def test_no_process_of_the_grader_imports_from_the_folder_it_was_started_in(room, graded):
    _, alone, _, _ = graded
    assert alone.returncode == 0, alone.stdout[-2000:]
    assert sorted(os.listdir(room['top'] / 'cwd')) == sorted(f'{m}.py' for m in PLANTED)
