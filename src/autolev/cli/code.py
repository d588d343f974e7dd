"""`autolev code`: the programs of a model's CODE commands, in Autolev's layout.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .common import failed_write, load_model, overwrite_option, statement_label


def cmd_code(ns: argparse.Namespace) -> int:
    """Write the programs a model's CODE commands name, in Autolev's layout."""
    from ..programs import write_programs

    path = Path(ns.file)
    model = load_model(path)
    if model is None:
        print(f"{path}: no program written", file=sys.stderr)
        return 1
    if not model.code_commands:
        print(f"{path}: the model has no CODE command: no program to write",
              file=sys.stderr)
        return 1
    out = Path(ns.out)
    try:
        done = write_programs(model, out, overwrite=ns.overwrite, quirks=ns.quirks)
    except OSError as exc:
        print(f"autolev code: cannot write into {out}: {failed_write(exc)}",
              file=sys.stderr)
        return 1
    finally:
        model.keep_built()        # loaded as for a run: it goes into the cache now
    refused = [w for w in done if w.refused]
    label = statement_label(model, path)
    for w in done:
        if w.refused:
            print(f"{label(w.command)}: error: {w.refused}", file=sys.stderr)
            continue
        for note in w.notes:
            print(f"{label(w.command)}: note: {note}", file=sys.stderr)
        if not ns.quiet:
            print("\n".join(f"wrote {f}" for f in w.files))
    return 1 if refused else 0


def add_code(sub) -> None:
    code = sub.add_parser(
        "code", help="write the programs of a model's CODE commands (Autolev's layout)",
        description="Write, for every CODE command of FILE, the program it names, in the "
        "layout of the programs Autolev wrote (the same global names, functions and "
        "section comments, reading the same .in file), and the .in file itself.  Written: "
        "CODE ALGEBRAIC and NONLINEAR into C (.c) and Matlab (.m); CODE DYNAMICS and ODE "
        "into C (.c), Matlab (.m) and Fortran 77 (.f, .for: Autolev 3.2's layout, with a "
        ".dir file, the file names in lower case).  Any other kind or language (a Fortran "
        "ALGEBRAIC program, CODE DYNAMICS with arguments) is reported and not written.  "
        "Folders in a CODE file name are kept under --out; a name whose folders would leave "
        "it (../c/bike.c) is written by its own name in --out, where autolev run writes "
        "its files, and said.")
    code.add_argument("file", metavar="FILE", help=".al model")
    code.add_argument("--out", metavar="DIR", default=".",
                      help="folder for the programs (default: the current folder)")
    code.add_argument("--no-quirks", dest="quirks", action="store_false",
                      help="compute the values meant where Autolev's programs computed "
                      "others (a quantity named i1 in a C program's outputs), as "
                      "`autolev run --no-quirks` does")
    code.add_argument("-q", "--quiet", action="store_true")
    overwrite_option(code)
    code.set_defaults(func=cmd_code)
