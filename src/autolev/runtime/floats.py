"""An expression's value in double precision at a point, each shared part computed once.

sympy's `xreplace` and `evalf` walk a shared part again wherever it occurs, and compute
with sympy's numbers: on the equations sympy's KanesMethod forms for a bicycle (parts
shared thousands of times) a check at one state took seconds.  Here every distinct
part is one complex float operation.  `complex_value` is the walk; `ValuesAt` gives
real values at one point and has sympy take the nodes the walk does not.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Mapping

import sympy as sm

from sympy.core.function import AppliedUndef, Application

from .sympy_functions import SPEC_OF_FUNCTION


class NoRealValue(ValueError):
    """An expression asked of ValuesAt has no real, finite value at its point."""


class NotElementary(Exception):
    """A node the double-precision walk does not take: a symbol without a value, a
    function without a complex double (or at its branch cut), a value not finite."""


# the functions taken in complex double precision (principal branches, as sympy's
# numbers take them)
_IN_COMPLEX = {f: s for f, s in SPEC_OF_FUNCTION.items() if s.complex_double is not None}


def complex_value(e, values: Mapping, memo: dict,
                  otherwise: Callable[[sm.Basic], complex] | None = None) -> complex:
    """e's value by a walk of its tree, each repeated part once (`memo` holds the parts
    done).  A node the walk does not take is `otherwise(node)`; without `otherwise` it
    raises NotElementary (sympy then decides).  ArithmeticError passes through."""
    if e in memo:
        return memo[e]
    out = _node_value(e, values, memo, otherwise)
    if out is None or not (math.isfinite(out.real) and math.isfinite(out.imag)):
        # infinities and NaN as sympy's numbers take them
        if otherwise is None:
            raise NotElementary(e)
        out = complex(otherwise(e))
    if out.imag == 0:
        out = complex(out.real, 0.0)   # a real number: no -0j to turn a root's branch
    memo[e] = out
    return out


def _node_value(e, values, memo, otherwise) -> complex | None:
    """e's value from its arguments' values; None where the walk does not take it."""
    if e.is_Symbol:
        return complex(values[e]) if e in values else None
    if e.is_Number or e.is_NumberSymbol or e is sm.I:
        return complex(e)
    if e.is_Add:
        return sum((complex_value(a, values, memo, otherwise) for a in e.args), 0j)
    if e.is_Mul:
        out = 1 + 0j
        for a in e.args:
            out *= complex_value(a, values, memo, otherwise)
        return out
    if e.is_Pow:
        base = complex_value(e.base, values, memo, otherwise)
        return base ** (int(e.exp) if e.exp.is_Integer
                        else complex_value(e.exp, values, memo, otherwise))
    spec = _IN_COMPLEX.get(e.func)
    if spec is None or len(e.args) != spec.arity:
        return None
    args = [complex_value(a, values, memo, otherwise) for a in e.args]
    if spec.branch_cut is not None and spec.branch_cut(*args):
        return None                # cmath and sympy take opposite sides of the cut there
    return complex(spec.complex_double(*args))


class ValuesAt:
    """Expressions' values at one point ({atom or applied function: its value}); a
    symbol, undefined function or derivative the point does not give is `otherwise(it)`
    (which may raise).  A part shared by several expressions asked is computed once.
    Complex intermediate values (a negative base to a fractional power) stay complex;
    each value asked must be real."""

    def __init__(self, point: Mapping, otherwise: Callable[[sm.Basic], float]) -> None:
        self._memo: dict = {k: complex(v) for k, v in point.items()}
        self._otherwise = otherwise

    def __call__(self, expr) -> float:
        try:
            value = self._at(sm.sympify(expr))
        except (ZeroDivisionError, OverflowError) as exc:
            raise NoRealValue(f"{expr} has no value at the point ({exc})") from None
        if value.imag != 0:
            raise NoRealValue(f"{expr} is not real at the point ({value})")
        return value.real

    def define(self, symbol: sm.Symbol, expr) -> None:
        """Give `symbol` the value of `expr` (a definition, in dependency order)."""
        self._memo[symbol] = complex(self(expr))

    def _at(self, e) -> complex:
        return complex_value(e, {}, self._memo, self._by_sympy)

    def _by_sympy(self, e) -> complex:
        """A node the walk leaves: what the point lacks is asked; a function is taken by
        its record's double where its arguments are real, else by sympy."""
        if e.is_Atom or isinstance(e, (AppliedUndef, sm.Derivative)):
            return complex(self._otherwise(e))
        if isinstance(e, Application):
            return _function_at(e, [self._at(a) for a in e.args])
        raise NoRealValue(f"{e} has no finite value at the point")


def _function_at(e: Application, args: list[complex]) -> complex:
    """A function of the model's at its arguments' values: in double precision by its
    record where they are real, else (a complex argument, past math's domain, a
    function without one) by sympy."""
    spec = SPEC_OF_FUNCTION.get(e.func)
    if spec is not None and spec.double is not None and all(a.imag == 0 for a in args):
        try:
            return complex(spec.double(*(a.real for a in args)))
        except (ValueError, OverflowError):     # outside math's real domain: sympy's
            pass
    return complex(e.func(*[sm.sympify(a) for a in args]).evalf())
