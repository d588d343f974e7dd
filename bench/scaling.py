#!/usr/bin/env python3
"""How forming and simulating Kane's equations scales with the size of the model,
against sympy.physics.mechanics.KanesMethod on the same systems.

    python bench/scaling.py                  # the full run (about 10-15 minutes)
    python bench/scaling.py --quick          # small models only (a smoke run)
    python bench/scaling.py --limit 60       # seconds allowed per run / per sympy stage
    python bench/scaling.py --no-sympy       # our pipeline only

Two families of models from bench/chains.py: the planar n-link pendulum (n = 2 ... 32)
and the 3-D chain of n bodies in ball joints (n = 1 ... 8).  Each model runs through
the real pipeline in its own subprocess, with a fresh, empty AUTOLEV_CACHE so that the
C compilation is cold:

    form       autolev.load(path): translate the .al and form Kane's equations
    M,f        the first access of m.mass_matrix and m.forcing (taken from the
               equations on demand)
    DAG        Z intermediates (m.defs.z_count), the definitions the equations and
               kinematical equations need, and their total sympy count_ops
    compile    NumericSystem(m): generate the C right-hand side and compile it
    call       microseconds per Python call of NumericSystem.derivatives(t, x)
    simulate   m.simulate(method="dop853") with RELERR = ABSERR = 1e-8 over 10 s
               (planar) or 2 s (3-D), compiled loop: integration seconds and wall time

Side by side, the same system built independently with sympy's KanesMethod
(dynamicsymbols, orient_axis / orient_body_fixed('123'), v2pt_theory, RigidBody):
form time, `sm.lambdify(..., cse=True)` of mass_matrix_full and forcing_full, and
microseconds per call of the lambdified M, f plus np.linalg.solve.  Our runs are
limited to --limit seconds as a whole; each sympy stage gets --limit seconds and
prints "> limit" when killed (larger models of that family are then not tried).
PyDy's Cython route is timed too when `import pydy` works.

Printed: one table per family, the fitted growth exponents of form time (log-log least
squares over the finished n >= 4), and PASS/FAIL lines for the targets.  With
matplotlib importable, bench/out/scaling.png shows form time against n (log-log).
The exit status is 1 when one of our runs crashed or was killed, else 0.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import queue
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

PLANAR_N = (2, 4, 8, 12, 16, 24, 32)
CHAIN3D_N = (1, 2, 3, 4, 5, 6, 8)
QUICK_PLANAR_N = (2, 4, 8)
QUICK_CHAIN3D_N = (1, 2, 3)
TFINAL = {"planar": 10.0, "chain3d": 2.0}
TOLERANCE = 1e-8
MARK = "@@ "          # prefix of the children's report lines on stdout

# the INPUT values of bench/chains.py, by family (parameter name -> value)
PARAMETERS = {"planar": {"G": 9.81, "L": 0.5, "M": 1.0},
              "chain3d": {"G": 9.81, "IXX": 0.02, "IYY": 0.03, "IZZ": 0.01, "L": 0.5,
                          "M": 1.0}}


def initial_state(kind: str, n: int) -> tuple[list, list]:
    """The initial (q, u) of bench/chains.py's INPUT lines, in radians."""
    if kind == "planar":
        return [math.radians(10 + 5 * (i % 4)) for i in range(1, n + 1)], [0.0] * n
    return ([math.radians(5 + 3 * (i % 5)) for i in range(1, 3 * n + 1)],
            [0.1] * (3 * n))


# -- the same systems in sympy.physics.mechanics -----------------------------------------
def sympy_planar(n: int):
    """The planar n-link pendulum with KanesMethod: link i turns by q_i about the z
    axis of the link before it, u_i = q_i', mass center at L/2 and next joint at L
    along the link's x axis, central inertia M L^2/12 about z, gravity G along N.x.
    Returns (KanesMethod with its equations formed, q, u, [G, L, M])."""
    import sympy as sm
    import sympy.physics.mechanics as me
    q = me.dynamicsymbols(f"q1:{n + 1}")
    u = me.dynamicsymbols(f"u1:{n + 1}")
    G, L, M = sm.symbols("G L M")
    N = me.ReferenceFrame("N")
    joint = me.Point("NO")
    joint.set_vel(N, 0)
    parent = N
    bodies, loads = [], []
    for i in range(n):
        B = me.ReferenceFrame(f"B{i + 1}")
        B.orient_axis(parent, parent.z, q[i])
        B.set_ang_vel(parent, u[i] * N.z)
        center = joint.locatenew(f"B{i + 1}O", L / 2 * B.x)
        center.v2pt_theory(joint, N, B)
        inertia = me.inertia(B, 0, 0, M * L ** 2 / 12)
        bodies.append(me.RigidBody(f"body{i + 1}", center, B, M, (inertia, center)))
        loads.append((center, M * G * N.x))
        nxt = joint.locatenew(f"P{i + 1}", L * B.x)
        nxt.v2pt_theory(joint, N, B)
        parent, joint = B, nxt
    kd = [qi.diff() - ui for qi, ui in zip(q, u)]
    km = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    km.kanes_equations(bodies, loads)
    return km, q, u, [G, L, M]


def sympy_chain3d(n: int):
    """The 3-D chain: body i oriented relative to the body before by body-fixed 1-2-3
    angles, u's the measure numbers in body i of its angular velocity relative to the
    body before, mass center at L/2 and next joint at L along the body's z axis,
    central inertia diag(IXX, IYY, IZZ), gravity -G along N.z.
    Returns (KanesMethod with its equations formed, q, u, [G, IXX, IYY, IZZ, L, M])."""
    import sympy as sm
    import sympy.physics.mechanics as me
    q = me.dynamicsymbols(f"q1:{3 * n + 1}")
    u = me.dynamicsymbols(f"u1:{3 * n + 1}")
    G, IXX, IYY, IZZ, L, M = sm.symbols("G IXX IYY IZZ L M")
    N = me.ReferenceFrame("N")
    joint = me.Point("NO")
    joint.set_vel(N, 0)
    parent = N
    bodies, loads, kd = [], [], []
    for i in range(n):
        qi, ui = q[3 * i:3 * i + 3], u[3 * i:3 * i + 3]
        B = me.ReferenceFrame(f"B{i + 1}")
        B.orient_body_fixed(parent, qi, "123")
        w = B.ang_vel_in(parent)            # in terms of the q' (from the orientation)
        kd += [w.dot(B.x) - ui[0], w.dot(B.y) - ui[1], w.dot(B.z) - ui[2]]
        B.set_ang_vel(parent, ui[0] * B.x + ui[1] * B.y + ui[2] * B.z)
        center = joint.locatenew(f"B{i + 1}O", L / 2 * B.z)
        center.v2pt_theory(joint, N, B)
        inertia = me.inertia(B, IXX, IYY, IZZ)
        bodies.append(me.RigidBody(f"body{i + 1}", center, B, M, (inertia, center)))
        loads.append((center, -M * G * N.z))
        nxt = joint.locatenew(f"P{i + 1}", L * B.z)
        nxt.v2pt_theory(joint, N, B)
        parent, joint = B, nxt
    km = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    km.kanes_equations(bodies, loads)
    return km, q, u, [G, IXX, IYY, IZZ, L, M]


SYMPY_BUILDERS = {"planar": sympy_planar, "chain3d": sympy_chain3d}


# -- timing helpers -----------------------------------------------------------------------
def per_call_us(fn, budget: float = 0.5, batches: int = 15) -> float:
    """Median over `batches` batches of the microseconds per call of fn()."""
    count = 1
    while True:                             # calibrate: a batch of about budget/batches
        t0 = time.perf_counter()
        for _ in range(count):
            fn()
        dt = time.perf_counter() - t0
        if dt > budget / batches / 4 or count >= 1 << 20:
            break
        count *= 4
    count = max(1, int(count * (budget / batches) / max(dt, 1e-9)))
    per = []
    for _ in range(batches):
        t0 = time.perf_counter()
        for _ in range(count):
            fn()
        per.append((time.perf_counter() - t0) / count)
    per.sort()
    return per[len(per) // 2] * 1e6


def needed_definitions(m, mass_matrix, forcing) -> list:
    """The definitions (Z's and user definitions) the mass matrix, the forcing and the
    kinematical equations need, dependencies first."""
    exprs = list(mass_matrix) + list(forcing) + list(m.kinematical_equations.values())
    roots = set()
    for e in exprs:
        roots |= e.free_symbols
    return m.defs.evaluation_order(roots)


# -- the children (run in subprocesses) ---------------------------------------------------
def _emit(**event) -> None:
    print(MARK + json.dumps(event), flush=True)


def child_ours(kind: str, n: int) -> None:
    import numpy as np
    import sympy as sm
    import chains
    import autolev
    from autolev.runtime.numerics.system import NumericSystem
    with tempfile.TemporaryDirectory() as tmp:
        path = chains.write(kind, n, tmp, tfinal=TFINAL[kind])
        _emit(begin="form")
        t0 = time.perf_counter()
        m = autolev.load(path)
        _emit(end="form", seconds=time.perf_counter() - t0, coords=len(m.coordinates))
        _emit(begin="equations")            # M and f are taken from ZERO on demand
        t0 = time.perf_counter()
        mm, f = m.mass_matrix, m.forcing
        _emit(end="equations", seconds=time.perf_counter() - t0)
        _emit(begin="dag")
        needed = needed_definitions(m, mm, f)
        ops = sum(sm.count_ops(m.defs.rhs[s]) for s in needed)
        ops += sum(sm.count_ops(e) for e in list(mm) + list(f))
        _emit(end="dag", z=m.defs.z_count, defs=len(needed), ops=int(ops),
              shape=list(mm.shape))
        _emit(begin="compile")
        t0 = time.perf_counter()
        ns = NumericSystem(m.snapshot_for(m.plain_dynamics()))
        _emit(end="compile", seconds=time.perf_counter() - t0,
              backend=ns.rhs_function.backend)
        _emit(begin="simulate")
        t0 = time.perf_counter()
        r = m.simulate(method="dop853", RELERR=TOLERANCE, ABSERR=TOLERANCE)
        wall = time.perf_counter() - t0
        _emit(end="simulate", wall=wall, seconds=r.stats.get("seconds"),
              evaluations=r.stats.get("evaluations"), steps=r.stats.get("steps"),
              ok=r.ok, failure=r.failure, build=r.stats.get("build_seconds"))
        _emit(begin="call")
        system = r.system
        x = np.array(r.states[0])
        us = per_call_us(lambda: system.derivatives(0.0, x))
        _emit(end="call", us=us)


def child_sympy(kind: str, n: int) -> None:
    import numpy as np
    import sympy as sm
    _emit(begin="form")
    t0 = time.perf_counter()
    km, q, u, p = SYMPY_BUILDERS[kind](n)
    _emit(end="form", seconds=time.perf_counter() - t0)
    _emit(begin="lambdify")
    t0 = time.perf_counter()
    fn = sm.lambdify((q, u, p), [km.mass_matrix_full, km.forcing_full], cse=True)
    _emit(end="lambdify", seconds=time.perf_counter() - t0)
    _emit(begin="call")
    q0, u0 = initial_state(kind, n)
    q0, u0 = np.array(q0), np.array(u0)
    pv = np.array([PARAMETERS[kind][s.name] for s in p])
    us = per_call_us(lambda: np.linalg.solve(*fn(q0, u0, pv)))
    _emit(end="call", us=us)
    try:
        import pydy.codegen.ode_function_generators as gen
    except ImportError:
        _emit(pydy="not installed")
        return
    _emit(begin="pydy")
    t0 = time.perf_counter()
    rhs = gen.generate_ode_function(km.forcing_full, q, u, p,
                                    mass_matrix=km.mass_matrix_full, generator="cython")
    seconds = time.perf_counter() - t0
    x0 = np.concatenate([q0, u0])
    _emit(end="pydy", seconds=seconds, us=per_call_us(lambda: rhs(x0, 0.0, pv)))


# -- running children under a time limit --------------------------------------------------
def run_child(args: list, limit: float, env=None, per_stage: bool = False) -> dict:
    """Run this script as `--child ...args`, collecting its stage reports.  The run
    (or, with per_stage, each stage) is killed after `limit` seconds: the result
    then has "killed" = the stage running.  "error" holds the end of stderr when the
    child failed."""
    cmd = [sys.executable, str(Path(__file__).resolve()), "--child", *args]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, env=env, cwd=str(ROOT))
    lines: queue.Queue = queue.Queue()
    err: list = []

    def pump_out():
        for line in proc.stdout:
            lines.put(line)
        lines.put(None)

    def pump_err():
        err.append(proc.stderr.read())

    threads = [threading.Thread(target=pump_out, daemon=True),
               threading.Thread(target=pump_err, daemon=True)]
    for th in threads:
        th.start()
    out: dict = {}
    stage = "start"
    deadline = time.monotonic() + limit
    while True:
        try:
            line = lines.get(timeout=max(0.0, deadline - time.monotonic()))
        except queue.Empty:
            proc.kill()
            out["killed"] = stage
            break
        if line is None:
            break
        if not line.startswith(MARK):
            continue
        event = json.loads(line[len(MARK):])
        if "begin" in event:
            stage = event["begin"]
            if per_stage:
                deadline = time.monotonic() + limit
        elif "end" in event:
            out[event["end"]] = event
        else:
            out.update(event)
    proc.wait()
    for th in threads:
        th.join(timeout=5)
    if proc.returncode != 0 and "killed" not in out:
        out["error"] = "".join(err).strip()[-1500:] or f"exit status {proc.returncode}"
    return out


# -- reporting ----------------------------------------------------------------------------
def describe_run() -> str:
    """What the numbers were measured on: the source's commit (and whether src/ had
    uncommitted changes), the CPU count and the load average at the start."""
    def git(*args):
        try:
            r = subprocess.run(["git", *args], cwd=str(ROOT), capture_output=True,
                               text=True, timeout=10)
        except (OSError, subprocess.SubprocessError):
            return None
        return r.stdout.strip() if r.returncode == 0 else None
    commit = git("rev-parse", "--short", "HEAD")
    dirty = git("--no-optional-locks", "status", "--porcelain", "--", "src")
    where = ("unknown source version" if commit is None else
             f"commit {commit}" + (" + uncommitted changes in src/" if dirty else ""))
    load = ", ".join(f"{x:.2f}" for x in os.getloadavg()) if hasattr(os, "getloadavg") \
        else "n/a"
    return (f"autolev at {where}; Python {sys.version.split()[0]}; {os.cpu_count()} CPUs; "
            f"load average {load}")


LEGEND = """columns: form = autolev.load (translate + Kane's equations); M,f = first access
of m.mass_matrix and m.forcing; Z = Z intermediates made; defs, ops = definitions the
equations need and their total count_ops; gen+cc = NumericSystem(m) with an empty
compile cache; us/call = NumericSystem.derivatives from Python (median); integ =
integration seconds of m.simulate (DOP853, compiled loop, 1e-8); sim wall = the whole
simulate() call; sympy: KanesMethod form, lambdify(cse=True) of M_full and f_full,
us per call of those plus np.linalg.solve"""


def fit_exponent(points: list) -> float | None:
    """Slope of log(seconds) against log(n), least squares, over n >= 4."""
    pts = [(math.log(n), math.log(s)) for n, s in points if n >= 4 and s and s > 0]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx if sxx else None


def _stage(res: dict, stage: str, key: str, fmt: str, limit: float) -> str:
    if res is None:
        return "-"
    if stage in res and res[stage].get(key) is not None:
        return format(res[stage][key], fmt)
    if res.get("killed") == stage:
        return f">{limit:g}s"
    if res.get("skipped"):
        return "skip"
    if res.get("killed") or res.get("error"):
        return "n/a"
    return "-"


def print_table(kind: str, ns: tuple, ours: dict, theirs: dict, limit: float) -> None:
    title = {"planar": "planar n-link pendulum (DOP853, 10 s)",
             "chain3d": "3-D chain of n bodies in ball joints (DOP853, 2 s)"}[kind]
    print(f"\n{title}")
    head = ("n", "dof", "form s", "M,f s", "Z", "defs", "ops", "M", "gen+cc s",
            "us/call", "integ s", "sim wall s", "| sympy form s", "lambdify s", "us/call")
    widths = (3, 4, 8, 6, 6, 6, 8, 6, 9, 8, 8, 10, 14, 10, 8)
    print(" ".join(h.rjust(w) for h, w in zip(head, widths)))
    for n in ns:
        o, s = ours.get(n), theirs.get(n)
        dag = (o or {}).get("dag", {})
        shape = dag.get("shape")
        row = (str(n), str((o or {}).get("form", {}).get("coords", "-")),
               _stage(o, "form", "seconds", ".3f", limit),
               _stage(o, "equations", "seconds", ".3f", limit),
               str(dag.get("z", "-")), str(dag.get("defs", "-")), str(dag.get("ops", "-")),
               f"{shape[0]}x{shape[1]}" if shape else "-",
               _stage(o, "compile", "seconds", ".3f", limit),
               _stage(o, "call", "us", ".2f", limit),
               _stage(o, "simulate", "seconds", ".4f", limit),
               _stage(o, "simulate", "wall", ".3f", limit),
               "| " + _stage(s, "form", "seconds", ".3f", limit).rjust(12),
               _stage(s, "lambdify", "seconds", ".3f", limit),
               _stage(s, "call", "us", ".1f", limit))
        print(" ".join(c.rjust(w) for c, w in zip(row, widths)))
    for n in ns:
        for who, res in (("ours", ours.get(n)), ("sympy", theirs.get(n))):
            if res and res.get("error"):
                print(f"  {kind} {n} ({who}) FAILED:\n    "
                      + res["error"].replace("\n", "\n    "))
            if who == "ours" and res and "simulate" in res and not res["simulate"]["ok"]:
                print(f"  {kind} {n}: the simulation failed: {res['simulate']['failure']}")


def form_points(results: dict) -> list:
    return [(n, r["form"]["seconds"]) for n, r in sorted(results.items())
            if r and "form" in r]


def plot(path: Path, sizes: dict, all_ours: dict, all_theirs: dict, limit: float) -> bool:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.ticker import NullFormatter, ScalarFormatter
    except ImportError:
        return False
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, kind in zip(axes, ("planar", "chain3d")):
        for label, res, style in (("autolev (Z engine)", all_ours[kind], "o-"),
                                  ("sympy KanesMethod", all_theirs[kind], "s--")):
            pts = form_points(res)
            if pts:
                ax.loglog(*zip(*pts), style, label=label)
            killed = [n for n, r in res.items() if r and r.get("killed") == "form"]
            if killed:
                ax.loglog(killed, [limit] * len(killed), "rx", ms=9,
                          label=f"{label}: > {limit:g} s limit")
        ax.set_title({"planar": "planar n-link pendulum",
                      "chain3d": "3-D chain (ball joints)"}[kind])
        ax.set_xticks(sizes[kind])
        ax.xaxis.set_major_formatter(ScalarFormatter())
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_xlabel("n (links)" if kind == "planar" else "n (bodies)")
        ax.set_ylabel("form time (s)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def check(targets: list, name: str, value, ok) -> None:
    """Record a target's line: PASS / FAIL, or NOT RUN when there is no number."""
    if value is None:
        targets.append(("NOT RUN", name, "no measurement"))
    else:
        targets.append(("PASS" if ok(value) else "FAIL", name, value))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="small models only")
    ap.add_argument("--limit", type=float, default=120.0,
                    help="seconds per run of ours, per stage of sympy's (default 120)")
    ap.add_argument("--no-sympy", action="store_true", help="skip sympy's KanesMethod")
    ap.add_argument("--child", nargs=3, metavar=("WHO", "KIND", "N"), help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.child:
        who, kind, n = args.child
        (child_ours if who == "ours" else child_sympy)(kind, int(n))
        return 0

    sizes = {"planar": QUICK_PLANAR_N if args.quick else PLANAR_N,
             "chain3d": QUICK_CHAIN3D_N if args.quick else CHAIN3D_N}
    print(describe_run(), flush=True)
    start = time.perf_counter()
    all_ours: dict = {"planar": {}, "chain3d": {}}
    all_theirs: dict = {"planar": {}, "chain3d": {}}
    pydy_note = None
    for kind in ("planar", "chain3d"):
        sympy_stopped = False
        for n in sizes[kind]:
            with tempfile.TemporaryDirectory(prefix="autolev-cache-") as cache:
                env = dict(os.environ, AUTOLEV_CACHE=cache, PYTHONHASHSEED="0")
                res = run_child(["ours", kind, str(n)], args.limit, env)
            all_ours[kind][n] = res
            status = ("killed in " + res["killed"] if "killed" in res else
                      "ERROR" if "error" in res else
                      f"form {res['form']['seconds']:.2f} s")
            print(f"[{time.perf_counter() - start:6.0f} s] ours  {kind:7s} {n:2d}: {status}",
                  flush=True)
            if args.no_sympy:
                continue
            if sympy_stopped:
                all_theirs[kind][n] = {"skipped": True}
                continue
            res = run_child(["sympy", kind, str(n)], args.limit, per_stage=True)
            all_theirs[kind][n] = res
            if "pydy" in res and isinstance(res["pydy"], str):
                pydy_note = res["pydy"]
            status = ("killed in " + res["killed"] if "killed" in res else
                      "ERROR" if "error" in res else
                      f"form {res['form']['seconds']:.2f} s")
            print(f"[{time.perf_counter() - start:6.0f} s] sympy {kind:7s} {n:2d}: {status}",
                  flush=True)
            if res.get("killed") in ("start", "form"):
                sympy_stopped = True        # larger ones only take longer

    print("\n" + LEGEND)
    for kind in ("planar", "chain3d"):
        print_table(kind, sizes[kind], all_ours[kind], all_theirs[kind], args.limit)
    if args.no_sympy:
        print("\nsympy KanesMethod: skipped (--no-sympy)")
    else:
        print("\n'skip': not run, a smaller model already exceeded the limit in that stage")
        rows = [(k, n, r["pydy"]) for k in all_theirs for n, r in all_theirs[k].items()
                if r and isinstance(r.get("pydy"), dict)]
        if rows:
            print("PyDy (Cython): " + ", ".join(
                f"{k} {n}: generate {p['seconds']:.2f} s, {p['us']:.1f} us/call"
                for k, n, p in rows))
        else:
            print(f"PyDy: skipped ({pydy_note or 'not installed'})")

    print("\nform-time growth exponent (log-log least squares over finished n >= 4):")
    exps = {}
    for kind in ("planar", "chain3d"):
        for who, res in (("ours", all_ours[kind]), ("sympy", all_theirs[kind])):
            e = fit_exponent(form_points(res))
            exps[kind, who] = e
            used = [n for n, _ in form_points(res) if n >= 4]
            tail = fit_exponent(form_points(res)[-3:]) if len(used) > 3 else None
            print(f"  {kind:7s} {who:5s}: "
                  + (f"n^{e:.2f}  (n = {', '.join(map(str, used))})" if e is not None
                     else "n/a (fewer than two finished sizes with n >= 4)")
                  + (f"; n^{tail:.2f} over the three largest" if tail is not None else ""))

    def got(kind, n, stage, key="seconds"):
        return all_ours[kind].get(n, {}).get(stage, {}).get(key)

    targets: list = []
    check(targets, "planar 16 form < 2 s", got("planar", 16, "form"), lambda v: v < 2)
    check(targets, "planar 32 form < 15 s", got("planar", 32, "form"), lambda v: v < 15)
    check(targets, "3-D 6-body form < 5 s", got("chain3d", 6, "form"), lambda v: v < 5)
    check(targets, "planar form growth <= n^3", exps["planar", "ours"], lambda v: v <= 3)
    check(targets, "3-D form growth <= n^3", exps["chain3d", "ours"], lambda v: v <= 3)
    check(targets, "planar 16 generate+compile <= 1 s", got("planar", 16, "compile"),
          lambda v: v <= 1)
    print("\ntargets:")
    for verdict, name, value in targets:
        shown = f"{value:.3f}" if isinstance(value, float) else value
        print(f"  {verdict:7s} {name}  ({shown})")

    png = HERE / "out" / "scaling.png"
    if plot(png, sizes, all_ours, all_theirs, args.limit):
        print(f"\nwrote {png.relative_to(ROOT)}")
    else:
        print("\nmatplotlib not importable: no plot written")
    print(f"total {time.perf_counter() - start:.0f} s")
    broken = [(k, n) for k in all_ours for n, r in all_ours[k].items()
              if "error" in r or "killed" in r]
    if broken:
        print("our pipeline failed or was killed for: "
              + ", ".join(f"{k} {n}" for k, n in broken))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
