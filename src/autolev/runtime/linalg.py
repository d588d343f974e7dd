"""Small symbolic linear algebra that keeps expressions small (Z-named entries)."""
from __future__ import annotations

import sympy as sm

from .calculus import Definitions, NumericPoint
from .vector import AutolevModelError


def _small(z: complex) -> bool:
    return not (abs(z) > 1e-9)          # also true for nan


def solve_linear(a: sm.Matrix, b: sm.Matrix, defs: Definitions, what: str = "") -> list[sm.Expr]:
    """x with a*x = b by Gaussian elimination with full pivoting, naming intermediate
    results by Z's.

    The symbolic solution divides by its pivots, so a pivot must be nonzero wherever
    the model goes.  Numbers are taken first; otherwise the entry that stays farthest
    from zero, relative to its size, over several configurations (the time-varying
    quantities all 0, all pi/2, and spread over [-pi, pi]) -- (L2+Q2) rather than
    cos(Q1), which a cell model or a bicycle meets at 90 degrees.  An entry that is
    zero for generic values is never a pivot."""
    n = a.rows
    generic = NumericPoint(defs, seed=1)
    probes = [NumericPoint(defs, zero_varying=True, seed=2),
              NumericPoint(defs, varying=sm.pi / 2, seed=3)] + \
        [NumericPoint(defs, varying="wide", seed=s) for s in (4, 5, 6, 7)]
    scores: dict = {}

    def score(e) -> float:
        """2 for a number; else min|e| / max|e| over the probes (0 when it vanishes)."""
        if e.is_number:
            return 2.0
        hit = scores.get(e)
        if hit is None:
            if _small(defs.numeric(e, generic)):
                hit = -1.0                        # zero for generic values: unusable
            else:
                vals = [abs(defs.numeric(e, p)) for p in probes]
                top = max(vals)
                hit = 0.0 if any(_small(v) for v in vals) or not top > 0 else \
                    min(vals) / top
            scores[e] = hit
        return hit

    if a.cols != n or b.rows != n:
        raise AutolevModelError(f"cannot solve {what}: {a.rows} equations for {a.cols} "
                                "unknowns")
    m = [[a[i, j] for j in range(n)] + [b[i, 0]] for i in range(n)]
    cols = list(range(n))                 # cols[k]: the unknown in position k
    for k in range(n):
        best, where = -1.0, None
        for c in range(k, n):
            for r in range(k, n):
                e = m[r][c]
                if e == 0:
                    continue
                s_ = score(e)
                if s_ > best:
                    best, where = s_, (r, c)
            if best >= 2.0:
                break
        if where is None or best < 0:
            raise AutolevModelError(f"cannot solve {what}: the equations are singular (they "
                                    f"do not determine unknown {cols[k] + 1})")
        r, c = where
        m[k], m[r] = m[r], m[k]
        if c != k:
            for row in m:
                row[k], row[c] = row[c], row[k]
            cols[k], cols[c] = cols[c], cols[k]
        p = m[k][k]
        for r in range(k + 1, n):
            f = m[r][k]
            if f == 0:
                continue
            ratio = defs.zify(f / p)
            for j in range(k + 1, n + 1):
                if m[k][j] != 0:
                    m[r][j] = defs.zify(m[r][j] - ratio * m[k][j])
            m[r][k] = sm.S.Zero
    y = [sm.S.Zero] * n
    for i in reversed(range(n)):
        acc = m[i][n] - sm.Add(*[m[i][j] * y[j] for j in range(i + 1, n) if m[i][j] != 0])
        y[i] = defs.zify(acc / m[i][i])
    x = [sm.S.Zero] * n
    for k in range(n):
        x[cols[k]] = y[k]
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
