"""The compiled integration loop (loop.c) driven from Python.

A model's right-hand side is compiled together with loop.c into one library; this
module holds the evaluation context (the arrays the C code reads and writes, kept
alive here) and runs Autolev's Kutta-Merson or DOP853 over the whole print grid in
C, a slice of right-hand-side calls at a time so that progress can be shown.  The
rows, the failures and their messages are those of the Python loops in
integrate.py; the same steps are taken (tests compare the two).
"""
from __future__ import annotations

import ctypes
import functools
import importlib.machinery
import importlib.util
import math
import os
import sysconfig
import time as _time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .integrators import DOP853, integrator_named
from .massmatrix import LTDL_SOURCE

LOOP_SOURCE = (Path(__file__).with_name("loop.c")).read_text()
PYEXT_SOURCE = (Path(__file__).with_name("pyext.c")).read_text()


def python_include() -> str | None:
    """The folder of Python.h when this Python has its headers, and numpy its own
    (then the library also carries a CPython entry point, pyext.c), else None."""
    inc = sysconfig.get_paths().get("include")
    if inc and (Path(inc) / "Python.h").exists() and \
            (Path(np.get_include()) / "numpy" / "arrayobject.h").exists() and \
            not os.environ.get("AUTOLEV_NO_PYEXT"):
        return inc
    return None


def extra_source() -> tuple[str, tuple]:
    """(C appended to a right-hand side, extra compiler flags): the loop, after ltdl.c
    (whose factorization its mass matrix's solve uses)."""
    loop = "\n" + LTDL_SOURCE + "\n" + LOOP_SOURCE
    inc = python_include()
    if inc is None:
        return loop, ()
    return loop + "\n" + PYEXT_SOURCE, ("-I" + inc, "-I" + np.get_include())


def _load_extension(path: str):
    """The CPython module inside a library built with PYEXT_SOURCE, or None."""
    loader = importlib.machinery.ExtensionFileLoader("_autolev_rhs", path)
    spec = importlib.util.spec_from_file_location("_autolev_rhs", path, loader=loader)
    if spec is None:
        return None
    try:
        module = importlib.util.module_from_spec(spec)
    except ImportError:
        return None
    return module

# return codes and the layout of st[] / opts[] (loop.c's enums)
DONE, MORE, SINGULAR, SMALL_STEP, CUTS, NONFINITE, STIFF = range(7)
(ST_T, ST_H, ST_NUMCUTS, ST_NFEV, ST_NSTEP, ST_NREJ, ST_ROW, ST_STARTED, ST_HAVE_STEP,
 ST_TOLD, ST_HPREV, ST_FAIL_T, ST_FAIL_H, ST_IASTI, ST_NONSTI, ST_STIFF_T, ST_HLAMB,
 ST_KMROWS) = range(18)
ST_SIZE = 24
(OP_RTOL, OP_ATOL, OP_MAXSTEP, OP_TBOUND, OP_STIFF_STOP, OP_BUDGET, OP_INTEGSTP,
 OP_FRESH) = range(8)


@dataclass(frozen=True)
class KuttaMersonState:
    """Where Kutta-Merson's stepping stands between two INTEGSTP steps (loop.c's st[]):
    its step, the halvings it still allows, its stiffness counts and the time the
    stiffness test fired (nan: not yet)."""

    h: float
    numcuts: int
    iasti: int
    nonsti: int
    stiff_t: float

_P = ctypes.c_void_p


class _Context(ctypes.Structure):
    _fields_ = [("n", ctypes.c_int), ("m", ctypes.c_int), ("upos", _P), ("c", _P),
                ("s", _P), ("w", _P), ("out", _P), ("lu", _P), ("b", _P),
                ("yfail", _P), ("nfev", ctypes.c_double), ("order", _P), ("start", _P),
                ("col", _P), ("gather", _P)]


@functools.cache
def _table(method: str = DOP853.name) -> np.ndarray:
    """A method's tables as one array, in the order the C loop reads them (the shipped
    tableaux: no scipy import): DOP853's A (16 x 16), B, C, E3, E5, D (4 x 16);
    RK45's A (6 x 6), B, C, E; Kutta-Merson's none."""
    return np.array(integrator_named(method).tableau, dtype=float)


class CompiledLoop:
    """Evaluation and integration in C for one NumericSystem (its rhs library)."""

    def __init__(self, lib, nstate: int, unknown_pos, work: np.ndarray, nout: int):
        self.lib = lib
        self.n = nstate
        self.m = len(unknown_pos)
        self._upos = np.ascontiguousarray(unknown_pos, dtype=np.intc)
        self._w = work
        self.out_buffer = np.zeros(max(1, nout))
        self._lu = np.zeros(max(1, self.m * self.m))
        self._b = np.zeros(max(1, self.m))
        self.yfail = np.zeros(max(1, nstate))
        self._c = np.zeros(1)
        self._s = np.zeros(1)
        self._structure = None
        ctx = self.ctx = _Context()
        ctx.n, ctx.m = nstate, self.m
        ctx.upos = self._upos.ctypes.data
        ctx.w = work.ctypes.data
        ctx.out = self.out_buffer.ctypes.data
        ctx.lu = self._lu.ctypes.data
        ctx.b = self._b.ctypes.data
        ctx.yfail = self.yfail.ctypes.data
        self._ctx_ref = ctypes.byref(ctx)
        fn = lib.autolev_derivatives
        fn.argtypes = [_P, ctypes.c_double, _P, _P]
        fn.restype = ctypes.c_int
        self._deriv = fn
        fn = lib.autolev_integrate
        fn.argtypes = [_P, ctypes.c_int, _P, _P, _P, ctypes.c_int, _P, _P, _P, _P, _P, _P]
        fn.restype = ctypes.c_int
        self._integrate = fn
        self.context_address = ctypes.addressof(ctx)
        self.python_entry = None
        if hasattr(lib, "PyInit__autolev_rhs"):
            module = _load_extension(lib._name)
            if module is not None:
                self.python_entry = module.rhs

    def set_values(self, c: np.ndarray, s: np.ndarray) -> None:
        """The constants and specifieds the evaluations read (kept referenced here)."""
        self._c = np.ascontiguousarray(c, dtype=float) if len(c) else np.zeros(1)
        self._s = s if len(s) else np.zeros(1)
        self.ctx.c = self._c.ctypes.data
        self.ctx.s = self._s.ctypes.data

    def set_structure(self, structure) -> None:
        """How the mass matrix is factored (massmatrix.MassStructure: M = L^T D L), or
        None: by pivoting."""
        self._structure = None
        ctx = self.ctx
        ctx.order = ctx.start = ctx.col = ctx.gather = None
        if structure is not None:
            columns = structure.columns
            gather = [structure.order[k] * self.m + structure.order[j]
                      for k, j in zip(structure.rows, columns)]
            arrays = [np.ascontiguousarray(v, dtype=np.intc)
                      for v in (structure.order, structure.starts, columns, gather)]
            self._structure = arrays        # kept referenced while the C reads them
            ctx.order, ctx.start, ctx.col, ctx.gather = (a.ctypes.data for a in arrays)

    def derivatives(self, t: float, x: np.ndarray) -> tuple[np.ndarray, int]:
        """(x', status): status 0, or SINGULAR (then self.yfail is x)."""
        if self.python_entry is not None:
            try:
                xdot = self.python_entry(self.context_address, t, x)
            except (TypeError, ValueError):
                pass       # not a contiguous float64 array (scipy's Jacobian columns
                #            are strided views): converted, as below
            else:
                return (xdot, 0) if xdot is not None else (np.full(self.n, np.nan),
                                                           SINGULAR)
        xdot = np.empty(self.n)
        x = np.ascontiguousarray(x, dtype=float)
        r = self._deriv(self._ctx_ref, float(t), x.ctypes.data, xdot.ctypes.data)
        return xdot, r

    def run(self, method: str, y0, blocks, opts: dict, on_rows, progress=None,
            stiff_stop: bool = False, budget: float = 2000.0, adapt: bool = True,
            steps_state: KuttaMersonState | None = None) -> dict:
        """Integrate from y0 at opts['t0'] over `blocks` of the schedule, (times,
        printed, end) each; Kutta-Merson, and RK45 started afresh over each step: the T
        after every INTEGSTP step and which are printed (end None); DOP853: the print
        times (printed None) and the end it may step to (see
        Schedule.bounded_print_blocks).  The state carries from block to block, so only
        one block's rows are in memory.  on_rows(t_array, rows) gets the rows of
        each slice.  `budget`: right-hand-side calls in the first slice (later slices
        are sized to about 0.1 s each unless `adapt` is false).
        Returns a dict: status, t (of the last accepted state), y, stats, fail_t,
        fail_h, stiff_t, hlamb, and rest (DOP853: the print times of the current block
        not reached when it stopped).  `steps_state`: Kutta-Merson's state where Python
        stepped until now (KuttaMerson.steps_state): its step and stiffness counts."""
        integrator = integrator_named(method)
        code, stepped = integrator.loop_code, integrator.stepped
        n = self.n
        y = np.array(y0, dtype=float)
        st = np.zeros(ST_SIZE)
        st[ST_T] = opts["t0"]
        st[ST_NUMCUTS] = 20
        st[ST_STIFF_T] = math.nan
        if steps_state is not None:
            st[ST_H], st[ST_NUMCUTS] = steps_state.h, steps_state.numcuts
            st[ST_IASTI], st[ST_NONSTI] = steps_state.iasti, steps_state.nonsti
            st[ST_STIFF_T] = steps_state.stiff_t
        op = np.zeros(8)
        op[OP_RTOL], op[OP_ATOL] = opts["rtol"], opts["atol"]
        op[OP_MAXSTEP] = opts.get("max_step", math.inf)
        op[OP_TBOUND] = opts["t0"]
        op[OP_STIFF_STOP] = 1.0 if stiff_stop else 0.0
        op[OP_INTEGSTP] = opts.get("integstp", 0.0)
        op[OP_FRESH] = 1.0 if opts.get("fresh") else 0.0
        work = np.zeros((16 + 8 + 7) * max(1, n))  # DOP853: 29 n, RK45: 11 n, K-M: 7 n
        table = _table(method)
        r = DONE
        times = np.zeros(0)
        for block, printed, end in blocks:
            times = np.ascontiguousarray(block, dtype=float)
            if end is not None:
                op[OP_TBOUND] = end
            flags = np.ascontiguousarray(printed if printed is not None else
                                         np.ones(len(times)), dtype=np.intc)
            nrows = int(flags.sum()) if stepped else len(times)
            rows = np.zeros((max(1, nrows), n))
            rtimes = np.zeros(max(1, nrows))
            st[ST_ROW] = st[ST_KMROWS] = 0
            done_rows = 0
            args = (self._ctx_ref, code, y.ctypes.data, st.ctypes.data, op.ctypes.data,
                    len(times), times.ctypes.data, flags.ctypes.data, rows.ctypes.data,
                    rtimes.ctypes.data, work.ctypes.data, table.ctypes.data)
            while True:
                op[OP_BUDGET] = budget
                start = _time.perf_counter()
                r = self._integrate(*args)
                elapsed = _time.perf_counter() - start
                written = int(st[ST_KMROWS] if stepped else st[ST_ROW])
                if written > done_rows:
                    t_rows = (rtimes[done_rows:written] if stepped
                              else times[done_rows:written])
                    on_rows(np.array(t_rows), rows[done_rows:written].copy())
                    done_rows = written
                if progress is not None:
                    progress.update(st[ST_T])
                if r != MORE:
                    break
                if adapt:       # slices of about a tenth of a second
                    budget = min(max(200.0, budget * (0.1 / max(elapsed, 1e-6))), 1e7)
            if r != DONE:
                break
        rest = np.zeros(0) if stepped else times[int(st[ST_ROW]):]
        stats = {"evaluations": int(st[ST_NFEV]), "steps": int(st[ST_NSTEP]),
                 "rejected": int(st[ST_NREJ])}
        return {"status": r, "t": float(st[ST_T]), "y": y, "stats": stats, "rest": rest,
                "fail_t": float(st[ST_FAIL_T]), "fail_h": float(st[ST_FAIL_H]),
                "stiff_t": float(st[ST_STIFF_T]), "hlamb": float(st[ST_HLAMB])}
