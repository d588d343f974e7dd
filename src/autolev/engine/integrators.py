"""The integrators a run can ask for (`--method NAME`, `method="NAME"`), one record each
in one table, as scipy's `solve_ivp` keeps its METHODS and pydy's System its
`ode_solver`.  What differs between them is declared here, and no other module names
one (tests/engine/test_integrators.py).

The records say which of the engine's ways of stepping runs each (integrate.py):
Autolev's Kutta-Merson (`KuttaMerson`; loop.c's method 0), scipy's solver classes by
name, and in the compiled loop DOP853 (method 1) and RK45 started afresh over every
INTEGSTP (method 2; `RK45Interval` in Python).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from . import dop853_tableau, rk45_tableau

if TYPE_CHECKING:
    from .integrate import Schedule


@dataclass(frozen=True)
class Integrator:
    """One integrator.  `loose_relerr`: the RELERR at and above which it is known to
    give qualitatively wrong motion over long runs (integration_notes warns there);
    `kutta_merson`: Autolev's Kutta-Merson, each call advancing exactly INTEGSTP, its
    own step halved on a failed error test and doubled within INTEGSTP;
    `loop_afresh_only`: the compiled loop runs it only started afresh over every
    INTEGSTP (Autolev's Matlab loop), as `RK45Interval` computes it in Python;
    `switches_when_stiff`: the compiled loop's stiffness test stops it, and the run
    goes on with the method integration_notes.switch_when_stiff chooses."""

    name: str                           # as asked for: --method NAME, method="NAME"
    loose_relerr: float
    kutta_merson: bool = False
    scipy_name: str | None = None       # its scipy.integrate solver class
    loop_code: int | None = None        # loop.c's number for it (None: not in the loop)
    loop_afresh_only: bool = False
    switches_when_stiff: bool = False
    tableau: tuple = ()                 # the coefficients loop.c reads, in its order

    @property
    def stepped(self) -> bool:
        """Whether in the compiled loop its rows come after every INTEGSTP step of
        Autolev's loop, each step's numbers those of its Python twin (`KuttaMerson`,
        `RK45Interval`), rather than at print times inside its own steps."""
        return self.kutta_merson or self.loop_afresh_only

    def in_loop(self, schedule: Schedule) -> bool:
        """Whether the compiled loop runs it on `schedule`."""
        return self.loop_code is not None and (schedule.restart_each_step
                                               or not self.loop_afresh_only)

    def hands_over(self, schedule: Schedule) -> bool:
        """Whether the compiled loop goes on from any step Python took (a cold run
        steps in Python while its C compiles)."""
        return self.stepped and self.in_loop(schedule)

    @property
    def waits_for_loop(self) -> bool:
        """Whether a run that has a compiled loop waits for its C: the loop runs it,
        and Python's steps (scipy's, summed in another order) cannot be handed to it."""
        return self.loop_code is not None and not self.stepped


# RELERR limits: the relative energy error of the conservative double pendulum over
# 100 s (Q1 = 30 deg, Q2 = 60 deg; bench/work_precision.py) exceeds 1 % there --
# RK23 1.5 % at 1e-4; RK45 8.8 %, LSODA 4.3 %, BDF 11 % at 1e-3 (steps not bounded by
# INTEGSTP); Radau, DOP853 and Kutta-Merson stay below 0.1 % at 1e-3.
KUTTA_MERSON = Integrator("kutta-merson", 1e-2, kutta_merson=True, loop_code=0)
RK45 = Integrator("rk45", 1e-3, scipy_name="RK45", loop_code=2, loop_afresh_only=True,
                  tableau=rk45_tableau.A + rk45_tableau.B + rk45_tableau.C
                  + rk45_tableau.E)
DOP853 = Integrator("dop853", 1e-2, scipy_name="DOP853", loop_code=1,
                    switches_when_stiff=True,
                    tableau=dop853_tableau.A + dop853_tableau.B + dop853_tableau.C
                    + dop853_tableau.E3 + dop853_tableau.E5 + dop853_tableau.D)
RADAU = Integrator("radau", 1e-2, scipy_name="Radau")
BDF = Integrator("bdf", 1e-3, scipy_name="BDF")
LSODA = Integrator("lsoda", 1e-3, scipy_name="LSODA")
RK23 = Integrator("rk23", 1e-4, scipy_name="RK23")

INTEGRATORS = (KUTTA_MERSON, RK45, DOP853, RADAU, BDF, LSODA, RK23)
METHODS = tuple(integrator.name for integrator in INTEGRATORS)
# scipy's solver class names by ours
SCIPY_METHODS = {i.name: i.scipy_name for i in INTEGRATORS if i.scipy_name is not None}
_BY_NAME = {integrator.name: integrator for integrator in INTEGRATORS}


def integrator_named(name: str) -> Integrator:
    """The integrator of that name, in any case (ValueError naming the others)."""
    found = _BY_NAME.get(name.lower())
    if found is None:
        raise ValueError(f"unknown integrator {name!r} (one of {', '.join(METHODS)})")
    return found


def of_program(language: str) -> Integrator:
    """The integrator of the program Autolev wrote in that language ("c", "m", "f",
    ...): Matlab's programs call ode45 (Dormand-Prince 5(4), which is scipy's RK45),
    the C and Fortran ones their Kutta-Merson."""
    return RK45 if language == "m" else KUTTA_MERSON


def scipy_stand_in(integrator: Integrator) -> Integrator:
    """The solver a script without autolev integrates with in place of `integrator`:
    itself where scipy has it, else DOP853 (an embedded pair with error control, as
    Kutta-Merson is, of higher order)."""
    return integrator if integrator.scipy_name is not None else DOP853


def for_run(name: str | None, language: str) -> Integrator:
    """The integrator a run asked for by name, else (no name) that of Autolev's
    program in that language."""
    return integrator_named(name) if name else of_program(language)
