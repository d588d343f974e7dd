"""What the commands share: loading a model for a run, the options every run
takes, NAME=VALUE lists, the CODE statement a message points at.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..engine.integrators import METHODS, of_program
from ..errors import AutolevRuntimeError, AutolevSyntaxError, AutolevTranslationError
from . import background

MODEL_SUFFIXES = (".al",)
MACRO_SUFFIXES = (".a",)


class UsageError(Exception):
    """A wrong use of the command line: main says it once, as `autolev COMMAND: error:
    ...`, and exits with 2.  `diagnostics`: those of an option's text, shown with it."""

    def __init__(self, message: str, diagnostics=()):
        super().__init__(message)
        self.diagnostics = list(diagnostics)


def print_diagnostics(diagnostics, prefix: str = "") -> None:
    """Diagnostics in the order of the files and lines they point at."""
    from ..irbuild import sort_key
    for d in sorted(diagnostics, key=sort_key):
        print(prefix + d.format(), file=sys.stderr)


def failure_diagnostics(path: Path, exc) -> list:
    """What stopped a model, as `check` shows it: after a syntax error the statements
    that did read are translated too, so every command shows the errors in one round."""
    if not isinstance(exc, AutolevSyntaxError) or path.suffix.lower() == ".py":
        return exc.diagnostics
    from ..pipeline import diagnostics
    return diagnostics(path)


def failed_write(exc: OSError) -> str:
    """Why a file could not be written, and which: a rename's target (filename2), not
    the temporary it renamed (a folder in the way of out/x.c said only 'Is a
    directory')."""
    where = exc.filename2 or exc.filename
    return f"{exc.strerror or exc}" + (f" ({where})" if where and exc.strerror else "")


def print_warning(message, category, filename, lineno, file=None, line=None):
    print(f"autolev: warning: {message}", file=sys.stderr)


def load_model(path: Path, progress=None, before_building=None):
    """The model, or None after printing its diagnostics; a load past two seconds is
    announced on `progress` (a stream, or None); `before_building`: called with the
    translation of a model to be built (loader.load_translation)."""
    from ..loader import load_for_run, load_python
    from ..runtime.steps import SlowStep
    if path.suffix.lower() != ".py":
        background.wait_for_finishing(path, progress)
    try:
        with SlowStep(progress, f"{path}: reading and forming the model"):
            if path.suffix.lower() == ".py":      # a converted model, as it now reads
                model, notes = load_python(path), []
            else:
                model, notes = load_for_run(path, before_building)
    except (AutolevSyntaxError, AutolevTranslationError, AutolevRuntimeError) as exc:
        print_diagnostics(failure_diagnostics(path, exc))
        return None
    for note in notes:
        print(note, file=sys.stderr)
    return model


def statement_label(model, path: Path):
    """file:line of a CODE command's statement (the model's path when unknown)."""
    located = model.loaded.code_locations if model.loaded is not None else []
    where = {id(c): w for c, w in zip(model.code_commands, located)}

    def label(command) -> str:
        w = where.get(id(command))
        return f"{w.start.file}:{w.start.line}" if w is not None else str(path)
    return label


def specified_values(model, ns: argparse.Namespace) -> dict:
    """--specified NAME=EXPR as {symbol: expression} (UsageError: one that is not)."""
    from ..specified import SpecifiedValueError, specified_definitions
    try:
        return specified_definitions(model, name_values(ns.specified, "--specified"),
                                     "--specified")
    except SpecifiedValueError as exc:
        raise UsageError("a --specified value cannot be one", exc.diagnostics) from None


def name_values(items, option: str, numbers: bool = False) -> dict:
    """NAME=VALUE items of a repeatable option (with `numbers`, each VALUE a number as
    an .in file writes it); UsageError for one that is not."""
    from ..engine.numbers import parse_number
    values = {}
    for item in items or []:
        name, sep, value = item.partition("=")
        if not sep or not name.strip():
            raise UsageError(f"{option} expects NAME=VALUE, not {item!r}")
        if numbers and parse_number(value) is None:
            raise UsageError(f"{option} {item}: {value.strip() or 'nothing'} is not a finite "
                             "number")
        values[name.strip()] = value.strip()
    return values


def refuse_unknown_names(model, overrides: dict) -> None:
    """UsageError for --set names that are no quantity of the model as built; a name
    declared after its last CODE statement is said so (no program reads it)."""
    unknown = [name for name in overrides if not model.names_a_quantity(name)]
    if not unknown:
        return
    declared = {name.upper() for name in model.loaded.names} if model.loaded else set()
    later = [name for name in unknown if name.rstrip("'").upper() in declared]
    if later:
        raise UsageError(f"--set {', '.join(later)}: declared after the model's last CODE "
                         "statement, so no program of its CODE commands reads "
                         f"{'it' if len(later) == 1 else 'them'}")
    raise UsageError(f"--set {', '.join(unknown)}: the model has no quantity of "
                     f"{'that name' if len(unknown) == 1 else 'those names'}")


def listed(values) -> list:
    """Names given as repeated options, each possibly comma-separated."""
    return [n.strip() for v in values or () for n in v.split(",") if n.strip()]


def has_matplotlib() -> bool:
    import importlib.util
    return importlib.util.find_spec("matplotlib") is not None


def megabytes(size: int) -> str:
    return f"{size / 2 ** 20:.1f} MB"


def positive_int(text: str) -> int:
    """An option's whole number of at least 1 (argparse reports anything else)."""
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected a whole number of at least 1, not {text!r}")
    return value


def model_value_options(parser, backend_help: str = "compiled C when a compiler is found "
                        "(auto), or pure Python") -> None:
    """The model and where its values come from, shared by `run`, `animate` and
    `linearize`."""
    parser.add_argument("file", metavar="FILE", help=".al model")
    parser.add_argument("--set", action="append", metavar="NAME=VALUE",
                        help="an input value, in the unit the model gives it (degrees for a "
                        "DEG input); repeatable")
    parser.add_argument("--in", dest="infile", metavar="FILE.in",
                        help="read input values from an Autolev .in file")
    parser.add_argument("--specified", action="append", metavar="NAME=EXPR",
                        help="a SPECIFIED quantity the model leaves undefined, as an "
                        "Autolev expression of T, the model's constants and variables "
                        "(e.g. 'F=3*SIN(2*PI*T)'); --set NAME=VALUE gives it a constant "
                        "value; repeatable")
    parser.add_argument("--backend", default="auto", choices=("auto", "c", "python"),
                        help=backend_help)
    parser.add_argument("--zero-missing", action="store_true",
                        help="give 0 to constants that have no value (INPUT, --in or --set) "
                        "instead of stopping before the build")


def run_options(parser) -> None:
    """The options of a run, shared by `run` and `animate`."""
    model_value_options(parser)
    parser.add_argument("--out", default=".", metavar="DIR",
                        help="folder for the output files (default: the current folder)")
    parser.add_argument("--method", default=None, metavar="M",
                        help=f"integrator: {', '.join(METHODS)} (default: the one of "
                        "Autolev's program for each CODE file: "
                        f"{of_program('m').name} -- Matlab's ode45 -- for .m, else "
                        "Kutta-Merson)")
    parser.add_argument("--tfinal", type=float, metavar="T", help="final time (TFINAL)")
    parser.add_argument("--no-quirks", dest="quirks", action="store_false",
                        help="compute the values meant where Autolev's programs computed "
                        "others (a quantity named i1 in a C program's outputs)")
    parser.add_argument("-q", "--quiet", action="store_true")
    overwrite_option(parser)


def overwrite_option(parser) -> None:
    parser.add_argument("--overwrite", action="store_true",
                        help="replace files in the way that autolev did not write (an .in "
                        "file you edited, Autolev's own output); without it they stop the "
                        "command")
