#!/usr/bin/python3
"""Draw with the controller through its action `draw`: draw.py TEXT, or --svg FILE."""
import os
import signal
import sys

# A Ctrl-C while the imports load leaves quietly, with main()'s status for it.
signal.signal(signal.SIGINT, lambda *_: os._exit(130))

from turtle_letters.actions.client import main  # noqa: E402

if __name__ == '__main__':
    signal.signal(signal.SIGINT, signal.default_int_handler)
    sys.exit(main())
