"""Vectors and dyadics with Autolev's semantics.

The API follows sympy.physics.vector (`v.dot(w)`, `v.express(A)`, `v.dt(N)`), but
measure numbers are kept small: whatever a product of direction cosines or a
derivative would expand into is named by a Z in the model's definitions table.
`to_sympy()` gives the plain sympy.physics.vector objects when they are wanted.  The
frames whose unit vectors they are, and their orientations, are frame.py's.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

import sympy as sm

from ..engine.errors import AutolevModelError
from .fastdiff import sum_of_products
from .interop import to_sympy_vector

if TYPE_CHECKING:
    from .frame import Frame


_ZERO = sm.S.Zero
_ZERO3 = (_ZERO, _ZERO, _ZERO)


def _s(x) -> sm.Expr:
    return x if isinstance(x, sm.Basic) else sm.sympify(x)


def row_times(m, i: int, comps) -> sm.Expr:
    """Row i of the 3x3 matrix m times the measure numbers `comps`, as sympy sums it."""
    return sum_of_products(zip((m[i, 0], m[i, 1], m[i, 2]), comps))


def matrix_times(m, comps) -> tuple:
    """The 3x3 matrix m times the column of measure numbers `comps`."""
    return tuple(row_times(m, i, comps) for i in range(3))


def _difference(a: sm.Expr, b: sm.Expr) -> sm.Expr:
    """a - b as sympy's subtraction makes it (a + (-b)), a zero side costing nothing."""
    if b is _ZERO:
        return a
    return -b if a is _ZERO else sm.Add(a, -b)


# ---------------------------------------------------------------------------
class Vector:
    """A vector as measure numbers in one or more frames: {frame: (x1, x2, x3)}."""

    __slots__ = ("terms",)
    is_vector = True

    def __init__(self, terms: dict | None = None):
        clean = {}
        for frame, comps in (terms or {}).items():
            comps = tuple(_s(c) for c in comps)
            if any(c != 0 for c in comps):
                clean[frame] = comps
        self.terms: dict[Frame, tuple] = clean

    # -- arithmetic ---------------------------------------------------------------
    def __add__(self, other):
        if isinstance(other, (int, float)) and other == 0 or (
                isinstance(other, sm.Basic) and other == 0):
            return self
        if not isinstance(other, Vector):
            return NotImplemented
        terms = dict(self.terms)
        for f, c in other.terms.items():
            if f in terms:
                a = terms[f]
                terms[f] = (a[0] + c[0], a[1] + c[1], a[2] + c[2])
            else:
                terms[f] = c
        return Vector(terms)

    __radd__ = __add__

    def __neg__(self):
        return Vector({f: (-c[0], -c[1], -c[2]) for f, c in self.terms.items()})

    def __sub__(self, other):
        if isinstance(other, Vector):
            return self + (-other)
        if other == 0:
            return self
        return NotImplemented

    def __rsub__(self, other):
        if other == 0:
            return -self
        return NotImplemented

    def __mul__(self, other):
        if isinstance(other, Vector):           # Autolev: V>*W> is the dyadic V>W>
            return outer(self, other)
        if isinstance(other, Dyadic):
            return NotImplemented
        try:
            k = sm.sympify(other)
        except (sm.SympifyError, TypeError):
            return NotImplemented
        if not isinstance(k, sm.Expr):
            return NotImplemented
        return Vector({f: (k * c[0], k * c[1], k * c[2]) for f, c in self.terms.items()})

    def __rmul__(self, other):
        return self.__mul__(other)

    def __truediv__(self, other):
        k = sm.sympify(other)
        return self * (1 / k)

    def __eq__(self, other):
        if isinstance(other, Vector):
            return (self - other).is_zero_structurally()
        if other == 0:
            return self.is_zero_structurally()
        return NotImplemented

    def is_zero_structurally(self) -> bool:
        return not self.terms

    # -- products -----------------------------------------------------------------
    def dot(self, other):
        if isinstance(other, Dyadic):
            return other.rdot(self)
        if not isinstance(other, Vector):
            raise TypeError(f"DOT needs vectors, got {type(other).__name__}")
        total = []
        for fa, a in self.terms.items():
            for fb, b in other.terms.items():
                if fa is fb:
                    total.append(sum_of_products(zip(a, b)))
                else:
                    c = fa.dcm(fb)
                    for i in range(3):
                        if a[i] == 0:
                            continue
                        total.append(a[i] * row_times(c, i, b))
        return sm.Add(*total)

    def cross(self, other):
        if isinstance(other, Dyadic):
            return other.rcross(self)
        if not isinstance(other, Vector):
            raise TypeError(f"CROSS needs vectors, got {type(other).__name__}")
        out: dict = {}
        for fa, a in self.terms.items():
            for fb, b in other.terms.items():
                bb = b if fa is fb else fa.express_components(fb, b)
                c = tuple(_difference(sum_of_products(((a[j], bb[k]),)),
                                      sum_of_products(((a[k], bb[j]),)))
                          for j, k in ((1, 2), (2, 0), (0, 1)))
                prev = out.get(fa, _ZERO3)
                out[fa] = (prev[0] + c[0], prev[1] + c[1], prev[2] + c[2])
        return Vector(out).zified()

    def outer(self, other):
        return outer(self, other)

    # -- frames -----------------------------------------------------------------
    def frames(self) -> list["Frame"]:
        return list(self.terms)

    def express(self, frame: "Frame") -> "Vector":
        """The same vector with measure numbers in `frame` only."""
        total = _ZERO3
        for f, c in self.terms.items():
            cc = c if f is frame else frame.express_components(f, c)
            total = (total[0] + cc[0], total[1] + cc[1], total[2] + cc[2])
        return Vector({frame: total}).zified()

    def components_in(self, frame: "Frame") -> tuple:
        """Measure numbers in `frame`, not named by Z's (used inside products)."""
        total = _ZERO3
        for f, c in self.terms.items():
            cc = c if f is frame else frame.express_components(f, c)
            total = (total[0] + cc[0], total[1] + cc[1], total[2] + cc[2])
        return total

    def to_matrix(self, frame: "Frame") -> sm.Matrix:
        comps = self.express(frame).terms.get(frame, _ZERO3)
        return sm.Matrix(comps)

    def components(self, frame: "Frame") -> tuple:
        return self.express(frame).terms.get(frame, _ZERO3)

    def zified(self) -> "Vector":
        defs = self.definitions()
        if defs is None:
            return self
        return Vector({f: tuple(defs.zify(x) for x in c) for f, c in self.terms.items()})

    def definitions(self):
        """The Definitions of the model its frames belong to (None for 0>)."""
        for f in self.terms:
            return f.scene.defs
        return None

    def applyfunc(self, fn) -> "Vector":
        return Vector({f: tuple(fn(x) for x in c) for f, c in self.terms.items()})

    # -- calculus ---------------------------------------------------------------
    def dt(self, frame: "Frame") -> "Vector":
        """Time derivative in `frame`: measure numbers differentiated in their own
        frames, plus W_F_frame x (the part in F) for every other frame F."""
        out = Vector()
        for f, c in self.terms.items():
            defs = f.scene.defs
            part = Vector({f: tuple(defs.dt(x) for x in c)})
            if f is not frame:
                w = f.ang_vel_in(frame)
                if w.terms:
                    part = part + w.cross(Vector({f: c}))
            out = out + part
        return out.zified()

    def diff(self, var, frame: "Frame") -> "Vector":
        """Partial derivative with respect to `var` in `frame` (through definitions)."""
        out = Vector()
        for f, c in self.terms.items():
            defs = f.scene.defs
            if f is not frame and any(defs.depends_on(e, var)
                                      for e in frame.dcm(f) if e != 0):
                c = frame.express_components(f, c)
                f = frame
            out = out + Vector({f: tuple(defs.diff(x, var) for x in c)})
        return out.zified()

    def magnitude(self):
        return sm.sqrt(self.dot(self))

    def normalize(self):
        return self / self.magnitude()

    def subs(self, *args, **kw) -> "Vector":
        return self.applyfunc(lambda e: e.subs(*args, **kw))

    def xreplace(self, mapping) -> "Vector":
        return self.applyfunc(lambda e: e.xreplace(mapping))

    # -- display ----------------------------------------------------------------
    def __repr__(self) -> str:
        if not self.terms:
            return "0>"
        parts = []
        for f, c in self.terms.items():
            for i, x in enumerate(c):
                if x == 0:
                    continue
                parts.append(f"{sm.sstr(x) if x != 1 else ''}{'*' if x != 1 else ''}"
                             f"{f.name}{i + 1}>")
        return " + ".join(parts)

    __str__ = __repr__

    def to_sympy(self, frames: dict | None = None):
        """sympy.physics.vector.Vector (frames mapped by `frames`, else made)."""
        return to_sympy_vector(self, frames)



def outer(a: Vector, b: Vector) -> "Dyadic":
    terms: dict = {}
    for fa, ca in a.terms.items():
        for fb, cb in b.terms.items():
            m = sm.Matrix(3, 3, lambda i, j: ca[i] * cb[j])
            key = (fa, fb)
            terms[key] = terms[key] + m if key in terms else m
    return Dyadic(terms)


# ---------------------------------------------------------------------------
class Dyadic:
    """A dyadic as 3x3 blocks between frame pairs: {(A, B): M} means sum M_ij ai bj."""

    __slots__ = ("terms",)
    is_vector = False

    def __init__(self, terms: dict | None = None):
        self.terms: dict[tuple[Frame, Frame], sm.Matrix] = {
            k: sm.Matrix(v) for k, v in (terms or {}).items() if any(x != 0 for x in v)}

    def __add__(self, other):
        if isinstance(other, (int, float)) and other == 0:
            return self
        if not isinstance(other, Dyadic):
            return NotImplemented
        terms = dict(self.terms)
        for k, m in other.terms.items():
            terms[k] = terms[k] + m if k in terms else m
        return Dyadic(terms)

    __radd__ = __add__

    def __neg__(self):
        return Dyadic({k: -m for k, m in self.terms.items()})

    def __sub__(self, other):
        return self + (-other)

    def __mul__(self, other):
        k = sm.sympify(other)
        return Dyadic({key: k * m for key, m in self.terms.items()})

    __rmul__ = __mul__

    def __truediv__(self, other):
        return self * (1 / sm.sympify(other))

    def dot(self, other):
        """D . v  (a vector) or D . E (a dyadic)."""
        if isinstance(other, Vector):
            out = Vector()
            for (fa, fb), m in self.terms.items():
                out = out + Vector({fa: matrix_times(m, other.components_in(fb))})
            return out.zified()
        if isinstance(other, Dyadic):
            out = Dyadic()
            for (fa, fb), m in self.terms.items():
                for (fc, fd), n in other.terms.items():
                    c = fb.dcm(fc)
                    out = out + Dyadic({(fa, fd): m * c * n})
            return out
        raise TypeError(f"cannot dot a dyadic with {type(other).__name__}")

    def rdot(self, v: Vector) -> Vector:
        """v . D"""
        out = Vector()
        for (fa, fb), m in self.terms.items():
            a = v.components_in(fa)
            out = out + Vector({fb: tuple(sum_of_products(zip(a, (m[0, j], m[1, j], m[2, j])))
                                          for j in range(3))})
        return out.zified()

    def cross(self, v: Vector) -> "Dyadic":
        """D x v: each ai (bj x v)."""
        out = Dyadic()
        for (fa, fb), m in self.terms.items():
            for j in range(3):
                bxv = fb[j + 1].cross(v)
                for i in range(3):
                    if m[i, j] != 0:
                        out = out + m[i, j] * outer(fa[i + 1], bxv)
        return out

    def rcross(self, v: Vector) -> "Dyadic":
        """v x D: each (v x ai) bj."""
        out = Dyadic()
        for (fa, fb), m in self.terms.items():
            for i in range(3):
                vxa = v.cross(fa[i + 1])
                for j in range(3):
                    if m[i, j] != 0:
                        out = out + m[i, j] * outer(vxa, fb[j + 1])
        return out

    def express(self, a: "Frame", b: "Frame | None" = None) -> "Dyadic":
        b = b or a
        total = sm.zeros(3, 3)
        for (fa, fb), m in self.terms.items():
            total += a.dcm(fa) * m * fb.dcm(b)
        defs = a.scene.defs
        return Dyadic({(a, b): total.applyfunc(defs.zify)})

    def to_matrix(self, a: "Frame", b: "Frame | None" = None) -> sm.Matrix:
        d = self.express(a, b)
        return next(iter(d.terms.values()), sm.zeros(3, 3))

    def dt(self, frame: "Frame") -> "Dyadic":
        out = Dyadic()
        for (fa, fb), m in self.terms.items():
            defs = fa.scene.defs
            out = out + Dyadic({(fa, fb): m.applyfunc(defs.dt)})
            if fa is not frame:
                w = fa.ang_vel_in(frame)
                out = out + self._block(fa, fb, m).rcross(w)
            if fb is not frame:
                w = fb.ang_vel_in(frame)
                out = out + self._block(fa, fb, m).cross(w)
        return out

    @staticmethod
    def _block(fa, fb, m) -> "Dyadic":
        return Dyadic({(fa, fb): m})

    def applyfunc(self, fn) -> "Dyadic":
        return Dyadic({k: m.applyfunc(fn) for k, m in self.terms.items()})

    def __repr__(self) -> str:
        if not self.terms:
            return "0>>"
        parts = []
        for (fa, fb), m in self.terms.items():
            for i in range(3):
                for j in range(3):
                    x = m[i, j]
                    if x != 0:
                        parts.append(f"{sm.sstr(x)}*{fa.name}{i + 1}>*{fb.name}{j + 1}>")
        return " + ".join(parts)

    __str__ = __repr__



class UnitDyadic(Dyadic):
    """1>>: dotting leaves a vector unchanged, and in any frame it is the identity."""

    def __init__(self, frame: "Frame"):
        super().__init__({(frame, frame): sm.eye(3)})
        self.frame = frame

    def dot(self, other):
        if isinstance(other, (Vector, Dyadic)):
            return other
        return super().dot(other)

    def rdot(self, v: Vector) -> Vector:
        return v

    def express(self, a: "Frame", b: "Frame | None" = None) -> Dyadic:
        if b is None or b is a:
            return Dyadic({(a, a): sm.eye(3)})
        return super().express(a, b)

    def dt(self, frame: "Frame") -> Dyadic:
        return Dyadic()


def _vector(value) -> Vector:
    if isinstance(value, Vector):
        return value
    if value == 0:
        return Vector()
    raise AutolevModelError(f"a vector is needed here, not {value!r}")
