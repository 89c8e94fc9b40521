"""What a failed drawing says: an error of this package's own is logged
once at ERROR with its traceback, and summed up in one line."""
import logging

import pytest

diagnosis = pytest.importorskip('turtle_letters.classroom.diagnosis')


def test_an_unexpected_error_is_logged_once_with_its_traceback(caplog):
    caplog.set_level(logging.DEBUG)
    try:
        {}['missing']
    except KeyError as e:
        said = diagnosis.why_stopped(e, driver=None)
    assert said == "KeyError: 'missing'"
    errors = [r for r in caplog.records if r.levelno == logging.ERROR]
    assert len(errors) == 1
    assert 'Traceback' in errors[0].getMessage() and "KeyError: 'missing'" in errors[0].getMessage()
