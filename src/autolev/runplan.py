"""Run plans: a warm `autolev run FILE` without the model.

A run without an animation whose every CODE command was computed (integrated in the
compiled loop, to its end or to the failure of its integration, or evaluated and
solved: ALGEBRAIC, NONLINEAR) leaves a plan in the cache, for the options it was given
(values, an .in file by its content, the method...): per command, its compiled system
as numbers and sources (C, whose libraries are found again in the build cache, or
Python), its inputs as numbers, the texts of its files besides the rows, the message
of its failure, and what the run printed on stderr (notes, warnings).  The next run of
the same file with the same options, while the file, every file its translation read
and autolev itself are unchanged (the translation cache's manifest), repeats the run
from the plan and writes the same files (and the tables and plots asked for, from its
rows), importing no sympy (scipy only for what needs it: a scipy method, a .mat file)
and translating nothing.  Anything else runs from the model.

A run that writes no file repeats what it printed and its exit status: a model without
a CODE command (the responses Autolev displayed) or one refused before any command ran
(its diagnostics).  A linearization (`autolev linearize FILE`, no sweep) keeps its
answer the same way, and `autolev transcript` its text.
"""
from __future__ import annotations

import io
import pickle
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from .cachekeys import PLAN_PREFIX, enabled, file_key, manifest
from .runtime import diskcache
from .runtime.code_kinds import INTEGRATION_PARAMETERS
from .runtime.numerics.clibrary import CompileError
from .runtime.numerics.evaluation import CompiledEvaluation
from .runtime.numerics.execute import Execution
from .runtime.numerics.linear import Linearization
from .runtime.numerics.results import Column


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
        self.rhs_function, self.output_function = system.rhs_function, system.output_function
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
    manifest: tuple             # of the files the translation read (cachekeys.manifest)
    load_messages: str          # what loading the model printed on stderr
    commands: list


@dataclass
class KeptOutcome:
    """A run that wrote no file, for its options: what it printed and its exit status.
    Nothing outside the model's files decided it (no disk, no compiler, no values)."""

    manifest: tuple             # of the files the translation read (cachekeys.manifest)
    messages: str               # what it printed on stderr (notes, diagnostics)
    transcript: str             # what it printed on stdout: the responses, or nothing
    status: int


def can_plan(execution: Execution, result) -> bool:
    """Whether a command's run can be repeated from a plan: it used no user functions;
    integrated, in the compiled loop (its right-hand side C) with C outputs (`autolev
    run` projects onto no constraints).  An integration that failed fails again at the
    same step (the loop's numbers are the Python's to the last bit): its message is
    kept."""
    system = execution.system
    if system.specified_functions:
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
                      known_failure=failure)
    return PlannedCommand(reduced, label, messages)


def _entry(path: Path, options: tuple) -> Path | None:
    """The plan's place in the cache for the model file at `path` run with `options`
    (what the command line gave that changes the run, the .in file first: by its
    content too).  None: a file unreadable, or the caches turned off."""
    if not enabled():
        return None
    infile = options[0]
    try:
        raw = path.read_bytes()
        given = Path(infile).read_bytes() if infile is not None else b""
    except OSError:
        return None
    key = file_key("plan", path.resolve(), raw, repr(options).encode("utf-8", "surrogatepass"),
                   given)
    return diskcache.cache_dir() / f"{PLAN_PREFIX}{key[:40]}.pickle"


def write_plan(path: Path, options: tuple, files_read: list, load_messages: str,
               commands: list) -> None:
    """Keep the plan of a run of the model at `path` with `options` (`files_read`: its
    translation's)."""
    _keep(path, options, RunPlan(manifest(path, files_read), load_messages, commands))


def keep_outcome(path: Path, options: tuple, files_read: list, messages: str,
                 transcript: str, status: int) -> None:
    """Keep what a run of the model at `path` with `options` that wrote no file
    printed, and its exit status (`files_read`: every file its translation read)."""
    _keep(path, options, KeptOutcome(manifest(path, files_read), messages, transcript,
                                     status))


def read_plan(path: Path, options: tuple) -> RunPlan | KeptOutcome | None:
    """The plan (or the kept outcome) of the model at `path` run with `options`, while
    it holds, else None."""
    return _kept(path, options, (RunPlan, KeptOutcome))


# a transcript's options: no .in file (the first of a run's options), made by transcript
_TRANSCRIPT = (None, "transcript")


@dataclass
class KeptTranscript:
    """The text of `autolev transcript FILE`: the same files read give the same text."""

    manifest: tuple             # of the files read to make it (cachekeys.manifest)
    text: str


def keep_transcript(path: Path, files_read: list, text: str) -> None:
    """Keep the transcript of the model at `path` (`files_read`: every file read to
    make it)."""
    _keep(path, _TRANSCRIPT, KeptTranscript(manifest(path, files_read), text))


def kept_transcript(path: Path) -> str | None:
    """The transcript of the model at `path`, while every file it read is unchanged."""
    kept = _kept(path, _TRANSCRIPT, KeptTranscript)
    return None if kept is None else kept.text


@dataclass
class KeptLinearization:
    """The answer of `autolev linearize FILE` for its options (no sweep): the same
    file, files read and options give the same numbers, so the next such command
    reports it again without the model (BICYCLE14: 1.6 s of reading the model back and
    importing sympy and scipy, for a 10-state answer)."""

    manifest: tuple             # of the files the translation read (cachekeys.manifest)
    load_messages: str          # what loading the model printed on stderr
    messages: str               # what the linearization printed on stderr
    linearization: Linearization


def keep_linearization(path: Path, options: tuple, files_read: list, load_messages: str,
                       messages: str, linearization: Linearization) -> None:
    _keep(path, options + ("linearize",),
          KeptLinearization(manifest(path, files_read), load_messages, messages,
                            linearization))


def kept_linearization(path: Path, options: tuple) -> KeptLinearization | None:
    """The linearization of the model at `path` with `options`, while it holds."""
    return _kept(path, options + ("linearize",), KeptLinearization)


def _keep(path: Path, options: tuple, kept) -> None:
    entry = _entry(path, options)
    if entry is None:
        return
    try:
        diskcache.install(pickle.dumps(kept, protocol=pickle.HIGHEST_PROTOCOL), entry)
    except OSError:
        return                      # a full or read-only disk: the next run forms its own


def _kept(path: Path, options: tuple, kind: type | tuple):
    """What `_keep` kept for the model at `path` and `options`, while every file its
    translation read is unchanged; else None."""
    entry = _entry(path, options)
    data = None if entry is None else diskcache.read_verified(entry)
    if data is None:
        return None
    try:
        kept = pickle.loads(data)
    except CompileError:
        return None                 # its libraries are gone and no compiler rebuilds them
    if not isinstance(kept, kind) or kept.manifest != manifest(
            path, [name for name, _ in kept.manifest[0]]):
        return None
    return kept


class Recorder(io.TextIOBase):
    """A text stream that writes through to another and keeps what was written."""

    def __init__(self, through):
        self.through = through
        self.kept = io.StringIO()

    def write(self, text: str) -> int:
        self.kept.write(text)
        return self.through.write(text)

    def flush(self) -> None:
        self.through.flush()

    def take(self) -> str:
        """What was written since the last take."""
        text = self.kept.getvalue()
        self.kept = io.StringIO()
        return text
