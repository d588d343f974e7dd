"""Small symbolic linear algebra that keeps expressions small (Z-named entries)."""
from __future__ import annotations

import cmath

import sympy as sm

from .calculus import Definitions, NumericPoint
from ..engine.errors import AutolevModelError


def _small(z: complex) -> bool:
    return not (abs(z) > 1e-9)          # also true for nan


def solve_linear(a: sm.Matrix, b: sm.Matrix, defs: Definitions, what: str = "") -> list[sm.Expr]:
    """x with a*x = b by Gaussian elimination with full pivoting, naming intermediate
    results by Z's.

    The symbolic solution divides by its pivots, so a pivot must be nonzero wherever
    the model goes.  Numbers are taken first; then entries nonzero where the
    time-varying quantities are zero (where models start and are linearised); then
    those nonzero at more probe configurations (all pi/2, and spread over [-pi, pi]),
    and farthest from zero relative to their size -- (L2+Q2) rather than cos(Q1),
    which a cell model meets at 90 degrees.  An entry that is zero for generic values
    is never a pivot.  The system is first split into its block-triangular form;
    blocks of up to CRAMER_MAX equations are solved by Cramer's rule, which divides
    only by their determinants (so they are right wherever they are regular); larger
    irreducible blocks by the elimination above."""
    n = a.rows
    if a.cols != n or b.rows != n:
        raise AutolevModelError(f"cannot solve {what}: {a.rows} equations for {a.cols} "
                                "unknowns")
    if n <= 3:
        return _cramer(a, b, defs, what, NumericPoint(defs, seed=1))
    blocks = _block_triangular(a)
    if blocks is not None and len(blocks) == 1 and n <= CRAMER_MAX:
        return _cramer(a, b, defs, what, NumericPoint(defs, seed=1))
    if blocks is not None and len(blocks) > 1:
        return _solve_by_blocks(a, b, blocks, defs, what)
    return _eliminate(a, b, defs, what)


def _solve_by_blocks(a: sm.Matrix, b: sm.Matrix, blocks: list, defs: Definitions,
                     what: str) -> list:
    """Block by block, each given the unknowns of the blocks before it (a linkage's
    loops, a joint's pair of constraints); small blocks by Cramer's rule, so no pivot
    can vanish where a block is regular."""
    n = a.rows
    x = [None] * n
    for rows, cols in blocks:
        rhs = []
        for r in rows:
            known = [a[r, c] * x[c] for c in range(n) if x[c] is not None and a[r, c] != 0]
            rhs.append(defs.zify(b[r, 0] - sm.Add(*known)) if known else b[r, 0])
        sub = solve_linear(a.extract(rows, cols), sm.Matrix(rhs), defs, what)
        for c, v in zip(cols, sub):
            x[c] = v
    return x


class _PivotScore:
    """Numbers first; then nonzero where the varying quantities are zero (where models
    start and are linearised), then nonzero at more probes, then farthest from zero
    relative to its size.  None: zero for generic values (unusable)."""

    def __init__(self, defs: Definitions):
        self.defs = defs
        self.generic = NumericPoint(defs, seed=1)
        self.probes = [NumericPoint(defs, zero_varying=True, seed=2),
                       NumericPoint(defs, varying=sm.pi / 2, seed=3)] + \
            [NumericPoint(defs, varying="wide", seed=s) for s in (4, 5, 6, 7)]
        self.scores: dict = {}

    def __call__(self, e) -> tuple | None:
        if e.is_number:
            return (3,)
        hit = self.scores.get(e, False)
        if hit is False:
            if _small(self.defs.numeric(e, self.generic)):
                hit = None
            else:
                vals = [abs(self.defs.numeric(e, p)) for p in self.probes]
                nonzero = [not _small(v) for v in vals]
                top = max((v for v, ok in zip(vals, nonzero) if ok), default=0.0)
                ratio = min(vals) / top if all(nonzero) and top > 0 else 0.0
                hit = (1, int(nonzero[0]), sum(nonzero), ratio)
            self.scores[e] = hit
        return hit


def _eliminate(a: sm.Matrix, b: sm.Matrix, defs: Definitions, what: str) -> list:
    """Gaussian elimination with full pivoting (pivots chosen by _PivotScore), then
    back substitution; every intermediate named by a Z."""
    n = a.rows
    score = _PivotScore(defs)
    m = [[a[i, j] for j in range(n)] + [b[i, 0]] for i in range(n)]
    cols = list(range(n))                 # cols[k]: the unknown in position k
    for k in range(n):
        best, where = None, None
        for c in range(k, n):
            for r in range(k, n):
                e = m[r][c]
                if e == 0:
                    continue
                s_ = score(e)
                if s_ is not None and (best is None or s_ > best):
                    best, where = s_, (r, c)
            if best == (3,):
                break
        if where is None:
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


def _block_triangular(a: sm.Matrix) -> list[tuple[list, list]] | None:
    """The blocks of a's block-triangular form, in the order to solve them (rows and
    the columns they determine), or None when a is structurally singular.

    Each row is matched to a column it contains (augmenting paths); row i depends on
    row j when it contains j's column; the strongly connected components of that graph
    (Tarjan: a component is finished after everything it depends on) are the blocks."""
    n = a.rows
    nz = [[j for j in range(n) if a[i, j] != 0] for i in range(n)]
    owner = [-1] * n                       # column -> row

    def augment(i, seen):
        for j in nz[i]:
            if j in seen:
                continue
            seen.add(j)
            if owner[j] < 0 or augment(owner[j], seen):
                owner[j] = i
                return True
        return False
    for i in range(n):
        if not augment(i, set()):
            return None
    col_of = {owner[j]: j for j in range(n)}
    deps = [[owner[j] for j in nz[i] if owner[j] != i] for i in range(n)]
    index, low, on_stack, stack, blocks = {}, {}, set(), [], []
    counter = [0]

    def visit(v):                          # Tarjan, iterative over the edges
        work = [(v, iter(deps[v]))]
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        while work:
            node, edges = work[-1]
            for w in edges:
                if w not in index:
                    index[w] = low[w] = counter[0]
                    counter[0] += 1
                    stack.append(w)
                    on_stack.add(w)
                    work.append((w, iter(deps[w])))
                    break
                if w in on_stack:
                    low[node] = min(low[node], index[w])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    comp = []
                    while True:
                        w = stack.pop()
                        on_stack.discard(w)
                        comp.append(w)
                        if w == node:
                            break
                    rows = sorted(comp)
                    blocks.append((rows, [col_of[r] for r in rows]))
    for v in range(n):
        if v not in index:
            visit(v)
    return blocks


# irreducible blocks up to this size are solved by Cramer's rule: no pivot of theirs
# can vanish where they are regular (a 4x4 loop of the bicycle-with-arms model has one
# at its symmetric pose, a Whipple bicycle's 5x5 rolling constraints one upright).  Its
# determinants by expansion in minors cost n 2^(n-1) products each, 4 times
# elimination's at n = 4 and 12 times at n = 6.
CRAMER_MAX = 6


def _det(rows, defs: Definitions):
    """Determinant of a small square matrix (lists) by expansion along its rows, each
    minor (the last rows, a set of columns) computed once and named by a Z."""
    n = len(rows)
    minors: dict = {}

    def minor(k: int, cols: tuple):
        if k == n - 1:
            return rows[k][cols[0]]
        got = minors.get((k, cols))
        if got is None:
            terms = []
            for pos, j in enumerate(cols):
                if rows[k][j] != 0:
                    rest = minor(k + 1, cols[:pos] + cols[pos + 1:])
                    if rest != 0:
                        terms.append((-1) ** pos * rows[k][j] * rest)
            got = minors[(k, cols)] = defs.zify(sm.Add(*terms))
        return got

    return minor(0, tuple(range(n)))


def _cramer(a: sm.Matrix, b: sm.Matrix, defs: Definitions, what: str, generic) -> list:
    """A small system by Cramer's rule, as Autolev's solutions read (x_i =
    det(A_i)/det(A)): the only division is by the determinant, zero exactly where the
    system is singular, not where an elimination pivot happens to vanish."""
    n = a.rows
    rows = [[a[i, j] for j in range(n)] for i in range(n)]
    det = _det(rows, defs)
    value = 0j if det == 0 else None if det.is_number else defs.numeric(det, generic)
    if value is not None and cmath.isnan(value):
        raise AutolevModelError(f"cannot solve {what}: the determinant of its equations has "
                                "no value for generic values of its names (it divides by "
                                "zero there, or gives a function such as MIN a complex "
                                "number)")
    if value is not None and _small(value):
        raise AutolevModelError(f"cannot solve {what}: the equations are singular (their "
                                "determinant is zero)")
    out = []
    for i in range(n):
        ai = [[b[r, 0] if j == i else rows[r][j] for j in range(n)] for r in range(n)]
        out.append(defs.zify(_det(ai, defs) / det))
    return out


def coefficients(rows, unknowns, defs: Definitions) -> tuple[sm.Matrix, sm.Matrix]:
    """(A, r) with rows = A*unknowns + r, for rows linear in the unknowns; both in terms
    of the definitions (A by differentiation, r by setting the unknowns to zero)."""
    rows = list(rows)
    jac = defs.jacobian(rows, unknowns)
    a = sm.Matrix(len(rows), len(unknowns), lambda i, j: jac[i][j])
    zero = {u: 0 for u in unknowns}
    r = sm.Matrix([defs.substitute(e, zero) for e in rows])
    return a, r
