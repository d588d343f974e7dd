"""Autolev's functions that need no model: vector algebra, matrices, algebra, units."""
from __future__ import annotations

import math
import re

import sympy as sm

from .calculus import is_real_number, refuse_huge_powers, refused_substitution
from .sympy_functions import Int, Round
from ..engine.errors import AutolevModelError
from ..engine.functions import MAX, MIN
from .frame import Frame
from .vectors import Dyadic, Vector, outer

ZERO = Vector()
# a symbolic matrix this large takes minutes and gigabytes to build (1000 x 1000: 3 s)
MAX_MATRIX_ELEMENTS = 10 ** 6


# -- vectors -----------------------------------------------------------------------
class VectorColumn(list):
    """[V1>; V2>]: a column of vectors (DOT with it gives a column of scalars)."""


def dot(a, b):
    """DOT(a, b) of vectors and dyadics; with a column of vectors, a column."""
    if isinstance(a, VectorColumn):
        return sm.Matrix([dot(x, b) for x in a])
    if isinstance(b, VectorColumn):
        return sm.Matrix([dot(a, x) for x in b])
    if isinstance(a, (Vector, Dyadic)):
        return a.dot(b)
    raise AutolevModelError(f"DOT needs vectors or dyadics, not {type(a).__name__}")


def cross(a, b):
    if isinstance(a, (Vector, Dyadic)):
        return a.cross(b)
    raise AutolevModelError(f"CROSS needs vectors, not {type(a).__name__}")


def mag(v: Vector):
    """MAG(V>), named by a Z (as Autolev's Z12 = Z11^0.5) when not small."""
    defs = v.definitions()
    square = v.dot(v)
    if defs is None:
        return sm.sqrt(square)
    return defs.zify(sm.sqrt(defs.zify(square)))


def unitvec(v: Vector) -> Vector:
    """UNITVEC(V>): its measure numbers over its magnitude, each named by a Z (the
    derivatives of unnamed quotients of square roots grow without bound)."""
    defs = v.definitions()
    if defs is None:
        return v / mag(v)
    return (v * defs.zify(1 / mag(v))).zified()


def express(x, frame: Frame, other: Frame | None = None):
    """EXPRESS(V>, A) or EXPRESS(D>>, A): the same quantity with measure numbers in A."""
    if isinstance(x, Vector):
        return x.express(frame)
    if isinstance(x, Dyadic):
        return x.express(frame, other or frame)
    if isinstance(x, sm.MatrixBase):
        return x
    raise AutolevModelError(f"EXPRESS takes a vector or dyadic, not {type(x).__name__}")


def vector(frame: Frame, *comps) -> Vector:
    """VECTOR(A, x, y, z) or VECTOR(A, M): measure numbers in A."""
    if len(comps) == 1:
        m = sm.Matrix(comps[0])
        if len(m) != 3:
            raise AutolevModelError(f"VECTOR needs 3 measure numbers, not {len(m)}")
        comps = tuple(m)
    if len(comps) != 3:
        raise AutolevModelError(f"VECTOR needs 3 measure numbers, not {len(comps)}")
    return Vector({frame: tuple(sm.sympify(c) for c in comps)})


def matrix(frame: Frame, x, other: Frame | None = None) -> sm.Matrix:
    """MATRIX(A, V>): the measure numbers in A as a column; MATRIX(A, D>>): 3x3."""
    if isinstance(x, Vector):
        return x.to_matrix(frame)
    if isinstance(x, Dyadic):
        return x.to_matrix(frame, other or frame)
    raise AutolevModelError(f"MATRIX takes a vector or dyadic, not {type(x).__name__}")


def dyadic(frame: Frame, m, other: Frame | None = None) -> Dyadic:
    """DYADIC(A, M): sum of M[i,j] Ai> Aj> (or Ai> Bj> with a second frame)."""
    m = sm.Matrix(m)
    if m.shape != (3, 3):
        raise AutolevModelError(f"DYADIC needs a 3x3 matrix, not {m.rows}x{m.cols}")
    return Dyadic({(frame, other or frame): m})


# -- matrices --------------------------------------------------------------------------
def set_element(m, index: tuple, value) -> sm.Matrix:
    """X[i] = value or X[i, j] = value (1-based); X grows to hold the element."""
    idx = [_index(i) for i in index]
    if math.prod(idx) > MAX_MATRIX_ELEMENTS:
        raise AutolevModelError(f"element {list(idx)}: a matrix of more than "
                                f"{MAX_MATRIX_ELEMENTS} elements is not built")
    if m is None:
        m = sm.zeros(0, 1) if len(idx) == 1 else sm.zeros(0, 0)
    m = sm.Matrix(m) if not isinstance(m, sm.MutableDenseMatrix) else m.copy()
    if len(idx) == 1:
        (i,) = idx
        if m.cols > 1 and m.rows == 1:           # a row: grow along it
            if i > m.cols:
                m = m.row_join(sm.zeros(1, i - m.cols))
            m[0, i - 1] = value
            return m
        if m.cols == 0:
            m = sm.zeros(m.rows, 1)
        if i > m.rows:
            m = m.col_join(sm.zeros(i - m.rows, m.cols))
        m[i - 1, 0] = value
        return m
    i, j = idx
    if i > m.rows:
        m = m.col_join(sm.zeros(i - m.rows, m.cols))
    if j > m.cols:
        m = m.row_join(sm.zeros(m.rows, j - m.cols))
    m[i - 1, j - 1] = value
    return m


def maximum(*args):
    """MAX(a, b, ...)."""
    return sm.Max(*_comparable(MAX.autolev, args))


def minimum(*args):
    """MIN(a, b, ...)."""
    return sm.Min(*_comparable(MIN.autolev, args))


def _comparable(what: str, args) -> list:
    """The arguments, after refusing any that is a number but not a real one: there is
    no order among complex numbers (and sympy's attempt to find one may never end)."""
    out = [sm.sympify(a) for a in args]
    for k, a in enumerate(out, 1):
        if not a.is_number:
            if a.is_extended_real is False:
                raise AutolevModelError(f"{what}'s argument {k}, {a}, is not real: complex "
                                        "numbers have no order")
            continue
        z = complex(a) if a.is_Number else complex(sm.N(a))
        if math.isnan(z.real) or math.isnan(z.imag):
            why = "a division by zero" if a == sm.zoo else "not a number"
            raise AutolevModelError(f"{what}'s argument {k} is undefined ({why})")
        if not is_real_number(z):
            raise AutolevModelError(f"{what}'s argument {k} is the complex number "
                                    f"{z.real:.6g}{z.imag:+.6g}i: complex numbers have no order")
    return out


def whole_number(x, what: str) -> int:
    """A count, order or index the model gives, as an int (a number's whole part)."""
    try:
        return int(x)
    except TypeError:                # a symbol or expression: not a number
        raise AutolevModelError(f"{what} must be a number, not {x}") from None


def _index(i) -> int:
    try:
        k = int(i)
    except TypeError:
        raise AutolevModelError(f"an index must be a whole number, not {i}") from None
    if k != i or k < 1:
        raise AutolevModelError(f"an index counts from 1, not {i}")
    return k


def block_matrix(rows) -> sm.Matrix:
    """[A, B; C, D] where entries may be matrices (joined into one matrix)."""
    built = []
    for row in rows:
        parts = [x if isinstance(x, sm.MatrixBase) else sm.Matrix([[x]]) for x in row]
        built.append(parts)
    try:
        return sm.Matrix.vstack(*[sm.Matrix.hstack(*parts) for parts in built])
    except sm.ShapeError as exc:     # blocks whose rows or columns do not line up
        raise AutolevModelError(f"the blocks of this matrix do not fit together: "
                                f"{exc}") from None


def transpose(m) -> sm.Matrix:
    return sm.Matrix(m).T


def trace(m):
    m = sm.Matrix(m)
    if not m.is_square:
        raise AutolevModelError(f"TRACE needs a square matrix, not {m.rows}x{m.cols}")
    return m.trace()


def diagmat(n, *args) -> sm.Matrix:
    """DIAGMAT(n, x): x on the diagonal of n x n; DIAGMAT(n, m, x): of n x m."""
    rows = whole_number(n, "DIAGMAT's number of rows")
    cols = whole_number(args[0], "DIAGMAT's number of columns") if len(args) == 2 else rows
    x = args[-1]
    if rows < 0 or cols < 0:
        raise AutolevModelError(f"DIAGMAT: a matrix cannot have {rows} x {cols} elements")
    if rows * cols > MAX_MATRIX_ELEMENTS:
        raise AutolevModelError(f"DIAGMAT: a {rows} x {cols} matrix has more than "
                                f"{MAX_MATRIX_ELEMENTS} elements, the most that is built")
    return sm.Matrix(rows, cols, lambda i, j: x if i == j else 0)


def _selection(items, count: int) -> list[int]:
    out = []
    for it in items:
        if isinstance(it, tuple):
            lo, hi = whole_number(it[0], "an index"), whole_number(it[1], "an index")
            # the ends first: a range of millions outside the matrix is never listed
            if lo <= hi and not 1 <= lo <= hi <= count:
                raise AutolevModelError(f"indices {lo}:{hi} are outside 1..{count}")
            out.extend(range(lo, hi + 1))
        else:
            out.append(whole_number(it, "an index"))
    for k in out:
        if not 1 <= k <= count:
            raise AutolevModelError(f"index {k} is outside 1..{count}")
    return [k - 1 for k in out]


def rows(m, *selection):
    """ROWS(M): how many rows; ROWS(M, i, j:k, ...): those rows."""
    m = sm.Matrix(m)
    if not selection:
        return m.rows
    return m.extract(_selection(selection, m.rows), list(range(m.cols)))


def cols(m, *selection):
    m = sm.Matrix(m)
    if not selection:
        return m.cols
    return m.extract(list(range(m.rows)), _selection(selection, m.cols))


def eig(m, vectors: bool = False):
    """EIG(M): eigenvalues (numbers), ordered by real part then imaginary part;
    with vectors=True also the unit eigenvectors as the columns of a matrix."""
    m = sm.Matrix(m)
    names = sorted(str(s) for s in m.free_symbols)
    if names:
        raise AutolevModelError("EIG needs a matrix of numbers; give values to "
                                + ", ".join(names) + " first (EVALUATE)")
    import numpy as np      # here: forming a model needs no numpy
    a = np.array(m.evalf(), dtype=complex)
    if a.ndim != 2 or a.shape[0] != a.shape[1]:
        raise AutolevModelError("EIG needs a square matrix of numbers")
    if not np.all(np.isfinite(a)):
        raise AutolevModelError("EIG needs a matrix of numbers (substitute values first)")
    values, vecs = np.linalg.eig(a)
    order = sorted(range(len(values)), key=lambda i: (round(values[i].real, 12),
                                                      round(values[i].imag, 12)))
    vals = sm.Matrix([_number(values[i]) for i in order])
    if not vectors:
        return vals
    vm = sm.Matrix(len(values), len(values), lambda r, c: _number(vecs[r, order[c]]))
    return vals, vm


def _number(z: complex):
    if is_real_number(z):
        return sm.Float(z.real)
    return sm.Float(z.real) + sm.I * sm.Float(z.imag)


# -- algebra ----------------------------------------------------------------------------
def _map(x, fn):
    if isinstance(x, (Vector, Dyadic)):
        return x.applyfunc(fn)
    if isinstance(x, sm.MatrixBase):
        return x.applyfunc(fn)
    return fn(sm.sympify(x))


def scalar_values(mapping: dict, what: str) -> dict:
    """The substitutions of REPLACE or EVALUATE, sympified: each value is a scalar."""
    for k, v in mapping.items():
        if isinstance(v, (Vector, Dyadic, sm.MatrixBase)):
            raise AutolevModelError(f"{what}: {k} is a scalar; it cannot be replaced by a "
                                    f"{'matrix' if isinstance(v, sm.MatrixBase) else 'vector'}")
    return {sm.sympify(k): sm.sympify(v) for k, v in mapping.items()}


def replace(x, mapping: dict):
    """REPLACE(E, a=b, ...): substitute sub-expressions."""
    mapping = scalar_values(mapping, "REPLACE")

    def substituted(e):
        refuse_huge_powers(e, mapping)
        try:
            return e.subs(mapping)
        except ValueError as exc:    # sympy's refusal of a function's new argument
            raise refused_substitution(mapping, exc) from None
    return _map(x, substituted)


def expand(x, lo=None, hi=None):
    """EXPAND(E) or EXPAND(E, n:m)."""
    return _map(x, sm.expand)


def factor(x, *vars_):
    if vars_:
        return _map(x, lambda e: sm.collect(sm.expand(e, deep=False), list(vars_)))
    return _map(x, sm.factor)


def simplify(x):
    return _map(x, sm.simplify)


def arrange(x, n, var):
    """ARRANGE(E, n, x): E collected in powers of x."""
    return _map(x, lambda e: sm.collect(sm.expand(e), var))


def polynomial(coeffs, var, degree=None):
    """POLYNOMIAL([a, b, c], x) = a*x^2 + b*x + c; POLYNOMIAL(E, x, n) is the row of
    the coefficients of E in x, from x^n down to x^0 (the inverse)."""
    if degree is not None:
        e = sm.expand(sm.sympify(coeffs))
        n = whole_number(degree, "POLYNOMIAL's degree")
        return sm.Matrix([[e.coeff(var, k) if k else e.subs(var, 0)
                           for k in range(n, -1, -1)]])
    if not isinstance(coeffs, (list, tuple, sm.MatrixBase)):
        raise AutolevModelError("POLYNOMIAL takes a list of coefficients and a variable")
    c = list(sm.Matrix(coeffs))
    n = len(c) - 1
    return sm.Add(*[ci * var ** (n - i) for i, ci in enumerate(c)])


def roots(p, var=None, degree=None):
    """ROOTS([c...]) of the polynomial with those coefficients (highest first), or
    ROOTS(P, x, n) of a polynomial expression in x.  Numbers when the coefficients are
    numbers (ordered by real, then imaginary part); the closed forms otherwise, up to
    degree 2."""
    if var is None:
        coeffs = list(sm.Matrix(p))
    else:
        try:
            coeffs = sm.Poly(sm.expand(p), var).all_coeffs()
        except sm.PolynomialError:
            raise AutolevModelError(f"ROOTS: {p} is not a polynomial in {var}") from None
    if all(sm.sympify(c).is_number for c in coeffs):
        import numpy as np
        r = np.roots([complex(sm.N(c)) for c in coeffs])
        order = sorted(range(len(r)), key=lambda i: (round(r[i].real, 12),
                                                     round(r[i].imag, 12)))
        return sm.Matrix([_number(r[i]) for i in order])
    if len(coeffs) == 2:
        return sm.Matrix([-coeffs[1] / coeffs[0]])
    if len(coeffs) == 3:
        a, b, c = coeffs
        d = sm.sqrt(b ** 2 - 4 * a * c)
        return sm.Matrix([(-b - d) / (2 * a), (-b + d) / (2 * a)])
    raise AutolevModelError("ROOTS of a polynomial with symbolic coefficients is only "
                            "available up to degree 2; substitute numbers first")


def epsilon(x, tol):
    """EPSILON(E, tol): numbers smaller than tol in magnitude become 0."""
    try:
        tol = float(tol)
    except TypeError:                # a symbol or expression: not a number
        raise AutolevModelError(f"EPSILON's tolerance must be a number, not {tol}") from None

    def clean(e):
        return e.xreplace({f: 0 for f in e.atoms(sm.Float) if abs(float(f)) < tol})
    return _map(x, clean)


def integer_part(x):
    """INT(x): x truncated toward zero."""
    return Int(sm.sympify(x))


def round_half_away(x):
    """ROUND(x): nearest integer, halves away from zero."""
    return Round(sm.sympify(x))


def degrees_to_radians(x):
    return sm.sympify(x) * sm.pi / 180


# -- units ----------------------------------------------------------------------------------
# one unit: its value in SI base units (exact where the definition is exact) and its
# dimension as exponents of (length, mass, time, angle)
_LBF = sm.Rational(44482216152605, 10**13)        # 0.45359237 kg * 9.80665 m/s^2
_FT = sm.Rational(3048, 10000)
_L, _M, _T, _A = (1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1)
_FORCE, _ENERGY, _POWER = (1, 1, -2, 0), (2, 1, -2, 0), (2, 1, -3, 0)


def _units(names: str, value, dim) -> dict:
    return {n: (sm.sympify(value), dim) for n in names.split()}


_UNITS = {
    **_units("rad radian radians", 1, _A),
    **_units("deg degree degrees degs", sm.pi / 180, _A),
    **_units("rev revs revolution revolutions", 2 * sm.pi, _A),
    **_units("rpm", 2 * sm.pi / 60, (0, 0, -1, 1)),
    **_units("m meter meters metre metres", 1, _L),
    **_units("cm", sm.Rational(1, 100), _L), **_units("mm", sm.Rational(1, 1000), _L),
    **_units("km", 1000, _L), **_units("in inch inches", sm.Rational(254, 10000), _L),
    **_units("ft foot feet", _FT, _L), **_units("mile miles", sm.Rational(1609344, 1000), _L),
    **_units("s sec secs second seconds", 1, _T), **_units("ms", sm.Rational(1, 1000), _T),
    **_units("min minute minutes", 60, _T), **_units("hr hour hours", 3600, _T),
    **_units("kg kilogram kilograms", 1, _M), **_units("g gram grams", sm.Rational(1, 1000), _M),
    **_units("lbm", sm.Rational(45359237, 100000000), _M),
    **_units("slug slugs", _LBF / _FT, _M),             # lbf*s^2/ft, exactly
    **_units("n newton newtons", 1, _FORCE), **_units("lbf", _LBF, _FORCE),
    **_units("kip", _LBF * 1000, _FORCE),
    **_units("j joule joules", 1, _ENERGY), **_units("w watt watts", 1, _POWER),
}


def _unit(text: str):
    """(value in SI, dimension) of a unit expression (`n*m`, `lbf*ft`, `rad/sec^2`)."""
    tokens = re.findall(r"[A-Za-z_]+|\d+(?:\.\d*)?|[*/^.]", text)
    value, dim = sm.S.One, [0, 0, 0, 0]
    op = "*"
    i = 0
    while i < len(tokens):
        tok = tokens[i]
        if tok in "*/.":
            op = "/" if tok == "/" else "*"
            i += 1
            continue
        if tok[0].isdigit():
            factor, fdim = sm.nsimplify(tok), (0, 0, 0, 0)
        else:
            entry = _UNITS.get(tok.lower())
            if entry is None:
                raise AutolevModelError(f"unknown unit '{tok}' in {text}")
            factor, fdim = entry
        power = 1
        if i + 2 < len(tokens) and tokens[i + 1] == "^":
            power = int(tokens[i + 2])
            i += 2
        sign = 1 if op == "*" else -1
        value = value * factor ** (sign * power)
        dim = [d + sign * power * e for d, e in zip(dim, fdim)]
        i += 1
    return value, tuple(dim)


def unit_value(text: str):
    """Value of a unit expression in SI base units."""
    return _unit(text)[0]


def units_factor(a: str, b: str):
    """UNITS(a, b): the number of b in one a (UNITS(deg, rad) = pi/180); a and b must
    measure the same kind of quantity."""
    va, da = _unit(a)
    vb, db = _unit(b)
    if da != db:
        raise AutolevModelError(f"UNITS({a}, {b}): {a} and {b} do not measure the same "
                                "kind of quantity")
    return va / vb


__all__ = ["ZERO", "VectorColumn", "dot", "cross", "mag", "unitvec", "express", "vector",
           "matrix", "dyadic", "outer", "set_element", "block_matrix", "transpose", "trace",
           "diagmat", "rows", "cols", "eig", "replace", "expand", "factor", "simplify",
           "arrange", "polynomial", "roots", "epsilon", "maximum", "minimum", "integer_part",
           "round_half_away", "Int", "Round", "degrees_to_radians", "unit_value",
           "units_factor"]
