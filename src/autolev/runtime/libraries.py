"""The private parts of sympy and scipy autolev leans on, each behind one function.

Each is a fact a library does not promise to keep; tests/runtime/test_libraries.py checks each
against what autolev needs of it, so a release that changes one fails there, by name,
not somewhere deep in a run.  Where a library changed one, the function raises
LibraryChanged (an internal error: autolev must follow the library, the user cannot).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import sympy as sm

from ..engine.errors import AutolevModelError

if TYPE_CHECKING:
    import numpy as np


class LibraryChanged(RuntimeError):
    """A private part of sympy or scipy is not what autolev was written against."""


def sum_or_product_as_given(kind: type, args: tuple, commutative: bool | None) -> sm.Expr:
    """sm.Add or sm.Mul of `args` exactly as given: neither sorted nor combined again
    (sympy's private `_from_args`; the public constructors redo that work, 2.7 times
    slower when a cached model of many terms is read back)."""
    if kind is not sm.Add and kind is not sm.Mul:
        raise AutolevModelError(f"only sums and products are rebuilt this way, not {kind}")
    return kind._from_args(args, commutative)


def power_as_given(base: sm.Expr, exponent: sm.Expr) -> sm.Expr:
    """base**exponent as it was written (a cached model read back: not evaluated)."""
    return sm.Pow(base, exponent, evaluate=False)


@dataclass(frozen=True)
class DormandPrince853:
    """The Dormand-Prince 8(5,3) tableau: `a` (extended stages x extended stages, the
    stages' coefficients), `b` (the solution's weights), `c` (the nodes), `e3` and `e5`
    (the error estimates' weights) and `d` (4 x extended stages, dense output)."""

    stages: int
    extended: int
    a: np.ndarray
    b: np.ndarray
    c: np.ndarray
    e3: np.ndarray
    e5: np.ndarray
    d: np.ndarray


def dormand_prince_853() -> DormandPrince853:
    """The tableau of scipy's DOP853, which the compiled loop integrates with so that
    its steps are scipy's (scipy's private module of published coefficients)."""
    # imported here: 0.14 s, paid only when the compiled loop's C is generated
    import numpy as np
    try:
        from scipy.integrate._ivp import dop853_coefficients as k
    except ImportError as exc:
        raise LibraryChanged(f"scipy moved DOP853's coefficients: {exc}") from None
    n, ne = k.N_STAGES, k.N_STAGES_EXTENDED
    tableau = DormandPrince853(
        n, ne, np.array(k.A[:ne, :ne], float), np.array(k.A[n, :n], float),
        np.array(k.C[:ne], float), np.array(k.E3, float), np.array(k.E5, float),
        np.array(k.D, float))
    shapes = (tableau.a.shape, tableau.b.shape, tableau.c.shape, tableau.e3.shape,
              tableau.e5.shape, tableau.d.shape)
    wanted = ((ne, ne), (n,), (ne,), (n + 1,), (n + 1,), (4, ne))
    if (n, ne) != (12, 16) or shapes != wanted:
        raise LibraryChanged(f"scipy's DOP853 tableau has shapes {shapes} for {n} and {ne} "
                             f"stages; autolev's compiled loop was written for {wanted}")
    return tableau
