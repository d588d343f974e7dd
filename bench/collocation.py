"""What trajectory optimization pays for a model's dynamics and their derivatives
(Model.dynamics): per collocation node, the explicit f and the implicit residual r
alone, their sparse Jacobians (r's also without the parameters' columns, as a
collocation with fixed parameters asks), and the ratio of a Jacobian to its function;
with the time to form and compile them.

    python bench/collocation.py [--nodes N] [--chains 8,32] [--corpus DIR] [--only TEXT]
                                [--solve]

Models: the shipped examples, planar n-link chains (bench/chains.py) and, when the
corpus is there, gait2de (csu-hmc/gait2d: the joint moments mom4..mom9 as controls,
its parameters set to 1 where it gives none).  Every node's numbers come from one call
(C where there is a compiler); each time is the best of five repeats, in one run.
With Pinocchio installed (`pip install 'autolev[bench]'`), the planar chains' ABA
derivatives (pinocchio.computeABADerivatives in a C++ loop over the same nodes, the
driver bench/anchors.py compiles once from Pinocchio's headers) are timed beside ours.

`--solve`: the pendulum swing-up of docs/tutorials/trajectory.md (backward Euler, 51
nodes, 2 s, the torque squared) solved twice in one run, each by IPOPT from the same
first guess: through Dynamics.casadi() (CasADi's derivatives of the model's own
expressions) and through opty (Model.to_opty(): sympy's equations, opty's generated C);
then, with the corpus, gait2de's squat to stand (bench/squat.py) through our compiled
Jacobians and through opty, each built once and solved from the same five first guesses
(its paths are chaotic: one solve compares luck).  Needs casadi, and opty with cyipopt.
Each is timed from the model loaded to the optimum, and IPOPT's own part apart.
"""
from __future__ import annotations

import argparse
import os
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
import chains  # noqa: E402
import squat  # noqa: E402

CORPUS = Path(os.environ.get("AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus"))
GAIT2DE = "csu-hmc+gait2d/algait2de/gait2de.al"


def best_of(repeats: int, run) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return min(times)


def measured(name: str, model, nodes: int, controls=None, parameters=None) -> dict:
    start = time.perf_counter()
    dyn = model.dynamics(controls=controls, missing_values="zero")
    rng = np.random.default_rng(0)
    x = 0.3 * rng.normal(size=(nodes, len(dyn.states)))
    u = rng.normal(size=(nodes, len(dyn.controls)))
    p = dyn.parameter_values if parameters is None else parameters(dyn)
    t = np.linspace(0.0, 1.0, nodes)
    dyn.explicit_jacobians(x[:1], u[:1], p, t[:1])     # the Jacobians form when first asked
    dyn.explicit_jacobians(x[:1], u[:1], p, t[:1], parameters=False)
    formed = time.perf_counter() - start
    xdot = dyn.explicit(x, u, p, t)
    per_node = {
        "f": best_of(5, lambda: dyn.explicit(x, u, p, t)) / nodes,
        "df": best_of(5, lambda: dyn.explicit_jacobians(x, u, p, t)) / nodes,
        # what Pinocchio's ABA derivatives compute: d(rates)/d(x, u), no parameter
        "dff": best_of(5, lambda: dyn.explicit_jacobians(x, u, p, t,
                                                          parameters=False)) / nodes,
        "r": best_of(5, lambda: dyn.residual(x, xdot, u, p, t)) / nodes,
        "dr": best_of(5, lambda: dyn.residual_jacobians(x, xdot, u, p, t)) / nodes,
        # a collocation with the parameters fixed: r's Jacobian in x, x' and u alone
        "drf": best_of(5, lambda: dyn.residual_jacobians(x, xdot, u, p, t,
                                                          parameters=False)) / nodes,
    }
    nnz = sum(pat.nnz for pat in dyn.residual_jacobians(x[:1], xdot[:1], u[:1], p,
                                                        t[:1]).patterns.values())
    return {"model": name, "states": len(dyn.states), "controls": len(dyn.controls),
            "nnz": nnz, "formed": formed, "backend": dyn.backend, **per_node,
            "dynamics": dyn, "x": x}


def pinocchio_planar(n: int, nodes: int, row: dict) -> tuple | None:
    """(seconds per node of computeABADerivatives on the planar n-link chain, in a C++
    loop over the same nodes (bench/anchors.py's driver, header-only at -O3
    -march=native), the largest gap between its d(qdd)/d(q, v) and ours at the first
    node, relative to the largest entry), or None without Pinocchio."""
    try:
        import pinocchio  # noqa: F401
    except ImportError:
        return None
    import anchors
    driver = anchors.Pinocchio(anchors.pinocchio_library(log=lambda text: print(text,
                                                                                 flush=True)))
    dyn, x = row["dynamics"], row["x"]
    order = [dyn.states.index(f"Q{i}") for i in range(1, n + 1)]
    speeds = [dyn.states.index(f"U{i}") for i in range(1, n + 1)]
    q, v = x[:, order], x[:, speeds]
    seconds = best_of_seconds(5, lambda: driver.aba_derivatives_seconds(q, v)) / nodes
    theirs = np.hstack(driver.aba_derivatives(q[0], v[0]))
    ours = dyn.explicit_jacobians(x[:1], parameters=False).dense("x")[0][
        np.ix_(speeds, order + speeds)]
    return seconds, float(np.abs(ours - theirs).max() / np.abs(theirs).max())


def best_of_seconds(repeats: int, timed) -> float:
    """The least of `repeats` calls of `timed`, each returning the seconds it measured."""
    return min(timed() for _ in range(repeats))


SWINGUP = ROOT / "docs" / "examples" / "swingup.al"


def swingup_by_casadi(nodes: int, duration: float) -> dict:
    import casadi as ca
    start = time.perf_counter()
    dyn = autolev.load(SWINGUP).dynamics()
    form = dyn.casadi()
    h = duration / (nodes - 1)
    opti = ca.Opti()
    x = opti.variable(len(dyn.states), nodes)
    u = opti.variable(len(dyn.controls), nodes)
    residual = form.residual.map(nodes - 1)
    times = np.linspace(0.0, duration, nodes)
    opti.subject_to(ca.vec(residual(x[:, 1:], (x[:, 1:] - x[:, :-1]) / h, u[:, 1:],
                                    dyn.parameter_values, times[1:].reshape(1, -1))) == 0)
    opti.subject_to(x[:, 0] == [0.0, 0.0])
    opti.subject_to(x[:, -1] == [np.pi, 0.0])
    opti.minimize(h * ca.sumsqr(u))
    opti.set_initial(x[0, :], np.linspace(0.0, np.pi, nodes))
    opti.solver("ipopt", {"print_time": False}, {"print_level": 0, "sb": "yes"})
    began = time.perf_counter()
    solution = opti.solve()
    done = time.perf_counter()
    return {"total": done - start, "ipopt": done - began,
            "objective": float(solution.value(opti.f)),
            "iterations": solution.stats()["iter_count"]}


def swingup_by_opty(nodes: int, duration: float) -> dict:
    from opty import Problem
    start = time.perf_counter()
    parts = autolev.load(SWINGUP).to_opty()
    h = duration / (nodes - 1)
    q, u = parts.states
    torque = parts.controls[0]

    def objective(free):
        return h * np.sum(free[2 * nodes:] ** 2)

    def gradient(free):
        grad = np.zeros_like(free)
        grad[2 * nodes:] = 2 * h * free[2 * nodes:]
        return grad
    t = parts.time
    problem = Problem(objective, gradient, parts.equations_of_motion, parts.states, nodes, h,
                      known_parameter_map=parts.parameters,
                      instance_constraints=(q.func(0 * t), u.func(0 * t),
                                            q.func(duration + 0 * t) - np.pi,
                                            u.func(duration + 0 * t)),
                      integration_method="backward euler", tmp_dir=tempfile.mkdtemp())
    problem.add_option("print_level", 0)
    problem.add_option("sb", "yes")
    guess = np.zeros(3 * nodes)
    guess[:nodes] = np.linspace(0.0, np.pi, nodes)
    began = time.perf_counter()
    free, info = problem.solve(guess)
    done = time.perf_counter()
    assert torque in parts.controls
    return {"total": done - start, "ipopt": done - began, "objective": float(info["obj_val"]),
            "iterations": None}


def solve_both(corpus: Path, nodes: int = 51, duration: float = 2.0) -> None:
    try:
        import casadi  # noqa: F401
        import cyipopt  # noqa: F401
        import opty  # noqa: F401
    except ImportError as exc:
        print(f"(--solve needs casadi and opty with cyipopt: {exc})")
        return
    ours = swingup_by_casadi(nodes, duration)
    theirs = swingup_by_opty(nodes, duration)
    for name, row in (("Dynamics.casadi()", ours), ("opty (Model.to_opty())", theirs)):
        print(f"swing-up, {nodes} nodes, {name:24s}: {row['total']:7.2f} s from the model "
              f"loaded, IPOPT {row['ipopt']:6.3f} s, objective {row['objective']:.8f}")
    gap = abs(ours["objective"] - theirs["objective"]) / abs(theirs["objective"])
    print(f"ours / opty: {ours['total'] / theirs['total']:.2f}x from the model, "
          f"{ours['ipopt'] / theirs['ipopt']:.2f}x in IPOPT; optima {gap:.1e} apart")
    gait = corpus / squat.GAIT2DE
    if not gait.exists():
        print(f"(no {gait}: the gait problem needs the corpus)")
        return
    nodes, seeds = 31, (None, 1, 2, 3, 4)
    ours, theirs = (squat.by_our_jacobians(gait, nodes, seeds),
                    squat.by_opty(gait, nodes, seeds))
    print(f"gait2de squat to stand, {nodes} nodes, from {len(seeds)} first guesses (the "
          "straight line, then moved at random):")
    for name, row in (("our compiled Jacobians", ours), ("opty (Model.to_opty())", theirs)):
        cells = "  ".join(f"{s['ipopt']:5.2f} s {s['objective']:7.1f} ({s['status']})"
                          for s in row["solves"])
        print(f"  {name:22s} problem built in {row['build']:6.2f} s; IPOPT s, objective "
              f"(status) per guess: {cells}")
    total = {name: sum(s["ipopt"] for s in row["solves"])
             for name, row in (("ours", ours), ("opty", theirs))}
    points = {name: sum(s["evaluations"] for s in row["solves"])
              for name, row in (("ours", ours), ("opty", theirs))}
    print(f"ours / opty: {(ours['build'] + total['ours']) / (theirs['build'] + total['opty']):.2f}x"
          f" from the model (build + all solves), {total['ours'] / total['opty']:.2f}x in IPOPT "
          f"(sums: {total['ours']:.2f} / {total['opty']:.2f} s); trial points "
          f"{points['ours']} / {points['opty']}, "
          f"{total['ours'] / points['ours'] * 1e3:.1f} / {total['opty'] / points['opty'] * 1e3:.1f}"
          " ms each")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--nodes", type=int, default=500)
    ap.add_argument("--chains", default="8,32")
    ap.add_argument("--corpus", type=Path, default=CORPUS)
    ap.add_argument("--only", default="")
    ap.add_argument("--solve", action="store_true",
                    help="only the swing-up solved through CasADi and through opty")
    ns = ap.parse_args()
    if ns.solve:
        solve_both(ns.corpus)
        return 0
    warnings.simplefilter("ignore")
    rows = []
    folder = Path(tempfile.mkdtemp(prefix="autolev-collocation-"))
    cases = [(p.stem, lambda p=p: (autolev.load(p), None, None))
             for p in sorted((ROOT / "autolev_examples").glob("*.al"))]
    for n in (int(k) for k in ns.chains.split(",") if k):
        path = folder / f"planar{n}.al"
        path.write_text(chains.planar(n))
        cases.append((f"planar{n}", lambda path=path: (autolev.load(path), None, None)))
    gait = ns.corpus / GAIT2DE
    if gait.exists():
        cases.append(("gait2de", lambda: (autolev.load(gait),
                                          [f"mom{k}" for k in range(4, 10)],
                                          lambda dyn: np.ones(len(dyn.parameters)))))
    for name, make in cases:
        if ns.only and ns.only not in name:
            continue
        model, controls, parameters = make()
        row = measured(name, model, ns.nodes, controls, parameters)
        if name.startswith("planar"):
            row["pinocchio"] = pinocchio_planar(int(name[6:]), ns.nodes, row)
        rows.append(row)
        us = {k: row[k] * 1e6 for k in ("f", "df", "dff", "r", "dr", "drf")}
        anchor = row.get("pinocchio")
        print(f"{name:22s} {row['states']:3d} states {row['controls']:2d} controls "
              f"{row['nnz']:5d} nnz  formed {row['formed']:6.2f} s ({row['backend']})  "
              f"f {us['f']:8.2f} us  df {us['df']:8.2f} us ({row['df'] / row['f']:5.2f}x)  "
              f"r {us['r']:8.2f} us  dr {us['dr']:8.2f} us ({row['dr'] / row['r']:5.2f}x)  "
              f"dr without p {us['drf']:8.2f} us ({row['drf'] / row['f']:5.2f}x f)"
              + ("" if anchor is None else
                 f"  pinocchio ABA derivatives {anchor[0] * 1e6:8.2f} us "
                 f"(ours without p {us['dff']:8.2f} us, {row['dff'] / anchor[0]:5.2f}x; "
                 f"they agree to {anchor[1]:.1e})"),
              flush=True)
    chains_timed = [r for r in rows if "pinocchio" in r]
    if chains_timed and all(r["pinocchio"] is None for r in chains_timed):
        print("(Pinocchio is not installed: no anchor; pip install 'autolev[bench]')")
    print(f"per node, best of 5 over {ns.nodes} nodes in one call each")
    return 0


if __name__ == "__main__":
    sys.exit(main())
