"""Linearization of a model's equations of motion about an operating point.

The state x is what the model's CODE DYNAMICS program integrates, the inputs s are
its specified quantities without a definition, the outputs y its OUTPUT columns:

    x' = f(x, s)      ->   dx' = A dx + B ds
    y  = g(x, s, x')  ->   dy  = C dx + D ds

Exact: every Jacobian is the derivative of the symbolic equations through the Z's
(`Definitions.jacobian`), compiled and evaluated at the point; no finite differences.
Where Kane's equations give accelerations a from M a = F, the derivative of a is
M^-1 (dF - dM a) at the point (M is factorised, never inverted symbolically).
Dependent speeds are definitions in terms of the independent ones, so they are
eliminated already.  Dependent coordinates stay in the state (each configuration
constraint then adds an eigenvalue 0: the constraint's value is conserved) unless the
configuration constraints g(q) = 0 are given: the point is then put on them (Newton on
the dependent coordinates) and the state reduced to the independent ones, with
dq_dep = -G_dep^-1 G_ind dq_ind (G = dg/dx at the point).
"""
from __future__ import annotations

import warnings
from dataclasses import dataclass, field

import numpy as np
import scipy.linalg
import sympy as sm

from .. import symbols as S
from ...engine.errors import AutolevModelError
from ..io import CodeKind
from ...engine import clibrary
from . import codegen
from .inputs import display_name
from .projection import Projector
from ...engine.linear import Linearization
from .command import given_specified, program_of, solved_by_lu, with_undefined
from ...engine.options import RunOptions
from ..steps import SlowStep
from .prepare import prepare_command
from .snapshot import ModelSnapshot
from .compiled import compile_program
from ...engine.dual import DualJacobian, NotDifferentiable
from ...engine.evaluation import pivot_ratios
from .system import NumericSystem


def linearize(snapshot: ModelSnapshot, operating_point=None, inputs=None,
              backend: str = "auto", infile=None, missing_values: str = "refuse",
              overrides=None, constraints=None, dependent=None, locked=None,
              specified=None, progress=None, sweep_size: int = 1) -> Linearization:
    """The linearization of the snapshot's command (a CODE DYNAMICS) at
    `operating_point`: {name: value} for the model's constants, coordinates, speeds and
    specified quantities, in SI units and radians.  Names it leaves out take their INPUT
    (or .in) values; coordinates and speeds without either are 0, specified quantities
    0.  `inputs`: the names of the specified quantities that make B's columns (default:
    all of the program's specified quantities without a definition).  `overrides`:
    {name: value} in the quantities' own units (as `simulate` takes them), before the
    point's.
    `constraints`: configuration constraints g (sympy expressions in the model's
    symbols, g = 0 on the motion); `dependent`: the names of the coordinates they fix
    (default: chosen where G is best conditioned).  `locked`: names of coordinates held
    at their values (a rigid joint: Q' = U, with U and U' then 0 and U's row of Kane's
    equations dropped); the state leaves them out.  `specified`: {name: number or sympy
    expression} defining specified quantities (see run.given_specified); they are then
    no inputs.  `progress`: a stream told of steps past two seconds.  `sweep_size`: how
    many points the caller linearizes this system at (a sweep's length): backend "auto"
    compiles the Jacobians when that many would pay for it (see `_compiling_pays`)."""
    command, held = _program_to_linearize(snapshot, snapshot.command, locked)
    command, functions, overrides = given_specified(snapshot, command, specified, overrides)
    if functions:
        raise AutolevModelError("specified: a linearization takes values or expressions "
                                "for specified quantities, not Python functions: "
                                + ", ".join(map(display_name, functions)))
    point = dict(operating_point or {})
    for q in held:                # a locked coordinate without a value is held at 0
        if q not in command.inputs and not any(
                _symbol_named(snapshot, name) == q for name in point):
            point[display_name(q)] = 0.0
    specified_values = {}
    for name in list(point):
        sym = _symbol_named(snapshot, name)
        if sym is not None and snapshot.kind_of(sym) == "specified":
            specified_values[sym] = float(point.pop(name))
    prepared = prepare_command(snapshot, command, RunOptions(
        backend=backend, infile=infile, overrides=overrides, constraints=constraints,
        missing_values=missing_values, progress=progress), internal_values=point,
        warn_unassigned=False, locked=held, compile_functions=False)
    system = prepared.system
    if not system.nstate:
        raise AutolevModelError(f"CODE DYNAMICS {command.filename} integrates nothing: "
                                "there is no state to linearize")
    unused = [display_name(s) for s in specified_values if s not in system.specified]
    if unused:
        raise AutolevModelError("these specified quantities are not inputs of "
                                f"{command.filename}: {', '.join(unused)}")
    chosen = _chosen_inputs(snapshot, system, inputs)
    n_columns = sum(len(cols) for cols in system.files)
    tier = backend
    if backend == "auto":
        tier = "c" if _compiling_pays(sweep_size, system.nstate + len(chosen)) else "dual"
    # the tier is the request's (its size), never the history's: a point's answer is the
    # same whichever linearizations came before it
    key = (tuple(display_name(s) for s in chosen), n_columns, tier)

    def formed(tier: str, step: str, kept_as: tuple = key) -> _Jacobians:
        program = program_of(snapshot, command)
        with snapshot.definitions.as_of(program.definitions), SlowStep(
                progress, f"CODE DYNAMICS {command.filename}: {step}"):
            # a sweep's C that fails to compile warns and runs as Python (the same bits)
            made = system.jacobians[kept_as] = _jacobian_functions(
                system, chosen, n_columns, "auto" if tier == "c" and backend == "auto" else tier)
        snapshot.systems_changed()
        return made
    # once per system and tier: a sweep, and a later process, reuse them
    jacobians = system.jacobians.get(key) or formed(tier, "forming the Jacobians" + (
        f" (compiled for a sweep of {sweep_size} points)" if tier != backend else ""))
    t0 = prepared.inputs.internal("TINITIAL")
    x0 = np.array(prepared.inputs.vector(system.states), dtype=float)
    s0 = np.array([specified_values.get(s, 0.0) for s in system.specified], dtype=float)
    on_constraints = None
    if constraints:
        on_constraints = _ConfigurationConstraints(
            system, constraints, t0, x0, prepared.inputs.vector(prepared.extra_constants),
            dependent)
        x0 = on_constraints.solve(t0, x0)
    try:
        lin = _evaluate(system, jacobians, chosen, t0, x0, s0)
    except NotDifferentiable:       # a point where only the symbolic derivatives tell
        # kept apart: the points dual numbers take keep theirs (a later point's answer
        # must not depend on this one having come first)
        apart = key + ("symbolic",)
        jacobians = system.jacobians.get(apart) or formed(
            "python", "forming the Jacobians symbolically", apart)
        lin = _evaluate(system, jacobians, chosen, t0, x0, s0)
    bad = [display_name(x) for x, row, rate in zip(system.states, lin.A, lin.rates)
           if not (np.all(np.isfinite(row)) and np.isfinite(rate))]
    if bad:
        raise AutolevModelError(
            "the equations of motion are not finite at the operating point: the "
            f"derivatives of {', '.join(bad)} (or their partial derivatives) are "
            "infinite or undefined there (a division by zero: a mass or an inertia of 0?)")
    lin.point = {display_name(p): float(v) for p, v in zip(system.params, system.constant_values)}
    lin.point.update({display_name(x): float(v) for x, v in zip(system.states, x0)})
    lin.point.update({display_name(s): float(v) for s, v in zip(system.specified, s0)})
    lin.outputs = [c.label for cols in system.files for c in cols]
    lin.locked = [display_name(q) for q in held]
    if on_constraints is not None:
        on_constraints.reduce(lin, t0, x0)
    return lin


@dataclass
class SymbolicLinearization:
    """A and B as sympy matrices in the model's symbols (x' = f(x, s): A = df/dx,
    B = df/ds), with the names of their rows and columns."""

    A: sm.Matrix
    B: sm.Matrix
    states: list
    inputs: list
    locked: list = field(default_factory=list)


# beyond this many states symbolic Jacobians grow past what anyone reads or simplifies
MAX_SYMBOLIC_STATES = 12


def linearize_symbolic(snapshot: ModelSnapshot, point=None, inputs=None, locked=None,
                       max_states: int = MAX_SYMBOLIC_STATES) -> SymbolicLinearization:
    """A and B of the snapshot's command's equations of motion as expressions: every
    definition and Z expanded, Kane's accelerations solved by sympy's LU (for small
    models: more than `max_states` states is refused).  `point`: {name: value}
    substituted (SI units and radians); the rest stay symbols.  Dependent coordinates
    stay in the state."""
    command, held = _program_to_linearize(snapshot, snapshot.command, locked)
    values = {}
    for name, value in (point or {}).items():
        sym = _symbol_named(snapshot, name)
        if sym is None:
            raise AutolevModelError(f"point: the model has no quantity named {name!r}")
        values[sym] = sm.nsimplify(value) if isinstance(value, int) else value
    program = program_of(snapshot, command)
    with snapshot.definitions.as_of(program.definitions):
        system = NumericSystem(snapshot, backend="python", zero=command.zero, locked=held,
                               solving=solved_by_lu(snapshot, command))
        if system.nstate > max_states:
            raise AutolevModelError(
                f"{system.nstate} states: symbolic A and B are for models of at most "
                f"{max_states} states (Model.linearize gives them as numbers at a point)")
        chosen = _chosen_inputs(snapshot, system, inputs)
        explicit = snapshot.definitions.explicit
        nx, n = system.nstate, len(system.implicit_unknowns)
        rates = [explicit(e) for e in system.rhs_exprs[:nx]]
        if n:
            dyn = [explicit(e) for e in system.rhs_exprs[nx:nx + n * n + n]]
            mass, forcing = sm.Matrix(n, n, dyn[:n * n]), sm.Matrix(dyn[n * n:])
            for pos, a in zip(system.unknown_positions, mass.LUsolve(forcing)):
                rates[pos] = a
    fixed = {k: sm.S.Zero for k in system.aux_fixed}
    f = sm.Matrix(rates).xreplace(fixed)
    a_matrix = f.jacobian(system.states)
    b_matrix = f.jacobian(chosen) if chosen else sm.zeros(len(f), 0)
    if values:
        a_matrix, b_matrix = a_matrix.xreplace(values), b_matrix.xreplace(values)
    return SymbolicLinearization(a_matrix, b_matrix,
                                 [display_name(x) for x in system.states],
                                 [display_name(c) for c in chosen],
                                 [display_name(q) for q in held])


class _ConfigurationConstraints:
    """g(x) = 0 and G = dg/dx compiled; puts a point on g = 0 by Newton's method on
    the dependent coordinates and reduces a linearization to the independent ones."""

    def __init__(self, system, constraints, t0: float, x0, extra_values, dependent):
        self.projector = Projector(system, constraints, t0, x0, extra_values)
        self.names = [display_name(x) for x in system.states]
        g, jac = self.projector.residual_and_jacobian(t0, np.asarray(x0, dtype=float))
        m = len(g)
        if dependent is None:
            _, r, pivots = scipy.linalg.qr(jac, pivoting=True)
            if m > min(jac.shape) or abs(r[m - 1, m - 1]) <= 1e-10 * max(1.0, abs(r[0, 0])):
                raise AutolevModelError("the configuration constraints are not independent "
                                        "at the operating point")
            self.dep = sorted(int(k) for k in pivots[:m])
        else:
            upper = [n.upper() for n in self.names]
            unknown = [d for d in dependent if str(d).upper() not in upper]
            if unknown or len(dependent) != m:
                raise AutolevModelError(f"dependent: {m} state names are needed (one per "
                                        f"constraint), not {', '.join(map(str, dependent))}")
            self.dep = sorted(upper.index(str(d).upper()) for d in dependent)
        self.ind = [k for k in range(len(self.names)) if k not in self.dep]

    def solve(self, t0: float, x0) -> np.ndarray:
        x = np.array(x0, dtype=float)
        for _ in range(50):
            g, jac = self.projector.residual_and_jacobian(t0, x)
            if np.abs(g).max() <= 1e-13 * (1.0 + np.abs(x).max()):
                return x
            x[self.dep] -= np.linalg.solve(jac[:, self.dep], g)
        raise AutolevModelError(
            "the operating point cannot be put on the configuration constraints by "
            f"changing {', '.join(self.names[k] for k in self.dep)} (residual "
            f"{np.abs(g).max():.3g}); give values for them closer to the constraints")

    def reduce(self, lin: Linearization, t0: float, x0) -> None:
        _, jac = self.projector.residual_and_jacobian(t0, x0)
        ind, dep = self.ind, self.dep
        basis = np.zeros((len(self.names), len(ind)))
        basis[ind, np.arange(len(ind))] = 1.0
        basis[dep] = -np.linalg.solve(jac[:, dep], jac[:, ind])
        lin.A, lin.B = lin.A[ind] @ basis, lin.B[ind]
        lin.C = lin.C @ basis
        lin.rates = lin.rates[ind]
        lin.states = [self.names[k] for k in ind]
        lin.dependent = [self.names[k] for k in dep]


def _program_to_linearize(snapshot, command, locked) -> tuple:
    """(the command whose equations are linearized, the locked coordinates): a CODE
    DYNAMICS, solving Kane's equations where coordinates are locked."""
    if command.kind is not CodeKind.DYNAMICS:
        raise AutolevModelError(f"CODE {command.kind.upper()} {command.filename}: only a "
                                "CODE DYNAMICS program has equations of motion to linearize")
    held = _locked_coordinates(snapshot, locked or ())
    return (_with_kanes_equations(snapshot, program_of(snapshot, command)) if held
            else command), held


def _locked_coordinates(snapshot, names) -> list:
    held = []
    for name in names:
        sym = _symbol_named(snapshot, name)
        if sym is None or snapshot.kind_of(sym) not in ("variable", "motionvariable") \
                or S.base_and_order(sym)[1] != 0:
            raise AutolevModelError(f"locked: {name!r} is not a coordinate of the model")
        if sym not in held:
            held.append(sym)
    return held


def _with_kanes_equations(snapshot, command):
    """`command` with the speeds' derivatives undefined again where SOLVE(ZERO, U')
    defined them, so the program solves Kane's equations (which locking can cut down);
    one object per command, so its numeric system is built once."""
    kept = snapshot.derived.table("commands solving Kane's equations")
    entry = kept.get(id(command))
    if entry is not None and entry[0] is command:
        return entry[1]
    unsolved = with_undefined(snapshot, command,
                              {S.derivative(u) for u in snapshot.solved_speeds})
    kept[id(command)] = (command, unsolved)
    return unsolved


def _symbol_named(snapshot, name: str):
    wanted = str(name).strip().upper().replace("'", "P")
    for sym in snapshot.symbols:
        if display_name(sym).upper().replace("'", "P") == wanted:
            return sym
    return None


def _chosen_inputs(snapshot, system, names) -> list:
    if names is None:
        return list(system.specified)
    chosen = []
    for name in names:
        sym = _symbol_named(snapshot, name)
        if sym is None or sym not in system.specified:
            known = ", ".join(display_name(s) for s in system.specified) or "none"
            raise AutolevModelError(f"{name!r} is not a specified quantity this program "
                                    f"reads (those it reads: {known})")
        chosen.append(sym)
    return chosen


# seconds gcc takes per byte of the Python source of the symbolic Jacobians (BICYCLE14's:
# 7 MB of Python, 60 s of gcc on an idle core; see bench/large_models.py)
C_SECONDS_PER_SOURCE_BYTE = 1e-5
# seconds one evaluation on dual numbers takes per byte of the right-hand side's Python
# (the Whipple benchmark's 87 kB: 16 ms; a double pendulum's 2 kB: 0.3 ms)
DUAL_SECONDS_PER_SOURCE_BYTE = 1.6e-7


def _compiling_pays(sweep_size: int, n_varied: int) -> bool:
    """Whether `sweep_size` evaluations on dual numbers cost more than compiling the
    symbolic Jacobians, which are about 1 + n_varied times the right-hand side's source
    (so the source's size cancels).  Without a C compiler the dual numbers stay: compiled
    to Python, the symbolic Jacobians are no faster."""
    if clibrary.compiler() is None:
        return False
    return (sweep_size * DUAL_SECONDS_PER_SOURCE_BYTE
            >= C_SECONDS_PER_SOURCE_BYTE * (1 + n_varied))


@dataclass
class _Jacobians:
    """The Jacobians of one system: the right-hand side's own Python run on dual
    numbers (dual.py: one linearization never waits for a compiler), or formed
    symbolically and compiled (a sweep large enough to pay for it, or a backend asked
    for)."""

    rhs: object             # values and Jacobian of the right-hand side
    outputs: object         # values-free Jacobian of the OUTPUT columns
    n_rhs: int
    n_out: int


def _jacobian_functions(system, chosen: list, n_columns: int, backend: str) -> _Jacobians:
    """The right-hand side (rates, M, F) and its Jacobian in the state and the chosen
    inputs; the Jacobian of the OUTPUT columns in the state, the chosen inputs and the
    accelerations: on dual numbers (backend "dual"), else compiled."""
    defs = system.defs
    variables = list(system.states) + chosen
    rhs = list(system.rhs_exprs)
    c_syms = system.params + system.constant_defs
    given = {"t": [S.TIME], "x": system.states, "c": c_syms, "s": system.specified}
    fixed = dict(system.aux_fixed)
    out_exprs = system.output_exprs[:n_columns]
    accels = list(system.implicit_unknowns)
    if backend == "dual":
        states = list(range(len(system.states)))
        inputs = [system.specified.index(s) for s in chosen]
        rhs_source = codegen.python_source(
            codegen.Program(given, rhs, defs, fixed).build(), "autolev_linear_rhs")
        out_source = codegen.python_source(
            codegen.Program(dict(given, a=accels), out_exprs, defs, fixed).build(),
            "autolev_linear_outputs")
        return _Jacobians(
            DualJacobian(rhs_source, "autolev_linear_rhs", 4, {1: states, 3: inputs},
                         with_values=True),
            DualJacobian(out_source, "autolev_linear_outputs", 5,
                         {1: states, 3: inputs, 4: list(range(len(accels)))},
                         with_values=False),
            len(rhs), len(out_exprs))
    rhs_jac = defs.jacobian(rhs, variables)
    rhs_fn = compile_program(
        codegen.Program(given, rhs + [d for row in rhs_jac for d in row], defs,
                        fixed).build(), backend, "autolev_linear_rhs")
    out_jac = defs.jacobian(out_exprs, variables + accels) if out_exprs else []
    out_fn = compile_program(
        codegen.Program(dict(given, a=accels), [d for row in out_jac for d in row], defs,
                        fixed).build(), backend, "autolev_linear_outputs")
    return _Jacobians(rhs_fn, out_fn, len(rhs), len(out_exprs))


def _evaluate(system, jac: _Jacobians, chosen: list, t0: float, x0, s0) -> Linearization:
    nx, nv, n = system.nstate, system.nstate + len(chosen), len(system.implicit_unknowns)
    out = np.empty(jac.n_rhs * (1 + nv))
    jac.rhs.call(np.array([t0]), x0, system.constant_values, s0, out)
    values, grads = out[:jac.n_rhs], out[jac.n_rhs:].reshape(jac.n_rhs, nv)
    # a recursion's pivot that is not positive makes M singular
    if system.pivot_count and not np.all(pivot_ratios(values, system.pivot_count) > 0):
        raise AutolevModelError("the mass matrix is singular at the operating point")
    rates = values[:nx].copy()
    jrates = grads[:nx].copy()
    accelerations = np.zeros(n)
    if n:
        # each equation divided by its largest coefficient: whether M is singular does not
        # depend on the units (a cell model's masses are 1e-23 kg)
        mass = values[nx:nx + n * n].reshape(n, n)
        if not np.all(np.isfinite(mass)):
            raise AutolevModelError("the mass matrix is not finite at the operating point")
        rows = np.max(np.abs(mass), axis=1)
        if not np.all(rows > 0):
            raise AutolevModelError("the mass matrix is singular at the operating point")
        mass = mass / rows[:, None]
        forcing = values[nx + n * n:nx + n * n + n] / rows
        dmass = grads[nx:nx + n * n].reshape(n, n, nv) / rows[:, None, None]
        dforcing = grads[nx + n * n:nx + n * n + n] / rows[:, None]
        with warnings.catch_warnings():     # a singular M is reported below
            warnings.simplefilter("ignore", scipy.linalg.LinAlgWarning)
            lu = scipy.linalg.lu_factor(mass, check_finite=False)
        if np.any(np.abs(np.diag(lu[0])) <= 1e-14):
            raise AutolevModelError("the mass matrix is singular at the operating point")
        accelerations = scipy.linalg.lu_solve(lu, forcing, check_finite=False)
        # in Fortran order: LAPACK's, which a C-ordered right side is first copied to
        daccel = scipy.linalg.lu_solve(lu, np.asfortranarray(
            dforcing - np.einsum("ijk,j->ik", dmass, accelerations)), check_finite=False)
        rates[system.unknown_positions] = accelerations
        jrates[system.unknown_positions] = daccel
    else:
        daccel = np.zeros((0, nv))
    ny = jac.n_out
    jy = np.empty(ny * (nv + n))
    jac.outputs.call(np.array([t0]), x0, system.constant_values, s0, accelerations, jy)
    jy = jy.reshape(ny, nv + n)
    through_accelerations = jy[:, nv:nv + n] @ daccel if n else np.zeros((ny, nv))
    jout = jy[:, :nv] + through_accelerations
    return Linearization(
        A=jrates[:, :nx], B=jrates[:, nx:], C=jout[:, :nx], D=jout[:, nx:],
        states=[display_name(x) for x in system.states],
        inputs=[display_name(s) for s in chosen], outputs=[], point={},
        rates=rates, accelerations=rates[_speed_positions(system)])


def _speed_positions(system) -> list:
    """The states that are speeds: those Kane's equations give the rates of, and those
    that are the rate of another state (Q' = U makes U a speed, Q' one in X'' = ...)."""
    positions = set(system.unknown_positions)
    index = {x: k for k, x in enumerate(system.states)}
    for expr in system.rhs_exprs[:system.nstate]:
        if expr in index:
            positions.add(index[expr])
    return sorted(positions)
