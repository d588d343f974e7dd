#!/usr/bin/env python3
"""The corpus's largest models end to end: cold and warm runs split by stage, the size
of the generated code and its compile time, microseconds per evaluation against
Autolev's own generated program where the corpus has it, and peak memory.

    python bench/large_models.py [--corpus DIR] [--warm N] [--only TEXT] [--no-autolev]

Per model, each run a fresh Python process (`autolev run` with the model's .in file
where the corpus has one, else INPUT values and 0 for the rest):
    cold      an empty cache folder: translate, form, generate, compile, run
    warm      the same folder again (the minimum of --warm runs): everything derived is
              read back from the cache of built models and the build cache
    stages    import / load (translate + execute the module) / build (generate and
              compile the numeric code) / run (integrate or evaluate, write the files)
    code      bytes of generated C and Python; compile: seconds in the C compiler
    RSS       peak resident memory of the cold run's Python process (and of the
              compiler, the largest of its processes)
    us/eval   one evaluation of the program's computation, at one state, in C:
              ours     DYNAMICS: autolev_derivatives (right-hand side + the solve of
                       the mass matrix), timed in a C loop; ALGEBRAIC: the ENCODE/OUTPUT
                       quantities with every definition they need, compiled as one C
                       function (as Autolev's eqns1 recomputes its constants), and
                       per state: the parts in constants alone lifted out and
                       evaluated once per parameter set, as our runs do
              Autolev  its program from the corpus, compiled with the same compiler and
                       flags (clibrary.C_FLAGS), its eqns1 called in a loop: C through a
                       driver linked in its place of main, Fortran with a timing loop
                       put before its first integration step (gfortran)
              Both sides read the same values (the model's .in, or for a model
              without one every constant and input set from its name); the states are
              those values.
Target (issue 17): warm < 1 s; cold < 10 s to the first row and < 30 s to the last;
per evaluation faster than Autolev's C; peak RSS < 1 GB.  With matplotlib,
bench/out/large_models.png draws cold and warm times by stage.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))
sys.path.insert(0, str(ROOT / "bench"))

BIOMAC = "mad-lab-fau+BioMAC-Sim-Toolbox/src/model/gait3d/c_files/gait3d_pelvis213/"
SPRINT = "TomRottier+SprintingModel/Model/7segv2/"
SPRINT13 = "TomRottier+SprintingModel_julia/model/13seg_tq/"

# (label, model, its .in or None, Autolev's program for the timed command or None)
MODELS = [
    ("gait3d pelvis213 NoDer (33 speeds)", BIOMAC + "gait3d_pelvis213_NoDer.al", None,
     BIOMAC + "gait3d_pelvis213_NoDer_raw.c"),
    ("gait3d pelvis213 FK (33 speeds)", BIOMAC + "gait3d_pelvis213_FK.al", None,
     BIOMAC + "gait3d_pelvis213_FK_raw.c"),
    ("Whipple bicycle + rider, lean", "moorepants+RiderModel/autolev/WhipplePlusRiderLean.AL",
     None, None),
    ("Whipple bicycle + rider, lean angle",
     "moorepants+RiderModel/autolev/WhipplePlusRiderLeanAngle.AL", None, None),
    ("bicycle + rider, lean torque", "moorepants+RiderModel/autolev/LeanTorque.AL", None,
     None),
    ("MAE-223 bicycle 13", "moorepants+MAE-223/BicycleDynamicsProject/AutolevSRC/BICYCLE13.AL",
     None, None),
    ("swing bike", "moorepants+SwingBike/SB_01.AL", None, None),
    ("sprinter, 13 segments", SPRINT13 + "model.al", SPRINT13 + "model.in",
     SPRINT13 + "model.f"),
    ("sprinter, 7 segments", SPRINT + "7segsprint.al", None,
     SPRINT + "base/raw/7segsprint_raw.f"),
    ("rower", "csu-hmc+rowing/model/rowerdynamics.al", None, None),
]
EXAMPLE = ("Whipple benchmark (shipped example)",
           str(ROOT / "autolev_examples" / "whipple_benchmark.al"), None, None)

RUN_CHILD = r"""
import json, resource, sys, time, warnings
t0 = time.perf_counter()
import autolev
from autolev.loader import load_for_run
from autolev.engine.errors import AutolevModelError
from autolev.engine import clibrary
from autolev.runtime.numerics import codegen
from autolev.engine.options import RunOptions
from autolev.runtime.numerics.run import run_command
t1 = time.perf_counter()
code = {"c": 0, "python": 0, "compile": 0.0}
real_library, real_python = clibrary.build_shared_library, codegen.compile_python
def library(source, *a, **k):
    start = time.perf_counter()
    path = real_library(source, *a, **k)
    code["compile"] += time.perf_counter() - start
    code["c"] += len(source)
    return path
def python(prog, name="compute"):
    made = real_python(prog, name)
    code["python"] += len(made[1])
    return made
clibrary.build_shared_library, codegen.compile_python = library, python
warnings.simplefilter("ignore")
model, notes = load_for_run(sys.argv[1])
t2 = time.perf_counter()
build = run = 0.0
rows = failed = 0
first_row = None
infile = sys.argv[2] or None
commands = model.commands_named(None) or [model.command_to_run()]
import tempfile
with tempfile.TemporaryDirectory() as out:
    for command in commands:
        start = time.perf_counter()
        try:
            result = run_command(model.snapshot_for(command), out,
                                 RunOptions(infile=infile, missing_values="zero"))
        except AutolevModelError:
            failed += 1
            continue
        finally:
            elapsed = time.perf_counter() - start
        build += result.stats.get("build_seconds", 0.0)
        rows += result.stats.get("rows", 0)
        run += elapsed
        if first_row is None:
            first_row = t2 - t0 + result.stats.get("build_seconds", 0.0)
model.keep_built()
t3 = time.perf_counter()
print(json.dumps({
    "import": t1 - t0, "load": t2 - t1, "build": build, "run": run - build,
    "total": t3 - t0, "first_row": first_row, "rows": rows, "failed": failed,
    "code_c": code["c"], "code_python": code["python"], "compile": code["compile"],
    "rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
    "cc_rss_mb": resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024}))
"""


def _child(code: str, args: list, cache: str, limit: float) -> dict | str:
    """The JSON a fresh Python running `code` prints last, with the model cache on
    and its folder `cache`; or why there is none."""
    env = dict(os.environ, AUTOLEV_CACHE=cache, PYTHONPATH=str(ROOT / "src"))
    env.pop("AUTOLEV_NO_MODEL_CACHE", None)
    try:
        r = subprocess.run([sys.executable, "-c", code, *map(str, args)],
                           capture_output=True, text=True, timeout=limit, env=env)
    except subprocess.TimeoutExpired:
        return f"> {limit:.0f} s"
    if r.returncode != 0:
        return "failed: " + (r.stderr.strip().splitlines() or ["?"])[-1][:70]
    return json.loads(r.stdout.strip().splitlines()[-1])


def run_child(path: Path, infile, cache: str, limit: float) -> dict | str:
    return _child(RUN_CHILD, [path, infile or ""], cache, limit)


# -- the values both programs read ---------------------------------------------------
def value_of(name: str) -> float:
    """A value in [0.1, 1) fixed by the quantity's name (for models without a .in)."""
    digest = hashlib.sha256(name.lower().encode()).digest()
    return 0.1 + 0.9 * int.from_bytes(digest[:6], "big") / 2.0 ** 48


IN_LINE = re.compile(r"^(\S+:?)\s+(\S+)\s+\S+\s+\|")


def filled_in_file(template: str) -> str:
    """Autolev's .in template with each value (from column 60) set by value_of."""
    out = []
    for line in template.splitlines():
        m = IN_LINE.match(line)
        if m and len(line) >= 60 and not line.startswith("-"):
            line = line[:59] + f" {value_of(m.group(2)):.15g}"
        out.append(line)
    return "\n".join(out) + "\n"


# -- ours ----------------------------------------------------------------------------
PER_EVAL_CHILD = r"""
import json, sys, warnings
import numpy as np
sys.path.insert(0, sys.argv[3])
warnings.simplefilter("ignore")
import autolev, large_models, rhs_speed
from autolev.loader import load_for_run
from autolev.engine import clibrary
from autolev.runtime.numerics import codegen
from autolev.engine.options import RunOptions
from autolev.runtime.numerics.prepare import prepare_command
model, notes = load_for_run(sys.argv[1])
infile = sys.argv[2] or None
commands = [c for c in model.code_commands if c.kind in ("dynamics", "ode")] \
    or list(model.code_commands) or [model.plain_dynamics()]
command = commands[-1]
prepared = prepare_command(model.snapshot_for(command), command,
                           RunOptions(infile=infile, missing_values="zero"))
system = prepared.system
values = prepared.inputs
def by_name(symbols):
    return np.array([large_models.value_of(str(s)) for s in symbols])
if infile:
    params = values.vector(system.params)
    x = values.vector(system.states) if system.nstate else by_name(system.states)
else:
    params = by_name(system.params)
    x = by_name(system.states)
system.set_parameters(params)
if system.loop is not None:
    us, alone = rhs_speed.CDriver().us_per_eval(system, x)
    print(json.dumps({"us": us, "rhs_us": alone, "what": "derivatives"}))
    raise SystemExit
import time
from autolev.runtime import symbols as S
defs = model.defs
accel = list(system.implicit_unknowns) + list(system.solved)
fixed = dict(system.aux_fixed)
inputs = {"t": [S.TIME], "x": system.states, "c": system.params,
          "s": system.specified, "a": accel}
with defs.as_of(command.definitions):
    whole = codegen.Program(inputs, system.output_exprs, defs, fixed).build()
    # as our runs evaluate it: what the constants alone give, once per parameter set
    per_state = codegen.Program(inputs, system.output_exprs, defs, fixed).build(
        lift_into="c")
    constants = codegen.Program({"p": system.params}, [e for _, e in per_state.lifted],
                                defs).build(False)
lifted = np.empty(len(per_state.lifted))
codegen.compile_python(constants)[0](params, lifted)
rest = [np.zeros(1), x]
tail = [np.zeros(len(system.specified)), by_name(accel), np.empty(len(system.output_exprs))]
def us_per_call(call, args):
    count, spent = 1, 0.0
    while spent < 0.3:
        count *= 2
        start = time.perf_counter()
        for _ in range(count):
            call(*args)
        spent = time.perf_counter() - start
    return spent / count * 1e6
whole_call = codegen.compile_c(whole, "autolev_eval")[0]
state_call = codegen.compile_c(per_state, "autolev_state")[0]
a = [*rest, params, *tail]
b = [*rest, np.concatenate([params, lifted]), *tail[:2], np.empty(len(tail[2]))]
whole_call(*a)
state_call(*b)
same = np.allclose(a[-1], b[-1], rtol=1e-9, atol=1e-12, equal_nan=True)
print(json.dumps({"us": us_per_call(whole_call, a), "us_state": us_per_call(state_call, b),
                  "what": "outputs", "agree": bool(same)}))
"""


def ours_per_eval(path: Path, infile, cache: str, limit: float) -> dict | str:
    return _child(PER_EVAL_CHILD, [path, infile or "", ROOT / "bench"], cache, limit)


# -- Autolev's ------------------------------------------------------------------------
C_DRIVER = r"""
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
int autolev_main(void);
void eqns1(void);
int main(int argc, char **argv)
{
    long count = atol(argv[1]);
    struct timespec a, b;
    autolev_main();
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (long i = 0; i < count; i++)
        eqns1();
    clock_gettime(CLOCK_MONOTONIC, &b);
    printf("AUTOLEV_BENCH %.9g\n", (b.tv_sec - a.tv_sec) + 1e-9 * (b.tv_nsec - a.tv_nsec));
    return 0;
}
"""

# Autolev's Fortran programs call SOLVE and KUTTA from Autolev's own library, which
# the corpus does not have: a Gaussian elimination in SOLVE's place (the timed eqns1
# solves the mass matrix with it) and a KUTTA that is never reached (the loop stops first)
FORTRAN_LIBRARY = """\
      SUBROUTINE SOLVE(N, A, B, X)
      IMPLICIT DOUBLE PRECISION (A-H, O-Z)
      INTEGER N, I, J, K, IP
      DIMENSION A(N,N), B(N), X(N)
      DO 30 K = 1, N
        IP = K
        DO 10 I = K + 1, N
          IF (ABS(A(I,K)) .GT. ABS(A(IP,K))) IP = I
10      CONTINUE
        DO 15 J = 1, N
          S = A(K,J)
          A(K,J) = A(IP,J)
          A(IP,J) = S
15      CONTINUE
        S = B(K)
        B(K) = B(IP)
        B(IP) = S
        DO 25 I = K + 1, N
          F = A(I,K) / A(K,K)
          DO 20 J = K, N
            A(I,J) = A(I,J) - F * A(K,J)
20        CONTINUE
          B(I) = B(I) - F * B(K)
25      CONTINUE
30    CONTINUE
      DO 50 I = N, 1, -1
        S = B(I)
        DO 40 J = I + 1, N
          S = S - A(I,J) * X(J)
40      CONTINUE
        X(I) = S / A(I,I)
50    CONTINUE
      RETURN
      END

      SUBROUTINE KUTTA(F, N, Y, T, H, AE, RE, K, *)
      STOP
      END
"""

FORTRAN_LOOP = """\
      CALL CPU_TIME(TBENCH0)
      DO 9991 IBENCH = 1, {count}
        CALL EQNS1(T, VAR, VARPBNCH, 0)
9991  CONTINUE
      CALL CPU_TIME(TBENCH1)
      WRITE(*,*) 'AUTOLEV_BENCH', TBENCH1 - TBENCH0
      STOP
"""


def _input_path(program: str) -> str | None:
    """The .in path the program opens (relative to where it runs)."""
    m = re.search(r"""strcpy\(fileName, "([^"]+\.in)"\)|FILE='([^']+\.in)'""", program)
    return (m.group(1) or m.group(2)) if m else None


def autolev_per_eval(program: Path, infile, workdir: Path) -> dict | str:
    """Autolev's eqns1 timed; the compile time of its program too."""
    from autolev.engine import clibrary
    text = program.read_text(errors="replace")
    where = _input_path(text)
    if where is None:
        return "no .in name found in the program"
    target = workdir / where
    target.parent.mkdir(parents=True, exist_ok=True)
    template = (Path(infile) if infile else program.with_suffix(".in"))
    if not template.exists():
        return f"no .in template ({template.name})"
    body = template.read_text(errors="replace")
    target.write_text(body if infile else filled_in_file(body))
    flags = list(clibrary.C_FLAGS)
    if program.suffix == ".c":
        compiler = clibrary.compiler()
        (workdir / "driver.c").write_text(C_DRIVER)
        shutil.copy(program, workdir / "program.c")
        start = time.perf_counter()
        r = subprocess.run([compiler, *flags, "-c", "-Dmain=autolev_main", "program.c"],
                           cwd=workdir, capture_output=True, text=True)
        compile_s = time.perf_counter() - start
        if r.returncode:
            return "compile failed: " + r.stderr[-200:]
        subprocess.run([compiler, *flags, "-o", "bench", "driver.c", "program.o", "-lm"],
                       cwd=workdir, check=True, capture_output=True)
        run = [str(workdir / "bench")]
    else:
        compiler = shutil.which("gfortran")
        if compiler is None:
            return "no gfortran"

        def with_loop(count: int) -> str:
            lines = text.splitlines()
            first = next(k for k, line in enumerate(lines) if "CALL KUTTA(" in line)
            declared = next(k for k, line in enumerate(lines)
                            if line.lstrip().upper().startswith("DIMENSION"))
            lines.insert(first, FORTRAN_LOOP.format(count=count).rstrip("\n"))
            lines.insert(declared + 1, "      DIMENSION        VARPBNCH(100)\n"
                         "      INTEGER          IBENCH")
            return "\n".join(lines) + "\n" + FORTRAN_LIBRARY
        (workdir / "program.f").write_text(with_loop(1))
        start = time.perf_counter()
        r = subprocess.run([compiler, "-O1", "-std=legacy", "-o", "bench", "program.f"],
                           cwd=workdir, capture_output=True, text=True)
        compile_s = time.perf_counter() - start
        if r.returncode:
            return "compile failed: " + r.stderr[-200:]
        run = None
    count, seconds = 16, 0.0
    while seconds < 0.3 and count < 1 << 26:
        count *= 4
        if run is None:
            (workdir / "program.f").write_text(with_loop(count))
            subprocess.run([compiler, "-O1", "-std=legacy", "-o", "bench", "program.f"],
                           cwd=workdir, check=True, capture_output=True)
            cmd = [str(workdir / "bench")]
        else:
            cmd = run + [str(count)]
        r = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True, timeout=600)
        m = re.search(r"AUTOLEV_BENCH\s+(\S+)", r.stdout)
        if m is None:
            return "run failed: " + (r.stdout + r.stderr)[-200:]
        seconds = float(m.group(1).replace("D", "E"))
    return {"us": seconds / count * 1e6, "compile": compile_s,
            "bytes": program.stat().st_size}


# -- the table -------------------------------------------------------------------------
def _cell(value, fmt: str, width: int) -> str:
    return f"{'-':>{width}s}" if value is None else f"{value:{width}{fmt}}"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corpus", default=os.environ.get(
        "AUTOLEV_CORPUS", str(Path.home() / ".cache" / "autolev-corpus")))
    ap.add_argument("--warm", type=int, default=2, help="warm runs per model")
    ap.add_argument("--limit", type=float, default=900.0, help="seconds per run")
    ap.add_argument("--only", help="models whose label contains this text")
    ap.add_argument("--no-autolev", action="store_true",
                    help="skip compiling and timing Autolev's programs")
    ap.add_argument("--json", help="write the measurements to this file")
    args = ap.parse_args(argv)
    corpus = Path(args.corpus)
    rows = []
    for label, rel, infile, program in MODELS + [EXAMPLE]:
        if args.only and args.only.lower() not in label.lower():
            continue
        path = corpus / rel
        if not path.exists():
            print(f"{label}: not in the corpus ({rel})", flush=True)
            continue
        infile = corpus / infile if infile else None
        cache = tempfile.mkdtemp(prefix="autolev-large-")
        row = {"label": label, "cold": run_child(path, infile, cache, args.limit)}
        warm = [run_child(path, infile, cache, args.limit) for _ in range(args.warm)]
        good = [w for w in warm if isinstance(w, dict)]
        row["warm"] = min(good, key=lambda w: w["total"]) if good else (warm or ["-"])[0]
        row["ours"] = ours_per_eval(path, infile, cache, args.limit)
        if program and not args.no_autolev:
            with tempfile.TemporaryDirectory(prefix="autolev-theirs-") as work:
                row["autolev"] = autolev_per_eval(corpus / program, infile, Path(work))
        shutil.rmtree(cache, ignore_errors=True)
        rows.append(row)
        print_row(row)
    print_summary(rows)
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1))
    plot(rows)
    return 0


HEAD = (f"{'model':36s} {'':4s} {'total s':>8s} {'import':>6s} {'load':>6s} {'build':>6s} "
        f"{'run':>6s} {'1st row':>7s} {'C KB':>7s} {'py KB':>7s} {'cc s':>6s} "
        f"{'RSS MB':>7s} {'cc MB':>6s}")


def print_row(row: dict) -> None:
    if not getattr(print_row, "headed", False):
        print(HEAD)
        print_row.headed = True
    for kind in ("cold", "warm"):
        d = row[kind]
        if not isinstance(d, dict):
            print(f"{row['label']:36s} {kind:4s} {d}")
            continue
        print(f"{row['label']:36s} {kind:4s} {d['total']:8.2f} {d['import']:6.2f} "
              f"{d['load']:6.2f} {d['build']:6.2f} {d['run']:6.2f} "
              f"{_cell(d['first_row'], '.2f', 7)} {d['code_c'] / 1e3:7.0f} "
              f"{d['code_python'] / 1e3:7.0f} {d['compile']:6.2f} {d['rss_mb']:7.0f} "
              f"{d['cc_rss_mb']:6.0f}", flush=True)
    ours, theirs = row["ours"], row.get("autolev")
    text = (f"{'':36s} us/eval ours {ours['us']:.2f} ({ours['what']}"
            + (f"; without the solve {ours['rhs_us']:.2f})" if "rhs_us" in ours else
               f"; {ours['us_state']:.2f} with the constants' parts evaluated once"
               + ("" if ours["agree"] else ", DISAGREEING") + ")")
            if isinstance(ours, dict) else f"{'':36s} us/eval ours: {ours}")
    if isinstance(theirs, dict):
        text += (f", Autolev's {theirs['us']:.2f} (ours/theirs "
                 f"{ours['us'] / theirs['us']:.2f}); Autolev's program "
                 f"{theirs['bytes'] / 1e3:.0f} KB compiles in {theirs['compile']:.1f} s"
                 if isinstance(ours, dict) else f", Autolev's {theirs['us']:.2f}")
    elif theirs is not None:
        text += f"; Autolev's: {theirs}"
    print(text, flush=True)


def print_summary(rows: list) -> None:
    def ok(kind, key):
        return [r for r in rows if isinstance(r[kind], dict) and r[kind].get(key) is not None]
    warm = ok("warm", "total")
    cold = ok("cold", "total")
    if warm:
        slow = max(warm, key=lambda r: r["warm"]["total"])
        print(f"warm: slowest {slow['warm']['total']:.2f} s ({slow['label']}); "
              f"{sum(r['warm']['total'] < 1 for r in warm)}/{len(warm)} under 1 s")
    if cold:
        firsts = [r for r in cold if r["cold"]["first_row"] is not None]
        slow = max(cold, key=lambda r: r["cold"]["total"])
        print(f"cold: slowest {slow['cold']['total']:.1f} s to the last row "
              f"({slow['label']}); {sum(r['cold']['first_row'] < 10 for r in firsts)}"
              f"/{len(firsts)} under 10 s to the first row")
        big = max(cold, key=lambda r: r["cold"]["rss_mb"])
        print(f"peak RSS: {big['cold']['rss_mb']:.0f} MB ({big['label']})")
    pairs = [r for r in rows if isinstance(r["ours"], dict)
             and isinstance(r.get("autolev"), dict)]
    for r in pairs:
        ours, theirs = r["ours"], r["autolev"]["us"]
        text = (f"per evaluation, {r['label']}: Autolev's {theirs:.2f} us; ours "
                f"{ours['us']:.2f} us ({theirs / ours['us']:.2f}x Autolev's speed)")
        if "us_state" in ours:
            text += (f", per state {ours['us_state']:.2f} us "
                     f"({theirs / ours['us_state']:.2f}x)")
        print(text)


def plot(rows: list) -> None:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    rows = [r for r in rows if isinstance(r["cold"], dict) and isinstance(r["warm"], dict)]
    if not rows:
        return
    stages = ("import", "load", "build", "run")
    fig, ax = plt.subplots(figsize=(9, 0.6 * len(rows) + 1.5))
    for k, r in enumerate(rows):
        for offset, kind in ((0.2, "cold"), (-0.2, "warm")):
            left = 0.0
            for n, stage in enumerate(stages):
                width = max(r[kind][stage], 0.0)
                ax.barh(k + offset, width, left=left, height=0.35, color=f"C{n}",
                        label=stage if k == 0 and kind == "cold" else None,
                        alpha=1.0 if kind == "cold" else 0.55)
                left += width
    ax.set_yticks(range(len(rows)), [r["label"] for r in rows], fontsize=8)
    ax.set_xscale("symlog", linthresh=1.0)
    ax.axvline(1.0, color="k", lw=0.6, ls=":")
    ax.set_xlabel("seconds (each model: cold, the lower bar; warm, the light upper bar)")
    ax.legend(loc="lower right", fontsize=8)
    ax.invert_yaxis()
    fig.tight_layout()
    out = ROOT / "bench" / "out"
    out.mkdir(exist_ok=True)
    fig.savefig(out / "large_models.png", dpi=110)
    print(f"plot: {out / 'large_models.png'}")


if __name__ == "__main__":
    sys.exit(main())
