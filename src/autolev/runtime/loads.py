"""A model's loads: the resultant force on each point, the resultant torque on each
frame, and the g> of each GRAVITY (a part of Model, changed only through its methods).
"""
from __future__ import annotations

from types import MappingProxyType

from ..engine.errors import AutolevModelError
from .derived import Owned, mutation
from .frame import Frame
from .point import Body, Particle, Point
from .vectors import Vector, _vector


class Loads(Owned):
    """FORCE, TORQUE and GRAVITY as resultants, in the order first applied."""

    def __init__(self, revision) -> None:
        super().__init__(revision)
        self._forces: dict[Point, Vector] = {}
        self._torques: dict[Frame, Vector] = {}
        self._gravity: tuple[Vector, ...] = ()

    @property
    def forces(self) -> MappingProxyType:
        return MappingProxyType(self._forces)

    @property
    def torques(self) -> MappingProxyType:
        return MappingProxyType(self._torques)

    @property
    def gravity_vectors(self) -> tuple:
        """g> of each GRAVITY statement, in order."""
        return self._gravity

    def force_on(self, point: Point) -> Vector:
        return self._forces.get(point, Vector())

    def torque_on(self, frame: Frame) -> Vector:
        return self._torques.get(frame, Vector())

    @mutation
    def add_force(self, point: Point, value) -> None:
        self._forces[point] = self.force_on(point) + _vector(value)

    @mutation
    def set_force(self, point: Point, value) -> None:
        self._forces[point] = _vector(value)

    @mutation
    def add_torque(self, frame: Frame, value) -> None:
        self._torques[frame] = self.torque_on(frame) + _vector(value)

    @mutation
    def set_torque(self, frame: Frame, value) -> None:
        self._torques[frame] = _vector(value)

    @mutation
    def gravity(self, g: Vector, targets) -> None:
        """m*g> on the mass center of each body and particle of `targets`."""
        self._gravity += (g,)
        for b in targets:
            if isinstance(b, Body):
                point, mass = b.masscenter, b.mass_checked()
            elif isinstance(b, Particle):
                if b.mass is None:
                    raise AutolevModelError(f"the mass of particle {b.name} is not given")
                point, mass = b, b.mass
            else:
                raise AutolevModelError(f"GRAVITY acts on bodies and particles, not {b!r}")
            self._forces[point] = self.force_on(point) + _vector(mass * g)
