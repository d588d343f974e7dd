"""What a CODE command computes and reads: its output columns and ENCODE
values, the equations and unknowns it solves, its sweep, its time, and the
values given for its specified quantities (shared by the runs and by the
programs `autolev code` writes).
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, replace

import sympy as sm

from .. import symbols as S
from .. import units
from ...engine.errors import AutolevModelError
from ..calculus import symbols_in
from ..io import CodeKind
from ..vectors import Vector
from ...errors import some_names
from .inputs import INTEGRATION, display_name
from ...engine.numbers import parse_number
from ...engine.results import Column


# -- building -------------------------------------------------------------------------------
def output_columns(snapshot, command) -> list[list[Column]]:
    files = []
    for cols in snapshot.outputs:
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


def encoded_values(snapshot) -> list:
    out = []
    for name, value in snapshot.encoded:
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


def program_file_name(filename: str) -> str:
    """A CODE command's file name as Autolev wrote its files: a Fortran program's in
    lower case (`CODE DYNAMICS() 7segSprint.f` wrote 7segsprint.f, which reads
    7segsprint.in and writes 7segsprint.1 ...; docs/language.md), any other as written."""
    return filename.lower() if program_language(filename) in ("f", "for") else filename


def time_dependence(system) -> list[str]:
    """What an ALGEBRAIC or NONLINEAR program computes that depends on T (OUTPUT columns,
    ENCODE arrays, its equations).  Such a program has no time of its own: it reads T
    from its .in file as it reads its variables (see take_time)."""
    defs = system.defs
    named = [(c.label, c.expr) for cols in system.files for c in cols]
    named += list(system.encoded)
    named += [("its equations", e) for v in system.extra_exprs.values() for e in v]
    found = []
    for label, value in named:
        values = list(value) if isinstance(value, sm.MatrixBase) else [sm.sympify(value)]
        # one walk over all of an array's entries (their parts are shared)
        if label not in found and defs.reaches(symbols_in(*values), S.TIME):
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


def definitions_at(snapshot, command) -> dict:
    """The model's definitions as `command` sees them: those at its CODE line, or the
    model's own for a command made later (a plain run)."""
    return snapshot.definitions.user_definitions() if command.definitions is None \
        else command.definitions


def with_undefined(snapshot, command, symbols: set):
    """A copy of `command` in which `symbols` have no definition."""
    return replace(command, definitions={
        s: e for s, e in definitions_at(snapshot, command).items() if s not in symbols})


def program_of(snapshot, command):
    """The command as its numeric system is built: where SOLVE defined the independent
    speeds' derivatives (SOLVE(ZERO, U4', U6', U7')), a copy in which they are undefined,
    their SOLVE's equations being solved at every evaluation instead (`solved_by_lu`).
    Other commands are themselves."""
    return _solved_numerically(snapshot, command)[0]


def solved_by_lu(snapshot, command) -> tuple | None:
    """(equations, unknowns) of the SOLVE that defined the independent speeds'
    derivatives for `command` (a CODE DYNAMICS), which its run solves by LU with
    partial pivoting at every evaluation: SOLVE's accelerations, without the
    cancellations of its closed form, a ratio of determinants (which lost 7 digits at a
    swing bike's state where LU loses 4).  None when the run uses the definitions."""
    return _solved_numerically(snapshot, command)[1]


def _solved_numerically(snapshot, command) -> tuple:
    """(program_of, solved_by_lu), once per command and revision of the model."""
    if command.kind is not CodeKind.DYNAMICS or not snapshot.solved_rates \
            or snapshot.dynamics is None:
        return command, None
    kept = snapshot.derived.table("programs solving SOLVE's equations numerically")
    entry = kept.get(id(command))
    if entry is not None and entry[0] is command:
        return entry[1]
    found = command, None
    defs = snapshot.definitions
    with defs.as_of(command.definitions):
        rhs = defs.rhs
        in_effect = [r for r in snapshot.solved_rates
                     if all(rhs.get(u) is v for u, v in zip(r.unknowns, r.solution))]
        if in_effect:
            wanted = {S.derivative(u) for u in snapshot.dynamics.independent_speeds()}
            solves = [r for r in in_effect if set(r.unknowns) == wanted]
            if solves:
                solve = solves[-1]
                found = (with_undefined(snapshot, command, wanted),
                         (list(solve.equations), list(solve.unknowns)))
    kept[id(command)] = (command, found)
    return found


def given_specified(snapshot, command, specified, overrides):
    """`command` as if the model had defined, before it, the SPECIFIED quantities it
    leaves undefined and that are given a value -- a number or a sympy expression in
    the model's symbols in `specified`, or a number among the `overrides` (in the
    quantity's unit) -- as Autolev's user edited the program's "Quantities to be
    specified"; with the functions of `specified` (callables f(t) or f(t, x)) and the
    overrides that are left."""
    given, functions, rest = {}, {}, {}
    for name, value in (specified or {}).items():
        sym = find_symbol(snapshot, name)
        if callable(value) and not isinstance(value, sm.Basic):
            functions[sym] = value
            continue
        given[sym] = sm.sympify(value)
        if snapshot.definitions.depends_on(given[sym], sym):
            raise AutolevModelError(f"specified: the value of {display_name(sym)} depends "
                                    f"on {display_name(sym)} itself")
    for name, value in (overrides or {}).items():
        sym = undefined_specified(snapshot, name)
        if sym is None:
            rest[name] = value
            continue
        number = _override_number(name, value)
        given[sym] = sm.Float(units.to_internal(number, command.units.get(sym)
                                                 or snapshot.units.get(sym)))
    if not given:
        return command, functions, rest
    kept = snapshot.derived.table("commands with specified quantities given")
    key = (id(command), tuple(sorted((str(k), sm.srepr(v)) for k, v in given.items())))
    entry = kept.get(key)
    if entry is None or entry[0] is not command:
        entry = kept[key] = (command, replace(
            command, definitions={**definitions_at(snapshot, command), **given}))
    return entry[1], functions, rest


def with_controls_given(snapshot, controls, overrides) -> dict:
    """`overrides` with a placeholder value for each of `controls` that is a parameter,
    not a specified quantity: a control takes its value from the nodes and its input is
    never read, so it needs none (gait2d's joint moments are VARIABLES without a value)."""
    placeholders = {name: 0.0 for name in controls or ()
                    if isinstance(name, str) and name.strip().upper() not in INTEGRATION
                    and snapshot.names_a_quantity(name)
                    and undefined_specified(snapshot, name) is None}
    return {**placeholders, **(overrides or {})}


def undefined_specified(snapshot, name: str):
    """The SPECIFIED quantity `name` (Q1', Q1P) names when the model leaves it undefined."""
    if not isinstance(name, str) or not snapshot.names_a_quantity(name) \
            or name.strip().upper() in INTEGRATION:
        return None
    try:
        sym = find_symbol(snapshot, name)
    except AutolevModelError:
        return None
    base = S.base_and_order(sym)[0]
    return sym if snapshot.kind_of(base) == "specified" \
        and sym not in snapshot.definitions.rhs else None


def _override_number(name: str, value) -> float:
    number = parse_number(value) if isinstance(value, str) else float(value)
    if number is None:
        raise AutolevModelError(f"{name}={value}: not a number")
    return number


def solution_columns(command, files: list, unknowns: list) -> list:
    """The OUTPUT files of a CODE ALGEBRAIC/NONLINEAR that solves for `unknowns`: with
    no OUTPUT, the solution is what the program is for, so one file of the unknowns."""
    if command.kind is CodeKind.NONLINEAR and not unknowns:
        raise AutolevModelError("CODE NONLINEAR needs equations and unknowns: "
                                "CODE NONLINEAR(EQ, x, y) file")
    if unknowns and not files and command.kind.solves:
        return [[Column(u, u.name, (command.inputs.get(u) or (None, None))[1]
                        or command.units.get(u)) for u in unknowns]]
    return files


def hidden_in_outputs(command) -> tuple:
    """Names the output routine of Autolev's program for `command` declares for itself
    (every C program of Autolev 4.1 has `int i1;` there)."""
    return ("i1",) if program_language(command.filename) == "c" else ()


def hidden_note(filename: str, hidden) -> str:
    """What `autolev run` and `autolev code` both say when they compute a program's
    outputs as Autolev's did, with the model's `hidden` quantities read as 0."""
    return (f"{filename}: Autolev's C program computed the OUTPUT and ENCODE quantities "
            "with " + ", ".join(f"{s} = 0" for s in hidden) + " (its output routine's "
            "counter `int i1` hides the model's i1); `autolev run` and `autolev code` "
            "reproduce them as it printed them (--no-quirks, or quirks=False, for the "
            "values meant)")


def solver_expressions(defs, kind: CodeKind, equations: list, unknowns: list) -> dict | None:
    """What CODE ALGEBRAIC (the linear system's matrix and right side) and CODE
    NONLINEAR (residuals and their Jacobian) evaluate besides the outputs."""
    if kind is CodeKind.ALGEBRAIC and equations:
        zero = {u: 0 for u in unknowns}
        return {"linear": [d for row in defs.jacobian(equations, unknowns) for d in row]
                + [defs.substitute(e, zero) for e in equations]}
    if kind is CodeKind.NONLINEAR:
        return {"residual": list(equations),
                "jacobian": [d for row in defs.jacobian(equations, unknowns) for d in row]}
    return None


def find_symbol(snapshot, name):
    if isinstance(name, sm.Symbol):
        return name
    for sym in snapshot.symbols:
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
    """[q deg = start, stop, step]: its target, its values start + step*k (k < count)
    given in `unit` (engine.algebraic.SweepPoints makes them, one at a time)."""

    target: object
    start: float
    step: float
    count: int
    unit: str | None


def sweep_values(command, inputs) -> SweepValues | None:
    found = sweep_of(command, inputs)
    return None if found is None else SweepValues(*found)
