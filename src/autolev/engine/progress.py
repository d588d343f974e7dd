"""How far a long task is, said on a stream: an integration's T, an ALGEBRAIC sweep's
points, the responses a verification has compared, a movie's frames, a parameter
study's points.  One reporter for all of them, in the engine (which imports nothing
outside itself) so that the engine's loops and the runtime's can share it."""
from __future__ import annotations

import time

# how often a line is redrawn in place on a terminal
IN_PLACE_EVERY = 0.2
# the words of a task whose position goes from start to end: `T = 2 of 10 (20%)`
OF_THE_WAY = "{what} = {position:.6g} of {end:.6g} ({percent:.0f}%)"


class Progress:
    """Lines on `stream` saying how far a task is, once it has run `wait` seconds: then
    at most every `every` seconds (on a terminal, when `in_place`, a line redrawn every
    IN_PLACE_EVERY seconds), and at each 1/`steps` of the way when `steps` is not 0.
    Each line is `says` (formatted with `what`, `position`, `end` and `percent`) and
    the seconds so far."""

    stream: object              # where the lines go (None: nowhere)
    what: str                   # the task, as `says` names it
    start: float                # the position the task starts from
    end: float                  # the position it ends at
    says: str                   # the line's words, a format
    wait: float                 # seconds before the first line
    every: float                # seconds between two lines, at least
    in_place: bool              # on a terminal, one line redrawn rather than a line each time
    steps: int                  # also a line at each 1/steps of the way (0: by time alone)
    from_first: bool            # the clock starts at the first update, and lines say the time left
    position: float             # where the task is
    first: float                # the position when the clock started
    began: float | None         # the clock when it started (None: not yet)
    last: float                 # the clock at the last line
    step: int                   # the 1/steps of the way of the last line (-1: none yet)
    shown: bool                 # a line has been written
    tty: bool                   # the stream is a terminal

    def __init__(self, stream, what: str, start: float, end: float, says: str = OF_THE_WAY,
                 wait: float = 1.0, every: float = 5.0, in_place: bool = True,
                 steps: int = 0, from_first: bool = False):
        self.stream, self.what, self.says = stream, what, says
        self.start, self.end = start, end
        self.wait, self.every, self.in_place, self.steps = wait, every, in_place, steps
        self.from_first = from_first
        self.position = self.first = start
        # a study's first point builds and compiles: its time says nothing of the rest
        self.began = None if from_first or stream is None else time.monotonic()
        self.last = float("-inf")
        self.step = -1
        self.shown = False
        self.tty = bool(getattr(stream, "isatty", lambda: False)())

    def update(self, position: float) -> None:
        """The task is at `position`: a line if one is due."""
        self.position = position
        if self.stream is None:
            return
        now = time.monotonic()
        if self.began is None:
            self.began, self.first = now, position
            return
        step = self._step()
        every = IN_PLACE_EVERY if self.in_place and self.tty else self.every
        if now - self.began >= self.wait and (now - self.last >= every
                                               or self.steps and step > self.step):
            self._line(now, step)

    def advance(self, n: float) -> None:
        """`n` more done."""
        self.update(self.position + n)

    def done(self) -> None:
        """The task ended: a line redrawn in place is ended, and a task said in steps
        says its last."""
        if not self.shown:
            return
        if self.in_place and self.tty:
            self.stream.write("\n")
            self.stream.flush()
        elif self.steps and self.step < self.steps:
            self._line(time.monotonic(), self.steps)

    def _step(self) -> int:
        return (self.position - self.start) * self.steps // max(self.end - self.start, 1)

    def _line(self, now: float, step: int) -> None:
        span = self.end - self.start
        percent = 100 * (self.position - self.start) / span if span else 100.0
        elapsed = now - self.began
        said = self.says.format(what=self.what, position=self.position, end=self.end,
                                percent=percent)
        text = f"  {said}, {elapsed:.1f} s"
        if self.from_first and self.position < self.end:
            left = elapsed * (self.end - self.position) / max(self.position - self.first, 1)
            text += f", about {left:.0f} s left"
        self.stream.write("\r" + text + "   " if self.in_place and self.tty else text + "\n")
        self.stream.flush()
        self.last, self.step, self.shown = now, step, True
