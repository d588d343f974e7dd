"""Algebra and calculus through the model's definitions: DT, D, RHS, EXPLICIT, ZEE,
EVALUATE, REPLACE, EXPAND, FACTOR, SIMPLIFY, COEF, EXCLUDE, INCLUDE, ARRANGE, TAYLOR,
POLYNOMIAL, ROOTS, EPSILON."""
from __future__ import annotations

from ... import ir
from ..kinds import Typed, ValueType
from .arguments import (declared_in, describe, is_unit_vector, matrix_arg, names_arg,
                        number_arg, value_arg, variable_arg)
from .table import function, nargs

# beyond this, exact computation takes minutes or gigabytes for what a model never needs
MAX_TAYLOR_ORDER = 30


# -- calculus -----------------------------------------------------------------------
@function("DT")
def _dt(tr, c):
    args = nargs(tr, c, 1, 2)
    x = value_arg(tr, args[0], "DT")
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
    x = value_arg(tr, args[0], "D")
    var = variable_arg(tr, args[1], "D")
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
    x = value_arg(tr, a, "RHS")
    return Typed(f"model.rhs({x.code})", x.type)


@function("EXPLICIT")
def _explicit(tr, c):
    args = nargs(tr, c, 1, 2)
    x = value_arg(tr, args[0], "EXPLICIT")
    extra = "".join(f", {names_arg(tr, a, 'EXPLICIT').code}" for a in args[1:])
    return Typed(f"model.explicit({x.code}{extra})", x.type)


@function("ZEE", "AUTOZ")
def _zee(tr, c):
    args = nargs(tr, c, 1, 2)
    name = c.name.upper()
    x = value_arg(tr, args[0], name)
    keep = f", {names_arg(tr, args[1], name).code}" if len(args) == 2 else ""
    return Typed(f"model.zee({x.code}{keep})", x.type)


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
    x = value_arg(tr, c.args[0], "EVALUATE")
    return Typed(f"model.evaluate({x.code}, {_substitutions(tr, c.args[1:])})", x.type)


@function("REPLACE")
def _replace(tr, c):
    if not c.args:
        raise tr.error("REPLACE needs an expression", c, "T007")
    x = value_arg(tr, c.args[0], "REPLACE")
    return Typed(f"al.replace({x.code}, {_substitutions(tr, c.args[1:])})", x.type)


def _degree_range(tr, a, what: str) -> str:
    if isinstance(a, ir.Range):
        return f"{number_arg(tr, a.lo, what).code}, {number_arg(tr, a.hi, what).code}"
    return number_arg(tr, a, what).code


@function("EXPAND")
def _expand(tr, c):
    args = nargs(tr, c, 1, 2)
    x = value_arg(tr, args[0], "EXPAND")
    degree = "EXPAND's degree"
    extra = f", {_degree_range(tr, args[1], degree)}" if len(args) == 2 else ""
    return Typed(f"model.expand({x.code}{extra})", x.type)


@function("FACTOR")
def _factor(tr, c):
    args = nargs(tr, c, 1, 2)
    x = value_arg(tr, args[0], "FACTOR")
    extra = "".join(f", {names_arg(tr, a, 'FACTOR').code}" for a in args[1:])
    return Typed(f"al.factor({x.code}{extra})", x.type)


@function("SIMPLIFY")
def _simplify(tr, c):
    (a,) = nargs(tr, c, 1)
    x = value_arg(tr, a, "SIMPLIFY")
    return Typed(f"al.simplify({x.code})", x.type)


@function("COEF")
def _coef(tr, c):
    """COEF(E, x) of every measure number or element of E; COEF(E, [x, y]) of a scalar or
    column, a matrix; COEF(V>, N1>), V>'s measure number on N1> (docs/language.md)."""
    a, b = nargs(tr, c, 2)
    x = value_arg(tr, a, "COEF")
    if isinstance(b, ir.VectorName) and not b.dyadic:
        if not is_unit_vector(tr, b):
            raise tr.error(f"COEF(V>, {b.text}): the coefficient is taken of a unit vector "
                           "of a frame (N1>, N2>, N3>)", b, "T001")
        if x.type not in (ValueType.VECTOR, ValueType.UNKNOWN):
            raise tr.error(f"COEF(E, {b.text}) takes a vector E, not {describe(tr, a, x)}", a,
                           "T001")
        return Typed(f"model.coef({x.code}, {tr.expr(b).code})", ValueType.SCALAR)
    v = names_arg(tr, b, "COEF")
    if v.type == ValueType.MATRIX and x.type in (ValueType.VECTOR, ValueType.DYADIC):
        raise tr.error(f"COEF(E, [x, y]) takes a scalar or a column E, not a {x.type}", a,
                       "T001")
    rtype = ValueType.MATRIX if ValueType.MATRIX in (x.type, v.type) else x.type
    return Typed(f"model.coef({x.code}, {v.code})", rtype)


@function("EXCLUDE", "INCLUDE")
def _exclude(tr, c):
    a, b = nargs(tr, c, 2)
    x, v = value_arg(tr, a, c.name.upper()), names_arg(tr, b, c.name.upper())
    fn = c.name.lower()
    return Typed(f"model.{fn}({x.code}, {v.code})", x.type)


@function("ARRANGE")
def _arrange(tr, c):
    a, n, v = nargs(tr, c, 3)
    x = value_arg(tr, a, "ARRANGE")
    degree = number_arg(tr, n, "ARRANGE's degree")
    return Typed(f"al.arrange({x.code}, {degree.code}, {names_arg(tr, v, 'ARRANGE').code})",
                 x.type)


@function("TAYLOR")
def _taylor(tr, c):
    if len(c.args) < 3:
        raise tr.error("TAYLOR(E, n, x=a, ...) or TAYLOR(E, n:m, x=a, ...)", c, "T007")
    x = value_arg(tr, c.args[0], "TAYLOR")
    degrees = [number_arg(tr, d, "TAYLOR's order")
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
        coefficients = matrix_arg(tr, args[0], "POLYNOMIAL([a, b, ...], x)")
        return Typed(f"al.polynomial({coefficients.code}, {tr.scalar(args[1]).code})",
                     ValueType.SCALAR)
    # the row of E's coefficients in x
    e, x = tr.scalar(args[0]), tr.scalar(args[1])
    n = number_arg(tr, args[2], "POLYNOMIAL's degree")
    return Typed(f"al.polynomial({e.code}, {x.code}, {n.code})", ValueType.MATRIX)


@function("ROOTS")
def _roots(tr, c):
    args = nargs(tr, c, 1, 3)
    if len(args) == 1:          # the polynomial's coefficients, highest power first
        items = [matrix_arg(tr, args[0], "ROOTS([a, b, ...])")]
        symbol = declared_in(tr, items[0].elements)
        if symbol is not None and len(items[0].elements) > 3:
            raise tr.error(f"ROOTS of a polynomial of degree {len(items[0].elements) - 1} "
                           f"takes numbers; this one holds {symbol.name} (the closed forms are "
                           "computed up to degree 2)", args[0], "T001")
    else:
        items = [tr.scalar(args[0]), tr.scalar(args[1]), number_arg(tr, args[2], "ROOTS' degree")]
    return Typed(f"al.roots({', '.join(i.code for i in items)})", ValueType.MATRIX)


@function("EPSILON")
def _epsilon(tr, c):
    a, b = nargs(tr, c, 2)
    x = value_arg(tr, a, "EPSILON")
    tolerance = number_arg(tr, b, "EPSILON's tolerance")
    return Typed(f"al.epsilon({x.code}, {tolerance.code})", x.type)
