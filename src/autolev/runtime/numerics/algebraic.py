"""Evaluating a CODE ALGEBRAIC or NONLINEAR command: once, or once per value of
its sweep, solving its linear equations or Newton's method first.
"""
from __future__ import annotations

import warnings

import numpy as np

from .. import symbols as S
from ..errors import AutolevModelError
from ..io import CodeKind
from .advice import zero_hint
from .inputs import display_name
from .results import split_outputs, tables_of


def run_algebraic(system, inputs, result, writer, kind, unknowns, sweep, zero_params,
                   keep_rows: bool = True):
    """Evaluate (and solve) once, or once per value of the sweep, made and written one
    at a time; with `keep_rows` False the Result holds only the last row."""
    rows = [[] for _ in system.files]
    encoded: dict = {}
    solutions, swept = [], []
    points = [None] if sweep is None else sweep
    n = len(unknowns)
    guess = np.array(inputs.vector(unknowns)) if kind.from_guesses else np.zeros(n)
    base = inputs.vector(system.params)
    t = inputs.internal(S.TIME) if S.TIME in inputs.values else 0.0
    target_pos = None
    if sweep is not None:
        if sweep.target in system.params:
            target_pos = system.params.index(sweep.target)
        else:
            warnings.warn(f"the swept input {display_name(sweep.target)} does not enter the "
                          "outputs", stacklevel=3)
    for point in points:
        if not keep_rows:
            rows = [[] for _ in system.files]
            del solutions[:], swept[:]
        if point is not None and target_pos is not None:
            p = list(base)
            p[target_pos] = point[0]
            system.set_parameters(p)
        if kind is CodeKind.ALGEBRAIC and n:
            # the coefficients hold no unknown, but the compiled function takes their
            # slots (Python's reads them; C's read past an empty array)
            ab = system.extra("linear", t, solved=np.zeros(n))
            a = ab[:n * n].reshape(n, n)
            b = ab[n * n:]
            x = _linear_solve(a, -b, zero_params)
        elif kind is CodeKind.NONLINEAR:
            x = _newton(system, guess, t, inputs.internal("ABSERR"),
                        inputs.internal("RELERR"), unknowns, zero_params)
            guess = x
        else:
            x = np.zeros(0)
        solutions.append(x)
        if point is not None:
            swept.append(point[1])
        values = system.outputs(t, np.zeros(0), None, x)
        split_outputs(system, values, rows, writer, encoded)
    result.t = np.array(swept, dtype=float)
    result.solution = {display_name(u): np.array([s[i] for s in solutions])
                       for i, u in enumerate(unknowns)}
    result.outputs = tables_of(system, rows, result.name)
    result.encoded = encoded


def _linear_solve(a, b, zero_params):
    import scipy.linalg  # 0.1 s to import: only CODE ALGEBRAIC's solves pay it
    try:
        lu, piv = scipy.linalg.lu_factor(a, check_finite=True)
    except (ValueError, np.linalg.LinAlgError):
        raise AutolevModelError("CODE ALGEBRAIC: the equations' coefficients are not "
                                "finite" + zero_hint(zero_params)) from None
    if np.any(np.diag(lu) == 0):
        raise AutolevModelError("CODE ALGEBRAIC: the equations are singular for these "
                                "inputs" + zero_hint(zero_params))
    return scipy.linalg.lu_solve((lu, piv), b)


def _newton(system, x0, t, abserr, relerr, unknowns, zero_params, max_iter: int = 50):
    """Newton's method from the guesses; converged when every step is within
    max(ABSERR, RELERR*|x|) and the residual is small."""
    x = np.array(x0, dtype=float)
    n = len(x)
    for _ in range(max_iter):
        r = system.extra("residual", t, (), x)
        j = system.extra("jacobian", t, (), x).reshape(n, n)
        if not (np.all(np.isfinite(r)) and np.all(np.isfinite(j))):
            raise AutolevModelError("CODE NONLINEAR: the equations are not finite at "
                                    + _at(unknowns, x) + zero_hint(zero_params))
        try:
            dx = np.linalg.solve(j, -r)
        except np.linalg.LinAlgError:
            raise AutolevModelError("CODE NONLINEAR: the Jacobian is singular at "
                                    + _at(unknowns, x)) from None
        x = x + dx
        if np.all(np.abs(dx) <= np.maximum(abserr, relerr * np.abs(x))):
            return x
    raise AutolevModelError(f"CODE NONLINEAR: Newton's method did not converge in "
                            f"{max_iter} iterations (last {_at(unknowns, x)}); try other "
                            "guesses")


def _at(unknowns, x) -> str:
    return ", ".join(f"{display_name(u)} = {v:.6g}" for u, v in zip(unknowns, x))
