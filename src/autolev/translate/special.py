"""Autolev's reserved vector names, resolved against the declared frames and points.

    N1>          unit vector of frame N            -> N.x
    P_A_B>       position of B from A             -> B.pos_from(A)
    V_P_N>       velocity of P in N                -> P.vel(N)
    A_P_N>       acceleration of P in N            -> P.acc(N)
    W_A_N>       angular velocity of A in N        -> A.ang_vel_in(N)
    ALF_A_N>     angular acceleration of A in N    -> A.ang_acc_in(N)
    I_B_O>>      inertia of body B about point O   -> B.inertia_about(O)
    FORCE_P>     resultant force on P              -> model.force_on(P)
    TORQUE_A>    resultant torque on A             -> model.torque_on(A)
    0>, 1>>      zero vector, unit dyadic

A name whose parts are not declared frames and points is an ordinary user vector.
"""
from __future__ import annotations

from dataclasses import dataclass

from .. import ir
from .core import EXPRESSIONS, Translator
from .kinds import ATOM, FRAME_KINDS, POINT_KINDS, Entry, NameKind, Typed, ValueType

_AXES = {"1": "x", "2": "y", "3": "z"}


@dataclass
class Special:
    kind: str
    parts: tuple[Entry, ...] = ()
    axis: str = ""


def classify(tr: Translator, v: ir.VectorName) -> Special | None:
    name = v.name
    upper = name.upper()
    if v.dyadic:
        if name == "1":
            return Special("unit_dyadic")
        if upper.startswith("I_"):
            parts = _split(tr, name[2:], ((NameKind.BODY, NameKind.PARTICLE), POINT_KINDS))
            if parts:
                return Special("inertia", tuple(parts))
        return None
    if name == "0":
        return Special("zero")
    if name[-1] in _AXES:
        ent = tr.entities.get(name[:-1].lower())
        if ent is not None and ent.kind in FRAME_KINDS:
            return Special("unit", (ent,), _AXES[name[-1]])
    rules = (("ALF_", "angacc", (FRAME_KINDS, FRAME_KINDS)), ("FORCE_", "force", (POINT_KINDS,)),
             ("TORQUE_", "torque", (FRAME_KINDS,)), ("P_", "pos", (POINT_KINDS, POINT_KINDS)),
             ("V_", "vel", (POINT_KINDS, FRAME_KINDS)), ("A_", "acc", (POINT_KINDS, FRAME_KINDS)),
             ("W_", "angvel", (FRAME_KINDS, FRAME_KINDS)))
    for prefix, kind, kinds in rules:
        if upper.startswith(prefix):
            parts = _split(tr, name[len(prefix):], kinds)
            if parts:
                return Special(kind, tuple(parts))
    return None


def _split(tr: Translator, text: str, kinds) -> list[Entry] | None:
    pieces = text.split("_")

    def go(pieces, kinds):
        if len(kinds) == 1:
            ent = tr.entities.get("_".join(pieces).lower())
            return [ent] if ent is not None and ent.kind in kinds[0] else None
        for i in range(1, len(pieces)):
            ent = tr.entities.get("_".join(pieces[:i]).lower())
            if ent is None or ent.kind not in kinds[0]:
                continue
            rest = go(pieces[i:], kinds[1:])
            if rest is not None:
                return [ent] + rest
        return None

    return go(pieces, kinds) if pieces and all(pieces) else None


@EXPRESSIONS.register(ir.VectorName)
def vector_name(tr: Translator, v: ir.VectorName, want: str = "value") -> Typed:
    """The Python that reads a vector or dyadic name (the same whatever is wanted)."""
    sp = classify(tr, v)
    if sp is None:
        entry = tr.vectors.get(v.name.lower())
        if entry is None or (entry.type == ValueType.DYADIC) != v.dyadic:
            raise tr.error(f"'{v.text}' is not defined (a vector must be assigned before "
                           "it is used)", v, "T002")
        return Typed(entry.py, entry.type)
    p = [e.py for e in sp.parts]
    code = {
        "zero": lambda: "al.ZERO",
        "unit_dyadic": lambda: "model.unit_dyadic()",
        "unit": lambda: f"{p[0]}.{sp.axis}",
        "pos": lambda: f"{p[1]}.pos_from({p[0]})",
        "vel": lambda: f"{p[0]}.vel({p[1]})",
        "acc": lambda: f"{p[0]}.acc({p[1]})",
        "angvel": lambda: f"{p[0]}.ang_vel_in({p[1]})",
        "angacc": lambda: f"{p[0]}.ang_acc_in({p[1]})",
        "inertia": lambda: (f"{p[0]}.inertia_about({p[1]})" if sp.parts[0].kind == NameKind.BODY
                            else f"model.particle_inertia({p[0]}, {p[1]})"),
        "force": lambda: f"model.force_on({p[0]})",
        "torque": lambda: f"model.torque_on({p[0]})",
    }[sp.kind]()
    return Typed(code, ValueType.DYADIC if v.dyadic else ValueType.VECTOR, ATOM)


def assign_vector(tr: Translator, target: ir.VectorName, op: str, value: Typed) -> None:
    """Write `target op value` for a vector or dyadic name."""
    want = ValueType.DYADIC if target.dyadic else ValueType.VECTOR
    if value.type not in (want, ValueType.UNKNOWN) and not (value.exact == 0):
        raise tr.error(f"{target.text} is a {want}; the right side is a {value.type}", target,
                       "T001")
    sp = classify(tr, target)
    if sp is None:
        _user_vector(tr, target, op, value, want)
        return
    p = [e.py for e in sp.parts]
    if sp.kind in ("zero", "unit", "unit_dyadic"):
        raise tr.error(f"{target.text} cannot be assigned", target, "T010")
    if sp.kind in ("force", "torque"):
        what = "force" if sp.kind == "force" else "torque"
        if op in ("=", ":="):
            tr.emit(f"model.set_{what}({p[0]}, {value.code})")
        elif op == "+=":
            tr.emit(f"model.add_{what}({p[0]}, {value.code})")
        elif op == "-=":
            tr.emit(f"model.add_{what}({p[0]}, -{value.wrapped(6)})")
        else:
            raise tr.error(f"{op} is not defined for {target.text}", target, "T010")
        return
    current = vector_name(tr, target).code
    rhs = _combine(tr, current, op, value, target)
    setter = {
        "pos": f"{p[1]}.set_pos({p[0]}, {{}})",
        "vel": f"{p[0]}.set_vel({p[1]}, {{}})",
        "acc": f"{p[0]}.set_acc({p[1]}, {{}})",
        "angvel": f"{p[0]}.set_ang_vel({p[1]}, {{}})",
        "angacc": f"{p[0]}.set_ang_acc({p[1]}, {{}})",
        "inertia": f"{p[0]}.set_inertia_dyadic({{}}, about={p[1]})",
    }[sp.kind]
    tr.emit(setter.format(rhs))


def _user_vector(tr: Translator, target: ir.VectorName, op: str, value: Typed, want) -> None:
    key = target.name.lower()
    entry = tr.vectors.get(key)
    if entry is None:
        if op not in ("=", ":="):
            raise tr.error(f"{target.text} has no value yet", target, "T002")
        entry = Entry(tr.py_name("vector", target.name, want.value), NameKind.VECTOR, want)
        tr.vectors[key] = entry
    rhs = _combine(tr, entry.py, op, value, target)
    tr.emit(f"{entry.py} = {rhs}")


def _combine(tr: Translator, current: str, op: str, value: Typed, node) -> str:
    if op in ("=", ":="):
        return value.code
    if op == "+=":
        return f"{current} + {value.wrapped(5)}"
    if op == "-=":
        return f"{current} - {value.wrapped(5)}"
    if op == "*=":
        return f"{current}*{value.wrapped(6)}"
    if op == "/=":
        return f"{current}/{value.wrapped(7)}"
    raise tr.error(f"{op} is not defined for vectors", node, "T010")
