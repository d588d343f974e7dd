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


class OurSquat:
    """The problem as cyipopt's problem object, through Model.dynamics' residual and its
    sparse Jacobians: the variables node-major, x at every node then u at every node;
    the rows r at nodes 1 ... N-1, then the end conditions."""

    def __init__(self, path: Path, nodes: int):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            self.dynamics = autolev.load(path).dynamics(
                controls=TORQUES, overrides=BODY | {"mom1": 0, "mom2": 0, "mom3": 0})
        dyn = self.dynamics
        self.nodes, self.states = nodes, dyn.states
        self.nx, self.nu = nx, nu = len(dyn.states), len(dyn.controls)
        self.h = DURATION / (nodes - 1)
        zero = np.zeros((1, nx))
        self.patterns = dyn.residual_jacobians(zero, zero, np.zeros((1, nu)),
                                               parameters=False).patterns
        self.n_x = nodes * nx
        self.n = self.n_x + nodes * nu
        self.fixed, self.values = fixed_ends(nodes, dyn.states)
        self.m = (nodes - 1) * nx + len(self.fixed)
        self.times = np.linspace(0.0, DURATION, nodes)[1:]
        self.evaluations = 0          # objective evaluations: IPOPT's trial points
        # r at node k in (x_k, x_k-1, u_k), every entry of the block given, as opty gives
        # its own: IPOPT's linear solves (MUMPS) cost about half as much an iteration on
        # this pattern as on the structural nonzeros alone (measured; cause not known)
        self.width = width = 2 * nx + nu
        block_rows = np.repeat(np.arange(nx), width)
        block_cols = np.tile(np.arange(width), nx)
        rows, cols = [], []
        for k in range(1, nodes):
            rows.append((k - 1) * nx + block_rows)
            cols.append(np.select([block_cols < nx, block_cols < 2 * nx],
                                  [k * nx + block_cols, (k - 2) * nx + block_cols],
                                  self.n_x + k * nu + block_cols - 2 * nx))
        rows.append((nodes - 1) * nx + np.arange(len(self.fixed)))
        cols.append(self.fixed)
        self._structure = np.concatenate(rows), np.concatenate(cols)

    def _split(self, z):
        return (z[:self.n_x].reshape(self.nodes, self.nx),
                z[self.n_x:].reshape(self.nodes, self.nu))

    def objective(self, z):
        self.evaluations += 1
        return self.h * np.sum(z[self.n_x + self.nu:] ** 2)

    def gradient(self, z):
        g = np.zeros_like(z)
        g[self.n_x + self.nu:] = 2 * self.h * z[self.n_x + self.nu:]
        return g

    def constraints(self, z):
        x, u = self._split(z)
        r = self.dynamics.residual(x[1:], (x[1:] - x[:-1]) / self.h, u[1:], t=self.times)
        return np.concatenate([r.ravel(), z[self.fixed] - self.values])

    def jacobianstructure(self):
        return self._structure

    def jacobian(self, z):
        x, u = self._split(z)
        j = self.dynamics.residual_jacobians(x[1:], (x[1:] - x[:-1]) / self.h, u[1:],
                                             t=self.times, parameters=False).values
        nx, pat = self.nx, self.patterns
        block = np.zeros((self.nodes - 1, nx, self.width))
        block[:, pat["x"].rows, pat["x"].cols] = j["x"]
        block[:, pat["xdot"].rows, pat["xdot"].cols] += j["xdot"] / self.h
        block[:, pat["xdot"].rows, nx + pat["xdot"].cols] = -j["xdot"] / self.h
        block[:, pat["u"].rows, 2 * nx + pat["u"].cols] = j["u"]
        return np.concatenate([block.ravel(), np.ones(len(self.fixed))])

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """(lower, upper) of every variable: the speeds bounded, nothing else."""
        low, high = speed_bounds(self.states)
        free = self.n - self.n_x
        return (np.concatenate([np.tile(low, self.nodes), np.full(free, -1e19)]),
                np.concatenate([np.tile(high, self.nodes), np.full(free, 1e19)]))

    def guess(self, seed: int | None) -> np.ndarray:
        return np.concatenate([first_guess(self.nodes, self.states, seed).ravel(),
                               np.zeros(self.n - self.n_x)])


def by_our_jacobians(path: Path, nodes: int, seeds=(None,)) -> dict:
    """The problem through Model.dynamics' compiled Jacobians (OurSquat), solved from
    each seed's first guess: {"build": seconds from the model loaded to the problem,
    "solves": one row per seed}."""
    import cyipopt
    start = time.perf_counter()
    squat = OurSquat(path, nodes)
    low, high = squat.bounds()
    problem = cyipopt.Problem(n=squat.n, m=squat.m, problem_obj=squat, lb=low, ub=high,
                              cl=np.zeros(squat.m), cu=np.zeros(squat.m))
    for option, value in (("print_level", 0), ("sb", "yes"), ("max_iter", 3000),
                          ("hessian_approximation", "limited-memory")):
        problem.add_option(option, value)
    built = time.perf_counter() - start

    def solve(seed):
        squat.evaluations = 0
        began = time.perf_counter()
        _, info = problem.solve(squat.guess(seed))
        return _solved(began, info, squat.evaluations)
    return {"build": built, "solves": [solve(seed) for seed in seeds]}


def _solved(began: float, info: dict, evaluations: int) -> dict:
    """IPOPT's seconds (since `began`), optimum, status and trial points (objective
    evaluations) of one solve."""
    return {"ipopt": time.perf_counter() - began, "objective": float(info["obj_val"]),
            "status": info["status"], "evaluations": evaluations}


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
        calls["objective"] = 0
        began = time.perf_counter()
        _, info = problem.solve(guess)
        return _solved(began, info, calls["objective"])
    return {"build": built, "solves": [solve(seed) for seed in seeds]}
