"""`autolev check`: every problem of a model, in one round.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

from ..errors import AutolevError, AutolevFileError, Diagnostic
from .common import MACRO_SUFFIXES, MODEL_SUFFIXES


def model_files(args: list[str]) -> list[Path]:
    """The files named, with folders searched for .al files (any case)."""
    out: list[Path] = []
    for a in args:
        p = Path(a)
        if p.is_dir():
            out.extend(sorted(f for f in p.rglob("*")
                              if f.is_file() and f.suffix.lower() in MODEL_SUFFIXES))
        else:
            out.append(p)
    return out


def check_file(path: Path) -> list[Diagnostic]:
    """Every diagnostic for one file (errors and warnings), in file order: the syntax,
    then (for a model that reads) everything the translation finds -- undeclared
    names, wrong kinds, unknown functions -- so that a clean check means the model
    converts.  Nothing is built or run."""
    from ..pipeline import diagnostics
    return diagnostics(path, macro=path.suffix.lower() in MACRO_SUFFIXES)


def _same_file(a, b) -> bool:
    return os.path.realpath(a) == os.path.realpath(b)


def cmd_check(ns: argparse.Namespace) -> int:
    files = model_files(ns.files)
    if not files:       # only folders were named (a file named is checked, there or not)
        print(f"autolev check: no .al files found in {', '.join(ns.files)}",
              file=sys.stderr)
        return 1
    report = []
    n_errors = n_warnings = n_bad = 0
    for path in files:
        try:
            diags = check_file(path)
        except AutolevFileError as exc:
            diags = []
            # a file the model includes (RUN, macro, function) is named: the model reads
            failure = exc.reason if _same_file(exc.path, path) else str(exc)
        except AutolevError as exc:
            diags = []
            failure = str(exc)
        else:
            failure = None
        errors = sum(d.severity == "error" for d in diags) + (failure is not None)
        warnings = sum(d.severity == "warning" for d in diags)
        n_errors += errors
        n_warnings += warnings
        n_bad += errors > 0
        report.append({"file": str(path), "errors": errors, "warnings": warnings,
                       "diagnostics": [d.as_dict() for d in diags]
                       + ([{"file": str(path), "severity": "error", "code": "E000",
                            "message": failure}] if failure else [])})
        if not ns.json:
            if failure:
                print(f"{path}: error: {failure}")
            for d in diags:
                if d.severity == "error" or not ns.quiet:
                    print(d.format(context=not ns.no_context))
    summary = {"files": len(files), "files_with_errors": n_bad, "errors": n_errors,
               "warnings": n_warnings}
    if ns.json:
        json.dump({"files": report, "summary": summary}, sys.stdout, indent=2)
        print()
    else:
        plural = lambda n, w: f"{n} {w}{'' if n == 1 else 's'}"  # noqa: E731
        print(f"checked {plural(len(files), 'file')}: {plural(n_errors, 'error')}, "
              f"{plural(n_warnings, 'warning')}"
              + (f" ({plural(n_bad, 'file')} with errors)" if n_bad else ""))
    return 1 if n_errors else 0


def add_check(sub) -> None:
    check = sub.add_parser("check", help="report syntax errors in .al files",
                           description="Read each model (with its macros and RUN files) "
                           "and report every problem as file:line:col. Exit status 0 when "
                           "all files are clean, 1 otherwise.")
    check.add_argument("files", nargs="+", metavar="FILE",
                       help=".al model (or a folder to search for them); a .a macro file "
                       "is checked with its #k# placeholders replaced by ARGk")
    check.add_argument("--json", action="store_true", help="machine-readable report")
    check.add_argument("-q", "--quiet", action="store_true", help="errors only, no warnings")
    check.add_argument("--no-context", action="store_true",
                       help="omit the source line and caret under each diagnostic")
    check.set_defaults(func=cmd_check)
