"""The mass matrix at one state: M u' = f solved in the operations of loop.c's solve
(the Python and C back ends give the same numbers), and how near singular M is."""
from __future__ import annotations

import numpy as np


class SingularMassMatrix(ArithmeticError):
    def __init__(self, t):
        super().__init__(f"the mass matrix is singular at T = {t:.6g}")
        self.t = t



def solve_mass_matrix(mm: np.ndarray, f: np.ndarray, t: float) -> np.ndarray:
    """u' from M u' = f by Gaussian elimination with partial pivoting: the operations
    of loop.c's solve in the same order (each pivot inverted once and multiplied by),
    so that the Python and C back ends give the same numbers.  SingularMassMatrix when
    a pivot is exactly zero."""
    m = len(f)
    if m == 1:
        if mm[0, 0] == 0 or not np.isfinite(mm[0, 0]):
            raise SingularMassMatrix(t)
        return f / mm[0, 0]
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
