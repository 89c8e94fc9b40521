"""What the talker publishes for a key press. No ROS here."""
import string
from typing import Optional

# The lab's binding: P (either case) publishes the trigger "P".
LAB_BINDINGS = {'p': 'P', 'P': 'P'}
TYPEABLE = set(string.ascii_letters + string.digits + ' ')


def message_for(key: str, typing: bool = False) -> Optional[str]:
    """The string to publish on chatter for `key`, or None to publish nothing.

    In typing mode every letter, digit and space is published (letters in
    upper case), so the controller draws what is typed.
    """
    if typing:
        return key.upper() if key in TYPEABLE else None
    return LAB_BINDINGS.get(key)
