"""Where a turtle's letters go, like a typewriter. No ROS here.

The lab's turtle has the whole canvas, from where it first stands; a
turtle on a shared canvas has its part of it (parts.py), and may carry on
from where an earlier run of its controller had got to.
"""
from .layout import Layout


class Sheet:
    def __init__(self, size, font):
        self.size, self.font = size, font
        self.part = None        # (first place, letter bounds) on a shared canvas
        self._resume_at = None  # where the next letter goes in the part, once known
        self._layout = None     # laid out at the first drawing

    def give_part(self, first_place, bounds, cursor=None):
        self.part = (tuple(first_place), bounds)
        self._resume_at = tuple(cursor) if cursor else None
        self._layout = None

    def reserve(self, text, where):
        """The places of `text`'s characters and whether the canvas must be
        cleared first (a part: started again); raises plan.DoesNotFit (then
        nothing was reserved). `where`: the turtle's pose, for the lab."""
        return self._layout_from(where).reserve(text)

    def reserve_picture(self, width, name, where):
        """The place of a picture `width` letter heights wide, as reserve() does."""
        places, cleared = self._layout_from(where).reserve_widths([width], name, 'pictures')
        return places[0], cleared

    def _layout_from(self, where):
        if self._layout is None:
            if self.part is None:
                self._layout = Layout((where.x, where.y), self.size, self.font)
            else:
                self._layout = Layout(self.part[0], self.size, self.font, bounds=self.part[1])
                if self._resume_at is not None:
                    self._layout.cursor = self._resume_at
        return self._layout

    def mark(self):
        """Where the sheet stands, for undo() if what was reserved since is not drawn."""
        return self._layout, self._layout.cursor if self._layout else None, self._resume_at

    def undo(self, mark):
        """Back to `mark`: nothing reserved since takes a place (a drawing
        cancelled before it began)."""
        self._layout, cursor, self._resume_at = mark
        if self._layout is not None:
            self._layout.cursor = cursor

    @property
    def cursor(self):
        """Where the next letter goes, once known."""
        return self._layout.cursor if self._layout is not None else self._resume_at

    def forget(self):
        """After a failed drawing: the lab starts a new layout where the turtle
        then is; a part goes on at its next place, past what the failed one took."""
        self._resume_at = self.cursor if self.part is not None else None
        self._layout = None
