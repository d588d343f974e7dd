"""Functions of Kane's method and the system's mass: FR, FRSTAR, KE, MASS, CM, INERTIA,
MOMENTUM, GYROSTAT, PARTIALS, NICHECK."""
from __future__ import annotations

from ... import ir
from ..kinds import NameKind, Typed, ValueType
from .arguments import variable_arg
from .table import function, nargs


@function("FR")
def _fr(tr, c):
    nargs(tr, c, 0)
    return Typed("model.fr()", ValueType.MATRIX)


@function("FRSTAR")
def _frstar(tr, c):
    nargs(tr, c, 0)
    _warn_inertia_lacking(tr, c)
    return Typed("model.frstar()", ValueType.MATRIX)


def _warn_inertia_lacking(tr, c) -> None:
    """FRSTAR() needs the inertia of every body that turns: the bodies oriented or given
    an angular velocity, with no INERTIA nor I_B_O>> so far, are named (the run refuses
    them unless they turn not at all)."""
    lacking = []
    for entry in tr.entities.values():
        if entry.kind != NameKind.BODY:
            continue
        name = tr.autolev_name(entry)
        turned = tr.statements_at.get(("orientation", name.upper())) \
            or tr.statements_at.get(("angular velocity", name.upper()))
        if turned and ("inertia", name.upper()) not in tr.statements_at:
            lacking.append((name, turned[0]))
    if len(lacking) == 1:
        (name, where), = lacking
        tr.warn(f"body {name} has no INERTIA, and it turns ({where}): FRSTAR() needs its "
                f"inertia (INERTIA {name}, I11, I22, I33)", c, "W107")
    elif lacking:
        tr.warn(f"bodies {', '.join(name for name, _ in lacking)} have no INERTIA, and they "
                f"turn ({lacking[0][0]}: {lacking[0][1]}): FRSTAR() needs their inertia "
                "(INERTIA B, I11, I22, I33 for each)", c, "W107")


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
    speeds = [variable_arg(tr, a, "PARTIALS") for a in c.args[1:]]
    codes = [v.code] + [u.code for u in speeds]
    if len(speeds) == 1 and speeds[0].type == ValueType.SCALAR:
        return Typed(f"model.partials({', '.join(codes)})[0]", ValueType.VECTOR)
    return Typed(f"model.partials({', '.join(codes)})", ValueType.VECTORS)


@function("NICHECK")
def _nicheck(tr, c):
    nargs(tr, c, 0)
    return Typed("model.nicheck()", ValueType.SCALAR)
