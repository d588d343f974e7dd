"""Executing a translated model, with failures reported at the Autolev statement.

What a model's statements may raise as the model's own fault is the runtime's
AutolevModelError, the few arithmetic failures of the values they ask for, and sympy's
refusal of what a statement's own line does with them; anything else raised while a
translation runs is a bug in autolev (AutolevInternalError)."""
from __future__ import annotations

import dataclasses
import os
import textwrap
import traceback
import types
import warnings
from dataclasses import dataclass
from pathlib import Path

from . import modelcache
from .errors import (AutolevFileError, AutolevInternalError, AutolevRuntimeError,
                     AutolevSyntaxError, AutolevTranslationError, Diagnostic, Location)
from .engine.errors import AutolevModelError
from .translate import Translation, translate

# sympy and the runtime are imported where a model is built (not at this module's
# import: a command that reads only the translation, as the note naming missing values
# before the model is built, does without them)


def _model_faults() -> tuple:
    """The model's fault: what the runtime refuses, and arithmetic on the values it asks
    for (a division by zero, an overflow, a singular matrix to invert)."""
    from sympy.matrices.exceptions import NonInvertibleMatrixError
    return (AutolevModelError, ZeroDivisionError, OverflowError, NonInvertibleMatrixError)

# sympy's refusals of the calls and operators a statement's own line applies to the
# model's values (the translation writes matrix arithmetic, element access, int() of an
# index and functions such as MIN as Python, which no runtime function checks first):
# wrong shapes, an element outside the matrix, a symbol where a number is needed, MIN of
# a value that is not real
_OPERATOR_REFUSALS = (ValueError, IndexError, TypeError)

# autolev's own code: an unexpected exception raised in it is autolev's bug
_PACKAGE = os.path.dirname(os.path.abspath(__file__)) + os.sep


def _sympy_folder() -> str:
    import sympy
    return os.path.dirname(os.path.abspath(sympy.__file__)) + os.sep


def load(path):
    """Translate the model at `path`, execute it, and return its `Model`."""
    p = Path(path)
    return load_translation(_translation(p), str(p))


def _translation(path: Path):
    """The model file's translation (read back from the cache while nothing it read
    changed)."""
    def translated():
        # the parser takes a third of a warm run's imports: only a new text needs it
        from .pipeline import translation
        return translation(path)
    return modelcache.translation(path, translated)


def translation_of(path) -> Translation:
    """The translation of the model file at `path` (from the cache while nothing it
    read changed); raises AutolevSyntaxError or AutolevTranslationError."""
    return _translation(Path(path))


def files_read(path) -> list[str] | None:
    """Every file reading the model at `path` reads (its RUN files, macros, functions),
    the model's first; None when it cannot be read or parsed."""
    p = Path(path)
    try:
        return list(_translation(p).files)
    except AutolevTranslationError:
        pass
    from .pipeline import parse
    try:
        return list(parse(p).files)
    except (AutolevSyntaxError, AutolevFileError):
        return None


def load_translation(translation, filename: str, write_later: bool = False,
                     before_building=None):
    """Run the generated module (or read the model it built from the cache of built
    models); return its model, with `namespace` and `names`.  `write_later`: a model
    built now goes into the cache when its first runs end (see ModelKeeper), with the
    numeric systems they built, instead of now and again then.  `before_building`: called
    with the translation when the model is to be built (not read from the cache)."""
    key = modelcache.key(translation.code, filename)
    built = modelcache.read(key)
    keeper = None
    if built is None:
        if before_building is not None:
            before_building(translation)
        built = _build(translation, filename)
        keeper = ModelKeeper(key, built.warnings, _as_built(built.model))
        if not write_later:
            keeper.flush(built.model)
    built.warn_again()
    model = built.model
    model.loaded = dataclasses.replace(
        model.loaded, names=translation.names, namespaces=translation.namespaces,
        code_locations=list(translation.code_spans), defined_at=dict(translation.defined_at),
        statements_at=dict(translation.statements_at),
        source=ModelSource("translation", translation, filename, model.revision()),
        # the numeric systems its runs build are kept with it too, while it is as built
        keeper=keeper or ModelKeeper(key, built.warnings, _as_built(model), False))
    return model


def _as_built(model) -> tuple:
    """What a caller may change in a model after loading it (statements, definitions,
    inputs, outputs, settings): a model changed since is not what its module built."""
    return model.revision()


class ModelKeeper:
    """Writes a loaded model back to the cache of built models, with the numeric
    systems its runs built (`added`), once the work that builds them is done (`flush`:
    the end of run_commands, simulate and linearize) and only while the model is as
    its module built it: one write of the whole entry instead of one per system."""

    def __init__(self, key: str, warnings_: list, as_built: tuple, pending: bool = True):
        self.key, self.warnings, self.as_built, self.pending = key, warnings_, as_built, pending

    def added(self) -> None:
        self.pending = True

    def flush(self, model) -> None:
        if self.pending and _as_built(model) == self.as_built:
            modelcache.write(self.key, modelcache.Built(model, self.warnings))
        self.pending = False


def _build(translation, filename: str) -> modelcache.Built:
    """Execute the module, keeping the warnings its statements give (each once) to be
    given again whenever the model is read back from the cache."""
    caught: list = []
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            model = _execute(translation, filename)
    except BaseException:
        modelcache.Built(None, _distinct(caught)).warn_again()
        raise
    return modelcache.Built(model, _distinct(caught))


def _distinct(caught) -> list:
    return list(dict.fromkeys((str(w.message), w.category, w.filename, w.lineno)
                              for w in caught))


def _execute(translation, filename: str):
    """The model the generated module builds, with the module's namespace."""
    name = "autolev_model"
    module = types.ModuleType(name)
    module.__file__ = filename + ".py"
    try:
        code = compile(translation.code, module.__file__, "exec")
    except (RecursionError, SyntaxError) as exc:
        if not _beyond_pythons_nesting(exc):
            raise
        raise AutolevRuntimeError(_too_deep(translation, module.__file__)) from None
    lines = translation.code.splitlines()
    try:
        exec(code, module.__dict__)
    except MemoryError:
        raise                     # the machine's limit, neither the model's nor a bug
    except Exception as exc:  # judged below; re-raised either way
        failure = _translation_failure(exc, translation, lines, module.__file__)
        # an internal error keeps autolev's traceback; the user's diagnostic needs none
        raise failure from (exc if isinstance(failure, AutolevInternalError) else None)
    from .runtime.model import Loaded
    model = module.__dict__["model"]
    model.loaded = Loaded(module.__dict__)
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


def _failed_in(exc: BaseException, filename: str) -> tuple[int | None, list[str]]:
    """The line of `filename` the exception last passed through, and the files of the
    frames below it (none when that line raised it itself)."""
    line, below = None, []
    for frame, lineno in traceback.walk_tb(exc.__traceback__):
        name = frame.f_code.co_filename
        if name == filename:
            line, below = lineno, []
        elif line is not None:
            below.append(name)
    return line, below


def _models_fault(exc: BaseException, below: list[str]) -> bool:
    """Whether exc, raised through the frames of files `below` a statement's line, is
    the model's fault rather than autolev's."""
    if isinstance(exc, (RecursionError, *_model_faults())):
        return True
    by_sympy = bool(below) and below[0].startswith(_sympy_folder()) and \
        not any(f.startswith(_PACKAGE) for f in below)
    return by_sympy and isinstance(exc, _OPERATOR_REFUSALS)


def _translation_failure(exc: Exception, translation, lines: list[str], pyfile: str):
    """The error of a generated module that raised exc: the model's R001 diagnostic at
    the .al statement, or an internal error (a bug in autolev)."""
    line, below = _failed_in(exc, pyfile)
    span = translation.line_map.get(line) if line is not None else None
    location = span.start if span is not None else Location(pyfile, line or 1, 1)
    quoted = _quoted_statement(lines, line) if line else None
    if not _models_fault(exc, below):
        return AutolevInternalError(location, _executing(quoted), exc)
    return AutolevRuntimeError(_diagnostic(exc, location))


def _executing(quoted: str | None) -> str:
    return f"executing `{quoted}`" if quoted else "executing this statement"


def _diagnostic(exc: BaseException, location: Location) -> Diagnostic:
    """The R001 diagnostic of a statement that failed by the model's fault."""
    if isinstance(exc, AutolevModelError):
        message = str(exc)
    elif isinstance(exc, RecursionError):
        message = "this statement nests too deeply for Python to evaluate"
    else:
        message = f"this statement failed: {type(exc).__name__}: {exc}"
    return Diagnostic(location, "R001", message, "error", None)


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
    """The model of a converted module's text (see load_python).  The module is the
    user's Python: what its own lines raise (a NameError of an edit, a sympy call that
    fails) is the user's fault; an unexpected exception raised inside autolev, from a
    call the module made, is autolev's bug."""
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
    except MemoryError:
        raise                     # the machine's limit, neither the model's nor a bug
    except Exception as exc:  # judged below; re-raised either way
        failure = _python_failure(exc, text, filename)
        # an internal error keeps autolev's traceback; the user's diagnostic needs none
        raise failure from (exc if isinstance(failure, AutolevInternalError) else None)
    model = module.__dict__.get("model")
    if model is None:
        raise AutolevRuntimeError(Diagnostic(Location(filename, 1, 1), "R003",
                                             "this module defines no `model`", "error",
                                             None))
    from .runtime.model import Loaded
    model.loaded = Loaded(module.__dict__,
                          source=ModelSource("python", text, filename, model.revision()))
    return model


def _python_failure(exc: Exception, text: str, filename: str) -> Exception:
    """The error of a converted module that raised exc: an internal error when autolev
    raised it unexpectedly, else the user's R001 at the module's line."""
    line, below = _failed_in(exc, filename)
    quoted = _quoted_statement(text.splitlines(), line) if line else None
    location = Location(filename, line or 1, 1)
    # the user's own Python, or a library it called itself, raised it: the user's
    called_autolev = bool(below) and below[0].startswith(_PACKAGE)
    if called_autolev and not _models_fault(exc, below):
        return AutolevInternalError(location, _executing(quoted), exc)
    d = _diagnostic(exc, location)
    if quoted:
        d = dataclasses.replace(d, message=f"{d.message} (Autolev: {quoted})")
    return AutolevRuntimeError(d)


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


def load_for_run(path, before_building=None) -> tuple[object, list]:
    """The model for `autolev run` (and the other commands on its CODE commands): as
    `autolev.load`, but built through its last CODE statement only, since the programs
    CODE wrote do not depend on what follows (Autolev wrote each when it read its
    line); when statements after it fail to translate, the model is built up to it
    (Autolev's session rejected a bad statement and went on).  A model built now goes
    into the cache of built models when its first run or linearization ends.  Returns
    (model, notes): the translation's warnings and what was left out, each a line
    `file:line:col: warning: ...` to show the user.  `before_building`: as
    load_translation's."""
    p = Path(path)
    try:
        result = _translation(p).through_last_code()
        model = load_translation(result, str(p), write_later=True,
                                 before_building=before_building)
        return model, translation_warnings(result)
    except AutolevTranslationError as exc:
        failure = exc
    from .pipeline import parse
    program = parse(p)
    codes = [i for i, st in enumerate(program.statements) if st.kind == "code"]
    if not codes or codes[-1] == len(program.statements) - 1:
        raise failure
    cut = dataclasses.replace(program, statements=program.statements[:codes[-1] + 1])
    result = translate(cut)
    if any(d.severity == "error" for d in result.diagnostics):
        raise failure
    model = load_translation(result, str(p), write_later=True,
                             before_building=before_building)
    first = next(d for d in failure.diagnostics if d.severity == "error")
    notes = [f"{p}: warning: statements after the last CODE command fail to translate and "
             f"are left out of the run (first: {first.format(context=False).splitlines()[0]})"]
    return model, translation_warnings(result) + notes


def translation_warnings(result: Translation) -> list[str]:
    """The translation's warnings, each a line `file:line:col: warning: ...`."""
    return [d.format(context=False) for d in result.diagnostics if d.severity == "warning"]


__all__ = ["load", "load_translation", "load_for_run", "load_python", "run_python",
           "ModelSource", "translation_of", "files_read", "translation_warnings"]
