"""The mass matrix at one state: M u' = f solved in the operations of loop.c's solve
(the Python and C back ends give the same numbers), and how near singular M is.

A symmetric mass matrix (Kane's: the entry of row r, column s is that of row s,
column r, as expressions or in value at a run's constants) is factored as
M = L^T D L without pivoting, in the
order of Featherstone's LTDL (RBDA, section 6.5): the speeds of a tree's branches
never meet in a product, so only each row's chain of "parents" is worked on (for a
dense matrix, every row before it).  All of D positive means M is positive definite
(Sylvester's law of inertia), where this is backward stable; otherwise the solve
falls back to Gaussian elimination with partial pivoting, which also stands for a
matrix whose expressions are not symmetric."""
from __future__ import annotations

import ctypes
from dataclasses import dataclass
from pathlib import Path

import numpy as np

# M X = B at many nodes (a tree's Jacobian program links it in: see ltdl_columns)
LTDL_SOURCE = Path(__file__).with_name("ltdl.c").read_text()


class SingularMassMatrix(ArithmeticError):
    def __init__(self, t):
        super().__init__(f"the mass matrix is singular at T = {t:.6g}")
        self.t = t


@dataclass(frozen=True)
class MassStructure:
    """How a symmetric mass matrix is factored: `order[k]` is the speed eliminated
    k-th from the end, and `parent[k]` (< k, or -1) the row that k's elimination
    reaches next: every entry (k, j) that is not structurally zero, before and after
    the elimination of the rows after k, has j on k's chain of parents."""
    order: tuple
    parent: tuple
    proven: bool        # each entry (r, s) is the expression of (s, r)

    @property
    def starts(self) -> list:
        """Where each row starts when rows are held compactly (loop.c): its diagonal,
        then its entries in the columns of its chain of parents; then the end."""
        starts = [0]
        for k in range(len(self.parent)):
            starts.append(starts[-1] + len(self._chain(k)))
        return starts

    @property
    def columns(self) -> list:
        """The column of each compactly held entry, row after row."""
        return [j for k in range(len(self.parent)) for j in self._chain(k)]

    @property
    def rows(self) -> list:
        """The row of each compactly held entry."""
        return [k for k in range(len(self.parent)) for _ in self._chain(k)]

    def _chain(self, k: int) -> list:
        chain = [k]
        while self.parent[chain[-1]] >= 0:
            chain.append(self.parent[chain[-1]])
        return chain

    @classmethod
    def eliminated(cls, nonzero: list, order: list) -> MassStructure:
        """The structure of eliminating the speeds from the last of `order` to its
        first (`nonzero[s]`: the speeds whose entry in s's row or column is not
        structurally zero); a tree's from its leaves fills in nothing."""
        parent, _, order = _parents(nonzero, list(order))
        return cls(tuple(order), tuple(parent), False)

    @classmethod
    def of(cls, entries: list, m: int) -> MassStructure | None:
        """The structure of the m x m matrix whose `entries` (sympy expressions, row
        by row) may be symmetric: (r, s) is zero where (s, r) is; `proven` when each
        is the same expression.  Otherwise symmetry is a matter of values (a
        constrained model's entries are sums formed in different orders), which
        `symmetric` judges at the constants of a run.  None for a matrix that cannot
        be symmetric (it is solved by pivoting)."""
        if m < 2:
            return None
        nonzero = [[s for s in range(m) if s != r and entries[r * m + s] != 0]
                   for r in range(m)]
        if any(r not in nonzero[s] for r in range(m) for s in nonzero[r]):
            return None
        proven = all(entries[r * m + s] == entries[s * m + r]
                     for r in range(m) for s in nonzero[r] if s > r)
        # eliminate the later speeds first or the earlier ones, which fills in less
        # (a tree whose parents come first: none, in the declared order)
        candidates = [list(range(m)), list(range(m - 1, -1, -1))]
        best = min((_parents(nonzero, order) for order in candidates),
                   key=lambda found: found[1])
        return cls(tuple(best[2]), tuple(best[0]), proven)


def symmetric(matrices: np.ndarray) -> bool:
    """Whether a stack of mass matrices (one per state) is symmetric with a positive
    diagonal: each |M_rs - M_sr| within 1e-10 of sqrt(M_rr M_ss), which bounds |M_rs|
    in a positive definite matrix (so the test is free of the speeds' units)."""
    if not np.all(np.isfinite(matrices)):
        return False
    diagonal = np.diagonal(matrices, axis1=1, axis2=2)
    if np.any(diagonal <= 0):
        return False
    scale = np.sqrt(diagonal[:, :, None] * diagonal[:, None, :])
    return bool(np.all(np.abs(matrices - matrices.transpose(0, 2, 1)) <= 1e-10 * scale))


def _parents(nonzero: list, order: list) -> tuple[list, int, list]:
    """(parent of each position, the multiplications the factorization takes, order):
    the elimination tree of the matrix permuted to `order`, eliminated from the last
    position to the first."""
    m = len(order)
    position = {speed: k for k, speed in enumerate(order)}
    below = [set(position[s] for s in nonzero[speed] if position[s] < k)
             for k, speed in enumerate(order)]
    parent = [-1] * m
    for k in range(m - 1, -1, -1):
        if below[k]:
            p = max(below[k])
            parent[k] = p
            below[p] |= below[k] - {p}      # the fill of eliminating k
    cost, depth = 0, [0] * m
    for k in range(m):
        depth[k] = depth[parent[k]] + 1 if parent[k] >= 0 else 0
        cost += depth[k] * (depth[k] + 1) // 2
    return parent, cost, order


def solve_mass_matrix(mm: np.ndarray, f: np.ndarray, t: float,
                      structure: MassStructure | None = None) -> np.ndarray:
    """u' from M u' = f: by M = L^T D L along `structure` when all of D is positive,
    else by Gaussian elimination with partial pivoting; the operations of loop.c's
    solves in the same order (each pivot inverted once and multiplied by), so that
    the Python and C back ends give the same numbers.  SingularMassMatrix when a
    pivot of the elimination is exactly zero."""
    m = len(f)
    if m == 1:
        if mm[0, 0] == 0 or not np.isfinite(mm[0, 0]):
            raise SingularMassMatrix(t)
        return f / mm[0, 0]
    if structure is not None:
        x = _solve_ltdl(mm, f, structure)
        if x is not None:
            return x
    a = np.array(mm, dtype=float)
    b = [float(v) for v in f]
    inv = [0.0] * m
    for k in range(m):
        col = np.abs(a[k:, k]).tolist()
        p, amax = k, col[0]
        for i in range(1, m - k):
            if col[i] > amax:
                p, amax = k + i, col[i]
        if amax == 0.0:
            raise SingularMassMatrix(t)
        if p != k:
            a[[k, p]] = a[[p, k]]
            b[k], b[p] = b[p], b[k]
        r = 1.0 / float(a[k, k])
        inv[k] = r
        for i in range(k + 1, m):
            li = float(a[i, k]) * r
            if li != 0.0:
                a[i, k + 1:] -= li * a[k, k + 1:]
                b[i] -= li * b[k]
    x = [0.0] * m
    rows = a.tolist()
    for i in range(m - 1, -1, -1):
        acc = b[i]
        ri = rows[i]
        for j in range(i + 1, m):
            acc -= ri[j] * x[j]
        x[i] = acc * (inv[i] if m <= 64 else 1.0 / ri[i])
    return np.array(x)


def _solve_ltdl(mm: np.ndarray, f: np.ndarray, structure: MassStructure):
    """u' by M = L^T D L (loop.c's al_ltdl_solve), or None when a diagonal entry of D
    is not positive and finite."""
    order, parent = structure.order, structure.parent
    m = len(order)
    a = np.asarray(mm, dtype=float)[np.ix_(order, order)].tolist()
    b = [float(f[k]) for k in order]
    inv = [0.0] * m
    for k in range(m - 1, -1, -1):
        d = a[k][k]
        if not d > 0.0 or d == np.inf:
            return None
        r = inv[k] = 1.0 / d
        i = parent[k]
        while i >= 0:
            li = a[k][i] * r
            j = i
            while j >= 0:
                a[i][j] -= li * a[k][j]
                j = parent[j]
            a[k][i] = li
            i = parent[i]
    for k in range(m - 1, -1, -1):      # L^T y = b
        j = parent[k]
        while j >= 0:
            b[j] -= a[k][j] * b[k]
            j = parent[j]
    for k in range(m):                  # D z = y and L x = z, row by row
        acc = b[k] * inv[k]
        j = parent[k]
        while j >= 0:
            acc -= a[k][j] * b[j]
            j = parent[j]
        b[k] = acc
    x = np.empty(m)
    x[list(order)] = b
    return x


@dataclass(frozen=True)
class CompactRows:
    """A MassStructure's rows held compactly, as ltdl.c reads them (C ints): where each
    row starts and its entries' columns; and for each row i, the rows k after it whose
    chain holds i, from the last (`ustart`, `uk`), with where L's entry (k, i) is
    (`uat`)."""
    start: np.ndarray
    col: np.ndarray
    ustart: np.ndarray
    uk: np.ndarray
    uat: np.ndarray

    @classmethod
    def of(cls, structure: MassStructure) -> CompactRows:
        start, col = structure.starts, structure.columns
        m = len(structure.order)
        updates: list = [[] for _ in range(m)]
        for k in range(m - 1, -1, -1):
            for at in range(start[k] + 1, start[k + 1]):
                updates[col[at]].append((k, at))
        ustart = np.cumsum([0] + [len(u) for u in updates])
        pairs = [pair for u in updates for pair in u]
        return cls(*(np.array(a, dtype=np.intc).reshape(-1) for a in (
            start, col, ustart, [k for k, _ in pairs], [at for _, at in pairs])))


def ltdl_columns(rows: np.ndarray, at_r: int, at_b: int, m: int, w: int,
                 compact: CompactRows) -> int:
    """ltdl.c's autolev_ltdl_columns over every row of `rows` (nodes x outputs), in
    place, each entry by the same operations in the same order (a node is a row of the
    arrays here): M compactly from `at_r`, the m x w matrix B from `at_b` overwritten
    by M^-1 B.  0, or 1 + the first node where an entry of D is not positive and
    finite."""
    start, col = compact.start.tolist(), compact.col.tolist()
    r = rows[:, at_r:at_r + start[-1]]
    b = rows[:, at_b:at_b + m * w].reshape(len(rows), m, w)
    bad = np.zeros(len(rows), dtype=bool)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for k in range(m - 1, -1, -1):
            s, length = start[k], start[k + 1] - start[k]
            d = r[:, s]
            bad |= ~((d > 0.0) & (d != np.inf))
            inv = 1.0 / d
            for t in range(1, length):
                i = col[s + t]
                n = start[i + 1] - start[i]
                lk = r[:, s + t] * inv
                r[:, start[i]:start[i] + n] -= lk[:, None] * r[:, s + t:s + t + n]
                r[:, s + t] = lk
            r[:, s] = inv
        for k in range(m - 1, -1, -1):              # L^T Y = B
            for t in range(1, start[k + 1] - start[k]):
                b[:, col[start[k] + t]] -= r[:, start[k] + t, None] * b[:, k]
        for k in range(m):                          # D Z = Y and L X = Z, row by row
            b[:, k] *= r[:, start[k], None]
            for t in range(1, start[k + 1] - start[k]):
                b[:, k] -= r[:, start[k] + t, None] * b[:, col[start[k] + t]]
    failed = np.nonzero(bad)[0]
    return int(failed[0]) + 1 if len(failed) else 0


def compiled_ltdl_columns(lib, rows: np.ndarray, at_r: int, at_b: int, m: int, w: int,
                          compact: CompactRows) -> int:
    """ltdl_columns by LTDL_SOURCE's C in the library `lib` that links it in."""
    fn = lib.autolev_ltdl_columns
    fn.argtypes = [ctypes.c_long, ctypes.c_void_p] + [ctypes.c_long] * 5 + [ctypes.c_void_p] * 5
    fn.restype = ctypes.c_long
    if rows.dtype != np.float64 or not rows.flags.c_contiguous:
        raise ValueError("ltdl_columns: C-ordered doubles expected")
    return int(fn(len(rows), rows.ctypes.data, rows.shape[1], at_r, at_b, m, w,
                  *(a.ctypes.data for a in (compact.start, compact.col, compact.ustart,
                                            compact.uk, compact.uat))))


def scaled_condition(mm: np.ndarray) -> np.ndarray | float:
    """The 2-norm condition number of M after scaling by its diagonal (D^-1/2 M D^-1/2):
    free of the units the speeds happen to have, so that a large value means the
    equations are nearly singular, not that a rotor is light.  `mm`: one matrix, or a
    stack of them (one number each); inf for a singular or non-finite matrix."""
    a = np.asarray(mm, dtype=float)
    single = a.ndim == 2
    if single:
        a = a[None]
    d = np.abs(np.diagonal(a, axis1=1, axis2=2))
    s = np.where(d > 0, 1.0 / np.sqrt(np.where(d > 0, d, 1.0)), 1.0)
    scaled = a * s[:, :, None] * s[:, None, :]
    finite = np.all(np.isfinite(scaled), axis=(1, 2))
    out = np.full(len(a), np.inf)
    if finite.any():
        sv = np.linalg.svd(scaled[finite], compute_uv=False)
        with np.errstate(divide="ignore", invalid="ignore"):
            out[finite] = np.where(sv[:, -1] > 0, sv[:, 0] / sv[:, -1], np.inf)
    return float(out[0]) if single else out
