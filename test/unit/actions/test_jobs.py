"""The controller's job policy: one drawing per trigger, typed keys wait."""
import threading
import time

from turtle_letters.letters.plan import SvgFile
from turtle_letters.letters.font import BUILTIN
from turtle_letters.actions.jobs import Jobs, goal_request


def test_a_trigger_while_drawing_is_refused_and_the_next_one_after_is_taken():
    jobs = Jobs()
    assert jobs.offer('N')
    assert not jobs.offer('N')          # waiting
    assert jobs.take(0.1) == 'N'
    assert not jobs.offer('N')          # being drawn
    jobs.done()
    assert jobs.offer('N')


def test_typed_keys_wait_their_turn_up_to_the_limit():
    jobs = Jobs(typed_ahead=3)
    assert [jobs.offer_key(c) for c in 'ABCD'] == [True, True, True, False]
    assert not jobs.offer('WORD')       # keys are waiting: a word is a trigger
    assert [jobs.take(0.1) for _ in range(1)] == ['A']
    assert jobs.offer_key('E')          # one drawn, so one more may wait
    drawn = []
    for _ in range(4):
        jobs.done()
        drawn.append(jobs.take(0.1))
    assert drawn == ['B', 'C', 'E', None]


def test_up_to_32_typed_keys_wait():
    jobs = Jobs()
    assert all(jobs.offer_key('A') for _ in range(32))
    assert not jobs.offer_key('B')


def test_take_times_out_with_nothing_to_draw():
    assert Jobs().take(0.05) is None


def test_racing_triggers_are_taken_only_when_nothing_waits_or_is_drawn():
    """Thousands of triggers from several threads while a worker draws: no
    trigger is ever taken behind another or during a drawing, none that was
    taken is lost, and a trigger is taken again at the end."""
    jobs = Jobs()
    taken, queued_meanwhile = [], []
    senders_done = threading.Event()

    def worker():
        while True:
            text = jobs.take(0.01)
            if text is None and senders_done.is_set():
                return
            if text is None:
                continue
            taken.append(text)
            time.sleep(0.0002)                  # drawing
            queued_meanwhile.extend(jobs._waiting)
            jobs.done()

    accepted = []

    def sender():
        for _ in range(3000):
            if jobs.offer('P'):
                accepted.append('P')
            time.sleep(0.0001)

    drawer = threading.Thread(target=worker)
    senders = [threading.Thread(target=sender) for _ in range(3)]
    for t in [drawer] + senders:
        t.start()
    for t in senders:
        t.join()
    senders_done.set()
    drawer.join(10)
    assert not drawer.is_alive()
    assert queued_meanwhile == []
    assert len(taken) == len(accepted) > 1
    assert jobs.offer('P') and jobs.take(0.1) == 'P'


def test_each_hands_out_the_requests_in_turn_until_stopped():
    jobs = Jobs()
    jobs.offer_key('A')
    jobs.offer_key('B')
    seen = []
    for request in jobs.each(lambda: len(seen) == 2, timeout=0.01):
        seen.append(request)
        jobs.done()
    assert seen == ['A', 'B']


def test_a_goal_is_accepted_before_it_can_be_taken_and_only_when_idle():
    jobs, said = Jobs(), []
    taker = threading.Thread(target=lambda: said.append(('taken', jobs.take(5.0))))
    taker.start()
    assert jobs.offer('N', accept=lambda: (time.sleep(0.2), said.append(('accepted', 'N'))))
    taker.join()
    assert said == [('accepted', 'N'), ('taken', 'N')]
    assert not jobs.offer('Z', accept=lambda: said.append(('accepted', 'Z')))
    assert said[-1] == ('taken', 'N')


def test_a_goal_has_exactly_one_of_text_and_svg():
    assert goal_request('', '', BUILTIN) == (None, 'a goal has exactly one of text and svg '
                                                   '(neither was given)')
    assert 'both were given' in goal_request('N', 'a.svg', BUILTIN)[1]
    assert goal_request('', '/tmp/a.svg', BUILTIN) == (SvgFile('/tmp/a.svg'), None)
    assert goal_request('n', '', BUILTIN) == ('N', None)
    request, why = goal_request('N\u00e9', '', BUILTIN)
    assert request is None and 'no glyph' in why
