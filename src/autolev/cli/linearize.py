"""`autolev linearize`: eigenvalues at an operating point, or along a sweep.
"""
from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

from .common import (UsageError, failed_write, has_matplotlib, listed, load_model,
                     model_value_options, name_values, overwrite_option, specified_values)


def cmd_linearize(ns: argparse.Namespace) -> int:
    """Linearize a model's CODE DYNAMICS at an operating point; print the eigenvalues.
    The answer is kept for its request (request.LinearizeRequest) and the files it
    read, as read (runplan.KeptLinearization)."""
    from ..engine import reading
    path = Path(ns.file)
    if path.suffix.lower() == ".py" or ns.sweep:
        return _linearize(path, ns, None)
    from ..engine.request import LinearizeRequest
    from ..engine.keeping import Recorder, kept
    from ..engine.runplan import KeptLinearization
    from .run import Keeping
    request = LinearizeRequest.of(ns)
    with reading.recording() as reads:
        found = kept(request, reads, lambda: KeptLinearization)
        if found is not None:
            sys.stderr.write(found.load_messages + found.messages)
            print(f"{path}: linearized as before with these options (the model and the "
                  "files it reads unchanged)", file=sys.stderr)
            return _report_eigenvalues(path, found.linearization, ns.out, ns.overwrite)
        recorder = sys.stderr = Recorder(sys.stderr)
        try:
            return _linearize(path, ns, Keeping(request, reads, recorder))
        finally:
            sys.stderr = recorder.through


def _linearize(path: Path, ns: argparse.Namespace, keeping) -> int:
    """The linearization from the model; `keeping` (run.Keeping): to keep its answer."""
    from ..engine.errors import AutolevModelError

    overrides, point, sweep = _linearize_request(ns)
    progress = sys.stderr if keeping is None else keeping.recorder.through
    model = load_model(path, progress)
    if model is None:
        print(f"{path}: not linearized", file=sys.stderr)
        return 1
    load_messages = keeping.recorder.take() if keeping is not None else ""
    options = dict(inputs=ns.inputs.split(",") if ns.inputs else None,
                   code=int(ns.code) if ns.code and ns.code.isdigit() else ns.code,
                   backend=ns.backend, infile=ns.infile, overrides=overrides,
                   missing_values="zero" if ns.zero_missing else "refuse",
                   constraints=_constraint_values(model, ns.constraint) or None,
                   dependent=listed(ns.dependent) or None, locked=listed(ns.lock) or None,
                   specified=specified_values(model, ns))
    if sweep is not None:
        return _linearize_sweep(path, model, sweep, point, options, ns)
    try:
        lin = model.linearize(point, progress=progress, **options)
    except AutolevModelError as exc:
        print(f"{path}: error: {exc}", file=sys.stderr)
        return 1
    if keeping is not None:
        from ..engine.runplan import KeptLinearization
        messages = keeping.recorder.take()
        keeping.keep(lambda reads: KeptLinearization(reads, load_messages, messages, lin))
    return _report_eigenvalues(path, lin, ns.out, ns.overwrite)


def _linearize_request(ns: argparse.Namespace):
    """(--set values, --at point, --sweep range or None) from the options; UsageError
    for what is wrong with them."""
    overrides = name_values(ns.set, "--set", numbers=True)
    point = {}
    for name, text in name_values(ns.at, "--at").items():
        try:
            point[name] = float(text)
        except ValueError:
            point[name] = math.nan
        if not math.isfinite(point[name]):
            raise UsageError(f"--at {name}={text}: not a finite number")
    sweep = _sweep_range(ns.sweep) if ns.sweep else None
    if ns.plot:
        if sweep is None:
            raise UsageError("--plot draws a --sweep")
        if not has_matplotlib():
            raise UsageError("--plot needs matplotlib (pip install 'autolev[plot]')")
    return overrides, point, sweep


def _constraint_values(model, names) -> list:
    """The model's quantities named by --constraint, each matrix taken element by
    element; UsageError for a name the model does not have."""
    constraints = []
    for name in listed(names):
        try:
            value = model.quantity(name)
        except KeyError:
            raise UsageError(f"--constraint {name}: the model has no quantity of that "
                             "name") from None
        constraints += list(value) if hasattr(value, "shape") else [value]
    return constraints


def _report_eigenvalues(path: Path, lin, out_dir: str | None, overwrite: bool = False) -> int:
    """Print a linearization's eigenvalues (and write them into `out_dir`)."""
    # not the runtime's façade (it imports sympy): a kept linearization needs neither
    from ..engine.files import safe_stem
    from ..engine.outputs import write_output

    if not lin.steady:
        print(f"{path}: warning: not an equilibrium or a steady motion: the accelerations "
              f"are {', '.join(f'{a:.6g}' for a in lin.accelerations)} there "
              "(the eigenvalues describe only the motion near this instant)", file=sys.stderr)
    table = lin.eigenvalue_table()
    print(f"{len(lin.states)} states ({', '.join(lin.states)}); inputs: "
          f"{', '.join(lin.inputs) or 'none'}; parts of eigenvalues within "
          f"{lin.zero_tolerance():.2g} of 0 are shown as 0 (roundoff)")
    print(table, end="")
    if out_dir:
        out = Path(out_dir)
        try:
            out.mkdir(parents=True, exist_ok=True)
            stem = safe_stem(path.stem)
            contents = [(f"{stem}-eigenvalues.csv", table)]
            contents += [(f"{stem}-{m}.csv", lin.matrix_csv(m)) for m in "ABCD"]
            contents.append((f"{stem}-linear.mat", lin.mat_bytes()))
            written = [write_output(out, name, data, overwrite) for name, data in contents]
        except OSError as exc:
            print(f"autolev linearize: cannot write into {out}: {failed_write(exc)}",
                  file=sys.stderr)
            return 1
        for target in written:
            print(f"  wrote {target}")
    return 0


# a sweep's table is held for its CSV and plot: past this, Model.sweep streams to a file
MAX_SWEEP_POINTS = 100_000


def _sweep_range(text: str):
    """NAME=START:STOP:N as (name, values); UsageError for anything else."""
    name, sep, rest = text.partition("=")
    parts = rest.split(":")
    try:
        start, stop, count = float(parts[0]), float(parts[1]), int(parts[2])
    except (IndexError, ValueError):
        count = 0
    if not sep or not name.strip() or len(parts) != 3 or count < 1 \
            or not (math.isfinite(start) and math.isfinite(stop)):
        raise UsageError(f"--sweep expects NAME=START:STOP:N (N >= 1), not {text!r}")
    if count > MAX_SWEEP_POINTS:
        raise UsageError(f"--sweep asks for {count} points; at most {MAX_SWEEP_POINTS} "
                         "from the command line (Model.sweep in Python takes more)")
    if count == 1:
        return name.strip(), [start]
    return name.strip(), [start + (stop - start) * k / (count - 1) for k in range(count)]


def _linearize_sweep(path: Path, model, sweep, point: dict, options: dict,
                     ns: argparse.Namespace) -> int:
    """Eigenvalues against one quantity of the operating point, by the studies'
    sweep (worker processes when it pays): CSV on stdout (and in --out as
    NAME-sweep.csv; with --plot, NAME-sweep.png in --out or here)."""
    import numpy as np
    from ..runtime.tools import safe_stem
    from ..runtime.tools import write_output
    from ..runtime.studies import eigenvalues_and_modes, follow_modes
    from ..engine.errors import AutolevModelError
    name, values = sweep
    if not model.names_a_quantity(name):
        raise UsageError(f"--sweep {name}: the model has no quantity of that name")
    try:
        table = model.sweep([dict(point, **{name: v}) for v in values], what="linearize",
                            as_frame=False, collect=eigenvalues_and_modes, **options)
    except AutolevModelError as exc:
        print(f"{path}: error: {exc}", file=sys.stderr)
        return 1
    if "failure" in table.names:
        first = next(k for k, why in enumerate(table["failure"]) if why)
        print(f"{path}: error: at {name} = {values[first]:.6g}: {table['failure'][first]}",
              file=sys.stderr)
        return 1
    n = sum(c.startswith("re") for c in table.names)
    eigenvalues = np.column_stack([np.asarray(table[f"re{k}"], dtype=float)
                                   + 1j * np.asarray(table[f"im{k}"], dtype=float)
                                   for k in range(1, n + 1)])
    vectors = np.stack([np.column_stack([
        np.asarray(table[f"vre{k}_{j}"], dtype=float)
        + 1j * np.asarray(table[f"vim{k}_{j}"], dtype=float) for j in range(1, n + 1)])
        for k in range(1, n + 1)], axis=2)          # points x components x modes
    order = follow_modes(eigenvalues, vectors)
    eigenvalues = np.take_along_axis(eigenvalues, order, axis=1)
    columns = [f"{p}{k}" for k in range(1, n + 1) for p in ("re", "im")]
    numbers = np.column_stack([np.asarray(values, dtype=float)] + [
        part(eigenvalues[:, k]) for k in range(n) for part in (np.real, np.imag)])
    csv = "\n".join([",".join([name] + columns)]
                    + [",".join(f"{x:.15g}" for x in row) for row in numbers]) + "\n"
    print(csv, end="")
    unsteady = [v for v, steady in zip(values, table["steady"]) if not steady]
    if unsteady:
        print(f"{path}: warning: not an equilibrium or a steady motion at {name} = "
              + ", ".join(f"{v:.6g}" for v in unsteady[:5])
              + (" ..." if len(unsteady) > 5 else ""), file=sys.stderr)
    if ns.out or ns.plot:
        folder = Path(ns.out or ".")
        stem = safe_stem(path.stem)
        try:
            folder.mkdir(parents=True, exist_ok=True)
            written = []
            if ns.out:
                written.append(write_output(folder, f"{stem}-sweep.csv", csv, ns.overwrite))
            if ns.plot:
                from ..plots import write_eigenvalue_png
                written.append(write_eigenvalue_png(
                    folder / f"{stem}-sweep.png", name, values, eigenvalues,
                    f"{path.name}: eigenvalues", ns.overwrite))
        except OSError as exc:
            print(f"autolev linearize: cannot write into {folder}: {failed_write(exc)}",
                  file=sys.stderr)
            return 1
        for target in written:
            print(f"  wrote {target}")
    return 0


def add_linearize(sub) -> None:
    lin = sub.add_parser("linearize", help="eigenvalues of a model at an operating point",
                         description="Linearize FILE's first CODE DYNAMICS (or --code) at "
                         "an operating point (--at, in SI units and radians; the rest from "
                         "INPUT, --in and --set; states and specified quantities otherwise "
                         "0) and print the eigenvalues (CSV: real, imaginary, frequency in "
                         "Hz, damping ratio).  Exact Jacobians through the Z's.")
    model_value_options(lin, backend_help="the Jacobians: the equations' own code on dual "
                        "numbers, compiled to C for a --sweep long enough to pay for it "
                        "(auto); symbolic Jacobians compiled to C (c) or Python (python)")
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
                     help="also write there NAME-eigenvalues.csv, A, B, C and D as "
                     "NAME-A.csv ... NAME-D.csv and all in NAME-linear.mat (with a --sweep: "
                     "NAME-sweep.csv)")
    overwrite_option(lin)
    lin.set_defaults(func=cmd_linearize)
