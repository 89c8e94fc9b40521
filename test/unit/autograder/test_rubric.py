"""The rubric: the package's defaults, an instructor's file over them, and
what each kind of run earns under it, criterion by criterion."""
import math
import os
import re

import pytest

from turtle_letters.autograder.observations import Drawing
from turtle_letters.autograder.rubric import (CRITERIA, Facts, Limits, RubricError, credited,
                                             grade, load)
from turtle_letters.autograder.reports import overlay
from turtle_letters.autograder.session import Step
from turtle_letters.reading.cleanness import strays
from turtle_letters.reading.ocr import read_text
from turtle_letters.reading.rows import read_row

from support.cadet_paths import arc, driven, forward, wandering
from support.glyph_rows import row

DEFAULT = os.path.join(os.path.dirname(__file__), '..', '..', '..', 'config', 'rubric.yaml')
L_PATH = [(1.0, 3.0), (1.0, 1.0), (2.2, 1.0)]
OK = Step(True, 'fine')


def facts(drawing=None, expected='L', ocr=False, **steps):
    drawing = drawing or Drawing([L_PATH], 1.0, 5.0, 200, [])
    given = dict(build=OK, launch=OK, waited=OK, talker=OK)
    given.update(steps)
    return Facts(expected, '', given['build'], given['launch'], given['waited'],
                 given['talker'], drawing,
                 read_row(drawing.strokes, expected) if drawing.strokes else [],
                 ocr=read_text(drawing.strokes, expected) if ocr and drawing.strokes else None)


def scores_of(graded):
    return {t.name: (t.score, t.output) for t in graded.tests}


def write(tmp_path, text):
    path = tmp_path / 'rubric.yaml'
    path.write_text(text)
    return str(path)


def test_the_default_rubric_scores_every_criterion_and_totals_100():
    rubric = load(DEFAULT)
    assert list(rubric.points) == list(CRITERIA)
    assert sum(rubric.points.values()) == 100
    graded = grade(facts(), rubric)
    assert (graded.score, graded.verdict, graded.reason) == (100, 'pass', 'every criterion met')


def test_an_instructors_file_changes_only_what_it_gives(tmp_path):
    rubric = load(DEFAULT, write(tmp_path, 'points: {letter: 50}\nlimits: {drawing: 20}\n'))
    assert rubric.points['letter'] == 50 and rubric.points['builds'] == 10
    assert rubric.limits.drawing == 20 and rubric.limits.build == 300


def limits_in(text, start):
    """{name: (value, reason)} of the limits block of the rubric file, or
    of the table under `start` in doc/grading.md."""
    found, lines = {}, text[text.index(start):].lstrip('\n').splitlines()[1:]
    for line in lines:
        if re.match(r'^[a-z]', line) or (found and not line.strip()):
            break
        yaml_entry = re.match(r'^  ([a-z_]+): ([0-9.]+)\s+# (.*)$', line)
        table_row = re.match(r'^\| `([a-z_]+)` \| ([0-9.]+) \| (.*) \|$', line)
        entry = yaml_entry or table_row
        if entry:
            found[entry.group(1)] = (float(entry.group(2)), entry.group(3))
    return found


def test_every_limit_is_declared_once_with_its_reason_and_shown_as_declared():
    """config/rubric.yaml's `limits:` is the one table of a run's limits:
    each there with a reason, each used (a field of Limits), and
    doc/grading.md shows that table as it is."""
    with open(DEFAULT) as f:
        declared = limits_in(f.read(), '\nlimits:')
    with open(os.path.join(os.path.dirname(DEFAULT), '..', 'doc', 'grading.md')) as f:
        shown = limits_in(f.read(), '| limit | default | what for |\n|---|')
    assert list(declared) == list(Limits._fields)
    assert shown == declared
    assert load(DEFAULT).limits == Limits(*(value for value, _ in declared.values()))


@pytest.mark.parametrize('text, says', [
    ('points: {colour: 5}\n', 'unknown colour'),
    ('limits: {drawing: -1}\n', 'limits: drawing: -1'),
    ('limits: {turtles: 6.5}\n', 'limits: turtles: 6.5 is not a whole number'),
    ('accuracy: {full: 0.2}\n', 'must be above full'),
    ('pass_score: [1]\n', 'pass_score'),
    ('- a list\n', 'expected a mapping'),
    ('points: {letter: 5\n', 'rubric.yaml'),
])
def test_a_bad_rubric_says_which_entry_and_why(tmp_path, text, says):
    with pytest.raises(RubricError, match=says):
        load(DEFAULT, write(tmp_path, text))


def test_each_step_that_failed_costs_its_points_and_says_why():
    graded = grade(facts(talker=Step(False, "nothing on /chatter: NameError: 'raw_input'")),
                   load(DEFAULT))
    assert graded.score == 90 and graded.verdict == 'pass'
    assert graded.reason.endswith("NameError: 'raw_input'")


def test_a_failed_build_reaches_nothing_else():
    graded = grade(Facts('L', '', Step(False, 'catkin_make failed: x'), None, None, None, None,
                         []), load(DEFAULT))
    assert graded.score == 0 and graded.verdict == 'fail'
    assert scores_of(graded)['It launches'] == (0, 'not tried: the build failed')


def test_a_fail_says_what_failed_it_after_what_cost_points_first():
    """The row's reason begins with the first criterion that lost points;
    where a required one failed it, that follows, unless it only echoes
    that nothing came of the run."""
    wrong = grade(facts(expected='K', launch=Step(False, 'no launch file')), load(DEFAULT))
    assert wrong.reason == ('It launches: no launch file; failed on The letter drawn is the '
                            'expected one: drew L, expected K')
    unbuilt = grade(Facts('L', '', Step(False, 'catkin_make failed: x'), None, None, None, None,
                          []), load(DEFAULT))
    assert unbuilt.reason == 'It builds: catkin_make failed: x'
    alone = grade(facts(expected='K'), load(DEFAULT))
    assert alone.reason == 'The letter drawn is the expected one: drew L, expected K'


def test_a_letter_cut_short_by_a_script_stopped_at_a_rostopic_pub_says_where():
    stopped = 'scripts/l.sh line 9: rostopic pub without -1 publishes once and waits'
    graded = grade(facts(expected='K')._replace(waiting=stopped), load(DEFAULT))
    assert scores_of(graded)['The letter drawn is the expected one'] == (
        0, f'drew L, expected K; {stopped}')
    right = grade(facts()._replace(waiting=stopped), load(DEFAULT))      # drawn before it stopped
    assert scores_of(right)['The letter drawn is the expected one'] == (25, 'drew L, as expected')


def test_a_letter_read_only_loosely_as_another_is_not_said_to_be_drawn():
    """An L whose foot droops 0.3 m lies nearest an L, 9% of its height off:
    no letter reads beyond doubt, and graded against K the row says what it
    lies nearest, not that the student drew it (a real class's cursive L
    was told it drew a P). Within CLEAN (a droop of 0.1 m, 4%) it drew an L."""
    drooping = Drawing([[(1.0, 3.0), (1.0, 1.0), (2.2, 0.7)]], 1.0, 5.0, 200, [])
    line = scores_of(grade(facts(drooping, expected='K'), load(DEFAULT)))[
        'The letter drawn is the expected one']
    assert line == (0, 'no letter reads cleanly, and L is the nearest, 9% of its height off '
                       '(within 7.5% a letter reads beyond doubt): expected K')
    clean = Drawing([[(1.0, 3.0), (1.0, 1.0), (2.2, 0.9)]], 1.0, 5.0, 200, [])
    assert scores_of(grade(facts(clean, expected='K'), load(DEFAULT)))[
        'The letter drawn is the expected one'] == (0, 'drew L, expected K')


def test_the_wrong_letter_earns_no_accuracy():
    graded = grade(facts(expected='K'), load(DEFAULT))
    lines = scores_of(graded)
    assert lines['The letter drawn is the expected one'] == (0, 'drew L, expected K')
    assert lines['Its accuracy'][0] == 0


def test_accuracy_is_how_cleanly_the_ink_makes_its_letter_not_how_close_to_a_font():
    """A barred J with a round hook, lines and arcs as a turtle drives them:
    12% of its height off the nearest J of the readers' forms, and every
    point; an L whose stem weaves 6 cm either side: the points fall
    linearly from 2% of the height (20) to 10% (0) of how far it strays."""
    j = [driven([forward(2.0), arc(0.5, -math.pi)], 2.0, 3.0, -math.pi / 2), [(1.0, 3.0),
                                                                             (3.0, 3.0)]]
    barred = facts(Drawing(j, 1.0, 5.0, 9, []), expected='J')
    assert barred.readings[0].fits['J'].fit > 0.1
    points, said = scores_of(grade(barred, load(DEFAULT)))['Its accuracy']
    assert points == 20 and said.startswith(
        "its strokes stray 0.0% of its height from the lines and arcs they draw, and its "
        "loops close (every point at 2% or less, none from 10%)")
    stem = [(1.0 + 0.06 * math.sin(2 * math.pi * k / 40), 3.0 - k * 0.01) for k in range(201)]
    woven = facts(Drawing([stem + [(1.0 + k * 0.01, 1.0) for k in range(1, 121)]], 1.0, 5.0,
                          9, []))
    wobble = strays(woven.drawing.strokes).wobble
    assert woven.readings[0].letter == 'L' and 0.02 < wobble < 0.04
    assert scores_of(grade(woven, load(DEFAULT)))['Its accuracy'][0] == pytest.approx(
        20 * (0.10 - wobble) / 0.08, abs=0.01)
    # an O stopping 0.1 rad short: a gap of 5% of its height, one spot, counted half
    o = facts(Drawing([driven([(2 * math.pi - 0.1, (2 * math.pi - 0.1) / 2, 2.0)], 2.0, 1.0)],
                      1.0, 5.0, 9, []), expected='O')
    gap = strays(o.drawing.strokes).gap
    assert 0.04 < gap < 0.06
    assert scores_of(grade(o, load(DEFAULT)))['Its accuracy'][0] == pytest.approx(
        20 * (0.10 - gap / 2) / 0.08, abs=0.01)


def test_a_limit_of_the_sandbox_fails_the_submission_in_words():
    graded = grade(facts()._replace(limit='memory limit of 2 GiB reached'), load(DEFAULT))
    assert graded.verdict == 'fail' and graded.score == 100
    assert graded.reason == "It keeps within the sandbox's limits: memory limit of 2 GiB reached"
    assert not graded.tests[0].met and graded.tests[0].max_score == 0


def test_cheats_on_the_trigger_and_the_canvas_cost_the_criterion_they_break():
    rubric = load(DEFAULT)
    own = scores_of(grade(facts()._replace(own_triggers=['/v_drawer']), rubric))
    flood = scores_of(grade(facts()._replace(chatter_peak=9000.0), rubric))
    cleared = scores_of(grade(facts(Drawing([L_PATH], 1.0, 5.0, 200, [], 0, 0, 5.0,
                                            [(2.5, 'clear')])), rubric))
    reset = scores_of(grade(facts(Drawing([L_PATH], 1.0, 5.0, 200, [], 0, 0, 5.0,
                                          [(1.0, 'reset'), (3.0, 'reset')])), rubric))
    talker, letter, driven = ('The talker publishes P on a key press',
                              'The letter drawn is the expected one',
                              'The turtle was driven over cmd_vel')
    assert own[talker] == (0, '/v_drawer drives the turtle and published "P" on /chatter '
                              'itself: it draws without the trigger')
    assert flood[talker] == (0, 'fine, but /chatter was flooded: 9000 messages a second')
    # a student may start again: the canvas left is graded, and the row says so
    assert cleared[letter] == (25, 'drew L, as expected (graded on the canvas left after '
                                   'turtlesim was cleared 2.5 s into the drawing)')
    assert reset[letter] == (25, 'drew L, as expected (graded on the canvas left after '
                                 'turtlesim was reset 3.0 s into the drawing, the last of 2 times)')
    assert cleared[driven][0] == 10 and reset[driven][0] == 10


def test_impostors_teleported_ink_and_a_broken_world_fail_the_driving():
    driven = 'The turtle was driven over cmd_vel'
    made_up = scores_of(grade(facts(Drawing([L_PATH], 1.0, 5.0, 90, ['/f_drawer'])),
                             load(DEFAULT)))
    inked = scores_of(grade(facts(Drawing([L_PATH], 1.0, 5.0, 90, [], 3, 2)), load(DEFAULT)))
    travel = scores_of(grade(facts(Drawing([L_PATH], 1.0, 5.0, 90, [], 3, 0)), load(DEFAULT)))
    broken = scores_of(grade(facts()._replace(broken="the grader's simulator was shut down: x"),
                             load(DEFAULT)))
    assert made_up[driven][0] == 0 and '/f_drawer posed as turtlesim' in made_up[driven][1]
    assert inked[driven] == (0, '2 teleports with the pen down laid ink: ink is credited only '
                                'where a turtle was driven')
    assert travel[driven] == (10, 'driven over cmd_vel: 90 commands, 3 teleports with the pen up')
    own = scores_of(grade(facts(Drawing([L_PATH], 1.0, 5.0, 90, [], turtles=['theo'],
                                        pen_lifts=1)), load(DEFAULT)))
    assert own[driven] == (10, 'driven over cmd_vel: 90 commands, 1 pen lift, by theo')
    assert broken[driven] == (0, "the grader's simulator was shut down: x")
    assert broken['The letter drawn is the expected one'][0] == 0
    assert broken['The drawing ends, the turtle standing still'][0] == 0


def test_a_letter_not_read_says_what_teleports_laid_beside_the_ink_read():
    """A real class's M laid by teleports, its i's dot driven: the row
    says why the letters the student sees are not read."""
    letter = 'The letter drawn is the expected one'
    inked = Drawing([L_PATH], 1.0, 5.0, 90, [], 5, 4)
    assert scores_of(grade(facts(inked, expected='M'), load(DEFAULT)))[letter] == (
        0, 'drew L, expected M; 4 teleports with the pen down laid ink no letter is read from')
    assert scores_of(grade(facts(inked), load(DEFAULT)))[letter] == (25, 'drew L, as expected')


def test_a_flood_of_turtles_is_said_to_be_one_not_nothing_drawn():
    """Thirty turtles wandering a minute: no letter, nor 'nothing was
    drawn' (the flood's readings have no shape), nor accuracy."""
    scores = scores_of(grade(facts(Drawing(wandering(), 1.0, 60.0, 9000, []), expected='MF',
                                   ocr=True), load(DEFAULT)))
    assert scores['The letter drawn is the expected one'] == (
        0, 'no letter is read from a flood of ink: more than 50 times its height for each '
           'letter expected (a letter is drawn with far less)')
    assert scores['Its accuracy'][0] == 0


def test_a_dash_alone_is_said_to_be_one_not_nothing_drawn():
    """A real class's script drove its turtle 1.8 m straight from its start
    and died: the row said 'nothing was drawn' beside its picture of a line."""
    scores = scores_of(grade(facts(Drawing([[(5.54, 5.54), (3.74, 5.54)]], 1.0, 3.0, 7, [])),
                             load(DEFAULT)))
    score, said = scores['The letter drawn is the expected one']
    assert score == 0 and said.startswith('no letter reads from the ink: a dash, 1.80 m across '
                                          'and 0.00 m high')
    assert scores['Its accuracy'] == (0, f'not scored: {said}')


def test_turtles_that_moved_and_laid_no_ink_are_said_to_not_only_nothing_drawn():
    """A real package spawned 27 turtles in the shape of a G and turned them
    in place: the row said 'nothing was drawn' beside 11,286 commands to
    27 turtles. It says they moved and laid no ink; a turtle that never
    moved is said as before."""
    spawned = Drawing([], 1.0, 40.0, 11286, [], turtles=[f'turtle{i}' for i in range(1, 28)],
                      spawns=28)
    said = scores_of(grade(facts(spawned), load(DEFAULT)))['The letter drawn is the expected one']
    assert said == (0, 'nothing was drawn: 27 turtles moved and laid no ink (turned in place, '
                       'or drove with their pens up), and 28 were spawned or killed: a letter '
                       'is the ink turtles lay as they drive, not where turtles stand'), said
    turned = Drawing([], 1.0, 5.0, 3, [], turtles=['turtle1'])
    said = scores_of(grade(facts(turned), load(DEFAULT)))['The letter drawn is the expected one']
    assert said == (0, 'nothing was drawn: turtle1 moved and laid no ink (turned in place, or '
                       'drove with its pen up)'), said
    assert scores_of(grade(facts(Drawing([], None, None, 0, [])), load(DEFAULT)))[
        'The letter drawn is the expected one'] == (0, 'nothing was drawn')


def test_a_drawing_that_never_ends():
    lines = scores_of(grade(facts(Drawing([L_PATH], 1.0, None, 900, [])), load(DEFAULT)))
    assert lines['The drawing ends, the turtle standing still'][0] == 0


def test_a_required_criterion_failed_fails_whatever_the_score():
    jumped = grade(facts(Drawing([L_PATH], 1.0, 5.0, 50, [], 1, 1)), load(DEFAULT))
    assert jumped.score == 90 and jumped.verdict == 'fail'
    assert jumped.reason.startswith('The turtle was driven over cmd_vel: 1 teleport with the pen')


def test_expected_is_the_first_letter_or_the_initials(tmp_path):
    assert load(DEFAULT).expected == 'first'
    assert load(DEFAULT, write(tmp_path, 'expected: initials\n')).expected == 'initials'
    with pytest.raises(RubricError, match="expected: 'middle' is not one of first, initials"):
        load(DEFAULT, write(tmp_path, 'expected: middle\n'))


def test_required_names_only_criteria(tmp_path):
    with pytest.raises(RubricError, match='required'):
        load(DEFAULT, write(tmp_path, 'required: [colour]\n'))


def test_initials_earn_each_letter_in_its_place():
    a = [(1.0, 1.0), (1.6, 3.0), (2.2, 1.0)], [(1.2, 1.7), (2.0, 1.7)]
    l_beside = [[(x + 2.0, y) for x, y in L_PATH]]
    row = [*a, *l_beside]
    both = scores_of(grade(facts(Drawing(row, 1.0, 5.0, 90, []), expected='AL'), load(DEFAULT)))
    half = scores_of(grade(facts(Drawing(row, 1.0, 5.0, 90, []), expected='AT'), load(DEFAULT)))
    letter, accuracy = 'The letter drawn is the expected one', 'Its accuracy'
    assert both[letter] == (25, 'drew AL, as expected') and both[accuracy][0] > 19
    assert half[letter] == (12.5, 'drew AL, expected AT: 1 in place')
    assert 9 < half[accuracy][0] <= 10
    # half the accuracy of a clean row is explained where it is given
    assert half[accuracy][1].endswith('; for 1 of the 2 letters, those in place')
    assert 'letters, those in place' not in both[accuracy][1]


def test_a_bare_stroke_past_the_first_letter_is_the_small_l_the_roster_expects():
    """A real class's Al, for Alexander (an arched A, then one green stroke
    as tall), read AI and failed: a TA reads a small l, as the roster says.
    The stroke is an I's as much, so only where it is an l's shape: past
    the first letter, one bare stroke, upright or leaning, as tall as the
    row (an i's stem is half as tall); a serif I, or a first letter, is an
    I. (Graded again, the real stroke, leaning a little, was fitted by a
    form of two three-point strokes, not the plain one-line form: a bare
    form is any narrower than a fifth of its height.)"""
    a = [(1.0, 1.0), (1.6, 3.0), (2.2, 1.0)], [(1.2, 1.7), (2.0, 1.7)]
    rubric, letter = load(DEFAULT), 'The letter drawn is the expected one'

    def graded(strokes, expected='AL'):
        read = facts(Drawing(strokes, 1.0, 5.0, 90, []), expected=expected)
        return scores_of(grade(read, rubric)), [e for _, e in credited(read)], overlay(read)
    tall, credits, shown = graded([*a, [(3.0, 1.0), (3.0, 3.0)]])
    assert tall[letter] == (25, 'drew Al, as expected; its l one bare stroke, as a small l is '
                                'written')
    assert credits == ['A', 'L'] and tall['Its accuracy'][0] > 19
    assert [label for label, _ in shown] == ['A', 'l']     # the picture names it as read
    short, credits, _ = graded([*a, [(3.0, 1.0), (3.0, 2.0)]])
    assert short[letter] == (12.5, 'drew AI, expected AL: 1 in place; the L reads as an I: a '
                                   'small l is credited past the first letter, one bare '
                                   'stroke at least 80% as high as the row (a capital L reads)')
    assert credits == ['A']
    leaning, credits, _ = graded([*a, [(3.0, 1.0), (3.15, 3.0)]])    # an italic I's form fits
    assert leaning[letter][0] == 25 and credits == ['A', 'L']
    serif, _, _ = graded([*a, [(2.7, 3.0), (3.3, 3.0)], [(3.0, 3.0), (3.0, 1.0)],
                          [(2.7, 1.0), (3.3, 1.0)]])
    assert serif[letter][0] == 12.5 and serif[letter][1].startswith('drew AI, expected AL')
    first, _, _ = graded([[(3.0, 1.0), (3.0, 3.0)], *[[(x + 2.6, y) for x, y in s] for s in a]],
                         expected='LA')
    assert first[letter][0] == 12.5 and first[letter][1].startswith('drew IA, expected LA')


def test_a_tilted_letter_is_read_and_its_tilt_said():
    from turtle_letters.reading.ink import turned
    tilted = turned([L_PATH], 10, (1.5, 2.0))
    said = scores_of(grade(facts(Drawing(tilted, 1.0, 5.0, 90, [])), load(DEFAULT)))
    assert said['The letter drawn is the expected one'] == (25, 'drew L, as expected')
    assert said['Its accuracy'][1].endswith(', drawn 10 degrees off level')


def test_what_a_drawing_may_use_besides_cmd_vel_is_the_rubrics(tmp_path):
    used = Drawing([L_PATH], 1.0, 5.0, 90, [], jumps=2, pens=3, spawns=2)
    strict = load(DEFAULT, write(tmp_path, 'allowed: {teleport: false, set_pen: false}\n'))
    assert scores_of(grade(facts(used), load(DEFAULT)))['The turtle was driven over cmd_vel'][0] == 10
    assert scores_of(grade(facts(used), strict))['The turtle was driven over cmd_vel'] == (
        0, 'teleported 2 times, called set_pen 3 times: the rubric does not allow it')
    with pytest.raises(RubricError, match='allowed: .* true or false for each of teleport'):
        load(DEFAULT, write(tmp_path, 'allowed: {teleport: 1}\n'))


def test_a_dash_before_the_initials_costs_neither_the_letters_nor_their_accuracy():
    """A level dash reads as no letter (it has no height): the letters and
    their accuracy are both judged on the letters read, in the same places."""
    dash = [[(0.2, 2.0), (0.6, 2.0)]]
    a = [(1.0, 1.0), (1.6, 3.0), (2.2, 1.0)], [(1.2, 1.7), (2.0, 1.7)]
    l_beside = [[(x + 2.0, y) for x, y in L_PATH]]
    said = scores_of(grade(facts(Drawing([*dash, *a, *l_beside], 1.0, 5.0, 90, []),
                                 expected='AL'), load(DEFAULT)))
    assert said['The letter drawn is the expected one'] == (25, 'drew AL, as expected')
    assert said['Its accuracy'][0] > 19, said['Its accuracy']


def test_ocr_credits_what_the_strokes_miss_and_the_row_says_both():
    """DejaVu Serif Bold's R drawn round its edge, serifs and all, which
    the strokes do not read (neither its middle line nor its edges fit a
    letter within 15%): OCR reads it, and the letter is credited in its words."""
    from turtle_letters.letters.outlines import DEJAVU_BOLD, outline_glyphs
    ink = [[(1 + x * 2, 3 + y * 2) for x, y in line] for line in outline_glyphs(DEJAVU_BOLD[1])['R']]
    said = scores_of(grade(facts(Drawing(ink, 1.0, 5.0, 90, []), 'R', ocr=True), load(DEFAULT)))
    line = said['The letter drawn is the expected one']
    assert line[0] == 25 and line[1].startswith('drew R, as expected: OCR reads R ('), line
    assert line[1].endswith('sure); its strokes read ?'), line


def test_neither_reader_credits_a_mirrored_letter_or_another_one():
    rubric = load(DEFAULT)
    for drawn, expected in (('N', 'N'), ('R', 'R'), ('P', 'R'), ('E', 'F')):
        ink = row(drawn, 0.0)
        if drawn == expected:
            ink = [[(12.0 - x, y) for x, y in line] for line in ink]     # mirrored
        said = scores_of(grade(facts(Drawing(ink, 1.0, 5.0, 90, []), expected, ocr=True),
                               rubric))
        assert said['The letter drawn is the expected one'][0] == 0, (drawn, expected, said)


def test_a_drawing_that_never_ended_says_the_limit_it_was_watched_for():
    rubric, ends = load(DEFAULT), CRITERIA['ends'][0]
    moving = Drawing([L_PATH], 1.0, None, 200, [])
    full = scores_of(grade(facts(moving)._replace(limit_s=rubric.limits.drawing), rubric))
    share = scores_of(grade(facts(moving)._replace(limit_s=72.46), rubric))
    assert full[ends] == (0.0, 'the turtle was still moving 180 s after it started: the '
                                 'drawing never ended')
    assert share[ends] == (0.0, 'the turtle was still moving 72.5 s after it started (run '
                                  'alone, with what was left of the 180 s the alone runs '
                                  'share): the drawing never ended')
