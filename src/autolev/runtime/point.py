"""Points, particles and rigid bodies.

Positions form an undirected graph (P_O_P> = ... adds an edge); velocities and
accelerations are assigned (V_P_N> = ..., V2PTS, V1PT, A2PTS, A1PT) per frame.
A velocity that was never defined is an error when it is needed (Autolev gave none
by itself); an acceleration that was not assigned is DT(V_P_N>, N), as Autolev did.
"""
from __future__ import annotations

from collections import deque

import sympy as sm

from .interop import to_sympy_point
from ..engine.errors import AutolevModelError
from .derived import mutation
from .frame import Frame, Scene
from .vectors import Dyadic, Vector, _vector, outer


class Point:
    """A point (Autolev POINTS, the origin NO of a Newtonian frame, a mass center BO)."""

    def __init__(self, name: str, scene: Scene):
        self.name = name
        self.scene = scene
        self._pos: dict[Point, Vector] = {}     # other -> self.pos_from(other)
        self._vel: dict[Frame, Vector] = {}
        self._acc: dict[Frame, Vector] = {}
        # derived when asked, each with the model's revision it was derived at
        self._acc_derived: dict[Frame, tuple[tuple, Vector]] = {}
        self._vel_derived: dict[Frame, tuple[tuple, Vector]] = {}

    def __repr__(self) -> str:
        return self.name

    def note_change(self) -> None:
        self.scene.note_change()

    # -- position -----------------------------------------------------------------
    @mutation
    def set_pos(self, other: "Point", value) -> None:
        """P_other_self> = value."""
        if other is self:
            raise AutolevModelError(f"the position of {self.name} from itself is 0>")
        value = _vector(value)
        self._pos[other] = value
        other._pos[self] = -value

    def pos_from(self, other: "Point") -> Vector:
        """P_other_self>: the sum of position vectors along the points linking them."""
        if other is self:
            return Vector()
        prev = {self: None}
        queue = deque([self])
        while queue:
            p = queue.popleft()
            if p is other:
                break
            for q in p._pos:
                if q not in prev:
                    prev[q] = p
                    queue.append(q)
        if other not in prev:
            raise AutolevModelError(
                f"the position of {self.name} relative to {other.name} is not defined")
        total = Vector()
        p = other
        while prev[p] is not None:
            total = total + prev[p]._pos[p]
            p = prev[p]
        return total

    def linked_points(self) -> list["Point"]:
        """The points whose position from this one the model gave directly."""
        return list(self._pos)

    def locate_new(self, name: str, value) -> "Point":
        p = self.scene.point(name)
        p.set_pos(self, value)
        return p

    # -- velocity and acceleration -----------------------------------------------------
    @mutation
    def set_vel(self, frame: Frame, value) -> None:
        """V_self_frame> = value."""
        self._vel[frame] = _vector(value)

    def has_vel(self, frame: Frame) -> bool:
        """Whether V_self_frame> is assigned or follows from the positions."""
        return frame in self._vel or self._moving_base(frame) is not None

    def vel(self, frame: Frame) -> Vector:
        """V_self_frame>: as assigned; else V_Q_frame> + DT(P_Q_self>, frame) for the
        nearest point Q along the defined positions whose velocity in frame is
        assigned or which is fixed in frame (its origin)."""
        if frame in self._vel:
            return self._vel[frame]
        version = self.scene.revision.key
        cached = self._vel_derived.get(frame)
        if cached is not None and cached[0] == version:
            return cached[1]
        base = self._moving_base(frame)
        if base is None:
            raise AutolevModelError(
                f"the velocity of {self.name} in {frame.name} is not defined "
                f"(assign V_{self.name}_{frame.name}>, use V2PTS/V1PT, or define the "
                f"position of {self.name} from a point fixed in {frame.name} such as "
                f"{frame.name}O)")
        v = self.pos_from(base).dt(frame)
        if frame in base._vel:
            v = base._vel[frame] + v
        self._vel_derived[frame] = (version, v)
        return v

    def _moving_base(self, frame: Frame) -> "Point | None":
        """The nearest point linked to self by defined positions whose velocity in
        frame is assigned, or which is frame's origin (fixed in it)."""
        origin = frame.declared_origin
        seen = {self}
        queue = deque([self])
        while queue:
            p = queue.popleft()
            if p is not self and (frame in p._vel or p is origin):
                return p
            for q in p._pos:
                if q not in seen:
                    seen.add(q)
                    queue.append(q)
        return None

    @mutation
    def set_acc(self, frame: Frame, value) -> None:
        """A_self_frame> = value."""
        self._acc[frame] = _vector(value)

    def acc(self, frame: Frame) -> Vector:
        """A_self_frame>: as assigned, else DT(V_self_frame>, frame)."""
        if frame in self._acc:
            return self._acc[frame]
        if frame not in self._vel:
            # the velocity itself comes from the positions, as they stand now
            return self.vel(frame).dt(frame)
        version = self.scene.revision.key
        cached = self._acc_derived.get(frame)
        if cached is None or cached[0] != version:
            cached = self._acc_derived[frame] = (version, self.vel(frame).dt(frame))
        return cached[1]

    def acc_assigned_zero(self, frame: Frame) -> bool:
        """Whether the model assigned A_self_frame> = 0>."""
        return frame in self._acc and not self._acc[frame].terms

    def v2pt_theory(self, other: "Point", outframe: Frame, fixedframe: Frame) -> Vector:
        """V2PTS(outframe, fixedframe, other, self): both points fixed in fixedframe."""
        v = other.vel(outframe) + fixedframe.ang_vel_in(outframe).cross(self.pos_from(other))
        self.set_vel(outframe, v)
        return v

    def v1pt_theory(self, other: "Point", outframe: Frame, interframe: Frame) -> Vector:
        """V1PT(outframe, interframe, other, self): other fixed in interframe, self
        moving in it (its velocity there is assigned, or DT(P_other_self>, interframe))."""
        r = self.pos_from(other)
        v_rel = self._vel.get(interframe)
        if v_rel is None:
            v_rel = r.dt(interframe)
        v = other.vel(outframe) + v_rel + interframe.ang_vel_in(outframe).cross(r)
        self.set_vel(outframe, v)
        return v

    def a2pt_theory(self, other: "Point", outframe: Frame, fixedframe: Frame) -> Vector:
        """A2PTS(outframe, fixedframe, other, self)."""
        r = self.pos_from(other)
        w = fixedframe.ang_vel_in(outframe)
        alf = fixedframe.ang_acc_in(outframe)
        a = other.acc(outframe) + alf.cross(r) + w.cross(w.cross(r))
        self.set_acc(outframe, a)
        return a

    def a1pt_theory(self, other: "Point", outframe: Frame, interframe: Frame) -> Vector:
        """A1PT(outframe, interframe, other, self)."""
        r = self.pos_from(other)
        w = interframe.ang_vel_in(outframe)
        alf = interframe.ang_acc_in(outframe)
        v_rel = self._vel.get(interframe)
        if v_rel is None:
            v_rel = r.dt(interframe)
        a_rel = self._acc.get(interframe)
        if a_rel is None:
            a_rel = v_rel.dt(interframe)
        a = (other.acc(outframe) + a_rel + 2 * w.cross(v_rel) + alf.cross(r)
             + w.cross(w.cross(r)))
        self.set_acc(outframe, a)
        return a

    def to_sympy(self):
        return to_sympy_point(self)


def _mass_property() -> property:
    """A particle's or body's mass (None until MASS gives it): giving it changes the
    model, whose revision its Scene bumps."""
    def get(self) -> sm.Expr | None:
        return self._mass

    @mutation
    def give(self, value) -> None:
        self._mass = value
    return property(get, give, doc=_mass_property.__doc__)


class Particle(Point):
    """A point with a mass (Autolev PARTICLES)."""

    mass = _mass_property()

    def __init__(self, name: str, scene: Scene):
        super().__init__(name, scene)
        self._mass: sm.Expr | None = None

    @property
    def point(self) -> Point:
        return self


class Body(Frame):
    """A rigid body (Autolev BODIES): a frame with a mass center BO, a mass and a
    central inertia dyadic."""

    mass = _mass_property()

    def __init__(self, name: str, scene: Scene, masscenter: Point):
        super().__init__(name, scene)
        self.masscenter = masscenter
        self.origin = masscenter
        self._mass: sm.Expr | None = None
        self._inertia: Dyadic | None = None
        self._inertia_about: tuple[Point, Dyadic] | None = None

    @property
    def frame(self) -> Frame:
        return self

    @mutation
    def set_inertia(self, i11, i22, i33, i12=0, i23=0, i31=0, frame: Frame | None = None,
                    about: Point | None = None) -> None:
        """INERTIA B[_O][(A)], I11, I22, I33[, I12, I23, I31]: the inertia dyadic of the
        body about its mass center (or about point `about`), measure numbers in `frame`
        (the body's own frame unless given)."""
        f = frame or self
        m = sm.Matrix([[i11, i12, i31], [i12, i22, i23], [i31, i23, i33]])
        dyadic = Dyadic({(f, f): m})
        if about is None or about is self.masscenter:
            self._inertia, self._inertia_about = dyadic, None
        else:
            self._inertia, self._inertia_about = None, (about, dyadic)

    @mutation
    def set_inertia_dyadic(self, dyadic: Dyadic, about: Point | None = None) -> None:
        """I_B_O>> = dyadic."""
        if about is None or about is self.masscenter:
            self._inertia, self._inertia_about = dyadic, None
        else:
            self._inertia, self._inertia_about = None, (about, dyadic)

    @property
    def central_inertia(self) -> Dyadic:
        """I_B_BO>>; given about another point O, it is I_B_O>> minus the inertia of the
        whole mass at BO about O (parallel axes)."""
        if self._inertia is not None:
            return self._inertia
        if self._inertia_about is not None:
            point, dyadic = self._inertia_about
            return dyadic - point_mass_inertia(self.mass_checked(), self.masscenter.pos_from(point),
                                               self)
        raise AutolevModelError(f"the inertia of body {self.name} is not given "
                                f"(INERTIA {self.name}, I11, I22, I33)")

    def inertia_about(self, point: Point) -> Dyadic:
        """I_B_O>>: the inertia dyadic of the body about `point`."""
        central = self.central_inertia
        if point is self.masscenter:
            return central
        return central + point_mass_inertia(self.mass_checked(),
                                            self.masscenter.pos_from(point), self)

    def mass_checked(self) -> sm.Expr:
        if self.mass is None:
            raise AutolevModelError(f"the mass of body {self.name} is not given "
                                    f"(MASS {self.name}=...)")
        return self.mass


def point_mass_inertia(mass, r: Vector, frame: Frame) -> Dyadic:
    """Inertia of a mass at position r about the origin of r: m (r.r U - r r), with
    the unit dyadic U written in `frame` (or in r's own frame when r has one)."""
    frames = list(r.terms)
    f = frames[0] if len(frames) == 1 else frame
    rr = r.dot(r)
    unit = Dyadic({(f, f): sm.eye(3)})
    return mass * (rr * unit - outer(r, r))
