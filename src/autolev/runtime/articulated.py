"""Kane's equations of a tree of bodies, solved by recursion: the articulated-body
algorithm (Featherstone, Rigid Body Dynamics Algorithms, ch. 7) in Kane's terms.

A model is a tree when every moving body has a parent (another body, or the Newtonian
frame) relative to which it moves by speeds of its own: its angular velocity relative
to the parent and the velocity of its mass centre relative to the parent's (a point
fixed in the parent) depend on no speed of the parent's ancestors.  A particle is a
body without inertia that turns with its parent (a cart carries its pendulum's bob,
a bob the next one when each link's angle is measured from N).  Then each partial
velocity of a body for an ancestor's speed is the ancestor's, carried rigidly, and
Kane's equations Fr + Fr* = 0 are those the recursion solves: a pass from the leaves
gives each body's articulated inertia (its subtree's, seen through the joints below
it), a pass from the root the accelerations.  The work grows as the number of bodies,
where forming the mass matrix grows as its n^2 entries, each a sum over the bodies
beyond both speeds; and no mass matrix is solved, so its condition does not multiply
the rounding.

Every quantity is a sympy expression in the model's Z's, in the Newtonian frame's
measure numbers, about each body's mass centre: motions are (angular, linear)
accelerations, forces (moment, force), and a speed's column of a body's partial
velocities dotted with a force gives its generalized force.  What the model says is
checked, not assumed: the recursion's velocities and accelerations of every body are
compared with the model's at random states (the model may assign velocities and
angular accelerations of its own), and a load goes to the body whose point or frame it
acts on only when that point or frame is shown to move with the body; any other load
enters through its partial velocities, as in Fr.  A model that is not such a tree is
refused (`NotATree`, with the reason), and its equations are formed as Kane's.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import sympy as sm

from . import symbols as S
from .calculus import NumericPoint
from ..engine.errors import AutolevModelError
from .frame import Frame
from .kane import System, partial_velocity
from .point import Body, Particle, Point
from .vectors import Vector

_ZERO = (sm.S.Zero,) * 3
CHECK_SEEDS = (11, 12)         # random states at which the recursion is compared
CHECK_TOLERANCE = 1e-9         # relative to the largest value compared


class NotATree(Exception):
    """The model's bodies do not form a tree of joints the recursion can solve."""


@dataclass
class _Joint:
    """One body (or particle) of the tree and the joint by which it hangs from its
    parent.  A particle turns with its parent: it has no angular velocity of its own,
    so it carries its children as a point of the parent would."""
    body: Body | Particle
    parent: int                      # index of the parent's joint; -1: the Newtonian frame
    speeds: list                     # indices of the speeds of this joint
    omega: tuple = ()                # the body's angular velocity (N measure numbers)
    offset: tuple = ()               # parent's mass centre to this one's (N)
    relative: tuple = ()             # angular velocity, then velocity of the mass
    #                                  centre, relative to the parent (N)
    bias_absolute: tuple = ()        # angular acceleration with every u' = 0 (N)
    columns: list = field(default_factory=list)   # per own speed: 6 partial velocities
    bias: tuple = ()                 # acceleration with every u' = 0, less the parent's
    #                                  carried over (angular then linear)
    inertia: tuple = ()              # central inertia (3x3, N) and mass
    applied: list = field(default_factory=lambda: [sm.S.Zero] * 6)  # moment, force

    @property
    def turns(self) -> bool:
        return isinstance(self.body, Body)

    @property
    def centre(self) -> Point:
        return self.body.masscenter if self.turns else self.body


@dataclass(frozen=True)
class Recursion:
    """The speeds' derivatives, and the pivots of each joint's factor D = L D L^T with
    the entries of D they come from.  In a tree det M is the product of the joints'
    det D, so M is singular where a pivot is 0, and a pivot small against its entry
    (a joint of several speeds near a gimbal lock) loses the accelerations as many
    digits as the ratio has."""
    rates: list
    pivots: list
    entries: list


def tree(system: System, speeds: list) -> "Tree":
    """The model's bodies as a tree of joints over `speeds` (the model's independent
    speeds; no dependent or auxiliary ones), checked; NotATree when they are not one
    the recursion solves.  Its recursions read it and change nothing in it."""
    try:
        return Tree(system, list(speeds))
    except AutolevModelError as exc:      # Kane's forming says the same, in its words
        raise NotATree(str(exc)) from None


def accelerations(system: System, speeds: list) -> Recursion:
    """The derivatives of `speeds` as Z-named expressions of the state, from the
    recursion over tree(system, speeds)."""
    return tree(system, speeds).recursion()


@dataclass(frozen=True)
class InverseDynamics:
    """Row k of M a - F for the k-th speed, and the speeds' indices from the leaves to
    the root (each joint's after its children's): eliminated in that order, a tree's M
    fills in nothing (Featherstone's L^T D L), and the pivots are the recursion's."""
    rows: list
    leaves_first: list


class Tree:
    def __init__(self, system: System, speeds: list):
        self.system, self.speeds, self.defs = system, speeds, system.defs
        self.n = system.newtonian
        self.rates = [S.derivative(u) for u in speeds]
        self.at_rest = {d: 0 for d in self.rates}
        self._rotations: dict = {self.n: sm.eye(3)}
        self._random_points: list | None = None
        self._still: list | None = None
        self._motions = [{} for _ in CHECK_SEEDS]   # per random state: each joint's numbers
        self.joints = self._joints()
        for index, joint in enumerate(self.joints):
            self._kinematics(index, joint)
        self.generalized = [sm.S.Zero] * len(speeds)     # loads not on a body's frame
        self._loads()
        self._check_rotations()

    # -- the tree ---------------------------------------------------------------------
    def _support(self, vectors) -> frozenset:
        return frozenset(r for r, u in enumerate(self.speeds)
                         if any(self.defs.depends_on(c, u)
                                for v in vectors for cs in v.terms.values() for c in cs))

    def _joints(self) -> list:
        n = self.n
        moving, supports = [], []
        for b in list(self.system.bodies) + list(self.system.particles):
            supp = self._support([v for v in _velocities_of(b, n) if v is not None])
            if supp:                          # a body no speed moves has no inertia force
                moving.append(b)
                supports.append(supp)
        order = sorted(range(len(moving)), key=lambda k: (len(supports[k]), k))
        joints, index = [], {}
        owner: dict = {}
        for k in order:
            supp = supports[k]
            below = [index[j] for j in index if supports[j] <= supp
                     and (isinstance(moving[j], Body) or not isinstance(moving[k], Body))]
            parent = max(below, key=lambda i: (len(supports[order[i]]), i), default=-1)
            if parent >= 0:
                above = supports[order[parent]]
                if any(not supports[order[i]] <= above for i in below):
                    raise NotATree(f"{moving[k].name} moves with two branches")
            own = sorted(supp - (supports[order[parent]] if parent >= 0 else frozenset()))
            for r in own:
                if r in owner:
                    raise NotATree(f"{self.speeds[r]} moves {owner[r]} and {moving[k].name}"
                                   " on separate branches")
                owner[r] = moving[k].name
            index[k] = len(joints)
            joints.append(_Joint(moving[k], parent, own))
        missing = [str(u) for r, u in enumerate(self.speeds) if r not in owner]
        if missing:
            raise NotATree(f"no body moves with {', '.join(missing)}")
        return joints

    # -- measure numbers in N ------------------------------------------------------------
    def _rotation(self, frame: Frame) -> sm.Matrix:
        """N's measure numbers from frame's: through the nearest frame already placed
        (a body's parent, placed before it), so each body costs one product."""
        known = self._rotations.get(frame)
        if known is not None:
            return known
        placed = _nearest(frame, self._rotations)
        if placed is None:
            raise NotATree(f"the orientation of {frame.name} in {self.n.name} is not defined")
        m = (self._rotations[placed] * placed.dcm(frame)).applyfunc(self.defs.zify)
        self._rotations[frame] = m
        return m

    def _in_n(self, v: Vector) -> tuple:
        total = [sm.S.Zero] * 3
        for f, c in v.terms.items():
            r = self._rotation(f)
            for i in range(3):
                total[i] += r[i, 0] * c[0] + r[i, 1] * c[1] + r[i, 2] * c[2]
        return tuple(self.defs.zify(x) for x in total)

    def _at_rest(self, comps) -> tuple:
        return tuple(self.defs.zify(self.defs.substitute(c, self.at_rest)) for c in comps)

    # -- each body's joint ---------------------------------------------------------------
    def _kinematics(self, index: int, joint: _Joint) -> None:
        """The joint's quantities in N, the first way whose motions of the body are the
        model's at random states: relative to the parent as the joint moves it (the
        derivatives, in the parent's frame, of the offset and of the relative angular
        velocity: a few terms a joint), else the model's velocities and accelerations
        less the parent's (whatever the model assigned, with whatever its vectors
        carry from the joints above)."""
        ways = (self._absolute,) if joint.parent < 0 else (self._relative,
                                                             self._differences)
        for way in ways:
            w_rel, v_rel, c_ang, c_lin, offset = way(joint)
            self._take(joint, w_rel, v_rel, c_ang, c_lin, offset)
            wrong = self._disagreement(index, joint)
            if wrong is None:
                return
        raise NotATree(f"the {wrong} of {joint.body.name} is not the one its parent's "
                       "and its joint's give")

    def _absolute(self, joint: _Joint) -> tuple:
        w, v, alpha, accel = (self._in_n(x) if x is not None else _ZERO
                              for x in _motion_of(joint.body, self.n))
        return w, v, self._at_rest(alpha), self._at_rest(accel), _ZERO

    def _relative(self, joint: _Joint) -> tuple:
        """The relative angular velocity and the offset from the parent's mass centre,
        in N by the tree's own rotations, differentiated in N through the definitions
        (each rotation's derivative once, from its parent's): the parent's frame's
        derivatives are these less the parent's turning."""
        b, p = joint.body, self.joints[joint.parent]
        dt = self.defs.dt
        w_n = self._in_n(b.ang_vel_in(p.body)) if joint.turns else _ZERO
        offset = self._in_n(joint.centre.pos_from(p.centre))
        rate = tuple(dt(x) for x in offset)
        v_rel = _add(rate, _cross(offset, p.omega))
        c_ang = self._at_rest(tuple(dt(x) for x in w_n))
        c_lin = _add(self._at_rest(tuple(dt(x) for x in rate)),
                     _cross(offset, p.bias_absolute))
        return w_n, v_rel, c_ang, c_lin, offset

    def _differences(self, joint: _Joint) -> tuple:
        b, p = joint.body, self.joints[joint.parent]
        offset = self._in_n(joint.centre.pos_from(p.centre))
        w, v, alpha, accel = (self._in_n(x - y) if x is not None else _ZERO
                              for x, y in zip(_motion_of(b, self.n), _motion_of(p.body, self.n)))
        v_rel = _add(v, _cross(offset, p.omega))
        c_lin = _add(self._at_rest(accel), _cross(offset, p.bias_absolute))
        return w, v_rel, self._at_rest(alpha), c_lin, offset

    def _take(self, joint: _Joint, w_rel, v_rel, c_ang, c_lin, offset) -> None:
        defs, z = self.defs, self.defs.zify
        w_p, alpha0_p = (_ZERO, _ZERO) if joint.parent < 0 else (
            self.joints[joint.parent].omega, self.joints[joint.parent].bias_absolute)
        joint.offset = tuple(z(x) for x in offset)
        joint.relative = tuple(z(x) for x in tuple(w_rel) + tuple(v_rel))
        joint.omega = tuple(z(x) for x in _add(w_p, w_rel))
        joint.bias = tuple(z(x) for x in tuple(c_ang) + tuple(c_lin))
        joint.bias_absolute = tuple(z(x) for x in _add(alpha0_p, joint.bias[:3]))
        joint.columns = [tuple(z(defs.diff(c, self.speeds[r])) for c in joint.relative)
                         for r in joint.speeds]
        b = joint.body
        i_n = sm.zeros(3, 3)
        if joint.turns:
            for (fa, fb), m in b.central_inertia.terms.items():
                i_n += self._rotation(fa) * m * self._rotation(fb).T
            mass = b.mass_checked()
        elif b.mass is None:
            raise NotATree(f"the mass of particle {b.name} is not given")
        else:
            mass = b.mass
        joint.inertia = (i_n.applyfunc(z), mass)

    def _disagreement(self, index: int, joint: _Joint) -> str | None:
        """None when the recursion's angular and linear velocities and accelerations of
        the body, at random speeds and u', are the model's (then kept for its
        children): the partial velocities for the ancestors' speeds are theirs carried
        to it, and its accelerations are those its velocities give; else what differs."""
        found = []
        for k, (point, still) in enumerate(zip(self._points(), self._still_points())):
            speeds = np.array([float(point.values[self.speeds[r]]) for r in joint.speeds])
            rates = np.array([float(point.values[self.rates[r]]) for r in joint.speeds])
            cols = np.array([self._numbers(c, point) for c in joint.columns]).reshape(-1, 6)
            own_vel = cols.T @ speeds if len(speeds) else np.zeros(6)
            own_acc = cols.T @ rates if len(rates) else np.zeros(6)
            bias = self._numbers(joint.bias, point)
            rel = own_vel + self._numbers(joint.relative, still)
            d = self._numbers(joint.offset, point)
            if joint.parent < 0:
                w_p = v_p = alpha_p = a_p = np.zeros(3)
            else:
                w_p, v_p, alpha_p, a_p = self._motions[k][joint.parent]
            ours = (w_p + rel[:3],
                    v_p + np.cross(w_p, d) + rel[3:],
                    alpha_p + bias[:3] + own_acc[:3],
                    a_p + np.cross(alpha_p, d) + bias[3:] + own_acc[3:])
            for mine, model, what in zip(ours, _motion_of(joint.body, self.n),
                                         ("angular velocity", "velocity",
                                          "angular acceleration", "acceleration")):
                if model is not None and not _near(mine, self._numbers(model, point)):
                    return what
            found.append(ours)
        for k, ours in enumerate(found):
            self._motions[k][index] = ours
        return None

    # -- loads ---------------------------------------------------------------------------
    def _loads(self) -> None:
        n = self.n
        by_centre = {j.centre: j for j in self.joints}
        by_frame = {j.body: j for j in self.joints if j.turns}
        for point, force in self.system.forces.items():
            if not force.terms:
                continue
            joint = by_centre.get(point)
            if joint is None and not self._support([point.vel(n)]):
                continue                            # it acts on a point no speed moves
            f_n = self._in_n(force)
            if joint is not None:
                joint.applied[3:] = _add(joint.applied[3:], f_n)
                continue
            joint, arm = self._carrier_of_point(point)
            if joint is None:
                self._through_partials(point.vel(n), force)
            else:
                joint.applied[:3] = _add(joint.applied[:3], _cross(self._in_n(arm), f_n))
                joint.applied[3:] = _add(joint.applied[3:], f_n)
        for frame, torque in self.system.torques.items():
            if not torque.terms:
                continue
            joint = by_frame.get(frame) or self._carrier_of_frame(frame)
            if joint is None:
                self._through_partials(frame.ang_vel_in(n), torque)
            else:
                joint.applied[:3] = _add(joint.applied[:3], self._in_n(torque))

    def _through_partials(self, velocity: Vector, load: Vector) -> None:
        for r, u in enumerate(self.speeds):
            self.generalized[r] += partial_velocity(velocity, u, self.defs).dot(load)

    def _carrier_of_point(self, point: Point):
        """(joint, arm from its mass centre) of the body the point is fixed in, or
        (None, None): its velocity must be the body's carried to it, at random states."""
        supp = self._support([point.vel(self.n)])
        for joint in sorted(self.joints, key=lambda j: len(self._joint_support(j))):
            if not joint.turns or not supp <= self._joint_support(joint):
                continue
            try:
                arm = point.pos_from(joint.body.masscenter)
            except AutolevModelError:
                continue
            carried = (point.vel(self.n), joint.body.masscenter.vel(self.n),
                       joint.body.ang_vel_in(self.n), arm)
            if all(self._carries(p, *carried) for p in self._points()):
                return joint, arm
        return None, None

    def _carrier_of_frame(self, frame: Frame):
        w = frame.ang_vel_in(self.n)
        supp = self._support([w])
        for joint in self.joints:
            if joint.turns and supp <= self._joint_support(joint) and all(
                    _near(self._numbers(w, p), self._numbers(joint.body.ang_vel_in(self.n), p))
                    for p in self._points()):
                return joint
        return None

    def _joint_support(self, joint: _Joint) -> set:
        out = set(joint.speeds)
        while joint.parent >= 0:
            joint = self.joints[joint.parent]
            out |= set(joint.speeds)
        return out

    def _carries(self, point: NumericPoint, v_point, v_centre, w, arm) -> bool:
        expected = self._numbers(v_centre, point) + np.cross(self._numbers(w, point),
                                                             self._numbers(arm, point))
        return _near(self._numbers(v_point, point), expected)

    # -- the check against the model's own velocities and accelerations ----------------
    def _points(self) -> list:
        if self._random_points is None:
            self._random_points = [self._random_point(seed, True) for seed in CHECK_SEEDS]
        return self._random_points

    def _still_points(self) -> list:
        """The random states with every speed and u' 0: what no speed gives."""
        if self._still is None:
            self._still = [self._random_point(seed, False) for seed in CHECK_SEEDS]
        return self._still

    def _random_point(self, seed: int, moving: bool) -> NumericPoint:
        """Random coordinates and constants (the same for a seed), and random speeds
        and derivatives, or 0 for them when not `moving`."""
        rng = np.random.default_rng(seed)
        values = {x: sm.Float(rng.uniform(-1, 1)) if moving else 0
                  for x in self.speeds + self.rates}
        return NumericPoint(self.defs, values, seed=seed, varying="wide")

    def _numbers(self, v, point: NumericPoint) -> np.ndarray:
        """N measure numbers of a vector (or of a tuple already in N) at a point."""
        if isinstance(v, Vector):
            total = np.zeros(3)
            for f, c in v.terms.items():
                r = np.array([[self._number(x, point) for x in row]
                              for row in self._rotation(f).tolist()])
                total += r @ np.array([self._number(x, point) for x in c])
            return total
        return np.array([self._number(x, point) for x in v])

    def _number(self, e, point: NumericPoint) -> float:
        value = self.defs.numeric(e, point)
        return value.real

    def _check_rotations(self) -> None:
        """Every rotation a rotation at the random states.  N's measure numbers serve
        only where each rotation is one at every state: Euler parameters are one on the
        unit sphere alone, where Kane's equations, in the body's own frame, never
        needed it."""
        for point in self._points():
            for frame, r in self._rotations.items():
                r = self._numbers(list(r), point).reshape(3, 3)
                if not _near(r @ r.T, np.eye(3)):
                    raise NotATree(f"the orientation of {frame.name} is a rotation only "
                                   "where its coordinates are constrained")

    # -- the recursion -------------------------------------------------------------------
    def _inertias(self) -> tuple[list, list]:
        """Per joint: the body's spatial inertia about its mass centre (6x6, N), and
        the force its motion asks with no acceleration (the gyroscopic moment) less
        the loads on it (moment, force)."""
        inertia, bias_force = [], []
        for j in self.joints:
            i_n, m = j.inertia
            spatial = [[sm.S.Zero] * 6 for _ in range(6)]
            for a in range(3):
                for c in range(3):
                    spatial[a][c] = i_n[a, c]
                spatial[3 + a][3 + a] = m
            inertia.append(spatial)
            w = j.omega
            gyro = _cross(w, tuple(sum(i_n[a, c] * w[c] for c in range(3)) for a in range(3)))
            bias_force.append([g - f for g, f in zip(gyro + _ZERO, j.applied)])
        return inertia, bias_force

    def _carried_acceleration(self, accel: list, j: _Joint) -> list:
        """The joint's acceleration before its own speeds' rates: the parent's carried
        to this mass centre, plus the joint's bias."""
        base = list(j.bias)
        if j.parent >= 0:
            ap = accel[j.parent]
            carried = ap[:3] + list(_add(ap[3:], _cross(ap[:3], j.offset)))
            base = [x + y for x, y in zip(carried, base)]
        return [self.defs.zify(x) for x in base]

    def recursion(self) -> Recursion:
        """The speeds' derivatives by the articulated-body recursion, with its pivots."""
        rates, pivots = self.solve()
        return Recursion(rates, [p for p, _ in pivots], [e for _, e in pivots])

    def inverse(self) -> InverseDynamics:
        """M a - F by the Newton-Euler recursion (a: the speeds' derivatives, as
        symbols), with the speeds from the leaves."""
        return InverseDynamics(self.inverse_dynamics(),
                               [r for j in reversed(self.joints) for r in j.speeds])

    def inverse_dynamics(self) -> list:
        """Row r of M a - F, with the speeds' rates a as the symbols `self.rates`: each
        body's acceleration from the root, the wrench its inertia and loads ask of it,
        summed from the leaves through the joints; a speed's row is its columns dotted
        with the wrench of the subtree it moves, less its generalized force from the
        loads that act through partial velocities.  Where a = the recursion's rates
        every row is 0 (the same equations as `solve`)."""
        z = self.defs.zify
        inertia, bias_force = self._inertias()
        accel, wrench = [None] * len(self.joints), [None] * len(self.joints)
        for k, j in enumerate(self.joints):
            base = self._carried_acceleration(accel, j)
            accel[k] = [z(base[a] + sum((col[a] * self.rates[r]
                                         for col, r in zip(j.columns, j.speeds)), sm.S.Zero))
                        for a in range(6)]
            wrench[k] = [_dot(inertia[k][a], accel[k]) + bias_force[k][a] for a in range(6)]
        rows = [None] * len(self.speeds)
        for k in range(len(self.joints) - 1, -1, -1):    # children come after parents
            j = self.joints[k]
            total = [z(x) for x in wrench[k]]
            for r, col in zip(j.speeds, j.columns):
                rows[r] = z(_dot(col, total) - self.generalized[r])
            if j.parent >= 0:
                _carry_force(wrench[j.parent], total, j.offset)
        return rows

    def solve(self) -> tuple[list, list]:
        """(the speeds' derivatives, the (pivot, its entry of D) of each joint's factor)."""
        z = self.defs.zify
        joints = self.joints
        pivots: list = []
        inertia, bias_force = self._inertias()
        kept = [None] * len(joints)
        for k in range(len(joints) - 1, -1, -1):
            j = joints[k]
            ia = _symmetric([[z(x) for x in row] for row in inertia[k]])
            pa = [z(x) for x in bias_force[k]]
            cols = j.columns
            tau = [self.generalized[r] for r in j.speeds]
            u_cols = [_matvec(ia, col) for col in cols]                  # IA S
            d_mat = [[z(_dot(col, uc)) for uc in u_cols] for col in cols]
            rhs = [z(t - _dot(col, pa)) for t, col in zip(tau, cols)]  # tau - S^T pA
            w_rows, g = _solve_spd(d_mat, [list(uc) for uc in u_cols], rhs, z, pivots)
            # articulated: IA - U D^-1 U^T, and pA + Ia c + U D^-1 (tau - S^T pA)
            k_own = range(len(cols))
            art = _symmetric([[z(ia[a][c] - sum(u_cols[i][a] * w_rows[i][c] for i in k_own))
                               for c in range(6)] for a in range(6)])
            c_bias = j.bias
            pa_art = [z(pa[a] + _dot(art[a], c_bias)
                        + sum(u_cols[i][a] * g[i] for i in k_own))
                      for a in range(6)]
            kept[k] = (w_rows, g)
            if j.parent >= 0:
                _carry_inertia(inertia[j.parent], art, j.offset)
                _carry_force(bias_force[j.parent], pa_art, j.offset)
        accel = [None] * len(joints)
        out = [None] * len(self.speeds)
        for k, j in enumerate(joints):
            base = self._carried_acceleration(accel, j)
            w_rows, g = kept[k]
            rates = [z(g[i] - _dot(w_rows[i], base)) for i in range(len(j.speeds))]
            for r, rate in zip(j.speeds, rates):
                out[r] = rate
            accel[k] = [z(base[a] + sum(col[a] * rate for col, rate in zip(j.columns, rates)))
                        for a in range(6)]
        return out, pivots


# -- small algebra on tuples of expressions ------------------------------------------------
def _add(a, b) -> tuple:
    return tuple(x + y for x, y in zip(a, b))


def _scale(s, a) -> tuple:
    return tuple(s * x for x in a)


def _cross(a, b) -> tuple:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a, b):
    return sm.Add(*[x * y for x, y in zip(a, b) if x != 0 and y != 0])


def _matvec(m, v) -> list:
    return [_dot(row, v) for row in m]


def _velocities_of(body: Body | Particle, n: Frame) -> tuple:
    """The model's angular velocity and mass-centre velocity of a body in N (a
    particle's: None, v)."""
    if not isinstance(body, Body):
        return None, body.vel(n)
    return body.ang_vel_in(n), body.masscenter.vel(n)


def _motion_of(body: Body | Particle, n: Frame) -> tuple:
    """_velocities_of, then the angular acceleration and mass-centre acceleration."""
    if not isinstance(body, Body):
        return _velocities_of(body, n) + (None, body.acc(n))
    return _velocities_of(body, n) + (body.ang_acc_in(n), body.masscenter.acc(n))


def _nearest(frame: Frame, placed: dict) -> Frame | None:
    """The frame of `placed` nearest to `frame` along the orientations the model gave."""
    seen, queue = {frame}, [frame]
    while queue:
        f = queue.pop(0)
        if f in placed:
            return f
        for g in f.oriented_neighbours():
            if g not in seen:
                seen.add(g)
                queue.append(g)
    return None


def _symmetric(m: list) -> list:
    """The matrix with its lower triangle the mirror of its upper: one expression per
    pair, as the mathematics has it."""
    for a in range(len(m)):
        for c in range(a):
            m[a][c] = m[c][a]
    return m


def _near(ours: np.ndarray, theirs: np.ndarray) -> bool:
    scale = max(1.0, float(np.max(np.abs(theirs))) if len(theirs) else 1.0)
    return bool(np.all(np.abs(ours - theirs) <= CHECK_TOLERANCE * scale))


def _solve_spd(d_mat, u_cols, rhs, z, pivots: list) -> tuple[list, list]:
    """(D^-1 U^T as rows, D^-1 rhs) for the joint's symmetric D, by L D L^T without
    pivoting (D's pivots are the mass matrix's in the order the recursion eliminates:
    positive where the mass matrix is definite; a zero one, a singular mass matrix,
    is reported by the run from the pivots kept in `pivots`)."""
    k = len(d_mat)
    if k == 0:
        return [], []
    lower = [[sm.S.Zero] * k for _ in range(k)]
    diag = [sm.S.Zero] * k
    for i in range(k):
        for c in range(i):
            lower[i][c] = z((d_mat[i][c] - sum(lower[i][m] * diag[m] * lower[c][m]
                                               for m in range(c))) / diag[c])
        diag[i] = z(d_mat[i][i] - sum(lower[i][m] ** 2 * diag[m] for m in range(i)))
        pivots.append((diag[i], d_mat[i][i]))

    def solve(b: list) -> list:
        y = []
        for i in range(k):
            y.append(z(b[i] - sum(lower[i][m] * y[m] for m in range(i))))
        x = [sm.S.Zero] * k
        for i in range(k - 1, -1, -1):
            x[i] = z(y[i] / diag[i] - sum(lower[m][i] * x[m] for m in range(i + 1, k)))
        return x

    per_column = [solve([u_cols[i][a] for i in range(k)]) for a in range(6)]
    w_rows = [[per_column[a][i] for a in range(6)] for i in range(k)]
    return w_rows, solve(rhs)


def _carry_inertia(target: list, art: list, d: tuple) -> None:
    """target += X^T art X, X carrying a motion of the parent to the child's mass
    centre d away: (alpha, a) -> (alpha, a + alpha x d); in blocks [[A, B], [B^T, C]],
    X^T art X = [[A + D B^T - (B + D C) D, B + D C], [(B + D C)^T, C]], D v = d x v."""
    a = [[art[i][c] for c in range(3)] for i in range(3)]
    b = [[art[i][3 + c] for c in range(3)] for i in range(3)]
    cc = [[art[3 + i][3 + c] for c in range(3)] for i in range(3)]
    skew = [[sm.S.Zero, -d[2], d[1]], [d[2], sm.S.Zero, -d[0]], [-d[1], d[0], sm.S.Zero]]
    b_new = [[b[i][c] + _dot(skew[i], [cc[m][c] for m in range(3)]) for c in range(3)]
             for i in range(3)]
    for i in range(3):
        for c in range(3):
            top = (a[i][c] + _dot(skew[i], [b[c][m] for m in range(3)])
                   - _dot(b_new[i], [skew[m][c] for m in range(3)]))
            target[i][c] += top
            target[i][3 + c] += b_new[i][c]
            target[3 + c][i] += b_new[i][c]
            target[3 + i][3 + c] += cc[i][c]


def _carry_force(target: list, force: list, d: tuple) -> None:
    """target += X^T force: the moment about the parent's mass centre gains d x f."""
    moment = _add(force[:3], _cross(d, force[3:]))
    for i in range(3):
        target[i] += moment[i]
        target[3 + i] += force[3 + i]
