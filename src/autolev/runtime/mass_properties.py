"""The mass properties, energy and momentum of a model's bodies and particles (a mixin
of Model): KE, MOMENTUM, GYROSTAT, CM, INERTIA, MASS and the unit dyadic 1>>."""
from __future__ import annotations

import sympy as sm

from ..engine.errors import AutolevModelError
from .frame import Frame
from .point import Body, Particle, Point, point_mass_inertia
from .vectors import Dyadic, UnitDyadic, Vector


class MassPropertiesMixin:
    def _items(self, items):
        return list(items) or (self.bodies_list + self.particles_list)

    def ke(self, *items):
        """KE(): kinetic energy in the Newtonian frame (of everything, or of the listed
        bodies and particles)."""
        n = self._newtonian()
        total = sm.S.Zero
        for it in self._items(items):
            if isinstance(it, Body):
                v = it.masscenter.vel(n)
                w = it.ang_vel_in(n)
                total += it.mass_checked() * v.dot(v) / 2 + w.dot(it.central_inertia.dot(w)) / 2
            else:
                v = it.vel(n)
                total += self._particle_mass(it) * v.dot(v) / 2
        return self.defs.zify(total)

    def _particle_mass(self, p: Particle):
        if p.mass is None:
            raise AutolevModelError(f"the mass of particle {p.name} is not given")
        return p.mass

    def momentum(self, kind: str, *args):
        """MOMENTUM(LINEAR[, B...]) or MOMENTUM(ANGULAR, O[, B...]) in the Newtonian frame."""
        n = self._newtonian()
        if kind.lower() == "linear":
            total = Vector()
            for it in self._items(args):
                if isinstance(it, Body):
                    total = total + it.mass_checked() * it.masscenter.vel(n)
                else:
                    total = total + self._particle_mass(it) * it.vel(n)
            return total.zified()
        point, items = args[0], args[1:]
        total = Vector()
        for it in self._items(items):
            if isinstance(it, Body):
                r = it.masscenter.pos_from(point)
                w = it.ang_vel_in(n)
                if r.terms:      # about its own mass centre the velocity is not needed
                    total = total + r.cross(it.mass_checked() * it.masscenter.vel(n))
                total = total + it.central_inertia.dot(w)
            else:
                total = total + it.pos_from(point).cross(self._particle_mass(it) * it.vel(n))
        return total.zified()

    def gyrostat_angmom(self, carrier: Frame, rotor: Frame, j) -> Vector:
        """GYROSTAT(ANGMOM, CYLINDER, A, B, J): the angular momentum that a rotor B,
        a cylinder with axial moment of inertia J spinning in carrier A, adds to the
        carrier's (whose inertia already holds the rotor's mass and transverse
        inertia): J times the rotor's spin.  The spin is W_B_A> when the model assigned
        it, otherwise the W_B_N> it assigned (tutorial 9 writes W_B_N> = Omega*A3> for
        a rotor spinning at Omega relative to A).  No Autolev source defines GYROSTAT;
        this is the textbook gyrostat term H = I.w + J*Omega*a3 it is used for."""
        n = self._newtonian()
        if rotor.ang_vel_assigned(carrier):
            spin = rotor.ang_vel_in(carrier)
        elif rotor.ang_vel_assigned(n):
            spin = rotor.ang_vel_in(n)
        else:
            raise AutolevModelError(
                f"GYROSTAT: the spin of rotor {rotor.name} is not given "
                f"(W_{rotor.name}_{carrier.name}> = ...)")
        return (j * spin).zified()

    def cm(self, point: Point, *items) -> Vector:
        """CM(O[, B...]): position of the mass center (of the listed bodies) from O."""
        total_m = sm.S.Zero
        total = Vector()
        for it in self._items(items):
            if isinstance(it, Body):
                m, p = it.mass_checked(), it.masscenter
            else:
                m, p = self._particle_mass(it), it
            total = total + m * p.pos_from(point)
            total_m += m
        if total_m == 0:
            raise AutolevModelError("CM of a system with no mass")
        return (total / total_m).zified()

    def inertia_of(self, point: Point, *items) -> Dyadic:
        """INERTIA(O[, B...]): inertia dyadic about O of the system (or listed items)."""
        n = self._some_frame()
        total = Dyadic()
        for it in self._items(items):
            if isinstance(it, Body):
                total = total + it.inertia_about(point)
            else:
                total = total + point_mass_inertia(self._particle_mass(it), it.pos_from(point),
                                                   n)
        return total

    def particle_inertia(self, particle: Particle, point: Point) -> Dyadic:
        """I_P_O>>: inertia dyadic of particle P about point O."""
        return point_mass_inertia(self._particle_mass(particle), particle.pos_from(point),
                                  self._some_frame())

    def _some_frame(self) -> Frame:
        frame = self.newtonian_frame or next(iter(self.frames_by_name.values()), None)
        if frame is None:
            raise AutolevModelError("no frame is declared")
        return frame

    def unit_dyadic(self) -> Dyadic:
        """1>>: the unit dyadic (the same in every frame's basis)."""
        return UnitDyadic(self._some_frame())

    def mass_of(self, *items):
        """MASS(): total mass (of everything, or of the bodies and particles listed)."""
        items = items or tuple(self.bodies_list) + tuple(self.particles_list)
        total = sm.S.Zero
        for it in items:
            m = it.mass_checked() if isinstance(it, Body) else it.mass
            if m is None:
                raise AutolevModelError(f"the mass of {it.name} is not given")
            total += m
        return total
