#!/usr/bin/env python3
"""Our runs against the numbers Autolev's own programs produced (shared/truth/).

    python bench/truth.py [--corpus DIR] [--only ID] [--method M] [--keep DIR]

For every reference run whose status is `ok` in shared/truth/index.tsv, the model's
.al (from the corpus cache, see bench/corpus.py) is translated and its CODE command
run with the same inputs: the run's `.in` file (C/Fortran programs) or the values of
the Matlab program's ReadUserInput block (`inputs.txt`).  Output files are compared
column by column: the error of a column is max|ours - theirs| over its rows divided
by the column's largest magnitude (absolute when the column is all zero); a file
matches when its rows are the same and every column is within the tolerance (1e-6,
the 7 significant digits of Autolev's files).  ENCODE values (`encode_values.txt`)
are compared value by value, relative to max(|value|, 1e-12 * largest).
Prints one line per run and a table; exits 0 always (it is a report).
"""
from __future__ import annotations

import argparse
import csv
import math
import os
import re
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))
sys.path.insert(0, str(ROOT / "bench"))

import autolev  # noqa: E402
from autolev.engine.integrators import for_run  # noqa: E402
from corpus import corpus_models  # noqa: E402

TRUTH = ROOT.parent / "shared" / "truth"


def read_table(path: Path) -> np.ndarray:
    """The numeric rows of an output file (Autolev's C, Fortran or Matlab layout)."""
    rows = []
    for line in path.read_text(errors="replace").splitlines():
        parts = line.split()
        if not parts or line.lstrip().startswith("%"):
            continue
        try:
            rows.append([float(p) for p in parts])
        except ValueError:
            continue
    width = max((len(r) for r in rows), default=0)
    if not width:
        return np.zeros((0, 0))
    return np.array([r for r in rows if len(r) == width]).reshape(-1, width)


def read_labels(path: Path) -> list[str]:
    """The column names of an output file: the line above the units line."""
    lines = path.read_text(errors="replace").splitlines()[:12]
    for k, line in enumerate(lines):
        toks = line.lstrip("%").split()
        if toks and all(t.startswith("(") for t in toks) and k > 0:
            return [t.upper() for t in lines[k - 1].lstrip("%").split()]
    return []


def _has_labels(path: Path) -> bool:
    """Whether the file's heading names its columns."""
    for line in path.read_text(errors="replace").splitlines()[:8]:
        text = line.lstrip("% ").strip()
        try:
            [float(p) for p in text.split()]
            if text:
                return False               # the rows began: no names above them
        except ValueError:
            pass
        if text and not text.startswith("FILE:") and not text.startswith("***"):
            return True
    return False


def read_matlab_inputs(path: Path) -> dict:
    values = {}
    for line in path.read_text().splitlines():
        if line.startswith("%") or "=" not in line:
            continue
        name, rest = line.split("=", 1)
        values[name.strip()] = rest.split("%", 1)[0].strip()
    return values


def evaluate(values: dict) -> dict:
    """Matlab inputs may be expressions of earlier ones (U5 = 4.5/RR)."""
    import sympy as sm
    out = {}
    for name, text in values.items():
        expr = sm.sympify(text.replace("^", "**"), locals={k: sm.Float(v) for k, v in
                                                           out.items()})
        out[name] = float(expr)
    return out


def read_encoded(path: Path) -> dict:
    out = {}
    for line in path.read_text().splitlines():
        if line.startswith("%") or not line.strip():
            continue
        key, value = line.split("\t")
        out[key] = float(value)
    return out


def encoded_flat(result) -> dict:
    out = {}
    for name, value in result.encoded.items():
        a = np.atleast_2d(np.asarray(value, dtype=float))
        if np.ndim(value) == 0:
            out[name] = float(value)
            continue
        rows, cols = a.shape
        for i in range(rows):
            for j in range(cols):
                idx = f"[{i + 1}]" if cols == 1 else (f"[{j + 1}]" if rows == 1
                                                       else f"[{i + 1},{j + 1}]")
                out[f"{name}{idx}"] = float(a[i, j])
    return out


def column_errors(ours: np.ndarray, ref: np.ndarray, t_max: float | None = None) -> np.ndarray:
    """Per column: max |ours - ref| / scale, scale = the column's largest magnitude, but
    at least 1e-6 of the file's largest (a column that is zero up to round-off, such
    as a torque of 1e-14, is compared on the file's scale)."""
    finite = np.isfinite(ref)
    file_scale = float(np.max(np.abs(ref[finite]))) if finite.any() else 0.0
    cols = [float(np.nanmax(np.abs(ref[:, j]))) if np.any(np.isfinite(ref[:, j])) else 0.0
            for j in range(ref.shape[1])]          # scales over the whole file
    if t_max is not None:
        keep = ref[:, 0] <= t_max
        ours, ref = ours[keep], ref[keep]
    errs = []
    for j in range(ref.shape[1]):
        a, b = ours[:, j], ref[:, j]
        both_nan = np.isnan(a) & np.isnan(b)
        col = cols[j]
        scale = max(col, 1e-6 * file_scale)
        d = np.abs(a - b)
        d[both_nan] = 0.0
        if np.any(np.isnan(d)):
            errs.append(math.inf)
            continue
        errs.append(float(d.max() / scale) if scale > 0 else float(d.max()))
    return np.array(errs)


# reference runs the truth notes restrict: chaotic after t ~ 0.07 s (1064 rad/s spin)
WINDOWS = {("sprint-7segv2-7segsprint", "f_raw_repo_in"): 0.07,
           ("sprint-7segv2-7segsprint", "f_raw_zoff_repo_in"): 0.07}


# runs whose program was generated from an earlier revision of the .al than the corpus
# holds (found by the program's header date in the repository's history): the model is
# read from that revision (from the fetched mirror, when there is one)
REVISIONS = {
    "dogtail-3dpendulum": ("TomRottier+dogtail", "b900419", "3dpendulum/3dpendulum.al",
                           "generated 2021-06-11; the .al of 2021-06-15 (space123, no "
                           "dependent speed) is the one the program matches"),
}
MIRRORS = Path(os.environ.get("AUTOLEV_MIRRORS", "/work/.mirror"))


def revision_file(ident: str) -> tuple[Path, str] | None:
    import subprocess
    entry = REVISIONS.get(ident)
    if entry is None:
        return None
    repo, commit, path, why = entry
    gitdir = MIRRORS / repo / "repo"
    if not gitdir.exists():
        return None
    r = subprocess.run(["git", "--git-dir", str(gitdir), "show", f"{commit}:{path}"],
                       capture_output=True)
    if r.returncode != 0:
        return None
    target = Path(tempfile.mkdtemp()) / Path(path).name
    target.write_bytes(r.stdout)
    return target, f"{repo.replace('+', '/')}@{commit} ({why})"


def run_one(row, models: dict, method: str, keep: Path | None) -> dict:
    ident, run = row["id"], row["run"]
    out = {"id": ident, "run": run, "kind": row["kind"], "status": "", "files": [],
           "seconds": 0.0}
    path = models.get(ident)
    if path is None:
        out["status"] = "model not in the corpus cache"
        return out
    revision = revision_file(ident)
    if revision is not None:
        path, out["revision"] = revision
    rundir = TRUTH / ident / run
    infile = None
    overrides = {}
    if row["kind"] in ("c", "f"):
        ins = sorted(rundir.glob("*.in"))
        infile = ins[0] if ins else None
    else:
        overrides = evaluate(read_matlab_inputs(rundir / "inputs.txt"))
    t0 = time.perf_counter()
    from autolev.loader import load_for_run
    try:
        model, load_notes = load_for_run(path)
    except autolev.AutolevError as exc:
        out["status"] = f"build failed: {str(exc).splitlines()[0]}"
        return out
    workdir = Path(keep) / f"{ident}__{run}" if keep else Path(tempfile.mkdtemp())
    commands = [c for c in model.code_commands]
    if not commands:
        out["status"] = "no CODE command"
        return out
    # the CODE command that made this program (a model may RUN another's CODE first)
    program = Path(row["source"].split(":", 1)[1].split("@")[0]).stem.lower()
    from autolev.engine.files import safe_stem
    named = [c for c in commands if safe_stem(c.filename).lower() == program]
    command = named[0] if named else commands[-1]
    from autolev.engine.options import RunOptions
    from autolev.runtime.numerics.run import run_command
    notes = []
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        known = {}
        if overrides:
            from autolev.runtime.numerics.inputs import Inputs
            probe = Inputs(model.defs, list(model.info), command.inputs, command.units)
            for k, v in overrides.items():
                if probe.lookup(k) is not None:
                    known[k] = v
                else:
                    notes.append(f"{k} not an input here")
        try:
            # the reference program read these values, zeros of a template included
            result = run_command(model.snapshot_for(command), workdir, RunOptions(
                method=method, infile=infile, overrides=known, missing_values="zero"))
        except autolev.AutolevError as exc:
            out["status"] = f"run failed: {exc}"
            return out
        except Exception as exc:  # noqa: BLE001 - a report must go on to the next model
            out["status"] = f"run failed: {type(exc).__name__}: {exc}"
            return out
    out["seconds"] = time.perf_counter() - t0
    # how far the requested tolerance determines the trajectory: the same run with
    # tolerances 1000 times tighter; rows after the first disagreement (> 1e-6 of a
    # state's largest magnitude) depend on the integration error, Autolev's included
    trusted = None
    if result.kind in ("dynamics", "ode") and len(result.t) > 1:
        ins = result.inputs
        tight = dict(known, RELERR=ins.get("RELERR", 1e-7) * 1e-3,
                     ABSERR=ins.get("ABSERR", 1e-8) * 1e-3)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            fine = run_command(model.snapshot_for(command), None, RunOptions(
                method=method, infile=infile, overrides=tight, missing_values="zero"))
        k = min(len(fine.t), len(result.t))      # a failed run: the rows both have
        if k > 1:
            a, b = fine.states[:k], result.states[:k]
            scale = np.maximum(np.abs(a).max(axis=0), 1e-300)
            bad = np.any(np.abs(a - b) / scale > 1e-6, axis=1)
            if bad.any():
                trusted = float(result.t[max(int(np.argmax(bad)) - 1, 0)])
                out["trusted"] = trusted
    out["warnings"] = load_notes + [str(w.message) for w in caught] + notes
    if result.failure:
        out["failure"] = result.failure
    worst = 0.0
    matched = True
    refs = sorted([p for p in rundir.iterdir() if re.search(r"\.\d+$", p.name)],
                  key=lambda p: int(p.suffix[1:]))
    for ref in refs:
        k = int(ref.suffix[1:])
        ours = workdir / f"{result.name}.{k}"
        theirs = read_table(ref)
        if not ours.exists():
            out["files"].append((ref.name, "missing", None))
            matched = False
            continue
        mine = read_table(ours)
        if theirs.size and not np.any(theirs[:, 1:] if theirs.shape[1] > 1 else theirs) \
                and not _has_labels(ref):
            # Autolev 4.0's Matlab wrote literal 0.0 for OUTPUT matrices (no heading)
            out["files"].append((ref.name, f"not comparable: Autolev wrote {theirs.shape[1]} "
                                 f"zero columns without names for OUTPUT matrices; we write "
                                 f"their {mine.shape[1]} elements", None))
            continue
        if theirs.size == 0 and row["status"].startswith("failed") and result.failure \
                and len(result.t) == 1:
            out["files"].append((ref.name, "failure reproduced: Autolev's program stopped "
                                 "before its first row; ours writes the row where it "
                                 "stopped", None))
            continue
        if mine.shape[0] == theirs.shape[0] and mine.shape[1] != theirs.shape[1]:
            # the program's revision of the .al wrote other columns: compare by name
            ours_l, theirs_l = read_labels(ours), read_labels(ref)
            common = [c for c in theirs_l if c in ours_l]
            if len(common) == len(theirs_l) == theirs.shape[1] and \
                    len(ours_l) == mine.shape[1]:
                mine = mine[:, [ours_l.index(c) for c in common]]
                extra = [c for c in ours_l if c not in theirs_l]
                out["files"].append((ref.name, f"revision differs: the program's file has "
                                     f"no {', '.join(extra)}; the {len(common)} common "
                                     "columns compared", None))
        if mine.shape != theirs.shape:
            out["files"].append((ref.name, f"shape {mine.shape} vs {theirs.shape}", None))
            matched = False
            continue
        window = WINDOWS.get((ident, run), trusted)
        if window is not None and trusted is not None:
            window = min(window, trusted)
        errs = column_errors(mine, theirs, window)
        e = float(errs.max()) if len(errs) else 0.0
        worst = max(worst, e)
        full = float(column_errors(mine, theirs).max()) if window is not None else e
        out["files"].append((ref.name, f"{theirs.shape[0]}x{theirs.shape[1]}"
                             + (f" (t <= {window:g}; whole run {full:.1e})"
                                if window is not None else ""), e))
    enc = rundir / "encode_values.txt"
    if enc.exists():
        ref = read_encoded(enc)
        mine = encoded_flat(result)
        missing = [k for k in ref if k not in mine]
        scale = max((abs(v) for v in ref.values() if math.isfinite(v)), default=1.0)
        e = 0.0
        nan_mismatch = 0
        for k, v in ref.items():
            if k not in mine:
                continue
            m = mine[k]
            if math.isnan(v) or math.isnan(m):
                nan_mismatch += math.isnan(v) != math.isnan(m)
                continue
            d = abs(m - v)
            e = max(e, d / max(abs(v), 1e-12 * scale) if d else 0.0)
        worst = max(worst, e)
        detail = f"{len(ref)} values"
        if missing:
            detail += f", {len(missing)} missing (e.g. {missing[0]})"
            matched = False
        if nan_mismatch:
            detail += f", {nan_mismatch} NaN differ"
            matched = False
        out["files"].append(("encode_values.txt", detail, e))
    out["worst"] = worst
    out["status"] = "ok" if matched else "differs"
    if row["status"].startswith("failed"):
        # a reference whose program stopped: ours must stop there too
        out["expected_failure"] = True
        if not result.failure:
            out["status"] = "differs"
            out["files"].append(("(failure)", "Autolev's program failed; our run did not",
                                 None))
    return out


def main() -> int:
    global TRUTH                  # --truth: the reference runs read by every function
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corpus", type=Path, default=Path(os.environ.get(
        "AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus")))
    ap.add_argument("--only", help="a truth id (substring)")
    ap.add_argument("--method", default=None,
                    help="integrator (default: the one the reference program used: "
                    "kutta-merson for C and Fortran, rk45 for Matlab's ode45)")
    ap.add_argument("--tolerance", type=float, default=1e-6)
    ap.add_argument("--keep", type=Path, help="keep our output files here")
    ap.add_argument("--truth", type=Path, default=TRUTH,
                    help="the folder of reference runs (index.tsv and one folder per run)")
    ns = ap.parse_args()
    TRUTH = ns.truth
    if not (TRUTH / "index.tsv").is_file():
        print(f"truth.py: no reference runs at {TRUTH} (index.tsv); give --truth DIR",
              file=sys.stderr)
        return 2
    models = dict(corpus_models(ns.corpus))
    rows = [r for r in csv.DictReader(open(TRUTH / "index.tsv"), delimiter="\t")
            if r["status"].startswith(("ok", "failed")) and r["run"] != "-"]
    if ns.only:
        rows = [r for r in rows if ns.only in r["id"] or ns.only in r["run"]]
    results = []
    for row in rows:
        method = for_run(ns.method, row["kind"]).name
        r = run_one(row, models, method, ns.keep)
        results.append(r)
        worst = r.get("worst")
        flag = ("" if worst is None else "MATCH" if r["status"] == "ok" and worst <= ns.tolerance
                else "DIFF") + (" (failure reproduced)" if r.get("expected_failure") and
                                r["status"] == "ok" else "")
        print(f"{r['id']} [{r['run']}] {r['status']} {flag} "
              f"worst={worst if worst is None else f'{worst:.2e}'} ({r['seconds']:.1f} s)")
        for name, detail, e in r["files"]:
            print(f"    {name}: {detail}" + ("" if e is None else f" err {e:.2e}"))
        if r.get("revision"):
            print(f"    model revision: {r['revision']}")
        if r.get("failure"):
            print(f"    failure: {r['failure'][:200]}")
        for w in r.get("warnings", [])[:4]:
            print(f"    warning: {w[:160]}")
    n = len(results)
    match = sum(1 for r in results if r["status"] == "ok" and r.get("worst", 1) <= ns.tolerance)
    print(f"\n{match}/{n} reference runs reproduced within {ns.tolerance:g} "
          "(column-relative)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
