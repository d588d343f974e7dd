"""Evaluating a CODE ALGEBRAIC or NONLINEAR command: once, or once per value of
its sweep, solving its linear equations or Newton's method first.  Its inputs are
numbers (AlgebraicInputs, made by runtime/numerics/run.py from the model's): no sympy
here, so that a warm run executes a run plan's ALGEBRAIC and NONLINEAR commands too.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .code_kinds import CodeKind
from .errors import AutolevModelError
from .progress import Progress
from .results import split_outputs, tables_of


@dataclass
class AlgebraicInputs:
    """What an ALGEBRAIC or NONLINEAR evaluation reads, as numbers."""

    t: float                    # T, as the program reads its time
    parameters: list            # the constants' values, in the system's order
    guesses: list               # the unknowns' first guesses (NONLINEAR), else zeros
    abserr: float               # Newton's tolerances (NONLINEAR)
    relerr: float
    unknown_names: list
    swept: int | None           # the swept constant's place in `parameters`
    points: SweepPoints | None  # the sweep's points; None: once
    zero_hint: str              # what a failure says of the constants that are 0


@dataclass(frozen=True)
class SweepPoints:
    """The points of [q deg = start, stop, step], made one at a time as they are
    evaluated (a sweep of 1e8 points holds none of them): (internal, given) values,
    the given one start + step*k in the sweep's unit."""

    start: float
    step: float
    count: int
    degrees: bool               # given in degrees: internal in radians

    def __len__(self) -> int:
        return self.count

    def __iter__(self):
        for k in range(self.count):
            given = self.start + self.step * k
            yield (given * math.pi / 180 if self.degrees else given), given


def run_algebraic(system, given: AlgebraicInputs, result, writer, kind,
                  keep_rows: bool = True, progress=None):
    """Evaluate (and solve) once, or once per value of the sweep, made and written one
    at a time; with `keep_rows` False the Result holds only the last row.  A sweep
    longer than a second says how far it is on `progress` (a stream, or None)."""
    rows = [[] for _ in system.files]
    encoded: dict = {}
    solutions, swept = [], []
    points = [None] if given.points is None else given.points
    n = len(given.unknown_names)
    guess = np.array(given.guesses, dtype=float)
    t = given.t
    bar = Progress(progress, "point", 0, len(points))
    for k, point in enumerate(points):
        bar.update(k + 1)
        if not keep_rows:
            rows = [[] for _ in system.files]
            del solutions[:], swept[:]
        if point is not None and given.swept is not None:
            p = list(given.parameters)
            p[given.swept] = point[0]
            system.set_parameters(p)
        if kind is CodeKind.ALGEBRAIC and n:
            # the coefficients hold no unknown, but the compiled function takes their
            # slots (Python's reads them; C's read past an empty array)
            ab = system.extra("linear", t, solved=np.zeros(n))
            a = ab[:n * n].reshape(n, n)
            b = ab[n * n:]
            x = _linear_solve(a, -b, given.zero_hint)
        elif kind is CodeKind.NONLINEAR:
            x = _newton(system, guess, t, given.abserr, given.relerr, given.unknown_names,
                        given.zero_hint)
            guess = x
        else:
            x = np.zeros(0)
        solutions.append(x)
        if point is not None:
            swept.append(point[1])
        values = system.outputs(t, np.zeros(0), None, x)
        split_outputs(system, values, rows, writer, encoded)
    bar.done()
    result.t = np.array(swept, dtype=float)
    result.solution = {name: np.array([s[i] for s in solutions])
                       for i, name in enumerate(given.unknown_names)}
    result.outputs = tables_of(system, rows, result.name)
    result.encoded = encoded


def _linear_solve(a, b, zero_hint: str):
    # LAPACK's LU with partial pivoting through numpy (scipy's import alone is 0.2 s of
    # a warm run's 0.35)
    if not (np.all(np.isfinite(a)) and np.all(np.isfinite(b))):
        raise AutolevModelError("CODE ALGEBRAIC: the equations' coefficients are not "
                                "finite" + zero_hint)
    try:
        return np.linalg.solve(a, b)
    except np.linalg.LinAlgError:       # a pivot exactly 0
        raise AutolevModelError("CODE ALGEBRAIC: the equations are singular for these "
                                "inputs" + zero_hint) from None


def _newton(system, x0, t, abserr, relerr, unknowns, zero_hint: str, max_iter: int = 50):
    """Newton's method from the guesses; converged when every step is within
    max(ABSERR, RELERR*|x|) and the residual is small."""
    x = np.array(x0, dtype=float)
    n = len(x)
    for _ in range(max_iter):
        r = system.extra("residual", t, (), x)
        j = system.extra("jacobian", t, (), x).reshape(n, n)
        if not (np.all(np.isfinite(r)) and np.all(np.isfinite(j))):
            raise AutolevModelError("CODE NONLINEAR: the equations are not finite at "
                                    + _at(unknowns, x) + zero_hint)
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
    return ", ".join(f"{name} = {v:.6g}" for name, v in zip(unknowns, x))
