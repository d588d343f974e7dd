"""Preparing a CODE command's run: its numeric system (built once per revision of
the model), then its inputs (INPUT values, an .in file, overrides), checked
before anything is compiled, then its compiled functions.
"""
from __future__ import annotations

import time
import warnings
from dataclasses import dataclass
from pathlib import Path

from .. import symbols as S
from .. import units
from ...engine.errors import AutolevModelError, MissingValues
from ..io import CodeKind
from ..steps import SlowStep
from .advice import inertia_problems
from .command import (encoded_values, equations_and_unknowns, find_symbol, given_specified,
                      hidden_in_outputs, hidden_note, output_columns, program_file_name,
                      program_of, solution_columns, solved_by_lu, solver_expressions,
                      sweep_values, take_time, time_dependence)
from ...engine.files import safe_stem
from ...errors import some_names
from .inputs import INTEGRATION, Inputs, display_name
from .projection import constants_needed
from .snapshot import ModelSnapshot
from ...engine.options import RunOptions
from ...engine.outputs import Written
from .system import NumericSystem


@dataclass
class Prepared:
    """A CODE command ready to execute: its numeric system (parameters set) and inputs."""

    system: NumericSystem
    inputs: Inputs
    kinds: dict             # input -> "Constant", "Initial Value", ...
    stem: str
    files: list
    encoded: list
    unknowns: list
    sweep: tuple | None
    extra_constants: list
    build_seconds: float


@dataclass
class InputsWanted:
    """What prepare_command was given for the run's inputs."""

    snapshot: ModelSnapshot
    command: object
    stem: str
    unknowns: list
    infile: object
    overrides: dict | None
    internal_values: dict | None
    constraints: object
    missing_values: str     # "refuse", "zero" (0, with a warning) or "keep" (0, silently)
    out_dir: object

    @property
    def integrate_states(self) -> bool:
        return self.command.kind.integrates


def take_inputs(ask: InputsWanted, system):
    """The run's inputs (constants, initial values or guesses, integration
    parameters): INPUT values, then the .in file, then the overrides.  Refuses, before
    anything is compiled, constants that have no value from any of them."""
    extra_constants = (constants_needed(system, ask.constraints)
                       if ask.constraints and ask.integrate_states else [])
    constants = list(system.params) + extra_constants
    kinds = {p: "Constant" for p in constants}
    names = list(constants)
    timed = [] if ask.integrate_states else time_dependence(system)
    if timed:
        names.append(S.TIME)
        kinds[S.TIME] = "Constant"
    if ask.integrate_states:
        names += system.states
        kinds.update({x: "Initial Value" for x in system.states})
        integration = INTEGRATION
    elif ask.command.kind.from_guesses:
        names += ask.unknowns
        kinds.update({u: "Initial Guess" for u in ask.unknowns})
        integration = ("ABSERR", "RELERR")
    else:
        integration = ()
    inputs = Inputs(ask.snapshot.definitions, names, ask.command.inputs, ask.command.units,
                    integration)
    notes = []
    program = f"CODE {ask.command.kind.upper()} {ask.command.filename}"
    if ask.infile is not None:
        notes += inputs.read_file_over_model(ask.infile, constants,
                                             ask.snapshot.names_a_quantity, program)
    elsewhere = []                    # the model's, but not inputs of this command
    for name, value in (ask.overrides or {}).items():
        if inputs.lookup(name) is None and ask.snapshot.names_a_quantity(name):
            elsewhere.append(name)
            continue
        inputs.set(name, value)
    for name, value in (ask.internal_values or {}).items():
        if inputs.lookup(name) is None and ask.snapshot.names_a_quantity(name):
            elsewhere.append(name)
            continue
        inputs.set_internal(name, value)
    if elsewhere:
        notes.append(", ".join(elsewhere) + f" {'is' if len(elsewhere) == 1 else 'are'}"
                     f" not {'an input' if len(elsewhere) == 1 else 'inputs'} of "
                     f"{program}: ignored there")
    for note in notes:
        warnings.warn(note, stacklevel=5)
    swept = ask.command.sweep[0] if ask.command.sweep is not None else None
    if swept in constants and inputs.missing([swept]):
        # CODE ALGEBRAIC() [Q = a, b, c]: the sweep gives Q its values
        inputs.set_internal(display_name(swept), 0.0, "the sweep")
    missing = inputs.missing(constants)
    if missing and ask.missing_values == "refuse":
        raise MissingValues(missing_message(ask.snapshot, missing, inputs, kinds, ask.out_dir,
                                             ask.stem, ask.command.filename),
                            [display_name(k) for k in missing])
    inputs.fill_missing(constants)
    if missing and ask.missing_values == "zero":
        warnings.warn("no value for " + some_names([display_name(k) for k in missing], 12)
                      + ": using 0", stacklevel=5)
    if timed:
        take_time(ask.command, inputs, timed)
    inputs.fill_missing(names)
    inputs.check_finite()
    degree_rates_note(inputs, names)
    if ask.integrate_states:       # before the build: it needs only the inputs
        bad = inertia_problems(ask.snapshot, system, inputs, zero=False)
        if bad:
            raise AutolevModelError("masses and inertias must be finite and not negative: "
                                    + "; ".join(bad))
    return inputs, kinds, names, extra_constants


def prepare_command(snapshot: ModelSnapshot, command, options: RunOptions = RunOptions(),
                    out_dir=None,
                    internal_values=None, warn_unassigned: bool = True,
                    locked=(), starts_now: bool = False,
                    compile_functions: bool = True) -> Prepared:
    """Build (or reuse) the command's numeric system, take its inputs (INPUT values, then
    the .in file, then the overrides in the quantities' units, then `internal_values`
    {name: value} in SI units and radians), refusing missing ones before anything is
    compiled, then compile it.  `warn_unassigned`: warn about specified quantities that
    will be 0 (not when they are a linearization's inputs).  `locked`: coordinates held
    fixed (see NumericSystem).  `starts_now`: an integration that can start on the
    Python follows: the right-hand side's C compiles in the background.
    `compile_functions=False`: the constants' function alone (a linearization
    evaluates its own Jacobians)."""
    command, specified, overrides = given_specified(snapshot, command, options.specified,
                                                    options.overrides)
    kind = command.kind
    stem = safe_stem(program_file_name(command.filename))
    files = output_columns(snapshot, command)
    encoded = encoded_values(snapshot)
    equations, unknowns = equations_and_unknowns(command.args, kind.upper())
    files = solution_columns(command, files, unknowns)
    ask = InputsWanted(snapshot, command, stem, unknowns, options.infile, overrides,
                       internal_values, options.constraints, options.missing_values, out_dir)
    build_start = time.perf_counter()
    what = f"CODE {kind.upper()} {command.filename}"
    build = SystemBuild.of(options, locked)
    with SlowStep(options.progress, f"{what}: forming its equations"):
        system = numeric_system(snapshot, command, files, encoded, (equations, unknowns),
                                build)
    fresh = not system.compiled and (compile_functions or system.constants_function is None)
    with snapshot.definitions.as_of(program_of(snapshot, command).definitions):
        inputs, kinds, names, extra_constants = take_inputs(ask, system)
        if fresh and compile_functions:     # inputs first: a refusal costs no compilation
            with SlowStep(options.progress, f"{what}: generating and compiling its code"):
                system.compile(background=starts_now)
        elif fresh:
            system.compile_constants()
    if fresh:                        # kept at the model's own revision, not as_of's view
        keep_system(snapshot, command, build, system)
    build_seconds = time.perf_counter() - build_start
    if system.hidden_in_outputs:
        warnings.warn(hidden_note(command.filename, system.hidden_in_outputs), stacklevel=3)
    set_specified(snapshot, system, specified, warn_unassigned)
    sweep = sweep_values(command, inputs)
    system.set_parameters(inputs.vector(system.params))
    return Prepared(system, inputs, kinds, stem, files, encoded, unknowns, sweep,
                    extra_constants, build_seconds)


@dataclass(frozen=True)
class SystemBuild:
    """What decides how a command's numeric system is built, besides the model: the
    key under which it is kept for the model's revision (every field, by
    construction)."""

    backend: str                # "auto", "c" or "python"
    quirks: bool                # Autolev's programs' quirks reproduced
    locked: tuple = ()          # coordinates held fixed
    recursion: bool = True      # a tree's u' by the articulated-body recursion

    @classmethod
    def of(cls, options: RunOptions, locked=()) -> "SystemBuild":
        return cls(options.backend, options.quirks, tuple(locked), options.recursion)


def numeric_system(snapshot: ModelSnapshot, command, files, encoded, solving: tuple,
                   build: SystemBuild) -> NumericSystem:
    """The command's numeric system, compiled, as kept for this revision of the model
    (repeated simulate() calls with other inputs reuse its compiled functions); else
    its analysis, to be compiled once its inputs are taken (then `keep_system`)."""
    kind = command.kind
    equations, unknowns = solving
    # the command itself is kept with its system: an id() alone may be reused
    entry = snapshot.derived.table("numeric systems").get(
        _system_key(snapshot, command, build))
    if entry is not None and entry[0] is command:
        return entry[1]
    program = program_of(snapshot, command)
    defs = snapshot.definitions
    with defs.as_of(program.definitions):
        return NumericSystem(
            snapshot, files, encoded, backend=build.backend, integrate=kind.integrates,
            solving=((equations, unknowns) if kind is CodeKind.ODE
                     else solved_by_lu(snapshot, command)),
            solved=unknowns if kind.solves else (),
            extra=solver_expressions(defs, kind, equations, unknowns),
            zero=command.zero if kind is CodeKind.DYNAMICS else None,
            hidden_in_outputs=hidden_in_outputs(command) if build.quirks else (),
            locked=build.locked, compile_functions=False, recursive=build.recursion)


def _system_key(snapshot: ModelSnapshot, command, build: SystemBuild) -> tuple:
    # by the command's place in the model (which a model read back from the cache keeps)
    place = snapshot.place if command is snapshot.command else id(command)
    return place, build


def keep_system(snapshot: ModelSnapshot, command, build: SystemBuild, system) -> None:
    """A compiled system kept for this revision of the model (after its build, which
    may have formed KANE), and for the cache of built models (Model.keep_built)."""
    snapshot.derived.table("numeric systems")[_system_key(snapshot, command, build)] = \
        (command, system)
    snapshot.systems_changed()


def set_specified(snapshot: ModelSnapshot, system, specified, warn_unassigned: bool) -> None:
    """Give the system the user's functions of the specified quantities."""
    functions = {find_symbol(snapshot, k): v for k, v in (specified or {}).items()}
    unused = [sym for sym in functions if sym not in system.set_specified(functions)]
    if unused:
        raise AutolevModelError("specified: " + "; ".join(
            unused_specified(system, sym) for sym in unused))
    given_fns = {i for i, _ in system.specified_functions}
    unassigned = [s for i, s in enumerate(system.specified) if i not in given_fns]
    if unassigned and warn_unassigned:
        warnings.warn("specified quantities without a definition or a function, set to 0: "
                      + ", ".join(map(str, unassigned)), stacklevel=4)


def missing_message(snapshot: ModelSnapshot, missing, inputs, kinds, out_dir, stem: str,
                     program: str) -> str:
    """What is missing, how to give it, and where a template to fill in was written
    (the run's output folder; an existing file is never replaced)."""
    # CODE ALGEBRAIC takes variables as inputs too
    what = ("constant" if all(snapshot.kind_of(S.base_and_order(k)[0]) == "constant"
                              for k in missing) else "input")
    text = (f"{len(missing)} {what}{'s' if len(missing) > 1 else ''} of {program} "
            f"{'have' if len(missing) > 1 else 'has'} no value: "
            + some_names(map(display_name, missing), 12)
            + ".  Autolev's program read them from its .in file; give them with --in FILE "
            "(an Autolev .in file), --set NAME=VALUE (in the model's units), or INPUT "
            "statements in the model (--zero-missing, or missing_values='zero', runs with "
            "0 for each)")
    if out_dir is None:
        return text
    template = Path(out_dir) / f"{stem}-template.in"
    filled = {k: inputs.values.get(k) for k in inputs.names}
    inputs.fill_missing(inputs.names, "template")
    try:
        folder = Path(out_dir)
        folder.mkdir(parents=True, exist_ok=True)
        with open(template, "x", encoding="utf-8", newline="\n") as h:
            h.write(inputs.file_text(template.name, kinds))
        Written(folder).record([template.name])     # a later run removes it, if unfilled
        text += f"; a template to fill in, with every input: {template}"
    except FileExistsError:
        text += f"; the template {template} from before is still there (fill it in)"
    except OSError as exc:
        text += f" (no template written: {exc.strerror})"
    for k, v in filled.items():
        if v is None:
            inputs.values.pop(k, None)
    return text


def unused_specified(system, sym) -> str:
    """Why a function given for `sym` would drive nothing."""
    if system.defs.rhs.get(sym) is not None:
        shown = str(system.defs.rhs[sym])
        shown = shown if len(shown) <= 60 else shown[:57] + "..."
        return (f"{sym} is defined in the model ({sym} = {shown}), so a "
                "function for it would be ignored; functions drive only SPECIFIED "
                "quantities the model leaves undefined (remove its definition to drive it)")
    if sym in system.params or sym in system.states:
        return f"{sym} is not a SPECIFIED quantity but an input (give it a value instead)"
    return f"{sym} does not enter this run's equations or outputs"


def degree_rates_note(inputs, names) -> None:
    """Autolev's programs converted DEG inputs but not DEG/S: say so when it matters."""
    odd = [display_name(k) for k in names
           if units.has_degrees(inputs.unit_of(k)) and inputs.values[k].given != 0]
    if odd:
        warnings.warn(
            "inputs in " + ", ".join(sorted({inputs.unit_of(k) for k in names
                                             if units.has_degrees(inputs.unit_of(k))}))
            + f" ({', '.join(odd)}) are used as radian rates, unconverted, as Autolev's "
            "programs did; give them in RAD/S if that was not meant", stacklevel=3)
