"""What a command was asked, declared once: the key of every answer kept for it.

A kept answer (a run plan, a kept outcome, a linearization, a transcript) is filed
under its request's key: the digest of autolev's own code, the request's kind, *every*
field of the request by name (a field added is in the key without anyone remembering
to put it there), and the digests of the files the request names (the model, an --in
file) as the command read them (`reading.py`).  No sympy: a warm run finds its
plan with it.
"""
from __future__ import annotations

import argparse
import dataclasses
import hashlib
import os
from dataclasses import dataclass
from pathlib import Path

from .cachekeys import code_digest
from . import reading

# environment variables that choose how numbers are computed (the compiler, the C or
# the Python back end): part of every request, as the command saw them
NUMBER_KNOBS = ("AUTOLEV_NO_C", "AUTOLEV_NO_PYEXT", "CC")


def environment() -> tuple[tuple[str, str], ...]:
    return tuple((name, os.environ.get(name, "")) for name in NUMBER_KNOBS)


def _given(name) -> str | None:
    return None if name is None else str(name)


def _folder(*names) -> str:
    """The working folder, when a path given is relative to it (messages quote the
    paths as given: the same text elsewhere is another request)."""
    relative = any(name is not None and not Path(name).is_absolute() for name in names)
    return os.getcwd() if relative else ""


def _listed(items) -> tuple:
    return tuple(items or ())


@dataclass(frozen=True)
class Request:
    """A command on a model file: the fields of a subclass are what it was asked."""

    model: str                  # the model file, as given
    folder: str                 # the working folder, when a path given is relative

    def named_files(self) -> tuple[str, ...]:
        """The files the request names, whose digests are part of its key."""
        return (self._path(self.model),)

    def _path(self, name: str) -> str:
        return str(Path(self.folder, name))

    def key(self, reads: reading.Reads) -> str | None:
        """The request's key, from its fields and the digests `reads` took of the files
        it names when they were first read (each is read now if it was not yet); None
        when one cannot be read."""
        parts = [code_digest(), type(self).__name__]
        for field in dataclasses.fields(self):
            parts.append(f"{field.name}={getattr(self, field.name)!r}")
        for path in self.named_files():
            if not reads.has_read(path):
                with reading.recording(reads):
                    try:
                        reading.read_bytes(path)
                    except OSError:
                        pass
            found = reads.digest_of(path)
            if found is None:
                return None
            parts.append(f"{path}\0{found}")
        text = "\0".join(parts)
        return hashlib.sha256(text.encode("utf-8", "surrogatepass")).hexdigest()


@dataclass(frozen=True)
class ValuesRequest(Request):
    """A command that takes the model's values (run, linearize)."""

    infile: str | None          # --in, as given
    values: tuple               # --set NAME=VALUE, as given
    specified: tuple            # --specified NAME=EXPR, as given
    backend: str
    zero_missing: bool
    environment: tuple          # NUMBER_KNOBS as the command saw them

    def named_files(self) -> tuple[str, ...]:
        return super().named_files() + \
            ((self._path(self.infile),) if self.infile is not None else ())


@dataclass(frozen=True)
class RunRequest(ValuesRequest):
    """`autolev run FILE` (no animation: its pictures are drawn from the model)."""

    method: str | None
    tfinal: float | None
    quirks: bool
    code: tuple                 # --code, as given

    @classmethod
    def of(cls, ns: argparse.Namespace) -> "RunRequest":
        return cls(_given(ns.file), _folder(ns.file, ns.infile), _given(ns.infile),
                   _listed(ns.set), _listed(ns.specified), ns.backend, ns.zero_missing,
                   environment(), ns.method, ns.tfinal, ns.quirks, _listed(ns.code))


@dataclass(frozen=True)
class LinearizeRequest(ValuesRequest):
    """`autolev linearize FILE` at one point."""

    at: tuple                   # --at NAME=VALUE
    inputs: str | None          # --inputs
    code: str | None            # --code
    lock: tuple                 # --lock
    constraint: tuple           # --constraint
    dependent: tuple            # --dependent

    @classmethod
    def of(cls, ns: argparse.Namespace) -> "LinearizeRequest":
        return cls(_given(ns.file), _folder(ns.file, ns.infile), _given(ns.infile),
                   _listed(ns.set), _listed(ns.specified), ns.backend, ns.zero_missing,
                   environment(), _listed(ns.at), ns.inputs, ns.code, _listed(ns.lock),
                   _listed(ns.constraint), _listed(ns.dependent))


@dataclass(frozen=True)
class TranscriptRequest(Request):
    """`autolev transcript FILE` (and a run of a model without a CODE command)."""

    @classmethod
    def of_file(cls, path) -> "TranscriptRequest":
        return cls(_given(path), _folder(path))
