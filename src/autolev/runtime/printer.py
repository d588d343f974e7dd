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
from enum import IntEnum

import sympy as sm
from sympy.core.numbers import NumberSymbol

from ..engine.errors import AutolevModelError
from ..engine.functions import FUNCTION_BY_SYMPY, SQRT, written
from ..engine.pyfunction import MATH_ERRORS, fast_namespace, safe_namespace

class Precedence(IntEnum):
    """How tightly a printed construct binds (higher binds tighter): a subexpression
    below the precedence its place needs is parenthesised."""

    ADD = 1
    MUL = 2
    UNARY = 3
    POW = 4
    ATOM = 5


ADD, MUL, UNARY, POW, ATOM = (Precedence.ADD, Precedence.MUL, Precedence.UNARY,
                              Precedence.POW, Precedence.ATOM)


def fraction_parts(mul) -> tuple[list, list]:
    """A product's factors as printed: (numerator, denominator), a factor x**-k in the
    denominator as x**k and a rational 1/q as q (the walk of interpret.py divides alike)."""
    num, den = [], []
    for f in mul.args:
        if f.is_Pow and f.exp.is_Number and f.exp.is_negative:
            den.append(f.base if f.exp == -1 else sm.Pow(f.base, -f.exp, evaluate=False))
        elif f.is_Rational and not f.is_Integer and f.p == 1:
            den.append(sm.Integer(f.q))
        else:
            num.append(f)
    return num, den


class CodePrinter:
    """The walk every language's printer shares: each expression once, in sympy's
    argument order, compound subexpressions printed once; `names` maps symbols to
    their code.  A language is a subclass that gives its words (the class attributes)
    and overrides the hooks where its syntax differs (`_power`, `_choice`, `_truth`,
    `_argument`); its functions are spelt by the records of engine/functions.py."""

    ONE = "1.0"             # the numerator of a reciprocal
    # the language: its field of the function records, its name in messages, and what
    # a refusal says cannot be generated
    LANGUAGE: str
    LANGUAGE_NAME: str
    GENERATES = "numeric code"
    # the language's words: logic; NaN, infinity, pi, e
    AND: str
    OR: str
    NOT: str
    NAN: str
    INF: str
    PI: str
    E: str

    def __init__(self, names: dict):
        self.names = names
        self._memo: dict = {}

    def __call__(self, expr) -> str:
        return self._p(sm.sympify(expr))[0]

    def bind(self, expr, text: str) -> None:
        """From now on print `expr` (a compound expression) as `text` (the variable
        that holds its value)."""
        self._memo[expr] = (text, ATOM)

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
                return self.names[e], ATOM
            except KeyError:
                raise AutolevModelError(f"no value for {e}") from None
        if e.is_Number:
            return self._number(e)
        if isinstance(e, NumberSymbol):
            return self._constant(e)
        if e is sm.true or e is sm.false:
            return self._truth(e is sm.true), ATOM
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
        # And, Or and Not are Functions too (sympy's BooleanFunction)
        if isinstance(e, (sm.And, sm.Or, sm.Not)):
            return self._logic(e)
        if e.is_Function:
            return self._function(e)
        if e.is_Relational:
            return self._relational(e)
        raise AutolevModelError(f"cannot generate numeric code for {type(e).__name__}: {e}")

    def _wrap(self, e, prec: int) -> str:
        text, p = self._p(e)
        return f"({text})" if p < prec else text

    def _number(self, e):
        if e is sm.nan or e is sm.zoo:
            return self.NAN, ATOM
        if e in (sm.oo, -sm.oo):
            return (self.INF if e is sm.oo else f"(-{self.INF})"), ATOM
        v = float(e)
        if math.isinf(v):
            raise AutolevModelError(f"the number {sm.Float(e, 6)} is beyond double precision "
                                    "(more than 1.8E308); Autolev computed in doubles")
        text = repr(v)
        if "e" not in text and "." not in text and "inf" not in text and "nan" not in text:
            text += ".0"
        return text, (UNARY if v < 0 else ATOM)

    def _constant(self, e):
        if e is sm.pi:
            return self.PI, ATOM
        if e is sm.E:
            return self.E, ATOM
        return self._number(sm.Float(e))

    def _add(self, e):
        parts = []
        for k, term in enumerate(e.args):
            coeff, rest = term.as_coeff_Mul()
            if k > 0 and coeff.is_Number and coeff.is_negative:
                neg = -term
                parts.append(" - " + self._wrap(neg, MUL))
            else:
                text = self._wrap(term, ADD)
                parts.append((" + " if k else "") + text)
        return "".join(parts), ADD

    def _mul(self, e):
        coeff, rest = e.as_coeff_Mul()
        if coeff == -1:
            return "-" + self._wrap(rest, MUL + 1 if rest.is_Mul else UNARY), UNARY
        num, den = fraction_parts(e)
        if not den:
            return "*".join(self._wrap(f, MUL) for f in num), MUL
        top = "*".join(self._wrap(f, MUL) for f in num) if num else self.ONE
        if len(den) == 1:
            bottom = self._wrap(den[0], POW)
        else:
            bottom = "(" + "*".join(self._wrap(f, MUL) for f in den) + ")"
        return f"{top}/{bottom}", MUL

    def _pow(self, e):
        base, exp = e.base, e.exp
        if exp == sm.Rational(1, 2):
            return self._sqrt(base), ATOM
        if exp == -1:
            return f"{self.ONE}/{self._wrap(base, POW)}", MUL
        if exp == sm.Rational(-1, 2):
            return f"{self.ONE}/{self._sqrt(base)}", MUL
        return self._power(base, exp)

    def _sqrt(self, base) -> str:
        return written(SQRT.spelling(self.LANGUAGE), [self._argument(base)])

    def _argument(self, e) -> str:
        """`e` as a function's argument."""
        return self._p(e)[0]

    # -- hooks: what each language says its own way ----------------------------------
    def _truth(self, value: bool) -> str:
        raise NotImplementedError

    def _power(self, base, exp):
        """base**exp for an exponent other than 1/2, -1 and -1/2: (text, precedence)."""
        raise NotImplementedError

    def _choice(self, condition: str, value: str, otherwise: str) -> str:
        """value where condition holds, else otherwise."""
        raise NotImplementedError

    def _logic(self, e):
        """And, Or (infix: AND, OR) and Not (prefix: NOT)."""
        if isinstance(e, sm.Not):
            return self.NOT + self._wrap(e.args[0], ATOM), UNARY
        op = self.AND if isinstance(e, sm.And) else self.OR
        return "(" + op.join(self._p(a)[0] for a in e.args) + ")", ATOM

    def _function(self, e):
        name = type(e).__name__
        args = [self._argument(a) for a in e.args]
        spec = FUNCTION_BY_SYMPY.get(name)
        if spec is None or spec.arity not in (None, len(args)):
            raise AutolevModelError(f"cannot generate {self.GENERATES} for the function "
                                    f"{name}")
        spelling = spec.spelling(self.LANGUAGE)
        if spelling is None:
            raise AutolevModelError(f"{name} has no {self.LANGUAGE_NAME} function to print "
                                    "it as")
        return written(spelling, args), ATOM

    def _piecewise(self, e):
        text = self.NAN
        for value, cond in reversed(list(e.args)):
            v = self._p(value)[0]
            text = v if cond is sm.true else self._choice(self._p(cond)[0], v, text)
        return text, ATOM

    def _relational(self, e):
        op = {"<": "<", "<=": "<=", ">": ">", ">=": ">=", "==": "==", "!=": "!="}[e.rel_op]
        return f"({self._p(e.lhs)[0]} {op} {self._p(e.rhs)[0]})", ATOM


class CPrinter(CodePrinter):
    """C (math.h)."""

    LANGUAGE, LANGUAGE_NAME = "c", "C"
    AND, OR, NOT = " && ", " || ", "!"
    NAN, INF = "NAN", "INFINITY"
    PI, E = "M_PI", "M_E"

    def _truth(self, value: bool) -> str:
        return "1" if value else "0"

    def _power(self, base, exp):
        return f"pow({self._p(base)[0]}, {self._p(exp)[0]})", ATOM

    def _choice(self, condition: str, value: str, otherwise: str) -> str:
        return f"(({condition}) ? ({value}) : ({otherwise}))"


class LanesUnsupported(Exception):
    """A construct CLanesPrinter does not print (its program is printed for one node)."""


LANES = 4           # nodes a lanes program computes at once


class CLanesPrinter(CPrinter):
    """C over LANES nodes at once: every symbol is a GCC vector (`al_v`) of one value
    per node, so each statement computes LANES nodes' values and a program's text is
    read once for all of them (a big program's instructions, not its arithmetic, bound
    its time).  The operations on each lane are C's, in the same order: the same bits.
    Numbers stay scalars (C broadcasts them into the vectors they meet); a function is
    called lane by lane.  Choices (Piecewise, logic, comparisons) are not printed."""

    def __init__(self, names: dict):
        super().__init__(names)
        self._varies: dict = {}

    def bind(self, expr, text: str) -> None:
        super().bind(expr, text)
        self._varies[expr] = True           # its variable is a vector, as all of them

    def varies(self, e) -> bool:
        """Whether `e` is printed as a vector: it holds a symbol or a bound variable."""
        if e.is_Symbol:
            return True
        if e.is_Atom:
            return False
        hit = self._varies.get(e)
        if hit is None:
            hit = self._varies[e] = any(self.varies(a) for a in e.args)
        return hit

    def _lanewise(self, spelling, args: list) -> str:
        """`spelling` called on each lane of `args` (vectors; numbers as they are)."""
        taken = [f"al_v _a{k} = {self._p(a)[0]}; " for k, a in enumerate(args)
                 if self.varies(a)]
        lanes = []
        for lane in range(LANES):
            texts = [f"_a{k}[{lane}]" if self.varies(a) else self._p(a)[0]
                     for k, a in enumerate(args)]
            lanes.append(written(spelling, texts))
        return "({ " + "".join(taken) + "(al_v){" + ", ".join(lanes) + "}; })"

    def _power(self, base, exp):
        if not self.varies(base) and not self.varies(exp):
            return super()._power(base, exp)
        if exp == 2:            # gcc's own reading of pow(b, 2)
            b = self._wrap(base, ATOM)
            return f"({b}*{b})", ATOM
        return self._lanewise("pow", [base, exp]), ATOM

    def _sqrt(self, base) -> str:
        if not self.varies(base):
            return super()._sqrt(base)
        return self._lanewise(SQRT.spelling(self.LANGUAGE), [base])

    def _function(self, e):
        if not self.varies(e):
            return super()._function(e)
        spec = FUNCTION_BY_SYMPY.get(type(e).__name__)
        if spec is None or spec.arity not in (None, len(e.args)) \
                or spec.spelling(self.LANGUAGE) is None:
            return super()._function(e)          # which names the refusal
        return self._lanewise(spec.spelling(self.LANGUAGE), list(e.args)), ATOM

    def _choice(self, condition: str, value: str, otherwise: str) -> str:
        raise LanesUnsupported("a choice")

    def _logic(self, e):
        raise LanesUnsupported("logic")

    def _relational(self, e):
        raise LanesUnsupported("a comparison")


class PythonPrinter(CodePrinter):
    """Python on `math` (and engine/pyfunction.py's _sign, _heaviside, _trunc, _round)."""

    LANGUAGE, LANGUAGE_NAME = "python", "Python"
    AND, OR, NOT = " and ", " or ", "not "
    NAN, INF = "math.nan", "math.inf"
    PI, E = "math.pi", "math.e"

    def _truth(self, value: bool) -> str:
        return str(value)

    def _power(self, base, exp):
        if exp == 2:
            # as gcc compiles C's pow(b, 2): b*b (libm's pow may round otherwise)
            b = self._wrap(base, ATOM)
            return f"({b}*{b})", ATOM
        if exp.is_Integer:
            # Python's ** with an integer exponent: like C's pow for these values
            return f"{self._wrap(base, ATOM)}**{int(exp)}", POW
        return f"{self._wrap(base, ATOM)}**{self._wrap(exp, ATOM)}", POW

    def _choice(self, condition: str, value: str, otherwise: str) -> str:
        return f"(({value}) if ({condition}) else ({otherwise}))"


class CasadiPrinter(CodePrinter):
    """Python building CasADi's symbolic expressions (`import casadi as ca`): the
    printed program run on SX symbols gives the model's equations as CasADi's graph,
    which CasADi differentiates and compiles itself."""

    LANGUAGE, LANGUAGE_NAME = "casadi", "CasADi"
    GENERATES = "CasADi expressions"
    NAN, INF = "math.nan", "ca.inf"
    PI, E = "ca.pi", "math.e"

    def _truth(self, value: bool) -> str:
        return "1.0" if value else "0.0"

    def _power(self, base, exp):
        return f"{self._wrap(base, ATOM)}**{self._wrap(exp, ATOM)}", POW

    def _choice(self, condition: str, value: str, otherwise: str) -> str:
        return f"ca.if_else({condition}, {value}, {otherwise})"

    def _logic(self, e):
        if isinstance(e, sm.Not):
            return f"ca.logic_not({self._p(e.args[0])[0]})", ATOM
        call = "ca.logic_and" if isinstance(e, sm.And) else "ca.logic_or"
        texts = [self._p(a)[0] for a in e.args]
        text = texts[0]
        for other in texts[1:]:
            text = f"{call}({text}, {other})"
        return text, ATOM


def number_value(expr) -> float:
    """A closed-form number (no symbols) in double precision, computed as the generated
    code computes it: inf or nan where that overflows or is undefined."""
    code = compile(PythonPrinter({})(expr), "<autolev number>", "eval")
    try:
        return float(eval(code, fast_namespace()))
    except MATH_ERRORS:
        import numpy as np  # where math raised: a model's forming needs no numpy otherwise
        with np.errstate(all="ignore"):
            return float(eval(code, safe_namespace()))
