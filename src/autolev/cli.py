"""The `autolev` command line."""
from __future__ import annotations

import argparse
import contextlib
import json
import math
import os
import re
import sys
from pathlib import Path

from . import __version__
from .errors import (AutolevError, AutolevFileError, AutolevInternalError, AutolevRuntimeError,
                     AutolevSyntaxError, AutolevTranslationError, Diagnostic, printable)

MODEL_SUFFIXES = (".al",)
MACRO_SUFFIXES = (".a",)

# the exit status of a bug in autolev (EX_SOFTWARE of sysexits.h)
EXIT_INTERNAL = 70
# set to 1: an internal error is shown with Python's traceback
TRACEBACK_VARIABLE = "AUTOLEV_TRACEBACK"

EPILOG = f"""exit status: 0 success; 1 the model has errors, or a command failed; 2 wrong use
of the command line; {EXIT_INTERNAL} an internal error (a bug in autolev, not in the model:
the message asks for a report; {TRACEBACK_VARIABLE}=1 in the environment shows its Python
traceback); 130 interrupted."""


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
    """Every diagnostic for one file (errors and warnings), in file order: the syntax,
    then (for a model that reads) everything the translation finds -- undeclared
    names, wrong kinds, unknown functions -- so that a clean check means the model
    converts.  Nothing is built or run."""
    from .irbuild import Builder, sort_key
    from .source import SourceFile
    from .translate import translate, vocabulary

    src = SourceFile.read(path, str(path))
    builder = Builder(src.name, path, reserved=vocabulary())
    if path.suffix.lower() in MACRO_SUFFIXES:
        builder.build_macro_source(src)
        return sorted(builder.diagnostics, key=sort_key)
    builder.build_source(src)
    program = builder.program()
    # the statements that read are translated even when others did not: one round
    more = [d for d in translate(program).diagnostics[len(program.diagnostics):]
            if not _follows_from(d, builder.errors)]
    return sorted(builder.diagnostics + more, key=sort_key)


def _follows_from(d: Diagnostic, syntax_errors: list[Diagnostic]) -> bool:
    """Whether a translation diagnostic only repeats a syntax error: a name it calls
    undeclared or of the wrong kind is a word of a line that did not read (whose
    declaration or definition is then missing)."""
    if d.code not in ("T002", "T008") or not syntax_errors:
        return False
    words = {w.lower() for e in syntax_errors
             for w in re.findall(r"[A-Za-z_][A-Za-z0-9_]*", e.source_line or "")}
    named = re.findall(r"'([A-Za-z_][A-Za-z0-9_]*)", d.message)
    named += re.findall(r"^([A-Za-z_][A-Za-z0-9_]*) has no value", d.message)
    return any(n.lower() in words for n in named)


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
        except AutolevFileError as exc:
            diags = []
            failure = exc.reason
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


def cmd_convert(ns: argparse.Namespace) -> int:
    """Translate one model; write the module only when translation succeeded."""
    from .irbuild import sort_key
    from .pipeline import translation

    path = Path(ns.file)
    try:
        result = translation(path)
    except (AutolevSyntaxError, AutolevTranslationError) as exc:
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
    from .runtime.outputs import write_output
    if out.is_dir():
        print(f"autolev convert: {out} is a folder; -o names the module's file",
              file=sys.stderr)
        return 2
    try:
        write_output(out.parent, out.name, result.code, ns.overwrite)  # whole, or nothing
    except OSError as exc:
        print(f"autolev convert: cannot write {out}: {exc.strerror or exc}", file=sys.stderr)
        return 1
    if not ns.quiet:
        print(f"wrote {out}")
    return 0


def _print_warning(message, category, filename, lineno, file=None, line=None):
    print(f"autolev: warning: {message}", file=sys.stderr)


def _load_for_run(path: Path):
    """The model, or None after printing its diagnostics."""
    from .irbuild import sort_key
    from .loader import load_for_run, load_python
    try:
        if path.suffix.lower() == ".py":      # a converted model, as it now reads
            model, notes = load_python(path), []
        else:
            model, notes = load_for_run(path)
    except (AutolevSyntaxError, AutolevTranslationError, AutolevRuntimeError) as exc:
        for d in sorted(exc.diagnostics, key=sort_key):
            print(d.format(), file=sys.stderr)
        return None
    for note in notes:
        print(note, file=sys.stderr)
    return model


def cmd_run(ns: argparse.Namespace) -> int:
    """Translate, build and run the model's CODE commands; write Autolev's files."""
    import time

    path = Path(ns.file)
    overrides = _run_overrides(ns)
    if overrides is None:
        return 2
    start = time.monotonic()
    model = _load_for_run(path)
    if model is None:
        print(f"{path}: not run", file=sys.stderr)
        return 1
    if not ns.quiet and (model.code_commands or ns.first_dynamics):
        print(f"{path}: built in {time.monotonic() - start:.1f} s")
    if not model.code_commands and not ns.first_dynamics:
        # what Autolev showed for a model that writes no program: its responses
        print(f"{path}: no CODE command: the responses Autolev displayed follow "
              "(autolev transcript FILE --out DIR writes them as NAME.all)", file=sys.stderr)
        return _print_transcript(path, None)
    from .runtime.numerics.command import names_a_quantity
    unknown = [name for name in overrides if not names_a_quantity(model, name)]
    if unknown:
        print(f"autolev run: --set {', '.join(unknown)}: the model has no quantity of "
              f"{'that name' if len(unknown) == 1 else 'those names'}", file=sys.stderr)
        return 2
    commands = _commands_to_run(model, ns, path)
    if isinstance(commands, int):
        return commands
    specified = _specified_values(model, ns, "run")
    if specified is None:
        return 2
    return _run_and_report(model, commands, overrides, specified, ns, path)


def _statement_label(model, path: Path):
    """file:line of a CODE command's statement (the model's path when unknown)."""
    located = model.loaded.code_locations if model.loaded is not None else []
    where = {id(c): w for c, w in zip(model.code_commands, located)}

    def label(command) -> str:
        w = where.get(id(command))
        return f"{w.start.file}:{w.start.line}" if w is not None else str(path)
    return label


def _specified_values(model, ns: argparse.Namespace, command: str) -> dict | None:
    """--specified NAME=EXPR as {symbol: expression}, or None after printing what is
    wrong with one."""
    from .specified import SpecifiedValueError, specified_definitions
    items = _name_values(ns.specified, "--specified")
    if items is None:
        return None
    try:
        return specified_definitions(model, items, "--specified")
    except SpecifiedValueError as exc:
        for d in exc.diagnostics:
            print(f"autolev {command}: {d.format()}", file=sys.stderr)
        return None


def _run_overrides(ns: argparse.Namespace) -> dict | None:
    """--set and --tfinal as {NAME: value}, after checking --method and --plot; None
    after printing what is wrong."""
    from .runtime.numerics.integrate import METHODS
    if ns.method is not None and ns.method not in METHODS:
        print(f"autolev run: unknown --method {ns.method} (one of {', '.join(METHODS)})",
              file=sys.stderr)
        return None
    overrides = _name_values(ns.set, "--set", numbers=True)
    if overrides is None:
        return None
    if ns.tfinal is not None:
        overrides["TFINAL"] = ns.tfinal
    if ns.plot:
        try:
            import matplotlib  # noqa: F401
        except ImportError:
            print("autolev run: --plot needs matplotlib (pip install 'autolev[plot]')",
                  file=sys.stderr)
            return None
    return overrides


def _commands_to_run(model, ns: argparse.Namespace, path: Path) -> list | int:
    """The CODE commands --code or --first-dynamics chose (all by default), or the
    exit status after printing why there are none."""
    from .runtime.errors import AutolevModelError
    if not model.code_commands:
        print(f"{path}: no CODE command; animating it as CODE DYNAMICS", file=sys.stderr)
        return [model.plain_dynamics()]
    if ns.code:
        try:
            return model.commands_named([int(name) if name.isdigit() else name
                                         for name in ns.code])
        except AutolevModelError as exc:
            print(f"autolev run: --code: {exc}", file=sys.stderr)
            return 2
    if ns.first_dynamics:
        chosen = [c for c in model.code_commands if c.kind in ("dynamics", "ode")][:1]
        if not chosen:
            print(f"{path}: error: no CODE DYNAMICS or ODE to animate", file=sys.stderr)
            return 1
        return chosen
    return list(model.code_commands)


def _run_and_report(model, commands: list, overrides: dict, specified: dict,
                    ns: argparse.Namespace, path: Path) -> int:
    from .runtime.errors import AutolevModelError
    from .runtime.numerics.files import safe_stem
    label = _statement_label(model, path)
    written_by: dict[str, str] = {}
    for command in commands:
        try:
            stem = safe_stem(command.filename).lower()
        except AutolevModelError:
            continue                # an unusable name: its run says so
        if stem in written_by:
            print(f"{label(command)}: warning: CODE {command.filename} writes the same "
                  f"files ({safe_stem(command.filename)}.1, ...) as CODE {written_by[stem]}; "
                  "its run replaces them (give --out per program to keep both)",
                  file=sys.stderr)
        written_by[stem] = command.filename
    out_dir = Path(ns.out)
    status = 0
    from .runtime.numerics.options import RunOptions
    runs = model.run_commands(commands, out_dir, keep_going=True, options=RunOptions(
        method=ns.method, backend=ns.backend, infile=ns.infile,
        progress=None if ns.quiet else sys.stderr, overrides=overrides, specified=specified,
        quirks=ns.quirks, keep_rows=bool(ns.plot or ns.animate), overwrite=ns.overwrite,
        missing_values="zero" if ns.zero_missing else "refuse"))
    for done in runs:
        if done.error is not None:
            print(f"{label(done.command)}: error: {done.error}", file=sys.stderr)
            status = 1
            continue
        if done.result.failure:
            print(f"{label(done.command)}: {done.result.failure}", file=sys.stderr)
            status = 1
        if not ns.quiet:
            print(done.summary())
            for f in done.result.files:
                print(f"  wrote {f}")
        status = max(status, _after_run(model, done, out_dir, ns, label(done.command)))
    return status


def _after_run(model, done, out_dir: Path, ns: argparse.Namespace, label: str) -> int:
    """--animate and --plot of one finished run."""
    from .runtime.errors import AutolevModelError
    result = done.result
    status = 0
    if ns.animate and result.kind in ("dynamics", "ode") and len(result.t):
        try:
            for f in _animate(model, result, out_dir, ns, label):
                if not ns.quiet:
                    print(f"  wrote {f}")
        except AutolevModelError as exc:
            print(f"{label}: error: cannot animate {done.command.filename}: {exc}",
                  file=sys.stderr)
            status = 1
        except OSError as exc:
            print(f"{label}: error: cannot write the animation into {out_dir}: "
                  f"{exc.strerror or exc}", file=sys.stderr)
            status = 1
    if ns.plot and result.outputs:
        from .plots import write_pngs
        try:
            pictures = write_pngs(result, out_dir, ns.overwrite)
        except OSError as exc:
            print(f"{label}: error: cannot write the plots into {out_dir}: "
                  f"{exc.strerror or exc}", file=sys.stderr)
            return 1
        for f in pictures:
            if not ns.quiet:
                print(f"  wrote {f}")
    return status


def _name_values(items, option: str, numbers: bool = False) -> dict | None:
    """NAME=VALUE items of a repeatable option (with `numbers`, each VALUE a number as
    an .in file writes it), or None after printing the bad one."""
    from .runtime.numerics.inputs import parse_number
    values = {}
    for item in items or []:
        name, sep, value = item.partition("=")
        if not sep or not name.strip():
            print(f"autolev: {option} expects NAME=VALUE, not {item!r}", file=sys.stderr)
            return None
        if numbers and parse_number(value) is None:
            print(f"autolev: {option} {item}: {value.strip() or 'nothing'} is not a finite "
                  "number", file=sys.stderr)
            return None
        values[name.strip()] = value.strip()
    return values


def cmd_linearize(ns: argparse.Namespace) -> int:
    """Linearize a model's CODE DYNAMICS at an operating point; print the eigenvalues."""
    from .runtime.errors import AutolevModelError

    path = Path(ns.file)
    request = _linearize_request(ns)
    if request is None:
        return 2
    overrides, point, sweep = request
    model = _load_for_run(path)
    if model is None:
        print(f"{path}: not linearized", file=sys.stderr)
        return 1
    constraints = _constraint_values(model, ns.constraint)
    specified = _specified_values(model, ns, "linearize")
    if constraints is None or specified is None:
        return 2

    def at(extra):
        return model.linearize(dict(point, **extra),
                               inputs=ns.inputs.split(",") if ns.inputs else None,
                               code=int(ns.code) if ns.code and ns.code.isdigit() else ns.code,
                               backend=ns.backend, infile=ns.infile, overrides=overrides,
                               missing_values="zero" if ns.zero_missing else "refuse",
                               constraints=constraints or None,
                               dependent=_listed(ns.dependent) or None,
                               locked=_listed(ns.lock) or None, specified=specified)
    try:
        if sweep is not None:
            return _linearize_sweep(path, sweep, at, ns.out, ns.plot, ns.overwrite)
        lin = at({})
    except AutolevModelError as exc:
        print(f"{path}: error: {exc}", file=sys.stderr)
        return 1
    return _report_eigenvalues(path, lin, ns.out, ns.overwrite)


def _linearize_request(ns: argparse.Namespace):
    """(--set values, --at point, --sweep range or None) from the options, or None after
    printing what is wrong with them."""
    overrides = _name_values(ns.set, "--set", numbers=True)
    at = _name_values(ns.at, "--at")
    if overrides is None or at is None:
        return None
    point = {}
    for name, text in at.items():
        try:
            point[name] = float(text)
        except ValueError:
            point[name] = math.nan
        if not math.isfinite(point[name]):
            print(f"autolev linearize: --at {name}={text}: not a finite number",
                  file=sys.stderr)
            return None
    sweep = _sweep_range(ns.sweep) if ns.sweep else None
    if ns.sweep and sweep is None:
        return None
    if ns.plot:
        if sweep is None:
            print("autolev linearize: --plot draws a --sweep", file=sys.stderr)
            return None
        try:
            import matplotlib  # noqa: F401
        except ImportError:
            print("autolev linearize: --plot needs matplotlib (pip install 'autolev[plot]')",
                  file=sys.stderr)
            return None
    return overrides, point, sweep


def _constraint_values(model, names) -> list | None:
    """The model's quantities named by --constraint, each matrix taken element by
    element; None after printing a name the model does not have."""
    constraints = []
    for name in _listed(names):
        try:
            value = model.quantity(name)
        except KeyError:
            print(f"autolev linearize: --constraint {name}: the model has no quantity "
                  "of that name", file=sys.stderr)
            return None
        constraints += list(value) if hasattr(value, "shape") else [value]
    return constraints


def _report_eigenvalues(path: Path, lin, out_dir: str | None, overwrite: bool = False) -> int:
    """Print a linearization's eigenvalues (and write them into `out_dir`)."""
    from .runtime.numerics.files import safe_stem
    from .runtime.numerics.linearize import eigenvalue_table
    from .runtime.outputs import write_output

    if not lin.steady:
        print(f"{path}: warning: not an equilibrium or a steady motion: the accelerations "
              f"are {', '.join(f'{a:.6g}' for a in lin.accelerations)} there "
              "(the eigenvalues describe only the motion near this instant)", file=sys.stderr)
    table = eigenvalue_table(lin)
    print(f"{len(lin.states)} states ({', '.join(lin.states)}); inputs: "
          f"{', '.join(lin.inputs) or 'none'}")
    print(table, end="")
    if out_dir:
        out = Path(out_dir)
        try:
            out.mkdir(parents=True, exist_ok=True)
            target = write_output(out, f"{safe_stem(path.stem)}-eigenvalues.csv", table,
                                  overwrite)
        except OSError as exc:
            print(f"autolev linearize: cannot write into {out}: {exc.strerror}",
                  file=sys.stderr)
            return 1
        print(f"  wrote {target}")
    return 0


def _listed(values) -> list:
    """Names given as repeated options, each possibly comma-separated."""
    return [n.strip() for v in values or () for n in v.split(",") if n.strip()]


def _sweep_range(text: str):
    """NAME=START:STOP:N as (name, values), or None after printing what is wrong."""
    name, sep, rest = text.partition("=")
    parts = rest.split(":")
    try:
        start, stop, count = float(parts[0]), float(parts[1]), int(parts[2])
    except (IndexError, ValueError):
        count = 0
    if not sep or not name.strip() or len(parts) != 3 or count < 1 \
            or not (math.isfinite(start) and math.isfinite(stop)):
        print(f"autolev linearize: --sweep expects NAME=START:STOP:N (N >= 1), not {text!r}",
              file=sys.stderr)
        return None
    if count == 1:
        return name.strip(), [start]
    return name.strip(), [start + (stop - start) * k / (count - 1) for k in range(count)]


def _linearize_sweep(path: Path, sweep, at, out: str | None, plot: bool = False,
                     overwrite: bool = False) -> int:
    """Eigenvalues against one quantity of the operating point: CSV on stdout (and in
    --out as NAME-sweep.csv; with `plot`, NAME-sweep.png in --out or here)."""
    import time

    from .runtime.numerics.files import safe_stem
    from .runtime.numerics.linearize import sweep_table
    from .runtime.outputs import write_output
    name, values = sweep
    start = time.monotonic()
    lins = []
    for k, v in enumerate(values):
        lins.append(at({name: v}))
        if time.monotonic() - start > 2 and (k + 1) % 20 == 0:
            print(f"  {k + 1}/{len(values)} points", file=sys.stderr)
    table = sweep_table(name, values, lins)
    print(table, end="")
    unsteady = [v for v, lin in zip(values, lins) if not lin.steady]
    if unsteady:
        print(f"{path}: warning: not an equilibrium or a steady motion at {name} = "
              + ", ".join(f"{v:.6g}" for v in unsteady[:5])
              + (" ..." if len(unsteady) > 5 else ""), file=sys.stderr)
    if out or plot:
        folder = Path(out or ".")
        stem = safe_stem(path.stem)
        try:
            folder.mkdir(parents=True, exist_ok=True)
            written = []
            if out:
                written.append(write_output(folder, f"{stem}-sweep.csv", table, overwrite))
            if plot:
                from .plots import write_eigenvalue_png
                written.append(write_eigenvalue_png(
                    folder / f"{stem}-sweep.png", name, values,
                    [lin.eigenvalues() for lin in lins], f"{path.name}: eigenvalues",
                    overwrite))
        except OSError as exc:
            print(f"autolev linearize: cannot write into {folder}: {exc.strerror}",
                  file=sys.stderr)
            return 1
        for target in written:
            print(f"  wrote {target}")
    return 0


def cmd_transcript(ns: argparse.Namespace) -> int:
    """The responses Autolev displayed for each statement, as its .all files."""
    return _print_transcript(Path(ns.file), Path(ns.out) if ns.out else None, ns.overwrite)


def _print_transcript(path: Path, out_dir: Path | None, overwrite: bool = False) -> int:
    from .runtime.outputs import write_output
    from .transcript import transcript
    if path.suffix.lower() == ".py":
        print(f"{path}: a transcript is made from the .al model", file=sys.stderr)
        return 2
    try:
        text = transcript(path)
    except (AutolevSyntaxError, AutolevTranslationError, AutolevRuntimeError) as exc:
        for d in exc.diagnostics:
            print(d.format(), file=sys.stderr)
        return 1
    if out_dir is None:
        sys.stdout.write(text)
        return 0
    target = out_dir / f"{path.stem}.all"
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
        write_output(out_dir, target.name, text, overwrite)
    except OSError as exc:
        print(f"autolev transcript: cannot write {target}: {exc.strerror}", file=sys.stderr)
        return 1
    print(f"wrote {target}")
    return 0


def cmd_animate(ns: argparse.Namespace) -> int:
    """`run` of one CODE DYNAMICS (the first, or --code), with its motion written."""
    if any(f in ("gif", "mp4") for f in ns.formats or ()) and not _has_matplotlib():
        print("autolev animate: a GIF or MP4 needs matplotlib (pip install "
              "'autolev[plot]'); --format html needs nothing more", file=sys.stderr)
        return 2
    ns.code = [ns.code] if ns.code is not None else None
    return cmd_run(ns)


def _has_matplotlib() -> bool:
    import importlib.util
    return importlib.util.find_spec("matplotlib") is not None


def _animate(model, result, out_dir: Path, ns, label: str) -> list[Path]:
    from .animation import MAX_FRAMES, motion, write_html, write_movie
    m = motion(model, result, ns.frames or MAX_FRAMES)
    for note in m.notes:
        print(f"{label}: note: {note}", file=sys.stderr)
    formats = ns.formats or ["html"] + (["gif"] if _has_matplotlib() else [])
    if not ns.formats and not _has_matplotlib():
        print("autolev: note: no GIF: it needs matplotlib (pip install 'autolev[plot]'); "
              "the HTML page needs nothing more", file=sys.stderr)
    from .runtime.outputs import Written
    names = [f"{result.name}.{fmt}" for fmt in formats]
    record = Written(out_dir)
    record.check(names, ns.overwrite)        # before drawing: nothing of theirs replaced
    written = []
    for fmt, name in zip(formats, names):
        path = out_dir / name
        if fmt == "html":
            written.append(write_html(m, path, f"{result.name} ({model.name})"))
        else:
            written.append(write_movie(m, path, progress=None if ns.quiet else sys.stderr))
        record.record([name])
    return written


def cmd_verify(ns: argparse.Namespace) -> int:
    """Replay Autolev's recorded responses; exit 0 only when every comparable one matches."""
    import json

    from autolev.verification import verify

    path = Path(ns.file)
    if not path.is_file():
        print(f"autolev: error: {path}: no such file", file=sys.stderr)
        return 2
    report = verify(path, points=ns.points)
    if ns.json:
        print(json.dumps(report.as_dict(), indent=1))
    else:
        if report.error:
            print(printable(f"{path}: {report.error}"), file=sys.stderr)
        for o in report.outcomes:
            if o.status == "match" and not ns.all:
                continue
            r = o.response
            line = printable(f"{path}:{r.line}: ({r.number}) {r.lhs}: {o.status}: "
                             f"{o.detail}")
            if o.status == "mismatch" and o.ours is not None:
                line += f"\n    ours {_short(o.ours)}\n    Autolev's {_short(o.theirs)}"
            print(line)
        print(report.summary())
    return 0 if report.ok else 1


def cmd_code(ns: argparse.Namespace) -> int:
    """Write the programs a model's CODE commands name, in Autolev's layout."""
    from .programs import write_programs
    from .runtime.numerics.prepare import keep_built

    path = Path(ns.file)
    model = _load_for_run(path)
    if model is None:
        print(f"{path}: no program written", file=sys.stderr)
        return 1
    if not model.code_commands:
        print(f"{path}: the model has no CODE command: no program to write",
              file=sys.stderr)
        return 1
    out = Path(ns.out)
    try:
        done = write_programs(model, out, overwrite=ns.overwrite,
                              source=path if path.suffix.lower() != ".py" else None)
    except OSError as exc:
        print(f"autolev code: cannot write into {out}: {exc.strerror or exc}",
              file=sys.stderr)
        return 1
    finally:
        keep_built(model)        # loaded as for a run: it goes into the cache now
    refused = [w for w in done if w.refused]
    label = _statement_label(model, path)
    for w in done:
        if w.refused:
            print(f"{label(w.command)}: error: {w.refused}", file=sys.stderr)
        elif not ns.quiet:
            print("\n".join(f"wrote {f}" for f in w.files))
    return 1 if refused else 0


def cmd_cache(ns: argparse.Namespace) -> int:
    """What the cache holds (built models, compiled code), or empty it."""
    from . import modelcache

    if ns.action == "clear":
        try:
            count, size = modelcache.clear()
        except OSError as exc:
            print(f"autolev cache: error: {exc}", file=sys.stderr)
            return 1
        print(f"removed {count} entr{'y' if count == 1 else 'ies'} ({_megabytes(size)})")
        return 0
    s = modelcache.summary()
    print(f"cache: {s.folder}")
    for label, (count, size) in (("built models", s.models), ("translations", s.translations),
                                 ("compiled code", s.compiled)):
        print(f"  {label + ':':14s} {count:5d}  {_megabytes(size)}")
    print(f"  limit: {_megabytes(s.limit)} (the oldest entries leave first)")
    if not modelcache.enabled():
        print(f"  built models are not kept: {modelcache.DISABLE_VARIABLE} is set")
    return 0


def _megabytes(size: int) -> str:
    return f"{size / 2 ** 20:.1f} MB"


def _short(v) -> str:
    import numpy as np
    a = np.asarray(v, dtype=complex)
    a = a.real if np.all(np.abs(a.imag) < 1e-12) else a
    return np.array2string(a, precision=8, max_line_width=100)


def _positive_int(text: str) -> int:
    """An option's whole number of at least 1 (argparse reports anything else)."""
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected a whole number of at least 1, not {text!r}")
    return value


def _model_value_options(parser) -> None:
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
                        help="compiled C when a compiler is found (auto), or pure Python")
    parser.add_argument("--zero-missing", action="store_true",
                        help="give 0 to constants that have no value (INPUT, --in or --set) "
                        "instead of stopping before the build")


def _run_options(parser) -> None:
    """The options of a run, shared by `run` and `animate`."""
    _model_value_options(parser)
    parser.add_argument("--out", default=".", metavar="DIR",
                        help="folder for the output files (default: the current folder)")
    parser.add_argument("--method", default=None, metavar="M",
                        help="integrator: kutta-merson, rk45, dop853, radau, bdf, lsoda, "
                        "rk23 (default: the one of Autolev's program for each CODE file: "
                        "rk45 -- Matlab's ode45 -- for .m, else Kutta-Merson)")
    parser.add_argument("--tfinal", type=float, metavar="T", help="final time (TFINAL)")
    parser.add_argument("--no-quirks", dest="quirks", action="store_false",
                        help="compute the values meant where Autolev's programs computed "
                        "others (a quantity named i1 in a C program's outputs)")
    parser.add_argument("-q", "--quiet", action="store_true")
    _overwrite_option(parser)


def _overwrite_option(parser) -> None:
    parser.add_argument("--overwrite", action="store_true",
                        help="replace files in the way that autolev did not write (an .in "
                        "file you edited, Autolev's own output); without it they stop the "
                        "command")


def _add_check(sub) -> None:
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


def _add_convert(sub) -> None:
    convert = sub.add_parser("convert", help="translate a model into a Python module",
                             description="Translate FILE into a Python module on "
                             "autolev.runtime; importing it builds the model, running it "
                             "performs the model's CODE commands.  Nothing is written when "
                             "the model has errors.")
    convert.add_argument("file", metavar="FILE", help=".al model")
    convert.add_argument("-o", "--output", metavar="OUT.py",
                         help="where to write the module (default: FILE with .py)")
    convert.add_argument("-q", "--quiet", action="store_true")
    _overwrite_option(convert)
    convert.set_defaults(func=cmd_convert)


def _add_run(sub) -> None:
    run = sub.add_parser("run", help="run a model's CODE commands (simulate)",
                         description="Translate and build FILE, then perform its CODE "
                         "commands with its INPUT values: DYNAMICS and ODE are integrated, "
                         "ALGEBRAIC and NONLINEAR solved.  Writes Autolev's files NAME.in, "
                         "NAME.1 ... NAME.k (one per OUTPUT) and NAME.dir into --out.")
    _run_options(run)
    run.add_argument("--plot", action="store_true",
                     help="also write a PNG per output file (needs matplotlib)")
    run.add_argument("--animate", action="store_true",
                     help="also write the motion of each CODE DYNAMICS: NAME.html (a 3-D "
                     "view to rotate and scrub) and, with matplotlib, NAME.gif")
    run.add_argument("--code", action="append", metavar="FILE",
                     help="run only this CODE command (its file name, e.g. bike.c, or "
                     "its 0-based index); repeatable")
    run.set_defaults(func=cmd_run, formats=None, frames=None, first_dynamics=False)


def _add_linearize(sub) -> None:
    lin = sub.add_parser("linearize", help="eigenvalues of a model at an operating point",
                         description="Linearize FILE's first CODE DYNAMICS (or --code) at "
                         "an operating point (--at, in SI units and radians; the rest from "
                         "INPUT, --in and --set; states and specified quantities otherwise "
                         "0) and print the eigenvalues (CSV: real, imaginary, frequency in "
                         "Hz, damping ratio).  Exact Jacobians through the Z's.")
    _model_value_options(lin)
    lin.add_argument("--at", action="append", metavar="NAME=VALUE",
                     help="the operating point: a constant, coordinate, speed or specified "
                     "quantity in SI units and radians; repeatable")
    lin.add_argument("--inputs", metavar="NAMES",
                     help="the specified quantities that are inputs (B's columns), "
                     "comma-separated (default: all without a definition)")
    lin.add_argument("--code", metavar="FILE", help="which CODE DYNAMICS (file name or index)")
    lin.add_argument("--lock", action="append", metavar="NAMES",
                     help="coordinates held at their values, as by a rigid joint (each "
                     "with Q' = U: U's equation is dropped); comma-separated, repeatable")
    lin.add_argument("--constraint", action="append", metavar="NAME",
                     help="a quantity of the model that is 0 on the motion (a configuration "
                     "constraint, scalar or matrix): the point is put on it and the state "
                     "reduced to the independent coordinates; repeatable")
    lin.add_argument("--dependent", action="append", metavar="NAMES",
                     help="with --constraint: the coordinates the constraints fix "
                     "(default: chosen where the constraints' Jacobian is best conditioned)")
    lin.add_argument("--sweep", metavar="NAME=START:STOP:N",
                     help="eigenvalues at N values of one quantity of the operating point "
                     "(SI units, radians): CSV of the value and each eigenvalue's real and "
                     "imaginary part")
    lin.add_argument("--plot", action="store_true",
                     help="with --sweep: also draw NAME-sweep.png, real and imaginary parts "
                     "against the swept quantity (needs matplotlib)")
    lin.add_argument("--out", metavar="DIR",
                     help="also write NAME-eigenvalues.csv (or NAME-sweep.csv) there")
    _overwrite_option(lin)
    lin.set_defaults(func=cmd_linearize)


def _add_animate(sub) -> None:
    anim = sub.add_parser("animate", help="run a model and write its motion as a picture",
                          description="Run FILE's first CODE DYNAMICS (or --code) and write "
                          "a stick figure of its points in the Newtonian frame over the run: "
                          "NAME.html, a self-contained page with a 3-D view to rotate and a "
                          "time slider, and NAME.gif (or .mp4) with matplotlib.  The run's "
                          "own files are written too.")
    _run_options(anim)
    anim.add_argument("--code", metavar="FILE",
                      help="the CODE command to animate (default: the first DYNAMICS/ODE)")
    anim.add_argument("--format", dest="formats", action="append",
                      choices=("html", "gif", "mp4"),
                      help="what to write (repeatable; default: html, and gif when "
                      "matplotlib is installed)")
    anim.add_argument("--frames", type=_positive_int, default=None, metavar="N",
                      help="frames at most (default 400; the rows are sampled evenly)")
    anim.set_defaults(func=cmd_animate, plot=False, animate=True, first_dynamics=True)


def _add_transcript(sub) -> None:
    tr = sub.add_parser("transcript", help="the responses Autolev displayed (.all)",
                        description="Print what Autolev displayed for FILE: every input "
                        "line numbered (n), and after each assignment the value it defined "
                        "(with the Z variables it uses), as in Autolev's .all files.  "
                        "`autolev verify NAME.all` replays such a transcript.")
    tr.add_argument("file", metavar="FILE", help=".al model")
    tr.add_argument("--out", metavar="DIR", help="write DIR/NAME.all instead of printing")
    _overwrite_option(tr)
    tr.set_defaults(func=cmd_transcript)


def _add_verify(sub) -> None:
    ver = sub.add_parser("verify", help="check a translation against Autolev's responses",
                         description="Replay the responses Autolev printed (an .all session "
                         "saved by SAVE, or a .al file with '% ->' response comments): each "
                         "is compared with our translation's value at the same point of the "
                         "model, numerically at several values of every name, to the digits "
                         "Autolev displayed.  Exit status 0 only when every comparable "
                         "response matches.")
    ver.add_argument("file", metavar="FILE", help=".all session or .al file")
    ver.add_argument("--json", action="store_true", help="machine-readable report")
    ver.add_argument("--all", action="store_true", help="list the matches too")
    ver.add_argument("--points", type=int, default=3, metavar="N",
                     help="sample points per response (default 3)")
    ver.set_defaults(func=cmd_verify)


def _add_cache(sub) -> None:
    cache = sub.add_parser("cache", help="what the cache holds, or empty it",
                           description="autolev keeps the models it built (read back when "
                           "the model, autolev and its libraries are unchanged) and the "
                           "code it compiled, in $AUTOLEV_CACHE (default "
                           "~/.cache/autolev/build), private to you and kept under "
                           "$AUTOLEV_CACHE_LIMIT_MB (default 2048).  "
                           "AUTOLEV_NO_MODEL_CACHE=1 builds every model afresh.")
    cache.add_argument("action", choices=("info", "clear"), nargs="?", default="info",
                       help="info (default): entries and sizes; clear: remove them all")
    cache.set_defaults(func=cmd_cache)


def _add_code(sub) -> None:
    code = sub.add_parser(
        "code", help="write the programs of a model's CODE commands (Autolev's layout)",
        description="Write, for every CODE command of FILE, the program it names, in the "
        "layout of the programs Autolev 4.1 wrote (the same global names, functions and "
        "section comments, reading the same .in file), and the .in file itself.  Written "
        "now: CODE ALGEBRAIC() and CODE DYNAMICS() into .c and .m files; the others are "
        "reported and not written.  Folders in a CODE file name are kept under --out; a name "
        "that would leave it is refused.")
    code.add_argument("file", metavar="FILE", help=".al model")
    code.add_argument("--out", metavar="DIR", default=".",
                      help="folder for the programs (default: the current folder)")
    code.add_argument("-q", "--quiet", action="store_true")
    _overwrite_option(code)
    code.set_defaults(func=cmd_code)


COMMANDS = (_add_check, _add_convert, _add_run, _add_code, _add_linearize, _add_animate,
            _add_transcript, _add_verify, _add_cache)


def build_parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(
        prog="autolev",
        description="Autolev 4.1 models in Python: check, translate and run .al files.",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--version", action="version", version=f"autolev {__version__}")
    sub = ap.add_subparsers(dest="command", metavar="COMMAND")
    for add in COMMANDS:
        add(sub)
    return ap


@contextlib.contextmanager
def _warnings_as_notes():
    """Warnings printed as one-line notes while a command runs (not for the process:
    a caller of main() keeps its own warning display)."""
    import warnings
    shown = warnings.showwarning
    warnings.showwarning = _print_warning
    try:
        yield
    finally:
        warnings.showwarning = shown


def main(argv: list[str] | None = None) -> int:
    ap = build_parser()
    ns = ap.parse_args(argv)
    if ns.command is None:
        ap.print_help()
        return 2
    try:
        with _warnings_as_notes():
            return ns.func(ns)
    except AutolevSyntaxError as exc:
        print(exc, file=sys.stderr)
        return 1
    except AutolevInternalError as exc:
        _report_internal_error(exc)
        return EXIT_INTERNAL
    except AutolevError as exc:
        print(f"autolev: error: {exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 130
    except MemoryError:
        print("autolev: error: out of memory (the machine's limit, not a fault of the model)",
              file=sys.stderr)
        return 1
    except BrokenPipeError:
        # output piped into `head` and the like: stop quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    except Exception as exc:  # noqa: BLE001 -- what escapes every stage is autolev's bug
        internal = AutolevInternalError(getattr(ns, "file", None) or "autolev",
                                        f"running `autolev {ns.command}`", exc)
        internal.__cause__ = exc
        _report_internal_error(internal)
        return EXIT_INTERNAL


def _report_internal_error(exc: AutolevInternalError) -> None:
    """The bug's message; its Python traceback only when asked for."""
    print(exc, file=sys.stderr)
    if os.environ.get(TRACEBACK_VARIABLE) == "1":
        import traceback
        traceback.print_exception(exc, file=sys.stderr)
    else:
        print(f"autolev: note: {TRACEBACK_VARIABLE}=1 shows where in autolev it happened",
              file=sys.stderr)


if __name__ == "__main__":
    sys.exit(main())
