"""The letters a person sees in the ink: the ink drawn as a picture, black
on white, and read by Tesseract (Debian's tesseract-ocr, through
tesserocr), A-Z only. The second reader beside the strokes'
(recognition.py): it reads touching letters, outlines and curves as a
person does, and no template decides what it sees. No ROS here.

The expected text is the hypothesis to verify: the ink is read level and,
unless it reads confidently as another text as it lies, turned back by
each of TILTS and by the turn that stands it squarest, then narrowed (a
letter drawn twice as wide is no print letter to Tesseract); a reading
of the expected text at CONFIDENT or more (CONFIDENT_TURNED turned or
narrowed) is kept, with any reading of another view that leaves it in
doubt (_rival; read level, its reading stood upright, _upright_rival);
else the expected text where its readings vote for it (_voted); else the
reading level. (Turned, a J read as an S at 86%: what reads as something
else level is not turned until it reads as hoped.) A reading of the
expected text is read again, the ink drawn at other sizes, and holds
where one of them reads it too (_held).
"""
import collections
import os
import string
import threading
from typing import NamedTuple

from .ink import box, closed, dash, flooded, squarest_turn, thinned, turned
from .forms import CLEAN
from .recognition import (AMBIGUOUS, TWIN_LEVEL, TWINS, Reading, Unfinished, bounded,
                          plainly_other, quarter_apart, twin_farther)
from .rows import letters_of, levels, read_blind, without_specks

GLYPH_PX = 64           # the row's height in the picture (Tesseract reads 20 to 100 px best)
# ... the heights a reading of the expected text is tried at again: it holds where it reads
# at one of them too (a script IX read IG 89% sure at 64 px, SL at 48, IU at 80)
OTHER_PX = (48, 80)
PAD_PX = 16
CONFIDENT = 80          # Tesseract's confidence (0-100) from which a reading is believed
CONFIDENT_TURNED = 90   # ... turned back: each turn is one more chance to see what is hoped
TILTS = (0, -15, 15, -30, 30, -45, 45)      # degrees the ink is turned back by to be read
NEAR = 2.5          # degrees off within which a turn is as good as another
NARROWER = (0.7, 0.5)   # shares of its width the ink is read at last: a letter drawn wide
MAX_WIDTH_PX = 2000     # a wider picture (a flood of ink) is read narrowed to this
SURE = 95           # Tesseract's confidence in a reading's least sure letter, for a vote (_voted)
AS_SURE = 5         # confidence points below a turned Q within which another reading doubts it
_apis = threading.local()       # Tesseract's handles are not shared between threads
_drawn = threading.local()      # the height pictures are drawn at, while read_text reads
# Tesseract's OpenMP would take every core while it reads: the grader reads
# one student's ink while another's timed controller draws on the other core.
os.environ.setdefault('OMP_THREAD_LIMIT', '1')


class OcrReading(NamedTuple):
    text: str               # A-Z, '' when nothing reads
    confidence: float       # 0-100
    tilt: float = 0.0       # degrees the ink lies off level
    width: float = 1.0      # share of its width the ink was read at
    objection: str = ''     # the strokes' plainly other letter, read blind ('D in place of L')
    votes: tuple = ()       # ((text, readings of it), ...): where the readings voted (_voted)
    rival: object = None    # an OcrReading of the ink that leaves this one in doubt (_rival)
    unheld: tuple = ()      # (px, OcrReading) of each other height it does not hold at (_held)
    letters: float = 0.0    # its confidence in the least sure letter, where the text is
                            # the one expected or the word's confidence is 0 (else 0)


def picture(ink, filled=False):
    """`ink` (lines of (x, y), m) drawn black on white, the row GLYPH_PX
    high (or as high as _held draws it); `filled`: its closed lines
    filled, even-odd (an outline letter read as the solid letter it
    outlines, as a person sees it)."""
    from PIL import Image, ImageChops, ImageDraw
    x0, y0, w, h = box([p for line in ink for p in line])
    glyph_px = getattr(_drawn, 'px', GLYPH_PX)
    scale = glyph_px / max(h, w / (MAX_WIDTH_PX / glyph_px), 1e-9)
    width, height = int(w * scale) + 2 * PAD_PX, int(h * scale) + 2 * PAD_PX

    def px(line):
        return [((x - x0) * scale + PAD_PX, height - ((y - y0) * scale + PAD_PX)) for x, y in line]
    inside = Image.new('1', (width, height), 0)
    for line in (ink if filled else []):
        if closed(line, h):
            shape = Image.new('1', (width, height), 0)
            ImageDraw.Draw(shape).polygon(px(line), fill=1)
            inside = ImageChops.logical_xor(inside, shape)
    image = Image.new('L', (width, height), 255)
    image.paste(0, mask=inside)
    draw = ImageDraw.Draw(image)
    pen = max(2, glyph_px // 10)
    for line in ink:
        if filled and closed(line, h):
            continue
        points = px(line)
        if len(points) > 1:
            draw.line(points, fill=0, width=pen, joint='curve')
        for x, y in points[:1] + points[-1:]:       # round ends, as a pen leaves them
            draw.ellipse((x - pen / 2, y - pen / 2, x + pen / 2, y + pen / 2), fill=0)
    return image


def _api(mode):
    """This thread's Tesseract in page segmentation `mode`, A-Z only."""
    import tesserocr
    api = getattr(_apis, mode, None)
    if api is None:
        api = tesserocr.PyTessBaseAPI(psm=getattr(tesserocr.PSM, mode), lang='eng')
        api.SetVariable('tessedit_char_whitelist', string.ascii_uppercase)
        setattr(_apis, mode, api)
    return api


def _read_picture(ink, expected, needed=CONFIDENT):
    """(text, confidence) of the picture of `ink` (_pictures): the first
    reading of `expected` at `needed` or more, else the word's reading."""
    first = None
    for text, confidence, _ in _pictures(ink, expected):
        if text == expected and confidence >= needed:
            return text, confidence
        first = first or (text, confidence)
    return first


def _pictures(ink, expected):
    """(text, confidence, the least sure letter's confidence where the text
    is `expected` or the word's confidence is 0, else 0) of each reading of
    the picture of `ink`, in turn:
    read as a word, then as a line of letters or one letter, then (ink with
    contours) filled, the same two ways. (Each reads some drawings the
    others miss: a real class's ZA, the Z's foot run into the A, read as a
    word gave ZA at 93%, as a line A, as a letter LZ; DejaVu's outlines read
    6 and 9 of 26 as lines, 21 and 22 filled.)"""
    modes = ('SINGLE_WORD', 'SINGLE_CHAR' if len(expected) == 1 else 'SINGLE_LINE')
    height = box([p for line in ink for p in line])[3]
    for filled in (False, True):
        if filled and not any(closed(line, height) for line in ink):
            return
        image = picture(ink, filled)      # drawn once for both modes, only when asked
        for mode in modes:
            api = _api(mode)
            api.SetImage(image)
            text = ''.join(c for c in api.GetUTF8Text() if c in string.ascii_uppercase)
            confidence = float(api.MeanTextConf()) if text else 0.0
            yield (text, confidence,
                   _least_sure(api) if text and (text == expected or _no_word_confidence(confidence))
                   else 0.0)


def _no_word_confidence(confidence):
    """Whether Tesseract gave the word it read no confidence (0%, as a row says
    it): then its least sure letter's is taken too (_pictures), and said (_sure)."""
    return not round(confidence)


def _least_sure(api):
    """Tesseract's confidence (0-100) in the least sure letter it read last."""
    import tesserocr
    symbol = tesserocr.RIL.SYMBOL
    return min((r.Confidence(symbol) for r in tesserocr.iterate_level(api.GetIterator(), symbol)
                if (r.GetUTF8Text(symbol) or '') in string.ascii_uppercase), default=0.0)


def read_text(ink, expected='') -> OcrReading:
    """What Tesseract reads in `ink`, as a row of `expected`'s length: the
    expected text if its letters read alone (level, or turned back by the
    row's slope; not where the row read whole is plainly another text)
    or the whole at any tilt read it at CONFIDENT or more
    (CONFIDENT_TURNED turned or narrowed), else the most confident reading of the ink
    as it lies. A row read as expected carries the strokes' objection, if
    they see another letter plainly in a place (_objected). The strokes'
    part in it is bounded (recognition.bounded): cut short, OCR reads no
    letter, since the strokes could not check it. A reading of the
    expected text that nothing doubts carries the other heights of the
    picture it does not hold at (_held)."""
    with bounded():
        try:
            reading = _read_text(ink, expected)
            if not _believed(reading, expected):
                return reading
            reading = _objected(ink, reading)
            doubted = reading.objection or reading.rival is not None
            return reading if doubted else _held(ink, expected, reading)
        except Unfinished:
            return OcrReading('', 0.0)


def _believed(reading, expected):
    return bool(expected) and reading.text == expected and \
        reading.confidence >= _needed(reading.tilt, reading.width)


def _held(ink, expected, reading):
    """`reading` of the expected text, with the readings of the ink drawn
    OTHER_PX high where neither reads it too: letters drawn read at each
    size, and a reading at one only is a likeness of that picture. (A
    script IX graded as IG read IG 89% sure at 64 px, SL and IU at 48 and
    80; of the 292 drawings of the recognition benchmark that only OCR
    read right, 289 hold.)"""
    unheld = []
    for px in OTHER_PX:
        _drawn.px = px
        try:
            again = _read_text(ink, expected)
        finally:
            del _drawn.px
        if _believed(again, expected):
            return reading
        unheld.append((px, again))
    return reading._replace(unheld=tuple(unheld))


def _read_text(ink, expected):
    points = [p for line in ink for p in line]
    if len(points) < 2 or dash(ink, max(1, len(expected))) or \
            flooded(ink, max(1, len(expected))):
        return OcrReading('', 0.0)     # a flood (ink.flooded): thinned, chords; whole, a blot
    kept = without_specks(ink)      # a level line beside specks is a dash too: no row to cut
    rows = levels(kept, len(expected)) if len(expected) > 1 and not dash(kept, len(expected)) \
        else []
    if rows and _plainly_other(rows, expected):
        rows = []       # not read letter by letter
    for slope, _, upright in rows:
        alone = _letter_by_letter(upright, expected, _needed(slope))._replace(tilt=float(slope))
        if supports(alone, expected):
            return alone
    x, y, w, h = box(points)
    ink, centre = thinned(ink, h / 200), (x + w / 2, y + h / 2)
    level, votes, surest, seen = None, collections.Counter(), OcrReading('', 0.0), []
    views = [(tilt, width, centre) for tilt, width in _views(ink)]
    for k, view in enumerate(views):
        first = None
        for reading, sure in _read_view(ink, view, expected):
            if expected and reading.text == expected and \
                    reading.confidence >= _needed(reading.tilt, reading.width):
                return _rivalled(reading, seen, ink, views[k:])
            seen.append(reading)
            votes[_once(reading.text, expected)] += 1
            surest = max(surest, reading._replace(confidence=sure), key=lambda r: r.confidence)
            first = first or reading
        if level is None:
            level = first
            if level.confidence >= CONFIDENT:   # it reads as another text as it lies: that is it
                return level
    voted = _voted(votes, surest, expected)
    return voted if voted is not None else level


def _read_view(ink, view, expected):
    """Each reading of `ink` (thinned) seen at `view` (_views' degrees turned
    back by about a centre, and share of its width), as (OcrReading,
    _pictures' least sure letter where it reads `expected`, else 0)."""
    tilt, width, centre = view
    upright = turned(ink, -tilt, centre) if tilt else ink
    if width != 1.0:
        upright = [[(px * width, py) for px, py in line] for line in upright]
    for text, confidence, letters in _pictures(upright, expected):
        yield OcrReading(text, confidence, float(tilt), width, letters=letters), \
            letters if text == expected else 0.0


def _rivalled(reading, seen, ink, views):
    """`reading` of the expected text with the rival reading that doubts
    it, if one does: read level, its reading stood upright (_upright_rival);
    turned or narrowed, of those `seen` before it and of every reading of
    `views` (_rival; read only where one may doubt it)."""
    text = reading.text
    if not reading.tilt and reading.width == 1.0:
        return reading._replace(rival=_upright_rival(reading, ink, views[0][2]))
    if 'Q' in text or text in TWINS:
        later = [r for view in views for r, _ in _read_view(ink, view, text)]
        rival = next((r for r in seen + later if _rival(reading, r)), None)
        if rival is not None:
            return reading._replace(rival=rival)
    return reading


def _upright_rival(reading, ink, centre):
    """The reading of `ink` turned back by its squarest turn (ink.squarest_turn,
    where it is more than NEAR off level) that doubts `reading`, its level
    reading: another text read CONFIDENT or more in two of that view's
    readings, and the expected one in none. An outline stands upright at
    its squarest turn, and a person reads it there. (A DejaVu Serif Bold Z
    drawn round its edge, tilted 30 degrees, read level is an L 91% sure;
    turned back 30 degrees, a Z 87 and 83% sure. Of the recognition
    benchmark's 426 drawings that OCR reads level, as drawn, as their own
    text, one is doubted so, a DejaVu Sans Bold YVF read YVE upright: its
    strokes read it.)"""
    square = squarest_turn(ink)
    if abs(square) <= NEAR:
        return None
    upright = [r for r, _ in _read_view(ink, (square, 1.0, centre), reading.text)]
    if any(r.text == reading.text for r in upright):
        return None
    sure = collections.Counter(r.text for r in upright if r.text and r.confidence >= CONFIDENT)
    other = next((text for text, count in sure.most_common(1) if count >= 2), None)
    return max((r for r in upright if r.text == other), key=lambda r: r.confidence,
               default=None)


def _rival(reading, other):
    """Whether OCR's `other` reading of the ink doubts its turned `reading`:
    Tesseract reads a Q in round letters, level or turned (a C, D, G, O or
    P, 86 to 93% sure), so another letter read in a Q's place, less
    than AS_SURE below it, leaves it in doubt (a DejaVu Sans Bold P turned
    back 45 degrees read Q 90% sure, and 22.5 degrees, P 87%); and a
    letter's twin (recognition.TWINS), read CONFIDENT a quarter-turn from
    it and TWIN_LEVEL or more nearer level, is what a person reads (a
    DejaVu Serif Bold Z 31 degrees off read N 91% turned back -45, and Z
    85 to 90% turned back 30)."""
    text, seen = reading.text, _once(other.text, reading.text)
    if len(seen) == len(text) and other.confidence > reading.confidence - AS_SURE and \
            any(a == 'Q' and b != 'Q' for a, b in zip(text, seen)):
        return True
    return seen == TWINS.get(text) and other.confidence >= CONFIDENT and \
        quarter_apart(reading, other) and abs(other.tilt) + TWIN_LEVEL <= abs(reading.tilt)


def _once(text, expected):
    """`text`, a letter read twice taken once where one letter is expected
    (Tesseract's LSTM reads a wide letter twice over: a DejaVu Sans Bold T
    stretched and turned read T in 9 readings and TT in 9)."""
    return text[0] if len(expected) == 1 and len(text) == 2 and text[0] == text[1] else text


def _voted(votes, surest, expected):
    """The expected text, as `surest` read it, where more of the readings
    (`votes`: each view read as a word and as a letter or line, drawn and
    filled, up to 40 in all; no letter is no vote) read it than any other
    text, and one read each of its letters SURE or more; else None.
    Tesseract's word confidence is 0 for some letters it reads in view
    after view, each letter 95% sure or more (DejaVu Bold outlines of Z, W,
    P, X, stretched and turned); taken one by one, a letter that sure is
    seen in a reading or two where it is not drawn (a V as a W, 99% sure,
    in 2 readings of 36, as a V in 9)."""
    rivals = [count for text, count in votes.items() if text not in ('', expected)]
    if expected and surest.text == expected and surest.confidence >= SURE and \
            votes[expected] > max(rivals, default=0):
        return surest._replace(votes=tuple(sorted(votes.items())))
    return None


def _objected(ink, reading):
    """`reading` of a row of letters, with the strokes' objection where,
    cutting the row not knowing the roster (rows.read_blind), they read
    another letter plainly in a place (plainly_other). (A scripts ADP read
    ALP by OCR, 81% sure, and credited: cut blind, its D is a D within 3.2%
    of its height, where an L fits no better than 15%.)"""
    if len(reading.text) < 2:
        return reading
    for r, e in zip(read_blind(ink, len(reading.text)), reading.text):
        if plainly_other(r, e):
            return reading._replace(objection=f'{r.letter} in place of {e}')
    return reading


def _views(ink):
    """(degrees turned back by, share of its width) the ink is read at, in
    turn: level, its squarest turn (ink.squarest_turn) where not within NEAR
    of one of TILTS, each of TILTS, then squarest and NARROWER."""
    square = squarest_turn(ink)
    tilts = TILTS
    if all(abs(square - tilt) > NEAR for tilt in TILTS):
        tilts = TILTS[:1] + (square,) + TILTS[1:]
    return [(tilt, 1.0) for tilt in tilts] + [(square, width) for width in NARROWER]


def _needed(tilt, width=1.0):
    """The confidence a reading of the expected text needs, read turned
    back by `tilt` and at `width` of its width: each view but the ink as
    it lies is one more chance to see what is hoped."""
    return CONFIDENT_TURNED if tilt or width != 1.0 else CONFIDENT


def _plainly_other(rows, expected):
    """Whether the row (rows.levels), read whole at its slope, is plainly
    another text: a person sees that text, however the ink is cut. (The
    cuts seek the expected letters: a CH cut where its H's stem ends the
    C read letter by letter as QY, 87 and 83% sure; whole, it read CH 94%.)"""
    text, confidence = _read_picture(rows[0][2], expected)
    return text != expected and confidence >= CONFIDENT


def _letter_by_letter(ink, expected, needed):
    """Each letter the strokes' reader sets apart or cuts (level) read
    alone: letters whose ink touches read as one line may be read alone.
    The least sure letter's confidence is the row's."""
    if len(expected) < 2:
        return OcrReading('', 0.0)
    read = []
    for letter, (alone, shared) in zip(expected, letters_of(ink, expected)):
        text, confidence = _read_picture(alone, letter, needed) if alone else ('', 0.0)
        if (text != letter or confidence < needed) and shared:
            text, confidence = max([(text, confidence), _read_picture(shared, letter, needed)],
                                   key=lambda r: (r[0] == letter, r[1]))
        read.append((text, confidence))
    if not read:
        return OcrReading('', 0.0)
    return OcrReading(''.join(text for text, _ in read), min(c for _, c in read))


def told_apart(ink, readings):
    """The strokes' `readings` (rows.read_row), a letter dropped where
    another letter fits its place within CLEAN too and OCR reads the ink
    with that other one there (_reads_rival): where the strokes see two
    letters plainly, OCR tells them apart whichever the roster says
    (DejaVu Serif Bold's J drawn round its edge is an I within 2.2% of its
    height and a J within 6.1% to the strokes, a J 84 to 95% sure to OCR
    level; tilted 38 degrees, a J to OCR only turned back; beside a C, its
    middle line an I within 4.1%, a T, a J, a B and an F within 7%, and
    the row a CJ to OCR)."""
    told = list(readings)
    for k, reading in enumerate(readings):
        if reading.letter is None or reading.best.fit > CLEAN:
            continue
        rivals = sorted(c for c, f in reading.fits.items()
                        if c != reading.letter and f.fit <= CLEAN)
        if any(_reads_rival(ink, readings, k, rival) for rival in rivals):
            told[k] = Reading(None, reading.best, reading.fits)
    return told


def _reads_rival(ink, readings, k, rival):
    """Whether OCR reads `ink` as the strokes' letters with `rival` in place
    k (a row with a letter unread is not read), as it lies (CONFIDENT or
    more) or turned back by the tilt the strokes fit the rival at
    (CONFIDENT_TURNED). Not turned for the letter's twin
    (recognition.TWINS): OCR takes a Z turned a quarter for an N."""
    letters = [r.letter for r in readings]
    if None in letters:
        return False
    text = ''.join(letters[:k] + [rival] + letters[k + 1:])
    reading = readings[k]
    x, y, w, h = box([p for line in ink for p in line])
    level = thinned(ink, h / 200)
    tilt = reading.fits[rival].tilt if rival != TWINS.get(reading.letter) else 0
    for turn in ((0, tilt) if tilt else (0,)):
        view = turned(level, -turn, (x + w / 2, y + h / 2)) if turn else level
        read, confidence = _read_picture(view, text, _needed(turn))
        if read == text and confidence >= _needed(turn):
            return True
    return False


def supports(reading: OcrReading, expected: str, strokes=()) -> bool:
    """Whether the reading is the expected text, confidently, and none of
    the strokes' readings (recognition.Reading) is another letter: where
    the two readers each read a letter and differ, neither is credited.
    (A Z turned a quarter is an N to OCR, the strokes read it a Z; a round
    O with no tail is a Q to OCR 90% sure, the strokes read it an O within
    2% of its height; a rowmans L stretched and tilted 42 degrees is a V
    to OCR 91% sure read narrowed, an L within 1.4% to the strokes, who
    fit a V within 2.8% too. A serif J drawn round its edge, whose thin
    hook its middle line hardly keeps, is an I within 2.2% of its height
    and a J within 6.1%: told_apart drops the strokes' I, and OCR's J,
    95% sure, is credited.) Nor is it where OCR
    read the ink turned and the strokes' best fit is the expected letter's
    twin (recognition.TWINS): turned, a Z is an N to OCR; nor where the
    views voted for it and the strokes lean to another text (_contradicted);
    nor where another of OCR's readings leaves it in doubt (_rival); nor
    where OCR reads an O the strokes see a Q's tail on (_tail_missed);
    nor where it holds at one size of the picture only (_held)."""
    if not (_believed(reading, expected) and not reading.objection and
            reading.rival is None and not reading.unheld):
        return False
    return not _contradicted(reading, strokes) and not any(
        r.letter not in (None, e) or (reading.tilt and _twin_fits(r, e)) or _tail_missed(r, e)
        for r, e in zip(strokes, expected))


def _tail_missed(reading, expected):
    """Whether `expected` is an O and the strokes' best fit in its place,
    read or not, is a Q within the fit it reads at: a Q's tail is all that
    tells it from an O, and Tesseract misses a short one the strokes fit.
    (A DejaVu Sans Bold GQB drawn round its edges, tilted 20 degrees, is a
    GOB to OCR 94% sure; its middle letter is a Q within 12% of its height
    to the strokes, an O within 15%. Of the recognition benchmark's 160
    single O's and Q's, each read as both, none fits the other best; nor
    does any O of its 500 rows read as its own text.)"""
    best = reading.best
    return expected == 'O' and best is not None and best.letter == 'Q' and \
        best.fit <= best.readable


def _contradicted(reading, strokes):
    """Whether `reading` was voted for (_voted) and the strokes' best fits,
    read or not, spell another text that two readings or more read: the two
    readers lean each to another text. (A DejaVu Serif Bold O, stretched
    and turned, read Q in 7 readings of 36 and O in 3, its best fit an O.)"""
    guess = ''.join(r.best.letter if r.best else '?' for r in strokes)
    return bool(guess) and guess != reading.text and dict(reading.votes).get(guess, 0) >= 2


def _twin_fits(reading, expected):
    """Whether the strokes' best fit (recognition.upright_twin's choice) is
    `expected`'s twin, within the fit it reads at, and they read it, or
    `expected` fits only a quarter-turn from it, farther from level. (A
    DejaVu Serif Bold outline C fit a U at -52 degrees a little better
    than its own C at 20, read neither, and OCR's C was refused.) Or,
    where the strokes did not read `expected`, the twin fits within CLEAN,
    as well as `expected` (within AMBIGUOUS), a quarter-turn from it: the
    ink is either, as it lies. (A rowmans N tilted 44 degrees is an N
    within 2.0% of its height and a Z within 2.2%, at 45 and -45 degrees:
    turned back 45 degrees, OCR read a Z 90% sure.)"""
    own, twin = reading.fits.get(expected), reading.fits.get(TWINS.get(expected))
    if reading.letter != expected and own is not None and twin is not None and \
            twin.fit <= min(CLEAN, own.fit + AMBIGUOUS) and quarter_apart(own, twin):
        return True
    best = reading.best
    if best is None or best.letter != TWINS.get(expected) or best.fit > best.readable:
        return False
    own = reading.fits.get(expected)
    return reading.letter == best.letter or (own is not None and twin_farther(own, best))


def said(reading: OcrReading) -> str:
    if not reading.text:
        return 'OCR reads no letter'
    tilted = f', {abs(reading.tilt):g} degrees off level' if reading.tilt else ''
    narrowed = f', read at {reading.width:.0%} of its width' if reading.width != 1.0 else ''
    if reading.votes:
        votes = dict(reading.votes)
        narrowed += f'; {votes[reading.text]} of {sum(votes.values())} readings of it agree'
    objected = (f', but its strokes, cut not knowing the letters expected, read '
                f'{reading.objection}') if reading.objection else ''
    if reading.rival is not None:
        objected += f', and {said(reading.rival)[len("OCR reads "):]}: it does not tell them apart'
    if reading.unheld:
        others = ', and '.join(f'{px} px high it reads {said(r)[len("OCR reads "):]}'
                               for px, r in reading.unheld)
        objected += f', but drawn {others}: it holds at one size only'
    return f'OCR reads {reading.text} ({_sure(reading)}{tilted}{narrowed}){objected}'


def _sure(reading):
    """How sure Tesseract is of `reading`: its confidence in the word, and
    where that is 0, in its least sure letter too. (Tesseract gives some
    words it reads 0 whatever it makes of their letters: a real class's
    small m, read M, 0% as a word and 80% as a letter; the row said only
    `OCR reads M (0% sure)`.)"""
    if not _no_word_confidence(reading.confidence) or not round(reading.letters):
        return f'{reading.confidence:.0f}% sure'
    letter = 'its letter' if len(reading.text) == 1 else 'its least sure letter'
    return f'0% sure of it as a word, {reading.letters:.0f}% of {letter}'

