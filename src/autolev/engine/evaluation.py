"""A system's compiled functions evaluated: the state derivatives (the right-hand side
and the solve of the mass matrix), the outputs at print times, and the compiled
integration loop over them.  No sympy: NumericSystem (system.py) is one, and so is a
run plan's system, which a warm run reads without the model.
"""
from __future__ import annotations

import math

import numpy as np

from .cloop import CompiledLoop
from .massmatrix import SingularMassMatrix, solve_mass_matrix, symmetric


def pivot_ratios(rhs_out: np.ndarray, pivot_count: int) -> np.ndarray:
    """A recursion's pivots over the entries they come from, the last outputs of its
    right-hand side (pivots, then entries; NaN for 0 over 0), along the last axis."""
    end = rhs_out.shape[-1]
    pivots = rhs_out[..., end - 2 * pivot_count:end - pivot_count]
    with np.errstate(divide="ignore", invalid="ignore"):
        return pivots / rhs_out[..., end - pivot_count:]


def _ready(pending, wait: bool) -> bool:
    """Whether a background compile (or None) is to be taken now: built, or waited for."""
    return pending is not None and (wait or pending.done())


class CompiledEvaluation:
    """Evaluation of compiled functions, over what a subclass holds: nstate; _n and
    unknown_positions (the accelerations M a = f solves, and where they go in the
    state); n_rhs, n_outputs; rhs_function, output_function, extra_functions
    ({name: (function, size)}); solved (the unknowns the caller supplies at output
    time); mass_structure (how the mass matrix is factored if it is symmetric, or None:
    massmatrix.MassStructure); _factoring (the structure at the constants set, or None);
    constant_values, specified_values, specified_functions; rhs_compiling and
    outputs_compiling (the right-hand side's and the outputs' C being compiled while
    their Python runs, or None);
    constants_function and derived_constants (the constants computed from the
    parameters, and how many); pivot_count (a recursion's pivots, whose values and
    entries are the last outputs of the right-hand side, or 0)."""

    def set_parameters(self, values: np.ndarray) -> None:
        """Parameter values (in the system's order); evaluates the constants once."""
        p = np.asarray(values, dtype=float)
        cd = np.empty(self.derived_constants)
        if len(cd):
            self.constants_function.call(p, cd)
        self.set_constant_values(np.concatenate([p, cd]))

    def set_constant_values(self, values: np.ndarray) -> None:
        """The constants' values (parameters, then what is computed from them)."""
        self.constant_values = values
        self._factoring = self._factoring_at(values)
        if self.loop is not None:
            self.loop.set_values(self.constant_values, self.specified_values)
            self.loop.set_structure(self._factoring)

    def _factoring_at(self, values: np.ndarray):
        """The mass matrix's structure when it is symmetric at these constants (proven
        from its expressions, or judged at two random states and specified values),
        else None: it is solved by pivoting."""
        structure = self.mass_structure
        if structure is None or structure.proven:
            return structure
        if self.rhs_function is None:       # not compiled (a linearization's): no solve
            return None
        rng = np.random.default_rng(0)
        ns, n = self.nstate, self._n
        out = np.empty(self.n_rhs)
        matrices = []
        for _ in range(2):
            x = rng.uniform(-1.0, 1.0, ns)
            s = rng.uniform(-1.0, 1.0, len(self.specified_values))
            with np.errstate(all="ignore"):
                self.rhs_function.call(np.array([0.5]), x, values, s, out)
            matrices.append(out[ns:ns + n * n].reshape(n, n).copy())
        return structure if symmetric(np.array(matrices)) else None

    def _bind_loop(self) -> None:
        """The compiled integration loop and the CPython entry point of the right-hand
        side, when it is C."""
        self.loop = None
        if self.rhs_function is not None and self.rhs_function.backend == "c":
            call = self.rhs_function.call
            self.loop = CompiledLoop(call.lib, self.nstate, self.unknown_positions,
                                     call.work, self.n_rhs)
        self._rhs_out = np.empty(self.n_rhs)
        self._py = self.loop.python_entry if self.loop is not None else None
        self._py_ctx = self.loop.context_address if self.loop is not None else None

    # -- pickling (a NumericSystem with its model, a run plan's system alone) -------------
    _UNPICKLED = ("loop", "_rhs_out", "_py", "_py_ctx", "specified_functions",
                  "rhs_compiling", "outputs_compiling", "_factoring")

    def __getstate__(self) -> dict:
        """What rebuilds the system: its expressions (a NumericSystem's) and its
        functions' sources; not the loaded libraries, nor a run's specified functions.
        C still compiling is waited for: the system kept is the compiled one."""
        self.compiled_loop(wait=True)
        return {k: v for k, v in self.__dict__.items() if k not in self._UNPICKLED}

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self.specified_functions = []
        self.rhs_compiling = self.outputs_compiling = None
        self._factoring = None
        self._bind_loop()
        if self.constant_values is not None:
            self.set_constant_values(self.constant_values)

    def compiling(self) -> bool:
        """Whether C of the right-hand side or the outputs is still compiling."""
        return any(pending is not None and not pending.done()
                   for pending in (self.rhs_compiling, self.outputs_compiling))

    def compiled_loop(self, wait: bool = False):
        """The compiled integration loop, or None while the right-hand side's C is still
        compiling (NumericSystem.compile(background=True)): it replaces the Python one
        as soon as it is built (`wait`: once it is), as the outputs' C replaces theirs."""
        self._take_outputs(wait)
        if _ready(self.rhs_compiling, wait):
            pending, self.rhs_compiling = self.rhs_compiling, None
            function = pending.function()
            if function is not None:
                self.rhs_function = function
                self._bind_loop()
                if self.constant_values is not None:
                    self.set_constant_values(self.constant_values)
        return self.loop

    def _take_outputs(self, wait: bool) -> None:
        """The outputs' C in place of their Python once it is built (or waited for)."""
        if _ready(self.outputs_compiling, wait):
            pending, self.outputs_compiling = self.outputs_compiling, None
            self.output_function = pending.function() or self.output_function

    def _fill_specified(self, t, x) -> np.ndarray:
        s = self.specified_values
        for i, fn in self.specified_functions:
            s[i] = fn(t, x)
        return s

    def derivatives(self, t: float, x: np.ndarray) -> np.ndarray:
        """State derivatives at (t, x): a fresh array.  A recursion's derivatives that
        are not finite where one of its pivots is not positive: SingularMassMatrix, as
        the mass matrix's solve says."""
        xdot = self._derivatives(t, x)
        if self.pivot_count and not math.isfinite(xdot.sum()):
            ratios = self.last_pivot_ratios()
            if not np.all(ratios > 0):
                raise SingularMassMatrix(t)
        return xdot

    def _derivatives(self, t: float, x: np.ndarray) -> np.ndarray:
        if self.specified_functions:
            self._fill_specified(t, x)
        elif self._py is not None:      # loop.derivatives inlined: the common case, in
            #                             as few Python calls as possible
            try:
                xdot = self._py(self._py_ctx, t, x)
            except (TypeError, ValueError):
                pass                    # not a contiguous float64 array: below
            else:
                if xdot is None:
                    raise SingularMassMatrix(t)
                return xdot
        s = self.specified_values
        if self.loop is not None:
            xdot, status = self.loop.derivatives(t, x)
            if status:
                raise SingularMassMatrix(t)
            return xdot
        out = self._rhs_out
        self.rhs_function.call(np.array([t]), x, self.constant_values, s, out)
        ns = self.nstate
        xdot = out[:ns].copy()
        n = self._n
        if n:
            mm = out[ns:ns + n * n].reshape(n, n)
            f = out[ns + n * n:ns + n * n + n]
            xdot[self.unknown_positions] = solve_mass_matrix(mm, f, t, self._factoring)
        return xdot

    def last_mass_matrix(self) -> np.ndarray | None:
        """The mass matrix of the last evaluation of the derivatives (None when the
        model solves no accelerations)."""
        n, ns = self._n, self.nstate
        if not n:
            return None
        out = self.loop.out_buffer if self.loop is not None else self._rhs_out
        return np.array(out[ns:ns + n * n]).reshape(n, n)

    def last_pivot_ratios(self) -> np.ndarray | None:
        """The recursion's pivots over the entries they come from at the last evaluation
        of the derivatives (NaN for 0 over 0; None for a mass matrix's system)."""
        if not self.pivot_count:
            return None
        out = self.loop.out_buffer if self.loop is not None else self._rhs_out
        return pivot_ratios(out[:self.n_rhs], self.pivot_count)

    def last_conditioning(self) -> np.ndarray | None:
        """What the conditioning of the last evaluation is judged by: the recursion's
        pivot ratios, else the mass matrix (None: no accelerations solved)."""
        return self.last_pivot_ratios() if self.pivot_count else self.last_mass_matrix()

    def _accel_inputs(self, t, x, xdot, solved) -> np.ndarray:
        parts = []
        if self._n:
            if xdot is None:
                try:
                    xdot = self.derivatives(t, x)
                except SingularMassMatrix:          # outputs that need them are NaN
                    xdot = np.full(self.nstate, np.nan)
            parts.append(xdot[self.unknown_positions])
        if self.solved:
            parts.append(np.asarray(solved, dtype=float))
        return np.concatenate(parts) if parts else np.zeros(0)

    def _call(self, fn, size, t, x, xdot=None, solved=()) -> np.ndarray:
        x = np.asarray(x, dtype=float)
        a = self._accel_inputs(t, x, xdot, solved)
        s = self._fill_specified(t, x) if self.specified_functions else self.specified_values
        out = np.empty(size)
        fn.call(np.array([t]), x, self.constant_values, s, a, out)
        return out

    def outputs(self, t: float, x=(), xdot=None, solved=()) -> np.ndarray:
        """Every output column and ENCODE value at (t, x), in internal units."""
        self._take_outputs(False)
        return self._call(self.output_function, self.n_outputs, t, x, xdot, solved)

    def outputs_rows(self, times: np.ndarray, states: np.ndarray) -> tuple:
        """The outputs at many (t, x) rows of a run in one call of their function: (rows
        x columns, and each row's last_conditioning() or None); the accelerations solved at
        each row (NaN where M is singular).  Rows whose specified quantities are Python
        functions of (t, x) go one by one."""
        self._take_outputs(False)
        n, ns = self._n, self.nstate
        count = len(times)
        out = np.empty((count, self.n_outputs))
        matrices = [] if n else None
        if self.specified_functions or self.solved:
            for i in range(count):
                out[i] = self.outputs(times[i], states[i])
                if n:
                    matrices.append(self.last_conditioning())
            return out, matrices
        accelerations = np.empty((count, n))
        for i in range(count):
            if n:
                try:
                    xdot = self.derivatives(times[i], states[i])
                except SingularMassMatrix:
                    xdot = np.full(ns, np.nan)
                accelerations[i] = xdot[self.unknown_positions]
                matrices.append(self.last_conditioning())
        t = np.ascontiguousarray(times, dtype=float).reshape(count, 1)
        x = np.ascontiguousarray(states, dtype=float).reshape(count, ns)
        self.output_function.call.rows(
            [t, x, self.constant_values, self.specified_values, accelerations],
            [True, True, False, False, True], out)
        return out, matrices

    def extra(self, name: str, t: float, x=(), solved=()) -> np.ndarray:
        fn, size = self.extra_functions[name]
        return self._call(fn, size, t, x, None, solved)
