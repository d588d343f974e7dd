"""A generated program evaluated without printing or compiling it: what a program run
once (a parameter set's constants: BioMAC's gait3d computes all its ENCODE values
there, 8 MB of Python that CPython takes 5 s to compile) costs less walked than
compiled.

Each expression is walked as `printer.PythonPrinter` prints it, with the same Python
operations on the same values in the same order (sums left to right, a negative term
subtracted, a product's numerator then its denominator, x**2 as x*x, the math
module's functions and the printed helpers), so the numbers are the compiled Python's
to the last bit.  Where that code raises (a division by zero, a domain error) the
caller compiles it, whose numpy fallback gives C's inf and nan.
"""
from __future__ import annotations

import math

import sympy as sm
from sympy.core.numbers import NumberSymbol

from ...engine.errors import AutolevModelError
from ...engine.functions import SQRT
from ..printer import fraction_parts
from ...engine.pyfunction import fast_namespace, python_callables

# sympy's function names -> what the printed Python computes
_CALLS = python_callables(fast_namespace())
_SQRT = _CALLS[SQRT.sympy]
_HALF, _MINUS_HALF = sm.Rational(1, 2), sm.Rational(-1, 2)


class ProgramWalk:
    """Values of a built codegen.Program's outputs from its inputs' values."""

    def __init__(self, prog):
        self.prog = prog

    def evaluate(self, *arrays) -> None:
        """As the compiled program's call: the inputs' arrays, then `out` to fill."""
        prog = self.prog
        values: dict = {}
        for (arg, syms), array in zip(prog.inputs.items(), arrays):
            for s, v in zip(syms, array.tolist() if hasattr(array, "tolist") else array):
                values[s] = v
        walk = _Walk(values)
        by_ident = {ident: s for s, ident in prog.names.items()}
        for ident, expr in prog.assignments:
            value = walk(expr)          # a hoisted call (prog.bound): remembered by walk
            if ident in by_ident:
                values[by_ident[ident]] = value
        out = arrays[len(prog.inputs)]
        for k, e in enumerate(prog.outputs):
            out[k] = walk(e)


class _Walk:
    """One evaluation: each compound subexpression's value once (as the printer prints
    each once)."""

    def __init__(self, values: dict):
        self.values = values
        self.memo: dict = {}

    def __call__(self, e):
        if e.is_Atom:
            return self._atom(e)
        v = self.memo.get(e, self)
        if v is self:
            v = self.memo[e] = self._compound(e)
        return v

    def _atom(self, e):
        if e.is_Symbol:
            try:
                return self.values[e]
            except KeyError:
                raise AutolevModelError(f"no value for {e}") from None
        if e.is_Number:
            return _number(e)
        if isinstance(e, NumberSymbol):
            return math.pi if e is sm.pi else math.e if e is sm.E else _number(sm.Float(e))
        if e is sm.true or e is sm.false:
            return e is sm.true
        raise AutolevModelError(f"cannot generate numeric code for {type(e).__name__}: {e}")

    def _compound(self, e):
        if e.is_Add:
            return self._add(e)
        if e.is_Mul:
            return self._mul(e)
        if e.is_Pow:
            return self._pow(e)
        if isinstance(e, sm.Piecewise):
            for value, condition in e.args:
                if condition is sm.true or self(condition):
                    return self(value)
            return math.nan
        if isinstance(e, sm.And):       # Python's `and`: the first false operand
            r = True
            for a in e.args:
                r = self(a)
                if not r:
                    return r
            return r
        if isinstance(e, sm.Or):
            r = False
            for a in e.args:
                r = self(a)
                if r:
                    return r
            return r
        if isinstance(e, sm.Not):
            return not self(e.args[0])
        if e.is_Function:
            return self._function(e)
        if e.is_Relational:
            return _RELATIONS[e.rel_op](self(e.lhs), self(e.rhs))
        raise AutolevModelError(f"cannot generate numeric code for {type(e).__name__}: {e}")

    def _add(self, e):
        total = None
        for k, term in enumerate(e.args):
            coeff = term.as_coeff_Mul()[0]
            if k > 0 and coeff.is_Number and coeff.is_negative:   # no sympy comparison
                total = total - self(-term)
            elif k:
                total = total + self(term)
            else:
                total = self(term)
        return total

    def _mul(self, e):
        coeff, rest = e.as_coeff_Mul()
        if coeff == -1:
            return -self(rest)
        num, den = fraction_parts(e)
        top = self._product(num) if num else 1.0
        return top / self._product(den) if den else top

    def _product(self, factors):
        v = self(factors[0])
        for f in factors[1:]:
            v = v * self(f)
        return v

    def _pow(self, e):
        base, exp = e.base, e.exp
        if exp == _HALF:
            return _SQRT(self(base))
        if exp == -1:
            return 1.0 / self(base)
        if exp == _MINUS_HALF:
            return 1.0 / _SQRT(self(base))
        b = self(base)
        if exp == 2:
            return b * b
        if exp.is_Integer:
            return b ** int(exp)
        return b ** self(exp)

    def _function(self, e):
        args = [self(a) for a in e.args]
        call = _CALLS.get(type(e).__name__)
        if call is None:
            raise AutolevModelError("cannot generate numeric code for the function "
                                    f"{type(e).__name__}")
        return call(*args)


_RELATIONS = {"<": lambda a, b: a < b, "<=": lambda a, b: a <= b, ">": lambda a, b: a > b,
              ">=": lambda a, b: a >= b, "==": lambda a, b: a == b,
              "!=": lambda a, b: a != b}


def _number(e) -> float:
    if e is sm.nan or e is sm.zoo:
        return math.nan
    if e is sm.oo or e is -sm.oo:
        return math.inf if e is sm.oo else -math.inf
    v = float(e)
    if math.isinf(v):
        raise AutolevModelError(f"the number {sm.Float(e, 6)} is beyond double precision "
                                "(more than 1.8E308); Autolev computed in doubles")
    return v
