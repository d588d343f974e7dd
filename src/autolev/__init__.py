"""autolev: Autolev 4.1 models in Python.

    import autolev
    program = autolev.parse(open("pendulum.al").read(), "pendulum.al")

`parse` reads a model into the IR and raises `AutolevSyntaxError` (carrying every
diagnostic) when it cannot.
"""
from __future__ import annotations

import os
from pathlib import Path

from .errors import (AutolevError, AutolevFileError, AutolevSyntaxError, Diagnostic,
                     Location, Span)
from .ir import Program

__version__ = "0.1.0"
__all__ = ["parse", "Program", "AutolevError", "AutolevSyntaxError", "AutolevFileError",
           "Diagnostic", "Location", "Span", "__version__"]


def parse(source: str | os.PathLike, filename: str | None = None) -> Program:
    """Read Autolev source into a `Program`.

    `source` is the text of a model, or a path (`pathlib.Path`) to read.  `filename`
    names the model in diagnostics; user macros (NAME.A) and `RUN` files are looked
    up next to it.  Raises `AutolevSyntaxError` with all diagnostics when the model
    cannot be read.
    """
    from .irbuild import Builder, sort_key
    from .source import SourceFile

    if isinstance(source, os.PathLike):
        src = SourceFile.read(source, filename or os.fspath(source))
        path: Path | None = Path(source)
    else:
        src = SourceFile(filename or "<string>", source)
        path = Path(filename) if filename else None
    builder = Builder(src.name, path)
    builder.build_source(src)
    if builder.errors:
        raise AutolevSyntaxError(sorted(builder.diagnostics, key=sort_key))
    program = builder.program()
    program.diagnostics.sort(key=sort_key)
    return program
