"""The `autolev` command's output and error streams, whose failed writes name the stream.

`autolev check x.al > file` on a full disk fails in a print deep in a command; as a bare
OSError it would read as a bug of autolev (exit 70).  The command's own streams raise
StreamWriteError instead, which the command line says as the user's disk or device:
"cannot write its output: No space left on device", exit 1.  A broken pipe (output into
`head`) stays a BrokenPipeError, ended quietly as before.
"""
from __future__ import annotations

import io
import os
import sys


class StreamWriteError(OSError):
    """A write to the command's output or error stream failed (errno, strerror kept)."""

    def __init__(self, stream: str, cause: OSError):
        super().__init__(cause.errno, cause.strerror)
        self.stream = stream


class _StandardStream(io.RawIOBase):
    """File descriptor 1 or 2, written as the interpreter writes it, failures named."""

    def __init__(self, fd: int, stream: str):
        super().__init__()
        self._fd = fd
        self._stream = stream

    def writable(self) -> bool:
        return True

    def fileno(self) -> int:
        return self._fd

    def isatty(self) -> bool:
        return os.isatty(self._fd)

    def write(self, data) -> int:
        try:
            return os.write(self._fd, data)
        except (BrokenPipeError, BlockingIOError):
            raise                       # the reader gone; a non-blocking descriptor's retry
        except OSError as exc:
            raise StreamWriteError(self._stream, exc) from exc


def _named(text: io.TextIOWrapper, fd: int, stream: str) -> io.TextIOWrapper:
    """`text` again, buffered as it was (unbuffered under python -u, PYTHONUNBUFFERED)."""
    raw = _StandardStream(fd, stream)
    binary = raw if isinstance(text.buffer, io.RawIOBase) else io.BufferedWriter(raw)
    return io.TextIOWrapper(binary, encoding=text.encoding, errors=text.errors,
                            line_buffering=text.line_buffering,
                            write_through=text.write_through)


def name_the_standard_streams() -> None:
    """sys.stdout and sys.stderr written through descriptors 1 and 2 with their failures
    named (the command itself only: a caller of cli.main keeps its own streams)."""
    if sys.stdout is sys.__stdout__ and sys.stdout is not None:
        sys.stdout.flush()
        sys.stdout = _named(sys.__stdout__, 1, "output")
    if sys.stderr is sys.__stderr__ and sys.stderr is not None:
        sys.stderr.flush()
        sys.stderr = _named(sys.__stderr__, 2, "error output")
