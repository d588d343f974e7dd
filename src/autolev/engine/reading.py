"""What a command read, taken when it read it.

An answer is a function of the bytes read and the options given, and of nothing else;
so whatever keeps an answer (a run plan, a kept outcome, a translation) is filed under
the digests of the files as they were *when they were read*, carried with the work to
where it is kept, never taken again later (an edit in between would file the old
answer under the new files' name).  Every file a model's command reads comes through
`read_bytes`, and every search of a folder (a macro's file in any case, the .R files
of a folder) through a registered `lookup`; inside `recording()` each is noted in the
current `Reads`: a file's SHA-256 at its first read, a lookup's answer at its first
asking.  A file read again with other bytes, or a lookup answered otherwise, makes the
record `torn`: the work then mixed two states of the files, and nothing of it is kept.

`Reads.snapshot()` is what a kept answer carries (`ReadSet`); `ReadSet.holds()` asks
the disk again whether each file and lookup is still what it was.
"""
from __future__ import annotations

import contextlib
import contextvars
import errno
import hashlib
import os
import stat
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

_current: contextvars.ContextVar["Reads | None"] = contextvars.ContextVar("reads",
                                                                          default=None)
# name -> function: the folder searches whose answers a kept result depends on
_LOOKUPS: dict[str, Callable] = {}


def digest(raw: bytes | None) -> str | None:
    return None if raw is None else hashlib.sha256(raw).hexdigest()


@dataclass(frozen=True)
class ReadSet:
    """The files read (path, digest or None when unreadable) and the lookups asked
    (name, arguments, answer), each as first seen."""

    files: tuple[tuple[str, str | None], ...]
    lookups: tuple[tuple[str, tuple, object], ...]

    def digest_of(self, path) -> str | None:
        wanted = _key(path)
        return next((d for p, d in self.files if p == wanted), None)

    def holds(self) -> bool:
        """Whether every file still has the digest it had and every lookup the same
        answer (what is read to tell is noted in the current record, if any)."""
        return all(_read_digest(path) == d for path, d in self.files) and \
            all(_LOOKUPS[name](*args) == answer for name, args, answer in self.lookups)


class Reads:
    """The record of one piece of work's reads: see the module's docstring."""

    def __init__(self) -> None:
        self._files: dict[str, str | None] = {}
        self._lookups: dict[tuple[str, tuple], object] = {}
        self.torn: list[str] = []           # what was found changed while read

    def note_file(self, path, raw: bytes | None) -> None:
        key, d = _key(path), digest(raw)
        if key not in self._files:
            self._files[key] = d
        elif self._files[key] != d:
            self.torn.append(key)

    def note_lookup(self, name: str, args: tuple, answer) -> None:
        if (name, args) not in self._lookups:
            self._lookups[name, args] = answer
        elif self._lookups[name, args] != answer:
            self.torn.append(f"{name}{args}")

    def take(self, other: "Reads") -> None:
        """Note what `other` (a nested record) noted."""
        for path, d in other._files.items():
            if path not in self._files:
                self._files[path] = d
            elif self._files[path] != d:
                self.torn.append(path)
        for key, answer in other._lookups.items():
            self.note_lookup(*key, answer)
        self.torn += other.torn

    def digest_of(self, path) -> str | None:
        return self._files.get(_key(path))

    def has_read(self, path) -> bool:
        return _key(path) in self._files

    def snapshot(self) -> ReadSet:
        return ReadSet(tuple(sorted(self._files.items())),
                       tuple(sorted(((n, a, v) for (n, a), v in self._lookups.items()),
                                    key=repr)))


def _key(path) -> str:
    return str(Path(path).absolute())


def _read_digest(path: str) -> str | None:
    try:
        return digest(read_bytes(path))
    except OSError:
        return None


def current() -> Reads | None:
    return _current.get()


@contextlib.contextmanager
def recording(reads: Reads | None = None):
    """Note every read inside in `reads` (a new record by default), and in the
    record around it when there is one."""
    reads = Reads() if reads is None else reads
    outer = _current.get()
    token = _current.set(reads)
    try:
        yield reads
    finally:
        _current.reset(token)
        if outer is not None and outer is not reads:
            outer.take(reads)


def read_bytes(path) -> bytes:
    """The file's bytes, noted in the current record (OSError as Path.read_bytes); a
    FIFO, a device or a folder is refused (OSError) without waiting on it."""
    reads = _current.get()
    try:
        raw = _regular_file_bytes(path)
    except OSError:
        if reads is not None:
            reads.note_file(path, None)
        raise
    if reads is not None:
        reads.note_file(path, raw)
    return raw


def _regular_file_bytes(path) -> bytes:
    # opened without blocking: a FIFO's open waits for a writer, its read for data
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    try:
        mode = os.fstat(fd).st_mode
        if not stat.S_ISREG(mode):
            what = ("a folder" if stat.S_ISDIR(mode) else "a FIFO" if stat.S_ISFIFO(mode)
                    else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode)
                    else "a socket" if stat.S_ISSOCK(mode) else "not a file")
            raise OSError(errno.EINVAL, f"not a regular file ({what})", str(path))
        chunks = []
        while True:
            chunk = os.read(fd, 1 << 20)
            if not chunk:
                return b"".join(chunks)
            chunks.append(chunk)
    finally:
        os.close(fd)


def lookup(name: str):
    """Register a folder search whose answer a kept result depends on: each call is
    noted in the current record with its arguments (hashable) and its answer."""
    def register(function: Callable) -> Callable:
        def looked_up(*args):
            answer = function(*args)
            reads = _current.get()
            if reads is not None:
                reads.note_lookup(name, args, answer)
            return answer
        looked_up.__name__, looked_up.__doc__ = function.__name__, function.__doc__
        _LOOKUPS[name] = looked_up
        return looked_up
    return register


# -- the folder searches a model's reading makes --------------------------------------
@lookup("find file")
def find_file(base: Path, relative: str) -> Path | None:
    """`base/relative`, matching each path component case-insensitively."""
    parts = [p for p in relative.replace("\\", "/").split("/") if p not in ("", ".")]
    current = base
    for part in parts:
        if part == "..":
            current = current.parent
            continue
        exact = current / part
        try:
            if exact.exists():
                current = exact
                continue
            matches = [c for c in current.iterdir() if c.name.lower() == part.lower()]
        except OSError:         # a name too long for the file system, an unreadable folder
            return None
        if not matches:
            return None
        current = sorted(matches)[0]
    return current if current.is_file() else None


@lookup("names with suffix")
def names_with_suffix(folder: Path, suffix: str) -> frozenset[str]:
    """The names (lower case, without `suffix`) of the folder's files ending in `suffix`
    (any case); none for a folder that cannot be read."""
    try:
        return frozenset(f[:-len(suffix)].lower() for f in os.listdir(folder)
                         if f.lower().endswith(suffix))
    except OSError:
        return frozenset()
