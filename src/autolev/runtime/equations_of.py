"""The equations of motion `autolev run` integrates for a CODE DYNAMICS or ODE, as sympy
expressions: the state, its rates, the mass matrix and forcing the other rates are
solved from, and every intermediate (Z's, definitions) in the order it is computed.
Read from the command's NumericSystem, so what is exported or printed is what runs.
"""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sm

from . import symbols as S
from . import units
from ..engine.errors import AutolevModelError


@dataclass(frozen=True)
class Equations:
    """What the script holds: a CODE command's equations, values and outputs."""

    model_name: str
    command: str
    states: list            # our symbols, in the run's order
    rates: list             # each state's rate, None where it is solved
    unknowns: list          # the derivatives solved from mass * unknowns = forcing
    mass: list              # rows of the mass matrix
    forcing: list
    definitions: list       # (symbol, expression), dependencies first
    constants: dict         # symbol -> value (SI units, radians); None: no value given
    initial: dict           # state -> value
    specified: list         # symbols given as functions of time
    integration: dict       # TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, RELERR
    outputs: list           # (label, unit, expression, in degrees)
    method: str             # the scipy solver standing for the program's integrator
    method_reason: str      # why that one


def equations_of(model, command, values: bool = True, infile=None,
                 overrides=None, missing_values: str = "refuse") -> Equations:
    """The equations, values and outputs `autolev run` uses for an integrating CODE
    command (DYNAMICS or ODE), its values taken as a run takes them (INPUT, then the .in
    file `infile`, then `overrides` in the quantities' units); without `values`, the
    equations alone (no constant needs a value; constants, initial values and
    integration are left empty).  `missing_values`: "refuse" (a constant without a
    value is refused, as a run refuses it) or "keep" (its value is None)."""
    from .numerics.command import (equations_and_unknowns, output_columns, program_language,
                                   program_of)
    from ..engine.integrators import of_program, scipy_stand_in
    from ..engine.files import safe_stem
    from .numerics.inputs import DEFAULT_SOURCE
    from .numerics.prepare import InputsWanted, SystemBuild, numeric_system, take_inputs

    kind = command.kind
    if not kind.integrates:
        raise AutolevModelError(f"CODE {kind.upper()} {command.filename} has no equations "
                                "of motion (those of a CODE DYNAMICS or ODE are written)")
    snapshot = model.snapshot_for(command)
    files = output_columns(snapshot, command)
    solving = equations_and_unknowns(command.args, kind.upper())
    system = numeric_system(snapshot, command, files, [], solving,
                            SystemBuild("python", False, (), False))
    ask = InputsWanted(snapshot, command, safe_stem(command.filename), solving[1], infile,
                       overrides, None, None,
                       missing_values, None)
    with model.defs.as_of(program_of(snapshot, command).definitions):
        inputs = take_inputs(ask, system)[0] if values else None
        n = len(system.implicit_unknowns)
        rows, nstate = system.rhs_exprs, system.nstate
        solved = {state_of(u) for u in system.implicit_unknowns}
        rates = [None if x in solved else sm.sympify(rows[k])
                 for k, x in enumerate(system.states)]
        mass = [[sm.sympify(e) for e in rows[nstate + r * n:nstate + (r + 1) * n]]
                for r in range(n)]
        forcing = [sm.sympify(e) for e in rows[nstate + n * n:nstate + n * n + n]]
        columns = [c for cols in system.files for c in cols]
        outputs = [(c.label, c.unit or "", sm.sympify(e), units.is_degrees(c.unit))
                   for c, e in zip(columns, system.output_exprs)]
        roots = [e for e in rates if e is not None] + [e for r in mass for e in r] \
            + forcing + [e for _, _, e, _ in outputs]
        given = set(system.states) | {S.TIME} | set(system.params) | set(system.specified) \
            | set(system.implicit_unknowns)
        order = model.defs.evaluation_order(
            {s for e in roots for s in e.free_symbols}, given)
        # speeds fixed for the run (a locked coordinate's, at 0) first, then what is defined
        definitions = [(s, sm.sympify(v)) for s, v in system.aux_fixed.items()] + \
            [(s, model.defs.rhs[s]) for s in order if s not in system.aux_fixed]
    program = of_program(program_language(command.filename))
    stand_in = scipy_stand_in(program)
    return Equations(
        model_name=model.name, command=f"CODE {kind.upper()} {command.filename}",
        states=list(system.states), rates=rates, unknowns=list(system.implicit_unknowns),
        mass=mass, forcing=forcing, definitions=definitions,
        constants={p: None if inputs.values[p].source == DEFAULT_SOURCE
                   else inputs.internal(p)
                   for p in system.params} if values else {},
        initial={x: inputs.internal(x) for x in system.states} if values else {},
        specified=list(system.specified),
        integration={name: inputs.internal(name) for name in
                     ("TINITIAL", "TFINAL", "INTEGSTP", "ABSERR", "RELERR")}
        | {"PRINTINT": int(inputs.values["PRINTINT"].given)} if values else {},
        outputs=outputs, method=stand_in.scipy_name,
        method_reason=f"the program's own ({program.name})" if stand_in is program
        else f"scipy has no {program.name} (the program's)")


def state_of(unknown):
    """The state whose rate `unknown` is (U1 for U1', X' for X'')."""
    base, order = S.base_and_order(unknown)
    return base if order == 1 else S.derivative(base, order - 1)
