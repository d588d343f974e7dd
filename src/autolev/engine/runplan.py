"""Run plans: a warm `autolev run FILE` without the model.

A run without an animation whose every CODE command was computed (integrated in the
compiled loop, to its end or to the failure of its integration, or evaluated and
solved: ALGEBRAIC, NONLINEAR) leaves a plan in the cache for its request
(`request.RunRequest`: every option that can change what it computes, and the model and
--in file by their digests as the run read them): per command, its compiled system as
numbers and sources (C, whose libraries are found again in the build cache, or
Python), its inputs as numbers, the texts of its files besides the rows, the message
of its failure, and what the run printed on stderr (notes, warnings).  With it go the
digests of every file the run read, taken when it read them (`reading.py`).  The
next run with the same request, while each of those files is as it was read, repeats
the run from the plan and writes the same files (and the tables and plots asked for,
from its rows), importing no sympy (scipy only for what needs it: a scipy method, a
.mat file) and translating nothing.  Anything else runs from the model.

A run that writes no file repeats what it printed and its exit status: a model without
a CODE command (the responses Autolev displayed) or one refused before any command ran
(its diagnostics).  A linearization (`autolev linearize FILE`, no sweep) keeps its
answer the same way, and `autolev transcript` its text.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .reading import ReadSet
from .code_kinds import INTEGRATION_PARAMETERS
from .evaluation import CompiledEvaluation
from .execute import Execution
from .linear import Linearization
from .results import Column


class PlannedInputs:
    """A run's inputs as numbers: the integration parameters and the initial state."""

    def __init__(self, integration: dict, initial):
        self.integration = dict(integration)
        self.initial = [float(v) for v in initial]

    def internal(self, key) -> float:
        return self.integration[key]

    def vector(self, keys) -> list[float]:
        """The initial state (a plan's system asks for nothing else)."""
        return list(self.initial)


class PlannedSystem(CompiledEvaluation):
    """A NumericSystem's compiled functions, names and numbers, without its model
    (`states`: the state's names)."""

    def __init__(self, system, state_names: list, sweeps_constants: bool):
        self.states = list(state_names)
        self.nstate, self._n = system.nstate, system._n
        self.unknown_positions = list(system.unknown_positions)
        self.mass_structure = system.mass_structure
        self.n_rhs, self.n_outputs = system.n_rhs, system.n_outputs
        self.pivot_count = system.pivot_count
        self.files = [[Column(None, c.label, c.unit) for c in cols] for cols in system.files]
        self.degree_columns = [list(d) for d in system.degree_columns]
        self.encode_shapes = list(system.encode_shapes)
        # an algebraic program's outputs walked first: compiled, read back without sympy
        self.rhs_function = system.rhs_function
        self.output_function = system.output_function.compiled()
        self.rhs_compiling = self.outputs_compiling = None
        self.extra_functions = dict(system.extra_functions)
        # only a sweep of a constant evaluates them again: then compiled Python, which
        # reads back without sympy (a first evaluation's walk needs the expressions)
        self.constants_function = (system.constants_function.compiled() if sweeps_constants
                                   else None)
        self.derived_constants = system.derived_constants
        self.solved = [str(s) for s in system.solved]     # ALGEBRAIC's unknowns, by name
        self.specified_functions = []
        self.specified_values = np.array(system.specified_values, dtype=float)
        self.constant_values = np.array(system.constant_values, dtype=float)
        self._bind_loop()
        self.set_constant_values(self.constant_values)


@dataclass
class PlannedCommand:
    execution: Execution        # its system a PlannedSystem, its inputs PlannedInputs
    label: str                  # file:line of its CODE statement, for its messages
    messages: str               # what its run printed on stderr


@dataclass
class RunPlan:
    reads: ReadSet              # every file the run read, as it read it
    load_messages: str          # what loading the model printed on stderr
    commands: list


@dataclass
class KeptOutcome:
    """A run that wrote no file, for its options: what it printed and its exit status.
    Nothing outside the model's files decided it (no disk, no compiler, no values)."""

    reads: ReadSet              # every file the run read, as it read it
    messages: str               # what it printed on stderr (notes, diagnostics)
    transcript: str             # what it printed on stdout: the responses, or nothing
    status: int


@dataclass
class KeptLinearization:
    """The answer of `autolev linearize FILE` for its options (no sweep): the same
    file, files read and options give the same numbers, so the next such command
    reports it again without the model (BICYCLE14: 1.6 s of reading the model back and
    importing sympy and scipy, for a 10-state answer)."""

    reads: ReadSet              # every file the linearization read, as it read it
    load_messages: str          # what loading the model printed on stderr
    messages: str               # what the linearization printed on stderr
    linearization: Linearization


def can_plan(execution: Execution, result) -> bool:
    """Whether a command's run can be repeated from a plan: it used no user functions;
    integrated, in the compiled loop (its right-hand side C) with C outputs (`autolev
    run` projects onto no constraints).  An integration that failed fails again at the
    same step (the loop's numbers are the Python's to the last bit): its message is
    kept."""
    system = execution.system
    if system.specified_functions or execution.projector is not None:
        return False
    return not execution.kind.integrates or (
        system.loop is not None and system.output_function.backend == "c"
        and not system.extra_functions)


def planned_command(execution: Execution, result, label: str,
                    messages: str) -> PlannedCommand:
    """The command's execution with its system and inputs reduced to numbers."""
    inputs = execution.inputs
    integrates = execution.kind.integrates     # ALGEBRAIC's numbers: execution.algebraic
    integration = {k: inputs.internal(k) for k in INTEGRATION_PARAMETERS} if integrates \
        else {}
    initial = inputs.vector(execution.system.states) if integrates else []
    sweeps = execution.algebraic is not None and execution.algebraic.swept is not None
    failure = None if result.failure is None else (result.failure_time, result.failure)
    reduced = replace(execution, system=PlannedSystem(execution.system,
                                                      execution.state_names, sweeps),
                      inputs=PlannedInputs(integration, initial), build_seconds=0.0,
                      known_failure=failure, projector=None, advise=None)
    return PlannedCommand(reduced, label, messages)


