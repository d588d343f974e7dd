"""Executing a translated model, with failures reported at the Autolev statement."""
from __future__ import annotations


import traceback
import types

import sympy as sm
from sympy.matrices.exceptions import NonInvertibleMatrixError

from .errors import AutolevRuntimeError, Diagnostic, Location
from .runtime.vector import AutolevModelError

# what a model's own statements can raise when the model asks for something impossible
# (a division by zero, a non-square matrix to invert, ...), besides our own error
_STATEMENT_FAILURES = (AutolevModelError, TypeError, ValueError, ZeroDivisionError,
                       ArithmeticError, IndexError, KeyError, AttributeError,
                       NotImplementedError, RecursionError, sm.SympifyError,
                       NonInvertibleMatrixError)


def load_translation(translation, filename: str):
    """Run the generated module; return its model, with `namespace` and `names`."""
    name = "autolev_model"
    module = types.ModuleType(name)
    module.__file__ = filename + ".py"
    code = compile(translation.code, module.__file__, "exec")
    try:
        exec(code, module.__dict__)
    except _STATEMENT_FAILURES as exc:
        raise AutolevRuntimeError(_diagnostic(exc, translation, module.__file__)) from None
    model = module.__dict__["model"]
    model.namespace = module.__dict__
    model.names = translation.names
    return model


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


__all__ = ["load_translation"]
