#!/usr/bin/env python3
"""Work-precision of the integrators: final-time error against wall time, per model.

    python bench/work_precision.py                  # every model, rtol = atol = 1e-3 ... 1e-12
    python bench/work_precision.py --quick          # 2 models (3 cases), 3 tolerances
    python bench/work_precision.py --models double_pendulum,spring_chain --limit 10
    python bench/work_precision.py --no-energy      # skip the energy-drift table

Models (name: what, TFINAL, INTEGSTP):

    double_pendulum  autolev_examples/double_pendulum.al           10 s, 0.1
    planar8          bench/chains.py planar 8-link pendulum          5 s, 0.1
                     (chaotic: at 10 s two runs at 1e-13 differ by 1e-6)
    euler_body       autolev_examples/euler_parameters_body.al      10 s, 0.1
    rolling_disc     autolev_examples/rolling_disc.al (dependent)    3 s, 0.05
    spring_chain     bench/models/spring_chain.al, one case per stiffness
                     K = 1e2, 1e4, 1e6, 1e8 (override K=...)          2 s, 0.1

Integrators (labels in the tables):

    kutta-merson C   Autolev's Kutta-Merson, whole loop in C (compiled=True)
    dop853 C         DOP853, whole loop in C (switches to LSODA when it finds the
                     equations stiff; the note says from when)
    dop853 scipy     scipy's DOP853 stepping in Python on our C right-hand side
    rk45, lsoda, radau, bdf   scipy's, stepping in Python on our C right-hand side
    sympy+lambdify dop853 / lsoda   the same model built independently with
                     sympy.physics.mechanics.KanesMethod, lambdify(cse=True), a
                     numpy solve of the mass matrix per call, and solve_ivp
                     (double_pendulum and planar8; checked against ours: final
                     states at 1e-13 and right-hand sides at 5 random states)
    pydy dop853      PyDy's System (lambdify generator) on the same KanesMethod, when
                     pydy is importable (else "skipped" is printed)

All runs use the same INTEGSTP (scipy's max_step, Kutta-Merson's largest step and the
print step) and rtol = atol = 10^-k (Autolev's RELERR = ABSERR).

Error: max over the states of |y - y_ref| / max(1, |y_ref|) at the final print time
(angles in radians).  Reference: DOP853 (C) at 1e-13, cross-checked against Radau at
1e-12 (LSODA at 1e-12 when Radau is over the limit); for the stiff chain (K >= 1e6)
Radau at 1e-13 is the reference and DOP853 (C) at 1e-13 the check.  The difference
of the two is printed as the error floor: errors below it are not resolved.

Time: the integration's own wall time, Result.stats["seconds"] (it includes the
outputs computed at each print row, the same for every integrator; the per-row cost is
printed), the minimum of up to 7 repeats (0.3 s in all) when a run takes under 50 ms.
Every run is made in a worker process, killed when a run exceeds --limit seconds
(default 20; 5 with --quick) by far: a run still going at 1.25 times the limit plus
2 s.  A run that finishes over the limit is kept, and every tighter tolerance of its
integrator is then skipped ("> limit"); a tolerance is also skipped ("> limit (est.)")
when the last two times of the integrator predict it would exceed the limit.  Results
are deterministic apart from the times.

Outputs (in --out, default bench/out/): work_precision_<case>.txt (the table of a
case), work_precision.csv (every row), work_precision_<case>.png (error on x, time on
y, log-log, one line per integrator; skipped with a note when matplotlib is missing),
work_precision_summary.txt (for each error level 1e-3 ... 1e-10: the cheapest
configuration reaching it, the best compiled-loop and the best Python-stepped scipy
configuration and the ratio of their times) and energy_drift.txt (the double
pendulum over 100 s: relative energy drift max|E(t) - E(0)|/|E(0)| and time, for
Kutta-Merson C and DOP853 C at 1e-6 ... 1e-12 and RK45 at 1e-3; E computed from the
states, checked against the model's own ENERGY output; RK45 at 1e-3 is also run
with INTEGSTP = 1, where its steps are no longer capped, from Q1 = 30 deg and from
1e-12 deg either side: its drift there changes with round-off).

One file over 600 lines on purpose: a bench script runs from a checkout alone, and its
reference solutions, integrators and plot share one table of runs.
"""
from __future__ import annotations

import argparse
import csv
import math
import multiprocessing as mp
import sys
import time
import traceback
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))
sys.path.insert(0, str(ROOT / "bench"))

# -- what is measured -------------------------------------------------------------------

OURS_C = ("kutta-merson C", "dop853 C")
SCIPY_STEPPED = ("dop853 scipy", "rk45", "lsoda", "radau", "bdf")
SYMPY = ("sympy+lambdify dop853", "sympy+lambdify lsoda")
PYDY = ("pydy dop853",)
# label -> (kind, method, compiled)
CONFIGS = {
    "kutta-merson C": ("autolev", "kutta-merson", True),
    "dop853 C": ("autolev", "dop853", True),
    "dop853 scipy": ("autolev", "dop853", False),
    "rk45": ("autolev", "rk45", True),
    "lsoda": ("autolev", "lsoda", True),
    "radau": ("autolev", "radau", True),
    "bdf": ("autolev", "bdf", True),
    "sympy+lambdify dop853": ("sympy", "DOP853", None),
    "sympy+lambdify lsoda": ("sympy", "LSODA", None),
    "pydy dop853": ("pydy", "DOP853", None),
}
LEVELS = [10.0 ** -k for k in range(3, 11)]
SHORT_RUN = 0.05           # runs shorter than this are repeated (minimum kept)
MAX_REPEATS = 7
REPEAT_BUDGET = 0.3        # seconds of repeats at most


@dataclass
class Case:
    """One model with its run settings."""

    name: str
    model: str                     # key of the model file (see model_path)
    overrides: dict                # TFINAL, INTEGSTP, constants
    description: str
    stiff: bool = False            # reference: Radau first
    sympy: str | None = None       # key of the independent sympy build, if any


def cases() -> dict[str, list[Case]]:
    """Model name -> its cases (the spring chain has one per stiffness)."""
    chain = []
    for k in (2, 4, 6, 8):
        chain.append(Case(f"spring_chain_K1e{k}", "spring_chain",
                          {"TFINAL": 2.0, "INTEGSTP": 0.1, "K": 10.0 ** k},
                          f"5 masses in a line, springs K = 1e{k} N/m between them and a "
                          "soft one (20 N/m) to the wall, dampers 0.5 N s/m, from rest, "
                          "driven by 1 - cos(3t) N on the last", stiff=k >= 6))
    return {
        "double_pendulum": [Case("double_pendulum", "double_pendulum",
                                 {"TFINAL": 10.0, "INTEGSTP": 0.1},
                                 "two point masses on rigid links (4 states)",
                                 sympy="double_pendulum")],
        # chaotic: over 10 s two 1e-13 runs differ by 1e-6 (1e-10 at T = 5)
        "planar8": [Case("planar8", "planar8", {"TFINAL": 5.0, "INTEGSTP": 0.1},
                         "planar 8-link pendulum, relative joint angles (16 states)",
                         sympy="planar8")],
        "euler_body": [Case("euler_body", "euler_body", {"TFINAL": 10.0, "INTEGSTP": 0.1},
                            "rigid body under a torque, Euler parameters (7 states)")],
        "rolling_disc": [Case("rolling_disc", "rolling_disc",
                              {"TFINAL": 3.0, "INTEGSTP": 0.05},
                              "rolling disc, U4 and U5 dependent (8 states)")],
        "spring_chain": chain,
    }


def model_path(key: str, out_dir: Path) -> Path:
    if key == "planar8":
        import chains
        folder = out_dir / "models"
        folder.mkdir(parents=True, exist_ok=True)
        return chains.write("planar", 8, folder)
    return {"double_pendulum": ROOT / "autolev_examples" / "double_pendulum.al",
            "euler_body": ROOT / "autolev_examples" / "euler_parameters_body.al",
            "rolling_disc": ROOT / "autolev_examples" / "rolling_disc.al",
            "spring_chain": ROOT / "bench" / "models" / "spring_chain.al"}[key]


def error_of(y, y_ref) -> float:
    """max_i |y_i - yref_i| / max(1, |yref_i|)."""
    y, y_ref = np.asarray(y, float), np.asarray(y_ref, float)
    return float(np.max(np.abs(y - y_ref) / np.maximum(1.0, np.abs(y_ref))))


# -- the independent sympy builds -------------------------------------------------------

def sympy_double_pendulum():
    """Two particles on massless links, angles from the downward vertical N.x."""
    import sympy as sm
    import sympy.physics.mechanics as me
    q1, q2, u1, u2 = me.dynamicsymbols("q1 q2 u1 u2")
    l1, l2, m1, m2, g = sm.symbols("l1 l2 m1 m2 g")
    frame_n = me.ReferenceFrame("N")
    frame_a = me.ReferenceFrame("A")
    frame_b = me.ReferenceFrame("B")
    frame_a.orient_axis(frame_n, frame_n.z, q1)
    frame_b.orient_axis(frame_n, frame_n.z, q2)
    frame_a.set_ang_vel(frame_n, u1 * frame_n.z)
    frame_b.set_ang_vel(frame_n, u2 * frame_n.z)
    pivot = me.Point("O")
    pivot.set_vel(frame_n, 0)
    bob1 = pivot.locatenew("P1", l1 * frame_a.x)
    bob2 = bob1.locatenew("P2", l2 * frame_b.x)
    bob1.v2pt_theory(pivot, frame_n, frame_a)
    bob2.v2pt_theory(bob1, frame_n, frame_b)
    particles = [me.Particle("p1", bob1, m1), me.Particle("p2", bob2, m2)]
    loads = [(bob1, m1 * g * frame_n.x), (bob2, m2 * g * frame_n.x)]
    kane = me.KanesMethod(frame_n, q_ind=[q1, q2], u_ind=[u1, u2],
                          kd_eqs=[q1.diff() - u1, q2.diff() - u2])
    kane.kanes_equations(particles, loads)
    values = {l1: 1.0, l2: 1.0, m1: 1.0, m2: 1.0, g: 9.81}
    y0 = [math.radians(30), math.radians(60), 0.0, 0.0]
    return kane, [q1, q2], [u1, u2], values, y0, ["Q1", "Q2", "U1", "U2"]


def sympy_planar(n: int = 8):
    """bench/chains.py's planar n-link pendulum in KanesMethod (bench/scaling.py builds
    it), with its INPUT values and initial state."""
    import scaling
    kane, q, u, (g, length, mass) = scaling.sympy_planar(n)
    values = {length: 0.5, mass: 1.0, g: 9.81}
    q0, u0 = scaling.initial_state("planar", n)
    names = [f"Q{i}" for i in range(1, n + 1)] + [f"U{i}" for i in range(1, n + 1)]
    return kane, q, u, values, q0 + u0, names


SYMPY_BUILDS = {"double_pendulum": sympy_double_pendulum, "planar8": sympy_planar}


class SympyRoute:
    """y' = [u, M(q)^-1 f(q, u)] from lambdified KanesMethod matrices (q' = u here)."""

    def __init__(self, key: str):
        import sympy as sm
        start = time.perf_counter()
        kane, q, u, values, y0, names = SYMPY_BUILDS[key]()
        self.derive_seconds = time.perf_counter() - start
        self.kane, self.q, self.u, self.values = kane, q, u, values
        params = list(values)
        start = time.perf_counter()
        fn = sm.lambdify([q + u, params], [kane.mass_matrix, kane.forcing], cse=True)
        self.lambdify_seconds = time.perf_counter() - start
        p = np.array([values[s] for s in params])
        n = len(q)

        def rhs(t, y):
            mm, f = fn(y, p)
            out = np.empty(2 * n)
            out[:n] = y[n:]
            out[n:] = np.linalg.solve(np.asarray(mm, float), np.asarray(f, float).ravel())
            return out

        self.rhs = rhs
        self.y0 = np.array(y0)
        self.names = names


class PydyRoute:
    """PyDy's System with its lambdify generator on the same KanesMethod (its mass
    matrix and forcing, solved by PyDy at each call)."""

    def __init__(self, route: SympyRoute):
        from pydy.system import System
        system = System(route.kane, constants=dict(route.values))
        start = time.perf_counter()
        fn = system.generate_ode_function(generator="lambdify")
        self.generate_seconds = time.perf_counter() - start
        p = np.array([route.values[s] for s in system.constants_symbols])
        # the generated function hands back the same buffer at every call: scipy keeps
        # the stages' derivatives, so each must be a copy
        self.rhs = lambda t, y: np.array(fn(y, t, p))
        self.y0, self.names = route.y0, route.names


# -- the worker process -----------------------------------------------------------------

class _Task:
    """What the worker does; models and sympy builds are kept between tasks."""

    def __init__(self):
        self.models = {}
        self.systems = {}
        self.routes = {}

    def load(self, task):
        import autolev
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            start = time.perf_counter()
            model = self.models.get(task["path"])
            if model is None:
                model = autolev.load(task["path"])
                self.models[task["path"]] = model
            # a short run builds (and compiles) the numeric system
            r = model.simulate(**dict(task["overrides"], TFINAL=task["overrides"]
                                      ["INTEGSTP"]))
        seconds = time.perf_counter() - start
        system = r.system
        self.systems[task["path"]] = system
        y = r.states[-1]
        calls = 200
        t0 = time.perf_counter()
        for _ in range(calls):
            system.outputs(0.0, y)
        row_cost = (time.perf_counter() - t0) / calls
        return {"seconds": seconds, "row_cost": row_cost, "names": r.state_names}

    def autolev(self, task):
        model = self.models[task["path"]]
        tol = task["tol"]
        kw = dict(task["overrides"], RELERR=tol, ABSERR=tol)
        best = None
        notes = []
        spent = 0.0
        for rep in range(MAX_REPEATS):
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                start = time.perf_counter()
                r = model.simulate(method=task["method"], compiled=task["compiled"], **kw)
                wall = time.perf_counter() - start
            seconds = r.stats.get("seconds", wall - r.stats.get("build_seconds", 0.0))
            spent += wall
            if rep == 0:
                notes = [_short_warning(str(w.message)) for w in caught
                         if not str(w.message).startswith("the equations are stiff")]
                stats = r.stats
                first = r
            best = seconds if best is None else min(best, seconds)
            if seconds >= SHORT_RUN or spent > REPEAT_BUDGET or not r.ok:
                break
        out = {"seconds": best, "repeats": rep + 1, "evaluations": stats.get("evaluations"),
               "steps": stats.get("steps"), "ok": first.ok, "failure": first.failure,
               "t": float(first.t[-1]), "y": first.states[-1].tolist(),
               "names": first.state_names, "notes": notes}
        if stats.get("switched_to"):
            out["notes"].append(f"stiff at T={stats.get('stiff_t', float('nan')):.3g}: "
                                f"-> {stats['switched_to']}")
        elif stats.get("stiff_t") is not None:
            out["notes"].append(f"stiff at T={stats['stiff_t']:.3g}")
        if task.get("full"):
            out["t_all"] = first.t.tolist()
            out["states"] = first.states.tolist()
            out["outputs"] = {lab: first.outputs[k][lab].tolist()
                              for k, table in enumerate(first.outputs)
                              for lab in table.labels}
        return out

    def sympy_build(self, task):
        key = task["key"]
        if key not in self.routes:
            self.routes[key] = SympyRoute(key)
        route = self.routes[key]
        out = {"derive": route.derive_seconds, "lambdify": route.lambdify_seconds,
               "names": route.names}
        if task.get("pydy"):
            try:
                pydy_route = PydyRoute(route)
            except ImportError as exc:
                out["pydy"] = f"not importable ({exc}): skipped"
            except Exception as exc:        # an API PyDy no longer has, ...
                out["pydy"] = f"failed: {type(exc).__name__}: {exc}"
            else:
                self.routes["pydy:" + key] = pydy_route
                out["pydy"] = f"generated in {pydy_route.generate_seconds:.2f} s"
        return out

    def rhs_check(self, task):
        """Our right-hand side against the sympy route's at seeded random states:
        max |ours - theirs| / max(1, |theirs|)."""
        system = self.systems[task["path"]]
        route = self.routes[task["key"]]
        ours_names = task["names"]
        rng = np.random.default_rng(1)
        worst = 0.0
        for _ in range(task.get("points", 5)):
            y = rng.uniform(-1.0, 1.0, len(route.names))
            theirs = route.rhs(0.0, y)
            y_ours = np.array(_reorder(list(y), route.names, ours_names))
            ours = _reorder(list(system.derivatives(0.0, y_ours)), ours_names, route.names)
            worst = max(worst, error_of(ours, theirs))
        return {"diff": worst}

    def sympy(self, task):
        from scipy.integrate import solve_ivp
        route = self.routes[("pydy:" if task["kind"] == "pydy" else "") + task["key"]]
        times = np.array(task["times"])
        best = None
        spent = 0.0
        for rep in range(MAX_REPEATS):
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                start = time.perf_counter()
                sol = solve_ivp(route.rhs, (times[0], times[-1]), route.y0,
                                method=task["method"], t_eval=times,
                                rtol=task["tol"], atol=task["tol"],
                                max_step=task["max_step"])
                seconds = time.perf_counter() - start
            spent += seconds
            best = seconds if best is None else min(best, seconds)
            if seconds >= SHORT_RUN or spent > REPEAT_BUDGET or not sol.success:
                break
        ok = bool(sol.success) and sol.t.size == times.size
        return {"seconds": best, "repeats": rep + 1, "evaluations": int(sol.nfev),
                "steps": None, "ok": ok, "failure": None if ok else sol.message,
                "t": float(sol.t[-1]), "y": sol.y[:, -1].tolist(), "names": route.names,
                "notes": [_short_warning(str(w.message)) for w in caught]}

    pydy = sympy


def _short_warning(text: str) -> str:
    text = " ".join(text.split())
    if text.startswith("RELERR = ") and " is loose for " in text:
        return "warned: loose RELERR"
    return text[:70]


def _serve(conn) -> None:
    tasks = _Task()
    while True:
        try:
            task = conn.recv()
        except EOFError:
            return
        if task is None:
            return
        try:
            out = getattr(tasks, task["kind"])(task)
        except Exception as exc:       # reported to the parent, the worker goes on
            out = {"error": f"{type(exc).__name__}: {exc}",
                   "trace": traceback.format_exc(limit=4)}
        conn.send(out)


class Worker:
    """A process that runs tasks; killed (by its pid) when a task overruns."""

    def __init__(self):
        self.proc = None
        self.conn = None
        self.ready = set()         # what it has loaded (model paths, sympy keys)
        self.restarts = 0

    def _start(self) -> None:
        ctx = mp.get_context("spawn")
        parent, child = ctx.Pipe()
        self.proc = ctx.Process(target=_serve, args=(child,), daemon=True)
        self.proc.start()
        child.close()
        self.conn = parent
        self.ready = set()

    def call(self, task: dict, timeout: float):
        """The task's answer, or None when it ran over `timeout` seconds (the worker
        is then killed and a new one started on the next call)."""
        if self.proc is None:
            self._start()
        self.conn.send(task)
        if self.conn.poll(timeout):
            try:
                return self.conn.recv()
            except EOFError:
                self.kill()
                return {"error": "the worker process died"}
        self.kill()
        self.restarts += 1
        return None

    def kill(self) -> None:
        if self.proc is not None:
            self.proc.kill()
            self.proc.join()
            self.conn.close()
        self.proc = None
        self.ready = set()

    def close(self) -> None:
        if self.proc is not None:
            self.conn.send(None)
            self.proc.join(10)
            if self.proc.is_alive():
                self.proc.kill()
                self.proc.join()
            self.proc = None


# -- measuring a case -------------------------------------------------------------------

@dataclass
class Point:
    case: str
    label: str
    tol: float
    error: float | None = None
    seconds: float | None = None
    evaluations: int | None = None
    steps: int | None = None
    status: str = "ok"             # ok, failed, > limit, > limit (est.), error
    notes: str = ""


class Bench:
    def __init__(self, out_dir: Path, limit: float, tolerances: list[float], log):
        self.out_dir = out_dir
        self.limit = limit
        self.tolerances = tolerances
        self.worker = Worker()
        self.log = log
        self.points: list[Point] = []
        self.case_info: dict[str, dict] = {}

    def ensure(self, case: Case, path: Path) -> dict:
        key = str(path)
        info = self.case_info.setdefault(case.name, {})
        if key in self.worker.ready and "row_cost" in info:
            return info
        out = self.worker.call({"kind": "load", "path": key, "overrides": case.overrides},
                               timeout=600)
        if out is None or "error" in out:
            raise RuntimeError(f"{case.name}: the model does not load: "
                               f"{out and out.get('error')}\n{out and out.get('trace')}")
        self.worker.ready.add(key)
        info.setdefault("load_seconds", out["seconds"])
        info["row_cost"] = out["row_cost"]
        return info

    def ensure_sympy(self, case: Case) -> dict | None:
        info = self.case_info[case.name]
        key = "sympy:" + case.sympy
        if key in self.worker.ready:
            return info.get("sympy")
        out = self.worker.call({"kind": "sympy_build", "key": case.sympy, "pydy": True},
                               timeout=600)
        if out is None or "error" in out:
            info["sympy"] = None
            info["sympy_error"] = out and out.get("error")
            return None
        self.worker.ready.add(key)
        info.setdefault("sympy", out)
        return info["sympy"]

    def run(self, case: Case, path: Path, label: str, tol: float, limit: float,
            full: bool = False) -> dict | None:
        """One run (None: over the limit)."""
        kind, method, compiled = CONFIGS[label]
        self.ensure(case, path)
        if kind == "autolev":
            task = {"kind": "autolev", "path": str(path), "overrides": case.overrides,
                    "method": method, "compiled": compiled, "tol": tol, "full": full}
        else:
            if self.ensure_sympy(case) is None:
                return {"error": self.case_info[case.name].get("sympy_error")}
            task = {"kind": kind, "key": case.sympy, "method": method, "tol": tol,
                    "times": self.case_info[case.name]["times"],
                    "max_step": case.overrides["INTEGSTP"]}
        # the worker's own overhead (repeats of short runs, rows) on top of the limit
        return self.worker.call(task, timeout=1.25 * limit + 2.0)

    def reference(self, case: Case, path: Path) -> None:
        """The two reference runs and their difference (the error floor)."""
        info = self.ensure(case, path)
        ref_limit = max(3 * self.limit, 60.0)
        if case.stiff:
            mains = [("radau", 1e-13), ("dop853 C", 1e-13), ("lsoda", 1e-12)]
        else:
            mains = [("dop853 C", 1e-13), ("radau", 1e-12), ("lsoda", 1e-12)]
        found = []
        for label, tol in mains:
            if len(found) == 2:
                break
            start = time.perf_counter()
            out = self.run(case, path, label, tol, ref_limit, full=not found)
            wall = time.perf_counter() - start
            if out is None or "error" in out or not out["ok"]:
                why = ("over the limit" if out is None else out.get("error")
                       or out.get("failure"))
                self.log(f"  reference {label} at {tol:.0e}: {why} ({wall:.1f} s)")
                continue
            found.append((label, tol, out))
        if not found:
            raise RuntimeError(f"{case.name}: no reference run succeeded")
        label, tol, main = found[0]
        info["reference"] = f"{label} at {tol:.0e} ({main['seconds']:.3g} s)"
        info["y_ref"] = main["y"]
        info["t_ref"] = main["t"]
        info["times"] = main["t_all"]
        info["names"] = main["names"]
        if len(found) > 1:
            label2, tol2, check = found[1]
            info["floor"] = error_of(check["y"], main["y"])
            info["check"] = f"{label2} at {tol2:.0e} ({check['seconds']:.3g} s)"
        else:
            info["floor"] = float("nan")
            info["check"] = "none succeeded"
        if case.sympy:
            built = self.ensure_sympy(case)
            if built is None:
                info["sympy_check"] = f"sympy build failed: {info.get('sympy_error')}"
            else:
                out = self.run(case, path, "sympy+lambdify dop853", 1e-13, ref_limit)
                if out is None or "error" in out or not out["ok"]:
                    info["sympy_check"] = "sympy+lambdify dop853 at 1e-13: " + (
                        "over the limit" if out is None else str(out.get("error")
                                                                 or out.get("failure")))
                else:
                    y = _reorder(out["y"], out["names"], info["names"])
                    info["sympy_diff"] = error_of(y, main["y"])
                    info["sympy_check"] = (
                        f"sympy+lambdify dop853 at 1e-13 vs our reference: "
                        f"{info['sympy_diff']:.2e} (derive {built['derive']:.2f} s, "
                        f"lambdify {built['lambdify']:.2f} s, integrate "
                        f"{out['seconds']:.2f} s)")
                rhs = self.worker.call({"kind": "rhs_check", "path": str(path),
                                        "key": case.sympy, "names": info["names"]},
                                       timeout=60)
                if rhs is not None and "diff" in rhs:
                    info["sympy_check"] += (f"; right-hand sides at 5 random states "
                                            f"differ by {rhs['diff']:.1e}")
                info["pydy"] = built.get("pydy") if built else None

    def sweep(self, case: Case, path: Path, labels) -> list[Point]:
        info = self.case_info[case.name]
        points = []
        for label in labels:
            kind = CONFIGS[label][0]
            if kind == "pydy" and not str(info.get("pydy", "")).startswith("generated"):
                continue
            if kind in ("sympy", "pydy") and info.get("sympy") is None:
                continue
            times: list[float] = []
            stop = None
            for tol in self.tolerances:
                pt = Point(case.name, label, tol)
                points.append(pt)
                if stop:
                    pt.status = stop
                    continue
                predicted = _predict(times)
                if predicted is not None and predicted > self.limit:
                    pt.status = stop = "> limit (est.)"
                    pt.notes = f"~{predicted:.0f} s predicted"
                    continue
                out = self.run(case, path, label, tol, self.limit)
                if out is None:
                    pt.status = stop = "> limit"
                    self.ensure(case, path)          # a fresh worker: load again
                    continue
                if "error" in out:
                    pt.status = "error"
                    pt.notes = out["error"][:80]
                    continue
                pt.seconds = out["seconds"]
                pt.evaluations = out["evaluations"]
                pt.steps = out["steps"]
                notes = list(dict.fromkeys(out["notes"]))
                if out["repeats"] > 1:
                    notes.append(f"min of {out['repeats']}")
                if not out["ok"] or abs(out["t"] - info["t_ref"]) > 1e-9 * max(
                        1.0, abs(info["t_ref"])):
                    pt.status = "failed"
                    notes.insert(0, _short_failure(out.get("failure")))
                else:
                    y = _reorder(out["y"], out["names"], info["names"])
                    pt.error = error_of(y, info["y_ref"])
                    times.append(pt.seconds)
                if pt.seconds > self.limit:
                    stop = "> limit"
                pt.notes = "; ".join(n for n in notes if n)
        return points


def _reorder(y, names, target) -> list:
    pos = {n.upper(): i for i, n in enumerate(names)}
    return [y[pos[n.upper()]] for n in target]


def _short_failure(text) -> str:
    if not text:
        return "failed"
    text = " ".join(str(text).split())
    return text.split("; the state there")[0][:80]


def _predict(times: list[float]) -> float | None:
    """The next time of an integrator from its last two (growth clamped to 1.2...10)."""
    if not times:
        return None
    if len(times) == 1:
        return times[-1] * 2.0
    growth = times[-1] / max(times[-2], 1e-9)
    return times[-1] * min(max(growth, 1.2), 10.0)


# -- reporting --------------------------------------------------------------------------

def _fmt(x, spec=".2e", none="-") -> str:
    return none if x is None or (isinstance(x, float) and math.isnan(x)) else format(x, spec)


def case_header(case: Case, info: dict) -> list[str]:
    ov = case.overrides
    extra = ", ".join(f"{k} = {v:g}" for k, v in ov.items() if k not in ("TFINAL",
                                                                           "INTEGSTP"))
    lines = [f"== {case.name}: {case.description}",
             f"   TFINAL = {ov['TFINAL']:g}, INTEGSTP = {ov['INTEGSTP']:g} (max step and "
             f"print step){', ' + extra if extra else ''}; {len(info['times'])} rows, "
             f"final T = {info['t_ref']!r}",
             f"   reference: {info['reference']}; check: {info['check']}; error floor "
             f"(their difference) {_fmt(info['floor'])}",
             f"   outputs at the print rows: {1e6 * info['row_cost']:.1f} us a row, "
             f"{1e3 * info['row_cost'] * len(info['times']):.2f} ms a run (inside every "
             "time below)"]
    if info.get("sympy_check"):
        lines.append(f"   {info['sympy_check']}")
    if case.sympy:
        lines.append(f"   PyDy: {info.get('pydy') or 'not importable: skipped'}")
    lines.append("   error = max over states |y - y_ref| / max(1, |y_ref|) at the final "
                 "time; seconds = integration wall time")
    return lines


def case_table(points: list[Point]) -> list[str]:
    head = f"{'method':<22} {'rtol':>7} {'error':>9} {'seconds':>9} {'evals':>9} " \
           f"{'steps':>7}  notes"
    lines = [head, "-" * len(head)]
    last = None
    for p in points:
        if last is not None and p.label != last:
            lines.append("")
        last = p.label
        if p.status in ("ok", "failed", "error"):
            err = _fmt(p.error) if p.status == "ok" else p.status
            secs = _fmt(p.seconds, ".4f")
        else:
            err, secs = "-", p.status
        lines.append(f"{p.label:<22} {p.tol:>7.0e} {err:>9} {secs:>9} "
                     f"{_fmt(p.evaluations, 'd'):>9} {_fmt(p.steps, 'd'):>7}  {p.notes}")
    return lines


def cheapest(points: list[Point], level: float, labels) -> Point | None:
    good = [p for p in points if p.label in labels and p.status == "ok"
            and p.error is not None and p.error <= level]
    return min(good, key=lambda p: p.seconds) if good else None


def summary(case: Case, points: list[Point], info: dict) -> list[str]:
    labels_all = set(CONFIGS)
    lines = [f"-- {case.name} (error floor {_fmt(info['floor'])})",
             f"{'level':>7}  {'cheapest':<34} {'best C loop':<28} {'best scipy-stepped':<28} "
             f"{'C/scipy':>8}  {'sympy route':<28} {'ours/sympy':>10}"]

    def cell(p):
        return "-" if p is None else f"{p.label} {p.tol:.0e} {p.seconds * 1e3:.3g}ms"

    for level in LEVELS:
        if not math.isnan(info["floor"]) and level < 10 * info["floor"]:
            lines.append(f"{level:>7.0e}  below 10x the error floor: not resolved")
            continue
        best = cheapest(points, level, labels_all)
        ours = cheapest(points, level, OURS_C)
        theirs = cheapest(points, level, SCIPY_STEPPED)
        sym = cheapest(points, level, SYMPY + PYDY)
        ours_any = cheapest(points, level, OURS_C + SCIPY_STEPPED)
        ratio = f"{ours.seconds / theirs.seconds:.3f}" if ours and theirs else "-"
        sratio = f"{ours_any.seconds / sym.seconds:.3f}" if ours_any and sym else "-"
        lines.append(f"{level:>7.0e}  {cell(best):<34} {cell(ours):<28} {cell(theirs):<28} "
                     f"{ratio:>8}  {cell(sym):<28} {sratio:>10}")
    return lines


def plot(case: Case, points: list[Point], info: dict, path: Path) -> str:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return "matplotlib is not installed: no plot"
    fig, ax = plt.subplots(figsize=(7.5, 5.2))
    styles = {"kutta-merson C": ("C0", "o", "-"), "dop853 C": ("C1", "s", "-"),
              "dop853 scipy": ("C1", "s", "--"), "rk45": ("C2", "^", "--"),
              "lsoda": ("C3", "v", "--"), "radau": ("C4", "D", "--"),
              "bdf": ("C5", "P", "--"), "sympy+lambdify dop853": ("C7", "s", ":"),
              "sympy+lambdify lsoda": ("C7", "v", ":"), "pydy dop853": ("C8", "x", ":")}
    for label in CONFIGS:
        pts = [p for p in points if p.label == label and p.status == "ok"]
        if not pts:
            continue
        color, marker, line = styles[label]
        ax.plot([max(p.error, 1e-17) for p in pts], [p.seconds for p in pts],
                color=color, marker=marker, linestyle=line, label=label, markersize=4)
    ax.set_xscale("log")
    ax.set_yscale("log")
    if not math.isnan(info["floor"]) and info["floor"] > 0:
        ax.axvline(info["floor"], color="grey", linestyle=":", linewidth=1)
        ax.text(info["floor"], ax.get_ylim()[0], " error floor", color="grey", fontsize=7,
                va="bottom", rotation=90)
    ax.invert_xaxis()
    ax.set_xlabel("error at T final: max |y - y_ref| / max(1, |y_ref|)")
    ax.set_ylabel("integration wall time [s]")
    ov = case.overrides
    tols = sorted({p.tol for p in points}, reverse=True)
    ax.set_title(f"{case.name}: TFINAL {ov['TFINAL']:g}, INTEGSTP {ov['INTEGSTP']:g}, "
                 f"rtol = atol = {tols[0]:.0e} ... {tols[-1]:.0e}", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return f"wrote {path}"


# -- energy drift of the double pendulum ------------------------------------------------

def pendulum_energy(states: np.ndarray, names: list[str], m1=1.0, m2=1.0, l1=1.0, l2=1.0,
                    g=9.81) -> np.ndarray:
    """E = T + V of double_pendulum.al (N1> down, angles from N1> about N3>)."""
    col = {n.upper(): j for j, n in enumerate(names)}
    q1, q2 = states[:, col["Q1"]], states[:, col["Q2"]]
    u1, u2 = states[:, col["U1"]], states[:, col["U2"]]
    v1x, v1y = -l1 * u1 * np.sin(q1), l1 * u1 * np.cos(q1)
    v2x, v2y = v1x - l2 * u2 * np.sin(q2), v1y + l2 * u2 * np.cos(q2)
    kinetic = 0.5 * m1 * (v1x ** 2 + v1y ** 2) + 0.5 * m2 * (v2x ** 2 + v2y ** 2)
    potential = -m1 * g * l1 * np.cos(q1) - m2 * g * (l1 * np.cos(q1) + l2 * np.cos(q2))
    return kinetic + potential


def energy_drift(bench: Bench, quick: bool) -> list[str]:
    path = model_path("double_pendulum", bench.out_dir)
    exps = [6, 9, 12] if quick else list(range(6, 13))
    # (label, rtol, INTEGSTP, Q1 in deg)
    runs = [("kutta-merson C", 10.0 ** -k, 0.1, 30.0) for k in exps] + \
           [("dop853 C", 10.0 ** -k, 0.1, 30.0) for k in exps] + [("rk45", 1e-3, 0.1, 30.0)]
    # RK45 with steps not capped by INTEGSTP (its own steps at 1e-3 stay below 1 s), and
    # from starts 1e-12 deg away: at 1e-3 its step choices, and so the drift, change
    # with round-off
    runs += [("rk45", 1e-3, 1.0, 30.0 + d) for d in (0.0, -1e-12, 1e-12)]
    lines = ["== energy drift: double_pendulum.al, TFINAL = 100, INTEGSTP = 0.1 (also "
             "1 for RK45: steps then uncapped), Q1 = 30 deg, Q2 = 60 deg at rest",
             "   drift = max over the print rows |E(t) - E(0)| / |E(0)|; E = kinetic + "
             "potential from the states (check: the model's ENERGY output); seconds "
             "include the outputs at the rows (1001 or 101 of them)",
             f"{'method':<16} {'rtol':>7} {'INTEGSTP':>8} {'drift':>10} {'E(T)-E(0)':>11} "
             f"{'seconds':>9} {'evals':>8} {'|E - ENERGY|':>12}  notes"]
    for label, tol, step, q1 in runs:
        case = Case("double_pendulum_100s", "double_pendulum",
                    {"TFINAL": 100.0, "INTEGSTP": step, "Q1": q1},
                    "double pendulum over 100 s")
        out = bench.run(case, path, label, tol, bench.limit, full=True)
        if out is None or "error" in out:
            lines.append(f"{label:<16} {tol:>7.0e} {step:>8g} "
                         f"{'> limit' if out is None else out['error'][:60]}")
            if out is None:
                bench.ensure(case, path)
            continue
        states = np.array(out["states"])
        energy = pendulum_energy(states, out["names"])
        theirs = np.array(out["outputs"].get("ENERGY", [np.nan] * len(energy)))
        e0 = energy[0]
        drift = float(np.max(np.abs(energy - e0)) / abs(e0))
        check = float(np.max(np.abs(energy - theirs)))
        notes = out["notes"] + ([] if out["ok"] else [_short_failure(out["failure"])])
        if q1 != 30.0:
            notes.append(f"Q1 = 30 {q1 - 30.0:+.0e} deg")
        lines.append(f"{label:<16} {tol:>7.0e} {step:>8g} {drift:>10.2e} "
                     f"{energy[-1] - e0:>+11.2e} "
                     f"{out['seconds']:>9.4f} {out['evaluations']:>8d} {check:>12.1e}  "
                     f"{'; '.join(notes)}")
    return lines


# -- main -------------------------------------------------------------------------------

def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true",
                    help="double_pendulum and spring_chain (K = 1e2, 1e6), rtol 1e-3, "
                         "1e-6, 1e-9: a smoke run")
    ap.add_argument("--models", help="comma-separated: " + ", ".join(cases()))
    ap.add_argument("--limit", type=float, default=None,
                    help="seconds of wall time per run (default 20; 5 with --quick)")
    ap.add_argument("--out", type=Path, default=ROOT / "bench" / "out")
    ap.add_argument("--no-energy", action="store_true", help="skip the energy-drift table")
    ns = ap.parse_args()
    started = time.perf_counter()
    out_dir = ns.out
    out_dir.mkdir(parents=True, exist_ok=True)
    all_cases = cases()
    if ns.models:
        names = [m.strip() for m in ns.models.split(",") if m.strip()]
        unknown = [m for m in names if m not in all_cases]
        if unknown:
            ap.error(f"unknown model(s) {', '.join(unknown)}; known: "
                     + ", ".join(all_cases))
    elif ns.quick:
        names = ["double_pendulum", "spring_chain"]
    else:
        names = list(all_cases)
    selected = [c for m in names for c in all_cases[m]]
    if ns.quick:
        selected = [c for c in selected if not c.name.startswith("spring_chain")
                    or c.name in ("spring_chain_K1e2", "spring_chain_K1e6")]
    exps = [3, 6, 9] if ns.quick else list(range(3, 13))
    limit = ns.limit if ns.limit is not None else (5.0 if ns.quick else 20.0)

    def log(text: str) -> None:
        print(text, flush=True)

    bench = Bench(out_dir, limit, [10.0 ** -k for k in exps], log)
    log(f"work-precision: {len(selected)} cases, rtol = atol = "
        f"{', '.join(f'1e-{k}' for k in exps)}; limit {limit:g} s a run; "
        f"python {sys.version.split()[0]}")
    summaries = []
    rows = []
    try:
        for case in selected:
            path = model_path(case.model, out_dir)
            t_case = time.perf_counter()
            bench.reference(case, path)
            info = bench.case_info[case.name]
            labels = list(OURS_C + SCIPY_STEPPED)
            if case.sympy:
                labels += list(SYMPY + PYDY)
            points = bench.sweep(case, path, labels)
            bench.points += points
            text = case_header(case, info) + [""] + case_table(points)
            text.append(f"   ({time.perf_counter() - t_case:.0f} s for this case)")
            log("\n" + "\n".join(text))
            (out_dir / f"work_precision_{case.name}.txt").write_text("\n".join(text) + "\n")
            log(plot(case, points, info, out_dir / f"work_precision_{case.name}.png"))
            summaries.append(summary(case, points, info))
            rows += points
        with open(out_dir / "work_precision.csv", "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["case", "method", "rtol", "error", "seconds", "evaluations", "steps",
                        "status", "notes"])
            for p in rows:
                w.writerow([p.case, p.label, f"{p.tol:.0e}", _fmt(p.error, ".6e", ""),
                            _fmt(p.seconds, ".6f", ""), _fmt(p.evaluations, "d", ""),
                            _fmt(p.steps, "d", ""), p.status, p.notes])
        summary_lines = [
            "== summary: for each error level, the cheapest measured configuration with "
            "error <= level;",
            "   C loop = kutta-merson C / dop853 C; scipy-stepped = dop853 scipy, rk45, "
            "lsoda, radau, bdf (Python stepping, our C right-hand side);",
            "   C/scipy = time of the best C loop / time of the best scipy-stepped; "
            "ours/sympy = best of ours (C loop or scipy-stepped) / best sympy route"]
        for s in summaries:
            summary_lines += [""] + s
        log("\n" + "\n".join(summary_lines))
        (out_dir / "work_precision_summary.txt").write_text("\n".join(summary_lines) + "\n")
        if not ns.no_energy:
            lines = energy_drift(bench, ns.quick)
            log("\n" + "\n".join(lines))
            (out_dir / "energy_drift.txt").write_text("\n".join(lines) + "\n")
    finally:
        bench.worker.close()
    log(f"\nwrote {out_dir}/work_precision.csv, work_precision_<case>.txt/.png, "
        f"work_precision_summary.txt{'' if ns.no_energy else ', energy_drift.txt'}; "
        f"worker restarts after a run over the limit: {bench.worker.restarts}; "
        f"total {time.perf_counter() - started:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
