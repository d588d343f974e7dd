"""autolev: Autolev 4.1 models in Python.

    import autolev
    program = autolev.parse(open("pendulum.al").read(), "pendulum.al")

`parse` reads a model into the IR and raises `AutolevSyntaxError` (carrying every
diagnostic) when it cannot.  `translation` and `transpile` translate it, `load` builds
its `Model`, `verify` replays Autolev's recorded responses against it, `grid` makes
the points of a parameter study, `write_programs` writes a model's CODE programs in
Autolev's layout and `export_sympy` a loaded model as a standalone SymPy script.  A bug
in autolev itself is `AutolevInternalError`.
"""
from __future__ import annotations

import importlib

__version__ = "0.1.0"
__all__ = ["parse", "translation", "transpile", "load", "verify", "grid", "write_programs",
           "export_sympy", "Program",
           "AutolevError", "AutolevSyntaxError", "AutolevTranslationError",
           "AutolevRuntimeError", "AutolevFileError", "AutolevInternalError", "Diagnostic",
           "Location", "Span", "__version__"]

# the stages are imported on first use, so that `import autolev` stays cheap
_LAZY = {"Program": ".ir", "parse": ".pipeline", "translation": ".pipeline",
         "transpile": ".pipeline", "load": ".loader", "verify": ".verification",
         "grid": ".runtime.studies", "write_programs": ".programs",
         "export_sympy": ".export_mechanics",
         # lazy too: `python -m autolev` imports the package before its __main__, which
         # takes a Ctrl-C while the command starts (nothing here may take long)
         **{name: ".errors" for name in (
             "AutolevError", "AutolevFileError", "AutolevInternalError",
             "AutolevRuntimeError", "AutolevSyntaxError", "AutolevTranslationError",
             "Diagnostic", "Location", "Span")}}


def __getattr__(name: str):
    if name == "errors":            # the module itself, as when it was imported here
        return importlib.import_module(".errors", __name__)
    if name not in _LAZY:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(_LAZY[name], __name__), name)
    globals()[name] = value
    return value
