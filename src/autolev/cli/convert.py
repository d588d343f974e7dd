"""`autolev convert`: a model translated into a Python module.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..errors import AutolevSyntaxError, AutolevTranslationError
from .common import UsageError, overwrite_option, print_diagnostics


def cmd_convert(ns: argparse.Namespace) -> int:
    """Translate one model; write the module only when translation succeeded."""
    from ..pipeline import translation

    path = Path(ns.file)
    try:
        result = translation(path)
    except (AutolevSyntaxError, AutolevTranslationError) as exc:
        print_diagnostics(exc.diagnostics)
        n = sum(d.severity == "error" for d in exc.diagnostics)
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
        write_output(out.parent, out.name, result.code, ns.overwrite)  # whole, or nothing
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
                         help="where to write the module (default: FILE with .py)")
    convert.add_argument("-q", "--quiet", action="store_true")
    overwrite_option(convert)
    convert.set_defaults(func=cmd_convert)
