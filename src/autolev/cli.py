"""The `autolev` command line."""
from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

from . import __version__
from .errors import AutolevError, AutolevSyntaxError, Diagnostic

MODEL_SUFFIXES = (".al",)
MACRO_SUFFIXES = (".a",)


def _model_files(args: list[str]) -> list[Path]:
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
    """Every diagnostic for one file (errors and warnings), in file order."""
    from .irbuild import Builder, sort_key
    from .source import SourceFile

    src = SourceFile.read(path, str(path))
    builder = Builder(src.name, path)
    if path.suffix.lower() in MACRO_SUFFIXES:
        builder.build_macro_source(src)
    else:
        builder.build_source(src)
    return sorted(builder.diagnostics, key=sort_key)


def cmd_check(ns: argparse.Namespace) -> int:
    files = _model_files(ns.files)
    if not files:
        print("autolev check: no .al files found", file=sys.stderr)
        return 1
    report = []
    n_errors = n_warnings = n_bad = 0
    for path in files:
        try:
            diags = check_file(path)
        except AutolevError as exc:   # unreadable file
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


def cmd_convert(ns: argparse.Namespace) -> int:
    """Translate one model; write the module only when translation succeeded."""
    import autolev
    from autolev.irbuild import sort_key

    path = Path(ns.file)
    try:
        result = autolev.translation(path)
    except (AutolevSyntaxError, autolev.AutolevTranslationError) as exc:
        for d in sorted(exc.diagnostics, key=sort_key):
            print(d.format(), file=sys.stderr)
        n = sum(d.severity == "error" for d in exc.diagnostics)
        print(f"{path}: not converted ({n} error{'s' if n != 1 else ''})", file=sys.stderr)
        return 1
    for d in result.diagnostics:
        print(d.format(), file=sys.stderr)
    out = Path(ns.output) if ns.output else path.with_suffix(".py")
    if out.resolve() == path.resolve():
        print(f"autolev convert: refusing to overwrite the model {path}", file=sys.stderr)
        return 2
    tmp = out.with_name(out.name + ".tmp")
    tmp.write_text(result.code)
    tmp.replace(out)              # never a half-written module
    if not ns.quiet:
        print(f"wrote {out}")
    return 0


def build_parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(
        prog="autolev",
        description="Autolev 4.1 models in Python: check, translate and run .al files.")
    ap.add_argument("--version", action="version", version=f"autolev {__version__}")
    sub = ap.add_subparsers(dest="command", metavar="COMMAND")

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

    convert = sub.add_parser("convert", help="translate a model into a Python module",
                             description="Translate FILE into a Python module on "
                             "autolev.runtime; importing it builds the model, running it "
                             "performs the model's CODE commands.  Nothing is written when "
                             "the model has errors.")
    convert.add_argument("file", metavar="FILE", help=".al model")
    convert.add_argument("-o", "--output", metavar="OUT.py",
                         help="where to write the module (default: FILE with .py)")
    convert.add_argument("-q", "--quiet", action="store_true")
    convert.set_defaults(func=cmd_convert)
    return ap


def main(argv: list[str] | None = None) -> int:
    ap = build_parser()
    ns = ap.parse_args(argv)
    if ns.command is None:
        ap.print_help()
        return 2
    try:
        return ns.func(ns)
    except AutolevSyntaxError as exc:
        print(exc, file=sys.stderr)
        return 1
    except AutolevError as exc:
        print(f"autolev: error: {exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        # output piped into `head` and the like: stop quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1


if __name__ == "__main__":
    sys.exit(main())
