"""The stages from Autolev source to a Python module: read (`parse`), then translate
(`translation`, `transpile`).  `autolev.parse` and the rest are these functions."""
from __future__ import annotations

import os
from pathlib import Path

from .errors import AutolevSyntaxError, AutolevTranslationError
from .ir import Program
from .irbuild import Builder, sort_key
from .source import SourceFile
from .translate import Probe, Translation, translate, vocabulary


def parse(source: str | os.PathLike, filename: str | None = None,
          folder: Path | None = None) -> Program:
    """Read Autolev source into a `Program`.

    `source` is the text of a model, or a path to read: a `pathlib.Path`, or a string
    of one line that names a file (or ends in .al, then a missing file is an error).
    `filename` names the model in diagnostics; user macros (NAME.A) and `RUN` files are
    looked up next to it, then in `folder` (the model's folder, for a text kept apart
    from it: a session's transcript).  Raises `AutolevSyntaxError` with all diagnostics
    when the model cannot be read, `AutolevFileError` when its file cannot.
    """
    source = _as_path(source)
    if isinstance(source, os.PathLike):
        src = SourceFile.read(source, filename or os.fspath(source))
        path: Path | None = Path(source)
    else:
        src = SourceFile(filename or "<string>", source)
        path = Path(filename) if filename else None
    builder = Builder(src.name, path, reserved=vocabulary(), folder=folder)
    builder.build_source(src)
    if builder.errors:
        raise AutolevSyntaxError(sorted(builder.diagnostics, key=sort_key))
    program = builder.program()
    program.diagnostics.sort(key=sort_key)
    return program


def _as_path(source):
    """A string that is a file's name, as a Path; model text is left as it is."""
    if not isinstance(source, str) or "\n" in source or "\r" in source:
        return source
    name = source.strip()
    if name and (name.lower().endswith((".al", ".all")) or os.path.isfile(name)):
        return Path(name)
    return source


def translation(source: str | os.PathLike, filename: str | None = None,
                probes: tuple[Probe, ...] = (), folder: Path | None = None) -> Translation:
    """Parse and translate; returns the `Translation` (code, line map, diagnostics), with
    the lines keeping `probes` (translate.Probe); `folder`: as parse's.  Raises
    AutolevSyntaxError or AutolevTranslationError."""
    program = source if isinstance(source, Program) else parse(source, filename, folder)
    result = translate(program, probes=probes)
    errors = [d for d in result.diagnostics if d.severity == "error"]
    if errors:
        raise AutolevTranslationError(result.diagnostics)
    return result


def transpile(source: str | os.PathLike, filename: str | None = None) -> str:
    """The Python module text of an Autolev model (text, or a path)."""
    return translation(source, filename).code


__all__ = ["parse", "translation", "transpile"]
