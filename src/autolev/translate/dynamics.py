"""Dynamics: MASS and INERTIA, and the commands GRAVITY, FORCE, TORQUE, CONSTRAIN, KANE."""
from __future__ import annotations

from .. import ir
from .commands import arguments, command
from .core import STATEMENTS, Translator
from .kinds import FRAME_KINDS, Entry, NameKind, ValueType
from .emit import quote


def _implicit_constant(tr: Translator, e: ir.Expr) -> None:
    """MASS B=mB and INERTIA B, I1, ... declare names that are new (as constants)."""
    if isinstance(e, ir.Name) and not e.primes:
        key = e.name.lower()
        if key not in tr.scalars and key not in tr.values and key not in ("t", "pi"):
            entry = tr.declare_scalar(e.name, NameKind.CONSTANT, 0)
            tr.emit(f"{entry.py} = model.constants({quote(e.name)})")


@STATEMENTS.register(ir.MassStatement)
def mass(tr: Translator, st: ir.MassStatement) -> None:
    for item in st.items:
        target = tr.entities.get(item.target.lower())
        if target is None or target.kind not in (NameKind.BODY, NameKind.PARTICLE):
            raise tr.error(f"MASS is given to bodies and particles; '{item.target}' is not "
                           "one", item, "T008")
        _implicit_constant(tr, item.value)
        value = tr.scalar(item.value)
        tr.emit(f"{target.py}.mass = {value.code}")
        tr.note_statement("mass", item.target)
        if item.value_of_value is not None:
            tr.emit(f"model.define({value.code}, {tr.scalar(item.value_of_value).code})")
            tr.defined.add((item.value.name.lower(), 0))


@STATEMENTS.register(ir.InertiaStatement)
def inertia(tr: Translator, st: ir.InertiaStatement) -> None:
    body = tr.entities.get(st.body.lower())
    about = None
    if body is None or body.kind != NameKind.BODY:
        pieces = st.body.split("_")
        for i in range(1, len(pieces)):
            b = tr.entities.get("_".join(pieces[:i]).lower())
            p = tr.entities.get("_".join(pieces[i:]).lower())
            if b is not None and b.kind == NameKind.BODY and p is not None and \
                    p.kind in (NameKind.POINT, NameKind.PARTICLE):
                body, about = b, p
                break
        else:
            raise tr.error(f"INERTIA is given to a body; '{st.body}' is not one", st, "T008")
    frame = None
    if st.frame is not None:
        frame = tr.entities.get(st.frame.lower())
        if frame is None or frame.kind not in FRAME_KINDS:
            raise tr.error(f"'{st.frame}' is not a frame", st, "T008")
    for name, value in st.definitions:
        v = tr.scalar(value)
        if name.lower() in tr.scalars:
            tr.emit(f"model.define({tr.scalars[name.lower()].py}, {v.code})")
            tr.defined.add((name.lower(), 0))
        else:
            py = tr.py_name("value", name)
            tr.values[name.lower()] = Entry(py, NameKind.VALUE, ValueType.SCALAR)
            tr.emit(f"{py} = {v.code}")
    for v in st.values:
        _implicit_constant(tr, v)
    values = [tr.scalar(v).code for v in st.values]
    if len(values) == 1:
        values = values * 3
    opts = ""
    if frame is not None:
        opts += f", frame={frame.py}"
    if about is not None:
        opts += f", about={about.py}"
    tr.emit(f"{body.py}.set_inertia({', '.join(values)}{opts})")
    tr.note_statement("inertia", tr.autolev_name(body))



@command("GRAVITY")
def _gravity(tr, c):
    if not c.args:
        raise tr.error("GRAVITY(g>) or GRAVITY(g>, B, ...)", c, "T007")
    g = tr.expr(c.args[0])
    if g.type not in (ValueType.VECTOR, ValueType.UNKNOWN):
        raise tr.error(f"GRAVITY takes a vector, not a {g.type}", c.args[0], "T001")
    rest = [tr.entity(a, (NameKind.BODY, NameKind.PARTICLE)).py for a in c.args[1:]]
    tr.emit(f"model.gravity({', '.join([g.code] + rest)})")
    tr.note_statement("gravity", "*")


def _pair(tr, e, kinds):
    """`A/B` in FORCE and TORQUE: the two things, or one."""
    if isinstance(e, ir.BinOp) and e.op == "/":
        return tr.entity(e.left, kinds), tr.entity(e.right, kinds)
    return None, tr.entity(e, kinds)


@command("FORCE")
def _force(tr, c):
    _load(tr, c, "force", (NameKind.POINT, NameKind.PARTICLE))


@command("TORQUE")
def _torque(tr, c):
    _load(tr, c, "torque", FRAME_KINDS)


def _load(tr, c, what: str, kinds) -> None:
    """FORCE(P, F>) / TORQUE(A, T>) on one, or FORCE(A/B, F>) on a pair (+ on B, - on A)."""
    a, f = arguments(tr, c, 2)
    first, second = _pair(tr, a, kinds)
    v = tr.expr(f)
    if v.type not in (ValueType.VECTOR, ValueType.UNKNOWN):
        raise tr.error(f"{what.upper()} takes a vector, not a {v.type}", f, "T001")
    if first is None:
        tr.emit(f"model.{what}({second.py}, {v.code})")
    else:
        tr.emit(f"model.{what}_pair({first.py}, {second.py}, {v.code})")
    tr.note_statement("load", *(tr.autolev_name(e) for e in (first, second) if e is not None))


@command("CONSTRAIN", "CONSTRAINT")
def _constrain(tr, c):
    if not c.args:
        raise tr.error("CONSTRAIN(DEPENDENT[u, ...]) or CONSTRAIN(AUXILIARY[u, ...])", c, "T007")
    for a in c.args:
        if not isinstance(a, ir.Index):
            raise tr.error("CONSTRAIN takes DEPENDENT[u, ...] or AUXILIARY[u, ...]", a, "T009")
        which = a.name.upper()
        eqs = tr.values.get(a.name.lower())
        if eqs is None:
            raise tr.error(f"{a.name} has no equations yet ({a.name}[1] = ...)", a, "T002")
        speeds = [tr.symbol(i) for i in a.indices]
        method = "constrain_auxiliary" if which == "AUXILIARY" else "constrain"
        tr.emit(f"model.{method}({eqs.py}, [{', '.join(speeds)}])")
        tr.note_statement("constrain", "AUXILIARY" if which == "AUXILIARY" else "DEPENDENT")
        for i in a.indices:
            if isinstance(i, ir.Name):
                tr.defined.add((i.name.lower(), i.primes))
                tr.defined.add((i.name.lower(), i.primes + 1))


@command("KANE")
def _kane(tr, c):
    unknowns = [tr.scalar(a).code for a in c.args]
    tr.session.kane_called = True
    tr.emit(f"model.kane({', '.join(unknowns)})")

