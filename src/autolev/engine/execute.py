"""Executing a prepared CODE command: computing it (integrated, evaluated or solved)
and writing its set of files.  No sympy: a warm run executes its run plan's commands
with this alone (run.py prepares them from the model).
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .code_kinds import CodeKind
from .algebraic import AlgebraicInputs, run_algebraic
from .dynamics import run_dynamics
from .files import (RunFiles, check_memory, check_room, dir_text, encoded_text,
                    termination_cleans_up, writing_into)
from .integrators import Integrator
from .options import RunOptions
from .results import Result


@dataclass
class Execution:
    """A prepared CODE command, as its run computes and writes it: the system (a
    NumericSystem, or a run plan's) and inputs it runs on, and what its files hold
    besides the rows."""

    kind: CodeKind
    stem: str
    filename: str               # the CODE command's, as written
    program_file: str           # the program's file name (NAME.c), as the .dir names it
    system: object
    inputs: object              # Inputs, or a run plan's PlannedInputs
    state_names: list
    given: dict                 # input name -> its value as given
    columns: list               # (labels, units) of each output file
    in_text: str                # NAME.in with the run's values (when it writes files)
    encoded: list               # the ENCODE names (NAME.encode)
    rows_expected: int
    language: str               # of Autolev's program: "c", "m", "f"...
    integrator: Integrator | None   # what an integration steps with (None: no integration)
    algebraic: AlgebraicInputs | None   # what ALGEBRAIC/NONLINEAR evaluate with
    build_seconds: float
    # (T, message) of the integration failure a run plan's run ended with: its advice
    # read the model, which the plan's replay does not have
    known_failure: tuple | None = None
    # from the model, for an integration (run_dynamics): the projection onto
    # configuration constraints, and the advice of a failure (a plan has neither)
    projector: object = None
    advise: object = None


def execute(execution: Execution, out_dir=None,
            options: RunOptions = RunOptions()) -> Result:
    """Compute a prepared command and write its files into out_dir (see run_command)."""
    e = execution
    system, inputs, kind, stem = e.system, e.inputs, e.kind, e.stem
    if options.keep_rows:
        check_memory(e.rows_expected, system.nstate + sum(len(labels)
                                                          for labels, _ in e.columns))
    result = Result(kind, stem, np.zeros(0), np.zeros((0, system.nstate)),
                    list(e.state_names), [], {}, dict(e.given), system=system,
                    execution=e)
    result.stats["build_seconds"] = e.build_seconds

    def perform(writer):
        if kind.integrates:
            run_dynamics(system, inputs, result, writer, e.integrator, options.progress,
                         options.compiled, e.projector, e.advise, program=e.language,
                         keep_rows=options.keep_rows, known_failure=e.known_failure)
        else:
            run_algebraic(system, e.algebraic, result, writer, kind, options.keep_rows,
                          options.progress)

    if out_dir is None:
        perform(None)
        return result
    folder = Path(out_dir)
    own_in = folder / f"{stem}.in"
    with termination_cleans_up():
        with writing_into(folder):
            run_files = RunFiles(folder, stem, options.overwrite)
        writes_in = options.infile is None or \
            Path(options.infile).resolve() != own_in.resolve()
        try:
            with writing_into(folder):
                check_room(folder, e.rows_expected, [len(labels) for labels, _ in e.columns])
                run_files.claim([own_in.name] * writes_in + [f"{stem}.dir", f"{stem}.encode"]
                                + [f"{stem}.{k}" for k in range(1, len(e.columns) + 1)])
                if writes_in:
                    run_files.text(own_in.name, e.in_text)
                writer = run_files.tables(e.columns)
            # the computing is outside: its own OSError (a compiler the machine cannot
            # start) is not the folder's; the writer says its own failures as the folder's
            perform(writer)
            with writing_into(folder):
                extra_files = []
                if e.encoded:
                    run_files.text(f"{stem}.encode",
                                   encoded_text(list(result.encoded.items())))
                    extra_files.append((f"{stem}.encode", ",".join(e.encoded)))
                # the `.dir` names the program whose files these are
                run_files.text(f"{stem}.dir", dir_text(
                    stem, e.program_file,
                    [labels for labels, _ in e.columns], extra_files))
                result.files = run_files.commit()
        except BaseException:
            run_files.discard()
            raise
        finally:
            run_files.release()
    return result
