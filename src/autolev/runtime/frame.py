"""Reference frames: their orientations and angular velocities, with Autolev's semantics.

The API follows sympy.physics.vector (`A.orient_axis(N, N.z, q)`, `A.dcm(N)`,
`A.ang_vel_in(N)`).  Frames are linked by orientation edges (SIMPROT, DIRCOS, A_B = M)
into an undirected graph, as Autolev allowed (`SIMPROT(N,G,..)` and `SIMPROT(D,G,..)`
in one model); angular velocities are edges too, implied by each orientation or set by
the user, who overrides the implied one (Autolev: an explicit W_B_A> wins).  The
direction cosines and angular velocities of rotation sequences (BODYijk, SPACEijk,
EULER, RODRIGUES) are functions of their angles here as well.
"""
from __future__ import annotations

from collections import deque
from dataclasses import dataclass, field
from typing import Callable

import sympy as sm
from sympy.polys.matrices import DomainMatrix
from sympy.polys.matrices.sdm import SDM

from .calculus import Definitions
from .derived import DerivedCache, Revision, mutation
from ..engine.errors import AutolevModelError
from .fastdiff import times
from .interop import to_sympy_frame
from .vectors import Vector, _s, _vector, matrix_times


@dataclass(eq=False)
class Scene:
    """What the frames and points of one model share, instead of the model itself: its
    definitions, its declared symbols (`info`, for sympy's dynamicsymbols), what is
    derived from it, its points by name (`point`: made on first use), and what an
    orientation's change drops (`orientation_changed`: the direction cosines derived
    along paths)."""

    defs: Definitions
    info: dict
    derived: DerivedCache
    point: Callable
    orientation_changed: Callable
    unit_quaternions: list = field(default_factory=list)

    @property
    def revision(self) -> Revision:
        return self.derived.revision

    def note_change(self) -> None:
        """What follows each `mutation` of a frame or point: the model's revision."""
        self.revision.bump()


# -- rotations: direction cosines and angular velocities of a rotation's angles ---------
def rotation(axis: int, angle) -> sm.Matrix:
    """DCM parent_i . child_j of a rotation by `angle` about parent axis 1, 2 or 3."""
    c, s = sm.cos(angle), sm.sin(angle)
    if axis == 1:
        return sm.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])
    if axis == 2:
        return sm.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    return sm.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def axis_rotation(axis_components, angle) -> sm.Matrix:
    """DCM (parent_i . child_j) for a rotation by `angle` about a unit axis given by its
    measure numbers in the parent frame (Rodrigues)."""
    k = sm.Matrix(axis_components)
    c, s = sm.cos(angle), sm.sin(angle)
    kx = sm.Matrix([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return sm.eye(3) * c + kx * s + (1 - c) * (k * k.T)


def rodrigues(g, dt) -> tuple[sm.Matrix, tuple]:
    """(parent.dcm(child), angular velocity measure numbers in child) for Rodrigues
    parameters g = k tan(angle/2) (the Gibbs vector)."""
    g = sm.Matrix([_s(x) for x in g])
    gg = (g.T * g)[0]
    gx = sm.Matrix([[0, -g[2], g[1]], [g[2], 0, -g[0]], [-g[1], g[0], 0]])
    dcm = ((1 - gg) * sm.eye(3) + 2 * g * g.T + 2 * gx) / (1 + gg)
    gd = sm.Matrix([dt(x) for x in g])
    w = 2 * (gd - gx * gd) / (1 + gg)
    return dcm, tuple(w)


def _sequence(sequence) -> list[int]:
    seq = [int(ch) for ch in str(sequence)]
    if len(seq) != 3 or any(k not in (1, 2, 3) for k in seq) or seq[0] == seq[1] \
            or seq[1] == seq[2]:
        raise AutolevModelError(f"not a rotation sequence: {sequence}")
    return seq


def _simple_rotations(angles, sequence, dt) -> tuple[list[sm.Matrix], list[sm.Matrix]]:
    """The three simple rotation matrices of a sequence, and each angle's rate as a
    column along its own axis."""
    a = [_s(x) for x in angles]
    seq = _sequence(sequence)
    rates = []
    for i in range(3):
        rate = sm.zeros(3, 1)
        rate[seq[i] - 1] = dt(a[i])
        rates.append(rate)
    return [rotation(seq[i], a[i]) for i in range(3)], rates


def product_as_sympy(a: sm.Matrix, b: sm.Matrix) -> sm.Matrix:
    """a*b as sympy's product of symbolic matrices makes it -- each entry the sum of
    its nonzero products, the entries stored in the same order (a later walk over them
    names Z's in that order) -- without its question whether 0 times each entry is
    finite (sdm_matmul_exraw's; an orientation has no infinite entry)."""
    left, right = a._rep.unify(b._rep)
    if not left.domain.is_EXRAW or not isinstance(left.rep, SDM):
        return a * b                    # numbers: sympy's own product is cheap
    left, right = left.rep, right.rep
    columns_of_right = set(right)
    product: dict = {}
    for i, row in left.items():
        terms: dict = {}
        for k in set(row) & columns_of_right:
            for j, rkj in right[k].items():
                terms.setdefault(j, []).append(times(row[k], rkj))
        entries = {j: e for j, ts in terms.items() if (e := sm.Add(*ts)) != 0}
        if entries:
            product[i] = entries
    return type(a)._fromrep(DomainMatrix.from_rep(
        SDM(product, (a.rows, b.cols), left.domain)))


def _product(mats) -> sm.Matrix:
    result = sm.eye(3)
    for m in mats:
        result = product_as_sympy(result, m)
    return result


def body_fixed(angles, sequence, dt) -> tuple[sm.Matrix, tuple]:
    """(parent.dcm(child), angular velocity measure numbers in child) of the
    body-fixed sequence: a about parent_i, b about the new j, c about the new k."""
    mats, rates = _simple_rotations(angles, sequence, dt)
    # rate i turns about an axis fixed in the i-th intermediate frame: carry it into
    # the child through the later rotations
    w = sum((product_as_sympy(_product(mats[i + 1:]).T, rates[i]) for i in range(3)),
            sm.zeros(3, 1))
    return _product(mats), tuple(w)


def space_fixed(angles, sequence, dt) -> tuple[sm.Matrix, tuple]:
    """(parent.dcm(child), angular velocity measure numbers in parent) of the
    space-fixed sequence: a about parent_i, then b about parent_j, then c about parent_k."""
    mats, rates = _simple_rotations(angles, sequence, dt)
    # rate i turns about a parent axis, itself turned by the later rotations
    w = sum((product_as_sympy(_product(mats[:i:-1]), rates[i]) for i in range(3)),
            sm.zeros(3, 1))
    return _product(mats[::-1]), tuple(w)


def angular_velocity_in_both(angles, kind: str, dt) -> tuple[tuple, tuple]:
    """(measure numbers in child, in parent) of the angular velocity of a BODYijk or
    SPACEijk sequence, each summed from the rotations it passes (no product with the
    direction cosines to undo: a body-fixed sequence's in the parent holds the first two
    angles alone, a space-fixed one's in the child likewise the last two)."""
    sequence = kind[4:] if kind.startswith("body") else kind[5:]
    mats, rates = _simple_rotations(angles, sequence, dt)
    if kind.startswith("body"):
        child = [product_as_sympy(_product(mats[i + 1:]).T, rates[i]) for i in range(3)]
        parent = [product_as_sympy(_product(mats[:i]), rates[i]) for i in range(3)]
    else:
        child = [product_as_sympy(_product(mats[i::-1]).T, rates[i]) for i in range(3)]
        parent = [product_as_sympy(_product(mats[:i:-1]), rates[i]) for i in range(3)]
    return tuple(sum(child, sm.zeros(3, 1))), tuple(sum(parent, sm.zeros(3, 1)))


def euler_parameters(e, dt) -> tuple[sm.Matrix, tuple]:
    """(parent.dcm(child), angular velocity measure numbers in child) for Euler
    parameters e1, e2, e3 (vector part) and e4 (scalar part)."""
    e1, e2, e3, e4 = (_s(x) for x in e)
    dcm = sm.Matrix([
        [1 - 2 * (e2 ** 2 + e3 ** 2), 2 * (e1 * e2 - e3 * e4), 2 * (e3 * e1 + e2 * e4)],
        [2 * (e1 * e2 + e3 * e4), 1 - 2 * (e3 ** 2 + e1 ** 2), 2 * (e2 * e3 - e1 * e4)],
        [2 * (e3 * e1 - e2 * e4), 2 * (e2 * e3 + e1 * e4), 1 - 2 * (e1 ** 2 + e2 ** 2)]])
    d1, d2, d3, d4 = (dt(x) for x in (e1, e2, e3, e4))
    # omega in child = 2 (e4 e' - e4' e - e x e')  (e the vector part)
    w = (2 * (e4 * d1 - d4 * e1 - (e2 * d3 - e3 * d2)),
         2 * (e4 * d2 - d4 * e2 - (e3 * d1 - e1 * d3)),
         2 * (e4 * d3 - d4 * e3 - (e1 * d2 - e2 * d1)))
    return dcm, w


def euler_parameter_rates(e, w) -> tuple:
    """e1'..e4' giving the angular velocity with measure numbers w in the child frame
    (inverse of the relation above, using e1^2+e2^2+e3^2+e4^2 = 1)."""
    e1, e2, e3, e4 = e
    w1, w2, w3 = w
    half = sm.Rational(1, 2)
    return (half * (e4 * w1 - e3 * w2 + e2 * w3),
            half * (e3 * w1 + e4 * w2 - e1 * w3),
            half * (-e2 * w1 + e1 * w2 + e4 * w3),
            -half * (e1 * w1 + e2 * w2 + e3 * w3))


# -- frames ------------------------------------------------------------------------------
class Frame:
    """A reference frame (Autolev FRAMES, NEWTONIAN, and the frame of a body)."""

    def __init__(self, name: str, scene: Scene):
        self.name = name
        self.scene = scene
        self._dcm_edges: dict[Frame, sm.Matrix] = {}   # other -> self.dcm(other)
        self._w_edges: dict[Frame, Vector] = {}        # other -> W_self_other
        self._w_user: set[Frame] = set()
        self._alf_user: dict[Frame, Vector] = {}
        self._dcm_cache: dict[Frame, sm.Matrix] = {}
        self._origin = None
        self.x = Vector({self: (1, 0, 0)})
        self.y = Vector({self: (0, 1, 0)})
        self.z = Vector({self: (0, 0, 1)})

    def __repr__(self) -> str:
        return self.name

    def __getitem__(self, i: int) -> Vector:
        """N[1], N[2], N[3]: Autolev's N1>, N2>, N3>."""
        return (self.x, self.y, self.z)[i - 1]

    def unit(self, i: int) -> Vector:
        return self[i]

    @property
    def origin(self):
        """AO: the point every frame A has (NO of a Newtonian frame, BO of a body), fixed
        in A; made when first asked for."""
        if self._origin is None:
            self._origin = self.scene.point(self.name + "O")
        return self._origin

    @origin.setter
    @mutation
    def origin(self, point) -> None:
        self._origin = point

    @property
    def declared_origin(self):
        """AO if the model has it, else None (asking for `origin` would make it)."""
        return self._origin

    def forget_derived(self) -> None:
        """Drop the direction cosines derived along paths (an orientation changed)."""
        self._dcm_cache.clear()

    def note_change(self) -> None:
        self.scene.note_change()

    # -- orientation ------------------------------------------------------------------
    @mutation
    def orient_dcm(self, parent: "Frame", dcm, ang_vel: Vector | None = None) -> None:
        """Orient self relative to parent with parent.dcm(self) == dcm (Autolev's
        PARENT_SELF = [...]).  The implied angular velocity is ang_vel if given,
        else derived from the DCM when first needed."""
        if parent is self:
            raise AutolevModelError(f"cannot orient frame {self.name} relative to itself")
        dcm = sm.Matrix(dcm)
        if dcm.shape != (3, 3):
            raise AutolevModelError(f"a direction cosine matrix is 3x3, not {dcm.shape}")
        self._dcm_edges[parent] = dcm.T
        parent._dcm_edges[self] = dcm
        self.scene.orientation_changed()
        if parent not in self._w_user:
            w = ang_vel if ang_vel is not None else _DerivedAngVel(parent, self)
            self._w_edges[parent] = w
            parent._w_edges[self] = -w if isinstance(w, Vector) else _Negated(w)

    def orient_axis(self, parent: "Frame", axis, angle) -> None:
        """SIMPROT(parent, self, axis, angle): self is parent turned by angle about axis
        (1, 2, 3, negative for the opposite direction, or a vector)."""
        angle = _s(angle)
        if angle.has(sm.zoo, sm.oo, sm.nan):
            raise AutolevModelError(f"SIMPROT: the angle is infinite or undefined ({angle})")
        if isinstance(axis, Vector):
            comps = axis.components_in(parent)
            norm = sm.sqrt(sum(c ** 2 for c in comps))
            unit = tuple(c / norm for c in comps) if norm != 1 else comps
            dcm = axis_rotation(unit, angle)
            rate = self.scene.defs.dt_raw(angle)
            w = Vector({parent: tuple(rate * u for u in unit)})
        else:
            k = int(axis)
            if k not in (1, 2, 3, -1, -2, -3):
                raise AutolevModelError(f"SIMPROT axis must be 1, 2, 3 (or negative), not {k}")
            if k < 0:
                angle = -angle
            dcm = rotation(abs(k), angle)
            comps = [0, 0, 0]
            comps[abs(k) - 1] = self.scene.defs.dt_raw(angle)
            w = Vector({parent: tuple(comps)})
        self.orient_dcm(parent, dcm, w)

    def orient_body_fixed(self, parent: "Frame", angles, sequence: str) -> None:
        """DIRCOS(parent, self, BODYijk, a, b, c)."""
        dcm, w = body_fixed(angles, sequence, self.scene.defs.dt_raw)
        self.orient_dcm(parent, dcm, Vector({self: w}))

    def orient_space_fixed(self, parent: "Frame", angles, sequence: str) -> None:
        """DIRCOS(parent, self, SPACEijk, a, b, c): rotations about parent-fixed axes."""
        dcm, w = space_fixed(angles, sequence, self.scene.defs.dt_raw)
        self.orient_dcm(parent, dcm, Vector({parent: w}))

    def orient_rodrigues(self, parent: "Frame", g1, g2, g3) -> None:
        """DIRCOS(parent, self, RODRIGUES, g1, g2, g3): Rodrigues parameters."""
        dcm, w = rodrigues((g1, g2, g3), self.scene.defs.dt_raw)
        self.orient_dcm(parent, dcm, Vector({self: w}))

    @mutation
    def orient_euler_parameters(self, parent: "Frame", e1, e2, e3, e4) -> None:
        """DIRCOS(parent, self, EULER, e1, e2, e3, e4) with e4 the scalar part."""
        dcm, w = euler_parameters((e1, e2, e3, e4), self.scene.defs.dt_raw)
        self.orient_dcm(parent, dcm, Vector({self: w}))
        # a unit quaternion: numeric checks give the four values unit length, else the
        # direction cosines are not orthogonal there
        self.scene.unit_quaternions.append(tuple(_s(e) for e in (e1, e2, e3, e4)))

    def _path(self, other: "Frame", edges_of) -> list["Frame"] | None:
        """Shortest path self -> other through the given edge dictionaries."""
        if other is self:
            return [self]
        prev = {self: None}
        queue = deque([self])
        while queue:
            f = queue.popleft()
            for g in edges_of(f):
                if g not in prev:
                    prev[g] = f
                    if g is other:
                        path = [g]
                        while prev[path[-1]] is not None:
                            path.append(prev[path[-1]])
                        return path[::-1]
                    queue.append(g)
        return None

    def dcm(self, other: "Frame") -> sm.Matrix:
        """self.dcm(other)[i, j] = self_i . other_j (Autolev's SELF_OTHER)."""
        if other is self:
            return sm.eye(3)
        cached = self._dcm_cache.get(other)
        if cached is not None:
            return cached
        path = self._path(other, lambda f: f._dcm_edges)
        if path is None:
            raise AutolevModelError(
                f"the orientation of {other.name} relative to {self.name} is not defined "
                "(SIMPROT, DIRCOS or an assigned direction cosine matrix links frames)")
        m = self._dcm_edges[path[1]]
        if len(path) > 2:
            rest = path[1].dcm(other)
            zify = self.scene.defs.zify
            # a product of Z's: an orientation's long entries (RODRIGUES', a body-fixed
            # sequence's) named once, not written into each entry of every product
            m = product_as_sympy(m.applyfunc(zify), rest.applyfunc(zify)).applyfunc(zify)
        self._dcm_cache[other] = m
        other._dcm_cache[self] = m.T
        return m

    def express_components(self, frame: "Frame", comps) -> tuple:
        """Measure numbers in self of the vector with measure numbers comps in frame."""
        return matrix_times(self.dcm(frame), comps)

    def orientation_known(self, other: "Frame") -> bool:
        return other is self or self._path(other, lambda f: f._dcm_edges) is not None

    # -- angular velocity and acceleration --------------------------------------------
    @mutation
    def set_ang_vel(self, other: "Frame", value) -> None:
        """W_self_other> = value (overrides what the orientation implies)."""
        value = _vector(value)
        self._w_edges[other] = value
        other._w_edges[self] = -value
        self._w_user.add(other)
        other._w_user.add(self)

    def oriented_neighbours(self) -> list["Frame"]:
        """The frames whose orientation relative to this one the model gave directly."""
        return list(self._dcm_edges)

    def ang_vel_assigned(self, other: "Frame") -> bool:
        """Whether the model assigned W_self_other> (or W_other_self>) itself."""
        return other in self._w_user

    def _w_edge(self, other: "Frame") -> Vector:
        w = self._w_edges[other]
        if not isinstance(w, Vector):
            w = w.value()
            self._w_edges[other] = w
            other._w_edges[self] = -w
        return w

    def ang_vel_in(self, other: "Frame") -> Vector:
        """W_self_other>: the sum of angular velocities along the frames linking them."""
        if other is self:
            return Vector()
        path = self._path(other, lambda f: f._w_edges)
        if path is None:
            raise AutolevModelError(
                f"the angular velocity of {self.name} in {other.name} is not defined")
        total = Vector()
        for a, b in zip(path, path[1:]):
            total = total + a._w_edge(b)
        return total

    @mutation
    def set_ang_acc(self, other: "Frame", value) -> None:
        self._alf_user[other] = _vector(value)
        other._alf_user[self] = -_vector(value)

    def ang_acc_in(self, other: "Frame") -> Vector:
        """ALF_self_other>, as Autolev forms it: assigned, or composed when ALF of self
        relative to the next frame towards `other` was assigned (ALF_C_A> = ALF_B_A> +
        ALF_C_B> + W_B_A> x W_C_B>, with ALF_B_A> formed the same way), so that an
        assigned relative ALF counts exactly as given, even when it was written as a
        derivative in the wrong frame; otherwise DT(W_self_other>, other).  (Checked
        against Autolev's own bicycle programs, which match only with this rule.)"""
        if other is self:
            return Vector()
        if other in self._alf_user:
            return self._alf_user[other]
        path = self._path(other, lambda f: f._w_edges)
        if path is None or path[1] not in self._alf_user:
            return self.ang_vel_in(other).dt(other)
        chain = list(reversed(path))             # other = F0, F1, ..., self
        alf, w = Vector(), Vector()              # ALF and W of F_j in F0 (None: true ALF)
        for parent, child in zip(chain, chain[1:]):
            w_rel = child._w_edge(parent)
            a_rel = child._alf_user.get(parent)
            if a_rel is None:
                alf = None                       # not assigned: DT(W, F0) when needed
            else:
                if alf is None:
                    alf = w.dt(other)
                alf = alf + a_rel + w.cross(w_rel)
            w = w + w_rel
        return alf

    def to_sympy(self):
        return to_sympy_frame(self)


class _DerivedAngVel:
    """W_child_parent derived from an assigned DCM when first needed (Poisson)."""

    def __init__(self, parent: Frame, child: Frame):
        self.parent, self.child = parent, child

    def value(self) -> Vector:
        c = self.parent._dcm_edges[self.child]          # parent_i . child_j
        defs = self.child.scene.defs
        cd = c.applyfunc(defs.dt_raw)
        w = c.T * cd                                     # skew, in child
        return Vector({self.child: (w[2, 1], w[0, 2], w[1, 0])}).zified()


class _Negated:
    def __init__(self, inner: _DerivedAngVel):
        self.inner = inner

    def value(self) -> Vector:
        return -self.inner.value()
