#!/usr/bin/env python3
"""Cost of one right-hand-side evaluation, from Python and in C, and of a whole
integration, against sympy's lambdify route.

    python bench/rhs_speed.py              # all models (a few minutes)
    python bench/rhs_speed.py --quick      # the small models and the planar 8-link run
    python bench/rhs_speed.py --limit 60   # seconds per sympy stage (default 60)
    python bench/rhs_speed.py --no-sympy   # our numbers only

Per model (the double pendulum of autolev_examples/, and bench/chains.py's planar 2,
8, 16 links and 3-D chains of 4 and 8 bodies), microseconds per evaluation:

    python     median over many calls of NumericSystem.derivatives(t, x), the
               Python-callable right-hand side
    C          autolev_derivatives (generated code plus the LU solve of the mass
               matrix) called in a loop by a small C driver compiled here, so without
               any Python in between (median of 7 timed loops)
    C rhs      the generated autolev_rhs alone (rates, mass matrix, forcing; no solve)
    loop       estimated from the compiled DOP853 loop: integration seconds /
               right-hand-side evaluations over a 50 s run with INTEGSTP = 5 (few
               printed rows; includes the integrator's own arithmetic)
    py/C       python / C (and python / loop)
    sympy      sympy's KanesMethod mass_matrix_full and forcing_full lambdified with
               cse=True, plus np.linalg.solve (each sympy stage in a subprocess killed
               after --limit seconds)

End to end, the planar 8-link pendulum over 10 s with DOP853 at RELERR = ABSERR =
1e-8 (the model's INTEGSTP = 0.1 is the largest step and the print interval): the
integration seconds (best of 5 runs, 2 for sympy's) of m.simulate(compiled=True)
(loop in C), compiled=False (scipy's DOP853 stepping, our C right-hand side), and
sympy lambdify + scipy solve_ivp DOP853 at the same tolerances, with the largest
differences of their states at T = 1, 5 and 10 s.  The pendulum is chaotic: a
reference run at 1e-12 shows how far the 1e-8 runs themselves are from the motion.

PASS/FAIL lines for the targets follow; with matplotlib importable,
bench/out/rhs_speed.png shows the per-call costs.  The exit status is 1 when a run
of ours failed or the integrations disagree by more than 1e-6 at T = 5 s, else 0.
Timings are wall-clock: run on an otherwise idle machine.
"""
from __future__ import annotations

import argparse
import ctypes
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

import chains                                   # noqa: E402
import scaling                                  # noqa: E402

EXAMPLE = ROOT / "autolev_examples" / "double_pendulum.al"
MODELS = [("double pendulum", None), ("planar", 2), ("planar", 8), ("planar", 16),
          ("chain3d", 4), ("chain3d", 8)]
QUICK_MODELS = MODELS[:3]
TOLERANCE = 1e-8

DRIVER_SOURCE = r"""
#include <time.h>
typedef int (*al_derivatives)(void *ctx, double t, const double *x, double *xdot);

/* seconds taken by `count` calls of fn(ctx, t, x, xdot); *status: their statuses ORed */
double al_bench_loop(void *fn, void *ctx, double t, const double *x, double *xdot,
                     long count, int *status)
{
    al_derivatives f = (al_derivatives)fn;
    struct timespec a, b;
    int s = 0;
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (long i = 0; i < count; i++)
        s |= f(ctx, t, x, xdot);
    clock_gettime(CLOCK_MONOTONIC, &b);
    *status = s;
    return (double)(b.tv_sec - a.tv_sec) + 1e-9 * (double)(b.tv_nsec - a.tv_nsec);
}

typedef void (*al_rhs)(const double *t, const double *x, const double *c, const double *s,
                       double *w, double *out);

/* seconds taken by `count` calls of the generated autolev_rhs alone (no solve) */
double al_bench_rhs(void *fn, const double *t, const double *x, const double *c,
                    const double *s, double *w, double *out, long count)
{
    al_rhs f = (al_rhs)fn;
    struct timespec a, b;
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (long i = 0; i < count; i++)
        f(t, x, c, s, w, out);
    clock_gettime(CLOCK_MONOTONIC, &b);
    return (double)(b.tv_sec - a.tv_sec) + 1e-9 * (double)(b.tv_nsec - a.tv_nsec);
}
"""


class CDriver:
    """The timing loop above, compiled once into a temporary folder."""

    def __init__(self):
        from autolev.engine import clibrary
        cc = clibrary.compiler()
        if cc is None:
            raise RuntimeError("no C compiler: the C timings need one")
        self._tmp = tempfile.TemporaryDirectory(prefix="autolev-bench-")
        src = Path(self._tmp.name) / "driver.c"
        lib = Path(self._tmp.name) / "driver.so"
        src.write_text(DRIVER_SOURCE)
        subprocess.run([cc, "-O2", "-shared", "-fPIC", "-o", str(lib), str(src)],
                       check=True, capture_output=True, text=True)
        lib = ctypes.CDLL(str(lib))
        P = ctypes.c_void_p
        self._loop = lib.al_bench_loop
        self._loop.argtypes = [P, P, ctypes.c_double, P, P, ctypes.c_long,
                               ctypes.POINTER(ctypes.c_int)]
        self._loop.restype = ctypes.c_double
        self._rhs = lib.al_bench_rhs
        self._rhs.argtypes = [P] * 7 + [ctypes.c_long]
        self._rhs.restype = ctypes.c_double

    @staticmethod
    def _median_us(run, budget: float, repeats: int) -> float:
        """Median microseconds per call, run(count) giving the seconds of count calls."""
        count = 16
        while True:
            dt = run(count)
            if dt > budget / repeats / 4 or count > 1 << 26:
                break
            count *= 4
        count = max(1, int(count * budget / repeats / max(dt, 1e-9)))
        times = sorted(run(count) / count for _ in range(repeats))
        return times[len(times) // 2] * 1e6

    def us_per_eval(self, system, x, t: float = 0.0, budget: float = 0.3,
                    repeats: int = 7) -> tuple[float, float]:
        """Median microseconds per C evaluation at (t, x) of the system's compiled
        autolev_derivatives (generated code and LU solve), and of the generated
        autolev_rhs alone (rates, mass matrix and forcing: no solve)."""
        loop = system.loop
        fn = ctypes.cast(loop._deriv, ctypes.c_void_p).value
        ctx = ctypes.addressof(loop.ctx)
        x = np.ascontiguousarray(x, dtype=float)
        xdot = np.empty(loop.n)
        status = ctypes.c_int(0)
        whole = self._median_us(
            lambda k: self._loop(fn, ctx, t, x.ctypes.data, xdot.ctypes.data, k,
                                 ctypes.byref(status)), budget, repeats)
        if status.value:
            raise RuntimeError(f"the mass matrix is singular at the timing state {x}")
        expected = system.derivatives(t, x)
        if not np.allclose(xdot, expected, rtol=1e-12, atol=0):
            raise RuntimeError("the driver's derivatives differ from the system's")
        rhs = ctypes.cast(loop.lib.autolev_rhs, ctypes.c_void_p).value
        tt = np.array([t])
        out = np.empty_like(loop.out_buffer)
        ptrs = (rhs, tt.ctypes.data, x.ctypes.data, loop.ctx.c, loop.ctx.s, loop.ctx.w,
                out.ctypes.data)
        alone = self._median_us(lambda k: self._rhs(*ptrs, k), budget, repeats)
        return whole, alone


def load_model(kind, n, folder):
    import autolev
    path = EXAMPLE if n is None else chains.write(kind, n, folder)
    return autolev.load(path)


def label(kind, n) -> str:
    return kind if n is None else f"{kind} {n}"


def measure_ours(kind, n, driver: CDriver, folder) -> dict:
    m = load_model(kind, n, folder)
    long = m.simulate(method="dop853", TFINAL=50, INTEGSTP=5, RELERR=TOLERANCE,
                      ABSERR=TOLERANCE)
    if not long.ok:
        raise RuntimeError(f"{label(kind, n)}: the 50 s run failed: {long.failure}")
    system = long.system
    x = np.array(long.states[0])
    py = scaling.per_call_us(lambda: system.derivatives(0.0, x))
    c, alone = driver.us_per_eval(system, x)
    loop = long.stats["seconds"] / long.stats["evaluations"] * 1e6
    return {"coords": len(m.coordinates), "py": py, "c": c, "rhs": alone, "loop": loop,
            "evaluations": long.stats["evaluations"]}


def measure_sympy(kind, n, limit: float) -> dict:
    if n is None:
        return {"note": "not built"}
    return scaling.run_child(["sympy", kind, str(n)], limit, per_stage=True)


def sympy_us(res: dict, limit: float) -> str:
    if "call" in res:
        return f"{res['call']['us']:.1f}"
    if res.get("killed"):
        return f">{limit:g}s {res['killed']}"
    if res.get("error"):
        return "error"
    return "-"


def _in_order(result, n: int) -> np.ndarray:
    """The rows of a planar run's states in the order Q1..Qn, U1..Un."""
    col = {name.upper(): j for j, name in enumerate(result.state_names)}
    idx = [col[f"Q{i}"] for i in range(1, n + 1)] + [col[f"U{i}"] for i in range(1, n + 1)]
    return result.states[:, idx]


def end_to_end(folder, with_sympy: bool, repeats: int = 5) -> dict:
    """The planar 8-link pendulum over 10 s with DOP853, three ways: {name: {"seconds"
    (the least integration seconds of `repeats` runs: the machine's other work only
    ever adds), "states" (rows at T = 0, 0.1, ..., 10 in the order Q1..Q8, U1..U8),
    "evaluations", "steps"}}; plus our compiled run with few printed rows, and a
    reference run at RELERR = ABSERR = 1e-12."""
    import scipy.integrate
    import sympy as sm
    n = 8
    m = load_model("planar", n, folder)
    out = {}
    for name, compiled in (("compiled (C loop)", True), ("scipy DOP853 + our C", False)):
        secs = []
        for _ in range(repeats):
            r = m.simulate(method="dop853", compiled=compiled, TFINAL=10,
                           RELERR=TOLERANCE, ABSERR=TOLERANCE)
            if not r.ok:
                raise RuntimeError(f"planar 8 ({name}) failed: {r.failure}")
            secs.append(r.stats["seconds"])
        out[name] = {"seconds": min(secs), "states": _in_order(r, n),
                     "evaluations": r.stats["evaluations"], "steps": r.stats["steps"]}
    if with_sympy:
        km, q, u, p = scaling.sympy_planar(n)
        fn = sm.lambdify((q, u, p), [km.mass_matrix_full, km.forcing_full], cse=True)
        pv = np.array([scaling.PARAMETERS["planar"][s.name] for s in p])

        def rhs(t, x):
            mm, f = fn(x[:n], x[n:], pv)
            return np.linalg.solve(mm, f).ravel()
        q0, u0 = scaling.initial_state("planar", n)
        x0 = np.array(q0 + u0)
        grid = np.linspace(0.0, 10.0, 101)
        secs = []
        for _ in range(max(1, repeats // 2)):         # slow: fewer repeats
            t0 = time.perf_counter()
            sol = scipy.integrate.solve_ivp(rhs, (0.0, 10.0), x0, method="DOP853",
                                            t_eval=grid, rtol=TOLERANCE, atol=TOLERANCE,
                                            max_step=0.1)
            secs.append(time.perf_counter() - t0)
            if not sol.success:
                raise RuntimeError(f"sympy + solve_ivp failed: {sol.message}")
        out["sympy lambdify + solve_ivp"] = {
            "seconds": min(secs), "states": sol.y.T,
            "evaluations": sol.nfev, "steps": None}
    secs = []
    for _ in range(repeats):
        r = m.simulate(method="dop853", TFINAL=10, INTEGSTP=10, RELERR=TOLERANCE,
                       ABSERR=TOLERANCE)
        secs.append(r.stats["seconds"])
    out["compiled, INTEGSTP = 10"] = {"seconds": min(secs),
                                      "evaluations": r.stats["evaluations"],
                                      "steps": r.stats["steps"]}
    r = m.simulate(method="dop853", TFINAL=10, RELERR=1e-12, ABSERR=1e-12)
    out["reference (tol 1e-12)"] = {"seconds": r.stats["seconds"], "states": _in_order(r, n),
                                    "evaluations": r.stats["evaluations"],
                                    "steps": r.stats["steps"]}
    return out


def plot(path: Path, rows: list) -> bool:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return False
    names = [r["label"] for r in rows]
    series = [("Python call (NumericSystem.derivatives)", [r["py"] for r in rows]),
              ("C evaluation (driver)", [r["c"] for r in rows]),
              ("sympy lambdify + solve", [r.get("sympy", math.nan) for r in rows])]
    fig, ax = plt.subplots(figsize=(9, 4.5))
    width = 0.27
    for k, (name, values) in enumerate(series):
        xs = [i + (k - 1) * width for i in range(len(rows))]
        ax.bar(xs, values, width, label=name)
    ax.set_yscale("log")
    ax.set_xticks(range(len(rows)))
    ax.set_xticklabels(names)
    ax.set_ylabel("microseconds per right-hand side")
    ax.set_title("right-hand-side cost per evaluation")
    ax.grid(True, axis="y", which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="small models only")
    ap.add_argument("--limit", type=float, default=60.0,
                    help="seconds per sympy stage (form, lambdify, calls); default 60")
    ap.add_argument("--no-sympy", action="store_true", help="skip sympy's route")
    args = ap.parse_args(argv)
    print(scaling.describe_run(), flush=True)
    start = time.perf_counter()
    driver = CDriver()
    rows, errors = [], []
    with tempfile.TemporaryDirectory(prefix="autolev-bench-") as folder:
        # first: a model built again in the same process gets its products' factors
        # in another order (its Z's sort after the earlier ones), so other round-off
        # (and, the pendulum being chaotic, other last digits at T = 10 s)
        e2e = end_to_end(folder, not args.no_sympy)
        print(f"[{time.perf_counter() - start:5.0f} s] planar 8 end to end: done", flush=True)
        for kind, n in (QUICK_MODELS if args.quick else MODELS):
            try:
                row = measure_ours(kind, n, driver, folder)
            except Exception as exc:            # reported below, and in the exit status
                errors.append(f"{label(kind, n)}: {type(exc).__name__}: {exc}")
                print(f"[{time.perf_counter() - start:5.0f} s] {label(kind, n)}: ERROR {exc}",
                      flush=True)
                continue
            row["label"] = label(kind, n)
            if not args.no_sympy:
                res = measure_sympy(kind, n, args.limit)
                row["sympy_text"] = sympy_us(res, args.limit) if n is not None else "-"
                if "call" in res:
                    row["sympy"] = res["call"]["us"]
                if res.get("error"):
                    errors.append(f"sympy {label(kind, n)}: {res['error']}")
            rows.append(row)
            print(f"[{time.perf_counter() - start:5.0f} s] {row['label']}: done", flush=True)

    print("\nright-hand side per evaluation (microseconds; median)")
    print("  python: NumericSystem.derivatives from Python; C: autolev_derivatives from a C "
          "loop\n  (rhs = generated code alone, the rest is the LU solve); loop: compiled "
          "DOP853 run\n  seconds / evaluations")
    head = ("model", "coords", "python", "C", "C rhs", "loop", "py/C", "py/loop",
            "sympy", "sympy/C")
    widths = (16, 6, 8, 8, 8, 8, 6, 8, 16, 8)
    print(" ".join(h.rjust(w) for h, w in zip(head, widths)))
    for r in rows:
        sy = r.get("sympy")
        cells = (r["label"], str(r["coords"]), f"{r['py']:.2f}", f"{r['c']:.3f}",
                 f"{r['rhs']:.3f}", f"{r['loop']:.3f}", f"{r['py'] / r['c']:.2f}",
                 f"{r['py'] / r['loop']:.2f}", r.get("sympy_text", "skipped"),
                 f"{sy / r['c']:.0f}" if sy else "-")
        print(" ".join(c.rjust(w) for c, w in zip(cells, widths)))

    print("\nplanar 8-link pendulum, 10 s, DOP853, RELERR = ABSERR = 1e-8, largest step "
          "0.1, 101 printed rows\n(integration seconds; best of repeated runs)")
    first = "compiled (C loop)"
    base = e2e[first]["seconds"]
    for name, v in e2e.items():
        steps = f", {v['steps']} steps" if v.get("steps") is not None else ""
        print(f"  {name:28s} {v['seconds'] * 1e3:9.2f} ms  x{v['seconds'] / base:7.2f}"
              f"   ({v['evaluations']} evaluations{steps})")
    ref = e2e[first]["states"]
    marks = (10, 50, 100)                    # rows at T = 1, 5, 10
    print("  largest state difference from the compiled run at T = "
          + ", ".join(f"{k / 10:g}" for k in marks) + " s:")
    final_diff, early_diff = 0.0, 0.0
    for name, v in e2e.items():
        if name == first or "states" not in v:
            continue
        d = [float(np.max(np.abs(v["states"][k] - ref[k]))) for k in marks]
        print(f"    {name:28s} " + "  ".join(f"{x:9.2e}" for x in d))
        if not name.startswith("reference"):
            final_diff = max(final_diff, d[-1])
            early_diff = max(early_diff, d[1])
    print("  (the reference row is the error of the 1e-8 runs themselves: this pendulum is "
          "chaotic,\n  so round-off differences grow by orders of magnitude over the "
          "last seconds)")
    if early_diff > 1e-6:
        errors.append(f"the three integrations disagree by {early_diff:.2e} at T = 5 s")

    targets = []

    def check(name, value, ok, unit=""):
        verdict = "NOT RUN" if value is None else ("PASS" if ok(value) else "FAIL")
        shown = "no measurement" if value is None else f"{value:.3g}{unit}"
        targets.append((verdict, name, shown))

    by_label = {r["label"]: r for r in rows}
    for name in ("double pendulum", "planar 2"):
        r = by_label.get(name)
        check(f"RHS Python call <= 1.5 us, {name}", r and r["py"], lambda v: v <= 1.5,
              " us")
    for r in rows:
        if r["coords"] >= 8:
            check(f"Python-call/C <= 1.5, {r['label']} ({r['coords']} coordinates)",
                  r["py"] / r["c"], lambda v: v <= 1.5)
    check("planar 8-link 10 s DOP853 rtol 1e-8 integration <= 10 ms", base * 1e3,
          lambda v: v <= 10, " ms")
    runs = [k for k, v in e2e.items() if "states" in v and not k.startswith("reference")]
    if len(runs) > 1:
        # chaotic: compare where round-off has not grown yet, and at the end against
        # the runs' own error (their distance from the 1e-12 reference)
        check(f"planar 8-link: the {len(runs)} runs agree to 1e-6 at T = 5 s",
              early_diff, lambda v: v <= 1e-6)
        own = [k for k in e2e if k.startswith("reference")]
        if own and "states" in e2e[own[0]]:
            own_error = float(np.max(np.abs(e2e[own[0]]["states"][marks[-1]]
                                            - ref[marks[-1]])))
            check(f"planar 8-link: at T = 10 s they differ less than their own error "
                  f"({own_error:.2g})", final_diff, lambda v: v <= own_error)
    print("\ntargets:")
    for verdict, name, shown in targets:
        print(f"  {verdict:7s} {name}  ({shown})")

    png = HERE / "out" / "rhs_speed.png"
    if rows and plot(png, rows):
        print(f"\nwrote {png.relative_to(ROOT)}")
    elif rows:
        print("\nmatplotlib not importable: no plot written")
    print(f"total {time.perf_counter() - start:.0f} s")
    if errors:
        print("errors:\n  " + "\n  ".join(errors))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
