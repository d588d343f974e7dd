"""The kinds of program a CODE command writes, and the integration parameters its
INPUT gives (no sympy: a warm run from its run plan reads them)."""
from __future__ import annotations

from enum import Enum

INTEGRATION_PARAMETERS = ("TINITIAL", "TFINAL", "INTEGSTP", "PRINTINT", "ABSERR", "RELERR")


class CodeKind(str, Enum):
    """The kind of program a CODE command names; a str, so "dynamics" is DYNAMICS."""

    DYNAMICS = "dynamics"
    ALGEBRAIC = "algebraic"
    NONLINEAR = "nonlinear"
    ODE = "ode"

    def __str__(self) -> str:      # "dynamics" in messages, on every Python version
        return self.value

    @property
    def integrates(self) -> bool:
        """Whether its program integrates differential equations over time."""
        return self in (CodeKind.DYNAMICS, CodeKind.ODE)

    @property
    def solves(self) -> bool:
        """Whether its program solves equations for unknowns (ALGEBRAIC, NONLINEAR)."""
        return not self.integrates

    @property
    def from_guesses(self) -> bool:
        """Whether its unknowns start from INPUT guesses (Newton's method)."""
        return self is CodeKind.NONLINEAR
