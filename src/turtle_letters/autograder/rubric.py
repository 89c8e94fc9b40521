"""The rubric (config/rubric.yaml, or the instructor's over it) and what a
run earns under it: criterion by criterion, points and one line of feedback.
No ROS here."""
from typing import Dict, List, NamedTuple, Optional

import yaml

from ..isolation.files import shown
from ..reading.cleanness import strays
from ..reading.forms import CLEAN
from ..reading.ink import LONGEST, box, flooded, turned
from ..reading.ocr import OcrReading, said as ocr_said, supports
from ..reading.recognition import Reading
from ..reading.rows import BARE
from .observations import Drawing, chatter_peak, own_triggers
from .roster import EXPECTED

CHATTER_FLOOD = 100     # messages a second on /chatter past which the talker floods it
# A bare stroke past a row's first letter, standing this share as high as its tallest
# letter or more, is the small l the roster expects there: a name's later letters are
# written small (nine of a real class of sixteen did), and an l is one tall stroke,
# an i's stem half as tall (a real class's Al, for Alexander, read AI and failed).
SMALL_L = 0.8


class RubricError(ValueError):
    """A rubric that cannot be used; the message says which entry and why."""


class Limits(NamedTuple):
    """Every limit of a run: config/rubric.yaml says how much, and why
    (seconds; memory in GiB; counts)."""
    build: float
    launch: float
    stand: float
    talker: float
    start: float
    drawing: float
    settle: float
    up: float
    cpu: float
    memory: float
    processes: int
    disk: float
    files: int
    events: int
    record: int
    turtles: int
    world_memory: float
    world_processes: int
    watcher_memory: float
    watcher_processes: int
    alone: int


ALLOWED = ('teleport', 'spawn', 'set_pen')


class Rubric(NamedTuple):
    expected: str                   # what a name asks for, without a letter in the roster
    allowed: Dict[str, bool]        # of ALLOWED: what a drawing may use besides cmd_vel
    pass_score: float
    required: List[str]             # criteria a pass needs every point of
    points: Dict[str, float]        # criterion: points, in order
    full: float                     # strays earning every accuracy point (share of the height)
    none: float                     # ... and none
    limits: Limits


class Facts(NamedTuple):
    """What happened to one submission (Step-like entries: .ok, .says; None: not reached)."""
    expected: str
    problem: str = ''               # why it could not even be built ('' if it could)
    build: object = None
    launch: object = None
    waited: object = None
    talker: object = None
    drawing: Optional[Drawing] = None
    readings: List[Reading] = []    # the letters drawn, left to right ([]: no ink)
    stuck: str = ''                 # why the turtle never moved after the trigger, if known
    limit: str = ''                 # the sandbox's limit it reached, in words ('' if none)
    own_triggers: List[str] = []    # its nodes that drive the turtle and published "P" too
    chatter_peak: float = 0.0       # the most messages a second on /chatter
    broken: str = ''                # how the grader's master or simulator was broken, if it was
    ocr: Optional[OcrReading] = None    # what OCR reads in the ink (ocr.py), beside `readings`
    limit_s: Optional[float] = None     # s the drawing was watched for at most (session.Run)
    writing: Optional[list] = None  # the ink the letters were read in, if not all the canvas's
    where: str = ''                 # ... which of the canvas's writing that is, in words
    waiting: str = ''               # where a script stops at a rostopic pub that never exits
    fought: str = ''                # how the executables started together fought (session.Run)
    longer: str = ''                # a row of more letters than expected it reads whole as

    @classmethod
    def never_ran(cls, expected, problem):
        """A submission that was never run (none handed in, no package, the
        grader's own failure): why, and nothing observed."""
        return cls(expected, problem)

    @classmethod
    def observed(cls, expected, run, drawing, page, ocr, longer=''):
        """A run's facts: its steps (session.Run), the drawing seen in it and
        the letters read from that drawing (a reading.page.Page)."""
        return cls.of_drawing(expected, drawing, page, ocr, longer)._replace(
            build=run.build, launch=run.launch, waited=run.waited, talker=run.talker,
            stuck=run.stuck, limit=run.limit, own_triggers=own_triggers(run.events),
            chatter_peak=chatter_peak(run.events), broken=run.broken, limit_s=run.limit_s,
            waiting=run.waiting, fought=run.fought)

    @classmethod
    def of_drawing(cls, expected, drawing, page, ocr, longer=''):
        """The facts of a drawing and the letters read from it alone (a
        drawing kept and read again: driver.reread)."""
        return cls(expected, drawing=drawing, readings=page.readings, ocr=ocr,
                   writing=page.writing.ink if page.where else None, where=page.where,
                   longer=longer)


class Mark(NamedTuple):
    name: str
    score: float
    max_score: float
    output: str
    broken: bool = False    # a rule broken, whatever the points (the sandbox's limits)

    @property
    def met(self):
        return not self.broken and self.score >= self.max_score


def _number(value, where):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or value < 0:
        raise RubricError(f'{where}: {value!r} is not a number of 0 or more')
    return float(value)


def _read(path):
    try:
        with open(path) as f:
            data = yaml.safe_load(f)
    except (OSError, yaml.YAMLError) as e:
        raise RubricError(f'{path}: {e}') from None
    if not isinstance(data, dict):
        raise RubricError(f'{path}: expected a mapping of rubric entries, got {data!r}')
    return data


def _limits(given):
    """Limits of the rubric file's entries: counts whole, none missing."""
    missing = sorted(set(Limits._fields) - set(given))
    if missing:
        raise RubricError(f'limits: {", ".join(missing)} missing')
    limits = {}
    for name, kind in Limits.__annotations__.items():
        value = _number(given[name], f'limits: {name}')
        if kind is int and value != int(value):
            raise RubricError(f'limits: {name}: {given[name]!r} is not a whole number')
        limits[name] = kind(value)
    return Limits(**limits)


def load(default_path, override_path=None) -> Rubric:
    """The package's rubric, with the instructor's entries over it."""
    data = _read(default_path)
    if override_path:
        for key, value in _read(override_path).items():
            if key not in data:
                raise RubricError(f'{override_path}: unknown entry {key!r} '
                                  f'(known: {", ".join(data)})')
            if isinstance(data[key], dict):
                if not isinstance(value, dict):
                    raise RubricError(f'{override_path}: {key}: expected a mapping, got {value!r}')
                unknown = sorted(set(value) - set(data[key]))
                if unknown:
                    raise RubricError(f'{override_path}: {key}: unknown {", ".join(map(str, unknown))}'
                                      f' (known: {", ".join(data[key])})')
                value = {**data[key], **value}
            data[key] = value
    points = {k: _number(v, f'points: {k}') for k, v in data['points'].items()}
    limits = _limits(data['limits'])
    full, none = (_number(data['accuracy'][k], f'accuracy: {k}') for k in ('full', 'none'))
    if none <= full:
        raise RubricError(f'accuracy: none ({none:g}) must be above full ({full:g})')
    required = data['required']
    if not isinstance(required, list) or not set(required) <= set(points):
        raise RubricError(f'required: {required!r} is not a list of criteria '
                          f'({", ".join(points)})')
    if data.get('expected') not in EXPECTED:
        raise RubricError(f'expected: {data.get("expected")!r} is not one of {", ".join(EXPECTED)}')
    allowed = data.get('allowed')
    if not isinstance(allowed, dict) or set(allowed) != set(ALLOWED) or \
            not all(isinstance(v, bool) for v in allowed.values()):
        raise RubricError(f'allowed: {allowed!r} is not true or false for each of '
                          f'{", ".join(ALLOWED)}')
    return Rubric(data['expected'], allowed, _number(data['pass_score'], 'pass_score'), required, points,
                  full, none, limits)


def _step(step, before):
    """A step's share and line; not reached when `step` is None."""
    if step is None:
        return 0.0, f'not tried: {before}'
    return (1.0 if step.ok else 0.0), step.says


def _talker(facts, _):
    if facts.own_triggers:
        return 0.0, (f'{", ".join(facts.own_triggers)} drives the turtle and published "P" on '
                     f'/chatter itself: it draws without the trigger')
    share, line = _step(facts.talker, 'the launch failed')
    if facts.chatter_peak > CHATTER_FLOOD:
        return 0.0, f'{line}, but /chatter was flooded: {facts.chatter_peak:.0f} messages a second'
    return share, line


def _wiped(facts):
    """Words for turtlesim's canvas cleared or reset while the turtle drew
    ('' if it was not): a student may start again, and what is graded is
    the canvas as it was left, the ink laid after the last of them; or, of
    a drawing that never ended, a canvas it wiped (Drawing.shown)."""
    d = facts.drawing
    if not d or not d.wiped:
        return ''
    if d.shown:
        begun, wiped = d.shown
        return (f' (graded on the canvas turtlesim showed from {begun:.1f} to {wiped:.1f} s into '
                f'the drawing, as a TA watching saw it: the drawing never ended, and turtlesim '
                f'was cleared or reset {len(d.wiped)} times, last {d.wiped[-1][0]:.1f} s in; '
                f'the canvas left then credits fewer letters)')
    seconds, what = d.wiped[-1]
    # driver.observed read the fullest canvases wiped where this one credits not every letter
    tried = d.fullest and len(_right(facts)) < len(facts.expected)
    return (f' (graded on the canvas left after turtlesim was '
            f'{"cleared" if what == "clear" else "reset"} {seconds:.1f} s into the drawing' +
            (f', the last of {len(d.wiped)} times' if len(d.wiped) > 1 else '') +
            (f'; the drawing never ended, and the {_the_fullest(len(d.fullest))} it wiped '
             f'credit{"s" if len(d.fullest) == 1 else ""} no more letters' if tried else '') +
            ')')


def _the_fullest(count):
    return 'fullest canvas' if count == 1 else f'{count} fullest canvases'


def _shapes(readings):
    """The readings of ink with a shape to read (a level dash has none): the
    letter, its accuracy and the report all count these, in these places."""
    return [r for r in readings if r.best is not None]


def drawn(readings):
    """The letters read, left to right ('?' for ink no letter fits)."""
    return ''.join(r.letter or '?' for r in _shapes(readings))


def by_ocr(facts):
    """Whether the letters are credited on OCR's reading: it reads the
    expected text confidently where the strokes read something else, and
    the strokes read no other letter in the place of one (ocr.supports; the
    strokes' reading alone never credits a letter it did not read)."""
    return drawn(facts.readings) != facts.expected and facts.ocr is not None and \
        supports(facts.ocr, facts.expected, facts.readings)


def drawn_text(facts):
    """The letters drawn, as the row gives them: the strokes' reading (a
    small l as 'l', _small_l_at), or OCR's where it credits them, or the
    longer row the ink reads whole as (Facts.longer)."""
    if facts.longer:
        return facts.longer
    return facts.ocr.text if by_ocr(facts) else as_read(facts.readings, facts.expected)


def as_read(readings, expected):
    """The strokes' letters, each I that is the small l `expected` has in
    its place as 'l' ('?' for ink no letter fits)."""
    shapes = _shapes(readings)
    return ''.join('l' if _small_l_at(shapes, k, expected) else r.letter or '?'
                   for k, r in enumerate(shapes))


def _small_l_at(shapes, k, expected):
    """Whether reading k of `shapes` (_shapes) is the small l `expected`
    has there: past the first letter (a capital), read as an I within CLEAN
    of a form narrower than BARE of its height (a bare stroke, upright or
    slanted; a serif I's bars are no l's), and standing SMALL_L as high as
    the row's tallest letter or more. The ink is an I's as much: the roster
    says which was meant, as a TA reads it."""
    reading = shapes[k]
    if not 0 < k < len(expected) or expected[k] != 'L' or reading.letter != 'I' or \
            reading.best.fit > CLEAN:
        return False
    width, height = _size(reading)
    return width < BARE * height and \
        height >= SMALL_L * max(_size(r)[1] for r in shapes)


def _size(reading):
    """(width, height) of the letter read, turned back by its tilt: its best
    fit's strokes lie on the ink's box."""
    points = [p for line in turned(reading.best.strokes, -reading.best.tilt, (0.0, 0.0))
              for p in line]
    return box(points)[2:] if points else (0.0, 0.0)


def credited_as_small_l(reading, letter):
    """Whether a credited (reading, letter) is a small l (_small_l_at): an I
    credited as an L (OCR credits no letter the strokes read as another)."""
    return reading.letter == 'I' and letter == 'L'


def fit_of(reading, letter):
    """The Fit a credited `letter` is judged by: its own, or a small l's, the I's."""
    return reading.best if credited_as_small_l(reading, letter) else reading.fits[letter]


def credited(facts):
    """(reading, letter) of each expected letter credited in its place."""
    return _right(facts) if _letter(facts, None)[0] > 0 else []


def _right(facts):
    """(reading, letter) of each expected letter drawn in its place: where
    OCR credits the row and the strokes were read as many letters, each
    reading with its expected letter (its fit to that letter is its accuracy)."""
    shapes = _shapes(facts.readings)
    if by_ocr(facts) and len(shapes) == len(facts.expected):
        return list(zip(shapes, facts.expected))
    return [(r, e) for k, (r, e) in enumerate(zip(shapes, facts.expected))
            if r.letter == e or _small_l_at(shapes, k, facts.expected)]


def letter_line(facts):
    """The letter criterion's line of feedback, as results.json shows it."""
    return shown(_letter(facts, None)[1])


def _letter(facts, rubric):
    if by_ocr(facts) and not facts.broken:
        strokes = drawn(facts.readings) or 'no letter'
        return 1.0, (f'drew {facts.expected}, as expected: {ocr_said(facts.ocr)}; its strokes '
                     f'read {strokes}' + _where(facts) + _wiped(facts))
    share, line = _letter_read(facts, rubric)
    shapes = _shapes(facts.readings)
    disagree = facts.ocr is not None and facts.ocr.text != drawn(facts.readings) and shapes
    return share, line + (f' ({ocr_said(facts.ocr)})' if disagree else '') + \
        (_teleported(facts) if shapes and share < 1 else '') + _where(facts) + _wiped(facts)


def _where(facts):
    """Words for the letters read in part of the canvas's ink ('' if in all
    of it): a frame round them, or another line of writing, left out."""
    return f' ({facts.where})' if facts.where else ''


def _teleported(facts):
    """Words for ink teleports laid beside the ink read ('' if none did):
    what the student sees drawn is more than what is read (a class's M laid
    by teleports, the dot of its i driven)."""
    jumps = facts.drawing.jump_ink if facts.drawing else 0
    return (f'; {jumps} teleport{"s" if jumps > 1 else ""} with the pen down laid ink '
            f'no letter is read from') if jumps else ''


def _moved_inkless(drawing):
    """': which turtles moved and laid no ink', or '': a real package turned
    27 turtles spawned in the shape of a G, and 'nothing was drawn' stood
    beside its 11,286 commands."""
    if drawing is None or not drawing.turtles:
        return ''
    moved = drawing.turtles
    who, its = (moved[0], 'its pen') if len(moved) == 1 else (f'{len(moved)} turtles',
                                                               'their pens')
    placed = (f', and {drawing.spawns} were spawned or killed: a letter is the ink turtles lay '
              f'as they drive, not where turtles stand') if drawing.spawns > 1 else ''
    return f': {who} moved and laid no ink (turned in place, or drove with {its} up){placed}'


def _letter_read(facts, _):
    if facts.broken:
        return 0.0, f'{facts.broken}: nothing drawn is credited'
    read = _shapes(facts.readings)
    if not read and facts.drawing and flooded(facts.drawing.strokes, len(facts.expected) or 1):
        return 0.0, (f'no letter is read from a flood of ink: more than {LONGEST} times its '
                     f'height for each letter expected (a letter is drawn with far less)')
    if not read and facts.drawing and facts.drawing.strokes:     # ink of no shape (ink.dash)
        _, _, w, h = box(facts.drawing.points)
        return 0.0, (f'no letter reads from the ink: a dash, {w:.2f} m across and {h:.2f} m '
                     f'high (no letter is drawn so flat)')
    if not read:
        teleported = facts.drawing.jump_ink if facts.drawing else 0
        return 0.0, (f'no ink was driven: {teleported} teleport{"s" if teleported > 1 else ""} '
                     f'laid all there is' if teleported else 'nothing was drawn' +
                (f': {facts.stuck or facts.waiting}' if facts.stuck or facts.waiting else
                 _moved_inkless(facts.drawing)))
    if len(read) == 1 and read[0].letter is None:
        closest = (f'closest: {read[0].best.letter}, {100 * read[0].best.fit:.0f}% of its '
                   f'height off')
        if facts.longer:
            return 0.0, (f'drew {facts.longer} where one letter, {facts.expected}, is expected '
                         f'({_longer_said(facts)}); read as one letter, none reads ({closest})' +
                         _cut_short(facts))
        return 0.0, f'no letter reads from the path ({closest})' + _cut_short(facts)
    text = as_read(facts.readings, facts.expected)
    if not facts.expected:
        return 0.0, (f'drew {text}, but no letter is expected: give it in the roster (its '
                     f'letter column, or a name)')
    right = len(_right(facts))
    said_l = _small_l_said(text, facts.expected)
    if text.upper() == facts.expected:
        return 1.0, f'drew {text}, as expected{said_l}'
    wrong = f'drew {text}, expected {facts.expected}'
    said_l += _cut_short(facts)
    if len(facts.expected) == 1:
        loose = nearest_only(facts)
        return 0.0, (_nearest(loose, facts.expected) if loose else wrong) + said_l + \
            _and_longer(facts)
    return right / max(len(text), len(facts.expected)), \
        f'{wrong}: {right} in place{said_l}{_and_longer(facts)}'


def _longer_said(facts):
    """Words for the longer row the ink reads whole as (Facts.longer)."""
    return (f'read as a row of {len(facts.longer)}, it reads {facts.longer} whole: a roster '
            f'that asks for {facts.longer} credits it, and a longer row is not searched for '
            f'the letters asked')


def _and_longer(facts):
    return f'; {_longer_said(facts)}' if facts.longer else ''


def nearest_only(facts):
    """The one letter read where one other is expected, read past CLEAN:
    it reads no letter beyond doubt, and is said to lie nearest that one,
    not to draw it (a real class's cursive L, its loops at both ends, lay
    nearest a P tilted 48 degrees, 10% of its height off: it drew no P).
    None where there is none such."""
    read = _shapes(facts.readings)
    if len(facts.expected) == 1 and len(read) == 1 and \
            read[0].letter not in (None, facts.expected) and read[0].best.fit > CLEAN:
        return read[0]
    return None


def _nearest(reading, expected):
    return (f'no letter reads cleanly, and {reading.letter} is the nearest, '
            f'{100 * reading.best.fit:.0f}% of its height off (within {100 * CLEAN:g}% a '
            f'letter reads beyond doubt): expected {expected}')


def _cut_short(facts):
    """'; where a script stopped at a rostopic pub that never exits' (a
    letter drawn in part), or ''."""
    return f'; {facts.waiting}' if facts.waiting else ''


def _small_l_said(text, expected):
    """Words for an L expected and read as a small l (_small_l_at), or read as
    an I that is none (the first letter, a serif I, a short stroke)."""
    if 'l' in text:
        return '; its l one bare stroke, as a small l is written'
    if any(t == 'I' and e == 'L' for t, e in zip(text, expected)):
        return ('; the L reads as an I: a small l is credited past the first letter, one bare '
                f'stroke at least {SMALL_L:.0%} as high as the row (a capital L reads)')
    return ''


def _accuracy(facts, rubric):
    """How cleanly the ink makes the letters credited (reading.cleanness),
    not how close it lies to any font: the worse of its wobble and half its
    gap (one spot, where a wobble is a whole stroke), full to none linearly,
    a share for each letter in its place."""
    right = _right(facts) if _letter(facts, rubric)[0] > 0 else []
    if not right:
        return 0.0, f'not scored: {_letter(facts, rubric)[1]}'
    stray = strays(facts.writing or facts.drawing.strokes)     # the ink the letters were read in
    worst = max(stray.wobble, stray.gap / 2)
    counted = max(len(_shapes(facts.readings)), len(facts.expected))
    share = min(1.0, max(0.0, (rubric.none - worst) / (rubric.none - rubric.full))) * \
        len(right) / counted
    # a share for each letter in place: the line says so, or a clean row's half is a riddle
    part = f'; for {len(right)} of the {counted} letters, those in place' \
        if len(right) < counted else ''
    gap = (f'a line misses itself by {100 * stray.gap:.1f}% where it comes back (counted half)'
           if stray.gap else 'its loops close')
    tilts = sorted({fit_of(r, e).tilt for r, e in right} - {0.0}, key=abs)
    tilted = f', drawn {abs(tilts[-1]):g} degrees off level' if tilts else ''
    return share, (f'its strokes stray {100 * stray.wobble:.1f}% of its height from the lines '
                   f'and arcs they draw, and {gap} (every point at {100 * rubric.full:g}% or '
                   f'less, none from {100 * rubric.none:g}%){tilted}{part}')


def _ends(facts, rubric):
    d = facts.drawing
    if facts.broken:
        return 0.0, f'not scored: {facts.broken}'
    if d is None or d.started is None:
        return 0.0, 'the turtle never moved after the trigger' + (
            f': {facts.stuck}' if facts.stuck else '')
    if d.ended is None and facts.fought:
        return 0.0, f'{facts.fought}, and the grader stopped them: the drawing never ended'
    if d.ended is None:
        limit = round(facts.limit_s or rubric.limits.drawing, 1)
        shared = (f' (run alone, with what was left of the {rubric.limits.drawing:g} s the '
                  f'alone runs share)' if limit < rubric.limits.drawing else '')
        return 0.0, (f'the turtle was still moving {limit:g} s after it started{shared}: '
                     f'the drawing never ended')
    return 1.0, f'ended after {d.seconds:.1f} s, the turtle standing still'


def _not_allowed(d, allowed):
    """What the drawing used that the rubric does not allow, in words, or ''."""
    used = [(d.jumps, 'teleport', 'teleported'), (d.spawns, 'spawn', 'spawned or killed'),
            (d.pens, 'set_pen', 'called set_pen')]
    said = [f'{words} {_counted(n, "time")}' for n, name, words in used
            if n and not allowed[name]]
    return f'{", ".join(said)}: the rubric does not allow it' if said else ''


def _driven(facts, rubric):
    d = facts.drawing
    if facts.broken:
        return 0.0, facts.broken
    if d is None:
        return 0.0, 'not tried: the lab did not run'
    if d.impostors:
        return 0.0, (f'{", ".join(d.impostors)} posed as turtlesim (published poses or served '
                     f'/spawn): nothing it says is evidence, and it is not credited')
    if _not_allowed(d, rubric.allowed):
        return 0.0, _not_allowed(d, rubric.allowed)
    if d.jump_ink:
        return 0.0, (f'{d.jump_ink} teleport{"s" if d.jump_ink > 1 else ""} with the pen down '
                     f'laid ink: ink is credited only where a turtle was driven')
    if d.started is None:
        return 0.0, 'the turtle never moved'
    if d.commands == 0:
        return 0.0, 'the turtle moved, but no command came on cmd_vel'
    return 1.0, 'driven over cmd_vel: ' + ', '.join(filter(None, [
        f'{d.commands} commands', d.jumps and _counted(d.jumps, 'teleport') + ' with the pen up',
        _counted(d.pen_lifts, 'pen lift'),
        f'by {", ".join(d.turtles)}' if d.turtles not in ([], ['turtle1']) else '']))


def _counted(n, what):
    return f'{n} {what}{"s" if n > 1 else ""}' if n else ''


CRITERIA = {
    'builds': ('It builds', lambda f, r: _step(f.build, f.problem)),
    'launches': ('It launches', lambda f, r: _step(f.launch, 'the build failed')),
    'talker': ('The talker publishes P on a key press', _talker),
    'waits': ('The turtle waits for the trigger', lambda f, r: _step(f.waited, 'the launch failed')),
    'letter': ('The letter drawn is the expected one', _letter),
    'accuracy': ('Its accuracy', _accuracy),
    'ends': ('The drawing ends, the turtle standing still', _ends),
    'driven': ('The turtle was driven over cmd_vel', _driven),
}


class Grade(NamedTuple):
    tests: List[Mark]
    score: float
    max_score: float
    verdict: str            # pass or fail
    reason: str             # the first thing that cost points, or what it achieved


def grade(facts: Facts, rubric: Rubric) -> Grade:
    """Each criterion's mark; a limit of the sandbox reached fails the submission."""
    marks = []
    for name, points in rubric.points.items():
        title, judge = CRITERIA[name]
        share, line = judge(facts, rubric)
        marks.append(Mark(title, round(share * points, 2), points, shown(line)))
    missed = [m for name, m in zip(rubric.points, marks) if name in rubric.required and not m.met]
    tests = ([Mark("It keeps within the sandbox's limits", 0.0, 0.0, shown(facts.limit), True)]
             if facts.limit else []) + marks
    score = round(sum(t.score for t in tests), 2)
    total = sum(t.max_score for t in tests)
    lost = next((t for t in tests if not t.met), None)
    reason = f'{lost.name}: {lost.output}' if lost else 'every criterion met'
    passed = score >= rubric.pass_score and not missed and not facts.limit
    return Grade(tests, score, total, 'pass' if passed else 'fail',
                 reason + _failed_on(missed, lost))


def _failed_on(missed, lost):
    """Words for the required criterion a fail missed, where another lost
    points first and it says more than that nothing came of it ('' if
    not): a row that begins with a lost launch file still says why no
    letter was credited."""
    if not missed or missed[0] is lost or missed[0].output == 'nothing was drawn' or \
            missed[0].output.startswith(('not tried', 'not scored')):
        return ''
    return f'; failed on {missed[0].name}: {missed[0].output}'

