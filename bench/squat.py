"""The squat-to-stand of docs/tutorials/gait.md (gait2de, both legs free), one problem
solved two ways with IPOPT (limited-memory Hessian, the same first guess): through
Model.dynamics' compiled residual and its sparse Jacobians (cyipopt), and through
opty's own generated code from Model.to_opty() (opty builds its cyipopt problem).

The problem is laid out as opty lays it out: backward Euler on N nodes, the moments at
every node (the first one's in no equation and out of the objective), both ends as
equality constraints, the speeds bounded.  The two NLPs are the same up to the order of
variables and rows (r's rows equal opty's equations at any point), yet a problem with
stiff contact is chaotic: rounding alone sends IPOPT down different paths to different
local optima.  So each is solved from several first guesses (the straight line, then
the same line with the inner nodes' angles moved at random, the same for both), and the
sums compared.  bench/collocation.py --solve prints it."""
from __future__ import annotations

import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

import autolev

GAIT2DE = "csu-hmc+gait2d/algait2de/gait2de.al"
# gait2d's standard body (Winter's data, 75 kg, 1.8 m) as the repository's examples give it
BODY = dict(
    par__TrunkMass=50.85, par__TrunkInertia=3.1777, par__TrunkCMy=0.3155,
    par__ThighMass=7.5, par__ThighInertia=0.1522, par__ThighCMy=-0.191, par__ThighLen=0.4410,
    par__ShankMass=3.4875, par__ShankInertia=0.0624, par__ShankCMy=-0.1917,
    par__ShankLen=0.4428, par__FootMass=1.0875, par__FootInertia=0.0184, par__FootCMx=0.0768,
    par__FootCMy=-0.0351, par__ContactY=-0.07, par__ContactHeelX=-0.06,
    par__ContactToeX=0.15, par__ContactStiff=5e7, par__ContactDamp=0.85,
    par__ContactV0=0.01, par__ContactFric=1.0, gravity=9.81)
TORQUES = [f"mom{k}" for k in range(4, 10)]
DURATION = 1.0


def ends() -> tuple[np.ndarray, np.ndarray]:
    """(q at the squat, q standing): the tutorial's."""
    sink = (BODY["gravity"] * 75.0 / 4 / BODY["par__ContactStiff"]) ** (1 / 3)
    ankle = -BODY["par__ContactY"] - sink
    thigh, shank = BODY["par__ThighLen"], BODY["par__ShankLen"]
    squat = np.array([0.0, ankle + thigh * np.cos(1.2) + shank * np.cos(0.5),
                      -0.6, 1.8, -1.7, 0.5, 1.8, -1.7, 0.5])
    stand = np.array([0.0, ankle + thigh + shank, 0, 0, 0, 0, 0, 0, 0])
    return squat, stand


def fixed_ends(nodes: int, states: list) -> tuple[np.ndarray, np.ndarray]:
    """(positions in the node-major state vector, their values) of the end conditions:
    every q and speed at the squat, the angles and speeds standing."""
    squat, stand = ends()
    q = [states.index(f"q{i}") for i in range(1, 10)]
    w = [states.index(f"q{i}'") for i in range(1, 10)]
    last = (nodes - 1) * len(states)
    where = q + w + [last + q[i] for i in range(2, 9)] + [last + i for i in w]
    return np.array(where), np.concatenate([squat, np.zeros(9), stand[2:], np.zeros(9)])


def first_guess(nodes: int, states: list, seed: int | None = None) -> np.ndarray:
    """Nodes x states: the angles straight from squat to standing at a constant rate;
    with a seed, the inner nodes' angles (q3 ... q9) moved by up to 0.1 rad at random
    (the same numbers whatever the order of `states`)."""
    squat, stand = ends()
    guess = np.zeros((nodes, len(states)))
    moved = np.zeros((nodes, 9))
    if seed is not None:
        moved[1:-1, 2:] = np.random.default_rng(seed).uniform(-0.1, 0.1, (nodes - 2, 7))
    for i in range(9):
        guess[:, states.index(f"q{i + 1}")] = np.linspace(squat[i], stand[i], nodes) \
            + moved[:, i]
        guess[1:-1, states.index(f"q{i + 1}'")] = (stand[i] - squat[i]) / DURATION
    return guess


def speed_bounds(states: list) -> tuple[np.ndarray, np.ndarray]:
    """Per state: the hip's speeds within 1.5 m/s, the angles' within 5 rad/s."""
    low, high = np.full(len(states), -1e19), np.full(len(states), 1e19)
    for i in range(1, 10):
        k = states.index(f"q{i}'")
        low[k], high[k] = (-1.5, 1.5) if i <= 2 else (-5.0, 5.0)
    return low, high


def by_our_jacobians(path: Path, nodes: int, seeds=(None,)) -> dict:
    """The problem through Model.dynamics' compiled Jacobians, solved from each seed's
    first guess: {"build": seconds from the model loaded to the problem, "solves": one
    row per seed}."""
    import cyipopt
    start = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        dyn = autolev.load(path).dynamics(controls=TORQUES,
                                          overrides=BODY | {"mom1": 0, "mom2": 0, "mom3": 0})
    nx, nu, h = len(dyn.states), len(dyn.controls), DURATION / (nodes - 1)
    zero = np.zeros((1, nx))
    patterns = dyn.residual_jacobians(zero, zero, np.zeros((1, nu)), parameters=False).patterns
    n_x, n_u = nodes * nx, nodes * nu
    fixed, values = fixed_ends(nodes, dyn.states)
    # r at node k in (x_k, x_k-1, u_k), every entry of the block given, as opty gives its
    # own: IPOPT's linear solves (MUMPS) cost about half as much an iteration on this
    # pattern as on the structural nonzeros alone (measured; the cause is not known)
    width = 2 * nx + nu
    block_rows = np.repeat(np.arange(nx), width)
    block_cols = np.tile(np.arange(width), nx)
    rows, cols = [], []
    for k in range(1, nodes):
        rows.append((k - 1) * nx + block_rows)
        cols.append(np.select([block_cols < nx, block_cols < 2 * nx],
                              [k * nx + block_cols, (k - 2) * nx + block_cols],
                              n_x + k * nu + block_cols - 2 * nx))
    rows.append((nodes - 1) * nx + np.arange(len(fixed)))
    cols.append(fixed)
    times = np.linspace(0.0, DURATION, nodes)[1:]

    def split(z):
        return z[:n_x].reshape(nodes, nx), z[n_x:].reshape(nodes, nu)

    calls = {"objective": 0}

    class Squat:
        def objective(self, z):
            calls["objective"] += 1
            return h * np.sum(z[n_x + nu:] ** 2)

        def gradient(self, z):
            g = np.zeros_like(z)
            g[n_x + nu:] = 2 * h * z[n_x + nu:]
            return g

        def constraints(self, z):
            x, u = split(z)
            r = dyn.residual(x[1:], (x[1:] - x[:-1]) / h, u[1:], t=times)
            return np.concatenate([r.ravel(), z[fixed] - values])

        def jacobianstructure(self):
            return np.concatenate(rows), np.concatenate(cols)

        def jacobian(self, z):
            x, u = split(z)
            j = dyn.residual_jacobians(x[1:], (x[1:] - x[:-1]) / h, u[1:], t=times,
                                       parameters=False).values
            block = np.zeros((nodes - 1, nx, width))
            block[:, patterns["x"].rows, patterns["x"].cols] = j["x"]
            block[:, patterns["xdot"].rows, patterns["xdot"].cols] += j["xdot"] / h
            block[:, patterns["xdot"].rows, nx + patterns["xdot"].cols] = -j["xdot"] / h
            block[:, patterns["u"].rows, 2 * nx + patterns["u"].cols] = j["u"]
            return np.concatenate([block.ravel(), np.ones(len(fixed))])

    low, high = speed_bounds(dyn.states)
    m = (nodes - 1) * nx + len(fixed)
    problem = cyipopt.Problem(n=n_x + n_u, m=m, problem_obj=Squat(),
                              lb=np.concatenate([np.tile(low, nodes), np.full(n_u, -1e19)]),
                              ub=np.concatenate([np.tile(high, nodes), np.full(n_u, 1e19)]),
                              cl=np.zeros(m), cu=np.zeros(m))
    for option, value in (("print_level", 0), ("sb", "yes"), ("max_iter", 3000),
                          ("hessian_approximation", "limited-memory")):
        problem.add_option(option, value)
    built = time.perf_counter() - start

    def solve(seed):
        guess = np.concatenate([first_guess(nodes, dyn.states, seed).ravel(), np.zeros(n_u)])
        return _timed_solve(problem, guess, calls)
    return {"build": built, "solves": [solve(seed) for seed in seeds]}


def _timed_solve(problem, guess, calls: dict) -> dict:
    """IPOPT's seconds, optimum, status and trial points (objective evaluations) of one
    solve from `guess`."""
    calls["objective"] = 0
    began = time.perf_counter()
    _, info = problem.solve(guess)
    return {"ipopt": time.perf_counter() - began, "objective": float(info["obj_val"]),
            "status": info["status"], "evaluations": calls["objective"]}


def by_opty(path: Path, nodes: int, seeds=(None,)) -> dict:
    """The problem through opty's generated code, as by_our_jacobians."""
    from opty import Problem
    start = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        parts = autolev.load(path).to_opty(controls=TORQUES, mom1=0, mom2=0, mom3=0, **BODY)
    h = DURATION / (nodes - 1)
    nx = len(parts.states)
    names = [str(s.func).replace("_rate", "'") for s in parts.states]
    t = parts.time
    where, values = fixed_ends(nodes, names)
    times = np.linspace(0.0, DURATION, nodes)
    instance = tuple(parts.states[i % nx].func(times[i // nx] + 0 * t) - v
                     for i, v in zip(where, values))
    low, high = speed_bounds(names)
    bounds = {s: (low[k], high[k]) for k, s in enumerate(parts.states) if high[k] < 1e19}
    controls = slice(nx * nodes, nx * nodes + len(parts.controls) * nodes)

    calls = {"objective": 0}

    def objective(free):
        calls["objective"] += 1
        return h * np.sum(free[controls].reshape(-1, nodes)[:, 1:] ** 2)

    def gradient(free):
        g = np.zeros_like(free)
        u = free[controls].reshape(-1, nodes).copy()
        u[:, 0] = 0.0
        g[controls] = 2 * h * u.ravel()
        return g
    problem = Problem(objective, gradient, parts.equations_of_motion, parts.states, nodes, h,
                      known_parameter_map=parts.parameters, instance_constraints=instance,
                      bounds=bounds, integration_method="backward euler",
                      tmp_dir=tempfile.mkdtemp())
    for option, value in (("print_level", 0), ("sb", "yes"), ("max_iter", 3000)):
        problem.add_option(option, value)
    built = time.perf_counter() - start

    def solve(seed):
        guess = np.concatenate([first_guess(nodes, names, seed).T.ravel(),
                                np.zeros(len(parts.controls) * nodes)])
        return _timed_solve(problem, guess, calls)
    return {"build": built, "solves": [solve(seed) for seed in seeds]}
