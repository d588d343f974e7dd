"""An expression's value in double precision at a point, each shared part computed once.

sympy's `xreplace` and `evalf` walk a shared part again wherever it occurs, and compute
with sympy's numbers: on the equations sympy's KanesMethod forms for a bicycle (parts
shared thousands of times) a check at one state took seconds.  Here every distinct
part is one float operation.
"""
from __future__ import annotations

from collections.abc import Callable, Mapping

import sympy as sm

from sympy.core.function import AppliedUndef

from .sympy_functions import SPEC_OF_FUNCTION


class ValuesAt:
    """Expressions' values at one point ({atom or applied function: its value}); a
    symbol, undefined function or derivative the point does not give is `otherwise(it)`
    (which may raise).  A part shared by several expressions asked is computed once.
    Complex intermediate values (a negative base to a fractional power) stay complex;
    each value asked must be real."""

    def __init__(self, point: Mapping, otherwise: Callable[[sm.Basic], float]) -> None:
        self._memo: dict = dict(point)
        self._otherwise = otherwise

    def __call__(self, expr) -> float:
        value = self._at(sm.sympify(expr))
        if isinstance(value, complex):
            if value.imag != 0:
                raise ValueError(f"{expr} is not real at the point ({value})")
            value = value.real
        return float(value)

    def define(self, symbol: sm.Symbol, expr) -> None:
        """Give `symbol` the value of `expr` (a definition, in dependency order)."""
        self._memo[symbol] = self(expr)

    def _at(self, e):
        r = self._memo.get(e)
        if r is not None:
            return r
        at = self._at
        if e.is_Number:
            r = float(e)
        elif e.is_Add:
            r = sum(at(a) for a in e.args)
        elif e.is_Mul:
            r = 1.0
            for a in e.args:
                r *= at(a)
        elif e.is_Pow:
            r = at(e.base) ** at(e.exp)
        elif isinstance(e, sm.Function) and not isinstance(e, AppliedUndef):
            r = _function_at(e, [at(a) for a in e.args])
        else:
            r = self._otherwise(e)
        self._memo[e] = r
        return r


def _function_at(e: sm.Function, args: list):
    """A function of the model's at arguments' values: in double precision by its record,
    else (a complex argument, a function without one) by sympy."""
    spec = SPEC_OF_FUNCTION.get(e.func)
    if spec is not None and spec.double is not None \
            and all(isinstance(a, float) for a in args):
        try:
            return float(spec.double(*args))
        except (ValueError, OverflowError):     # outside math's real domain: sympy's
            pass
    value = complex(e.func(*[sm.sympify(a) for a in args]).evalf())
    return value.real if value.imag == 0 else value
