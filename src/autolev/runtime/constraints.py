"""A model's constraints: the speeds CONSTRAIN made dependent or auxiliary, the
equations it solved, and the speeds' derivatives SOLVE defined (a part of Model,
changed only through its methods)."""
from __future__ import annotations

from dataclasses import dataclass

from .derived import Owned, mutation


@dataclass(frozen=True)
class SolvedRates:
    """A SOLVE that defined generalized speeds' derivatives (SOLVE(ZERO, U4', U6')): the
    derivatives, the equations (each = 0) it solved for them, and their definitions."""

    unknowns: tuple
    equations: tuple
    solution: tuple


class Constraints(Owned):
    """What decides which speeds are dependent, auxiliary or SOLVE's, in order."""

    def __init__(self, revision) -> None:
        super().__init__(revision)
        self._dependent: tuple = ()
        self._auxiliary: tuple = ()
        # the equations (each = 0) CONSTRAIN(DEPENDENT[...]) solved, as given
        self._dependent_equations: tuple = ()
        # speeds whose derivatives SOLVE defined: still speeds, not coordinates
        self._solved_speeds: frozenset = frozenset()
        # the SOLVEs that defined them, in order (a run solves their equations by LU)
        self._solved_rates: tuple[SolvedRates, ...] = ()

    @property
    def dependent_speeds(self) -> tuple:
        return self._dependent

    @property
    def auxiliary_speeds(self) -> tuple:
        return self._auxiliary

    @property
    def dependent_constraints(self) -> tuple:
        return self._dependent_equations

    @property
    def solved_speeds(self) -> frozenset:
        return self._solved_speeds

    @property
    def solved_rates(self) -> tuple:
        return self._solved_rates

    @mutation
    def add_dependent(self, equations, speeds) -> None:
        self._dependent_equations += tuple(equations)
        self._dependent += tuple(s for s in dict.fromkeys(speeds) if s not in self._dependent)

    @mutation
    def add_auxiliary(self, speeds) -> None:
        self._auxiliary += tuple(s for s in dict.fromkeys(speeds) if s not in self._auxiliary)

    @mutation
    def keep_speeds(self, speeds) -> None:
        """Speeds whose derivatives SOLVE defined, which stay speeds."""
        self._solved_speeds |= frozenset(speeds)

    @mutation
    def add_solved_rates(self, rates: SolvedRates) -> None:
        self._solved_rates += (rates,)
