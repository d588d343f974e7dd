"""Executing a translated model, with failures reported at the Autolev statement."""
from __future__ import annotations

import dataclasses
import textwrap
import traceback
import types
from dataclasses import dataclass
from pathlib import Path

import sympy as sm
from sympy.matrices.exceptions import NonInvertibleMatrixError

from .errors import (AutolevFileError, AutolevRuntimeError, AutolevTranslationError,
                     Diagnostic, Location)
from .pipeline import parse, translation
from .runtime.errors import AutolevModelError
from .translate import translate

# what a model's own statements can raise when the model asks for something impossible
# (a division by zero, a non-square matrix to invert, ...), besides our own error
_STATEMENT_FAILURES = (AutolevModelError, TypeError, ValueError, ZeroDivisionError,
                       ArithmeticError, IndexError, KeyError, AttributeError,
                       NotImplementedError, RecursionError, sm.SympifyError,
                       NonInvertibleMatrixError)


# what an edited converted module can raise besides what its statements can
_EDITING_SLIPS = (NameError, ImportError, AssertionError)


def load(path):
    """Translate the model at `path`, execute it, and return its `Model`."""
    p = Path(path)
    return load_translation(translation(p), str(p))


def load_translation(translation, filename: str):
    """Run the generated module; return its model, with `namespace` and `names`."""
    name = "autolev_model"
    module = types.ModuleType(name)
    module.__file__ = filename + ".py"
    try:
        code = compile(translation.code, module.__file__, "exec")
    except (RecursionError, SyntaxError) as exc:
        if not _beyond_pythons_nesting(exc):
            raise
        raise AutolevRuntimeError(_too_deep(translation, module.__file__)) from None
    try:
        exec(code, module.__dict__)
    except _STATEMENT_FAILURES as exc:
        raise AutolevRuntimeError(_diagnostic(exc, translation, module.__file__)) from None
    model = module.__dict__["model"]
    model.namespace = module.__dict__
    model.source = ModelSource("translation", translation, filename, model.revision())
    model.names = translation.names
    model.namespaces = translation.namespaces
    # where each CODE statement is in the .al file (diagnostics of its run point there)
    model.code_locations = [translation.line_map.get(n)
                            for n, text in enumerate(translation.code.splitlines(), 1)
                            if text.startswith("model.code(")]
    return model


def _beyond_pythons_nesting(exc: Exception) -> bool:
    """Python's own limits on nesting, which a correct translation can exceed too."""
    return isinstance(exc, RecursionError) or exc.msg == "too many nested parentheses"


def _too_deep(translation, pyfile: str) -> Diagnostic:
    """The statement whose Python nests deeper than Python compiles (a sum of thousands
    of terms inside a product of thousands, powers nested 200 deep, ...)."""
    lines = translation.code.splitlines()
    statements: dict = {}
    for n, span in translation.line_map.items():
        statements.setdefault(span, []).append(lines[n - 1])
    location = Location(pyfile, 1, 1)
    for span, code in statements.items():
        try:
            compile(textwrap.dedent("\n".join(code)), pyfile, "exec")
        except (RecursionError, SyntaxError) as exc:
            if _beyond_pythons_nesting(exc):
                location = span.start
                break
            # otherwise a part of a compound statement, which does not compile alone
    return Diagnostic(location, "R001", "this statement is nested too deeply for Python to "
                      "compile", "error", None)


def _diagnostic(exc: BaseException, translation, pyfile: str) -> Diagnostic:
    line = None
    for frame, lineno in traceback.walk_tb(exc.__traceback__):
        if frame.f_code.co_filename == pyfile:
            line = lineno
    span = translation.line_map.get(line) if line is not None else None
    message = str(exc) if isinstance(exc, AutolevModelError) else \
        f"this statement failed: {type(exc).__name__}: {exc}"
    loc = span.start if span is not None else Location(pyfile, line or 1, 1)
    return Diagnostic(loc, "R001", message, "error", None)


def load_python(path) -> object:
    """The model of a converted module (`python model.py`, `autolev run model.py`), as
    the file now reads (the user may have edited it): a statement that fails, or text
    that is not Python, is a diagnostic at its line, with the Autolev statement the
    comments above it quote."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise AutolevFileError(p, f"cannot read: {getattr(exc, 'strerror', None) or exc}")
    return run_python(text, str(p))


def run_python(text: str, filename: str) -> object:
    """The model of a converted module's text (see load_python)."""
    module = types.ModuleType("autolev_model")
    module.__file__ = filename
    try:
        code = compile(text, filename, "exec")
    except SyntaxError as exc:
        loc = Location(filename, exc.lineno or 1, exc.offset or 1)
        raise AutolevRuntimeError(Diagnostic(loc, "R002", f"not Python: {exc.msg}", "error",
                                             None)) from None
    try:
        exec(code, module.__dict__)
    except _STATEMENT_FAILURES + _EDITING_SLIPS as exc:
        line = None
        for frame, lineno in traceback.walk_tb(exc.__traceback__):
            if frame.f_code.co_filename == filename:
                line = lineno
        message = str(exc) if isinstance(exc, AutolevModelError) else \
            f"this statement failed: {type(exc).__name__}: {exc}"
        quoted = _quoted_statement(text.splitlines(), line) if line else None
        if quoted:
            message += f" (Autolev: {quoted})"
        raise AutolevRuntimeError(Diagnostic(Location(filename, line or 1, 1), "R001",
                                             message, "error", None)) from None
    model = module.__dict__.get("model")
    if model is None:
        raise AutolevRuntimeError(Diagnostic(Location(filename, 1, 1), "R003",
                                             "this module defines no `model`", "error",
                                             None))
    model.namespace = module.__dict__
    model.source = ModelSource("python", text, filename, model.revision())
    return model


@dataclass(frozen=True)
class ModelSource:
    """What rebuilds a loaded model in another process (a sweep's workers): its
    translation, or a converted module's text; `state`: its revision() as loaded."""

    kind: str               # "translation" or "python"
    content: object         # the Translation, or the module's text
    filename: str
    state: tuple

    def load(self):
        if self.kind == "translation":
            return load_translation(self.content, self.filename)
        return run_python(self.content, self.filename)


def _quoted_statement(lines: list[str], line: int) -> str | None:
    """The Autolev statement a converted module quotes in the comments just above the
    code at `line` (1-based)."""
    k = line - 2
    while k >= 0 and lines[k].strip() and not lines[k].lstrip().startswith("#"):
        k -= 1
    quoted = []
    while k >= 0 and lines[k].lstrip().startswith("#"):
        quoted.insert(0, lines[k].lstrip()[1:].strip())
        k -= 1
    return " ".join(q for q in quoted if q) or None


def load_for_run(path) -> tuple[object, list]:
    """The model for `autolev run`: as `autolev.load`, except that when the only
    statements that fail come after the last CODE command, the model is built up to
    that command (Autolev's session rejected a bad statement and went on; the program
    CODE wrote did not depend on what followed).  Returns (model, notes)."""
    p = Path(path)
    try:
        result = translation(p)
        return load_translation(result, str(p)), []
    except (AutolevTranslationError, AutolevRuntimeError) as exc:
        failure = exc
    program = parse(p)
    codes = [i for i, st in enumerate(program.statements) if st.kind == "code"]
    if not codes or codes[-1] == len(program.statements) - 1:
        raise failure
    cut = dataclasses.replace(program, statements=program.statements[:codes[-1] + 1])
    result = translate(cut)
    if any(d.severity == "error" for d in result.diagnostics):
        raise failure
    try:
        model = load_translation(result, str(p))
    except AutolevRuntimeError:
        raise failure from None
    first = next(d for d in failure.diagnostics if d.severity == "error")
    notes = [f"statements after the last CODE command fail and are left out of the run "
             f"(first: {first.format(context=False).splitlines()[0]})"]
    return model, notes


__all__ = ["load", "load_translation", "load_for_run", "load_python", "run_python",
           "ModelSource"]
