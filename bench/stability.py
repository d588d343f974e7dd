#!/usr/bin/env python3
"""Numerical stability: where models break, what a run does there.

    python bench/stability.py [--quick] [--out DIR]

Sections (each prints a table; PNGs go to DIR, default bench/out, when matplotlib is
there):

1. energy drift of the conservative double pendulum over 1000 s (INTEGSTP 0.1), per
   integrator and tolerance: max |E(t) - E(0)| / |E(0)| over the rows, and the time;
2. stiffness: the spring chain of bench/models/spring_chain.al for K = 1e2 ... 1e8
   with DOP853 and Kutta-Merson: when the stiffness test fires, what the run does
   (DOP853 hands over to Radau; Kutta-Merson warns), evaluations and time;
3. constraint drift: the four-bar's loop closure |g(q)| over 200 s with and without
   projection (simulate(constraints=...)), and the rolling disc's no-slip residual
   (its constraints are solved at every evaluation: nothing to drift);
4. near-singular mass matrices: a free body in 1-2-3 angles whose rates are the
   speeds, started ever closer to gimbal lock: the largest scaled condition number,
   the warning, how the run ends;
5. bad inputs: NaN and infinite inputs, a negative or zero mass, a missing inertia --
   the message a user gets (and that it is not a traceback).

--quick shortens every run (a smoke test of the script); the full run takes a few
minutes on 2 cores.
"""
from __future__ import annotations

import argparse
import math
import sys
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

import autolev  # noqa: E402
from autolev.errors import AutolevRuntimeError  # noqa: E402
from autolev.engine.errors import AutolevModelError  # noqa: E402
from autolev.runtime.numerics.projection import Projector  # noqa: E402

EXAMPLES = ROOT / "autolev_examples"
TESTDATA = ROOT / "tests" / "data" / "numerics"


def run(model, **kw):
    """simulate() with its warnings collected: (result, [warning texts])."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        start = time.perf_counter()
        r = model.simulate(**kw)
        wall = time.perf_counter() - start
    r.stats.setdefault("wall", wall)
    return r, [str(w.message) for w in caught]


def _plot(path: Path, title: str, series: dict, xlabel: str, ylabel: str) -> str:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return "matplotlib not installed: no plot"
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for label, (x, y) in series.items():
        ax.loglog(x, y, "o-", label=label)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return f"wrote {path}"


# -- 1. energy drift ----------------------------------------------------------------------
def energy_drift(out: Path, quick: bool) -> None:
    tfinal = 100 if quick else 1000
    print(f"== 1. energy drift: double pendulum, TFINAL = {tfinal} s, INTEGSTP 0.1 "
          "(drift = max|E - E0|/|E0| over the rows; time = the integration incl. rows)")
    m = autolev.load(EXAMPLES / "double_pendulum.al")
    configs = [("kutta-merson", True), ("dop853", True), ("dop853", False), ("rk45", True),
               ("lsoda", True), ("radau", True)]
    tols = [1e-4, 1e-6, 1e-8, 1e-10, 1e-12]
    print(f"{'method':18s} {'rtol':>7s} {'drift':>10s} {'seconds':>9s} {'evals':>9s}  notes")
    series = {}
    for method, compiled in configs:
        label = f"{method}{' C' if compiled and method in ('kutta-merson', 'dop853') else ''}"
        label += " (scipy loop)" if not compiled else ""
        xs, ys = [], []
        for tol in tols:
            if method == "radau" and tol < 1e-8:
                continue                       # Radau: 6 s at 1e-10 over 100 s
            r, warned = run(m, method=method, compiled=compiled, TFINAL=tfinal,
                            INTEGSTP=0.1, ABSERR=tol, RELERR=tol)
            if not r.ok:
                print(f"{label:18s} {tol:7.0e} failed: {r.failure[:60]}")
                continue
            e = r.outputs[1]["ENERGY"]
            drift = float(np.abs(e - e[0]).max() / abs(e[0]))
            secs = r.stats["seconds"]
            note = "; ".join(w[:50] for w in warned)
            print(f"{label:18s} {tol:7.0e} {drift:10.2e} {secs:9.3f} "
                  f"{r.stats.get('evaluations', 0):9d}  {note}")
            xs.append(max(drift, 1e-16))
            ys.append(secs)
        series[label] = (xs, ys)
    print(" ", _plot(out / "stability_energy_drift.png",
                     f"double pendulum, {tfinal} s: energy drift against time", series,
                     "relative energy drift", "seconds"))


# -- 2. stiffness ---------------------------------------------------------------------------
def stiffness(quick: bool) -> None:
    print("\n== 2. stiffness: spring chain (bench/models/spring_chain.al), TFINAL 2 s, "
          "RELERR = ABSERR = 1e-8")
    m = autolev.load(ROOT / "bench" / "models" / "spring_chain.al")
    print(f"{'K':>8s} {'method':14s} {'stiff from T':>12s} {'then':>7s} {'evals':>9s} "
          f"{'seconds':>9s}  ok")
    ks = [1e2, 1e6] if quick else [1e2, 1e4, 1e6, 1e8]
    for k in ks:
        for method in ("dop853", "kutta-merson", "radau"):
            r, warned = run(m, method=method, K=k, TFINAL=2, RELERR=1e-8, ABSERR=1e-8)
            st = r.stats.get("stiff_t")
            then = r.stats.get("switched_to") or ("warned" if st is not None else "-")
            print(f"{k:8.0e} {method:14s} {('%.4g' % st) if st is not None else '-':>12s} "
                  f"{then:>7s} {r.stats.get('evaluations', 0):9d} "
                  f"{r.stats['seconds']:9.3f}  {r.ok}")


# -- 3. constraint drift --------------------------------------------------------------------
def constraint_drift(quick: bool) -> None:
    tfinal = 20 if quick else 200
    print(f"\n== 3. constraint drift over {tfinal} s")
    m = autolev.load(EXAMPLES / "fourbar.al")
    n, p5, no = m["N"], m["P5"], m["NO"]
    r5 = p5.pos_from(no)
    g = [r5.dot(n.x), r5.dot(n.y)]
    print("four-bar (a parallelogram: it passes near its change point), loop closure "
          "max |g(q)| over the rows [m]:")
    print(f"{'method':14s} {'rtol':>7s} {'projection':>10s} {'max |g|':>10s} {'rows':>6s} "
          f"{'seconds':>8s}  ends")
    for method in ("kutta-merson", "dop853"):
        for tol in (1e-6, 1e-10):
            for cons in (None, g):
                r, _ = run(m, method=method, TFINAL=tfinal, INTEGSTP=0.1, ABSERR=tol,
                           RELERR=tol, constraints=cons)
                check = Projector(r.system, g, 0.0, r.states[0], [2.0])
                worst = max(float(np.abs(check.residual_and_jacobian(t, x)[0]).max())
                            for t, x in zip(r.t, r.states))
                ends = "ok" if r.ok else f"stopped at T = {r.failure_time:.4g}"
                print(f"{method:14s} {tol:7.0e} {'on' if cons else 'off':>10s} "
                      f"{worst:10.2e} {len(r.t):6d} {r.stats.get('seconds', 0):8.3f}  {ends}")
    disc = autolev.load(EXAMPLES / "rolling_disc.al")
    r, _ = run(disc, method="dop853", TFINAL=tfinal / 4, ABSERR=1e-8, RELERR=1e-8)
    print(f"rolling disc over {tfinal / 4:g} s: {'ok' if r.ok else r.failure[:60]} -- the "
          "no-slip constraints are solved for the dependent speeds at every evaluation, "
          "so they hold to rounding at every row (tests/engine/test_numerics.py checks the "
          "contact point's velocity < 1e-9)")


# -- 4. near-singular mass matrices ---------------------------------------------------------
def near_singular() -> None:
    print("\n== 4. near-singular mass matrices: free body, 1-2-3 angles, their rates as "
          "speeds (tests/data/numerics/gimbal.al), TFINAL 1 s")
    m = autolev.load(TESTDATA / "gimbal.al")
    print(f"{'Q2 at start':>12s} {'max cond':>10s} {'at T':>8s}  warning / end")
    for q2 in (60, 85, 89, 89.9, 89.99, 89.9999, 90):
        r, warned = run(m, Q2=q2)
        cond = r.stats.get("cond_max", float("nan"))
        ct = r.stats.get("cond_max_t")
        warn = next((w for w in warned if "nearly singular" in w), "")
        end = "ok" if r.ok else r.failure.split(";")[0].replace(
            "Numerical integration failed to converge: ", "failed: ")
        print(f"{q2:12g} {cond:10.2e} {ct if ct is not None else float('nan'):8.3g}  "
              f"{(warn[:70] + ' ...; ') if warn else ''}{end[:70]}")


# -- 5. bad inputs -------------------------------------------------------------------------
def bad_inputs() -> None:
    print("\n== 5. bad inputs (tests/data/numerics/two_links.al): what the user is told")
    m = autolev.load(TESTDATA / "two_links.al")
    cases = [("L = NaN", dict(L=math.nan)), ("Q1 = inf", dict(Q1=math.inf)),
             ("MB = -1", dict(MB=-1)), ("IB = -2", dict(IB=-2)),
             ("MB = 0, IB = 0", dict(MB=0, IB=0)), ("MB = 0 (inertia kept)", dict(MB=0))]
    for label, kw in cases:
        try:
            r, _ = run(m, TFINAL=1, **kw)
            said = "runs" if r.ok else "run stops: " + r.failure.split("; the state")[0][-70:] \
                + (" ..." + r.failure.split(")")[-1] if ")" in r.failure else "")
        except AutolevModelError as exc:
            said = f"refused: {exc}"
        print(f"  {label:24s} {said[:150]}")
    try:
        autolev.load(TESTDATA / "no_inertia.al")
        said = "loaded (unexpected)"
    except AutolevRuntimeError as exc:
        said = str(exc).splitlines()[0]
    print(f"  {'no INERTIA for B':24s} {said[:150]}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--out", default=str(ROOT / "bench" / "out"))
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    energy_drift(out, args.quick)
    stiffness(args.quick)
    constraint_drift(args.quick)
    near_singular()
    bad_inputs()
    print(f"\ntotal {time.perf_counter() - start:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
