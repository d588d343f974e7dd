"""Kane's method: generalized speeds, partial velocities, Fr and Fr*.

Apart from the Model as sympy keeps KanesMethod apart from bodies and loads: every
function takes what it needs explicitly (the Newtonian frame, the loads, the
particles and bodies, the definitions) and returns the equations; nothing here
changes a model.
"""
from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence, Set
from dataclasses import dataclass, field

import sympy as sm

from . import symbols as S
from .calculus import Definitions
from ..engine.errors import AutolevModelError
from .point import Body, Particle, Point
from .frame import Frame
from .vectors import Vector

MOTION_KINDS = ("variable", "motionvariable")


@dataclass
class SymbolInfo:
    kind: str            # constant variable motionvariable specified imaginary
    order: int           # derivatives declared
    index: int           # declaration order


@dataclass
class KaneEquations:
    """Kane's dynamical equations, one row per independent (then auxiliary) speed."""

    speeds: list          # independent speeds (rows), in order
    auxiliary: list       # auxiliary speeds (extra rows)
    dependent: list       # dependent speeds (defined by the constraints)
    fr: sm.Matrix
    frstar: sm.Matrix
    unknowns: list = field(default_factory=list)   # KANE(F1, ...): solved from the aux rows

    @property
    def rows(self) -> sm.Matrix:
        return self.fr + self.frstar


@dataclass
class System:
    """What Kane's method reads from a model: its frame, loads and massive items."""

    newtonian: Frame
    forces: Mapping[Point, Vector]
    torques: Mapping[Frame, Vector]
    particles: Sequence[Particle]
    bodies: Sequence[Body]
    defs: Definitions


@dataclass
class SpeedDeclarations:
    """What decides which symbols are generalized speeds."""

    info: Mapping[sm.Symbol, SymbolInfo]
    solved: Set            # speeds whose derivatives SOLVE defined
    dependent: Sequence
    auxiliary: Sequence


def velocity_sources(system: System, inertia: bool = True, strict: bool = True):
    """(velocities, angular velocities) of the loaded points and frames and, with
    `inertia`, of every particle and body.  Missing ones are errors when `strict`,
    else skipped."""
    n = system.newtonian
    vels, angs = [], []

    def vel(p):
        if strict or p.has_vel(n):
            vels.append(p.vel(n))

    def ang(f):
        try:
            angs.append(f.ang_vel_in(n))
        except AutolevModelError:
            if strict:
                raise
    for p, f in system.forces.items():
        if f.terms:
            vel(p)
    for a, t in system.torques.items():
        if t.terms:
            ang(a)
    if inertia:
        for p in system.particles:
            vel(p)
        for b in system.bodies:
            vel(b.masscenter)
            ang(b)
    return vels, angs


def generalized_speeds(system: System, decl: SpeedDeclarations) -> tuple[list, list, list]:
    """(independent, dependent, auxiliary) generalized speeds.

    A variable or motion variable whose first derivative is defined is a
    coordinate.  A symbol on the right of a kinematical equation is a speed.  Any
    other motion variable X declared with X' is a coordinate whose X' acts as the
    speed (MOTIONVARIABLES' Q{9}''); declared without, X is a speed.  Of these
    candidates, those the velocities depend on (through definitions) count, in
    declaration order."""
    defs = system.defs
    vels, angs = velocity_sources(system, strict=False)
    comps = [c for v in vels + angs for cs in v.terms.values() for c in cs]

    def appears(u) -> bool:
        return any(defs.depends_on(c, u) for c in comps)

    candidates = _speed_candidates(defs, decl, appears)
    taken = set(decl.dependent) | set(decl.auxiliary)
    independent = [u for u in candidates
                   if u not in taken and u not in defs.rhs and appears(u)]
    aux = [u for u in decl.auxiliary if appears(u)]
    return independent, list(decl.dependent), aux


def _speed_candidates(defs: Definitions, decl: SpeedDeclarations,
                      appears: Callable[[sm.Symbol], bool]) -> list:
    kin_rhs: set = set()
    for sym, info in decl.info.items():
        d = S.derivative(sym)
        if info.kind in MOTION_KINDS and d in defs.rhs \
                and S.base_and_order(sym)[1] == 0 and sym not in decl.solved:
            kin_rhs |= defs.rhs[d].free_symbols
    named_speeds = decl.solved | set(decl.dependent) | set(decl.auxiliary)
    candidates: list = []
    for sym, info in sorted(decl.info.items(), key=lambda kv: kv[1].index):
        if info.kind not in MOTION_KINDS or S.base_and_order(sym)[1]:
            continue
        d = S.derivative(sym)
        if d in defs.rhs and sym not in decl.solved:
            continue                                 # a coordinate
        if sym in kin_rhs or sym in named_speeds:
            candidates.append(sym)
        elif info.order >= 1 and appears(d):
            candidates.append(d)                     # q' acts as the speed
        elif info.kind == "motionvariable" or info.order >= 1:
            candidates.append(sym)
    return candidates


def partial_velocity(v: Vector, u, defs: Definitions) -> Vector:
    """Partial velocity dv/du, measure numbers differentiated in their own frames
    (orientations never depend on speeds)."""
    return Vector({f: tuple(defs.zify(defs.diff(c, u)) for c in comps)
                   for f, comps in v.terms.items()})


class _Partials:
    """The partial velocities of each velocity vector, taken once per vector."""

    def __init__(self, speeds: list, defs: Definitions):
        self.speeds, self.defs = speeds, defs
        self._by_vector: dict[int, tuple[Vector, list[Vector]]] = {}

    def __call__(self, v: Vector) -> list[Vector]:
        key = id(v)            # the vector is kept with its entry, so the id stays its own
        if key not in self._by_vector:
            self._by_vector[key] = (v, self._taken(v))
        return self._by_vector[key][1]

    def _taken(self, v: Vector) -> list[Vector]:
        """v's partial velocity for each speed: its measure numbers' Jacobian in one pass
        over the definitions (not one per speed)."""
        frames = list(v.terms)
        comps = [c for f in frames for c in v.terms[f]]
        jacobian = self.defs.jacobian(comps, self.speeds)
        z = self.defs.zify
        return [Vector({f: tuple(z(jacobian[3 * k + i][j]) for i in range(3))
                        for k, f in enumerate(frames)})
                for j in range(len(self.speeds))]


class Forming:
    """Kane's equations of one system and its speeds, formed as far as they are asked
    for: Fr at the first request, Fr* only when one asks for it, both over one set of
    partial velocities (FR() then FRSTAR() takes each partial velocity once).  It keeps
    no System: each request reads the model's as it stands (at one revision)."""

    def __init__(self, defs: Definitions, speeds: tuple[list, list, list]) -> None:
        indep, dep, aux = speeds
        if not indep + aux:
            raise AutolevModelError("no generalized speeds: the velocities depend on no "
                                    "motion variable (declare MOTIONVARIABLES, or give "
                                    "kinematical equations q' = ...)")
        self.indep, self.dep, self.aux = indep, dep, aux
        self._partials = _Partials(indep + aux, defs)
        self._fr: sm.Matrix | None = None
        self._formed: dict[bool, KaneEquations] = {}

    def equations(self, system: System, inertia: bool = True) -> KaneEquations:
        """Fr and (with `inertia`) Fr*, one row per independent then auxiliary speed,
        Z-named; the same object for each later request at this inertia."""
        kept = self._formed.get(inertia)
        if kept is not None:
            return kept
        n_rows = len(self.indep) + len(self.aux)
        fr = self._fr
        with _auxiliary_held(system.defs, self.aux):
            raw_fr = self._active_forces(system) if fr is None else None
            frstar: list[list] = [[] for _ in range(n_rows)]
            if inertia:
                _inertia_forces(system, self._partials, frstar)
        z = system.defs.zify
        if fr is None:       # zified after Fr*'s terms, as one forming always named them
            fr = self._fr = sm.Matrix([z(e) for e in raw_fr])
        equations = KaneEquations(self.indep, self.aux, self.dep, fr,
                                  sm.Matrix([z(sm.Add(*terms)) for terms in frstar]))
        self._formed[inertia] = equations
        return equations

    def _active_forces(self, system: System) -> list:
        n = system.newtonian
        fr: list[list] = [[] for _ in range(len(self.indep) + len(self.aux))]
        for p, f in system.forces.items():
            if f.terms:
                _accumulate(fr, self._partials(p.vel(n)), f)
        for a, t in system.torques.items():
            if t.terms:
                _accumulate(fr, self._partials(a.ang_vel_in(n)), t)
        return [sm.Add(*terms) for terms in fr]


def _auxiliary_held(defs: Definitions, aux: list):
    """The definitions with the auxiliary speeds undefined, while the partial
    velocities are taken: Autolev kept each one independent there (its Fr row for an
    independent speed has no part through an auxiliary speed's constraint), though
    CONSTRAIN(AUXILIARY[...]) solved it (docs/language.md, "Auxiliary speeds")."""
    now = defs.user_definitions()
    held = set(aux) | {S.derivative(u) for u in aux}
    return defs.as_of({s: e for s, e in now.items() if s not in held}
                      if held & set(now) else None)


def _accumulate(terms: list[list], partials: Iterable[Vector], load: Vector) -> None:
    """Each row's term of one load; the rows are summed once at the end (adding to a
    growing sum flattens all of it again at every load)."""
    for r, vr in enumerate(partials):
        terms[r].append(vr.dot(load))


def _inertia_forces(system: System, partials: _Partials, frstar: list[list]) -> None:
    n = system.newtonian
    for p in system.particles:
        if p.mass is None:
            raise AutolevModelError(f"the mass of particle {p.name} is not given "
                                    f"(MASS {p.name}=...)")
        v = p.vel(n)
        inertial = -p.mass * p.acc(n)     # before the partials: Z's keep their order
        _accumulate(frstar, partials(v), inertial)
    for b in system.bodies:
        mc = b.masscenter
        if not mc.has_vel(n) and mc.acc_assigned_zero(n) \
                and not (mc in system.forces and system.forces[mc].terms):
            # A_BO_N> = 0> given and no velocity (tutorial 9's fixed mass centre):
            # its inertia force is zero whatever its partial velocities are
            b.mass_checked()
        else:
            v = mc.vel(n)
            inertial = -b.mass_checked() * mc.acc(n)
            _accumulate(frstar, partials(v), inertial)
        w = b.ang_vel_in(n)
        alf = b.ang_acc_in(n)
        if not w.terms and not alf.terms:
            continue        # a body that does not turn needs no inertia
        inertia = b.central_inertia
        torque = -(inertia.dot(alf) + w.cross(inertia.dot(w)))
        _accumulate(frstar, partials(w), torque)
