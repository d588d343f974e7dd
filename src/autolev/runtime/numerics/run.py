"""Running a CODE command: DYNAMICS, ODE, ALGEBRAIC (with its input sweep), NONLINEAR.

`run_command` is what `autolev run`, `python model.py` and `Model.simulate` do: build
the numeric system, take the inputs (INPUT values, then an `.in` file, then
overrides), run, and write Autolev's files (`NAME.in`, `NAME.1..k`, `NAME.dir`, and
`NAME.encode` when there are ENCODE quantities) into the output folder.
"""
from __future__ import annotations

import warnings

from ...engine.algebraic import AlgebraicInputs, SweepPoints
from ...engine.code_kinds import CodeKind
from ...engine.dynamics import print_schedule
from ...engine.errors import AutolevModelError
from ...engine.execute import Execution, execute
from ...engine.integrators import Integrator, for_run
from ...engine.options import RunOptions
from ...engine.results import Result
from .. import symbols as S
from .. import units
from .advice import failure_message, zero_hint
from .command import program_file_name, program_language
from .inputs import display_name
from .prepare import prepare_command
from .snapshot import ModelSnapshot


def run_command(snapshot: ModelSnapshot, out_dir=None,
                options: RunOptions = RunOptions()) -> Result:
    """Run the CODE command of `snapshot` (Model.snapshot_for) with `options` (see
    RunOptions); its files go to out_dir (None: no files), written as one set: a file
    there that autolev did not write stops the run before it computes anything, unless
    `options.overwrite`."""
    command = snapshot.command
    kind = command.kind
    language = program_language(command.filename)
    integrator = _integrator(options.method, language) if kind.integrates else None
    # an integration may start on the Python while the C compiles, but not one that
    # waits for the compiled loop (run_dynamics) nor a projection onto constraints
    starts_now = (kind.integrates and not options.constraints
                  and not (integrator.waits_for_loop and options.compiled))
    prepared = prepare_command(snapshot, command, options, out_dir=out_dir,
                               starts_now=starts_now)
    system, inputs = prepared.system, prepared.inputs
    zero_params = [display_name(p) for p in system.params if inputs.internal(p) == 0.0]

    def advise(failure, result, integration) -> str:
        return failure_message(failure, snapshot, system, inputs, result, zero_params,
                               integration)
    execution = Execution(
        kind, prepared.stem, command.filename, program_file_name(command.filename), system,
        inputs, [display_name(x) for x in system.states],
        {display_name(k): inputs.values[k].given for k in inputs.names},
        [([c.label for c in cols], [c.unit for c in cols]) for cols in prepared.files],
        inputs.file_text(f"{prepared.stem}.in", prepared.kinds) if out_dir is not None else "",
        [name for name, _ in prepared.encoded], _rows_expected(prepared, command), language,
        integrator,
        None if kind.integrates else algebraic_inputs(
            system, inputs, kind, prepared.unknowns, prepared.sweep, zero_params),
        prepared.build_seconds,
        projector=_projector(system, inputs, options.constraints, prepared, language)
        if kind.integrates else None,
        advise=advise if kind.integrates else None)
    return execute(execution, out_dir, options)


def _integrator(name: str | None, language: str) -> Integrator:
    """The integrator asked for by name, else that of Autolev's program in `language`;
    an unknown name is the run's error."""
    try:
        return for_run(name, language)
    except ValueError as exc:
        raise AutolevModelError(str(exc)) from None


def _projector(system, inputs, constraints, prepared, language):
    """The projection onto the configuration `constraints` at each print time, or None
    (projection works on the model's expressions: imported only when asked for)."""
    if not constraints:
        return None
    from .projection import Projector
    return Projector(system, constraints, print_schedule(inputs, language).tinitial,
                     inputs.vector(system.states), inputs.vector(prepared.extra_constants))


def algebraic_inputs(system, inputs, kind, unknowns, sweep, zero_params) -> AlgebraicInputs:
    """The numbers of an evaluation from the run's inputs (warning when the swept
    input does not enter the outputs)."""
    swept = None
    if sweep is not None:
        if sweep.target in system.params:
            swept = system.params.index(sweep.target)
        else:
            warnings.warn(f"the swept input {display_name(sweep.target)} does not enter the "
                          "outputs", stacklevel=3)
    return AlgebraicInputs(
        inputs.internal(S.TIME) if S.TIME in inputs.values else 0.0,
        list(inputs.vector(system.params)),
        list(inputs.vector(unknowns)) if kind.from_guesses else [0.0] * len(unknowns),
        *((inputs.internal("ABSERR"), inputs.internal("RELERR"))
          if kind is CodeKind.NONLINEAR else (0.0, 0.0)),
        [display_name(u) for u in unknowns], swept,
        None if sweep is None else SweepPoints(sweep.start, sweep.step, sweep.count,
                                               units.is_degrees(sweep.unit)),
        zero_hint(zero_params))


def _rows_expected(prepared, command) -> int:
    """The rows each table of the run will have, known before it computes."""
    if command.kind.integrates:
        return print_schedule(prepared.inputs,
                              program_language(command.filename)).printed_rows()
    return 1 if prepared.sweep is None else prepared.sweep.count
