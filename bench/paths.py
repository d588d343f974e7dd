#!/usr/bin/env python3
"""One answer on every path: the same model and inputs give the same numbers whichever
way they are computed.

    python bench/paths.py [--examples] [--only ID ...] [--jobs N] [--limit S]
                          [--json FILE] [--keep DIR] [--states K]

For each shipped example (--examples) or visible corpus model (default; values as
bench/journeys.py gives them: INPUT, the .in shipped beside the model, constants
without a value 1 by rule), the model's answer is taken along every path a user can
take to it, and each is compared with the reference: a cold `autolev run` in an empty
cache, its C compiled in the background (the ordinary first run).

Rows (the files NAME.1 ... NAME.dir and NAME.in, and the exit status):

  warm         autolev run again, same cache: after the background compile, from the
               run plan it left
  no-cache     AUTOLEV_NO_MODEL_CACHE=1, an empty cache
  foreground   AUTOLEV_FOREGROUND=1 (the compile waited for), an empty cache
  python       --backend python (no C), an empty cache
  api          autolev.load(FILE).run(DIR, ...) from Python
  mass-matrix  the same with recursion=False: Kane's mass matrix solved at each step
               where the run uses the articulated-body recursion (a tree of joints)
  module       autolev convert FILE -o NAME.py, then autolev run NAME.py
  code         the programs autolev code writes, compiled and run (C; Fortran and
               Octave where installed), as bench/journeys.py checks them
  script       the `autolev convert --to sympy` script's rows (it integrates with
               scipy's DOP853)

  Identical files are `=`.  Where the arithmetic differs (mass-matrix, code, script)
  the rows are compared as bench/journeys.py compares a written program's: each value
  within 1e-6 of its column's largest, up to where the run itself parts from a run
  with tolerances 1000 times tighter (then the integration error decides the digits).

Rates (the state's derivatives at --states random states near the initial one, at
random times, against the run's own right-hand side; 1e-8 of max(1, |value|)):

  r:python     the right-hand side without C
  r:recursion  Kane's mass matrix solved, not the articulated-body recursion
  r:M,f        model.mass_matrix, model.forcing and model.kinematical_equations
  r:explicit   model.explicit_form()
  r:symsys     model.symbolic_system() (sympy's SymbolicSystem, lambdified)
  r:module     the converted module's model
  r:script     the `convert --to sympy` script's mass matrix and forcing
  r:dynamics   model.dynamics().explicit: the trajectory optimizer's compiled f(x, u, p, t)
  r:df         model.dynamics().explicit_jacobians of a tree (-M^-1 times the Jacobian
               of its rows M a - F by the Newton-Euler recursion, solved by
               engine/ltdl.c) against recursion=False's (the same of Kane's M and F, solved
               by numpy), within MATRIX_TOLERANCE of the largest entry of each block
  r:dr         model.dynamics().residual_jacobians of a tree at x' = f (its rows
               M a - F by the Newton-Euler recursion) against recursion=False's (M and
               F as Kane's equations form them), as r:df
  r:df-python  model.dynamics(backend="python").explicit_jacobians against the C's
               (its programs over four nodes at once, the tree's solve by ltdl.c):
               the same operations, so `=` is the only agreement

  The model-level equations (M,f, explicit, symsys) are those of the model as it
  stands; they are compared for a CODE DYNAMICS whose definitions are the model's last
  and whose state is the model's coordinates and speeds (else `-`, with the reason).

Linearization (autolev linearize's printed eigenvalues, for a CODE DYNAMICS):

  l:warm       again, same cache (its kept answer)
  l:no-cache   AUTOLEV_NO_MODEL_CACHE=1, an empty cache
  l:c          --backend c: the symbolic Jacobians compiled to C (the tier a long sweep
               takes), against the dual numbers' (A, B, C and D written by --out, each
               within MATRIX_TOLERANCE of its largest entry)

A cell is `=` (identical), `~` (equal within the tolerance), `DIFF` (an unexplained
difference), `x:NAME` (a difference Autolev's own behaviour explains: EXPLAINED names
it), `fail` (the path gave no answer where the reference did: a difference too), `slow`
(the path's own time limit: not compared), `-` (does not apply).  Prints the table,
each difference's detail, and the counts; exit status 1 when any cell is DIFF or fail.
"""
from __future__ import annotations

import argparse
import contextlib
import csv
import json
import math
import random
import re
import shutil
import signal
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))
sys.path.insert(0, str(ROOT / "bench"))

import numpy as np  # noqa: E402

from journeys import (CORPUS, LISTING, RunToMatch, Values, autolev_cli,  # noqa: E402
                      chosen_models, code_cell, compare_files, missing_names, output_files,
                      process_env, read_model, rule_values, run_process)
from autolev.engine.clibrary import compiler  # noqa: E402
from journeys import Cell as JourneyCell  # noqa: E402

ROW_PATHS = ("warm", "no-cache", "foreground", "python", "api", "mass-matrix", "module",
             "code", "script")
RATE_PATHS = ("r:python", "r:recursion", "r:M,f", "r:explicit", "r:symsys", "r:module",
              "r:script", "r:dynamics", "r:df", "r:dr", "r:df-python")
LINEARIZE_PATHS = ("l:warm", "l:no-cache", "l:c")
PATHS = ROW_PATHS + RATE_PATHS + LINEARIZE_PATHS
RATE_TOLERANCE = 1e-8
# Jacobians that two exact methods compute part by their roundings, which a badly
# scaled model's cancellations amplify (SSOpt's cell model: 5e-10 of its largest entry)
MATRIX_TOLERANCE = 1e-8
# seconds a rates path may take inside the rates process (sympy's own forms are slow on
# large models: past it the cell is `slow`, not compared)
RATE_PATH_LIMIT = 120.0
# differences the rules of Autolev explain, by name (the table's x:NAME): what each is
EXPLAINED = {
    "after-last-code": "the model has errors after its last CODE statement: autolev run "
                       "builds through that statement (Autolev wrote each program when it "
                       "read its line: docs/language.md), loading the whole model (the "
                       "API, convert) reports them",
    "integrator": "the sympy script integrates with scipy's DOP853, autolev run with "
                  "Autolev's Kutta-Merson, at the same RELERR and ABSERR: the rows part by "
                  "the integrators' errors (the script's rates, r:script, are the run's)",
    "singular": "the motion passes a state where a run 1000 times tighter stops (no step "
                "size integrates it): rows after it are not compared",
}
# what the reference run says when it builds through its last CODE statement only
AFTER_LAST_CODE = "statements after the last CODE command fail to translate"


@dataclass
class Row:
    ident: str
    path: str
    values: str = ""
    cells: dict = field(default_factory=dict)       # path -> Cell
    seconds: float = 0.0


@dataclass
class Cell:
    mark: str                   # =, ~, DIFF, x:NAME, fail, slow, -
    detail: str = ""

    @property
    def differs(self) -> bool:
        return self.mark in ("DIFF", "fail")


# -- the files of a run ----------------------------------------------------------------
def written(folder: Path) -> dict:
    """{name: bytes} of what a run wrote into `folder` (its record of written files
    aside)."""
    if not folder.is_dir():
        return {}
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())
            if p.is_file() and not p.name.startswith(".")}


def same_files(reference: Path, other: Path) -> Cell:
    ours, theirs = written(reference), written(other)
    if ours == theirs:
        return Cell("=")
    if set(ours) != set(theirs):
        return Cell("DIFF", f"wrote {sorted(theirs)}; the reference {sorted(ours)}")
    name = next(n for n in ours if ours[n] != theirs[n])
    a, b = ours[name].decode(errors="replace"), theirs[name].decode(errors="replace")
    line = next((k for k, (x, y) in enumerate(zip(a.splitlines(), b.splitlines()))
                 if x != y), min(len(a.splitlines()), len(b.splitlines())))
    return Cell("DIFF", f"{name} line {line + 1}: "
                f"{(b.splitlines()[line:line + 1] or ['(none)'])[0].strip()[:70]!r}, "
                f"the reference {(a.splitlines()[line:line + 1] or ['(none)'])[0].strip()[:70]!r}")


def close_files(run: RunToMatch, other: Path, integrated: bool) -> Cell:
    """The rows equal as bench/journeys.py compares a written program's (its tight-run
    rule; x:singular where the tighter run itself stops before the rows part)."""
    from journeys import SINGULAR, ProgramCheck
    problems, remarks, compared = [], [], 0
    for stem in stems(run.folder):
        check = ProgramCheck()
        compare_files(check, other, stem, run, integrated=integrated)
        if check.problem:
            problems.append(check.problem)
        remarks += check.remarks
        compared += 1
    if problems:
        return Cell("DIFF", "; ".join(problems))
    singular = [r for r in remarks if r.startswith(SINGULAR)]
    if singular:
        return Cell("x:singular", "; ".join(singular))
    return Cell("~", "; ".join(remarks) or f"{compared} programs' files")


def stems(folder: Path) -> list[str]:
    """The program names (NAME of NAME.1 ...) of the output files in `folder`."""
    found = set()
    for p in folder.iterdir() if folder.is_dir() else []:
        stem, _, number = p.name.rpartition(".")
        if number.isdigit():
            found.add(stem)
    return sorted(found)


# -- one model -------------------------------------------------------------------------
class ModelPaths:
    """The paths of one model in its working folder `work`."""

    def __init__(self, ident: str, path: Path, companion: Path | None, work: Path,
                 limit: float, states: int):
        self.ident, self.path, self.companion = ident, path.resolve(), companion
        self.work, self.limit, self.states = work, limit, states
        self.model = read_model(self.path)
        self.options: list = []
        self.row = Row(ident, str(self.path))
        self.matching = None
        self.module = self.script_path = None

    def env(self, cache: str, **more) -> dict:
        """A command's environment with its own cache folder under `work`."""
        env = process_env(AUTOLEV_CACHE=str(self.work / f"cache-{cache}"), **more)
        for name in ("AUTOLEV_FOREGROUND", "AUTOLEV_NO_MODEL_CACHE", "AUTOLEV_NO_C"):
            if name not in more:
                env.pop(name, None)
        return env

    def run(self, name: str, cache: str, *extra, env=None):
        folder = self.work / name
        shutil.rmtree(folder, ignore_errors=True)
        return run_process(autolev_cli("run", self.path, "--out", folder, "-q",
                                       *self.options, *extra),
                           self.work, self.limit, env or self.env(cache)), folder

    # -- the reference, with values -------------------------------------------------
    def reference(self):
        """The cold run (its values by rule when it lacks some): the outcome."""
        given = ["--in", str(self.companion)] if self.companion else []
        chosen: dict = {}
        for _ in range(50):
            self.options = given + [a for n, v in chosen.items()
                                    for a in ("--set", f"{n}={v}")]
            shutil.rmtree(self.work / "cache-cold", ignore_errors=True)
            outcome, _ = self.run("run", "cold")
            new = [n for n in missing_names(outcome.stderr) if n not in chosen]
            if outcome.returncode != 1 or not new:
                break
            chosen.update(rule_values(new, self.model.products_of_inertia
                                      if self.model else set()))
        self.row.values = "INPUT" + (f", {self.companion.name}" if self.companion else "") \
            + (f", {len(chosen)} by rule" if chosen else "")
        self.by_rule = bool(chosen)
        return outcome

    # -- the paths --------------------------------------------------------------------
    def all(self) -> Row:
        start = time.monotonic()
        cells = self.row.cells
        if self.model is None or not self.model.code:
            for p in PATHS:
                cells[p] = Cell("-", "no CODE command" if self.model else "not parsed")
            return self.row
        ref = self.reference()
        if ref.returncode is None or ref.returncode not in (0, 1):
            for p in PATHS:
                cells[p] = Cell("-", f"the reference run ended {ref.returncode}")
            self.row.seconds = time.monotonic() - start
            return self.row
        reference = self.work / "run"
        self.status = ref.returncode
        self.through_last_code = AFTER_LAST_CODE in ref.stderr
        self.rows(reference)
        if ref.returncode == 0:
            self.rates()
            self.linearizations()
            self.explain_the_scripts_rows()
        else:
            for p in RATE_PATHS + LINEARIZE_PATHS:
                cells[p] = Cell("-", "the reference run failed (exit 1)")
        self.row.seconds = time.monotonic() - start
        return self.row

    def compare_outcome(self, name, outcome, folder, reference, exact=True) -> Cell:
        if outcome.returncode is None:
            return Cell("slow", f"over {self.limit:g} s")
        if outcome.returncode != self.status:
            said = (outcome.stderr.strip().splitlines() or [""])[-1][:120]
            if self.through_last_code and name in ("api", "mass-matrix"):
                return Cell("x:after-last-code", said)
            return Cell("fail", f"exit {outcome.returncode} (reference {self.status}): "
                        f"{said}")
        if exact:
            return same_files(reference, folder)
        return close_files(self.to_match(), folder, self.integrates())

    def to_match(self) -> RunToMatch:
        """The reference run, as journeys compares programs with it (made once: its
        tighter run is kept)."""
        if self.matching is None:
            self.matching = RunToMatch(self.path, self.work,
                                       Values(self.options, "", self.by_rule),
                                       self.companion if not self.by_rule else None,
                                       self.limit)
        return self.matching

    def integrates(self) -> bool:
        return any(kind in ("dynamics", "ode") for kind, _ in self.model.code)

    def rows(self, reference: Path) -> None:
        cells = self.row.cells
        outcome, folder = self.run("warm", "cold")
        cells["warm"] = self.compare_outcome("warm", outcome, folder, reference)
        for name, env in (("no-cache", self.env("no-cache", AUTOLEV_NO_MODEL_CACHE="1")),
                          ("foreground", self.env("foreground", AUTOLEV_FOREGROUND="1"))):
            outcome, folder = self.run(name, name, env=env)
            cells[name] = self.compare_outcome(name, outcome, folder, reference)
        outcome, folder = self.run("python", "python", "--backend", "python")
        cells["python"] = self.compare_outcome("python", outcome, folder, reference)
        for name, recursion in (("api", "1"), ("mass-matrix", "0")):
            folder = self.work / name
            shutil.rmtree(folder, ignore_errors=True)
            outcome = run_process([sys.executable, __file__, "--api-run", self.path, folder,
                                   "--recursion", recursion, *self.options], self.work,
                                  self.limit, self.env(name))
            cells[name] = self.compare_outcome(name, outcome, folder, reference,
                                               exact=name == "api")
        module = self.work / f"{self.path.stem}_module.py"
        converted = run_process(autolev_cli("convert", self.path, "-q", "-o", module),
                                self.work, self.limit, self.env("module"))
        if converted.returncode != 0:
            said = "convert: " + _last(converted.stderr)
            cells["module"] = Cell("x:after-last-code", said) if self.through_last_code \
                else Cell("-", said + "; the reference run failed too") if self.status \
                else Cell("fail", said)
            self.module = None
        else:
            self.module = module
            outcome = run_process(autolev_cli("run", module, "--out", self.work / "module",
                                              "-q", *self.options), self.work, self.limit,
                                  self.env("module"))
            cells["module"] = self.compare_outcome("module", outcome, self.work / "module",
                                                   reference)
        cells["code"] = self.code(reference)
        cells["script"] = self.script(reference)

    def code(self, reference: Path) -> Cell:
        if self.status != 0:
            return Cell("-", "the reference run failed (exit 1)")
        cell = code_cell(self.ident, self.model, self.to_match(), {})
        return _from_journey(cell)

    def script(self, reference: Path) -> Cell:
        """The sympy script's rows, split into the run's files."""
        self.script_path = None
        if self.status != 0 or not self.integrates():
            return Cell("-", "no CODE DYNAMICS or ODE" if self.status == 0
                        else "the reference run failed (exit 1)")
        script = self.work / f"{self.path.stem}_sympy.py"
        made = run_process(autolev_cli("convert", self.path, "--to", "sympy", "-q", "-o",
                                       script, *self.options), self.work, self.limit,
                           self.env("script"))
        if made.returncode != 0:
            return Cell("fail", "convert --to sympy: " + _last(made.stderr))
        self.script_path = script
        rows = self.work / "script.csv"
        self.script_rows_path = rows
        ran = run_process([sys.executable, script, rows], self.work, self.limit,
                          self.env("script"))
        if ran.returncode is None:
            return Cell("slow", f"the script took over {self.limit:g} s")
        if ran.returncode != 0:
            return Cell("fail", "the script: " + _last(ran.stderr))
        return self.script_rows(reference, rows)

    def script_rows(self, reference: Path, rows: Path) -> Cell:
        """The script's CSV (the first integrating command's columns, file after file)
        written as that command's files, then compared as a program's."""
        if not stems(reference):
            return Cell("-", "no OUTPUT: neither writes a row")
        table = np.loadtxt(rows, delimiter=",", skiprows=1, ndmin=2) \
            if len(rows.read_text().splitlines()) > 1 else np.zeros((0, 0))
        if not table.size:
            return Cell("fail", "the script wrote no row")
        folder = self.work / "script"
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir()
        for stem in stems(reference):
            files = output_files(reference, stem)
            widths = [_width(files[n]) for n in sorted(files, key=_number_of)]
            if sum(widths) != table.shape[1]:
                continue
            start = 0
            for name, width in zip(sorted(files, key=_number_of), widths):
                np.savetxt(folder / files[name].name, table[:, start:start + width],
                           fmt="%.15e")
                start += width
            return close_files(self.to_match(), folder, True)
        return Cell("DIFF", f"its {table.shape[1]} columns match no command's files")

    def explain_the_scripts_rows(self) -> None:
        """Rows of the script that part after its first row, while its rates are the
        run's: the integrators differ (x:integrator)."""
        cells = self.row.cells
        rows, rates = cells.get("script"), cells.get("r:script")
        parted = re.search(r"from row (\d+)", rows.detail) if rows is not None else None
        if rows is not None and rows.mark == "DIFF" and parted and int(parted.group(1)) > 1 \
                and rates is not None and rates.mark in ("=", "~"):
            cells["script"] = Cell("x:integrator", rows.detail)

    def rates(self) -> None:
        cells = self.row.cells
        if not self.integrates():
            for p in RATE_PATHS:
                cells[p] = Cell("-", "no CODE DYNAMICS or ODE")
            return
        argv = [sys.executable, __file__, "--rates", self.path, "--states", str(self.states),
                *self.options]
        if self.module is not None:
            argv += ["--module", self.module]
        if self.script_path is not None:
            argv += ["--script", self.script_path]
        outcome = run_process(argv, self.work, self.limit, self.env("rates"))
        if outcome.returncode != 0:
            for p in RATE_PATHS:
                cells[p] = Cell("fail" if outcome.returncode else "slow",
                                "the rates process: " + _last(outcome.stderr))
            return
        found = json.loads(outcome.stdout)
        reference = found.get("run")
        for p in RATE_PATHS:
            got = found.get(p[2:], {"mark": "-", "detail": "not taken"})
            if got["mark"] != "ok":
                cells[p] = Cell(got["mark"], got.get("detail", ""))
                continue
            cells[p] = (compare_jacobians(got) if p in ("r:df", "r:dr", "r:df-python")
                        else compare_rates(reference, got))

    def linearizations(self) -> None:
        cells = self.row.cells
        if not any(kind == "dynamics" for kind, _ in self.model.code):
            for p in LINEARIZE_PATHS:
                cells[p] = Cell("-", "no CODE DYNAMICS")
            return
        argv = autolev_cli("linearize", self.path, *self.options)
        first = run_process(argv, self.work, self.limit, self.env("lin"))
        for name, env in (("l:warm", self.env("lin")),
                          ("l:no-cache", self.env("lin-nc", AUTOLEV_NO_MODEL_CACHE="1"))):
            again = run_process(argv, self.work, self.limit, env)
            if again.returncode != first.returncode:
                cells[name] = Cell("fail", f"exit {again.returncode} (first "
                                   f"{first.returncode}): {_last(again.stderr)}")
            elif again.stdout != first.stdout:
                cells[name] = Cell("DIFF", "the eigenvalues printed differ")
            else:
                cells[name] = Cell("=", "" if first.returncode == 0
                                   else f"both exit {first.returncode}")
        if compiler() is None:
            cells["l:c"] = Cell("-", "no C compiler")
            return
        folders = {tier: self.work / f"lin-{tier}" for tier in ("dual", "c")}
        ran = {}
        for tier, folder in folders.items():
            shutil.rmtree(folder, ignore_errors=True)
            ran[tier] = run_process(
                autolev_cli("linearize", self.path, *self.options, "--out", folder,
                            *(("--backend", "c") if tier == "c" else ())),
                self.work, self.limit, self.env("lin" if tier == "dual" else "lin-c"))
        if ran["c"].returncode is None:
            cells["l:c"] = Cell("slow", f"over {self.limit:g} s")
        elif ran["c"].returncode != ran["dual"].returncode:
            cells["l:c"] = Cell("fail", f"exit {ran['c'].returncode} (dual numbers "
                                f"{ran['dual'].returncode}): {_last(ran['c'].stderr)}")
        elif ran["c"].returncode:
            cells["l:c"] = Cell("=", f"both exit {ran['c'].returncode}")
        else:
            cells["l:c"] = compare_matrices(folders["dual"], folders["c"])


def linear_matrices(folder: Path) -> dict:
    """{name: (row names, column names, values)} of the A, B, C, D that `autolev
    linearize --out` wrote."""
    found = {}
    for path in sorted(folder.glob("*-[ABCD].csv")):
        with path.open(newline="") as f:
            rows = list(csv.reader(f))      # an output named X[1,2] is quoted
        found[path.stem[-1]] = (tuple(r[0] for r in rows[1:]), tuple(rows[0][1:]),
                                np.array([[float(v) for v in r[1:]] for r in rows[1:]]))
    return found


def compare_matrices(reference: Path, got: Path) -> Cell:
    """A, B, C and D alike: each within MATRIX_TOLERANCE of its largest entry (the
    eigenvalues are no measure: a defective one, SSOpt's cell model's cluster at -1,
    moves by the square root of A's rounding)."""
    ours, theirs = linear_matrices(reference), linear_matrices(got)
    if set(ours) != set(theirs) or not ours:
        return Cell("DIFF", f"matrices {sorted(theirs)}, not {sorted(ours)}")
    worst = 0.0
    for name, (rows, cols, a) in ours.items():
        rows_b, cols_b, b = theirs[name]
        if (rows, cols) != (rows_b, cols_b):
            return Cell("DIFF", f"{name}: other rows or columns")
        if a.size:
            worst = max(worst, float(np.max(np.abs(a - b))) / max(1.0, float(np.max(np.abs(a)))))
    if not worst <= MATRIX_TOLERANCE:
        return Cell("DIFF", f"A, B, C, D differ by {worst:.3g} of their largest entry")
    return Cell("~" if worst else "=", f"{worst:.1g}" if worst else "")


def compare_rates(reference: dict, got: dict) -> Cell:
    """The rates of the states both name, at the same points, within RATE_TOLERANCE or
    what solving the mass matrix may round (10 eps cond(M): its two solves, in another
    order of operations, part by that much)."""
    names = [n for n in reference["states"] if n in got["states"]]
    if set(names) != set(reference["states"]):
        return Cell("-", f"other states: {got['states']}")
    worst = 0.0
    for ours, theirs in zip(reference["rates"], got["rates"]):
        a = np.array([ours[reference["states"].index(n)] for n in names])
        b = np.array([theirs[got["states"].index(n)] for n in names])
        scale = np.maximum(1.0, np.abs(a))
        gap = float(np.max(np.abs(a - b) / scale))
        worst = max(worst, gap if math.isfinite(gap) else math.inf)
    allowed = max(RATE_TOLERANCE, 10 * np.finfo(float).eps * reference.get("condition", 1.0))
    if not math.isfinite(worst) or worst > allowed:
        return Cell("DIFF", f"rates differ by {worst:.3g} of max(1, |rate|)"
                    + (f" (allowed {allowed:.2g}: cond(M) "
                       f"{reference['condition']:.2g})" if allowed > RATE_TOLERANCE else ""))
    return Cell("~" if worst else "=", f"{worst:.1g}" if worst else "")


def compare_jacobians(got: dict) -> Cell:
    """f's or r's Jacobians by one route against another's, block by block (`exact`:
    routes of the same operations, which agree to the bit or not at all)."""
    worst = 0.0
    for ours, theirs in got["blocks"].values():
        a, b = np.array(ours), np.array(theirs)
        if b.size:
            gap = float(np.max(np.abs(a - b)) / max(1.0, float(np.max(np.abs(b)))))
            worst = max(worst, gap if math.isfinite(gap) else math.inf)
    if not math.isfinite(worst) or worst > (0.0 if got.get("exact") else MATRIX_TOLERANCE):
        return Cell("DIFF", f"{got['form']}'s Jacobians differ by {worst:.3g} of their "
                    "largest entry")
    return Cell("~" if worst else "=", f"{worst:.1g}" if worst else "")


def _from_journey(cell: JourneyCell) -> Cell:
    from journeys import SINGULAR
    if cell.status == "ok":
        return Cell("x:singular" if SINGULAR in cell.reason else "~", cell.reason)
    if cell.status == "-":
        return Cell("-", cell.reason)
    return Cell("DIFF" if "differs" in cell.reason else "fail", cell.reason)


def _width(path: Path) -> int:
    from truth import read_table
    table = read_table(path)
    return table.shape[1] if table.size else 0


def _number_of(name: str) -> int:
    return int(name.rpartition(".")[2])


def _last(text: str) -> str:
    """A command's last line, whole: a transient failure is known by it alone."""
    lines = [line for line in text.strip().splitlines() if line.strip()]
    return lines[-1][:1000] if lines else "(nothing said)"


# -- inside the paths' processes ---------------------------------------------------------
def api_run(path: Path, out: Path, recursion: bool, options: list) -> int:
    """`autolev.load(path).run(out, ...)` with the command line's values: the exit
    status autolev run would give (1 for a refusal or a failed command)."""
    import warnings

    import autolev
    infile, values = _values(options)
    warnings.simplefilter("ignore")
    try:
        model = autolev.load(path)
        status = 0
        for done in model.run_commands(model.code_commands, out, keep_going=True,
                                       options=_run_options(infile, values, recursion)):
            if done.error is not None or done.result.failure:
                print(done.error or done.result.failure, file=sys.stderr)
                status = 1
        return status
    except autolev.AutolevError as exc:
        print(str(exc).splitlines()[0], file=sys.stderr)
        return 1


def _run_options(infile, values: dict, recursion: bool):
    from autolev.engine.options import RunOptions
    return RunOptions(infile=infile, overrides=values or None, recursion=recursion,
                      keep_rows=False)


def _values(options: list) -> tuple:
    infile, values = None, {}
    for flag, item in zip(options, options[1:]):
        if flag == "--in":
            infile = item
        elif flag == "--set":
            name, _, value = item.partition("=")
            values[name] = float(value)
    return infile, values


class _Slow(Exception):
    pass


@contextlib.contextmanager
def _limited(seconds: float):
    def stop(_signum, _frame):
        raise _Slow()
    signal.signal(signal.SIGALRM, stop)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)


def rates(path: Path, options: list, count: int, module: Path | None,
          script: Path | None) -> dict:
    """{path: {"mark": ok|-|fail|slow, "states": names, "rates": [[...]...]}} at
    `count` states near the initial one (the run's first CODE DYNAMICS or ODE)."""
    import warnings

    import autolev
    from autolev.engine.options import RunOptions
    from autolev.runtime.numerics.prepare import prepare_command
    warnings.simplefilter("ignore")
    infile, values = _values(options)
    from autolev.loader import load_for_run
    model, _ = load_for_run(path)          # as autolev run builds it (to its last CODE)
    index, command = next((k, c) for k, c in enumerate(model.code_commands)
                          if c.kind.integrates)
    given = RunOptions(infile=infile, overrides=values or None)
    prepared = prepare_command(model.snapshot_for(command), command, given)
    system = prepared.system
    names = [str(s) for s in system.states]
    x0 = np.array(prepared.inputs.vector(system.states), dtype=float)
    rng = random.Random(7)
    points = []
    for _ in range(count):
        x = x0 + np.array([0.1 * rng.uniform(-1, 1) * (1 + abs(v)) for v in x0])
        points.append((prepared.inputs.internal("TINITIAL") + rng.uniform(0, 0.5), x))

    def of(system_):
        return [list(map(float, system_.derivatives(t, x))) for t, x in points]
    found = {"run": {"mark": "ok", "states": names, "rates": of(system)}}

    def taking(name, make):
        try:
            with _limited(RATE_PATH_LIMIT):
                found[name] = make()
        except _Slow:
            found[name] = {"mark": "slow", "detail": f"over {RATE_PATH_LIMIT:g} s"}
        except _NotApplicable as exc:
            found[name] = {"mark": "-", "detail": str(exc)}
        except (autolev.AutolevError, ArithmeticError, ValueError, TypeError,
                NotImplementedError, np.linalg.LinAlgError) as exc:
            found[name] = {"mark": "fail", "detail": f"{type(exc).__name__}: "
                           + str(exc).splitlines()[0][:150]}

    def again(**changes):
        other = prepare_command(model.snapshot_for(command), command,
                                given.but(**changes)).system
        return {"mark": "ok", "states": [str(s) for s in other.states], "rates": of(other)}

    def by_mass_matrix():
        found_ = again(recursion=False)
        other = prepare_command(model.snapshot_for(command), command,
                                given.but(recursion=False)).system
        conditions = []
        for t, x in points:                  # each solve's rounding: eps * cond(M)
            other.derivatives(t, x)
            mass = other.last_mass_matrix()
            if mass is not None and np.all(np.isfinite(mass)):
                conditions.append(float(np.linalg.cond(mass)))
        found["run"]["condition"] = max(conditions, default=1.0)
        return found_
    taking("python", lambda: again(backend="python"))
    taking("recursion", by_mass_matrix)
    params = {p: prepared.inputs.internal(p) for p in system.params}
    taking("M,f", lambda: model_rates(model, command, system, points, params, "M,f"))
    taking("explicit", lambda: model_rates(model, command, system, points, params,
                                           "explicit"))
    extra = dependent_values(model, system, points, params)
    taking("symsys", lambda: symbolic_rates(model, command, system, points, params, extra))
    def by_dynamics():
        from autolev.runtime.numerics.dynamics import dynamics
        dyn = dynamics(model.snapshot_for(command), infile=infile, overrides=values or None)
        rates_ = dyn.explicit(np.array([x for _, x in points]), None, None,
                              np.array([t for t, _ in points]))
        return {"mark": "ok", "states": dyn.states, "rates": rates_.tolist()}
    taking("dynamics", by_dynamics)

    def jacobians_by_both(form: str):
        from autolev.runtime.numerics.dynamics import dynamics
        x = np.array([x for _, x in points])
        t = np.array([t for t, _ in points])
        def by(recursion: bool):
            dyn = dynamics(model.snapshot_for(command), infile=infile,
                           overrides=values or None, recursion=recursion)
            return (dyn.explicit_jacobians(x, None, None, t) if form == "f" else
                    dyn.residual_jacobians(x, dyn.explicit(x, None, None, t), None, None, t))
        by_tree = by(True)
        if by_tree.by != "recursion":
            raise _NotApplicable(f"not a tree: {form}'s Jacobians by the mass matrix alone")
        by_mass = by(False)
        return {"mark": "ok", "form": form,
                "blocks": {b: (by_tree.dense(b).tolist(), by_mass.dense(b).tolist())
                           for b in by_mass.values}}
    taking("df", lambda: jacobians_by_both("f"))
    taking("dr", lambda: jacobians_by_both("r"))

    def jacobians_by_tiers():
        from autolev.engine import clibrary
        from autolev.runtime.numerics.dynamics import dynamics
        if clibrary.compiler() is None:
            raise _NotApplicable("no C compiler: one tier")
        x = np.array([x for _, x in points])
        t = np.array([t for t, _ in points])
        by_c, by_python = (dynamics(model.snapshot_for(command), infile=infile,
                                    overrides=values or None, backend=backend)
                           .explicit_jacobians(x, None, None, t)
                           for backend in ("c", "python"))
        return {"mark": "ok", "form": "f", "exact": True,
                "blocks": {b: (by_python.dense(b).tolist(), by_c.dense(b).tolist())
                           for b in by_c.values}}
    taking("df-python", jacobians_by_tiers)
    if module is not None:
        def from_module():
            from autolev.loader import load_python
            other = load_python(module)
            prepared_ = prepare_command(other.snapshot_for(other.code_commands[index]),
                                        other.code_commands[index], given)
            return {"mark": "ok", "states": [str(s) for s in prepared_.system.states],
                    "rates": of(prepared_.system)}
        taking("module", from_module)
    if script is not None:
        taking("script", lambda: script_rates(script, points, names, extra))
    return found


class _NotApplicable(Exception):
    pass


def _model_level(model, command, system):
    """Refuse (_NotApplicable) a command whose equations are not the model's own."""
    from autolev.runtime.symbols import derivative
    if command.kind.upper() != "DYNAMICS":
        raise _NotApplicable("a CODE ODE: its equations are not Kane's")
    now = model.defs.user_definitions()
    if command.definitions is not None and (
            len(now) != len(command.definitions)
            or any(command.definitions.get(s) is not e for s, e in now.items())):
        raise _NotApplicable("the model defines more after its CODE DYNAMICS")
    if model.auxiliary_speeds:
        raise _NotApplicable("auxiliary speeds (0 in the run)")
    states = [str(q) for q in model.coordinates] + [str(u) for u in model.speeds]
    if sorted(states) != sorted(str(s) for s in system.states):
        raise _NotApplicable(f"the model's state {states}, the command's "
                             f"{[str(s) for s in system.states]}")
    return derivative


def model_rates(model, command, system, points, params, which: str) -> dict:
    """The rates from model.mass_matrix/forcing/kinematical_equations, or from
    model.explicit_form(), evaluated through the model's definitions."""
    from autolev.runtime.calculus import NumericPoint
    from autolev.runtime.symbols import TIME
    derivative = _model_level(model, command, system)
    order = list(model.coordinates) + list(model.speeds)
    if which == "M,f":
        mass, forcing = model.mass_matrix, model.forcing
        kinematics = [model.kinematical_equations[derivative(q)] for q in model.coordinates]
    else:
        explicit = model.explicit_form()
    out = []
    for t, x in points:
        values = dict(zip(system.states, x)) | params | {TIME: t}
        values |= {s: 0.0 for s in system.specified if s not in model.defs.rhs}
        point = NumericPoint(model.defs, values)

        def number(e):
            return model.defs.numeric(e, point).real
        if which == "M,f":
            m = np.array([[number(e) for e in mass.row(i)] for i in range(mass.rows)])
            f = np.array([number(e) for e in forcing])
            rates_ = [number(e) for e in kinematics] + list(np.linalg.solve(m, f))
        else:
            rates_ = [number(e) for e in explicit]
        out.append(list(map(float, rates_)))
    return {"mark": "ok", "states": [str(s) for s in order], "rates": out}


def dependent_values(model, system, points, params) -> list[dict]:
    """At each point, {name: value} of the model's dependent speeds (the run's state
    holds the independent ones): their definitions, evaluated."""
    from autolev.runtime.calculus import NumericPoint
    from autolev.runtime.symbols import TIME
    out = []
    for t, x in points:
        values = dict(zip(system.states, x)) | params | {TIME: t}
        point = NumericPoint(model.defs, values)
        out.append({str(u): model.defs.numeric(u, point).real
                    for u in model.dependent_speeds})
    return out


def symbolic_rates(model, command, system, points, params, extra) -> dict:
    """The rates from sympy's SymbolicSystem, lambdified: its differential rows (the
    algebraic rows of dependent speeds given their values), specified quantities the
    model leaves undefined 0, as the run has them."""
    import sympy as sm
    import sympy.physics.mechanics as me
    _model_level(model, command, system)
    ss = model.symbolic_system("combined")
    t = me.dynamicsymbols._t
    plain = {x: sm.Dummy() for x in ss.states}
    by_name = {str(p): v for p, v in params.items()}
    consts = sorted(ss.constant_symbols(), key=str)
    from sympy.core.function import AppliedUndef
    both = (ss.comb_implicit_rhs, ss.comb_implicit_mat)
    undefined = {f for e in both for f in e.atoms(AppliedUndef) if f not in plain}
    # their derivatives (PX'' of a base's prescribed motion) 0, and themselves the value
    # the run gives them: an input's (a VARIABLE given by INPUT), else 0
    specified = {d: 0 for e in both for d in e.atoms(sm.Derivative)
                 if d.expr in undefined} | {f: by_name.get(str(f.func), 0) for f in undefined}
    args = [t] + list(plain.values()) + consts
    n = len(ss.states) - len(model.dependent_speeds)      # the differential rows
    mass = sm.lambdify(args, ss.comb_implicit_mat[:n, :n].xreplace(specified)
                       .xreplace(plain), "numpy")
    force = sm.lambdify(args, ss.comb_implicit_rhs[:n, :].xreplace(specified)
                        .xreplace(plain), "numpy")
    names = [_state_name(x) for x in ss.states]
    index = {str(s): k for k, s in enumerate(system.states)}
    out = []
    for (time_, x), dependent in zip(points, extra):
        state = [x[index[m]] if m in index else dependent[m] for m in names]
        numbers = [time_] + state + [by_name[str(c)] for c in consts]
        m = np.array(mass(*numbers), dtype=float)
        f = np.array(force(*numbers), dtype=float).ravel()
        out.append(list(map(float, np.linalg.solve(m, f))))
    return {"mark": "ok", "states": names[:n], "rates": out}


def _state_name(x) -> str:
    """Autolev's name of a sympy state: Q1 for Q1(t), Q1' for its derivative."""
    import sympy as sm
    if isinstance(x, sm.Derivative):
        return _state_name(x.expr) + "'" * sum(n for _, n in x.variable_count)
    return str(x.func) if isinstance(x, sm.Function) or getattr(x, "args", ()) else str(x)


def script_rates(script: Path, points, names: list, extra) -> dict:
    """The rates from the exported script's mass matrix and forcing (its state may
    hold the dependent speeds: `extra` gives their values)."""
    import importlib.util
    spec = importlib.util.spec_from_file_location("exported_script", script)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    mass, force, _ = module.numeric_functions()
    # a variable given by its second derivative has the speed NAME_rate at the mechanics
    # level, and the equations level names a derivative with a p per order (NAMEp)
    primed = {n.replace("'", "p"): n for n in names if "'" in n}
    order = [n[:-5] + "'" if n.endswith("_rate") and n[:-5] + "'" in names
             else primed.get(n, n) if n not in names else n
             for n in map(_state_name, module.states)]
    p = [module.constants[c] for c in module.constants]
    index = {n: k for k, n in enumerate(names)}
    if not set(names) <= set(order) or not set(order) - set(names) <= set(extra[0]):
        raise _NotApplicable(f"the script's state {order}")
    out = []
    for (t, x), dependent in zip(points, extra):
        state = np.array([x[index[n]] if n in index else dependent[n] for n in order])
        s = [v(t) if callable(v) else v for v in module.specified.values()]
        m = np.asarray(mass(t, state, p, s), dtype=float)
        f = np.asarray(force(t, state, p, s), dtype=float).ravel()
        out.append(list(map(float, np.linalg.solve(m, f))))
    return {"mark": "ok", "states": order, "rates": out}


# -- the report ------------------------------------------------------------------------
def table(rows: list[Row]) -> str:
    width = max([len(r.ident) for r in rows] + [5])
    marks = {p: max(len(p), *(len(r.cells.get(p, Cell("-")).mark) for r in rows))
             for p in PATHS}
    lines = [f"{'model':{width}s}  " + " ".join(f"{p:{marks[p]}s}" for p in PATHS)]
    for r in rows:
        lines.append(f"{r.ident:{width}s}  " + " ".join(
            f"{r.cells.get(p, Cell('-')).mark:{marks[p]}s}" for p in PATHS).rstrip())
    notes = [f"  {r.ident} {p}: {r.cells[p].mark}: {r.cells[p].detail}"
             for r in rows for p in PATHS
             if p in r.cells and (r.cells[p].differs or r.cells[p].mark.startswith("x:")
                                  or r.cells[p].mark == "slow")]
    if notes:
        lines += ["", "differences, explained differences and paths over their limit:"] \
            + notes
    return "\n".join(lines)


def counts(rows: list[Row]) -> dict:
    out = {}
    for p in PATHS:
        tally: dict = {}
        for r in rows:
            mark = r.cells.get(p, Cell("-")).mark
            mark = "x" if mark.startswith("x:") else mark
            tally[mark] = tally.get(mark, 0) + 1
        out[p] = tally
    return out


def one(item, limit: float, states: int, keep: Path | None) -> Row:
    ident, path, companion = item
    if keep is not None:
        work = keep / re.sub(r"[^\w.-]", "_", ident)
        shutil.rmtree(work, ignore_errors=True)
        work.mkdir(parents=True)
        return ModelPaths(ident, path, companion, work, limit, states).all()
    with tempfile.TemporaryDirectory(prefix="paths-") as tmp:
        return ModelPaths(ident, path, companion, Path(tmp), limit, states).all()


def run_all(models, limit: float, jobs: int, states: int, keep: Path | None = None,
            progress=None, on_row=lambda done: None) -> list[Row]:
    """Every model's row; `on_row` is given the rows done so far after each one (a run
    cut short keeps what it measured)."""
    lock = threading.Lock()
    done: list[Row] = []

    def each(item):
        row = one(item, limit, states, keep)
        with lock:
            done.append(row)
            on_row(list(done))
            if progress is not None:
                bad = sum(c.differs for c in row.cells.values())
                print(f"  {row.ident}: {bad} differences ({row.seconds:.0f} s)",
                      file=progress, flush=True)
        return row
    with ThreadPoolExecutor(jobs) as pool:
        return list(pool.map(each, models))


def parse_args(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corpus", type=Path, default=CORPUS)
    ap.add_argument("--listing", type=Path, default=LISTING)
    ap.add_argument("--examples", action="store_true",
                    help="the shipped autolev_examples/*.al instead of the corpus")
    ap.add_argument("--only", action="append", metavar="ID")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--limit", type=float, default=600, help="seconds per command")
    ap.add_argument("--states", type=int, default=3, help="random states for the rates")
    ap.add_argument("--json", type=Path, metavar="FILE")
    ap.add_argument("--keep", type=Path, metavar="DIR")
    # the paths' own processes
    ap.add_argument("--api-run", nargs=2, type=Path, metavar=("FILE", "OUT"),
                    help=argparse.SUPPRESS)
    ap.add_argument("--rates", type=Path, metavar="FILE", help=argparse.SUPPRESS)
    ap.add_argument("--recursion", default="1", help=argparse.SUPPRESS)
    ap.add_argument("--module", type=Path, help=argparse.SUPPRESS)
    ap.add_argument("--script", type=Path, help=argparse.SUPPRESS)
    ap.add_argument("--in", dest="infile", help=argparse.SUPPRESS)
    ap.add_argument("--set", action="append", default=[], help=argparse.SUPPRESS)
    return ap.parse_args(argv)


def main(argv=None) -> int:
    ns = parse_args(argv)
    options = (["--in", ns.infile] if ns.infile else []) + \
        [a for item in ns.set for a in ("--set", item)]
    if ns.api_run:
        return api_run(*ns.api_run, ns.recursion == "1", options)
    if ns.rates:
        print(json.dumps(rates(ns.rates, options, ns.states, ns.module, ns.script)))
        return 0
    models = chosen_models(ns)
    if not models:
        print("no model found (see --corpus, --listing, --only)", file=sys.stderr)
        return 2
    start = time.monotonic()
    rows = run_all(models, ns.limit, ns.jobs, ns.states, ns.keep, progress=sys.stderr,
                   on_row=(lambda done: write_json(ns.json, done)) if ns.json else
                   (lambda done: None))
    print(table(rows))
    print()
    for p, tally in counts(rows).items():
        print(f"{p:12s} " + "  ".join(f"{k} {v}" for k, v in sorted(tally.items())))
    bad = sum(c.differs for r in rows for c in r.cells.values())
    print(f"\n{len(rows)} models, {bad} unexplained differences, "
          f"{time.monotonic() - start:.0f} s")
    return 1 if bad else 0


def write_json(path: Path, rows: list[Row]) -> None:
    """Every cell of the rows so far, replacing the file whole (never half written)."""
    part = path.with_name(path.name + ".part")
    part.write_text(json.dumps({"models": {r.ident: {
        "values": r.values, "seconds": round(r.seconds, 1),
        "cells": {p: asdict(c) for p, c in r.cells.items()}} for r in rows}},
        indent=1) + "\n")
    part.replace(path)


if __name__ == "__main__":
    sys.exit(main())
