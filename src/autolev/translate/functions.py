"""Autolev functions in expressions: one small writer per function.

Each writer gets the translator and the call, checks its arguments, and returns the
Python (with its type).  Elementary functions map onto sympy; everything with
Autolev's own meaning (DT through definitions, EVALUATE, KE, ...) onto the runtime.
"""
from __future__ import annotations

import difflib
import math

from .. import ir
from .core import ATOM, EXPRESSIONS, NameKind, Translator, Typed, ValueType
from .emit import quote
from .special import classify

FUNCTIONS: dict = {}
# beyond these, exact computation takes minutes or gigabytes for what a model never needs
MAX_FACTORIAL = 450          # 450! has 1001 digits
MAX_TAYLOR_ORDER = 30
# functions nested deeper than this make sympy's automatic evaluation exponential (the
# real-imaginary split of TANH(SINH(...)) 150 deep runs for hours); models nest three
MAX_CALL_NESTING = 32


def function(*names):
    def register(fn):
        for n in names:
            FUNCTIONS[n] = fn
        return fn
    return register


@EXPRESSIONS.register(ir.Call)
def call_expression(tr: Translator, e: ir.Call, want: str) -> Typed:
    if tr.call_depth >= MAX_CALL_NESTING:
        raise tr.error(f"functions nested more than {MAX_CALL_NESTING} deep; at most "
                       f"{MAX_CALL_NESTING} are translated (name the inner parts)",
                       e, "T004")
    tr.call_depth += 1
    try:
        return call(tr, e)
    finally:
        tr.call_depth -= 1


def call(tr: Translator, c: ir.Call) -> Typed:
    fn = FUNCTIONS.get(c.name.upper())
    if fn is None:
        raise tr.error(f"unknown function {c.name.upper()}(): Autolev has no such function, "
                       f"and no user function file {c.name}.R is next to the model"
                       + did_you_mean(c.name, FUNCTIONS), c, "T003")
    return fn(tr, c)


def did_you_mean(word: str, known) -> str:
    """'; did you mean A, B or C?' for the known words closest to a misspelt one."""
    close = difflib.get_close_matches(word.upper(), known, n=3, cutoff=0.6)
    if not close:
        return ""
    return "; did you mean " + (" or ".join(close) if len(close) < 3 else
                                f"{close[0]}, {close[1]} or {close[2]}") + "?"


def nargs(tr: Translator, c: ir.Call, *counts: int) -> list:
    if len(c.args) not in counts:
        want = " or ".join(str(n) for n in counts)
        raise tr.error(f"{c.name.upper()} takes {want} argument"
                       f"{'s' if counts != (1,) else ''}, not {len(c.args)}", c, "T007")
    return list(c.args)


def _plain(tr: Translator, c: ir.Call):
    for a in c.args:
        if isinstance(a, (ir.Range, ir.Equation)):
            sign = "=" if isinstance(a, ir.Equation) else ":"
            raise tr.error(f"{c.name.upper()} does not take '{sign}' "
                           "arguments", a, "T009")


# -- the kinds of arguments -----------------------------------------------------------
# what no function takes where it wants an expression
_NOT_VALUES = (ValueType.FRAME, ValueType.POINT, ValueType.LIST, ValueType.STRING)
_NAME_OF_KIND = {NameKind.NEWTONIAN: "the Newtonian frame", NameKind.FRAME: "a frame",
                 NameKind.BODY: "a body", NameKind.POINT: "a point",
                 NameKind.PARTICLE: "a particle"}


def _what(tr: Translator, node, x: Typed) -> str:
    """What an argument is, for a message: a body, a vector, a number, ..."""
    if x.type in (ValueType.FRAME, ValueType.POINT) and isinstance(node, ir.Name):
        ent = tr.entities.get(node.name.lower())
        if ent is not None:
            return _NAME_OF_KIND.get(ent.kind, f"a {x.type}")
    if _is_number(x):
        return "a number"
    return f"a {x.type}"


def _what_not_a_name(tr: Translator, node, x: Typed) -> str:
    """What an argument that should be a name is: a number, an expression, a vector, ..."""
    if x.type == ValueType.SCALAR and not _is_number(x):
        return "an expression"
    return _what(tr, node, x)


def _is_number(x: Typed) -> bool:
    return x.exact is not None or x.approx is not None


def _value(tr: Translator, a, what: str) -> Typed:
    """An argument that is an expression: a scalar, vector, dyadic or matrix."""
    x = tr.expr(a)
    if x.type in _NOT_VALUES:
        raise tr.error(f"{what} takes an expression, not {_what(tr, a, x)}", a, "T001")
    return x


def _names(tr: Translator, a, what: str) -> Typed:
    """The quantities a function works on: a name (or a product of names, x*y), or a
    list of them ([x, y])."""
    x = tr.expr(a)
    if x.type not in (ValueType.SCALAR, ValueType.MATRIX, ValueType.UNKNOWN) or _is_number(x):
        raise tr.error(f"{what} takes a name or a list of names ([x, y]) here, not "
                       f"{_what(tr, a, x)}", a, "T001")
    for el in x.elements or ():
        if not any(isinstance(n, ir.Name) for n in ir.walk(el)):
            raise tr.error(f"{what} takes a list of names ([x, y]) here; this one holds a "
                           "number", a, "T001")
    return x


def _variable(tr: Translator, a, what: str) -> Typed:
    """A name to differentiate with respect to (Q, Q', U1), or a list of them."""
    x = tr.expr(a)
    if x.type == ValueType.MATRIX and x.elements is not None:
        for el in x.elements:
            if not isinstance(el, ir.Name):
                raise tr.error(f"{what} differentiates with respect to a list of names; "
                               "this one holds an expression", a, "T009")
    if x.type in (ValueType.MATRIX, ValueType.UNKNOWN) or \
            (x.type == ValueType.SCALAR and isinstance(a, ir.Name)):
        return x
    raise tr.error(f"{what} differentiates with respect to a name or a list of names, "
                   f"not {_what_not_a_name(tr, a, x)}", a, "T009")


def _number(tr: Translator, a, what: str) -> Typed:
    """A count, degree, index or tolerance: a scalar holding no declared quantity (a
    variable or constant is a symbol, never a number)."""
    x = tr.expr(a)
    if x.type not in (ValueType.SCALAR, ValueType.UNKNOWN):
        raise tr.error(f"{what} must be a number, not {_what(tr, a, x)}", a, "T001")
    for node in ir.walk(a):
        entry = tr.scalars.get(node.name.lower()) if isinstance(node, ir.Name) else None
        if entry is not None:
            raise tr.error(f"{what} must be a number, not {node.name}{chr(39) * node.primes} "
                           f"(a {entry.kind})", node, "T009")
    return x


def _declared_in(tr: Translator, elements) -> ir.Name | None:
    """The first declared quantity (a symbol, never a number) in a literal's elements."""
    for el in elements or ():
        for node in ir.walk(el):
            if isinstance(node, ir.Name) and node.name.lower() in tr.scalars:
                return node
    return None


def _is_unit_vector(tr: Translator, a) -> bool:
    """N1>, N2>, N3> of a declared frame or body."""
    if not isinstance(a, ir.VectorName) or a.dyadic:
        return False
    sp = classify(tr, a)
    return sp is not None and sp.kind == "unit"


# -- elementary scalar functions ---------------------------------------------------
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


for _n in ELEMENTARY:
    FUNCTIONS[_n] = _elementary


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


@function("MAX", "MIN")
def _maxmin(tr, c):
    _plain(tr, c)
    if not c.args:
        raise tr.error(f"{c.name.upper()} needs arguments", c, "T007")
    items = ", ".join(tr.scalar(a).code for a in c.args)
    function = "maximum" if c.name.upper() == "MAX" else "minimum"
    return Typed(f"al.{function}({items})", ValueType.SCALAR)


# -- vectors -----------------------------------------------------------------------
@function("DOT")
def _dot(tr, c):
    a, b = nargs(tr, c, 2)
    x, y = tr.expr(a), tr.expr(b)
    for v, node in ((x, a), (y, b)):
        if v.type not in (ValueType.VECTOR, ValueType.DYADIC, ValueType.VECTORS, ValueType.UNKNOWN):
            raise tr.error(f"DOT takes vectors or dyadics, not a {v.type}", node, "T001")
    rtype = ValueType.SCALAR if x.type == y.type == ValueType.VECTOR else \
        ValueType.VECTOR if ValueType.VECTOR in (x.type, y.type) else ValueType.DYADIC
    if ValueType.VECTORS in (x.type, y.type):
        rtype = ValueType.MATRIX
    return Typed(f"al.dot({x.code}, {y.code})", rtype)


@function("CROSS")
def _cross(tr, c):
    a, b = nargs(tr, c, 2)
    x, y = tr.expr(a), tr.expr(b)
    for v, node in ((x, a), (y, b)):
        if v.type not in (ValueType.VECTOR, ValueType.DYADIC, ValueType.UNKNOWN):
            raise tr.error(f"CROSS takes vectors, not a {v.type}", node, "T001")
    rtype = ValueType.DYADIC if ValueType.DYADIC in (x.type, y.type) else ValueType.VECTOR
    return Typed(f"al.cross({x.code}, {y.code})", rtype)


@function("MAG")
def _mag(tr, c):
    (a,) = nargs(tr, c, 1)
    x = _vector_arg(tr, a, "MAG")
    return Typed(f"al.mag({x.code})", ValueType.SCALAR)


@function("UNITVEC")
def _unitvec(tr, c):
    (a,) = nargs(tr, c, 1)
    x = _vector_arg(tr, a, "UNITVEC")
    return Typed(f"al.unitvec({x.code})", ValueType.VECTOR)


def _vector_arg(tr, a, what):
    x = tr.expr(a)
    if x.type not in (ValueType.VECTOR, ValueType.UNKNOWN):
        raise tr.error(f"{what} takes a vector, not a {x.type}", a, "T001")
    return x


@function("EXPRESS")
def _express(tr, c):
    args = nargs(tr, c, 2, 3)
    x = tr.expr(args[0])
    frames = [tr.frame(f).code for f in args[1:]]
    if x.type not in (ValueType.VECTOR, ValueType.DYADIC, ValueType.MATRIX, ValueType.UNKNOWN):
        raise tr.error(f"EXPRESS takes a vector or dyadic, not a {x.type}", args[0], "T001")
    return Typed(f"al.express({x.code}, {', '.join(frames)})", x.type)


@function("VECTOR")
def _vector(tr, c):
    args = nargs(tr, c, 2, 4)
    f = tr.frame(args[0]).code
    if len(args) == 2:
        rest = [_matrix_arg(tr, args[1], "VECTOR(A, M)")]
        shape = rest[0].shape
        if shape is not None and shape[0] * shape[1] != 3:
            raise tr.error(f"VECTOR(A, M) takes the 3 measure numbers, not a {shape[0]}x"
                           f"{shape[1]} matrix", args[1], "T001")
    else:
        rest = [tr.scalar(a) for a in args[1:]]
    return Typed(f"al.vector({f}, {', '.join(r.code for r in rest)})", ValueType.VECTOR)


@function("MATRIX")
def _matrix(tr, c):
    """MATRIX(A, V>) is a column of measure numbers; MATRIX(A, D>>[, B]) is 3x3."""
    args = nargs(tr, c, 2, 3)
    frames = [tr.frame(args[0]).code] + [tr.frame(a).code for a in args[2:]]
    x = tr.expr(args[1])
    if x.type not in (ValueType.VECTOR, ValueType.DYADIC, ValueType.UNKNOWN):
        raise tr.error(f"MATRIX takes a vector or dyadic, not a {x.type}", args[1], "T001")
    return Typed(f"al.matrix({frames[0]}, {x.code}" + "".join(f", {f}" for f in frames[1:])
                 + ")", ValueType.MATRIX)


@function("DYADIC")
def _dyadic(tr, c):
    args = nargs(tr, c, 2, 3)
    frames = [tr.frame(a).code for a in [args[0]] + args[2:]]
    m = _matrix_arg(tr, args[1], "DYADIC")
    if m.shape not in (None, (3, 3)):
        raise tr.error(f"DYADIC takes a 3x3 matrix, not a {m.shape[0]}x{m.shape[1]} one",
                       args[1], "T001")
    return Typed(f"al.dyadic({frames[0]}, {m.code}" +
                 (f", {frames[1]})" if len(frames) > 1 else ")"), ValueType.DYADIC)


# -- calculus -----------------------------------------------------------------------
@function("DT")
def _dt(tr, c):
    args = nargs(tr, c, 1, 2)
    x = _value(tr, args[0], "DT")
    if x.type in (ValueType.VECTOR, ValueType.DYADIC):
        if len(args) != 2:
            raise tr.error("DT of a vector needs the frame: DT(V>, N)", c, "T007")
        return Typed(f"model.dt({x.code}, {tr.frame(args[1]).code})", x.type)
    if len(args) == 2:
        tr.frame(args[1])       # a scalar's derivative is the same in every frame
    return Typed(f"model.dt({x.code})", x.type)


@function("D")
def _d(tr, c):
    args = nargs(tr, c, 2, 3)
    x = _value(tr, args[0], "D")
    var = _variable(tr, args[1], "D")
    if x.type in (ValueType.VECTOR, ValueType.DYADIC):
        if len(args) != 3:
            raise tr.error("D of a vector needs the frame: D(V>, x, N)", c, "T007")
        return Typed(f"model.d({x.code}, {var.code}, {tr.frame(args[2]).code})", x.type)
    if len(args) == 3:
        raise tr.error("D of a scalar takes no frame", args[2], "T007")
    rtype = ValueType.MATRIX if ValueType.MATRIX in (x.type, var.type) else x.type
    return Typed(f"model.d({x.code}, {var.code})", rtype)


@function("RHS")
def _rhs(tr, c):
    (a,) = nargs(tr, c, 1)
    x = _value(tr, a, "RHS")
    return Typed(f"model.rhs({x.code})", x.type)


@function("EXPLICIT")
def _explicit(tr, c):
    args = nargs(tr, c, 1, 2)
    x = _value(tr, args[0], "EXPLICIT")
    extra = "".join(f", {_names(tr, a, 'EXPLICIT').code}" for a in args[1:])
    return Typed(f"model.explicit({x.code}{extra})", x.type)


@function("ZEE", "AUTOZ")
def _zee(tr, c):
    args = nargs(tr, c, 1, 2)
    name = c.name.upper()
    x = _value(tr, args[0], name)
    keep = f", {_names(tr, args[1], name).code}" if len(args) == 2 else ""
    return Typed(f"model.zee({x.code}{keep})", x.type)


# -- dynamics -------------------------------------------------------------------------
@function("FR")
def _fr(tr, c):
    nargs(tr, c, 0)
    return Typed("model.fr()", ValueType.MATRIX)


@function("FRSTAR")
def _frstar(tr, c):
    nargs(tr, c, 0)
    return Typed("model.frstar()", ValueType.MATRIX)


def _things(tr, args, kinds=(NameKind.BODY, NameKind.PARTICLE)) -> list[str]:
    return [tr.entity(a, kinds).py for a in args]


@function("KE")
def _ke(tr, c):
    return Typed(f"model.ke({', '.join(_things(tr, c.args))})", ValueType.SCALAR)


@function("MASS")
def _mass(tr, c):
    return Typed(f"model.mass_of({', '.join(_things(tr, c.args))})", ValueType.SCALAR)


@function("CM")
def _cm(tr, c):
    if not c.args:
        raise tr.error("CM needs a point: CM(O) or CM(O, B, ...)", c, "T007")
    o = tr.point(c.args[0]).code
    rest = _things(tr, c.args[1:])
    return Typed(f"model.cm({', '.join([o] + rest)})", ValueType.VECTOR)


@function("INERTIA")
def _inertia(tr, c):
    if not c.args:
        raise tr.error("INERTIA() needs a point: INERTIA(O) or INERTIA(O, B, ...)", c, "T007")
    o = tr.point(c.args[0]).code
    rest = _things(tr, c.args[1:])
    return Typed(f"model.inertia_of({', '.join([o] + rest)})", ValueType.DYADIC)


@function("MOMENTUM")
def _momentum(tr, c):
    if not c.args or not isinstance(c.args[0], ir.Name):
        raise tr.error("MOMENTUM(LINEAR) or MOMENTUM(ANGULAR, O)", c, "T009")
    kind = c.args[0].name.upper()
    if kind == "LINEAR":
        rest = _things(tr, c.args[1:])
        return Typed(f"model.momentum('linear'{''.join(', ' + r for r in rest)})", ValueType.VECTOR)
    if kind == "ANGULAR":
        if len(c.args) < 2:
            raise tr.error("MOMENTUM(ANGULAR, O) needs the point O", c, "T007")
        o = tr.point(c.args[1]).code
        rest = _things(tr, c.args[2:])
        return Typed(f"model.momentum('angular', {', '.join([o] + rest)})", ValueType.VECTOR)
    raise tr.error(f"MOMENTUM takes LINEAR or ANGULAR, not {c.args[0].name}", c.args[0], "T003")


@function("GYROSTAT")
def _gyrostat(tr, c):
    if len(c.args) != 5 or not all(isinstance(a, ir.Name) for a in c.args[:2]):
        raise tr.error("GYROSTAT(ANGMOM, CYLINDER, A, B, J)", c, "T009")
    what, shape = c.args[0].name.upper(), c.args[1].name.upper()
    if what != "ANGMOM":
        raise tr.error(f"GYROSTAT({what}, ...) is not supported: only ANGMOM (angular "
                       "momentum) has a known meaning", c.args[0], "T003")
    if shape != "CYLINDER":
        raise tr.error(f"GYROSTAT(ANGMOM, {shape}, ...) is not supported: only a "
                       "CYLINDER rotor", c.args[1], "T003")
    a, b = tr.frame(c.args[2]).code, tr.frame(c.args[3]).code
    j = tr.scalar(c.args[4]).code
    return Typed(f"model.gyrostat_angmom({a}, {b}, {j})", ValueType.VECTOR)


@function("PARTIALS")
def _partials(tr, c):
    if not c.args:
        raise tr.error("PARTIALS(V>, u1, ...)", c, "T007")
    v = tr.expr(c.args[0])
    if v.type not in (ValueType.VECTOR, ValueType.UNKNOWN):
        raise tr.error(f"PARTIALS takes a velocity vector, not a {v.type}", c.args[0], "T001")
    speeds = [_variable(tr, a, "PARTIALS") for a in c.args[1:]]
    codes = [v.code] + [u.code for u in speeds]
    if len(speeds) == 1 and speeds[0].type == ValueType.SCALAR:
        return Typed(f"model.partials({', '.join(codes)})[0]", ValueType.VECTOR)
    return Typed(f"model.partials({', '.join(codes)})", ValueType.VECTORS)


@function("NICHECK")
def _nicheck(tr, c):
    nargs(tr, c, 0)
    return Typed("model.nicheck()", ValueType.SCALAR)


# -- algebra ----------------------------------------------------------------------------
def _substitutions(tr, args) -> str:
    items = []
    for a in args:
        if not isinstance(a, ir.Equation):
            raise tr.error("expected name=value", a, "T009")
        lhs = tr.expr(a.lhs)
        if isinstance(a.rhs, ir.Range):
            raise tr.error("a:b is only allowed in TAYLOR", a.rhs, "T009")
        items.append(f"{lhs.code}: {tr.expr(a.rhs).code}")
    return "{" + ", ".join(items) + "}"


@function("EVALUATE")
def _evaluate(tr, c):
    if not c.args:
        raise tr.error("EVALUATE needs an expression", c, "T007")
    x = _value(tr, c.args[0], "EVALUATE")
    return Typed(f"model.evaluate({x.code}, {_substitutions(tr, c.args[1:])})", x.type)


@function("REPLACE")
def _replace(tr, c):
    if not c.args:
        raise tr.error("REPLACE needs an expression", c, "T007")
    x = _value(tr, c.args[0], "REPLACE")
    return Typed(f"al.replace({x.code}, {_substitutions(tr, c.args[1:])})", x.type)


def _degree_range(tr, a, what: str) -> str:
    if isinstance(a, ir.Range):
        return f"{_number(tr, a.lo, what).code}, {_number(tr, a.hi, what).code}"
    return _number(tr, a, what).code


@function("EXPAND")
def _expand(tr, c):
    args = nargs(tr, c, 1, 2)
    x = _value(tr, args[0], "EXPAND")
    degree = "EXPAND's degree"
    extra = f", {_degree_range(tr, args[1], degree)}" if len(args) == 2 else ""
    return Typed(f"model.expand({x.code}{extra})", x.type)


@function("FACTOR")
def _factor(tr, c):
    args = nargs(tr, c, 1, 2)
    x = _value(tr, args[0], "FACTOR")
    extra = "".join(f", {_names(tr, a, 'FACTOR').code}" for a in args[1:])
    return Typed(f"al.factor({x.code}{extra})", x.type)


@function("SIMPLIFY")
def _simplify(tr, c):
    (a,) = nargs(tr, c, 1)
    x = _value(tr, a, "SIMPLIFY")
    return Typed(f"al.simplify({x.code})", x.type)


@function("COEF")
def _coef(tr, c):
    """COEF(E, x) of every measure number or element of E; COEF(E, [x, y]) of a scalar or
    column, a matrix; COEF(V>, N1>), V>'s measure number on N1> (docs/language.md)."""
    a, b = nargs(tr, c, 2)
    x = _value(tr, a, "COEF")
    if isinstance(b, ir.VectorName) and not b.dyadic:
        if not _is_unit_vector(tr, b):
            raise tr.error(f"COEF(V>, {b.text}): the coefficient is taken of a unit vector "
                           "of a frame (N1>, N2>, N3>)", b, "T001")
        if x.type not in (ValueType.VECTOR, ValueType.UNKNOWN):
            raise tr.error(f"COEF(E, {b.text}) takes a vector E, not {_what(tr, a, x)}", a,
                           "T001")
        return Typed(f"model.coef({x.code}, {tr.expr(b).code})", ValueType.SCALAR)
    v = _names(tr, b, "COEF")
    if v.type == ValueType.MATRIX and x.type in (ValueType.VECTOR, ValueType.DYADIC):
        raise tr.error(f"COEF(E, [x, y]) takes a scalar or a column E, not a {x.type}", a,
                       "T001")
    rtype = ValueType.MATRIX if ValueType.MATRIX in (x.type, v.type) else x.type
    return Typed(f"model.coef({x.code}, {v.code})", rtype)


@function("EXCLUDE", "INCLUDE")
def _exclude(tr, c):
    a, b = nargs(tr, c, 2)
    x, v = _value(tr, a, c.name.upper()), _names(tr, b, c.name.upper())
    fn = c.name.lower()
    return Typed(f"model.{fn}({x.code}, {v.code})", x.type)


@function("ARRANGE")
def _arrange(tr, c):
    a, n, v = nargs(tr, c, 3)
    x = _value(tr, a, "ARRANGE")
    degree = _number(tr, n, "ARRANGE's degree")
    return Typed(f"al.arrange({x.code}, {degree.code}, {_names(tr, v, 'ARRANGE').code})",
                 x.type)


@function("TAYLOR")
def _taylor(tr, c):
    if len(c.args) < 3:
        raise tr.error("TAYLOR(E, n, x=a, ...) or TAYLOR(E, n:m, x=a, ...)", c, "T007")
    x = _value(tr, c.args[0], "TAYLOR")
    degrees = [_number(tr, d, "TAYLOR's order")
               for d in ((c.args[1].lo, c.args[1].hi)
                         if isinstance(c.args[1], ir.Range) else (c.args[1],))]
    if any(d.exact is not None and d.exact > MAX_TAYLOR_ORDER for d in degrees):
        raise tr.error(f"TAYLOR to order {max(d.exact for d in degrees if d.exact)}: at most "
                       f"order {MAX_TAYLOR_ORDER} is expanded", c.args[1], "T005")
    order = _degree_range(tr, c.args[1], "TAYLOR's order")
    points = []
    for a in c.args[2:]:
        if isinstance(a, ir.Name):      # a bare name: expand about 0
            points.append(f"({tr.expr(a).code}, 0, None)")
            continue
        if not isinstance(a, ir.Equation):
            raise tr.error("expected x=a or x=a:dx", a, "T009")
        var = tr.expr(a.lhs).code
        if isinstance(a.rhs, ir.Range):
            points.append(f"({var}, {tr.expr(a.rhs.lo).code}, {tr.expr(a.rhs.hi).code})")
        else:
            points.append(f"({var}, {tr.expr(a.rhs).code}, None)")
    order_code = f"({order})" if "," in order else order
    return Typed(f"model.taylor({x.code}, {order_code}, [{', '.join(points)}])", x.type)


@function("POLYNOMIAL")
def _polynomial(tr, c):
    args = nargs(tr, c, 2, 3)
    if len(args) == 2:          # the polynomial of a list of coefficients
        coefficients = _matrix_arg(tr, args[0], "POLYNOMIAL([a, b, ...], x)")
        return Typed(f"al.polynomial({coefficients.code}, {tr.scalar(args[1]).code})",
                     ValueType.SCALAR)
    # the row of E's coefficients in x
    e, x = tr.scalar(args[0]), tr.scalar(args[1])
    n = _number(tr, args[2], "POLYNOMIAL's degree")
    return Typed(f"al.polynomial({e.code}, {x.code}, {n.code})", ValueType.MATRIX)


@function("ROOTS")
def _roots(tr, c):
    args = nargs(tr, c, 1, 3)
    if len(args) == 1:          # the polynomial's coefficients, highest power first
        items = [_matrix_arg(tr, args[0], "ROOTS([a, b, ...])")]
        symbol = _declared_in(tr, items[0].elements)
        if symbol is not None and len(items[0].elements) > 3:
            raise tr.error(f"ROOTS of a polynomial of degree {len(items[0].elements) - 1} "
                           f"takes numbers; this one holds {symbol.name} (the closed forms are "
                           "computed up to degree 2)", args[0], "T001")
    else:
        items = [tr.scalar(args[0]), tr.scalar(args[1]), _number(tr, args[2], "ROOTS' degree")]
    return Typed(f"al.roots({', '.join(i.code for i in items)})", ValueType.MATRIX)


@function("EPSILON")
def _epsilon(tr, c):
    a, b = nargs(tr, c, 2)
    x = _value(tr, a, "EPSILON")
    tolerance = _number(tr, b, "EPSILON's tolerance")
    return Typed(f"al.epsilon({x.code}, {tolerance.code})", x.type)


# -- matrices ------------------------------------------------------------------------
def _matrix_arg(tr, a, what):
    x = tr.expr(a)
    if x.type not in (ValueType.MATRIX, ValueType.UNKNOWN):
        raise tr.error(f"{what} takes a matrix, not {_what(tr, a, x)}", a, "T001")
    return x


def _square_arg(tr, a, what):
    """A matrix argument that must be square (when its shape is known here)."""
    x = _matrix_arg(tr, a, what)
    if x.shape is not None and x.shape[0] != x.shape[1]:
        raise tr.error(f"{what} takes a square matrix, not a {x.shape[0]}x{x.shape[1]} one",
                       a, "T001")
    return x


@function("TRANSPOSE")
def _transpose(tr, c):
    (a,) = nargs(tr, c, 1)
    return Typed(f"al.transpose({_matrix_arg(tr, a, 'TRANSPOSE').code})", ValueType.MATRIX)


@function("INV", "INVERSE")
def _inv(tr, c):
    (a,) = nargs(tr, c, 1)
    return Typed(f"model.inv({_square_arg(tr, a, c.name.upper()).code})", ValueType.MATRIX)


@function("DET")
def _det(tr, c):
    (a,) = nargs(tr, c, 1)
    return Typed(f"model.det({_square_arg(tr, a, 'DET').code})", ValueType.SCALAR)


@function("TRACE")
def _trace(tr, c):
    (a,) = nargs(tr, c, 1)
    return Typed(f"al.trace({_square_arg(tr, a, 'TRACE').code})", ValueType.SCALAR)


@function("DIAGMAT")
def _diagmat(tr, c):
    args = nargs(tr, c, 2, 3)
    sizes = [_number(tr, a, "DIAGMAT's size").code for a in args[:-1]]
    return Typed(f"al.diagmat({', '.join(sizes + [tr.scalar(args[-1]).code])})",
                 ValueType.MATRIX)


def _index(tr, a, count: int | None) -> Typed:
    """A 1-based index, within 1..count when both are known here."""
    x = _number(tr, a, "an index")
    if count is not None and x.exact is not None and not 1 <= x.exact <= count:
        raise tr.error(f"index {x.exact} is outside 1..{count}", a, "T001")
    return x


def _selection(tr, args, count: int | None) -> list[str]:
    out = []
    for a in args:
        if isinstance(a, ir.Range):
            out.append(f"({_index(tr, a.lo, count).code}, {_index(tr, a.hi, count).code})")
        else:
            out.append(_index(tr, a, count).code)
    return out


@function("ROWS", "COLS")
def _rows(tr, c):
    if not c.args:
        raise tr.error(f"{c.name.upper()} needs a matrix", c, "T007")
    m = _matrix_arg(tr, c.args[0], c.name.upper())
    fn = "rows" if c.name.upper() == "ROWS" else "cols"
    if len(c.args) == 1:
        return Typed(f"al.{fn}({m.code})", ValueType.SCALAR)
    axis = 0 if fn == "rows" else 1
    sel = _selection(tr, c.args[1:], m.shape[axis] if m.shape else None)
    return Typed(f"al.{fn}({m.code}, {', '.join(sel)})", ValueType.MATRIX)


@function("ELEMENT")
def _element(tr, c):
    args = nargs(tr, c, 2, 3)
    m = _matrix_arg(tr, args[0], "ELEMENT")
    counts = (m.shape if len(args) == 3 else (m.shape[0] * m.shape[1],)) if m.shape \
        else (None, None)
    for a, count in zip(args[1:], counts):
        _index(tr, a, count)
    idx = [tr.index_code(a) for a in args[1:]]
    return Typed(f"{m.wrapped(ATOM)}[{', '.join(idx)}]", ValueType.SCALAR)


@function("EIG")
def _eig(tr, c):
    (a,) = nargs(tr, c, 1)
    m = _square_arg(tr, a, "EIG")
    symbol = _declared_in(tr, m.elements)
    if symbol is not None:
        raise tr.error(f"EIG takes a matrix of numbers; this one holds {symbol.name}, a "
                       f"{tr.scalars[symbol.name.lower()].kind} (EVALUATE it first)", a, "T001")
    return Typed(f"al.eig(model.explicit({m.code}))", ValueType.MATRIX)


# -- units and inputs ------------------------------------------------------------------
@function("UNITS")
def _units(tr, c):
    a, b = nargs(tr, c, 2)
    ua, ub = _unit_text(tr, a), _unit_text(tr, b)
    from ..runtime.functions import units_factor
    from ..runtime.errors import AutolevModelError
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
                       f"{_what_not_a_name(tr, a, x)}", a, "T008")
    return Typed(f"model.input_value({tr.symbol(a)})", ValueType.SCALAR)  # SI (radians)
