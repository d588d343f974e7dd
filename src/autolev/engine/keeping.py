"""Answers kept under their requests (run plans, kept outcomes, linearizations,
transcripts: runplan.py's): `keep` files one under its request's key and the digests of
what was read, `kept` finds it again while those files are as they were read, and
`Recorder` keeps what a command printed.  Apart from runplan.py, whose compiled systems
import numpy: a cold command finds no answer kept and goes on without it (the note
naming missing values comes before numpy's import)."""
from __future__ import annotations

import io
import pickle
from pathlib import Path
from collections.abc import Callable
from typing import TYPE_CHECKING

from . import diskcache, reading
from .cachekeys import PLAN_PREFIX, enabled

if TYPE_CHECKING:
    from .reading import Reads
    from .request import Request


def keep(request: Request, reads: Reads, make) -> None:
    """Keep `make(reads.snapshot())` for `request`, filed under the digests `reads`
    took when the files were read; nothing when they changed while being read (the
    work mixed two states of them) or the caches are off."""
    key = request.key(reads) if enabled() else None
    if key is None or reads.torn:
        return
    try:
        diskcache.install(pickle.dumps(make(reads.snapshot()),
                                       protocol=pickle.HIGHEST_PROTOCOL), _entry(key))
    except OSError:
        return                      # a full or read-only disk: the next run forms its own


def kept(request: Request, reads: Reads, kinds: Callable[[], type | tuple]):
    """What `keep` kept for `request` with the files it names as now read (noted in
    `reads`), while every other file it read is as it was, and of one of `kinds()`
    (asked once something is found: their module imports numpy); else None."""
    if not enabled():
        return None
    key = request.key(reads)
    data = None if key is None else diskcache.read_verified(_entry(key))
    if data is None:
        return None
    from .clibrary import CompileError      # (numpy) for a kept answer that is there
    try:
        found = pickle.loads(data)
    except CompileError:
        return None                 # its libraries are gone and no compiler rebuilds them
    with reading.recording(reads):
        if not isinstance(found, kinds()) or not found.reads.holds():
            return None
    return found


def _entry(key: str) -> Path:
    return diskcache.cache_dir() / f"{PLAN_PREFIX}{key[:40]}.pickle"


class Recorder(io.TextIOBase):
    """A text stream that writes through to another and keeps what was written."""

    def __init__(self, through):
        self.through = through
        self.kept = io.StringIO()

    def write(self, text: str) -> int:
        self.kept.write(text)
        return self.through.write(text)

    def flush(self) -> None:
        self.through.flush()

    def take(self) -> str:
        """What was written since the last take."""
        text = self.kept.getvalue()
        self.kept = io.StringIO()
        return text
