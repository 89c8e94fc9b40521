from turtle_letters.keys import message_for


def test_only_p_publishes_in_the_lab():
    assert message_for('p') == 'P'
    assert message_for('P') == 'P'
    for key in 'aZ1 \n\x1b\x03é':
        assert message_for(key) is None


def test_typing_mode_publishes_letters_digits_and_space():
    assert [message_for(k, typing=True) for k in 'aK7 '] == ['A', 'K', '7', ' ']
    for key in '\n\x1b.é':
        assert message_for(key, typing=True) is None
