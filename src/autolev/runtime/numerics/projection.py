"""Projection onto configuration constraints.

Autolev's equations carry the constraints of a closed loop at the velocity level only
(the dependent speeds are solved from them at every evaluation), so the coordinates of
a loop drift off the loop as errors accumulate.  Given the configuration constraints
g(q) themselves, a run can be brought back onto g(q) = g(q0) at every print time: the
smallest correction of the state (Gauss-Newton with the minimum-norm step
G^T (G G^T)^-1 r, G = dg/dx) until the residual is at rounding level.  The integrator
restarts from the projected state on each print interval.
"""
from __future__ import annotations

import numpy as np
import sympy as sm

from .. import symbols as S
from ...engine.errors import AutolevModelError
from . import codegen
from .compiled import compile_program
from .system import alphabetical


class Projector:
    """g(x) and dg/dx compiled for a NumericSystem; projects states onto g = g(x0)."""

    def __init__(self, system, constraints, t0: float, x0, extra_values=(),
                 max_iter: int = 10):
        """`extra_values`: values of `constants_needed(system, constraints)`."""
        exprs = _expressions(constraints)
        for e in exprs:
            if not isinstance(e, sm.Expr):
                raise AutolevModelError(f"a constraint must be a scalar expression: {e}")
        states = list(system.states)
        jac = system.defs.jacobian(exprs, states)
        if all(d == 0 for row in jac for d in row):
            raise AutolevModelError("the constraints do not depend on the state")
        inputs = {"t": [S.TIME],
                  "x": states,
                  "c": system.params + system.constant_defs
                  + constants_needed(system, exprs),
                  "s": system.specified}
        prog = codegen.Program(inputs, exprs + [d for row in jac for d in row], system.defs,
                               dict(system.aux_fixed)).build()
        self.function = compile_program(prog, system.backend, "autolev_constraints")
        self.system = system
        self._c = np.concatenate([system.constant_values,
                                  np.asarray(extra_values, dtype=float)])
        self.k = len(exprs)
        self.n = len(states)
        self.max_iter = max_iter
        self.target = self.residual_and_jacobian(t0, np.asarray(x0, float))[0]
        self.largest_correction = 0.0

    def residual_and_jacobian(self, t, x):
        out = np.empty(self.k + self.k * self.n)
        self.function.call(np.array([t]), x, self._c, self.system.specified_values, out)
        return out[:self.k], out[self.k:].reshape(self.k, self.n)

    def __call__(self, t: float, x: np.ndarray) -> np.ndarray:
        x = np.array(x, dtype=float)
        x0 = x.copy()
        tol = 1e-13 * (1.0 + np.abs(self.target).max())
        for _ in range(self.max_iter):
            g, jac = self.residual_and_jacobian(t, x)
            r = g - self.target
            if np.abs(r).max() <= tol:
                break
            step, *_ = np.linalg.lstsq(jac, r, rcond=None)
            x -= step
        self.largest_correction = max(self.largest_correction, float(np.abs(x - x0).max()))
        return x


def _expressions(constraints) -> list:
    return [sm.sympify(c) for c in constraints]


def constants_needed(system, constraints) -> list:
    """Constants the constraints use that the equations of motion do not (their
    values are inputs of the run too), in alphabetical order."""
    exprs = _expressions(constraints)
    given = set(system.states) | {S.TIME} | set(system.aux_fixed) | set(system.params)
    _, undefined = system.needed(exprs, given)
    return alphabetical(s for s in undefined if not system.is_specified(s))
