"""Assignments: `X = ...`, `X += ...`, `M[i, j] = ...`, `V> = ...` and A_B = (a DCM)."""
from __future__ import annotations

from .. import ir
from .core import FRAME_KINDS, STATEMENTS, Entry, NameKind, Translator, Typed, ValueType
from .special import assign_vector

# -- assignments ---------------------------------------------------------------------------
_COMPOUND = {"+=": "+", "-=": "-", "*=": "*", "/=": "/", "^=": "**"}


@STATEMENTS.register(ir.Assignment)
def assignment(tr: Translator, st: ir.Assignment) -> None:
    assign(tr, st.target, st.op, st.value)


def assign(tr: Translator, target: ir.Expr, op: str, value_expr: ir.Expr) -> None:
    if isinstance(target, ir.Name) and op in ("=", ":="):
        tr.redefining = (target.name.lower(), target.primes)
    try:
        value = tr.expr(value_expr)
    finally:
        tr.redefining = None
    if value.type in (ValueType.FRAME, ValueType.POINT, ValueType.LIST):
        raise tr.error(f"a {value.type} cannot be assigned", value_expr, "T001")
    if isinstance(target, ir.VectorName):
        assign_vector(tr, target, op, value)
        return
    if isinstance(target, ir.Index):
        _assign_element(tr, target, op, value)
        return
    name, primes = target.name, target.primes
    key = name.lower()
    if key == "zee_not" and not primes:
        tr.emit(f"model.zee_not({value.code})")
        return
    if key in tr.scalars:
        sym = tr.symbol(target)
        if op in ("=", ":="):
            rhs = value.code
        else:
            rhs = f"model.rhs({sym}) {_COMPOUND[op]} {value.wrapped(6)}"
        if value.type == ValueType.MATRIX:
            raise tr.error(f"{name} is a scalar; the right side is a matrix", value_expr, "T001")
        tr.emit(f"model.define({sym}, {rhs})")
        tr.defined.add((key, primes))
        return
    if primes:
        raise tr.error(f"{name}{chr(39) * primes} needs {name} declared (VARIABLES "
                       f"{name}{chr(39) * primes})", target, "T002")
    if key not in tr.values:
        parts = tr.split_entities(name, FRAME_KINDS, 2)
        if parts is not None:
            if op not in ("=", ":="):
                raise tr.error(f"{op} is not defined for a direction cosine matrix", target, "T010")
            a, b = parts
            tr.emit(f"{b.py}.orient_dcm({a.py}, {value.code})")
            return
    entry = tr.values.get(key)
    if entry is None:
        if op not in ("=", ":="):
            raise tr.error(f"{name} has no value yet", target, "T002")
        entry = Entry(tr.py_name("value", name), NameKind.VALUE, value.type)
        tr.values[key] = entry
        tr.emit(f"{entry.py} = {value.code}")
        return
    if op in ("=", ":="):
        entry.type = value.type
        tr.emit(f"{entry.py} = {value.code}")
    else:
        tr.emit(f"{entry.py} = {entry.py} {_COMPOUND[op]} {value.wrapped(6)}")


def _assign_element(tr: Translator, target: ir.Index, op: str, value: Typed) -> None:
    key = target.name.lower()
    if target.primes:
        raise tr.error("a primed name cannot be indexed", target, "T010")
    if value.type not in (ValueType.SCALAR, ValueType.UNKNOWN):
        raise tr.error(f"a matrix element is a scalar, not a {value.type}", target, "T001")
    idx = ", ".join(_one_based(tr, i) for i in target.indices)
    entry = tr.values.get(key)
    if entry is None:
        if key in tr.scalars:
            raise tr.error(f"{target.name} is a declared scalar, not a matrix", target, "T008")
        if op not in ("=", ":="):
            raise tr.error(f"{target.name} has no value yet ({op} needs one)", target,
                           "T002")
        entry = Entry(tr.py_name("value", target.name), NameKind.VALUE, ValueType.MATRIX)
        tr.values[key] = entry
        current = "None"
    else:
        current = entry.py
        entry.type = ValueType.MATRIX
    if op not in ("=", ":="):
        old = f"{entry.py}[{', '.join(tr.index_code(i) for i in target.indices)}]"
        rhs = f"{old} {_COMPOUND[op]} {value.wrapped(6)}"
    else:
        rhs = value.code
    tr.emit(f"{entry.py} = al.set_element({current}, ({idx},), {rhs})")


def _one_based(tr: Translator, e: ir.Expr) -> str:
    x = tr.scalar(e)
    return x.code

