"""Functions of vectors and dyadics: DOT, CROSS, MAG, UNITVEC, EXPRESS, VECTOR, MATRIX,
DYADIC."""
from __future__ import annotations

from ..kinds import Typed, ValueType
from .arguments import matrix_arg
from .table import function, nargs


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
        rest = [matrix_arg(tr, args[1], "VECTOR(A, M)")]
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
    m = matrix_arg(tr, args[1], "DYADIC")
    if m.shape not in (None, (3, 3)):
        raise tr.error(f"DYADIC takes a 3x3 matrix, not a {m.shape[0]}x{m.shape[1]} one",
                       args[1], "T001")
    return Typed(f"al.dyadic({frames[0]}, {m.code}" +
                 (f", {frames[1]})" if len(frames) > 1 else ")"), ValueType.DYADIC)
