"""Assignments: `X = ...`, `X += ...`, `M[i, j] = ...`, `V> = ...` and A_B = (a DCM)."""
from __future__ import annotations

import re

from .. import ir
from .core import STATEMENTS, Translator
from .kinds import FRAME_KINDS, Entry, NameKind, Typed, ValueType
from .emit import call_lines
from .special import assign_vector, classify

# -- assignments ---------------------------------------------------------------------------
_COMPOUND = {"+=": "+", "-=": "-", "*=": "*", "/=": "/", "^=": "**"}


@STATEMENTS.register(ir.Assignment)
def assignment(tr: Translator, st: ir.Assignment) -> None:
    if isinstance(st.target, (ir.Name, ir.Index)) and st.span is not None:
        tr.defined_at[(st.target.name + "P" * st.target.primes).upper()] = tr.location(st)
        if not st.target.primes:
            tr.note_statement("assigned", st.target.name)
    elif isinstance(st.target, ir.VectorName):
        _note_mechanics(tr, st.target)
    run = _column_runs(tr).get(id(st))
    if run is None:
        assign(tr, st.target, st.op, st.value)
    elif st is run[-1]:
        _assign_column(tr, run)
    # an earlier element of a run is written with the run's last statement


# what an assignment to a reserved vector gives its first part
_GIVES = {"angvel": "angular velocity", "vel": "velocity", "force": "load", "torque": "load",
          "angacc": "acceleration", "acc": "acceleration", "inertia": "inertia"}


def _note_mechanics(tr: Translator, target: ir.VectorName) -> None:
    """W_B_N>, V_P_N>, P_A_B>, FORCE_P>, TORQUE_B>, ALF_B_N>, A_P_N> = ...: the statement
    that gives them."""
    special = classify(tr, target)
    if special is None:
        return
    if special.kind == "pos":
        tr.note_statement("position", "/".join(tr.autolev_name(e) for e in special.parts))
    elif special.kind in _GIVES:
        tr.note_statement(_GIVES[special.kind], tr.autolev_name(special.parts[0]))


def _column_runs(tr: Translator) -> dict[int, list[ir.Assignment]]:
    """The runs `X[1] = a`, `X[2] = b`, ... `X[n] = z` (n > 1, consecutive statements) of a
    name X no earlier statement mentions, by the id of each of their statements."""
    runs = tr.column_runs
    if runs is None:
        runs, seen = {}, set()
        statements = tr.program.statements
        i = 0
        while i < len(statements):
            run = _run_at(statements, i)
            if len(run) > 1 and run[0].target.name.lower() not in seen:
                runs.update((id(s), run) for s in run)
            for s in statements[i:i + max(len(run), 1)]:
                seen.update(w.lower() for w in re.findall(r"\w+", s.text))
            i += max(len(run), 1)
        tr.column_runs = runs
    return runs


def _run_at(statements: list[ir.Statement], i: int) -> list[ir.Assignment]:
    """The statements from i on that set elements 1, 2, ... of one name, none reading it."""
    run: list[ir.Assignment] = []
    for k in range(i, len(statements)):        # by index: no copy of a long model's list
        st = statements[k]
        target = getattr(st, "target", None)
        if not (isinstance(st, ir.Assignment) and st.op == "=" and isinstance(target, ir.Index)
                and not target.primes and len(target.indices) == 1
                and isinstance(target.indices[0], ir.Number)
                and target.indices[0].text == str(len(run) + 1)):
            break
        key = target.name.lower()
        if run and key != run[0].target.name.lower():
            break
        if any(isinstance(n, (ir.Name, ir.Index)) and n.name.lower() == key
               for n in ir.walk(st.value)):
            break
        run.append(st)
    return run


def _assign_column(tr: Translator, run: list[ir.Assignment]) -> None:
    """A new name's elements 1..n, set one by one in a row, as one column."""
    codes = []
    for st in run:
        value = tr.expr(st.value)
        if value.type in (ValueType.FRAME, ValueType.POINT, ValueType.LIST):
            raise tr.error(f"a {value.type} cannot be assigned", st.value, "T001")
        if value.type not in (ValueType.SCALAR, ValueType.UNKNOWN):
            raise tr.error(f"a matrix element is a scalar, not a {value.type}", st.target,
                           "T001")
        codes.append(value.code)
    name = run[0].target.name
    entry = Entry(tr.py_name("value", name), NameKind.VALUE, ValueType.MATRIX,
                  shape=(len(codes), 1), elements=tuple(st.value for st in run))
    tr.values[name.lower()] = entry
    tr.emit(call_lines(f"{entry.py} = sm.Matrix([", codes, "])"))


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
    if key == "zee_not" and not primes:      # a setting, also a value (Autolev answers it)
        entry = tr.values.get(key)
        if entry is None:
            entry = tr.values[key] = Entry(tr.py_name("value", name), NameKind.VALUE,
                                           ValueType.MATRIX)
        tr.emit(f"{entry.py} = model.zee_not({value.code})")
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
        entry = Entry(tr.py_name("value", name), NameKind.VALUE, value.type, shape=value.shape,
                      elements=value.elements)
        tr.values[key] = entry
        tr.emit(f"{entry.py} = {value.code}")
        return
    if op in ("=", ":="):
        entry.type, entry.shape, entry.elements = value.type, value.shape, value.elements
        tr.emit(f"{entry.py} = {value.code}")
    else:
        entry.shape = entry.elements = None     # M *= N: the product is not followed
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
        entry.type, entry.shape, entry.elements = ValueType.MATRIX, None, None   # it may grow
    if op not in ("=", ":="):
        old = f"{entry.py}[{', '.join(tr.index_code(i) for i in target.indices)}]"
        rhs = f"{old} {_COMPOUND[op]} {value.wrapped(6)}"
    else:
        rhs = value.code
    tr.emit(f"{entry.py} = al.set_element({current}, ({idx},), {rhs})")


def _one_based(tr: Translator, e: ir.Expr) -> str:
    x = tr.scalar(e)
    return x.code

