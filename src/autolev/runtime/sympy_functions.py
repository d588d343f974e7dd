"""The function records' sympy side (engine/functions.py holds the records, without
sympy): each record's sympy function, sympy's own of its name or one of Autolev's own
defined here (INT's and ROUND's), and the records by that function."""
from __future__ import annotations

import math

import sympy as sm

from ..engine.functions import FUNCTION_SPECS, FunctionSpec
from .printer import number_value


def _truncated(q) -> int:
    return int(q)


def _rounded(q) -> int:
    t = int(q)
    return t + (1 if q > 0 else -1) if abs(q - t) >= sm.Rational(1, 2) else t


class _IntegerValued(sm.Function):
    """A function of Autolev's whose value is an integer near x (`_integer` says
    which): one node, not sign(x)*floor(|x|), which holds x twice and doubles the tree
    at every level of nesting.  Its derivative is 0."""

    @classmethod
    def eval(cls, x):
        return _integer_of(x, cls._integer)

    def _eval_is_integer(self):
        return self.args[0].is_extended_real

    def _eval_is_real(self):
        return self.args[0].is_extended_real

    def fdiff(self, argindex=1):
        return sm.S.Zero


class Int(_IntegerValued):
    """INT(x) of Autolev: x truncated toward zero."""

    _integer = staticmethod(_truncated)


class Round(_IntegerValued):
    """ROUND(x) of Autolev: the nearest integer, halves away from zero (C's round)."""

    _integer = staticmethod(_rounded)


def _integer_of(x, integer):
    """INT or ROUND of a number: exact for a rational or a decimal, the double-precision
    value otherwise (as Autolev computed it; an exact evaluation of COS(SINH(1E7))
    needs millions of digits), None (kept as it is) for a symbol, an infinity or nan."""
    if isinstance(x, _IntegerValued):
        return x
    if not x.is_number or x.is_extended_real is False:
        return None
    if x.is_Rational:
        return sm.Integer(integer(x))
    if x.is_Float:
        return sm.Integer(integer(sm.Rational(x))) if x.is_finite else None
    v = number_value(x)
    return sm.Integer(integer(sm.Rational(v))) if math.isfinite(v) else None


_OWN = {f.__name__: f for f in (Int, Round)}


def sympy_function(spec: FunctionSpec):
    """The sympy function of a record with one (sm.sqrt makes a power, not a node)."""
    return _OWN[spec.sympy] if spec.sympy in _OWN else getattr(sm, spec.sympy)


SPEC_OF_FUNCTION = {sympy_function(s): s for s in FUNCTION_SPECS if s.sympy is not None}
