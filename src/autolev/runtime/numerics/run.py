"""Running a CODE command: DYNAMICS, ODE, ALGEBRAIC (with its input sweep), NONLINEAR.

`run_command` is what `autolev run`, `python model.py` and `Model.simulate` do: build
the numeric system, take the inputs (INPUT values, then an `.in` file, then
overrides), run, and write Autolev's files (`NAME.in`, `NAME.1..k`, `NAME.dir`, and
`NAME.encode` when there are ENCODE quantities) into the output folder.
"""
from __future__ import annotations

from .algebraic import algebraic_inputs
from .command import program_file_name, program_language, program_method
from .dynamics import print_schedule
from .execute import Execution, execute
from .inputs import display_name
from .options import RunOptions
from .prepare import prepare_command
from .results import Result


def run_command(model, command, out_dir=None,
                options: RunOptions = RunOptions()) -> Result:
    """Run one CODE command with `options` (see RunOptions); its files go to out_dir
    (None: no files), written as one set: a file there that autolev did not write
    stops the run before it computes anything, unless `options.overwrite`."""
    kind = command.kind
    method = options.method or program_method(command.filename)
    # an integration may start on the Python while the C compiles, but DOP853 in the
    # compiled loop (run_dynamics) and a projection onto constraints
    starts_now = (kind.integrates and not options.constraints
                  and not (method == "dop853" and options.compiled))
    prepared = prepare_command(model, command, options, out_dir=out_dir,
                               starts_now=starts_now)
    system, inputs = prepared.system, prepared.inputs
    language = program_language(command.filename)
    zero_params = [display_name(p) for p in system.params if inputs.internal(p) == 0.0]
    execution = Execution(
        kind, prepared.stem, command.filename, program_file_name(command.filename), system,
        inputs, [display_name(x) for x in system.states],
        {display_name(k): inputs.values[k].given for k in inputs.names}, zero_params,
        [([c.label for c in cols], [c.unit for c in cols]) for cols in prepared.files],
        inputs.file_text(f"{prepared.stem}.in", prepared.kinds) if out_dir is not None else "",
        [name for name, _ in prepared.encoded], _rows_expected(prepared, command), language,
        method, inputs.vector(prepared.extra_constants),
        None if kind.integrates else algebraic_inputs(
            system, inputs, kind, prepared.unknowns, prepared.sweep, zero_params),
        prepared.build_seconds)
    return execute(execution, out_dir, options)


def _rows_expected(prepared, command) -> int:
    """The rows each table of the run will have, known before it computes."""
    if command.kind.integrates:
        return print_schedule(prepared.inputs,
                              program_language(command.filename)).printed_rows()
    return 1 if prepared.sweep is None else prepared.sweep.count
