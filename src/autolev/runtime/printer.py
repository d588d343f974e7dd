"""One printer for the generated C and Python: fast, and the same operations in the same
order in both languages (so both back ends give the same numbers, bit for bit).

sympy's code printers sort the terms of every sum and dispatch per node through
several layers; on a gait model's thousands of long expressions that is minutes.  This
printer walks each expression once, in sympy's argument order, and prints numbers as
the shortest decimal that round-trips (exactly the double the other language reads).
The namespace the printed Python runs in, and closed-form numbers evaluated through
it (INT, ROUND of a number), are here too.
"""
from __future__ import annotations

import math

import numpy as np
import sympy as sm
from sympy.core.numbers import NumberSymbol

from .errors import AutolevModelError

_C_FUNCS = {"sin": "sin", "cos": "cos", "tan": "tan", "asin": "asin", "acos": "acos",
            "atan": "atan", "sinh": "sinh", "cosh": "cosh", "tanh": "tanh",
            "asinh": "asinh", "acosh": "acosh", "atanh": "atanh", "exp": "exp",
            "log": "log", "floor": "floor", "ceiling": "ceil", "Abs": "fabs",
            "atan2": "atan2", "erf": "erf", "gamma": "tgamma", "Int": "trunc",
            "Round": "round"}
_PY_FUNCS = {"sin": "math.sin", "cos": "math.cos", "tan": "math.tan", "asin": "math.asin",
             "acos": "math.acos", "atan": "math.atan", "sinh": "math.sinh",
             "cosh": "math.cosh", "tanh": "math.tanh", "asinh": "math.asinh",
             "acosh": "math.acosh", "atanh": "math.atanh", "exp": "math.exp",
             "log": "math.log", "floor": "math.floor", "ceiling": "math.ceil",
             "Abs": "math.fabs", "atan2": "math.atan2", "erf": "math.erf",
             "gamma": "math.gamma", "Int": "_trunc", "Round": "_round"}

# precedence: higher binds tighter
_ADD, _MUL, _UNARY, _POW, _ATOM = 1, 2, 3, 4, 5


class CodePrinter:
    """Expressions as C or Python source; `names` maps symbols to their code."""

    ONE = "1.0"             # the numerator of a reciprocal

    def __init__(self, language: str, names: dict):
        if language not in ("c", "python"):
            raise ValueError(language)
        self.c = language == "c"
        self.names = names
        self.funcs = _C_FUNCS if self.c else _PY_FUNCS
        self._memo: dict = {}

    def __call__(self, expr) -> str:
        return self._p(sm.sympify(expr))[0]

    def bind(self, expr, text: str) -> None:
        """From now on print `expr` (a compound expression) as `text` (the variable
        that holds its value)."""
        self._memo[expr] = (text, _ATOM)

    # each method returns (text, precedence); compound subexpressions are printed once
    def _p(self, e):
        if e.is_Atom:
            return self._atom(e)
        hit = self._memo.get(e)
        if hit is None:
            hit = self._memo[e] = self._compound(e)
        return hit

    def _atom(self, e):
        if e.is_Symbol:
            try:
                return self.names[e], _ATOM
            except KeyError:
                raise AutolevModelError(f"no value for {e}") from None
        if e.is_Number:
            return self._number(e)
        if isinstance(e, NumberSymbol):
            return self._constant(e)
        if e is sm.true or e is sm.false:
            return ("1" if e is sm.true else "0") if self.c else str(bool(e)), _ATOM
        raise AutolevModelError(f"cannot generate numeric code for {type(e).__name__}: {e}")

    def _compound(self, e):
        if e.is_Add:
            return self._add(e)
        if e.is_Mul:
            return self._mul(e)
        if e.is_Pow:
            return self._pow(e)
        if isinstance(e, sm.Piecewise):          # a Function too, of (value, condition)s
            return self._piecewise(e)
        if e.is_Function:
            return self._function(e)
        if e.is_Relational:
            return self._relational(e)
        if isinstance(e, (sm.And, sm.Or)):
            op = (" && " if self.c else " and ") if isinstance(e, sm.And) else \
                (" || " if self.c else " or ")
            return "(" + op.join(self._p(a)[0] for a in e.args) + ")", _ATOM
        if isinstance(e, sm.Not):
            return ("!" if self.c else "not ") + self._wrap(e.args[0], _ATOM), _UNARY
        raise AutolevModelError(f"cannot generate numeric code for {type(e).__name__}: {e}")

    def _wrap(self, e, prec: int) -> str:
        text, p = self._p(e)
        return f"({text})" if p < prec else text

    def _number(self, e):
        if e is sm.nan or e is sm.zoo or e in (sm.oo, -sm.oo):
            return ("NAN" if self.c else "math.nan") if e in (sm.nan, sm.zoo) else \
                (("INFINITY" if self.c else "math.inf") if e is sm.oo
                 else ("(-INFINITY)" if self.c else "(-math.inf)")), _ATOM
        v = float(e)
        if math.isinf(v):
            raise AutolevModelError(f"the number {sm.Float(e, 6)} is beyond double precision "
                                    "(more than 1.8E308); Autolev computed in doubles")
        text = repr(v)
        if "e" not in text and "." not in text and "inf" not in text and "nan" not in text:
            text += ".0"
        return text, (_UNARY if v < 0 else _ATOM)

    def _constant(self, e):
        if e is sm.pi:
            return ("M_PI" if self.c else "math.pi"), _ATOM
        if e is sm.E:
            return ("M_E" if self.c else "math.e"), _ATOM
        return self._number(sm.Float(e))

    def _add(self, e):
        parts = []
        for k, term in enumerate(e.args):
            coeff, rest = term.as_coeff_Mul()
            if coeff.is_Number and coeff < 0 and k > 0:
                neg = -term
                parts.append(" - " + self._wrap(neg, _MUL))
            else:
                text = self._wrap(term, _ADD)
                parts.append((" + " if k else "") + text)
        return "".join(parts), _ADD

    def _mul(self, e):
        coeff, rest = e.as_coeff_Mul()
        if coeff == -1:
            return "-" + self._wrap(rest, _MUL + 1 if rest.is_Mul else _UNARY), _UNARY
        num, den = [], []
        for f in e.args:
            if f.is_Pow and f.exp.is_Number and f.exp.is_negative:
                if f.exp == -1:
                    den.append(f.base)
                else:
                    den.append(sm.Pow(f.base, -f.exp, evaluate=False))
            elif f.is_Rational and not f.is_Integer and f.p == 1:
                den.append(sm.Integer(f.q))
            else:
                num.append(f)
        if not den:
            return "*".join(self._wrap(f, _MUL) for f in num), _MUL
        top = "*".join(self._wrap(f, _MUL) for f in num) if num else self.ONE
        if len(den) == 1:
            bottom = self._wrap(den[0], _POW)
        else:
            bottom = "(" + "*".join(self._wrap(f, _MUL) for f in den) + ")"
        return f"{top}/{bottom}", _MUL

    def _pow(self, e):
        base, exp = e.base, e.exp
        if exp == sm.Rational(1, 2):
            return self._sqrt(base), _ATOM
        if exp == -1:
            return f"{self.ONE}/{self._wrap(base, _POW)}", _MUL
        if exp == sm.Rational(-1, 2):
            return f"{self.ONE}/{self._sqrt(base)}", _MUL
        return self._power(base, exp)

    def _sqrt(self, base) -> str:
        return f"{'sqrt' if self.c else 'math.sqrt'}({self._p(base)[0]})"

    def _power(self, base, exp):
        """base**exp for an exponent other than 1/2, -1 and -1/2."""
        if self.c:
            return f"pow({self._p(base)[0]}, {self._p(exp)[0]})", _ATOM
        if exp.is_Integer:
            # Python's ** with an integer exponent: like C's pow for these values
            return f"{self._wrap(base, _ATOM)}**{int(exp)}", _POW
        return f"{self._wrap(base, _ATOM)}**{self._wrap(exp, _ATOM)}", _POW

    def _function(self, e):
        name = type(e).__name__
        args = [self._p(a)[0] for a in e.args]
        if name in self.funcs:
            if name == "log" and len(args) == 2:
                log = self.funcs["log"]
                return f"({log}({args[0]})/{log}({args[1]}))", _ATOM
            return f"{self.funcs[name]}({', '.join(args)})", _ATOM
        if name == "sign":
            a = args[0]
            return (f"((double)((({a}) > 0) - (({a}) < 0)))" if self.c
                    else f"_sign({a})"), _ATOM
        if name == "Heaviside":
            a = args[0]
            return (f"(({a}) > 0 ? 1.0 : (({a}) < 0 ? 0.0 : 0.5))" if self.c
                    else f"_heaviside({a})"), _ATOM
        if name in ("Max", "Min"):
            if self.c:
                fn = "fmax" if name == "Max" else "fmin"
                text = args[0]
                for a in args[1:]:
                    text = f"{fn}({text}, {a})"
                return text, _ATOM
            return f"{name.lower()}({', '.join(args)})", _ATOM
        if name == "factorial":
            return (f"tgamma({args[0]} + 1.0)" if self.c
                    else f"math.gamma({args[0]} + 1.0)"), _ATOM
        if name in ("sec", "csc", "cot"):
            inner = {"sec": "cos", "csc": "sin", "cot": "tan"}[name]
            return f"(1.0/{self.funcs[inner]}({args[0]}))", _ATOM
        raise AutolevModelError(f"cannot generate numeric code for the function {name}")

    def _piecewise(self, e):
        pieces = list(e.args)
        text = "NAN" if self.c else "math.nan"
        for value, cond in reversed(pieces):
            v = self._p(value)[0]
            if cond is sm.true:
                text = v
                continue
            c = self._p(cond)[0]
            text = f"(({c}) ? ({v}) : ({text}))" if self.c else \
                f"(({v}) if ({c}) else ({text}))"
        return text, _ATOM

    def _relational(self, e):
        op = {"<": "<", "<=": "<=", ">": ">", ">=": ">=", "==": "==", "!=": "!="}[e.rel_op]
        return f"({self._p(e.lhs)[0]} {op} {self._p(e.rhs)[0]})", _ATOM


# -- the namespace printed Python runs in ---------------------------------------------
def _sign(x):
    return (x > 0) - (x < 0)


def _heaviside(x):
    return 1.0 if x > 0 else (0.5 if x == 0 else 0.0)


def _trunc(x):
    return float(math.trunc(x))


def _round(x):
    # C's round: halves away from zero (x - trunc(x) is exact in double precision)
    t = float(math.trunc(x))
    return t + math.copysign(1.0, x) if abs(x - t) >= 0.5 else t


def _np_round(x):
    t = np.trunc(x)
    return t + np.copysign(1.0, x) * (np.abs(x - t) >= 0.5)


class _NumpyMath:
    """`math` for the fallback evaluation: numpy's functions, which give inf and nan
    where math raises (as the C code does)."""

    def __getattr__(self, name):
        if name in ("gamma", "erf"):
            import scipy.special   # 0.1 s to import: only where math raised
            return getattr(scipy.special, name)
        return getattr(np, {"fabs": "abs", "atan2": "arctan2", "asin": "arcsin",
                            "acos": "arccos", "atan": "arctan", "asinh": "arcsinh",
                            "acosh": "arccosh", "atanh": "arctanh"}.get(name, name))


# what the math module raises where C gives inf or nan
MATH_ERRORS = (ZeroDivisionError, ValueError, OverflowError, TypeError)


def _np_heaviside(x):
    return np.heaviside(x, 0.5)


def fast_namespace() -> dict:
    """What the printed Python calls: the math module and C's sign, step, trunc, round."""
    return {"math": math, "_sign": _sign, "_heaviside": _heaviside, "_trunc": _trunc,
            "_round": _round}


def safe_namespace() -> dict:
    """The same names on numpy, which gives inf and nan where math raises (as C does)."""
    return {"math": _NumpyMath(), "_sign": np.sign, "_heaviside": _np_heaviside,
            "_trunc": np.trunc, "_round": _np_round}


def number_value(expr) -> float:
    """A closed-form number (no symbols) in double precision, computed as the generated
    code computes it: inf or nan where that overflows or is undefined."""
    code = compile(CodePrinter("python", {})(expr), "<autolev number>", "eval")
    try:
        return float(eval(code, fast_namespace()))
    except MATH_ERRORS:
        with np.errstate(all="ignore"):
            return float(eval(code, safe_namespace()))
