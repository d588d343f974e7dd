"""Small symbolic linear algebra that keeps expressions small (Z-named entries)."""
from __future__ import annotations

import sympy as sm

from .calculus import Definitions, NumericPoint
from .vector import AutolevModelError


def _small(z: complex) -> bool:
    return not (abs(z) > 1e-9)          # also true for nan


def solve_linear(a: sm.Matrix, b: sm.Matrix, defs: Definitions, what: str = "") -> list[sm.Expr]:
    """x with a*x = b by Gaussian elimination, naming intermediate results by Z's.

    A pivot must be nonzero for generic values; among those, one that is also nonzero
    where the time-varying quantities are zero is preferred (models are linearised
    about such configurations: sin(q4) would divide by zero there), then numbers."""
    n = a.rows
    generic = NumericPoint(defs, seed=1)
    origin = NumericPoint(defs, zero_varying=True, seed=2)

    def rank(e) -> tuple:
        if e.is_number:
            return (0, 0)
        return (1 if _small(defs.numeric(e, origin)) else 0, 1)

    def usable(e) -> bool:
        return e.is_number and e != 0 or not _small(defs.numeric(e, generic))

    if a.cols != n or b.rows != n:
        raise AutolevModelError(f"cannot solve {what}: {a.rows} equations for {a.cols} "
                                "unknowns")
    m = [[a[i, j] for j in range(n)] + [b[i, 0]] for i in range(n)]
    for col in range(n):
        candidates = [r for r in range(col, n) if m[r][col] != 0 and usable(m[r][col])]
        if not candidates:
            raise AutolevModelError(f"cannot solve {what}: the equations are singular (they "
                                    f"do not determine unknown {col + 1})")
        piv = min(candidates, key=lambda r: rank(m[r][col]))
        m[col], m[piv] = m[piv], m[col]
        p = m[col][col]
        for r in range(col + 1, n):
            f = m[r][col]
            if f == 0:
                continue
            ratio = defs.zify(f / p)
            for j in range(col + 1, n + 1):
                if m[col][j] != 0:
                    m[r][j] = defs.zify(m[r][j] - ratio * m[col][j])
            m[r][col] = sm.S.Zero
    x = [sm.S.Zero] * n
    for i in reversed(range(n)):
        acc = m[i][n] - sm.Add(*[m[i][j] * x[j] for j in range(i + 1, n) if m[i][j] != 0])
        x[i] = defs.zify(acc / m[i][i])
    return x


def coefficients(rows, unknowns, defs: Definitions) -> tuple[sm.Matrix, sm.Matrix]:
    """(A, r) with rows = A*unknowns + r, for rows linear in the unknowns; both in terms
    of the definitions (A by differentiation, r by setting the unknowns to zero)."""
    rows = list(rows)
    a = sm.Matrix(len(rows), len(unknowns),
                  lambda i, j: defs.diff(rows[i], unknowns[j]))
    zero = {u: 0 for u in unknowns}
    r = sm.Matrix([defs.substitute(e, zero) for e in rows])
    return a, r
