"""Scalar functions: those of engine/functions.py's records (SIN, ATAN2, LOG10, INT,
MAX, ...: what each record says the translated Python calls; a number checked in double
precision as Autolev computed it) with SQR's power, and UNITS and INPUT."""
from __future__ import annotations

import math

from ... import ir
from ...engine.functions import FUNCTION_BY_NAME, FUNCTION_SPECS, SQR, FunctionSpec
from ..core import Translator
from ..kinds import ATOM, Typed, ValueType
from ..emit import quote
from .arguments import describe_not_a_name
from .table import function, nargs


def _call(tr: Translator, c: ir.Call) -> Typed:
    """A call of a function of engine/functions.py's records: what its record says the
    translated Python calls, of scalars or of a matrix entry by entry."""
    spec = FUNCTION_BY_NAME[c.name.upper()]
    if spec.entrywise:
        return _entrywise(tr, c, spec)
    if spec.arity is None:
        _plain(tr, c)
        if not c.args:
            raise tr.error(f"{spec.autolev} needs arguments", c, "T007")
        args = c.args
    else:
        args = nargs(tr, c, spec.arity)
    codes = [tr.scalar(a).code for a in args] + [str(k) for k in spec.fixed_arguments]
    return Typed(f"{spec.callee}({', '.join(codes)})", ValueType.SCALAR)


def _entrywise(tr: Translator, c: ir.Call, spec: FunctionSpec) -> Typed:
    (a,) = nargs(tr, c, 1)
    x = tr.expr(a)              # once: translating an argument twice is exponential
    name, largest = spec.autolev, spec.largest_exact_argument
    if largest is not None and x.exact is not None and x.exact > largest:
        raise tr.error(f"{name}({x.exact}) has more than a thousand digits; at most "
                       f"{name}({largest}) is computed exactly", c, "T005")
    if x.type == ValueType.MATRIX:
        return Typed(f"{x.wrapped(ATOM)}.applyfunc({spec.callee})", ValueType.MATRIX)
    if x.type not in (ValueType.SCALAR, ValueType.UNKNOWN):
        raise tr.error(f"a scalar is needed here, not a {x.type}", a, "T001")
    return Typed(f"{spec.callee}({x.code})", ValueType.SCALAR,
                 approx=_double_value(tr, c, spec, x))


def _double_value(tr: Translator, c: ir.Call, spec: FunctionSpec, x: Typed) -> float | None:
    """The function of a number in double precision, as Autolev computed it; a value
    beyond a double's range is refused (sympy would keep EXP(1E6) exact, and the sine
    of it takes millions of digits)."""
    if spec.double is None:
        return None
    v = x.double
    if v is None:
        return None
    try:
        r = spec.double(v)
    except (ValueError, ZeroDivisionError):
        return None             # outside the real domain: sympy's complex value stays
    except OverflowError:
        r = math.inf
    if math.isinf(r):
        raise tr.error(f"{spec.autolev} of this number is beyond double precision (more "
                       "than 1.8E308); Autolev computed numbers in doubles", c, "T005")
    return r


def _plain(tr: Translator, c: ir.Call):
    for a in c.args:
        if isinstance(a, (ir.Range, ir.Equation)):
            sign = "=" if isinstance(a, ir.Equation) else ":"
            raise tr.error(f"{c.name.upper()} does not take '{sign}' "
                           "arguments", a, "T009")


function(*(s.autolev for s in FUNCTION_SPECS if s.autolev is not None
            and s.callee is not None))(_call)


# SQR(x) is x**2: a power, not a call
@function(SQR.autolev)
def _sqr(tr, c):
    (a,) = nargs(tr, c, 1)
    return Typed(f"{tr.scalar(a).wrapped(8)}**2", ValueType.SCALAR, 7)


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
