"""Expressions: numbers, names, operators, indices and matrices, written with their type.

Each handler is registered in `core.EXPRESSIONS` for its IR class and called through
`Translator.expr`; calls of functions are in `functions.py`, vector names in `special.py`.
"""
from __future__ import annotations

import math
import operator
from fractions import Fraction

from .. import ir
from ..errors import MAX_EXACT_DIGITS
from .core import EXPRESSIONS, Translator
from .kinds import ADD, ATOM, MUL, POW, UNARY, Typed, ValueType

# Python cannot compile a longer chain A + B + ... (its nesting limit is about 3000)
MAX_CHAIN_TERMS = 2000


@EXPRESSIONS.register(ir.Number)
def number(tr: Translator, e: ir.Number, want: str) -> Typed:
    if e.is_integer:
        value = int(e.text)
        return Typed(str(value), ValueType.SCALAR, ATOM, Fraction(value))    # 007 is 7
    return Typed(e.text, ValueType.SCALAR, ATOM, approx=float(e.text))


@EXPRESSIONS.register(ir.Neg)
def negation(tr: Translator, e: ir.Neg, want: str) -> Typed:
    x = tr.expr(e.operand)
    exact = -x.exact if x.exact is not None else None
    if exact is not None:
        return _exact_typed(exact)
    approx = -x.approx if x.approx is not None else None
    return Typed("-" + x.wrapped(MUL), x.type, UNARY, approx=approx)


@EXPRESSIONS.register(ir.BinOp)
def binary_operation(tr: Translator, e: ir.BinOp, want: str) -> Typed:
    # a left-associated chain (A + B - C + ..., A*B/C) is folded in a loop: responses
    # pasted into models sum hundreds of terms, deeper than Python's recursion
    group = "+-" if e.op in "+-" else "*/" if e.op in "*/" else None
    chain = []
    node: ir.Expr = e
    while group and isinstance(node, ir.BinOp) and node.op in group:
        chain.append(node)
        node = node.left
    if not chain:
        chain, node = [e], e.left
    if len(chain) >= MAX_CHAIN_TERMS:
        what = "sum" if group == "+-" else "product"
        raise tr.error(f"a {what} of {len(chain) + 1} terms; at most {MAX_CHAIN_TERMS} "
                       f"terms in one sum or product are translated (split it into "
                       "several names)", e, "T004")
    result = tr.expr(node)
    for level in reversed(chain):
        result = _binary(tr, level, result, tr.expr(level.right))
        result.node = level
    return result


def _binary(tr: Translator, e: ir.BinOp, a: Typed, b: Typed) -> Typed:
    op = e.op
    if a.exact is not None and b.exact is not None:
        v = _fold(op, a.exact, b.exact)
        if v is not None:
            digits = max(v.numerator.bit_length(), v.denominator.bit_length()) * 0.30103
            if digits > MAX_EXACT_DIGITS:
                raise tr.error(f"this exact number has about {digits:.0f} digits; "
                               f"exact numbers of more than {MAX_EXACT_DIGITS} digits "
                               "are refused (write a decimal number, 1E300, for a "
                               "floating-point one)", e, "T005")
            return _exact_typed(v)
    result = _typed_binary(tr, e, a, b)
    result.approx = _double_of(op, a, b)
    return result


def _double_of(op: str, a: Typed, b: Typed) -> float | None:
    """The double value of a binary operation on numbers (not both exact), as Autolev
    computed it: inf where it overflows, None where it has none."""
    x, y = a.double, b.double
    if x is None or y is None:
        return None
    try:
        return _ARITHMETIC.get(op, math.pow)(x, y)
    except OverflowError:
        return math.inf
    except (ZeroDivisionError, ValueError):
        return None


def _typed_binary(tr: Translator, e: ir.BinOp, a: Typed, b: Typed) -> Typed:
    op = e.op
    ta, tb = a.type, b.type
    if op in "+-":
        if ValueType.UNKNOWN not in (ta, tb) and ta != tb:
            # matrices add to matrices only, even a 1x1 one to a scalar (docs/language.md)
            hint = ("; a 1x1 matrix is not a scalar (its element is M[1,1])"
                    if {ta, tb} == {ValueType.SCALAR, ValueType.MATRIX} else "")
            raise tr.error(f"cannot {'add' if op == '+' else 'subtract'} a {tb} "
                           f"{'to' if op == '+' else 'from'} a {ta}{hint}", e, "T001")
        left = a.wrapped(ADD)
        right = b.wrapped(ADD + 1) if op == "-" else b.wrapped(ADD)
        return Typed(f"{left} {op} {right}", ta if ta != ValueType.UNKNOWN else tb, ADD)
    if op == "*":
        if ta in (ValueType.VECTOR,) and tb in (ValueType.VECTOR,):
            return Typed(f"al.outer({a.code}, {b.code})", ValueType.DYADIC, ATOM)
        rtype = _product_type(ta, tb)
        if rtype is None:
            raise tr.error(f"cannot multiply a {ta} by a {tb}", e, "T001")
        return Typed(f"{a.wrapped(MUL)}*{b.wrapped(MUL)}", rtype, MUL)
    if op == "/":
        if tb not in (ValueType.SCALAR, ValueType.UNKNOWN):
            raise tr.error(f"cannot divide by a {tb}", e, "T001")
        return Typed(f"{a.wrapped(MUL)}/{b.wrapped(MUL + 1)}", ta, MUL)
    # power
    if ta not in (ValueType.SCALAR, ValueType.MATRIX, ValueType.UNKNOWN) or \
            tb not in (ValueType.SCALAR, ValueType.UNKNOWN):
        raise tr.error(f"cannot raise a {ta} to a power", e, "T001")
    if a.exact is not None and b.exact is not None and abs(a.exact) > 1 and \
            b.exact > 0 and _power_digits_log10(a.exact, b.exact) > \
            math.log10(MAX_EXACT_DIGITS):
        # sympy would compute the exact number (10^10^10 has 10^10 digits)
        log_digits = _power_digits_log10(a.exact, b.exact)
        # beyond a float's range (2^(10^400)), the digit count as a power of ten
        digits = f"{10 ** log_digits:.3g}" if log_digits < 300 else f"10^{log_digits:.0f}"
        raise tr.error(f"this power has about {digits} digits; exact numbers of "
                       f"more than {MAX_EXACT_DIGITS} digits are refused (write a "
                       "decimal number, 1E300, for a floating-point one)", e, "T005")
    return Typed(f"{a.wrapped(POW + 1)}**{b.wrapped(UNARY)}", ta, POW)


@EXPRESSIONS.register(ir.Name)
def name(tr: Translator, e: ir.Name, want: str) -> Typed:
    return tr.name(e.name, e.primes, e, want)


@EXPRESSIONS.register(ir.Index)
def index(tr: Translator, e: ir.Index, want: str) -> Typed:
    key = e.name.lower()
    if e.primes:
        raise tr.error("a prime on an indexed name is not supported", e, "T006")
    if key in tr.values or key in tr.scalars:
        base = tr.name(e.name, 0, e)
    else:
        base = tr.dcm_name(e.name)
        if base is None:
            raise tr.error(f"'{e.name}' is not defined", e, "T002")
    idx = [tr.index_code(i) for i in e.indices]
    if len(idx) == 1:
        return Typed(f"{base.code}[{idx[0]}]", ValueType.SCALAR, ATOM)
    if len(idx) == 2:
        return Typed(f"{base.code}[{idx[0]}, {idx[1]}]", ValueType.SCALAR, ATOM)
    raise tr.error("an index has one or two parts", e, "T007")


@EXPRESSIONS.register(ir.Matrix)
def matrix(tr: Translator, e: ir.Matrix, want: str) -> Typed:
    if not e.rows:
        return Typed("sm.Matrix()", ValueType.MATRIX)
    rows = []
    block = False
    typed = [[tr.expr(el) for el in row] for row in e.rows]
    kinds = {x.type for row in typed for x in row}
    if kinds & {ValueType.VECTOR, ValueType.DYADIC}:
        flat = [x for row in typed for x in row]
        if kinds - {ValueType.VECTOR, ValueType.DYADIC, ValueType.UNKNOWN} or \
                not (len(typed) == 1 or all(len(r) == 1 for r in typed)):
            raise tr.error("a matrix of vectors must be one row or one column of "
                           "vectors", e, "T001")
        return Typed("al.VectorColumn([" + ", ".join(x.code for x in flat) + "])",
                     ValueType.VECTORS)
    for row, trow in zip(e.rows, typed):
        items = []
        for el, x in zip(row, trow):
            if x.type == ValueType.MATRIX:
                block = True
            elif x.type not in (ValueType.SCALAR, ValueType.UNKNOWN):
                raise tr.error(f"a matrix holds scalars, not a {x.type}", el, "T001")
            items.append(x.code)
        rows.append(items)
    if block:
        inner = ", ".join("[" + ", ".join(r) + "]" for r in rows)
        return Typed(f"al.block_matrix([{inner}])", ValueType.MATRIX)
    if all(len(r) == 1 for r in rows):
        return Typed("sm.Matrix([" + ", ".join(r[0] for r in rows) + "])", ValueType.MATRIX,
                     shape=(len(rows), 1), elements=tuple(r[0] for r in e.rows))
    inner = ", ".join("[" + ", ".join(r) + "]" for r in rows)
    if len({len(r) for r in rows}) != 1:
        return Typed(f"sm.Matrix([{inner}])", ValueType.MATRIX)
    return Typed(f"sm.Matrix([{inner}])", ValueType.MATRIX, shape=(len(rows), len(rows[0])),
                 elements=tuple(x for r in e.rows for x in r))


@EXPRESSIONS.register(ir.NameRange)
def name_range(tr: Translator, e: ir.NameRange, want: str) -> Typed:
    items = [tr.expr(n) for n in e.names]
    return Typed("[" + ", ".join(i.code for i in items) + "]", ValueType.LIST)


@EXPRESSIONS.register(ir.Range)
def range_(tr: Translator, e: ir.Range, want: str) -> Typed:
    raise tr.error("a range n:m is only allowed in some function arguments", e, "T009")


@EXPRESSIONS.register(ir.Equation)
def equation(tr: Translator, e: ir.Equation, want: str) -> Typed:
    raise tr.error("'=' is only allowed in some function arguments", e, "T009")


# + - * / of two numbers, exact or double (a division by zero raises ZeroDivisionError)
_ARITHMETIC = {"+": operator.add, "-": operator.sub, "*": operator.mul, "/": operator.truediv}


def _fold(op: str, a: Fraction, b: Fraction) -> Fraction | None:
    if op in _ARITHMETIC:
        return _ARITHMETIC[op](a, b) if op != "/" or b != 0 else None
    if op == "^" and b.denominator == 1 and not (a == 0 and b < 0) and \
            (abs(b) <= 64 or _power_digits_log10(a, b) <= math.log10(MAX_EXACT_DIGITS)):
        return a ** int(b)
    return None


def _log10(v: Fraction) -> float:
    """log10 |v| of an exact number however large (float(v) would overflow)."""
    return math.log10(abs(v.numerator)) - math.log10(v.denominator)


def _power_digits_log10(a: Fraction, b: Fraction) -> float:
    """log10 of the number of digits of a^b (-inf for 0, 1 and -1, or b = 0)."""
    if a in (0, 1, -1) or b == 0:
        return -math.inf
    return _log10(b) + math.log10(abs(_log10(a)))


def _exact_typed(v: Fraction) -> Typed:
    if v.denominator == 1:
        text = str(v.numerator)
        return Typed(text, ValueType.SCALAR, ATOM if v >= 0 else UNARY, v)
    return Typed(f"sm.Rational({v.numerator}, {v.denominator})", ValueType.SCALAR, ATOM, v)


def _product_type(a: ValueType, b: ValueType) -> ValueType | None:
    if a == ValueType.UNKNOWN or b == ValueType.UNKNOWN:
        return a if b == ValueType.UNKNOWN and a != ValueType.UNKNOWN else \
            b if a == ValueType.UNKNOWN else ValueType.UNKNOWN
    if a == ValueType.SCALAR:
        return b
    if b == ValueType.SCALAR:
        return a
    if a == b == ValueType.MATRIX:
        return ValueType.MATRIX
    return None
