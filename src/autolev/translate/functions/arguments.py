"""The kinds of arguments Autolev's functions take: an expression, a name or a list of
names, a variable to differentiate with respect to, a number, a matrix; each refused
with a message saying what the argument is instead."""
from __future__ import annotations

from ... import ir
from ..core import Translator
from ..kinds import NameKind, Typed, ValueType
from ..special import classify

# what no function takes where it wants an expression
_NOT_VALUES = (ValueType.FRAME, ValueType.POINT, ValueType.LIST, ValueType.STRING)
_NAME_OF_KIND = {NameKind.NEWTONIAN: "the Newtonian frame", NameKind.FRAME: "a frame",
                 NameKind.BODY: "a body", NameKind.POINT: "a point",
                 NameKind.PARTICLE: "a particle"}


def describe(tr: Translator, node, x: Typed) -> str:
    """What an argument is, for a message: a body, a vector, a number, ..."""
    if x.type in (ValueType.FRAME, ValueType.POINT) and isinstance(node, ir.Name):
        ent = tr.entities.get(node.name.lower())
        if ent is not None:
            return _NAME_OF_KIND.get(ent.kind, f"a {x.type}")
    if is_number(x):
        return "a number"
    return f"a {x.type}"


def describe_not_a_name(tr: Translator, node, x: Typed) -> str:
    """What an argument that should be a name is: a number, an expression, a vector, ..."""
    if x.type == ValueType.SCALAR and not is_number(x):
        return "an expression"
    return describe(tr, node, x)


def is_number(x: Typed) -> bool:
    return x.exact is not None or x.approx is not None


def value_arg(tr: Translator, a, what: str) -> Typed:
    """An argument that is an expression: a scalar, vector, dyadic or matrix."""
    x = tr.expr(a)
    if x.type in _NOT_VALUES:
        raise tr.error(f"{what} takes an expression, not {describe(tr, a, x)}", a, "T001")
    return x


def names_arg(tr: Translator, a, what: str) -> Typed:
    """The quantities a function works on: a name (or a product of names, x*y), or a
    list of them ([x, y])."""
    x = tr.expr(a)
    if x.type not in (ValueType.SCALAR, ValueType.MATRIX, ValueType.UNKNOWN) or is_number(x):
        raise tr.error(f"{what} takes a name or a list of names ([x, y]) here, not "
                       f"{describe(tr, a, x)}", a, "T001")
    for el in x.elements or ():
        if not any(isinstance(n, ir.Name) for n in ir.walk(el)):
            raise tr.error(f"{what} takes a list of names ([x, y]) here; this one holds a "
                           "number", a, "T001")
    return x


def variable_arg(tr: Translator, a, what: str) -> Typed:
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
                   f"not {describe_not_a_name(tr, a, x)}", a, "T009")


def number_arg(tr: Translator, a, what: str) -> Typed:
    """A count, degree, index or tolerance: a scalar holding no declared quantity (a
    variable or constant is a symbol, never a number)."""
    x = tr.expr(a)
    if x.type not in (ValueType.SCALAR, ValueType.UNKNOWN):
        raise tr.error(f"{what} must be a number, not {describe(tr, a, x)}", a, "T001")
    for node in ir.walk(a):
        entry = tr.scalars.get(node.name.lower()) if isinstance(node, ir.Name) else None
        if entry is not None:
            raise tr.error(f"{what} must be a number, not {node.name}{chr(39) * node.primes} "
                           f"(a {entry.kind})", node, "T009")
    return x


def declared_in(tr: Translator, elements) -> ir.Name | None:
    """The first declared quantity (a symbol, never a number) in a literal's elements."""
    for el in elements or ():
        for node in ir.walk(el):
            if isinstance(node, ir.Name) and node.name.lower() in tr.scalars:
                return node
    return None


def is_unit_vector(tr: Translator, a) -> bool:
    """N1>, N2>, N3> of a declared frame or body."""
    if not isinstance(a, ir.VectorName) or a.dyadic:
        return False
    sp = classify(tr, a)
    return sp is not None and sp.kind == "unit"


def matrix_arg(tr, a, what):
    x = tr.expr(a)
    if x.type not in (ValueType.MATRIX, ValueType.UNKNOWN):
        raise tr.error(f"{what} takes a matrix, not {describe(tr, a, x)}", a, "T001")
    return x
