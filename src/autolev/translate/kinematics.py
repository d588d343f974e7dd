"""Kinematics: the commands that orient frames (SIMPROT, DIRCOS), relate angles and
speeds (KINDIFFS, ANGVEL) and apply the one- and two-point theorems (V2PTS, A1PT, ...)."""
from __future__ import annotations

import re

from .. import ir
from .commands import COMMANDS, arguments, command
from .core import Translator
from .kinds import ValueType
from .emit import comment, quote


def _angle(tr: Translator, e: ir.Expr) -> str:
    """A number is an angle in degrees unless DEGREES OFF; an angle written with PI
    (PI/2) is in radians either way (docs/language.md)."""
    x = tr.scalar(e)
    if tr.session.degrees and _is_plain_number(e):
        return f"al.degrees_to_radians({x.code})"
    return x.code


def _is_plain_number(e: ir.Expr) -> bool:
    return not any(isinstance(n, (ir.Name, ir.Call, ir.Index, ir.VectorName))
                   for n in ir.walk(e))


def _note_frame(tr: Translator, oriented: ir.Expr) -> None:
    if isinstance(oriented, ir.Name):
        tr.note_statement("orientation", oriented.name)


@command("SIMPROT")
def _simprot(tr, c):
    args = arguments(tr, c, 4)
    a, b = tr.frame(args[0]).code, tr.frame(args[1]).code
    axis = args[2]
    x = tr.expr(axis)
    if x.type == ValueType.VECTOR:
        axis_code = x.code
    elif x.exact is not None and x.exact.denominator == 1 and abs(int(x.exact)) in (1, 2, 3):
        k = int(x.exact)
        axis_code = ("-" if k < 0 else "") + f"{a}.{'xyz'[abs(k) - 1]}"
    else:
        raise tr.error("SIMPROT's axis is 1, 2, 3 (negative for the other way) or a vector",
                       axis, "T009")
    tr.emit(f"{b}.orient_axis({a}, {axis_code}, {_angle(tr, args[3])})")
    _note_frame(tr, args[1])


@command("DIRCOS")
def _dircos(tr, c):
    if len(c.args) < 4 or not isinstance(c.args[2], ir.Name):
        raise tr.error("DIRCOS(A, B, BODYijk|SPACEijk|EULER, angles...)", c, "T009")
    a, b = tr.frame(c.args[0]).code, tr.frame(c.args[1]).code
    _note_frame(tr, c.args[1])
    kind = c.args[2].name.upper()
    angles = [_angle(tr, x) for x in c.args[3:]]
    if kind == "EULER":
        if len(angles) != 4:
            raise tr.error("DIRCOS(A, B, EULER, e1, e2, e3, e4) takes 4 parameters", c, "T007")
        tr.emit(f"{b}.orient_euler_parameters({a}, {', '.join(angles)})")
        return
    if kind == "RODRIGUES":
        if len(angles) != 3:
            raise tr.error("DIRCOS(A, B, RODRIGUES, g1, g2, g3) takes 3 parameters", c, "T007")
        tr.emit(f"{b}.orient_rodrigues({a}, {', '.join(angles)})")
        return
    m = re.fullmatch(r"(BODY|SPACE)([123]{3})", kind)
    if not m or len(angles) != 3:
        raise tr.error(f"DIRCOS does not know {c.args[2].name}; expected BODYijk, SPACEijk "
                       "or EULER", c.args[2], "T003")
    method = "orient_body_fixed" if m.group(1) == "BODY" else "orient_space_fixed"
    tr.emit(f"{b}.{method}({a}, ({', '.join(angles)}), {quote(m.group(2))})")


@command("KINDIFFS")
def _kindiffs(tr, c):
    if len(c.args) < 4 or not isinstance(c.args[2], ir.Name):
        raise tr.error("KINDIFFS(A, B, BODYijk|SPACEijk|EULER, q...)", c, "T009")
    a, b = tr.frame(c.args[0]).code, tr.frame(c.args[1]).code
    coords = [tr.symbol(x) for x in c.args[3:]]
    tr.emit(f"model.kindiffs({a}, {b}, {quote(c.args[2].name.upper())}, {', '.join(coords)})")
    for x in c.args[3:]:
        if isinstance(x, ir.Name):
            tr.defined.add((x.name.lower(), x.primes + 1))


@command("ANGVEL")
def _angvel(tr, c):
    if len(c.args) == 2:
        a, b = tr.frame(c.args[0]).code, tr.frame(c.args[1]).code
        tr.emit(f"# (Autolev displayed {comment(f'W_{c.args[1].name}_{c.args[0].name}>')})")
        tr.emit(f"{b}.ang_vel_in({a})")
        return
    if len(c.args) == 6 and isinstance(c.args[2], ir.Name):
        a, b = tr.frame(c.args[0]).code, tr.frame(c.args[1]).code
        angles = [tr.scalar(x).code for x in c.args[3:]]
        tr.emit(f"model.angvel({a}, {b}, {quote(c.args[2].name.upper())}, {', '.join(angles)})")
        return
    raise tr.error("ANGVEL(A, B) or ANGVEL(A, B, BODYijk|SPACEijk|RODRIGUES, a1, a2, a3)", c,
                   "T009")


def _theory(method):
    def write(tr, c):
        args = arguments(tr, c, 4)
        outer, fixed = tr.frame(args[0]).code, tr.frame(args[1]).code
        o, p = tr.point(args[2]).code, tr.point(args[3]).code
        tr.emit(f"{p}.{method}({o}, {outer}, {fixed})")
        if method.startswith("v") and isinstance(args[3], ir.Name):
            tr.note_statement("velocity", args[3].name)
    return write


COMMANDS["V2PTS"] = _theory("v2pt_theory")
COMMANDS["V1PT"] = _theory("v1pt_theory")
COMMANDS["A2PTS"] = _theory("a2pt_theory")
COMMANDS["A1PT"] = _theory("a1pt_theory")

