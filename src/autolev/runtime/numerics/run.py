"""Running a CODE command: DYNAMICS, ODE, ALGEBRAIC (with its input sweep), NONLINEAR.

`run_command` is what `autolev run`, `python model.py` and `Model.simulate` do: build
the numeric system, take the inputs (INPUT values, then an `.in` file, then
overrides), run, and write Autolev's files (`NAME.in`, `NAME.1..k`, `NAME.dir`, and
`NAME.encode` when there are ENCODE quantities) into the output folder.
"""
from __future__ import annotations

import math
import sys
import time
import warnings
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np
import sympy as sm

from .. import symbols as S
from .. import units
from ..calculus import NumericPoint, is_real_number
from ..errors import AutolevModelError, MissingValues
from ..vector import Vector
from .files import RunFiles, dir_text, encoded_text, safe_stem, termination_cleans_up
from .inputs import INTEGRATION, Inputs, display_name, parse_number, some_names
from .integrate import IntegrationFailure, Progress, Schedule, integrate
from .projection import Projector, constants_needed, integrate_projected
from .system import Column, NumericSystem, SingularMassMatrix, scaled_condition

# the scaled condition number of the mass matrix beyond which a run warns (the
# accelerations then keep fewer than 6 of their 16 significant digits)
COND_WARN = 1e10


@dataclass
class OutputTable:
    """The rows of one output file (values in the file's units)."""

    filename: str
    labels: list
    units: list
    data: np.ndarray

    def __getitem__(self, label: str) -> np.ndarray:
        for j, name in enumerate(self.labels):
            if name.upper() == label.upper():
                return self.data[:, j]
        raise KeyError(label)

    def __contains__(self, label) -> bool:
        return isinstance(label, str) and any(n.upper() == label.upper()
                                              for n in self.labels)


@dataclass
class Result:
    """What a run produced.

    t: the print times (DYNAMICS, ODE), or the swept input's values (ALGEBRAIC with a
    sweep, in its unit); states: one row per print time, internal units (radians);
    outputs: one OutputTable per OUTPUT statement, in the units the OUTPUT asked for;
    encoded: the ENCODE quantities at the last row; failure: Autolev's message when
    the run stopped early (the rows before it are kept)."""

    kind: str
    name: str
    t: np.ndarray
    states: np.ndarray
    state_names: list
    outputs: list
    encoded: dict
    inputs: dict
    solution: dict = field(default_factory=dict)
    files: list = field(default_factory=list)
    failure: str | None = None
    failure_time: float | None = None
    stats: dict = field(default_factory=dict)
    system: object = field(default=None, repr=False)   # the NumericSystem (rhs, outputs)

    @property
    def ok(self) -> bool:
        return self.failure is None

    def __getitem__(self, name: str) -> np.ndarray:
        """A state's column (by name, any case), else the first output column so
        labelled, else an ALGEBRAIC/NONLINEAR unknown."""
        for j, s in enumerate(self.state_names):
            if s.upper() == name.upper():
                return self.states[:, j]
        for table in self.outputs:
            try:
                return table[name]
            except KeyError:
                pass
        for k, v in self.solution.items():
            if k.upper() == name.upper():
                return v
        raise KeyError(name)

    def __repr__(self) -> str:
        status = "ok" if self.ok else f"failed: {self.failure}"
        return (f"<autolev Result {self.kind} {self.name}: {len(self.t)} rows, "
                f"{len(self.outputs)} output files, {status}>")


# -- building -------------------------------------------------------------------------------
def output_columns(model, command) -> list[list[Column]]:
    files = []
    for cols in model.outputs[:command.n_outputs]:
        out = []
        for value, label, unit in cols:
            if not unit:          # UNITS x = unit given before the CODE statement
                unit = command.units.get(value) if isinstance(value, sm.Symbol) else None
                unit = unit or command.units.get(label.upper())
            if isinstance(value, Vector):
                raise AutolevModelError(f"OUTPUT {label}: a vector cannot be written to a "
                                        "file; output its measure numbers (DOT(...))")
            if isinstance(value, (sm.MatrixBase, list, tuple)):
                mat = sm.Matrix(value)
                for i in range(mat.rows):
                    for j in range(mat.cols):
                        idx = (f"[{i + 1}]" if mat.cols == 1 else f"[{j + 1}]"
                               if mat.rows == 1 else f"[{i + 1},{j + 1}]")
                        out.append(Column(mat[i, j], f"{label}{idx}", unit))
                continue
            out.append(Column(sm.sympify(value), label, unit))
        files.append(out)
    return files


def encoded_values(model, command) -> list:
    out = []
    for name, value in model.encoded[:command.n_encoded]:
        if isinstance(value, Vector):
            raise AutolevModelError(f"ENCODE {name}: a vector; ENCODE its measure numbers")
        if isinstance(value, (list, tuple)):
            value = sm.Matrix(value)
        out.append((name, value if isinstance(value, sm.MatrixBase) else sm.sympify(value)))
    return out


def equations_and_unknowns(args, what: str) -> tuple[list, list]:
    """(equations, unknowns) of CODE ALGEBRAIC/NONLINEAR/ODE(EQ, x, y, ...)."""
    if not args:
        return [], []
    eq, rest = args[0], args[1:]
    if isinstance(eq, sm.MatrixBase):
        equations = list(eq)
    elif isinstance(eq, (list, tuple)):
        equations = [e for item in eq for e in (item if isinstance(item, (list, tuple,
                                                                           sm.MatrixBase))
                                                   else [item])]
    else:
        equations = [eq]
    unknowns = []
    for a in rest:
        items = list(a) if isinstance(a, (list, tuple, sm.MatrixBase)) else [a]
        for u in items:
            if not isinstance(u, sm.Symbol):
                raise AutolevModelError(f"CODE {what}: the unknowns must be names, not {u}")
            unknowns.append(u)
    if len(equations) != len(unknowns):
        raise AutolevModelError(f"CODE {what}: {len(equations)} equations for "
                                f"{len(unknowns)} unknowns")
    return [sm.sympify(e) for e in equations], unknowns


# -- running --------------------------------------------------------------------------------
def program_language(filename: str) -> str:
    """The language of the program Autolev wrote for a CODE file ("c", "m", "f", ...):
    what it integrated with, and how, follows from it."""
    return filename.lower().rsplit(".", 1)[-1] if "." in filename else ""


def program_method(filename: str) -> str:
    """The integrator of the program Autolev wrote for a CODE file: Matlab's programs
    call ode45 (Dormand-Prince 5(4), which is scipy's RK45), the C and Fortran ones
    their Kutta-Merson."""
    return "rk45" if program_language(filename) == "m" else "kutta-merson"


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
class _InputsWanted:
    """What prepare_command was given for the run's inputs."""

    model: object
    command: object
    stem: str
    unknowns: list
    infile: object
    overrides: dict | None
    internal_values: dict | None
    constraints: object
    missing_values: str
    out_dir: object

    @property
    def integrate_states(self) -> bool:
        return self.command.kind in ("dynamics", "ode")


def _take_inputs(ask: _InputsWanted, system):
    """The run's inputs (constants, initial values or guesses, integration
    parameters): INPUT values, then the .in file, then the overrides.  Refuses, before
    anything is compiled, constants that have no value from any of them."""
    extra_constants = (constants_needed(system, ask.constraints)
                       if ask.constraints and ask.integrate_states else [])
    constants = list(system.params) + extra_constants
    kinds = {p: "Constant" for p in constants}
    names = list(constants)
    timed = [] if ask.integrate_states else time_dependence(ask.model, system)
    if timed:
        names.append(S.TIME)
        kinds[S.TIME] = "Constant"
    if ask.integrate_states:
        names += system.states
        kinds.update({x: "Initial Value" for x in system.states})
        integration = INTEGRATION
    elif ask.command.kind == "nonlinear":
        names += ask.unknowns
        kinds.update({u: "Initial Guess" for u in ask.unknowns})
        integration = ("ABSERR", "RELERR")
    else:
        integration = ()
    inputs = Inputs(ask.model, names, integration, given=ask.command.inputs,
                    unit_table=ask.command.units)
    notes = []
    if ask.infile is not None:
        notes += inputs.read_file_over_model(ask.infile, constants)
    elsewhere = []                    # the model's, but not inputs of this command
    for name, value in (ask.overrides or {}).items():
        if inputs.lookup(name) is None and names_a_quantity(ask.model, name):
            elsewhere.append(name)
            continue
        inputs.set(name, value)
    for name, value in (ask.internal_values or {}).items():
        if inputs.lookup(name) is None and names_a_quantity(ask.model, name):
            elsewhere.append(name)
            continue
        inputs.set_internal(name, value)
    if elsewhere:
        notes.append(", ".join(elsewhere) + f" {'is' if len(elsewhere) == 1 else 'are'}"
                     f" not {'an input' if len(elsewhere) == 1 else 'inputs'} of "
                     f"CODE {ask.command.kind.upper()} {ask.command.filename}: ignored there")
    for note in notes:
        warnings.warn(note, stacklevel=5)
    swept = ask.command.sweep[0] if ask.command.sweep is not None else None
    if swept in constants and inputs.missing([swept]):
        # CODE ALGEBRAIC() [Q = a, b, c]: the sweep gives Q its values
        inputs.set_internal(display_name(swept), 0.0, "the sweep")
    missing = inputs.missing(constants)
    if missing and ask.missing_values == "refuse":
        raise MissingValues(_missing_message(ask.model, missing, inputs, kinds, ask.out_dir,
                                             ask.stem, ask.command.filename),
                            [display_name(k) for k in missing])
    inputs.fill_missing(constants)
    if missing:
        warnings.warn("no value for " + ", ".join(display_name(k) for k in missing)
                      + ": using 0", stacklevel=5)
    if timed:
        take_time(ask.command, inputs, timed)
    inputs.fill_missing(names)
    inputs.check_finite()
    _degree_rates_note(inputs, names)
    if ask.integrate_states:       # before the build: it needs only the inputs
        bad = _inertia_problems(system, inputs, zero=False)
        if bad:
            raise AutolevModelError("masses and inertias must be finite and not negative: "
                                    + "; ".join(bad))
    return inputs, kinds, names, extra_constants


def prepare_command(model, command, backend: str = "auto", infile=None, specified=None,
                    overrides=None, internal_values=None, constraints=None,
                    quirks: bool = True, missing_values: str = "refuse",
                    out_dir=None, warn_unassigned: bool = True, locked=()) -> Prepared:
    """Build (or reuse) the command's numeric system and take its inputs: INPUT values,
    then the .in file, then `overrides` (in the quantities' units), then
    `internal_values` ({name: value} in SI units and radians); refuses missing values
    before anything is compiled (see run_command).  `warn_unassigned`: warn about
    specified quantities that will be 0 (not when they are a linearization's inputs).
    `locked`: coordinates held fixed (see NumericSystem)."""
    if missing_values not in ("refuse", "zero"):
        raise ValueError(f"missing_values: 'refuse' or 'zero', not {missing_values!r}")
    command, specified, overrides = given_specified(model, command, specified, overrides)
    kind = command.kind
    stem = safe_stem(command.filename)
    files = output_columns(model, command)
    encoded = encoded_values(model, command)
    equations, unknowns = equations_and_unknowns(command.args, kind.upper())
    files = solution_columns(command, files, unknowns)
    ask = _InputsWanted(model, command, stem, unknowns, infile, overrides, internal_values,
                        constraints, missing_values, out_dir)
    build_start = time.perf_counter()
    taken = []
    system = _numeric_system(model, command, files, encoded, (equations, unknowns),
                             backend, quirks, locked,
                             before_compiling=lambda s: taken.append(_take_inputs(ask, s)))
    inputs, kinds, names, extra_constants = taken[0] if taken else _take_inputs(ask, system)
    build_seconds = time.perf_counter() - build_start
    if system.hidden_in_outputs:
        warnings.warn(
            f"{command.filename}: Autolev's C program computed the OUTPUT and ENCODE "
            "quantities with " + ", ".join(f"{s} = 0" for s in system.hidden_in_outputs)
            + " (its output routine's counter `int i1` hides the model's i1); reproduced "
            "as it printed them (--no-quirks, or quirks=False, for the values meant)",
            stacklevel=3)
    _set_specified(model, system, specified, warn_unassigned)
    sweep = _sweep(model, command, inputs)
    system.set_parameters(inputs.vector(system.params))
    return Prepared(system, inputs, kinds, stem, files, encoded, unknowns, sweep,
                    extra_constants, build_seconds)


def time_dependence(model, system) -> list[str]:
    """What an ALGEBRAIC or NONLINEAR program computes that depends on T (OUTPUT columns,
    ENCODE arrays, its equations).  Such a program has no time of its own: it reads T
    from its .in file as it reads its variables (see take_time)."""
    defs = model.defs
    named = [(c.label, c.expr) for cols in system.files for c in cols]
    named += list(system.encoded)
    named += [("its equations", e) for v in system.extra_exprs.values() for e in v]
    found = []
    for label, value in named:
        values = list(value) if isinstance(value, sm.MatrixBase) else [value]
        if label not in found and any(defs.depends_on(v, S.TIME) for v in values):
            found.append(label)
    return found


def take_time(command, inputs, dependent: list[str]) -> None:
    """T, read by a program without time whose `dependent` quantities need it: 0 unless
    given (INPUT has no T to give; --set T=..., an .in file), said so."""
    if inputs.missing([S.TIME]):
        inputs.set_internal("T", 0.0, "0: no value given")
        warnings.warn(f"CODE {command.kind.upper()} {command.filename}: "
                      f"{some_names(dependent)} {'depends' if len(dependent) == 1 else 'depend'}"
                      " on T, which a program without time reads from its .in file as it "
                      "reads its variables: T = 0 (give it with --set T=VALUE)", stacklevel=6)


def given_specified(model, command, specified, overrides):
    """`command` as if the model had defined, before it, the SPECIFIED quantities it
    leaves undefined and that are given a value -- a number or a sympy expression in
    the model's symbols in `specified`, or a number among the `overrides` (in the
    quantity's unit) -- as Autolev's user edited the program's "Quantities to be
    specified"; with the functions of `specified` (callables f(t) or f(t, x)) and the
    overrides that are left."""
    given, functions, rest = {}, {}, {}
    for name, value in (specified or {}).items():
        sym = _find_symbol(model, name)
        if callable(value) and not isinstance(value, sm.Basic):
            functions[sym] = value
            continue
        given[sym] = sm.sympify(value)
        if model.defs.depends_on(given[sym], sym):
            raise AutolevModelError(f"specified: the value of {display_name(sym)} depends "
                                    f"on {display_name(sym)} itself")
    for name, value in (overrides or {}).items():
        sym = _undefined_specified(model, name)
        if sym is None:
            rest[name] = value
            continue
        number = _override_number(name, value)
        given[sym] = sm.Float(units.to_internal(number, command.units.get(sym)
                                                 or model.unit_of.get(sym)))
    if not given:
        return command, functions, rest
    kept = model.derived.table("commands with specified quantities given")
    key = (id(command), tuple(sorted((str(k), sm.srepr(v)) for k, v in given.items())))
    entry = kept.get(key)
    if entry is None or entry[0] is not command:
        definitions = (model.defs.user_definitions() if command.definitions is None
                       else command.definitions)
        entry = kept[key] = (command, replace(command, definitions={**definitions,
                                                                   **given}))
    return entry[1], functions, rest


def _undefined_specified(model, name: str):
    """The SPECIFIED quantity `name` (Q1', Q1P) names when the model leaves it undefined."""
    if not isinstance(name, str) or not names_a_quantity(model, name) \
            or name.strip().upper() in INTEGRATION:
        return None
    try:
        sym = _find_symbol(model, name)
    except AutolevModelError:
        return None
    base = S.base_and_order(sym)[0]
    return sym if model.kind_of(base) == "specified" and sym not in model.defs.rhs else None


def _override_number(name: str, value) -> float:
    number = parse_number(value) if isinstance(value, str) else float(value)
    if number is None:
        raise AutolevModelError(f"{name}={value}: not a number")
    return number


def solution_columns(command, files: list, unknowns: list) -> list:
    """The OUTPUT files of a CODE ALGEBRAIC/NONLINEAR that solves for `unknowns`: with
    no OUTPUT, the solution is what the program is for, so one file of the unknowns."""
    if command.kind == "nonlinear" and not unknowns:
        raise AutolevModelError("CODE NONLINEAR needs equations and unknowns: "
                                "CODE NONLINEAR(EQ, x, y) file")
    if unknowns and not files and command.kind in ("algebraic", "nonlinear"):
        return [[Column(u, u.name, (command.inputs.get(u) or (None, None))[1]
                        or command.units.get(u)) for u in unknowns]]
    return files


def _numeric_system(model, command, files, encoded, solving: tuple, backend: str,
                    quirks: bool, locked, before_compiling) -> NumericSystem:
    """The command's numeric system, built once per state of the model (repeated
    simulate() calls with other inputs reuse its compiled functions)."""
    kind = command.kind
    equations, unknowns = solving

    def systems():
        state = (model.version, model.defs.user_version, model.kane_calls,
                 len(model.outputs), len(model.encoded))
        return model.derived.table("numeric systems", state)
    # by the command's place in the model (which a model read back from the cache keeps)
    place = next((k for k, c in enumerate(model.code_commands) if c is command),
                 "plain" if command is model.plain_dynamics() else id(command))
    key = (place, backend, quirks, tuple(locked))
    # the command itself is kept with its system: an id() alone may be reused
    entry = systems().get(key)
    if entry is not None and entry[0] is command:
        return entry[1]
    with model.defs.as_of(command.definitions):
        system = NumericSystem(
            model, files, encoded, backend=backend, integrate=kind in ("dynamics", "ode"),
            ode=(equations, unknowns) if kind == "ode" else None,
            solved=unknowns if kind in ("algebraic", "nonlinear") else (),
            extra=solver_expressions(model.defs, kind, equations, unknowns),
            zero=command.zero if kind == "dynamics" else None,
            hidden_in_outputs=_hidden_in_outputs(command) if quirks else (),
            before_compiling=before_compiling, locked=locked)
    systems()[key] = (command, system)      # after the build: it may form KANE
    keeper = getattr(model, "cache_writer", None)
    if keeper is not None:          # the cache of built models keeps it (keep_built)
        keeper.added()
    return system


def keep_built(model) -> None:
    """The numeric systems built so far go to the cache of built models (loader's
    ModelKeeper), once the work that built them is done."""
    keeper = getattr(model, "cache_writer", None)
    if keeper is not None:
        keeper.flush(model)


def _set_specified(model, system, specified, warn_unassigned: bool) -> None:
    """Give the system the user's functions of the specified quantities."""
    functions = {_find_symbol(model, k): v for k, v in (specified or {}).items()}
    unused = [sym for sym in functions if sym not in system.set_specified(functions)]
    if unused:
        raise AutolevModelError("specified: " + "; ".join(
            _unused_specified(model, system, sym) for sym in unused))
    given_fns = {i for i, _ in system.specified_functions}
    unassigned = [s for i, s in enumerate(system.specified) if i not in given_fns]
    if unassigned and warn_unassigned:
        warnings.warn("specified quantities without a definition or a function, set to 0: "
                      + ", ".join(map(str, unassigned)), stacklevel=4)


def run_command(model, command, out_dir=None, method: str | None = None,
                backend: str = "auto", infile=None, specified=None, progress=None,
                overrides=None, compiled: bool = True, constraints=None,
                quirks: bool = True, keep_rows: bool = True,
                missing_values: str = "refuse", overwrite: bool = False) -> Result:
    """Run one CODE command; files go to out_dir (None: no files).  `constraints`:
    configuration constraints g(q) (sympy expressions in the model's symbols) kept at
    their initial values by projecting the state onto them at every print time.
    `quirks`: compute what Autolev's programs computed where they were wrong
    (docs/language.md, "What Autolev's programs computed"); False: what was meant.
    `keep_rows=False`: the Result holds only the last row (the files hold them all),
    so that memory does not grow with the length of the run.  `missing_values`:
    "refuse" (a constant the run needs without a value from INPUT, the .in file or
    the overrides stops it before anything is compiled, MissingValues) or "zero"
    (they are 0, with a warning).  `overwrite`: replace files in out_dir that autolev did
    not write (Autolev's own output, a .in the user edited); else they stop the run
    before it computes anything."""
    prepared = prepare_command(model, command, backend=backend, infile=infile,
                               specified=specified, overrides=overrides,
                               constraints=constraints, quirks=quirks,
                               missing_values=missing_values, out_dir=out_dir)
    system, inputs, kinds = prepared.system, prepared.inputs, prepared.kinds
    kind, stem, files, encoded = command.kind, prepared.stem, prepared.files, prepared.encoded
    unknowns, sweep, extra_constants = prepared.unknowns, prepared.sweep, prepared.extra_constants
    integrate_states = kind in ("dynamics", "ode")
    method = method or program_method(command.filename)
    zero_params = [display_name(p) for p in system.params if inputs.internal(p) == 0.0]
    result = Result(kind, stem, np.zeros(0), np.zeros((0, system.nstate)),
                    [display_name(x) for x in system.states], [], {},
                    {display_name(k): inputs.values[k].given for k in inputs.names},
                    system=system)
    result.stats["build_seconds"] = prepared.build_seconds

    def perform(writer):
        if integrate_states:
            _run_dynamics(system, inputs, result, writer, method, progress, zero_params,
                          compiled, constraints, inputs.vector(extra_constants),
                          program=program_language(command.filename), keep_rows=keep_rows)
        else:
            _run_algebraic(system, inputs, result, writer, kind, unknowns, sweep,
                           zero_params, keep_rows)

    if out_dir is None:
        perform(None)
        return result
    folder = Path(out_dir)
    own_in = folder / f"{stem}.in"
    with termination_cleans_up():
        with _writing(folder):
            run_files = RunFiles(folder, stem, overwrite)
        writes_in = infile is None or Path(infile).resolve() != own_in.resolve()
        try:
            with _writing(folder):
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
                    stem, command.filename, [[c.label for c in cols] for cols in files],
                    extra_files))
                result.files = run_files.commit()
        except BaseException:
            run_files.discard()
            raise
        finally:
            run_files.release()
    return result


def _missing_message(model, missing, inputs, kinds, out_dir, stem: str,
                     program: str) -> str:
    """What is missing, how to give it, and where a template to fill in was written
    (the run's output folder; an existing file is never replaced)."""
    # CODE ALGEBRAIC takes variables as inputs too
    what = ("constant" if all(model.kind_of(S.base_and_order(k)[0]) == "constant"
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
        text += f"; a template to fill in, with every input: {template}"
    except FileExistsError:
        text += f"; the template {template} from before is still there (fill it in)"
    except OSError as exc:
        text += f" (no template written: {exc.strerror})"
    for k, v in filled.items():
        if v is None:
            inputs.values.pop(k, None)
    return text


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


def _hidden_in_outputs(command) -> tuple:
    """Names the output routine of Autolev's program for `command` declares for itself
    (every C program of Autolev 4.1 has `int i1;` there)."""
    return ("i1",) if program_language(command.filename) == "c" else ()


def solver_expressions(defs, kind: str, equations: list, unknowns: list) -> dict | None:
    """What CODE ALGEBRAIC (the linear system's matrix and right side) and CODE
    NONLINEAR (residuals and their Jacobian) evaluate besides the outputs."""
    if kind == "algebraic" and equations:
        zero = {u: 0 for u in unknowns}
        return {"linear": [d for row in defs.jacobian(equations, unknowns) for d in row]
                + [defs.substitute(e, zero) for e in equations]}
    if kind == "nonlinear":
        return {"residual": list(equations),
                "jacobian": [d for row in defs.jacobian(equations, unknowns) for d in row]}
    return None


def names_a_quantity(model, name: str) -> bool:
    """Whether `name` (as --set or an override gives it: Q1, Q1', Q1P, TFINAL) is an
    integration parameter or a quantity of the model."""
    name = name.strip()
    if name.upper() in INTEGRATION or name.upper() in ("INTEGSTEP", "T"):
        return True         # T: the time, which a program without time reads
    primes = len(name) - len(name.upper().rstrip("P"))       # Q1PP is Q1''
    for candidate in [name] + [name[:-k] + "'" * k for k in range(1, primes + 1)]:
        try:
            model.quantity(candidate)
            return True
        except KeyError:
            continue
    return False


def _unused_specified(model, system, sym) -> str:
    """Why a function given for `sym` would drive nothing."""
    if model.defs.rhs.get(sym) is not None:
        shown = str(model.defs.rhs[sym])
        shown = shown if len(shown) <= 60 else shown[:57] + "..."
        return (f"{sym} is defined in the model ({sym} = {shown}), so a "
                "function for it would be ignored; functions drive only SPECIFIED "
                "quantities the model leaves undefined (remove its definition to drive it)")
    if sym in system.params or sym in system.states:
        return f"{sym} is not a SPECIFIED quantity but an input (give it a value instead)"
    return f"{sym} does not enter this run's equations or outputs"


def _find_symbol(model, name):
    if isinstance(name, sm.Symbol):
        return name
    for sym in model.info:
        if sym.name.upper() == str(name).upper():
            return sym
    raise AutolevModelError(f"specified: no quantity named {name!r}")


def sweep_of(command, inputs) -> tuple | None:
    """[q deg = start, stop, step] of CODE ALGEBRAIC: (key, start, step, the number of
    values, unit); the values are start + step*k, k = 0 ... count-1."""
    if command.sweep is None:
        return None
    target, start, stop, step = command.sweep[:4]
    unit = command.sweep[4] if len(command.sweep) > 4 else inputs.unit_of(target)
    start, stop, step = float(start), float(stop), float(step)
    name = display_name(target)
    if not all(math.isfinite(v) for v in (start, stop, step)):
        raise AutolevModelError(f"the sweep of {name}: its start, end and step must be "
                                f"numbers within double precision, not {start:g}, {stop:g}, "
                                f"{step:g}")
    if step == 0 or (stop - start) * step < 0:
        raise AutolevModelError(f"the sweep of {name}: step {step:g} does not lead from "
                                f"{start:g} to {stop:g}")
    count = math.floor((stop - start) / step + 1e-9) + 1 if math.isfinite(
        (stop - start) / step) else math.inf
    if count > MAX_SWEEP_VALUES:
        raise AutolevModelError(f"the sweep of {name} from {start:g} to {stop:g} by {step:g} "
                                f"has {count:.3g} values; at most {MAX_SWEEP_VALUES:.0e} are "
                                "swept (a larger step, or several programs)")
    return target, start, step, count, unit


# values of one sweep at most: each is a row of every output file
MAX_SWEEP_VALUES = 10 ** 9


@dataclass(frozen=True)
class SweepValues:
    """The values of [q deg = start, stop, step], made one at a time: given (in the
    sweep's unit) and internal."""

    target: object
    start: float
    step: float
    count: int
    unit: str | None

    def given(self, k: int) -> float:
        return self.start + self.step * k

    def __iter__(self):
        for k in range(self.count):
            given = self.given(k)
            yield units.to_internal(given, self.unit), given


def _sweep(model, command, inputs) -> SweepValues | None:
    found = sweep_of(command, inputs)
    return None if found is None else SweepValues(*found)


def _degree_rates_note(inputs, names) -> None:
    """Autolev's programs converted DEG inputs but not DEG/S: say so when it matters."""
    odd = [display_name(k) for k in names
           if units.has_degrees(inputs.unit_of(k)) and inputs.values[k].given != 0]
    if odd:
        warnings.warn(
            "inputs in " + ", ".join(sorted({inputs.unit_of(k) for k in names
                                             if units.has_degrees(inputs.unit_of(k))}))
            + f" ({', '.join(odd)}) are used as radian rates, unconverted, as Autolev's "
            "programs did; give them in RAD/S if that was not meant", stacklevel=3)


def _inertia_problems(system, inputs, zero: bool = True) -> list[str]:
    """Bodies and particles whose mass (or a principal inertia) is negative or not a
    number (and, with `zero`, zero) as the run uses them: a constant its equations do
    not contain (a planar model's I11 or I12) counts as 0 and never had a value chosen
    for it, and a mass or inertia holding one is not called zero or singular."""
    m = system.model
    values = {p: inputs.internal(p) for p in system.params}
    unused = set()

    def primitives(e):
        out = set()
        for f in sm.sympify(e).free_symbols:
            out |= m.defs.primitive_deps(f) if f in m.defs.rhs else {f}
        return out

    def unused_in(e) -> bool:
        found = {f for f in primitives(e)
                 if f not in values and f not in m.defs.varying and f != S.TIME}
        unused.update(found)
        return bool(found)

    masses = [(f"particle {p.name}", p.mass, None) for p in m.particles_list
              if p.mass is not None]
    for b in m.bodies_list:
        if b.mass is not None:
            try:
                inertia = b.central_inertia.to_matrix(b)
            except AutolevModelError:
                inertia = None
            masses.append((f"body {b.name}", b.mass, inertia))
    # every entry looked at (no short cut): each unused constant must get its 0
    partial = {name: (unused_in(mass), inertia is not None
                      and any([unused_in(e) for e in inertia]))
               for name, mass, inertia in masses}
    point = NumericPoint(m.defs, {**values, **{f: 0.0 for f in unused}})

    def num(e):
        z = m.defs.numeric(sm.sympify(e), point)
        return z.real if is_real_number(z) else math.nan

    out = []
    for name, mass_expr, inertia in masses:
        mass_partial, inertia_partial = partial[name]
        mass = num(mass_expr)
        principal = [] if inertia is None else _principal(
            np.array([[num(inertia[i, j]) for j in range(3)] for i in range(3)]))
        zero_mass = zero and not mass_partial
        if math.isinf(mass) or not all(map(math.isfinite, principal)):
            out.append(f"{name} has a {'mass' if math.isinf(mass) else 'central inertia'} "
                       "that is not a finite number (a value beyond double precision?)")
        elif not mass > 0 and (zero_mass or mass != 0):
            what = f"{name} has mass {mass:g}"
            if principal and not any(d > 0 for d in principal):
                what += " and no inertia"
            out.append(what)
        elif principal and any(d < 0 or math.isnan(d) for d in principal):
            out.append(f"{name} has principal inertias "
                       + ", ".join(f"{d:.6g}" for d in principal))
        elif zero and not inertia_partial and len(principal) == 3 and min(principal) == 0:
            out.append(f"{name} has a singular central inertia (principal inertias "
                       + ", ".join(f"{d:.6g}" for d in principal) + ")")
    return out


def _principal(numbers) -> list[float]:
    """The principal inertias of a numeric inertia matrix, those within rounding of
    0 (1e-12 of the largest) shown as 0; [nan] when an entry is not a number."""
    if not np.all(np.isfinite(numbers)):
        return [math.nan]
    principal = np.linalg.eigvalsh((numbers + numbers.T) / 2)
    scale = max(float(np.abs(principal).max()), 0.0)
    return [0.0 if abs(d) <= 1e-12 * scale else float(d) for d in principal]


def _zero_hint(zero_params) -> str:
    if not zero_params:
        return ""
    shown = ", ".join(zero_params[:12]) + (", ..." if len(zero_params) > 12 else "")
    return f" (constants that are 0: {shown})"


def _split_outputs(system, values, result_rows, writer, encoded_out: dict) -> None:
    pos = 0
    for k, cols in enumerate(system.files):
        vals = values[pos:pos + len(cols)].tolist()
        # units.to_output, with the unit test made once per column
        row = [v * 180 / math.pi if deg else v
               for v, deg in zip(vals, system.degree_columns[k])]
        pos += len(cols)
        result_rows[k].append(row)
        if writer is not None:
            writer.write(k, row)
    for name, shape in system.encode_shapes:
        size = int(np.prod(shape)) if shape else 1
        chunk = values[pos:pos + size]
        pos += size
        encoded_out[name] = chunk.reshape(shape) if shape else float(chunk[0])


def _tables(system, rows, stem: str) -> list[OutputTable]:
    out = []
    for k, cols in enumerate(system.files):
        data = np.array(rows[k], dtype=float).reshape(len(rows[k]), len(cols))
        out.append(OutputTable(f"{stem}.{k + 1}", [c.label for c in cols],
                               [c.unit for c in cols], data))
    return out


def _on_stiff(t: float, hlamb: float) -> str:
    # Radau, not LSODA: on the lightly damped stiff spring chain of
    # bench/work_precision.py LSODA took 1.4 ms to 680 ms depending on the tolerance,
    # Radau 5 to 133 ms at every tolerance
    warnings.warn(f"the equations are stiff from T = {t:.6g} (step size times the largest "
                  f"eigenvalue ~ {hlamb:.3g}, beyond DOP853's stability): going on with "
                  "Radau (implicit); ask for --method radau from the start to avoid the "
                  "switch", stacklevel=2)
    return "radau"


# RELERR at and above which a method is known to give qualitatively wrong motion
# over long runs: the relative energy error of the conservative double pendulum over
# 100 s (Q1 = 30 deg, Q2 = 60 deg; bench/work_precision.py) exceeds 1 % there --
# RK23 1.5 % at 1e-4; RK45 8.8 %, LSODA 4.3 %, BDF 11 % at 1e-3 (steps not bounded
# by INTEGSTP); Radau, DOP853 and Kutta-Merson stay below 0.1 % at 1e-3.
LOOSE_RELERR = {"rk23": 1e-4, "rk45": 1e-3, "lsoda": 1e-3, "bdf": 1e-3, "radau": 1e-2,
                "dop853": 1e-2, "kutta-merson": 1e-2}


def _loose_tolerance_note(method: str, relerr: float) -> None:
    limit = LOOSE_RELERR.get(method)
    if limit is not None and relerr >= limit:
        warnings.warn(f"RELERR = {relerr:g} is loose for {method}: at RELERR >= {limit:g} it "
                      "is known to give qualitatively wrong motion over long runs (a "
                      "conservative double pendulum gains or loses over 1 % of its energy in "
                      f"100 s); use RELERR <= {limit / 100:g}", stacklevel=4)


def _stiff_note(stats: dict, method: str) -> None:
    t = stats.get("stiff_t")
    if t is None or stats.get("switched_to"):
        return
    warnings.warn(f"the equations are stiff from T = {t:.6g}: {method}'s steps are limited "
                  "by its stability, not by the error asked for (a slow run); an implicit "
                  "method (--method lsoda or radau; method='lsoda') takes far fewer steps",
                  stacklevel=3)


class Conditioning:
    """The scaled condition number of the mass matrix at every row, in batches (its
    memory does not grow with the run): the largest value and where, and the first
    row past COND_WARN (an exactly singular matrix stops the run with its own
    message)."""

    BATCH = 4096

    def __init__(self):
        self.largest = None          # (cond, t)
        self.first_bad = None        # (cond, t, state)
        self._batch = []             # (t, state, matrix)

    def add(self, t, state, matrix) -> None:
        self._batch.append((t, state, matrix))
        if len(self._batch) >= self.BATCH:
            self._flush()

    def _flush(self) -> None:
        if not self._batch:
            return
        conds = scaled_condition(np.array([m for _, _, m in self._batch]))
        k = int(np.argmax(conds))
        if self.largest is None or conds[k] > self.largest[0]:
            self.largest = (float(conds[k]), self._batch[k][0])
        bad = np.nonzero((conds > COND_WARN) & np.isfinite(conds))[0]
        if len(bad) and self.first_bad is None:
            i = int(bad[0])
            self.first_bad = (float(conds[i]), self._batch[i][0], self._batch[i][1])
        self._batch = []

    def report(self, result) -> None:
        """The stats, and a warning with the time and state of the first bad row."""
        self._flush()
        if self.largest is None:
            return
        result.stats["cond_max"], result.stats["cond_max_t"] = self.largest
        if self.first_bad is not None:
            cond, t, state = self.first_bad
            shown = ", ".join(f"{n} = {v:.6g}" for n, v in zip(result.state_names, state))
            warnings.warn(
                f"the mass matrix is nearly singular at T = {t:.6g} (condition number "
                f"{cond:.2g} after scaling by its diagonal: the accelerations may have lost "
                f"{min(16, int(math.log10(min(cond, 1e16))))} of their 16 digits); the state "
                f"there: {shown}", stacklevel=4)


class _Rows:
    """The print rows of a run as they come: written, kept (all, or only the last), and
    the mass matrix's conditioning watched."""

    def __init__(self, system, result, writer, keep_rows: bool):
        self.system, self.result, self.writer, self.keep_rows = system, result, writer, keep_rows
        self.times: list = []
        self.states: list = []
        self.rows: list = [[] for _ in system.files]
        self.encoded: dict = {}
        self.conditioning = Conditioning()

    def __call__(self, t, y) -> None:
        values = self.system.outputs(t, y)       # solves for the accelerations once
        if not self.keep_rows and self.times:
            self.times.clear()
            self.states.clear()
            for r in self.rows:
                r.clear()
        self.times.append(t)
        self.states.append(np.array(y))
        _split_outputs(self.system, values, self.rows, self.writer, self.encoded)
        self.result.stats["rows"] = self.result.stats.get("rows", 0) + 1
        mm = self.system.last_mass_matrix()
        if mm is not None:
            self.conditioning.add(t, self.states[-1], mm)

    def finish(self) -> None:
        result, system = self.result, self.system
        result.t = np.array(self.times)
        result.states = np.array(self.states).reshape(len(self.states), system.nstate)
        result.outputs = _tables(system, self.rows, result.name)
        result.encoded = self.encoded


def _schedule(inputs, program: str) -> Schedule:
    """The print schedule of the INPUT integration parameters, integrated the way
    Autolev's program in that language integrated."""
    sched = Schedule(inputs.internal("TINITIAL"), inputs.internal("TFINAL"),
                     inputs.internal("INTEGSTP"), int(inputs.values["PRINTINT"].given),
                     fresh_derivatives=program == "c",
                     restart_each_step=program == "m")
    try:
        sched.check()
    except ValueError as exc:
        raise AutolevModelError(str(exc)) from None
    return sched


def _run_dynamics(system, inputs, result, writer, method, progress, zero_params,
                  compiled: bool = True, constraints=None, extra_values=(),
                  program: str = "", keep_rows: bool = True) -> None:
    """`program`: the language of Autolev's program for the CODE file ("c", "m", ...),
    whose way of integrating is followed.  `keep_rows`: the Result holds every row
    (else only the last: a run's memory is then independent of its length)."""
    if not system.nstate:
        raise AutolevModelError("nothing to integrate: no variable has a defined "
                                "derivative and there are no generalized speeds")
    y0 = np.array(inputs.vector(system.states))
    sched = _schedule(inputs, program)
    on_row = _Rows(system, result, writer, keep_rows)

    def f(t, y):
        try:
            return system.derivatives(t, y)
        except SingularMassMatrix as exc:
            raise IntegrationFailure(str(exc), t, y) from None

    bar = Progress(sys.stderr if progress is None else progress, sched.tinitial,
                   sched.tfinal, enabled=progress is not False and progress is not None)
    start = time.perf_counter()
    abserr, relerr = inputs.internal("ABSERR"), inputs.internal("RELERR")
    try:
        loop = system.loop if compiled and not system.specified_functions else None
        on_stiff = _on_stiff if method == "dop853" else None
        _loose_tolerance_note(method.lower(), relerr)
        if constraints:
            projector = Projector(system, constraints, sched.tinitial, y0, extra_values)
            result.stats.update(integrate_projected(
                f, y0, sched, method, abserr, relerr, on_row, bar, loop, on_stiff,
                projector))
        else:
            result.stats.update(integrate(f, y0, sched, method, abserr, relerr, on_row,
                                          bar, loop=loop, on_stiff=on_stiff))
        _stiff_note(result.stats, method)
    except IntegrationFailure as exc:
        on_row(exc.t, exc.y)              # Autolev's last row: where it stopped
        result.failure = _failure_message(exc, system, inputs, result, zero_params,
                                          (f, sched, abserr, relerr))
        result.failure_time = exc.t
        if writer is not None:
            writer.note("Error: " + result.failure)
    except ValueError as exc:
        raise AutolevModelError(str(exc)) from None
    finally:
        bar.done()
        result.stats["seconds"] = time.perf_counter() - start
        on_row.conditioning.report(result)
    on_row.finish()


def _failure_message(exc: IntegrationFailure, system, inputs, result, zero_params,
                     integration: tuple) -> str:
    """Autolev's message for a failed integration, with what we can tell of its cause."""
    state = ", ".join(f"{n} = {v:.6g}" for n, v in zip(result.state_names, exc.y))
    message = (f"Numerical integration failed to converge: {exc}; the state there: {state}"
               + (_zero_hint(zero_params) if result.stats["rows"] <= 1 else ""))
    if "singular" in str(exc) or (result.stats["rows"] <= 1 and "not finite" in str(exc)):
        problems = _inertia_problems(system, inputs)
        if problems:
            message += "; " + "; ".join(problems)
    mass = system.last_mass_matrix() if "singular" in str(exc) else None
    if mass is not None and not np.all(np.isfinite(mass)):
        huge = [f"{display_name(p)} = {v:g}" for p, v in zip(system.params,
                                                               system.constant_values)
                if abs(v) > 1e100]
        message += ("; its entries are not finite numbers (inf or NaN): a value beyond "
                    "double precision" + (f" (from {', '.join(huge[:4])}?)" if huge else ""))
    if exc.cuts:
        f, sched, abserr, relerr = integration
        message += "; " + _halving_verdict(f, exc, sched, abserr, relerr)
    return message


# h*|lambda| where Kutta-Merson stops being stable on the negative real axis
KM_STABILITY = 3.5


def _halving_verdict(f, failure, schedule, abserr: float, relerr: float) -> str:
    """Why Kutta-Merson's step was halved too often: zero tolerances, or stiffness
    (judged by the Jacobian's eigenvalues where it stopped), or neither."""
    if abserr <= 0 and relerr <= 0:
        return ("ABSERR and RELERR are both 0, which no step can satisfy: give them "
                "values (e.g. ABSERR = 1E-8, RELERR = 1E-7)")
    floor = abs(schedule.integstp) / 2 ** 20
    rho = _spectral_radius(f, failure.t, failure.y)
    if rho is None:
        return "the derivatives are not finite near that state"
    if rho * floor > KM_STABILITY:
        return (f"the equations are stiff there (the Jacobian's largest eigenvalue is "
                f"about {rho:.3g} in size: Kutta-Merson needs steps below "
                f"{KM_STABILITY / rho:.2g}, finer than the {floor:.2g} its 20 halvings of "
                "INTEGSTP allow); an implicit method takes them in stride: --method radau "
                "(method='radau')")
    verdict = (f"the equations are not stiff there (the Jacobian's largest eigenvalue is "
               f"about {rho:.3g} in size)")
    if abserr <= 0:
        return verdict + ("; ABSERR = 0 makes any state that is exactly 0 fail the error "
                          "test: give ABSERR a small value (e.g. 1E-8)")
    return verdict + ("; the derivatives may jump or grow without bound near that state, "
                      "or ABSERR and RELERR are below what double precision can meet")


def _spectral_radius(f, t: float, y: np.ndarray) -> float | None:
    """max |eigenvalue| of df/dy at (t, y), by forward differences; None where the
    derivatives cannot be evaluated."""
    try:
        f0 = np.asarray(f(t, y), dtype=float)
        columns = []
        for j in range(len(y)):
            step = 1.5e-8 * max(1.0, abs(y[j]))
            moved = np.array(y, dtype=float)
            moved[j] += step
            columns.append((np.asarray(f(t, moved), dtype=float) - f0) / step)
    except IntegrationFailure:
        return None
    jac = np.array(columns).T
    if not np.all(np.isfinite(jac)):
        return None
    return float(np.max(np.abs(np.linalg.eigvals(jac)))) if len(y) else 0.0


def _run_algebraic(system, inputs, result, writer, kind, unknowns, sweep, zero_params,
                   keep_rows: bool = True):
    """Evaluate (and solve) once, or once per value of the sweep, made and written one
    at a time; with `keep_rows` False the Result holds only the last row."""
    rows = [[] for _ in system.files]
    encoded: dict = {}
    solutions, swept = [], []
    points = [None] if sweep is None else sweep
    n = len(unknowns)
    guess = (np.array(inputs.vector(unknowns)) if kind == "nonlinear" else np.zeros(n))
    base = inputs.vector(system.params)
    t = inputs.internal(S.TIME) if S.TIME in inputs.values else 0.0
    target_pos = None
    if sweep is not None:
        if sweep.target in system.params:
            target_pos = system.params.index(sweep.target)
        else:
            warnings.warn(f"the swept input {display_name(sweep.target)} does not enter the "
                          "outputs", stacklevel=3)
    for point in points:
        if not keep_rows:
            rows = [[] for _ in system.files]
            del solutions[:], swept[:]
        if point is not None and target_pos is not None:
            p = list(base)
            p[target_pos] = point[0]
            system.set_parameters(p)
        if kind == "algebraic" and n:
            # the coefficients hold no unknown, but the compiled function takes their
            # slots (Python's reads them; C's read past an empty array)
            ab = system.extra("linear", t, solved=np.zeros(n))
            a = ab[:n * n].reshape(n, n)
            b = ab[n * n:]
            x = _linear_solve(a, -b, zero_params)
        elif kind == "nonlinear":
            x = _newton(system, guess, t, inputs.internal("ABSERR"),
                        inputs.internal("RELERR"), unknowns, zero_params)
            guess = x
        else:
            x = np.zeros(0)
        solutions.append(x)
        if point is not None:
            swept.append(point[1])
        values = system.outputs(t, np.zeros(0), None, x)
        _split_outputs(system, values, rows, writer, encoded)
    result.t = np.array(swept, dtype=float)
    result.solution = {display_name(u): np.array([s[i] for s in solutions])
                       for i, u in enumerate(unknowns)}
    result.outputs = _tables(system, rows, result.name)
    result.encoded = encoded


def _linear_solve(a, b, zero_params):
    import scipy.linalg      # 0.1 s to import: only CODE ALGEBRAIC's solves pay it
    try:
        lu, piv = scipy.linalg.lu_factor(a, check_finite=True)
    except (ValueError, np.linalg.LinAlgError):
        raise AutolevModelError("CODE ALGEBRAIC: the equations' coefficients are not "
                                "finite" + _zero_hint(zero_params)) from None
    if np.any(np.diag(lu) == 0):
        raise AutolevModelError("CODE ALGEBRAIC: the equations are singular for these "
                                "inputs" + _zero_hint(zero_params))
    return scipy.linalg.lu_solve((lu, piv), b)


def _newton(system, x0, t, abserr, relerr, unknowns, zero_params, max_iter: int = 50):
    """Newton's method from the guesses; converged when every step is within
    max(ABSERR, RELERR*|x|) and the residual is small."""
    x = np.array(x0, dtype=float)
    n = len(x)
    for _ in range(max_iter):
        r = system.extra("residual", t, (), x)
        j = system.extra("jacobian", t, (), x).reshape(n, n)
        if not (np.all(np.isfinite(r)) and np.all(np.isfinite(j))):
            raise AutolevModelError("CODE NONLINEAR: the equations are not finite at "
                                    + _at(unknowns, x) + _zero_hint(zero_params))
        try:
            dx = np.linalg.solve(j, -r)
        except np.linalg.LinAlgError:
            raise AutolevModelError("CODE NONLINEAR: the Jacobian is singular at "
                                    + _at(unknowns, x)) from None
        x = x + dx
        if np.all(np.abs(dx) <= np.maximum(abserr, relerr * np.abs(x))):
            return x
    raise AutolevModelError(f"CODE NONLINEAR: Newton's method did not converge in "
                            f"{max_iter} iterations (last {_at(unknowns, x)}); try other "
                            "guesses")


def _at(unknowns, x) -> str:
    return ", ".join(f"{display_name(u)} = {v:.6g}" for u, v in zip(unknowns, x))
