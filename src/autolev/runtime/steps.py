"""A line on the progress stream for a step of a command that takes longer than two
seconds (forming equations, compiling, reading a large model): what it is, once it has
taken that long, and its time when it ends; nothing for a quick step."""
from __future__ import annotations

import threading
import time

# a step shorter than this says nothing
ANNOUNCE_AFTER = 2.0


class SlowStep:
    """`with SlowStep(stream, "compiling bike.c"):` the step, announced on `stream` (None:
    silent) when it is still running after ANNOUNCE_AFTER seconds."""

    def __init__(self, stream, what: str, after: float | None = None):
        self.stream, self.what = stream, what
        self.after = ANNOUNCE_AFTER if after is None else after
        self._lock = threading.Lock()
        self._announced = False
        self._timer: threading.Timer | None = None
        self._start = 0.0

    def __enter__(self) -> SlowStep:
        self._start = time.monotonic()
        if self.stream is not None:
            self._timer = threading.Timer(self.after, self._announce)
            self._timer.daemon = True
            self._timer.start()
        return self

    def _announce(self) -> None:
        with self._lock:
            if self._timer is None:
                return
            self._announced = True
            self.stream.write(f"  {self.what} ...\n")
            self.stream.flush()

    def __exit__(self, *exc) -> None:
        timer = self._timer
        with self._lock:
            self._timer = None
        if timer is not None:
            timer.cancel()
            timer.join()        # no thread outlives the step (sweeps fork afterwards)
        if self._announced:
            self.stream.write(f"  {self.what}: {time.monotonic() - self._start:.1f} s\n")
            self.stream.flush()
