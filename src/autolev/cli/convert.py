"""`autolev convert`: a model translated into a Python module.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..errors import AutolevSyntaxError, AutolevTranslationError
from .common import (UsageError, failure_diagnostics, name_values, overwrite_option,
                     print_diagnostics)


def cmd_convert(ns: argparse.Namespace) -> int:
    """Translate one model; write the module only when translation succeeded."""
    from ..pipeline import translation

    path = Path(ns.file)
    if ns.to == "sympy":
        return _convert_to_sympy(path, ns)
    if ns.infile is not None or ns.set:
        raise UsageError("--in and --set give the values of a --to sympy script; a "
                         "module on autolev.runtime takes them when it runs")
    if ns.level is not None:
        raise UsageError("--level chooses the level of a --to sympy script")
    try:
        result = translation(path)
    except (AutolevSyntaxError, AutolevTranslationError) as exc:
        shown = failure_diagnostics(path, exc)
        print_diagnostics(shown)
        n = sum(d.severity == "error" for d in shown)
        print(f"{path}: not converted ({n} error{'s' if n != 1 else ''})", file=sys.stderr)
        return 1
    print_diagnostics(result.diagnostics)
    out = Path(ns.output) if ns.output else path.with_suffix(".py")
    if out.resolve() == path.resolve():
        raise UsageError(f"refusing to overwrite the model {path}")
    from ..runtime.tools import write_output
    if out.is_dir():
        raise UsageError(f"{out} is a folder; -o names the module's file")
    try:
        out.parent.mkdir(parents=True, exist_ok=True)      # as run --out makes its folder
        write_output(out.parent, out.name, result.code, ns.overwrite)  # whole, or nothing
    except OSError as exc:
        print(f"autolev convert: cannot write {out}: {exc.strerror or exc}", file=sys.stderr)
        return 1
    if not ns.quiet:
        print(f"wrote {out}")
    return 0


def _convert_to_sympy(path: Path, ns: argparse.Namespace) -> int:
    """The model's equations of motion as a standalone SymPy script."""
    from ..export_mechanics import AS_THEY_STAND, sympy_export
    from ..errors import some_names
    from ..engine.errors import AutolevModelError
    from ..runtime.tools import write_output
    from .common import load_model, refuse_unknown_names

    out = Path(ns.output) if ns.output else path.with_name(path.stem + "_sympy.py")
    if out.is_dir():
        raise UsageError(f"{out} is a folder; -o names the script's file")
    if out.resolve() == path.resolve():
        raise UsageError(f"refusing to overwrite the model {path}")
    overrides = name_values(ns.set, "--set", numbers=True)
    model = load_model(path)
    if model is None:
        print(f"{path}: not converted", file=sys.stderr)
        return 1
    refuse_unknown_names(model, overrides)
    try:
        script = sympy_export(model, path.name, infile=ns.infile, overrides=overrides,
                              level=ns.level or "auto")
    except AutolevModelError as exc:
        print(f"{path}: error: {exc}", file=sys.stderr)
        return 1
    if script.exported == AS_THEY_STAND:
        print(f"{path}: note: the model writes no CODE DYNAMICS or ODE: the script holds "
              "its equations as they stand (as linearize takes them)", file=sys.stderr)
    if script.lacking:
        print(f"{path}: note: no value given for {some_names(script.lacking)}: the "
              "script's `constants` holds None for them (give each there, or here with "
              "--set NAME=VALUE or --in FILE); its equations need none", file=sys.stderr)
    try:
        out.parent.mkdir(parents=True, exist_ok=True)
        write_output(out.parent, out.name, script.text, ns.overwrite)
    except OSError as exc:
        print(f"autolev convert: cannot write {out}: {exc.strerror or exc}", file=sys.stderr)
        return 1
    if not ns.quiet:
        print(f"wrote {out}")
    return 0


def add_convert(sub) -> None:
    convert = sub.add_parser("convert", help="translate a model into a Python module",
                             description="Translate FILE into a Python module on "
                             "autolev.runtime; importing it builds the model, running it "
                             "performs the model's CODE commands.  Nothing is written when "
                             "the model has errors.")
    convert.add_argument("file", metavar="FILE", help=".al model")
    convert.add_argument("-o", "--output", metavar="OUT.py",
                         help="where to write the module (default: FILE with .py; with "
                         "--to sympy, FILE_sympy.py)")
    convert.add_argument("--to", choices=("autolev", "sympy"), default="autolev",
                         help="autolev (default): a module on autolev.runtime; sympy: a "
                         "standalone script of the equations of motion that needs only "
                         "sympy, numpy and scipy (see its docstring)")
    convert.add_argument("--in", dest="infile", metavar="FILE",
                         help="with --to sympy: values from an Autolev .in file, as "
                         "`autolev run --in` takes them")
    convert.add_argument("--set", action="append", metavar="NAME=VALUE", default=[],
                         help="with --to sympy: a value in the quantity's own unit "
                         "(repeatable; after --in)")
    convert.add_argument("--level", choices=("auto", "mechanics", "equations"),
                         help="with --to sympy: mechanics (frames, points, bodies, loads "
                         "and sympy's KanesMethod), equations (the equations of motion "
                         "as expressions), or auto (default: mechanics when the model has "
                         "no dependent or auxiliary speeds and at most 12 speeds, else "
                         "equations, the reason said in the script)")
    convert.add_argument("-q", "--quiet", action="store_true")
    overwrite_option(convert)
    convert.set_defaults(func=cmd_convert)
