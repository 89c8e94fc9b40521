from turtle_letters.keys import KeyDecoder, message_for


def test_only_p_publishes_in_the_lab():
    assert message_for('p') == 'P'
    assert message_for('P') == 'P'
    for key in 'aZ1 \n\x1b\x03é':
        assert message_for(key) is None


def test_the_trigger_key_is_the_trigger_character_in_either_case():
    assert message_for('q', trigger='Q') == 'Q'
    assert message_for('Q', trigger='Q') == 'Q'
    assert message_for('p', trigger='Q') is None
    assert message_for('X', trigger='x') == 'x'


def test_a_longer_trigger_is_sent_by_enter():
    assert message_for('\n', trigger='GO') == 'GO'
    for key in 'gGoO P':
        assert message_for(key, trigger='GO') is None


def test_typing_mode_publishes_letters_digits_and_space():
    assert [message_for(k, typing=True) for k in 'aK7 '] == ['A', 'K', '7', ' ']
    for key in '\n\x1b.é':
        assert message_for(key, typing=True) is None


# What xterm-like terminals (tmux among them) send for these keys.
SEQUENCES = {
    'Up': b'\x1b[A', 'Down': b'\x1b[B', 'Right': b'\x1b[C', 'Left': b'\x1b[D',
    'F1': b'\x1bOP', 'F2': b'\x1bOQ', 'F4': b'\x1bOS', 'F5': b'\x1b[15~', 'F12': b'\x1b[24~',
    'Home': b'\x1b[H', 'Delete': b'\x1b[3~', 'Ctrl+Right': b'\x1b[1;5C',
    'Alt+p': b'\x1bp', 'Alt+P': b'\x1bP', 'Alt+Up': b'\x1b\x1b[A',
    'console F1': b'\x1b[[A', 'console F5': b'\x1b[[E',
}


def test_escape_sequences_are_no_keys():
    for name, sequence in SEQUENCES.items():
        decoder = KeyDecoder()
        assert decoder.feed(b'a' + sequence + b'p') == ['a', 'p'], name
        assert not decoder.pending, name


def test_a_sequence_split_across_reads_is_still_dropped():
    decoder = KeyDecoder()
    assert decoder.feed(b'\x1b') == []
    assert decoder.pending
    assert decoder.feed(b'[') == []
    assert decoder.feed(b'1;5') == []
    assert decoder.feed(b'Cp') == ['p']


def test_a_bare_esc_is_dropped_when_nothing_follows_in_time():
    decoder = KeyDecoder()
    assert decoder.feed(b'\x1b') == []
    decoder.timeout()
    assert not decoder.pending
    assert decoder.feed(b'p') == ['p']


def test_utf8_split_across_reads_is_one_key():
    decoder = KeyDecoder()
    encoded = 'é'.encode()
    assert decoder.feed(encoded[:1]) == []
    assert decoder.feed(encoded[1:] + b'\n') == ['é', '\n']
