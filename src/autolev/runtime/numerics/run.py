"""Running a CODE command: DYNAMICS, ODE, ALGEBRAIC (with its input sweep), NONLINEAR.

`run_command` is what `autolev run`, `python model.py` and `Model.simulate` do: build
the numeric system, take the inputs (INPUT values, then an `.in` file, then
overrides), run, and write Autolev's files (`NAME.in`, `NAME.1..k`, `NAME.dir`, and
`NAME.encode` when there are ENCODE quantities) into the output folder.
"""
from __future__ import annotations

from contextlib import contextmanager
from pathlib import Path

import numpy as np

from ..errors import AutolevModelError
from .algebraic import run_algebraic
from .command import program_file_name, program_language, program_method
from .dynamics import print_schedule, run_dynamics
from .files import RunFiles, check_room, dir_text, encoded_text, termination_cleans_up
from .inputs import display_name
from .options import RunOptions
from .prepare import prepare_command
from .results import Result


def run_command(model, command, out_dir=None,
                options: RunOptions = RunOptions()) -> Result:
    """Run one CODE command with `options` (see RunOptions); its files go to out_dir
    (None: no files), written as one set: a file there that autolev did not write
    stops the run before it computes anything, unless `options.overwrite`."""
    prepared = prepare_command(model, command, options, out_dir=out_dir)
    system, inputs, kinds = prepared.system, prepared.inputs, prepared.kinds
    kind, stem, files, encoded = command.kind, prepared.stem, prepared.files, prepared.encoded
    method = options.method or program_method(command.filename)
    zero_params = [display_name(p) for p in system.params if inputs.internal(p) == 0.0]
    result = Result(kind, stem, np.zeros(0), np.zeros((0, system.nstate)),
                    [display_name(x) for x in system.states], [], {},
                    {display_name(k): inputs.values[k].given for k in inputs.names},
                    system=system)
    result.stats["build_seconds"] = prepared.build_seconds

    def perform(writer):
        if kind.integrates:
            run_dynamics(system, inputs, result, writer, method, options.progress,
                         zero_params, options.compiled, options.constraints,
                         inputs.vector(prepared.extra_constants),
                         program=program_language(command.filename),
                         keep_rows=options.keep_rows)
        else:
            run_algebraic(system, inputs, result, writer, kind, prepared.unknowns,
                          prepared.sweep, zero_params, options.keep_rows)

    if out_dir is None:
        perform(None)
        return result
    folder = Path(out_dir)
    own_in = folder / f"{stem}.in"
    with termination_cleans_up():
        with _writing(folder):
            run_files = RunFiles(folder, stem, options.overwrite)
        writes_in = options.infile is None or \
            Path(options.infile).resolve() != own_in.resolve()
        try:
            with _writing(folder):
                check_room(folder, _rows_expected(prepared, command),
                           [len(cols) for cols in files])
                run_files.claim([own_in.name] * writes_in + [f"{stem}.dir", f"{stem}.encode"]
                                + [f"{stem}.{k}" for k in range(1, len(files) + 1)])
                if writes_in:
                    run_files.text(own_in.name, inputs.file_text(own_in.name, kinds))
                writer = run_files.tables([([c.label for c in cols], [c.unit for c in cols])
                                           for cols in files])
                perform(writer)          # rows are written as they come (a full disk, too)
                extra_files = []
                if encoded:
                    run_files.text(f"{stem}.encode",
                                   encoded_text(list(result.encoded.items())))
                    extra_files.append((f"{stem}.encode", ",".join(n for n, _ in encoded)))
                # the `.dir` names the program whose files these are
                run_files.text(f"{stem}.dir", dir_text(
                    stem, program_file_name(command.filename),
                    [[c.label for c in cols] for cols in files], extra_files))
                result.files = run_files.commit()
        except BaseException:
            run_files.discard()
            raise
        finally:
            run_files.release()
    return result


def _rows_expected(prepared, command) -> int:
    """The rows each table of the run will have, known before it computes."""
    if command.kind.integrates:
        return print_schedule(prepared.inputs,
                              program_language(command.filename)).printed_rows()
    return 1 if prepared.sweep is None else prepared.sweep.count


@contextmanager
def _writing(folder: Path):
    """A failure of the disk (a read-only or full folder, a file where the folder
    should be) as one message naming the place, not a traceback."""
    try:
        yield
    except OSError as exc:
        where = exc.filename or folder
        raise AutolevModelError(f"cannot write the output files into {folder}: "
                                f"{exc.strerror or exc} ({where})") from None
