"""A model's equations of motion as CasADi functions (the `casadi` extra): the explicit
f(x, u, p, t) and the implicit residual r(x, x', u, p, t) of numerics/dynamics.py,
built as CasADi's symbolic graph (SX) from the model's own expressions, so that CasADi
differentiates them exactly (its algorithmic differentiation, with sparsity), maps them
over collocation nodes and hands them to IPOPT.

The graph is built by the program the runs compile, printed for CasADi
(printer.CasadiPrinter) and run once on SX symbols: the same definitions, in the same
order, with the same functions of engine/functions.py.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from . import codegen
from ..printer import CasadiPrinter


@dataclass
class CasadiDynamics:
    """`f`: casadi.Function (x, u, p, t) -> xdot; `residual`: casadi.Function (x, xdot,
    u, p, t) -> r (0 on the motion; linear in xdot: no mass matrix solved).  Inputs and
    outputs are column vectors named as the fields below; `f.map(N)` and
    `residual.map(N)` evaluate N nodes, `casadi.jacobian` or an NLP solver's own
    derivatives give the exact sparse Jacobians."""

    f: object
    residual: object
    states: list
    controls: list
    parameters: list
    parameter_values: list
    source: str             # the printed program that built them (Python on casadi)


def casadi_dynamics(system, given: dict, control_positions: list,
                    names: dict) -> CasadiDynamics:
    """The CasADi form of a numeric system's equations (see the module's text): `given`,
    the program's inputs {"t", "x", "p", "s"} (Dynamics._given); `control_positions`:
    where in "s" the controls are (the rest is 0); `names`: {"states", "controls",
    "parameters"}: display names, and "values": p's."""
    try:
        import casadi as ca
    except ImportError:
        raise ModuleNotFoundError("the CasADi form needs casadi: pip install "
                                  "'autolev[casadi]'") from None
    nx, n = system.nstate, len(system.implicit_unknowns)
    program = codegen.Program(given, list(system.rhs_exprs), system.defs,
                              dict(system.aux_fixed)).build(factored=False)
    source = codegen.python_source(program, "autolev_casadi", printer=CasadiPrinter)
    namespace = {"ca": ca, "math": math}
    exec(compile(source, "<autolev casadi>", "exec"), namespace)
    x, xdot = ca.SX.sym("x", nx), ca.SX.sym("xdot", nx)
    u, p, t = (ca.SX.sym("u", len(control_positions)), ca.SX.sym("p", len(given["p"])),
               ca.SX.sym("t"))
    inputs = [0.0] * len(given["s"])
    for k, position in enumerate(control_positions):
        inputs[position] = u[k]
    out = [None] * len(system.rhs_exprs)
    namespace["autolev_casadi"]([t], [x[i] for i in range(nx)],
                                [p[i] for i in range(len(given["p"]))], inputs, out)
    dynamic = list(system.unknown_positions)
    mass = ca.SX(n, n)
    for k in range(n * n):
        mass[k // n, k % n] = out[nx + k]
    forcing = ca.vertcat(*out[nx + n * n:nx + n * n + n]) if n else ca.SX(0, 1)
    rates = [out[i] for i in range(nx)]
    rows = [xdot[i] - out[i] for i in range(nx)]
    if n:
        accelerations = ca.solve(mass, forcing)
        moved = ca.mtimes(mass, ca.vertcat(*[xdot[i] for i in dynamic])) - forcing
        for k, i in enumerate(dynamic):
            rates[i] = accelerations[k]
            rows[i] = moved[k]
    f = ca.Function("f", [x, u, p, t], [ca.vertcat(*rates)], ["x", "u", "p", "t"], ["xdot"])
    residual = ca.Function("residual", [x, xdot, u, p, t], [ca.vertcat(*rows)],
                           ["x", "xdot", "u", "p", "t"], ["r"])
    return CasadiDynamics(f, residual, names["states"], names["controls"],
                          names["parameters"], list(names["values"]), source)
