"""Functions of matrices: TRANSPOSE, INV, DET, TRACE, DIAGMAT, ROWS, COLS, ELEMENT,
EIG."""
from __future__ import annotations

from ... import ir
from ..kinds import ATOM, Typed, ValueType
from .arguments import declared_in, matrix_arg, number_arg
from .table import function, nargs


def _square_arg(tr, a, what):
    """A matrix argument that must be square (when its shape is known here)."""
    x = matrix_arg(tr, a, what)
    if x.shape is not None and x.shape[0] != x.shape[1]:
        raise tr.error(f"{what} takes a square matrix, not a {x.shape[0]}x{x.shape[1]} one",
                       a, "T001")
    return x


@function("TRANSPOSE")
def _transpose(tr, c):
    (a,) = nargs(tr, c, 1)
    return Typed(f"al.transpose({matrix_arg(tr, a, 'TRANSPOSE').code})", ValueType.MATRIX)


@function("INV", "INVERSE")
def _inv(tr, c):
    (a,) = nargs(tr, c, 1)
    return Typed(f"model.inv({_square_arg(tr, a, c.name.upper()).code})", ValueType.MATRIX)


@function("DET")
def _det(tr, c):
    (a,) = nargs(tr, c, 1)
    return Typed(f"model.det({_square_arg(tr, a, 'DET').code})", ValueType.SCALAR)


@function("TRACE")
def _trace(tr, c):
    (a,) = nargs(tr, c, 1)
    return Typed(f"al.trace({_square_arg(tr, a, 'TRACE').code})", ValueType.SCALAR)


@function("DIAGMAT")
def _diagmat(tr, c):
    args = nargs(tr, c, 2, 3)
    sizes = [number_arg(tr, a, "DIAGMAT's size").code for a in args[:-1]]
    return Typed(f"al.diagmat({', '.join(sizes + [tr.scalar(args[-1]).code])})",
                 ValueType.MATRIX)


def _index(tr, a, count: int | None) -> Typed:
    """A 1-based index, within 1..count when both are known here."""
    x = number_arg(tr, a, "an index")
    if count is not None and x.exact is not None and not 1 <= x.exact <= count:
        raise tr.error(f"index {x.exact} is outside 1..{count}", a, "T001")
    return x


def _selection(tr, args, count: int | None) -> list[str]:
    out = []
    for a in args:
        if isinstance(a, ir.Range):
            out.append(f"({_index(tr, a.lo, count).code}, {_index(tr, a.hi, count).code})")
        else:
            out.append(_index(tr, a, count).code)
    return out


@function("ROWS", "COLS")
def _rows(tr, c):
    if not c.args:
        raise tr.error(f"{c.name.upper()} needs a matrix", c, "T007")
    m = matrix_arg(tr, c.args[0], c.name.upper())
    fn = "rows" if c.name.upper() == "ROWS" else "cols"
    if len(c.args) == 1:
        return Typed(f"al.{fn}({m.code})", ValueType.SCALAR)
    axis = 0 if fn == "rows" else 1
    sel = _selection(tr, c.args[1:], m.shape[axis] if m.shape else None)
    return Typed(f"al.{fn}({m.code}, {', '.join(sel)})", ValueType.MATRIX)


@function("ELEMENT")
def _element(tr, c):
    args = nargs(tr, c, 2, 3)
    m = matrix_arg(tr, args[0], "ELEMENT")
    counts = (m.shape if len(args) == 3 else (m.shape[0] * m.shape[1],)) if m.shape \
        else (None, None)
    for a, count in zip(args[1:], counts):
        _index(tr, a, count)
    idx = [tr.index_code(a) for a in args[1:]]
    return Typed(f"{m.wrapped(ATOM)}[{', '.join(idx)}]", ValueType.SCALAR)


@function("EIG")
def _eig(tr, c):
    (a,) = nargs(tr, c, 1)
    m = _square_arg(tr, a, "EIG")
    symbol = declared_in(tr, m.elements)
    if symbol is not None:
        raise tr.error(f"EIG takes a matrix of numbers; this one holds {symbol.name}, a "
                       f"{tr.scalars[symbol.name.lower()].kind} (EVALUATE it first)", a, "T001")
    return Typed(f"al.eig(model.explicit({m.code}))", ValueType.MATRIX)
