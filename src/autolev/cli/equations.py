"""`autolev equations`: a model's equations of motion as LaTeX or plain sympy text.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .common import UsageError, load_model, overwrite_option


def cmd_equations(ns: argparse.Namespace) -> int:
    """Print (or write) the equations of motion of a CODE DYNAMICS or ODE."""
    from ..runtime.equations_of import equations_of
    from ..runtime.equations_text import latex, plain
    from ..engine.errors import AutolevModelError
    from ..runtime.tools import write_output

    path = Path(ns.file)
    model = load_model(path, sys.stderr)
    if model is None:
        print(f"{path}: no equations written", file=sys.stderr)
        return 1
    try:
        command = model.command_to_linearize(
            int(ns.code) if ns.code and ns.code.isdigit() else ns.code)
    except AutolevModelError as exc:
        raise UsageError(f"--code: {exc}") from None
    try:
        eqs = equations_of(model, command, values=False)
    except AutolevModelError as exc:
        print(f"{path}: error: {exc}", file=sys.stderr)
        return 1
    finally:
        model.keep_built()
    text = plain(eqs) if ns.sympy else latex(eqs)
    if ns.output is None:
        sys.stdout.write(text)
        return 0
    target = Path(ns.output)
    try:
        write_output(target.parent, target.name, text, ns.overwrite)
    except OSError as exc:
        print(f"autolev equations: cannot write {target}: {exc.strerror or exc}",
              file=sys.stderr)
        return 1
    print(f"wrote {target}")
    return 0


def add_equations(sub) -> None:
    eq = sub.add_parser(
        "equations", help="a model's equations of motion as LaTeX or sympy text",
        description="Print the equations of motion autolev integrates for a CODE DYNAMICS "
        "or ODE of FILE (the first CODE DYNAMICS, or --code): each intermediate (Z's and "
        "definitions) as a definition, the explicit rates (the kinematical differential "
        "equations), and M u' = F with the mass matrix and forcing.  No constant needs a "
        "value.")
    eq.add_argument("file", metavar="FILE", help=".al model")
    form = eq.add_mutually_exclusive_group()
    form.add_argument("--latex", action="store_true",
                      help="LaTeX for amsmath (the default): align* and equation*")
    form.add_argument("--sympy", action="store_true",
                      help="plain text: NAME = expression lines, then mass_matrix and "
                      "forcing as sympy prints them")
    eq.add_argument("--code", metavar="FILE",
                    help="the CODE command (its file name or 0-based index)")
    eq.add_argument("-o", "--output", metavar="OUT",
                    help="write the text to OUT instead of printing it")
    overwrite_option(eq)
    eq.set_defaults(func=cmd_equations)
