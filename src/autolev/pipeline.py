"""The stages from Autolev source to a Python module: read (`parse`), then translate
(`translation`, `transpile`).  `autolev.parse` and the rest are these functions."""
from __future__ import annotations

import os
import re
from pathlib import Path

from .errors import AutolevSyntaxError, AutolevTranslationError, Diagnostic
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


def diagnostics(path: Path, macro: bool = False) -> list:
    """Every diagnostic of the file at `path` (a macro's text when `macro`), in file
    order: the syntax, then, for the statements that read, what the translation finds
    (one round: a name only a line that did not read declares is not reported again).
    Nothing is built or run."""
    src = SourceFile.read(path, str(path))
    builder = Builder(src.name, path, reserved=vocabulary())
    if macro:
        builder.build_macro_source(src)
        return sorted(builder.diagnostics, key=sort_key)
    builder.build_source(src)
    program = builder.program()
    more = [d for d in translate(program).diagnostics[len(program.diagnostics):]
            if not _follows_from(d, builder.errors)]
    return sorted(builder.diagnostics + more, key=sort_key)


def _follows_from(d: Diagnostic, syntax_errors: list[Diagnostic]) -> bool:
    """Whether a translation diagnostic only repeats a syntax error: a name it calls
    undeclared or of the wrong kind is a word of a line that did not read (whose
    declaration or definition is then missing)."""
    if d.code not in ("T002", "T008") or not syntax_errors:
        return False
    words = {w.lower() for e in syntax_errors
             for w in re.findall(r"[A-Za-z_][A-Za-z0-9_]*", e.source_line or "")}
    named = re.findall(r"'([A-Za-z_][A-Za-z0-9_]*)", d.message)
    named += re.findall(r"^([A-Za-z_][A-Za-z0-9_]*) has no value", d.message)
    return any(n.lower() in words for n in named)


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


__all__ = ["diagnostics", "parse", "translation", "transpile"]
