#!/usr/bin/env python3
"""Our compiled right-hand side against outside anchors: Pinocchio's articulated-body
algorithm (Featherstone) per evaluation, an exact reference for accuracy, and MuJoCo's
RK4 for a whole run; on bench/chains.py's planar n-link chain of uniform rods.

    python bench/anchors.py                         # n = 2, 4, 8, 16, 32 (a few minutes,
                                                    # after a one-off C++ compile, ~2 min)
    python bench/anchors.py --quick                 # n = 2, 8; 20 states
    python bench/anchors.py --src OLD/src --src src # our side on two trees, alternated
    python bench/anchors.py --no-mujoco

Per n, both sides compute the accelerations u' of the same chain (link i turns by Q_i
relative to link i-1 about N3>, U_i = Q_i', rods of mass M = 1 and length L = 0.5
with inertia M L^2/12 about their centres, G = 9.81 along N1>):
    ours       autolev_derivatives (generated code and the solve of M u' = f) and
               the generated autolev_rhs alone, called in a C loop by rhs_speed.py's
               driver; solve share = 1 - rhs alone / whole evaluation
    Pinocchio  pinocchio::aba (tau = 0) with Pinocchio's q, v = our Q, U (RZ joints),
               header-only and inlined into a C++ loop: one shared library for every
               n, compiled once and kept under bench/out/ by the digest of its source
               and flags, loaded into the process that times ours
Per evaluation: microseconds at one state (the same for both), the median over
alternated rounds (ours, Pinocchio, then Pinocchio, ours) of medians of timed loops;
C KB: the size of our generated C source.  Agreement: at 200 random states (q uniform
in [-pi, pi], u in [-2, 2], a fixed seed) the two sides' accelerations agree to 1e-9
relative, else the bench fails.  Accuracy: max and median over those states of
||a - a_exact||_inf / ||a_exact||_inf, with a_exact from the chain's equations derived
here (absolute angles, mass matrix from the mass centres' Jacobians) solved in mpmath
at 40 digits; checked first against the double pendulum written out by hand and a
Lagrangian differentiated numerically at 60 digits (no accuracy numbers otherwise).

The 8-link chain over 10 s with DOP853 at RELERR = ABSERR = 1e-8 (warm): the wall
time of m.simulate() against the seconds inside the compiled integration loop of the
same runs (loop.c's autolev_integrate, timed around its calls; best of 5 each).
MuJoCo (optional): the same chain as MJCF, RK4 with the step whose end state at T = 10
s is as far from our DOP853 run at 1e-12 as our 1e-8 run is, stepped in C by
mujoco.rollout; our loop's and our whole simulate()'s time over MuJoCo's.  gait3d: our
per-evaluation cost on the BioMAC gait3d pelvis213 model (33 speeds, forward dynamics
of its equations as they stand), when the corpus has it.

--src PATH (repeatable) measures our side on each source tree in a process of its own
(PYTHONPATH=PATH, a cache folder per tree under bench/out/cache/), alternated with the
others; Pinocchio is timed in each of those processes and its column is the median
over all.  MuJoCo's comparison uses the last tree.  PASS/FAIL lines for the targets
follow (they do not change the exit status); with matplotlib, bench/out/anchors.png.
The exit status is 1 when a check fails: the reference's self-check, the agreement
with Pinocchio or MuJoCo, or a measuring process.  Timings are wall-clock: run on an
otherwise idle machine.
"""
from __future__ import annotations

import argparse
import ctypes
import hashlib
import json
import math
import os
import statistics
import subprocess
import sys
import sysconfig
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
OUT = HERE / "out"
sys.path.insert(0, str(HERE))

import chains                                   # noqa: E402
from rhs_speed import CDriver                   # noqa: E402

L, M, G = 0.5, 1.0, 9.81                        # the chain's INPUT values (chains.planar)
SIZES, QUICK_SIZES = (2, 4, 8, 16, 32), (2, 8)
STATES, QUICK_STATES = 200, 20
ROUNDS, QUICK_ROUNDS = 5, 3
SEED = 20240611
DIGITS = 40
AGREE = 1e-9                 # ours against Pinocchio, relative: else the bench fails
TOLERANCE, REFERENCE_TOLERANCE = 1e-8, 1e-12
CORPUS = Path(os.environ.get("AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus"))
GAIT3D = CORPUS / ("mad-lab-fau+BioMAC-Sim-Toolbox/src/model/gait3d/c_files/"
                   "gait3d_pelvis213/gait3d_pelvis213_NoDer.al")

# -- Pinocchio ------------------------------------------------------------------------
PINOCCHIO_SOURCE = r"""
// the planar chain of bench/chains.py for Pinocchio's articulated-body algorithm
#include <pinocchio/multibody.hpp>
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/aba-derivatives.hpp>
#include <string>
#include <time.h>

namespace pin = pinocchio;

struct Chain {
    pin::Model model;
    pin::Data data;
    Eigen::VectorXd tau;
    explicit Chain(const pin::Model &m) : model(m), data(m), tau(Eigen::VectorXd::Zero(m.nv)) {}
};

/* n rods of mass m and length l, each turning about z relative to the one before at
   the end of it (the first at the origin), mass centre at l/2 along the rod's x;
   gravity g along x */
extern "C" void *chain_new(int n, double l, double m, double g)
{
    pin::Model model;
    Eigen::Matrix3d rod = Eigen::Matrix3d::Zero();
    rod(1, 1) = rod(2, 2) = m * l * l / 12.0;
    pin::JointIndex parent = 0;
    for (int i = 0; i < n; i++) {
        pin::SE3 place = pin::SE3::Identity();
        if (i > 0)
            place.translation() << l, 0.0, 0.0;
        parent = model.addJoint(parent, pin::JointModelRZ(), place, "q" + std::to_string(i + 1));
        model.appendBodyToJoint(parent, pin::Inertia(m, Eigen::Vector3d(l / 2, 0.0, 0.0), rod));
    }
    model.gravity.linear() << g, 0.0, 0.0;
    return new Chain(model);
}

extern "C" void chain_free(void *chain)
{
    delete static_cast<Chain *>(chain);
}

/* a = the joint accelerations at (q, v) with no joint torques */
extern "C" void chain_accelerations(void *chain, const double *q, const double *v, double *a)
{
    Chain &c = *static_cast<Chain *>(chain);
    const int n = c.model.nv;
    pin::aba(c.model, c.data, Eigen::Map<const Eigen::VectorXd>(q, n),
             Eigen::Map<const Eigen::VectorXd>(v, n), c.tau);
    Eigen::Map<Eigen::VectorXd>(a, n) = c.data.ddq;
}

/* seconds taken by `count` evaluations at (q, v); *sink: a sum of their results */
extern "C" double chain_loop(void *chain, const double *q, const double *v, long count,
                             double *sink)
{
    Chain &c = *static_cast<Chain *>(chain);
    const int n = c.model.nv;
    const Eigen::VectorXd qq = Eigen::Map<const Eigen::VectorXd>(q, n);
    const Eigen::VectorXd vv = Eigen::Map<const Eigen::VectorXd>(v, n);
    struct timespec a, b;
    double s = 0.0;
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (long i = 0; i < count; i++)
        s += pin::aba(c.model, c.data, qq, vv, c.tau)[0];
    clock_gettime(CLOCK_MONOTONIC, &b);
    *sink = s;
    return (double)(b.tv_sec - a.tv_sec) + 1e-9 * (double)(b.tv_nsec - a.tv_nsec);
}

/* d(a)/dq and d(a)/dv (n x n each, row-major) at (q, v) with no joint torques */
extern "C" void chain_aba_derivatives(void *chain, const double *q, const double *v,
                                      double *da_dq, double *da_dv)
{
    Chain &c = *static_cast<Chain *>(chain);
    const int n = c.model.nv;
    pin::computeABADerivatives(c.model, c.data, Eigen::Map<const Eigen::VectorXd>(q, n),
                               Eigen::Map<const Eigen::VectorXd>(v, n), c.tau);
    typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> RowMajor;
    Eigen::Map<RowMajor>(da_dq, n, n) = c.data.ddq_dq;
    Eigen::Map<RowMajor>(da_dv, n, n) = c.data.ddq_dv;
}

/* seconds taken by `nodes` evaluations of the derivatives, one at each row of q and v
   (nodes x n, row-major), as a collocation asks for them; *sink: a sum of results */
extern "C" double chain_aba_derivatives_loop(void *chain, const double *q, const double *v,
                                             long nodes, double *sink)
{
    Chain &c = *static_cast<Chain *>(chain);
    const int n = c.model.nv;
    struct timespec a, b;
    double s = 0.0;
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (long k = 0; k < nodes; k++) {
        pin::computeABADerivatives(c.model, c.data,
                                   Eigen::Map<const Eigen::VectorXd>(q + k * n, n),
                                   Eigen::Map<const Eigen::VectorXd>(v + k * n, n), c.tau);
        s += c.data.ddq_dq(0, 0) + c.data.ddq_dv(0, 0);
    }
    clock_gettime(CLOCK_MONOTONIC, &b);
    *sink = s;
    return (double)(b.tv_sec - a.tv_sec) + 1e-9 * (double)(b.tv_nsec - a.tv_nsec);
}
"""

# header-only (no PINOCCHIO_ENABLE_TEMPLATE_INSTANTIATION): aba is inlined at these flags
PINOCCHIO_FLAGS = ("-O3", "-DNDEBUG", "-march=native", "-std=c++17",
                   "-DBOOST_MPL_LIMIT_LIST_SIZE=30", "-DBOOST_MPL_LIMIT_VECTOR_SIZE=30",
                   "-DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS",
                   "-DBOOST_FUSION_INVOKE_MAX_ARITY=12")


def cmeel_prefix() -> Path:
    """Where pip's Pinocchio (cmeel) keeps its headers and libraries."""
    return Path(sysconfig.get_paths()["purelib"]) / "cmeel.prefix"


def compiler_version(cc: str) -> str:
    try:
        r = subprocess.run([cc, "--version"], capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.SubprocessError):
        return cc
    return (r.stdout.splitlines() or [cc])[0]


def pinocchio_library(log=print) -> Path:
    """The Pinocchio driver as a shared library: bench/out/pinocchio-<digest>.so,
    compiled when absent (about two minutes: Pinocchio's templates)."""
    cxx = os.environ.get("CXX", "g++")
    prefix = cmeel_prefix()
    if not (prefix / "include" / "pinocchio" / "algorithm" / "aba.hpp").exists():
        raise RuntimeError(f"no Pinocchio headers under {prefix} (pip install pin)")
    flags = list(PINOCCHIO_FLAGS) + [f"-I{prefix / 'include'}",
                                     f"-I{prefix / 'include' / 'eigen3'}"]
    digest = hashlib.sha256("\0".join([PINOCCHIO_SOURCE, cxx, compiler_version(cxx), *flags])
                            .encode()).hexdigest()[:16]
    lib = OUT / f"pinocchio-{digest}.so"
    if lib.exists():
        return lib
    OUT.mkdir(parents=True, exist_ok=True)
    log(f"compiling the Pinocchio driver once ({cxx}; about two minutes) -> "
        f"{lib.relative_to(ROOT)}")
    with tempfile.TemporaryDirectory(prefix="autolev-pin-") as tmp:
        src = Path(tmp) / "chain.cpp"
        src.write_text(PINOCCHIO_SOURCE)
        made = Path(tmp) / lib.name
        r = subprocess.run([cxx, *flags, "-shared", "-fPIC", "-o", str(made), str(src),
                            f"-L{prefix / 'lib'}", "-lpinocchio_default",
                            f"-Wl,-rpath,{prefix / 'lib'}"], capture_output=True, text=True)
        if r.returncode:
            raise RuntimeError("compiling the Pinocchio driver failed:\n" + r.stderr[-3000:])
        os.replace(made, lib)           # whole or not at all: another run may read it
    return lib


class Pinocchio:
    """The driver above, loaded with ctypes: chains by n, their accelerations, and the
    seconds of a timed loop."""

    def __init__(self, library: Path):
        lib = ctypes.CDLL(str(library))
        P, D = ctypes.c_void_p, ctypes.c_double
        lib.chain_new.argtypes = [ctypes.c_int, D, D, D]
        lib.chain_new.restype = P
        lib.chain_free.argtypes = [P]
        lib.chain_accelerations.argtypes = [P, P, P, P]
        lib.chain_loop.argtypes = [P, P, P, ctypes.c_long, ctypes.POINTER(D)]
        lib.chain_loop.restype = D
        lib.chain_aba_derivatives.argtypes = [P, P, P, P, P]
        lib.chain_aba_derivatives_loop.argtypes = [P, P, P, ctypes.c_long, ctypes.POINTER(D)]
        lib.chain_aba_derivatives_loop.restype = D
        self._lib = lib
        self._chains: dict = {}

    def _chain(self, n: int):
        if n not in self._chains:
            self._chains[n] = self._lib.chain_new(n, L, M, G)
        return self._chains[n]

    def accelerations(self, q, u) -> np.ndarray:
        q, u = np.ascontiguousarray(q, dtype=float), np.ascontiguousarray(u, dtype=float)
        a = np.empty(len(q))
        self._lib.chain_accelerations(self._chain(len(q)), q.ctypes.data, u.ctypes.data,
                                      a.ctypes.data)
        return a

    def us_per_eval(self, q, u, budget: float, repeats: int) -> float:
        """Median microseconds per evaluation at (q, u), timed as CDriver times ours."""
        q, u = np.ascontiguousarray(q, dtype=float), np.ascontiguousarray(u, dtype=float)
        chain, sink = self._chain(len(q)), ctypes.c_double()
        return CDriver._median_us(
            lambda k: self._lib.chain_loop(chain, q.ctypes.data, u.ctypes.data, k,
                                           ctypes.byref(sink)), budget, repeats)


    def aba_derivatives(self, q, u) -> tuple[np.ndarray, np.ndarray]:
        """(d(accelerations)/dq, d(accelerations)/du) at (q, u): n x n each."""
        q, u = np.ascontiguousarray(q, dtype=float), np.ascontiguousarray(u, dtype=float)
        dq, du = np.empty((len(q), len(q))), np.empty((len(q), len(q)))
        self._lib.chain_aba_derivatives(self._chain(len(q)), q.ctypes.data, u.ctypes.data,
                                        dq.ctypes.data, du.ctypes.data)
        return dq, du

    def aba_derivatives_seconds(self, q, u) -> float:
        """Seconds of one C++ loop of the derivatives over the rows of q and u (nodes x n)."""
        q, u = np.ascontiguousarray(q, dtype=float), np.ascontiguousarray(u, dtype=float)
        sink = ctypes.c_double()
        return self._lib.chain_aba_derivatives_loop(self._chain(q.shape[1]), q.ctypes.data,
                                                    u.ctypes.data, len(q), ctypes.byref(sink))


# -- the exact reference ----------------------------------------------------------------
def exact_accelerations(q, u, digits: int = DIGITS) -> list:
    """u' of the n-link chain at (q, u) in mpmath at `digits` digits, from equations
    derived here.  Absolute angles th_i = q_1 + ... + q_i; rod i's mass centre at
    sum_{k<i} L e(th_k) + L/2 e(th_i), e = (cos, sin), so its velocity is
    sum_k l_ik e'(th_k) th_k' with l_ik = L (k < i), L/2 (k = i), 0 (k > i).  Kane's
    equations in th (zero joint torques): H th'' = f with
        H_jk = A_jk cos(th_j - th_k) + I delta_jk,    A_jk = M sum_i l_ij l_ik,
        f_j  = -G M sin(th_j) sum_i l_ij + sum_k A_jk sin(th_k - th_j) th_k'^2
    (the last from d/dt e'(th_k) = -e(th_k) th_k'), then u'_i = th''_i - th''_{i-1}."""
    import mpmath as mp
    with mp.workdps(digits):
        n = len(q)
        ml, mm, g = mp.mpf(L), mp.mpf(M), mp.mpf(G)     # the doubles both sides read
        inertia = mm * ml * ml / 12
        th, w = [], []
        for i in range(n):
            th.append((th[-1] if th else 0) + mp.mpf(q[i]))
            w.append((w[-1] if w else 0) + mp.mpf(u[i]))
        c, s = [mp.cos(x) for x in th], [mp.sin(x) for x in th]
        h, f = [], []
        for j in range(n):
            row = []
            # sum_i l_ij over i >= j: L/2 + (n - 1 - j) L (0-based j)
            fj = -g * mm * ml * (mp.mpf(1) / 2 + (n - 1 - j)) * s[j]
            for k in range(n):
                # sum_i l_ij l_ik over i >= max(j, k): L^2/4 (j = k) or L^2/2, + L^2 each after
                a = mm * ml * ml * ((mp.mpf(1) / 4 if j == k else mp.mpf(1) / 2)
                                    + (n - 1 - max(j, k)))
                row.append(a * (c[j] * c[k] + s[j] * s[k]) + (inertia if j == k else 0))
                fj += a * (s[k] * c[j] - c[k] * s[j]) * w[k] ** 2
            h.append(row)
            f.append(fj)
        thdd = _solve_positive_definite(h, f)
        return [+(thdd[i] - (thdd[i - 1] if i else 0)) for i in range(n)]


def _solve_positive_definite(h: list, f: list) -> list:
    """h x = f by Gaussian elimination without pivoting (h is symmetric positive
    definite: stable), on lists of mpf (mpmath's matrices are 3x slower here)."""
    import mpmath as mp
    n = len(f)
    h, f = [row[:] for row in h], f[:]
    for k in range(n):
        pivot = h[k]
        for i in range(k + 1, n):
            factor = h[i][k] / pivot[k]
            h[i][k + 1:] = [a - factor * b for a, b in zip(h[i][k + 1:], pivot[k + 1:])]
            f[i] -= factor * f[k]
    x = [mp.mpf(0)] * n
    for i in range(n - 1, -1, -1):
        x[i] = (f[i] - mp.fdot(h[i][i + 1:], x[i + 1:])) / h[i][i]
    return x


def double_pendulum_by_hand(q, u) -> list:
    """u' of the 2-link chain, its equations written out (absolute angles a, b):
        M L^2 (4/3 a'' + 1/2 cos(a-b) b'') = -3/2 M G L sin a - 1/2 M L^2 sin(a-b) b'^2
        M L^2 (1/2 cos(a-b) a'' + 1/3 b'') = -1/2 M G L sin b + 1/2 M L^2 sin(a-b) a'^2"""
    import mpmath as mp
    ml, mm, g = mp.mpf(L), mp.mpf(M), mp.mpf(G)
    a, b = mp.mpf(q[0]), mp.mpf(q[0]) + mp.mpf(q[1])
    ad, bd = mp.mpf(u[0]), mp.mpf(u[0]) + mp.mpf(u[1])
    k = mm * ml * ml
    h11, h12, h22 = k * 4 / 3, k * mp.cos(a - b) / 2, k / 3
    f1 = -3 * mm * g * ml * mp.sin(a) / 2 - k * mp.sin(a - b) * bd ** 2 / 2
    f2 = -mm * g * ml * mp.sin(b) / 2 + k * mp.sin(a - b) * ad ** 2 / 2
    det = h11 * h22 - h12 * h12
    add, bdd = (f1 * h22 - h12 * f2) / det, (h11 * f2 - h12 * f1) / det
    return [add, bdd - add]


def lagrangian_accelerations(q, u) -> list:
    """u' from Lagrange's equations with every derivative numerical (mpmath.diff):
    the mass centres' velocities by differentiating their positions along the motion,
    then d/dt dT/dth' - dL/dth = 0 from the second derivatives of L = T - V."""
    import mpmath as mp
    n = len(q)
    ml, mm, g = mp.mpf(L), mp.mpf(M), mp.mpf(G)
    inertia = mm * ml * ml / 12

    def centre(th, i):
        x = mp.fsum(ml * mp.cos(th[k]) for k in range(i)) + ml / 2 * mp.cos(th[i])
        y = mp.fsum(ml * mp.sin(th[k]) for k in range(i)) + ml / 2 * mp.sin(th[i])
        return x, y

    def lagrangian(*z):
        th, w = z[:n], z[n:]
        energy = mp.fsum(inertia * x * x / 2 for x in w)
        for i in range(n):
            def along(h, axis, i=i):
                return centre([a + h * b for a, b in zip(th, w)], i)[axis]
            vx, vy = mp.diff(lambda h: along(h, 0), 0), mp.diff(lambda h: along(h, 1), 0)
            energy += mm * (vx * vx + vy * vy) / 2 + mm * g * centre(th, i)[0]
        return energy

    th = [mp.fsum(mp.mpf(x) for x in q[:i + 1]) for i in range(n)]
    w = [mp.fsum(mp.mpf(x) for x in u[:i + 1]) for i in range(n)]

    def partial(*which):
        orders = [0] * (2 * n)
        for k in which:
            orders[k] += 1
        return mp.diff(lagrangian, th + w, tuple(orders))
    h = mp.matrix(n, n)
    f = mp.matrix(n, 1)
    for j in range(n):
        for k in range(n):
            h[j, k] = partial(n + j, n + k)
        f[j] = partial(j) - mp.fsum(partial(n + j, k) * w[k] for k in range(n))
    thdd = mp.lu_solve(h, f)
    return [thdd[i] - (thdd[i - 1] if i else 0) for i in range(n)]


def reference_self_check() -> tuple[bool, str]:
    """exact_accelerations against the hand-written double pendulum and the numerical
    Lagrangian (n = 3) at random states: (ok, what was found)."""
    import mpmath as mp
    rng = np.random.default_rng([SEED, 0])
    worst = {"n = 2 by hand": 0.0, "n = 3 Lagrangian": 0.0}
    for _ in range(2):
        for n, name, other in ((2, "n = 2 by hand", double_pendulum_by_hand),
                               (3, "n = 3 Lagrangian", lagrangian_accelerations)):
            q, u = rng.uniform(-np.pi, np.pi, n), rng.uniform(-2, 2, n)
            with mp.workdps(60):
                b = other(q, u)
                a = exact_accelerations(q, u, 60)
                err = max(abs(x - y) for x, y in zip(a, b)) / max(abs(y) for y in b)
            worst[name] = max(worst[name], float(err))
    ok = all(v < 1e-30 for v in worst.values())
    return ok, ", ".join(f"{k}: {v:.1e}" for k, v in worst.items())


def relative_errors(approx, exact) -> np.ndarray:
    """||a - a_exact||_inf / ||a_exact||_inf per state (computed in mpmath)."""
    import mpmath as mp
    out = []
    with mp.workdps(DIGITS):
        for a, e in zip(approx, exact):
            out.append(float(max(abs(e_i - float(a_i)) for a_i, e_i in zip(a, e))
                             / max(abs(e_i) for e_i in e)))
    return np.array(out)


def random_states(n: int, count: int) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng([SEED, n])
    return rng.uniform(-np.pi, np.pi, (count, n)), rng.uniform(-2.0, 2.0, (count, n))


# -- our side, in a process per source tree ---------------------------------------------
class OursServer:
    """What a measuring process does (anchors.py --serve, PYTHONPATH = one tree's
    src): one JSON request per line in, one JSON reply per line out."""

    def __init__(self):
        self.folder = tempfile.mkdtemp(prefix="autolev-anchors-")
        self.driver = CDriver()
        self.pinocchio = None
        self.chains: dict = {}

    def op_hello(self, pinocchio: str) -> dict:
        import autolev
        from autolev.engine import clibrary
        self.pinocchio = Pinocchio(Path(pinocchio))
        cc = clibrary.compiler()
        return {"module": str(Path(autolev.__file__).parent), "flags": list(clibrary.C_FLAGS),
                "cc": f"{cc} ({compiler_version(cc)})" if cc else "none"}

    def _state(self, n: int, q, u) -> np.ndarray:
        """Q1..Qn, U1..Un put in the system's (alphabetical) state order."""
        col = self.chains[n]["col"]
        x = np.empty(2 * n)
        x[[col[f"Q{i}"] for i in range(1, n + 1)]] = q
        x[[col[f"U{i}"] for i in range(1, n + 1)]] = u
        return x

    def op_chain(self, n: int, q: list, u: list) -> dict:
        """Build the n-link chain; our and Pinocchio's accelerations at the states."""
        import autolev
        start = time.perf_counter()
        m = autolev.load(chains.write("planar", n, self.folder))
        r = m.simulate(method="dop853", TFINAL=0.1, RELERR=TOLERANCE, ABSERR=TOLERANCE)
        if not r.ok:
            raise RuntimeError(f"planar {n}: the short run failed: {r.failure}")
        col = {name.upper(): j for j, name in enumerate(r.state_names)}
        self.chains[n] = {"model": m, "system": r.system, "col": col}
        speeds = [col[f"U{i}"] for i in range(1, n + 1)]
        ours = [r.system.derivatives(0.0, self._state(n, qi, ui))[speeds].tolist()
                for qi, ui in zip(q, u)]
        theirs = [self.pinocchio.accelerations(qi, ui).tolist() for qi, ui in zip(q, u)]
        source = r.system.rhs_function.source
        return {"ours": ours, "pinocchio": theirs, "seconds": time.perf_counter() - start,
                "source_bytes": len(source) if source is not None else None}

    def op_time(self, n: int, q: list, u: list, budget: float, repeats: int,
                pinocchio_first: bool) -> dict:
        """Microseconds per evaluation at one state: ours (whole, rhs alone) and
        Pinocchio's, one after the other in the order asked."""
        system = self.chains[n]["system"]
        x = self._state(n, q, u)
        out = {}
        for side in (("pinocchio", "ours") if pinocchio_first else ("ours", "pinocchio")):
            if side == "ours":
                out["ours"], out["rhs"] = self.driver.us_per_eval(system, x, budget=budget,
                                                                  repeats=repeats)
            else:
                out["pinocchio"] = self.pinocchio.us_per_eval(q, u, budget, repeats)
        return out

    def op_simulate(self, n: int, repeats: int) -> dict:
        """Whole m.simulate() against the seconds inside loop.c's autolev_integrate, the
        n-link chain over 10 s with DOP853 at 1e-8 (warm: built by op_chain; best of
        `repeats` each); the end states of that run and of one at 1e-12, in the order
        Q1..Qn, U1..Un, and the initial state with its accelerations."""
        chain = self.chains[n]
        m, col = chain["model"], chain["col"]
        order = ([col[f"Q{i}"] for i in range(1, n + 1)]
                 + [col[f"U{i}"] for i in range(1, n + 1)])

        def run(tol):
            return m.simulate(method="dop853", TFINAL=10, RELERR=tol, ABSERR=tol)
        r = run(TOLERANCE)                  # the same system object every run (kept)
        loop = r.system.loop
        inner = loop._integrate
        spent = [0.0]

        def timed(*args):                   # the ctypes call into loop.c, timed
            start = time.perf_counter()
            try:
                return inner(*args)
            finally:
                spent[0] += time.perf_counter() - start
        whole, inside, integration = [], [], []
        loop._integrate = timed
        try:
            for _ in range(repeats):
                spent[0] = 0.0
                start = time.perf_counter()
                r = run(TOLERANCE)
                whole.append(time.perf_counter() - start)
                inside.append(spent[0])
                integration.append(r.stats["seconds"])
                if r.system.loop is not loop:
                    raise RuntimeError("simulate() built another loop: not timed")
        finally:
            loop._integrate = inner
        if not r.ok:
            raise RuntimeError(f"planar {n}: {r.failure}")
        if not min(inside) > 0:
            raise RuntimeError("simulate() did not call the compiled loop")
        ref = run(REFERENCE_TOLERANCE)
        x0 = r.states[0]
        return {"whole": min(whole), "loop": min(inside), "integration": min(integration),
                "evaluations": r.stats["evaluations"], "steps": r.stats["steps"],
                "rows": len(r.t), "t_end": float(r.t[-1]),
                "end": r.states[-1][order].tolist(), "reference_end": ref.states[-1][order]
                .tolist(), "x0": x0[order].tolist(),
                "a0": r.system.derivatives(0.0, x0)[order[n:]].tolist()}

    def op_gait3d(self, path: str, budget: float, repeats: int, rounds: int) -> dict:
        """Our evaluation of the gait3d model's forward dynamics: its only CODE commands
        are ALGEBRAIC (inverse dynamics), so the equations as they stand (Kane's
        equations of its 33 speeds, the ground forces G1..G24 constants), every
        constant and state given large_models.value_of of its name."""
        import autolev                                # noqa: F401  (this tree's, first)
        import large_models                           # (it puts this checkout's src first)
        from autolev.loader import load_for_run
        from autolev.engine.options import RunOptions
        from autolev.runtime.numerics.prepare import prepare_command
        start = time.perf_counter()
        model, _ = load_for_run(path)
        command = model.plain_dynamics()
        prepared = prepare_command(model.snapshot_for(command), command,
                                   RunOptions(missing_values="zero"))
        model.keep_built()
        system = prepared.system
        if system.loop is None:
            return {"skip": "its right-hand side is not C: no compiled loop to time"}
        system.set_parameters(np.array([large_models.value_of(str(p))
                                        for p in system.params]))
        x = np.array([large_models.value_of(str(s)) for s in system.states])
        build = time.perf_counter() - start
        # rounds: its 3.8 MB of code runs at one of two speeds, changing unpredictably
        samples = [self.driver.us_per_eval(system, x, budget=budget, repeats=repeats)
                   for _ in range(rounds)]
        whole, alone = zip(*samples)
        source = system.rhs_function.source
        return {"ours": statistics.median(whole), "rhs": statistics.median(alone),
                "range": [min(whole), max(whole)], "rhs_range": [min(alone), max(alone)],
                "speeds": system._n,
                "states": system.nstate, "source_bytes": len(source), "build": build}


def serve() -> int:
    """The measuring process's loop; its stdout is the reply channel alone (anything
    else printed, from Python or C, goes to stderr)."""
    replies = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)
    sys.stdout = sys.stderr
    warnings.simplefilter("ignore")
    server = OursServer()
    for line in sys.stdin:
        request = json.loads(line)
        try:
            reply = getattr(server, "op_" + request.pop("op"))(**request)
        except Exception as exc:            # reported by the parent, and in its status
            reply = {"error": f"{type(exc).__name__}: {exc}"}
        replies.write(json.dumps(reply) + "\n")
        replies.flush()
    return 0


class Tree:
    """A source tree's measuring process (see OursServer)."""

    def __init__(self, src: Path, label: str, pinocchio: Path, logs: Path):
        self.src, self.label = src, label
        digest = hashlib.sha256(str(src).encode()).hexdigest()[:10]
        cache = OUT / "cache" / f"{src.parent.name}-{digest}"
        cache.mkdir(parents=True, exist_ok=True)
        env = dict(os.environ, PYTHONPATH=str(src), AUTOLEV_CACHE=str(cache))
        env.pop("AUTOLEV_NO_MODEL_CACHE", None)
        self.log = logs / f"{digest}.log"
        self._log = open(self.log, "w")
        self.proc = subprocess.Popen([sys.executable, str(Path(__file__).resolve()), "--serve"],
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=self._log, text=True, env=env)
        self.pinocchio = pinocchio
        self.info: dict = {}

    def hello(self) -> None:
        self.info = self.ask("hello", pinocchio=str(self.pinocchio))

    def ask(self, op: str, **kw) -> dict:
        self.proc.stdin.write(json.dumps(dict(kw, op=op)) + "\n")
        self.proc.stdin.flush()
        line = self.proc.stdout.readline()
        if not line:
            tail = self.log.read_text().strip().splitlines()[-5:]
            raise RuntimeError(f"{self.label}: the measuring process ended\n    "
                               + "\n    ".join(tail))
        reply = json.loads(line)
        if "error" in reply:
            raise RuntimeError(f"{self.label}: {op}: {reply['error']}")
        return reply

    def close(self) -> None:
        if self.proc.poll() is None:
            self.proc.stdin.close()
            self.proc.wait(timeout=60)
        self._log.close()


# -- MuJoCo -------------------------------------------------------------------------------
def chain_mjcf(n: int) -> str:
    """The chain as MJCF: hinges about z, rods' mass centres at L/2; Ixx tiny (MuJoCo
    wants Ixx + Iyy >= Izz, so Iyy = Izz as in a thin rod; neither moves a planar
    chain); no contacts, damping or armature; gravity along x; RK4."""
    rod = M * L * L / 12
    opened = "".join(
        f'<body name="b{i}" pos="{0 if i == 1 else L} 0 0">'
        f'<joint name="q{i}" type="hinge" axis="0 0 1"/>'
        f'<inertial pos="{L / 2} 0 0" mass="{M}" diaginertia="1e-9 {rod!r} {rod!r}"/>'
        for i in range(1, n + 1))
    return (f'<mujoco model="planar{n}"><option gravity="{G} 0 0" integrator="RK4"/>'
            f'<default><geom contype="0" conaffinity="0"/></default>'
            f'<worldbody>{opened}{"</body>" * n}</worldbody></mujoco>')


class MujocoChain:
    def __init__(self, n: int):
        import mujoco
        self.mj = mujoco
        self.n = n
        self.model = mujoco.MjModel.from_xml_string(chain_mjcf(n))
        self.data = mujoco.MjData(self.model)

    def accelerations(self, x0) -> np.ndarray:
        """qacc after mj_forward at x0 = (q, u)."""
        self.mj.mj_resetData(self.model, self.data)
        self.data.qpos[:], self.data.qvel[:] = x0[:self.n], x0[self.n:]
        self.mj.mj_forward(self.model, self.data)
        return self.data.qacc.copy()

    def run(self, x0, t_end: float, steps: int, chunk: int = 50000) -> tuple[np.ndarray, float]:
        """(q, u) at t_end after `steps` RK4 steps from x0 with mujoco.rollout (C; in
        chunks, its output holding every step's state), and the seconds it took."""
        import mujoco.rollout
        mj, model, data = self.mj, self.model, self.data
        model.opt.timestep = t_end / steps
        mj.mj_resetData(model, data)
        data.qpos[:], data.qvel[:] = x0[:self.n], x0[self.n:]
        spec = mj.mjtState.mjSTATE_FULLPHYSICS
        state = np.empty(mj.mj_stateSize(model, spec))
        mj.mj_getState(model, data, state, spec)
        left = steps
        start = time.perf_counter()
        while left:
            k = min(chunk, left)
            states, _ = mujoco.rollout.rollout(model, data, state, nstep=k)
            state = states[0, -1].copy()
            left -= k
        seconds = time.perf_counter() - start
        mj.mj_setState(model, data, state, spec)
        return np.concatenate([data.qpos, data.qvel]), seconds


def mujoco_anchor(sim: dict, n: int, log) -> dict:
    """MuJoCo's RK4 at the step count whose end error (against our 1e-12 run) first
    reaches our 1e-8 run's, bisected over the number of steps; its time (best of 3)."""
    chain = MujocoChain(n)
    x0, a0 = np.array(sim["x0"]), np.array(sim["a0"])
    qacc = chain.accelerations(x0)
    agree = float(np.max(np.abs(qacc - a0)) / np.max(np.abs(a0)))
    reference, t_end = np.array(sim["reference_end"]), sim["t_end"]
    target = float(np.max(np.abs(np.array(sim["end"]) - reference)))

    def error(steps):
        return float(np.max(np.abs(chain.run(x0, t_end, steps)[0] - reference)))
    lo, hi = None, 1000
    while error(hi) > target:               # double until as accurate as ours
        lo, hi = hi, hi * 2
        if hi > 1 << 21:
            return {"agree": agree, "target": target, "skip": "no step count up to 2^21 "
                    "reaches our end error"}
    while lo is None:                       # halve until less accurate than ours
        if hi <= 10:
            lo = hi
            break
        if error(hi // 2) > target:
            lo = hi // 2
        else:
            hi //= 2
    while hi / lo > 1.02 and hi - lo > 1:
        mid = int(round(math.sqrt(lo * hi)))
        if error(mid) > target:
            lo = mid
        else:
            hi = mid
    log(f"MuJoCo: {hi} RK4 steps match our end error {target:.2e}")
    end_error = error(hi)
    seconds = min(chain.run(x0, t_end, hi)[1] for _ in range(3))
    return {"agree": agree, "target": target, "steps": hi, "dt": t_end / hi,
            "end_error": end_error, "seconds": seconds}


# -- the report ---------------------------------------------------------------------------
def growth(values: dict, a: int = 16, b: int = 32) -> float | None:
    """log2 of the ratio from n = a to n = b (the exponent of n over a doubling)."""
    if values.get(a) and values.get(b):
        return math.log2(values[b] / values[a])
    return None


def plot(path: Path, sizes, timing: dict, labels: list) -> bool:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return False
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for k, label in enumerate(labels):
        ax.plot(sizes, [timing[k][n]["ours"] for n in sizes], "o-", label=f"ours ({label})")
    ax.plot(sizes, [timing["pinocchio"][n] for n in sizes], "s--",
            label="Pinocchio 4 (aba, inlined)")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xticks(sizes)
    ax.set_xticklabels([str(n) for n in sizes])
    ax.set_xlabel("links n (planar chain)")
    ax.set_ylabel("microseconds per evaluation")
    ax.set_title("forward dynamics per evaluation")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--src", action="append", type=Path,
                    help="a source tree (its src folder) for our side; repeatable")
    ap.add_argument("--quick", action="store_true", help="n = 2 and 8, fewer states")
    ap.add_argument("--no-mujoco", action="store_true", help="skip the MuJoCo anchor")
    ap.add_argument("--serve", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.serve:
        return serve()
    import scaling
    print(scaling.describe_run(), flush=True)
    start = time.perf_counter()

    def log(text):
        print(f"[{time.perf_counter() - start:5.0f} s] {text}", flush=True)
    sizes = QUICK_SIZES if args.quick else SIZES
    count = QUICK_STATES if args.quick else STATES
    rounds = QUICK_ROUNDS if args.quick else ROUNDS
    errors: list = []

    ok, found = reference_self_check()
    log(f"reference self-check ({DIGITS} digits against two other derivations): "
        f"{'ok' if ok else 'FAILED'} ({found})")
    if not ok:
        errors.append(f"the exact reference disagrees with its checks ({found})")
    try:
        library = pinocchio_library(log)
    except RuntimeError as exc:
        print(f"Pinocchio: {exc}")
        return 1

    srcs = [p.resolve() for p in (args.src or [ROOT / "src"])]
    labels = ["this tree" if p == (ROOT / "src").resolve() else str(p) for p in srcs]
    logs = Path(tempfile.mkdtemp(prefix="autolev-anchors-logs-"))
    trees = []
    try:
        for p, label in zip(srcs, labels):
            trees.append(Tree(p, label, library, logs))
            trees[-1].hello()
        return report(args, trees, sizes, count, rounds, errors, log, start)
    except RuntimeError as exc:
        print(f"error: {exc}")
        return 1
    finally:
        for t in trees:
            t.close()


def report(args, trees, sizes, count, rounds, errors, log, start) -> int:
    k_trees = range(len(trees))
    for k, t in zip(k_trees, trees):
        print(f"  [{k}] {t.label}: autolev from {t.info['module']}")
    cxx = os.environ.get("CXX", "g++")
    print(f"  ours: {trees[-1].info['cc']} {' '.join(trees[-1].info['flags'])} (generated "
          "code; loop.c with the solve at -O3)\n"
          f"  Pinocchio: {cxx} ({compiler_version(cxx)}) {' '.join(PINOCCHIO_FLAGS)}",
          flush=True)

    states = {n: random_states(n, count) for n in sizes}
    built: dict = {k: {} for k in k_trees}
    for n in sizes:
        q, u = states[n]
        for k, t in zip(k_trees, trees):
            built[k][n] = t.ask("chain", n=n, q=q.tolist(), u=u.tolist())
            theirs = np.array(built[0][n]["pinocchio"])
            ours = np.array(built[k][n]["ours"])
            agree = float(np.max(np.max(np.abs(ours - theirs), axis=1)
                                 / np.max(np.abs(theirs), axis=1)))
            built[k][n]["agree"] = agree
            if not agree <= AGREE:
                errors.append(f"[{k}] n = {n}: ours and Pinocchio differ by {agree:.1e} "
                              f"relative (more than {AGREE:g})")
            log(f"[{k}] planar {n}: built in {built[k][n]['seconds']:.1f} s; ours and "
                f"Pinocchio agree to {agree:.1e} at {count} states")

    # timings: rounds over every n and tree, ours and Pinocchio alternating which is first
    samples = {k: {n: [] for n in sizes} for k in k_trees}
    for r in range(rounds):
        for n in sizes:
            q, u = states[n]
            order = list(k_trees) if r % 2 == 0 else list(reversed(k_trees))
            for k in order:
                samples[k][n].append(trees[k].ask("time", n=n, q=q[0].tolist(),
                                                  u=u[0].tolist(), budget=0.2, repeats=5,
                                                  pinocchio_first=bool((r + k) % 2)))
        log(f"timing round {r + 1}/{rounds} done")
    timing: dict = {k: {} for k in k_trees}
    timing["pinocchio"] = {}
    for n in sizes:
        for k in k_trees:
            timing[k][n] = {key: statistics.median(s[key] for s in samples[k][n])
                            for key in ("ours", "rhs")}
            timing[k][n]["range"] = (min(s["ours"] for s in samples[k][n]),
                                     max(s["ours"] for s in samples[k][n]))
        timing["pinocchio"][n] = statistics.median(s["pinocchio"] for k in k_trees
                                                   for s in samples[k][n])

    accuracy: dict = {}
    if ok_reference(errors):
        for n in sizes:
            q, u = states[n]
            exact = [exact_accelerations(qi, ui) for qi, ui in zip(q, u)]
            accuracy[n] = {"pinocchio": relative_errors(built[0][n]["pinocchio"], exact)}
            for k in k_trees:
                accuracy[n][k] = relative_errors(built[k][n]["ours"], exact)
            log(f"planar {n}: exact reference at {count} states done")

    sims = {}
    for k, t in zip(k_trees, trees):
        try:
            sims[k] = t.ask("simulate", n=8, repeats=5)
        except RuntimeError as exc:
            errors.append(str(exc))
    log("planar 8 simulate() against its C loop: done")

    mujoco = None
    if args.no_mujoco:
        mujoco = "skipped (--no-mujoco)"
    elif (len(trees) - 1) not in sims:
        mujoco = "skipped: no 8-link run of ours"
    else:
        try:
            import mujoco as _mj                    # noqa: F401
        except ImportError as exc:
            mujoco = f"skipped: mujoco is not importable ({exc})"
        else:
            mujoco = mujoco_anchor(sims[len(trees) - 1], 8, log)
            if not mujoco["agree"] <= AGREE:
                errors.append(f"MuJoCo's initial accelerations differ from ours by "
                              f"{mujoco['agree']:.1e} relative")

    gait = {}
    for k, t in zip(k_trees, trees):
        if not GAIT3D.exists():
            gait[k] = {"skip": f"not in the corpus ({GAIT3D})"}
            continue
        log(f"[{k}] gait3d: loading (built on a cold cache: several minutes)")
        try:
            gait[k] = t.ask("gait3d", path=str(GAIT3D), budget=0.2, repeats=5,
                            rounds=rounds)
        except RuntimeError as exc:
            gait[k] = {"skip": str(exc)}

    print_tables(trees, sizes, count, rounds, built, timing, accuracy, sims, mujoco, gait)
    print_targets(trees, sizes, timing, built, accuracy, sims)
    png = OUT / "anchors.png"
    if plot(png, sizes, timing, [t.label for t in trees]):
        print(f"\nwrote {png.relative_to(ROOT)}")
    else:
        print("\nmatplotlib not importable: no plot written")
    print(f"total {time.perf_counter() - start:.0f} s")
    if errors:
        print("errors:\n  " + "\n  ".join(errors))
        return 1
    return 0


def ok_reference(errors: list) -> bool:
    """No accuracy numbers from a reference that failed its self-check."""
    return not any(e.startswith("the exact reference") for e in errors)


def print_tables(trees, sizes, count, rounds, built, timing, accuracy, sims, mujoco, gait):
    ks = range(len(trees))

    def tag(k):
        return f"[{k}] " if len(trees) > 1 else ""
    print(f"\nper evaluation, planar n-link chain (microseconds; median of {rounds} "
          "alternated rounds,\neach a median of 5 timed loops; rounds: ours' least and "
          "largest; solve share = 1 - rhs\nalone / whole; C KB = generated source)")
    head = f"{'n':>3} {'Pinocchio':>10}" + "".join(
        f" {tag(k) + 'ours':>10} {'rounds':>13} {'ours/Pin':>8} {'solve %':>7} {'C KB':>7}"
        for k in ks)
    print(head)
    for n in sizes:
        pin = timing["pinocchio"][n]
        cells = f"{n:3d} {pin:10.3f}"
        for k in ks:
            t = timing[k][n]
            size = built[k][n]["source_bytes"]
            low, high = t["range"]
            cells += (f" {t['ours']:10.3f} {f'{low:.3g}-{high:.3g}':>13} {t['ours'] / pin:8.2f} "
                      f"{100 * (1 - t['rhs'] / t['ours']):7.0f} "
                      + (f"{size / 1e3:7.1f}" if size else f"{'-':>7}"))
        print(cells)

    print("\ngrowth from n = 16 to 32 (log2 of the ratio: the exponent of n)")
    pin_growth = growth(timing["pinocchio"])
    if pin_growth is None:
        print("  not measured (needs n = 16 and 32)")
    else:
        print(f"  Pinocchio time {pin_growth:.2f}")
        for k in ks:
            size = {n: built[k][n]["source_bytes"] for n in sizes}
            code = growth(size)
            print(f"  {tag(k)}ours time {growth({n: timing[k][n]['ours'] for n in sizes}):.2f}"
                  f", code size " + (f"{code:.2f}" if code is not None else "-"))

    if accuracy:
        print(f"\nrelative acceleration error against the {DIGITS}-digit reference over "
              f"{count} random states\n(||a - a_exact||_inf / ||a_exact||_inf: max, median)")
        print(f"{'n':>3} {'Pinocchio max':>14} {'median':>9}" + "".join(
            f" {tag(k) + 'ours max':>14} {'median':>9}" for k in ks))
        for n in sizes:
            e = accuracy[n]
            print(f"{n:3d} {e['pinocchio'].max():14.1e} {np.median(e['pinocchio']):9.1e}"
                  + "".join(f" {e[k].max():14.1e} {np.median(e[k]):9.1e}" for k in ks))
    else:
        print("\naccuracy: not shown (the reference failed its self-check)")

    print("\nplanar 8-link, 10 s, DOP853, RELERR = ABSERR = 1e-8, warm (best of 5 each)")
    for k in ks:
        s = sims.get(k)
        if s is None:
            print(f"  {tag(k)}failed")
            continue
        print(f"  {tag(k)}whole simulate() {s['whole'] * 1e3:.2f} ms; inside the C loop "
              f"{s['loop'] * 1e3:.2f} ms (whole/loop {s['whole'] / s['loop']:.2f}; "
              f"{100 * (1 - s['loop'] / s['whole']):.0f} % outside); stats['seconds'] "
              f"{s['integration'] * 1e3:.2f} ms; {s['evaluations']} evaluations, "
              f"{s['steps']} steps, {s['rows']} rows")

    print("\nMuJoCo anchor (8-link, RK4 stepped by mujoco.rollout in C, its per-step state "
          "output included)")
    if isinstance(mujoco, str):
        print(f"  {mujoco}")
    else:
        last = len(trees) - 1
        print(f"  initial accelerations: MuJoCo's qacc against ours {mujoco['agree']:.1e} "
              "relative")
        print(f"  our 1e-8 run's end error at T = 10 s (against our 1e-12 run): "
              f"{mujoco['target']:.2e}")
        if "skip" in mujoco:
            print(f"  {mujoco['skip']}")
        else:
            s = sims[last]
            print(f"  MuJoCo RK4 with the same end error: {mujoco['steps']} steps of "
                  f"{mujoco['dt']:.3g} s (end error {mujoco['end_error']:.2e}): "
                  f"{mujoco['seconds'] * 1e3:.1f} ms")
            print(f"  {tag(last)}ours/MuJoCo: C loop {s['loop'] / mujoco['seconds']:.3f}, "
                  f"whole simulate() {s['whole'] / mujoco['seconds']:.3f}")

    print("\ngait3d pelvis213 (BioMAC), forward dynamics of its equations as they stand")
    for k in ks:
        g = gait[k]
        if "skip" in g:
            print(f"  {tag(k)}skipped: {g['skip']}")
        else:
            (low, high), (rlow, rhigh) = g["range"], g["rhs_range"]
            print(f"  {tag(k)}{g['speeds']} speeds: {g['ours']:.1f} us per evaluation "
                  f"({low:.1f} to {high:.1f}), rhs alone {g['rhs']:.1f} us ({rlow:.1f} to "
                  f"{rhigh:.1f}): medians (extremes) of {rounds} rounds; C source "
                  f"{g['source_bytes'] / 1e3:.0f} KB; loaded and built in {g['build']:.1f} s")


def print_targets(trees, sizes, timing, built, accuracy, sims):
    targets = []

    def check(name, value, ok, fmt=".3g"):
        verdict = "NOT RUN" if value is None else ("PASS" if ok(value) else "FAIL")
        shown = "not measured" if value is None else format(value, fmt)
        targets.append((verdict, name, shown))
    for k in range(len(trees)):
        tag = f" [{k}]" if len(trees) > 1 else ""
        ratio = {n: timing[k][n]["ours"] / timing["pinocchio"][n] for n in sizes}
        measured = ", ".join(map(str, sizes))
        check(f"per evaluation <= 1.0x Pinocchio at every n <= 32{tag} (largest ratio; "
              f"n = {measured})", max(ratio.values()), lambda v: v <= 1.0, ".2f")
        check(f"per evaluation <= 0.3x Pinocchio at n <= 8{tag} (largest ratio)",
              max(r for n, r in ratio.items() if n <= 8), lambda v: v <= 0.3, ".2f")
        check(f"time grows <= n^1.5 from 16 to 32{tag} (exponent)",
              growth({n: timing[k][n]["ours"] for n in sizes}), lambda v: v <= 1.5, ".2f")
        check(f"code grows <= n^1.5 from 16 to 32{tag} (exponent)",
              growth({n: built[k][n]["source_bytes"] for n in sizes}), lambda v: v <= 1.5,
              ".2f")
        err = accuracy.get(32, {}).get(k)
        check(f"relative acceleration error <= 1e-13 at n = 32{tag} (max)",
              None if err is None else float(err.max()), lambda v: v <= 1e-13, ".1e")
        s = sims.get(k)
        check(f"whole simulate() <= 1.3x its C loop, planar 8{tag}",
              None if s is None else s["whole"] / s["loop"], lambda v: v <= 1.3, ".2f")
    print("\ntargets:")
    for verdict, name, shown in targets:
        print(f"  {verdict:7s} {name}  ({shown})")


if __name__ == "__main__":
    sys.exit(main())
