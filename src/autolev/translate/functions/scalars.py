"""Scalar functions: the elementary ones (onto sympy, checked in double precision as
Autolev computed), ATAN2, LOG10, SQR, INT, ROUND, MAX, MIN, UNITS and INPUT."""
from __future__ import annotations

import math

from ... import ir
from ..core import Translator
from ..kinds import ATOM, Typed, ValueType
from ..emit import quote
from .arguments import describe_not_a_name
from .table import function, nargs

# beyond this, exact computation takes minutes or gigabytes for what a model never needs
MAX_FACTORIAL = 450          # 450! has 1001 digits

# the elementary functions by the name of their sympy function (sm.<name>)
ELEMENTARY = {"SIN": "sin", "COS": "cos", "TAN": "tan", "ASIN": "asin", "ACOS": "acos",
              "ATAN": "atan", "SINH": "sinh", "COSH": "cosh", "TANH": "tanh", "EXP": "exp",
              "LOG": "log", "SQRT": "sqrt", "ABS": "Abs", "SIGN": "sign",
              "FACTORIAL": "factorial", "CEIL": "ceiling", "FLOOR": "floor", "SEC": "sec",
              "CSC": "csc", "COT": "cot", "ASINH": "asinh", "ACOSH": "acosh",
              "ATANH": "atanh"}


# the same functions in double precision, to catch a number beyond a double's range
_DOUBLE = {"SIN": math.sin, "COS": math.cos, "TAN": math.tan, "ASIN": math.asin,
           "ACOS": math.acos, "ATAN": math.atan, "SINH": math.sinh, "COSH": math.cosh,
           "TANH": math.tanh, "EXP": math.exp, "LOG": math.log, "SQRT": math.sqrt,
           "ABS": abs, "FACTORIAL": lambda v: math.gamma(v + 1), "ASINH": math.asinh,
           "ACOSH": math.acosh, "ATANH": math.atanh}


def _elementary(tr: Translator, c: ir.Call) -> Typed:
    (a,) = nargs(tr, c, 1)
    x = tr.expr(a)              # once: translating an argument twice is exponential
    name = c.name.upper()
    fn = "sm." + ELEMENTARY[name]
    if fn == "sm.factorial" and x.exact is not None and x.exact > MAX_FACTORIAL:
        raise tr.error(f"FACTORIAL({x.exact}) has more than a thousand digits; at most "
                       f"FACTORIAL({MAX_FACTORIAL}) is computed exactly", c, "T005")
    if x.type == ValueType.MATRIX:
        return Typed(f"{x.wrapped(ATOM)}.applyfunc({fn})", ValueType.MATRIX)
    if x.type not in (ValueType.SCALAR, ValueType.UNKNOWN):
        raise tr.error(f"a scalar is needed here, not a {x.type}", a, "T001")
    return Typed(f"{fn}({x.code})", ValueType.SCALAR, approx=_double_value(tr, c, name, x))


def _double_value(tr: Translator, c: ir.Call, name: str, x: Typed) -> float | None:
    """The function of a number in double precision, as Autolev computed it; a value
    beyond a double's range is refused (sympy would keep EXP(1E6) exact, and the sine
    of it takes millions of digits)."""
    if name not in _DOUBLE:
        return None
    v = x.double
    if v is None:
        return None
    try:
        r = _DOUBLE[name](v)
    except (ValueError, ZeroDivisionError):
        return None             # outside the real domain: sympy's complex value stays
    except OverflowError:
        r = math.inf
    if math.isinf(r):
        raise tr.error(f"{name} of this number is beyond double precision (more than "
                       "1.8E308); Autolev computed numbers in doubles", c, "T005")
    return r


function(*ELEMENTARY)(_elementary)


@function("ATAN2")
def _atan2(tr, c):
    y, x = nargs(tr, c, 2)
    return Typed(f"sm.atan2({tr.scalar(y).code}, {tr.scalar(x).code})", ValueType.SCALAR)


@function("LOG10")
def _log10(tr, c):
    (a,) = nargs(tr, c, 1)
    return Typed(f"sm.log({tr.scalar(a).code}, 10)", ValueType.SCALAR)


@function("SQR")
def _sqr(tr, c):
    (a,) = nargs(tr, c, 1)
    return Typed(f"{tr.scalar(a).wrapped(8)}**2", ValueType.SCALAR, 7)


@function("INT")
def _int(tr, c):
    (a,) = nargs(tr, c, 1)
    return Typed(f"al.integer_part({tr.scalar(a).code})", ValueType.SCALAR)


@function("ROUND")
def _round(tr, c):
    (a,) = nargs(tr, c, 1)
    return Typed(f"al.round_half_away({tr.scalar(a).code})", ValueType.SCALAR)


def _plain(tr: Translator, c: ir.Call):
    for a in c.args:
        if isinstance(a, (ir.Range, ir.Equation)):
            sign = "=" if isinstance(a, ir.Equation) else ":"
            raise tr.error(f"{c.name.upper()} does not take '{sign}' "
                           "arguments", a, "T009")


@function("MAX", "MIN")
def _maxmin(tr, c):
    _plain(tr, c)
    if not c.args:
        raise tr.error(f"{c.name.upper()} needs arguments", c, "T007")
    items = ", ".join(tr.scalar(a).code for a in c.args)
    function = "maximum" if c.name.upper() == "MAX" else "minimum"
    return Typed(f"al.{function}({items})", ValueType.SCALAR)


# -- units and inputs ------------------------------------------------------------------
@function("UNITS")
def _units(tr, c):
    a, b = nargs(tr, c, 2)
    ua, ub = _unit_text(tr, a), _unit_text(tr, b)
    from ...runtime.functions import units_factor
    from ...engine.errors import AutolevModelError
    try:
        units_factor(ua, ub)              # unknown units and unlike kinds: diagnosed here
    except AutolevModelError as exc:
        raise tr.error(str(exc), c, "T003") from None
    return Typed(f"al.units_factor({quote(ua)}, {quote(ub)})", ValueType.SCALAR)


def _unit_text(tr, e) -> str:
    if isinstance(e, ir.Name):
        return e.name
    if isinstance(e, ir.BinOp) and e.op in "*/^":
        return f"{_unit_text(tr, e.left)}{e.op}{_unit_text(tr, e.right)}"
    if isinstance(e, ir.Number):
        return e.text
    raise tr.error("UNITS takes unit names such as deg, rad, n*m, lbf*ft", e, "T009")


@function("INPUT")
def _input(tr, c):
    (a,) = nargs(tr, c, 1)
    if not (isinstance(a, ir.Name) and a.name.lower() in tr.scalars):
        x = tr.expr(a)
        raise tr.error(f"INPUT(x) is the value INPUT gave to a declared name x, not to "
                       f"{describe_not_a_name(tr, a, x)}", a, "T008")
    return Typed(f"model.input_value({tr.symbol(a)})", ValueType.SCALAR)  # SI (radians)
