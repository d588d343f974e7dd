"""A model's registry: the frames, points, bodies and particles it declares, by name,
and its Newtonian frame (a part of Model, changed only through its methods)."""
from __future__ import annotations

from types import MappingProxyType
from typing import TYPE_CHECKING

from .derived import Owned, mutation

if TYPE_CHECKING:
    from .frame import Frame
    from .point import Body, Particle, Point


class Registry(Owned):
    """Frames (bodies among them) and points (particles among them) by name, in the
    order declared; each addition bumps the model's revision (a body or particle
    changes Kane's equations, a name what the model answers for it)."""

    def __init__(self, revision) -> None:
        super().__init__(revision)
        self._newtonian: Frame | None = None
        self._frames: dict[str, Frame] = {}
        self._points: dict[str, Point] = {}
        self._bodies: tuple[Body, ...] = ()
        self._particles: tuple[Particle, ...] = ()

    @property
    def newtonian(self) -> Frame | None:
        return self._newtonian

    @property
    def frames(self) -> MappingProxyType:
        return MappingProxyType(self._frames)

    @property
    def points(self) -> MappingProxyType:
        return MappingProxyType(self._points)

    @property
    def bodies(self) -> tuple:
        return self._bodies

    @property
    def particles(self) -> tuple:
        return self._particles

    @mutation
    def set_newtonian(self, frame: Frame) -> None:
        self._newtonian = frame

    @mutation
    def add_frame(self, frame: Frame) -> None:
        self._frames[frame.name] = frame

    @mutation
    def add_body(self, body: Body) -> None:
        self._frames[body.name] = body
        self._bodies += (body,)

    @mutation
    def add_point(self, point: Point) -> None:
        self._points[point.name] = point

    @mutation
    def add_particle(self, particle: Particle) -> None:
        self._points[particle.name] = particle
        self._particles += (particle,)
