"""Which files a save may replace. No ROS, no Qt."""
import os

# Written into every picture saved (a PNG tEXt chunk), so that a save
# replaces only a picture of ours: never a file that ~canvas_png names by
# mistake or by malice (`rosparam set` reaches the node from any machine).
SIGNATURE = 'turtle_letters bundled turtlesim'
PNG_MAGIC = b'\x89PNG\r\n\x1a\n'


def ours_to_replace(path: str) -> bool:
    """Whether a save may write `path`: nothing there yet, or a picture we saved."""
    if not os.path.lexists(path):
        return True
    if not os.path.isfile(path) or os.path.islink(path):
        return False
    with open(path, 'rb') as f:
        head = f.read(4096)
    return head.startswith(PNG_MAGIC) and SIGNATURE.encode() in head
