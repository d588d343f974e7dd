"""A model's equations of motion as trajectory optimization takes them, with their
exact derivatives, compiled, evaluated at many nodes in one call.

The state x is what the model's CODE DYNAMICS integrates, the controls u its specified
quantities (all of those it leaves undefined, or the ones named), the parameters p its
constants without a definition.  Two forms:

    explicit   x' = f(x, u, p, t)                     (Kane's M a = F solved at each node)
    implicit   r(x, x', u, p, t) = 0                  (no mass matrix solved)

r's row for a state whose rate is given (q' = g) is x'_i - g_i; its row for a speed
whose rate Kane's equations give is row k of M a - F (a: those speeds' rates, M and F
of the model's own forming), so r is linear in x'.  Every derivative is symbolic,
through the Z's (`Definitions.jacobian`), printed once and compiled (C where there is a
compiler, else Python); ∂r/∂x' is M's entries and ones.  The Jacobians are sparse: each
comes with its pattern (rows, cols) and values per node.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import symbols as S
from ...engine.errors import AutolevModelError
from ...engine.options import RunOptions
from . import codegen
from .command import given_specified, program_of, undefined_specified
from .compiled import compile_program
from .inputs import INTEGRATION, display_name
from .prepare import prepare_command
from .snapshot import ModelSnapshot
from ..steps import SlowStep


@dataclass(frozen=True)
class Pattern:
    """Where a sparse Jacobian's entries are: rows[k], cols[k] for entry k of each node's
    values, in a matrix of `shape`."""

    rows: np.ndarray
    cols: np.ndarray
    shape: tuple

    @property
    def nnz(self) -> int:
        return len(self.rows)

    def dense(self, values: np.ndarray) -> np.ndarray:
        """Values (nodes x nnz) as dense matrices (nodes x rows x cols)."""
        values = np.asarray(values, dtype=float)
        out = np.zeros((values.shape[0],) + self.shape)
        out[:, self.rows, self.cols] = values
        return out

    @classmethod
    def of_mask(cls, mask: np.ndarray) -> "Pattern":
        rows, cols = np.nonzero(mask)
        return cls(rows, cols, mask.shape)


@dataclass
class Jacobians:
    """The sparse Jacobians of one form at N nodes: values (N x nnz) by block, with the
    blocks' patterns ("x", "xdot" (implicit form only), "u", "p")."""

    values: dict
    patterns: dict

    def dense(self, block: str) -> np.ndarray:
        return self.patterns[block].dense(self.values[block])


@dataclass(frozen=True)
class _Derivatives:
    """A Dynamics' Jacobian program: the right-hand side, then the structural nonzeros
    of its Jacobian at `entries` (row, column of (x, u, p)), with the sparsity of r's
    and f's Jacobians."""

    function: object
    entries: np.ndarray
    patterns: dict              # r's: "x", "u", "p", "xdot"
    explicit_patterns: dict     # f's: "x", "u", "p"


class Dynamics:
    """The compiled equations of motion of one CODE DYNAMICS, with exact Jacobians (see
    the module's text).  Arrays have one row per node: x (N x nx), x' (N x nx), u (N x
    nu), t (N,) or a number; p (np,) is one parameter set for every node (default: the
    model's values).  One node may be given as 1-D arrays."""

    def __init__(self, system, controls: list, parameter_values: np.ndarray, backend: str,
                 definitions, progress=None, what: str = "CODE DYNAMICS"):
        self._system = system
        self._control_symbols = list(controls)
        self._definitions = definitions      # () -> the command's view of the definitions
        # the program's inputs besides t and x: the parameters left, and the specified
        # quantities with the parameters made controls (the rest of them 0)
        self._parameter_symbols = [p for p in system.params if p not in set(controls)]
        self._input_symbols = list(system.specified) + [
            c for c in controls if c not in set(system.specified)]
        self.states = [display_name(x) for x in system.states]
        self.controls = [display_name(u) for u in controls]
        self.parameters = [display_name(p) for p in self._parameter_symbols]
        self.parameter_values = np.array(parameter_values, dtype=float)
        self._control_positions = [self._input_symbols.index(u) for u in controls]
        nx, nu, n = system.nstate, len(controls), len(system.implicit_unknowns)
        self._sizes = (nx, nu, len(self._parameter_symbols), n)
        self._dynamic = np.array(system.unknown_positions, dtype=int)
        self._kinematic = np.array([i for i in range(nx) if i not in set(system.unknown_positions)],
                                   dtype=int)
        self._backend_asked = backend
        self._jacobians_step = SlowStep(progress, f"{what}: forming and compiling its Jacobians")
        with SlowStep(progress, f"{what}: compiling its equations"):
            rhs = codegen.Program(self._given(), list(system.rhs_exprs), system.defs,
                                  dict(system.aux_fixed)).build()
            self._values = compile_program(rhs, backend, "autolev_dynamics")
        self.backend = self._values.backend
        # formed when a Jacobian is first asked for: f and r alone need none of it
        self._derivatives: _Derivatives | None = None

    def _given(self) -> dict:
        """The program's inputs: time, state, parameters, specified quantities."""
        return {"t": [S.TIME], "x": self._system.states, "p": self._parameter_symbols,
                "s": self._input_symbols}

    def casadi(self):
        """The same equations as CasADi functions, for CasADi's own derivatives and
        solvers (needs casadi): a casadi_form.CasadiDynamics."""
        from .casadi_form import casadi_dynamics
        with self._definitions():
            return casadi_dynamics(self._system, self._given(), self._control_positions, {
                "states": self.states, "controls": self.controls,
                "parameters": self.parameters, "values": self.parameter_values})

    # -- forming ------------------------------------------------------------------------
    def _formed_derivatives(self) -> "_Derivatives":
        """The right-hand side (rates, M, F) with its Jacobian's structural nonzeros in
        (x, u, p), as one compiled program, and the sparsity it gives (once).  The
        constants' definitions are in the programs (they depend on p, which varies)."""
        if self._derivatives is not None:
            return self._derivatives
        system = self._system
        defs = system.defs
        with self._definitions(), self._jacobians_step:
            variables = (list(system.states) + self._control_symbols
                         + self._parameter_symbols)
            rhs = list(system.rhs_exprs)
            jacobian = defs.jacobian(rhs, variables)
            entries = [(i, j) for i, row in enumerate(jacobian) for j, d in enumerate(row)
                       if d != 0]
            program = codegen.Program(self._given(), rhs + [jacobian[i][j] for i, j in entries],
                                      defs, dict(system.aux_fixed)).build()
            function = compile_program(program, self._backend_asked,
                                       "autolev_dynamics_jacobian")
        entries = np.array(entries, dtype=int).reshape(-1, 2)
        self._derivatives = _Derivatives(function, entries, *self._sparsity(entries))
        return self._derivatives

    def _sparsity(self, entries: np.ndarray) -> tuple[dict, dict]:
        """The residual's patterns and f's, from the right-hand side's `entries`: a
        kinematical row has its rate's entries, a dynamical row of r those of its M row
        and F entry, and one of f those of every dynamical row (M^-1 mixes them)."""
        nx, nu, npar, n = self._sizes
        nw = nx + nu + npar
        rhs_mask = np.zeros((nx + n * n + n, nw), dtype=bool)
        rhs_mask[entries[:, 0], entries[:, 1]] = True
        mask = np.zeros((nx, nw), dtype=bool)
        mask[self._kinematic] = rhs_mask[self._kinematic]
        xdot = np.zeros((nx, nx), dtype=bool)
        xdot[self._kinematic, self._kinematic] = True
        mass = self._mass_nonzero()
        for k, row in enumerate(self._dynamic):
            mask[row] = rhs_mask[nx + n * n + k] | rhs_mask[nx + k * n:nx + (k + 1) * n].any(0)
            xdot[row, self._dynamic] = mass[k]
        explicit = mask.copy()
        explicit[self._dynamic] = mask[self._dynamic].any(0)
        return self._split(mask) | {"xdot": Pattern.of_mask(xdot)}, self._split(explicit)

    def _mass_nonzero(self) -> np.ndarray:
        nx, _, _, n = self._sizes
        exprs = self._system.rhs_exprs[nx:nx + n * n]
        return np.array([e != 0 for e in exprs], dtype=bool).reshape(n, n)

    def _split(self, mask: np.ndarray) -> dict:
        nx, nu, _, _ = self._sizes
        return {"x": Pattern.of_mask(mask[:, :nx]), "u": Pattern.of_mask(mask[:, nx:nx + nu]),
                "p": Pattern.of_mask(mask[:, nx + nu:])}

    # -- evaluating -----------------------------------------------------------------------
    def _nodes(self, x, u, t, xdot=None):
        nx, nu, _, _ = self._sizes
        x = np.atleast_2d(np.asarray(x, dtype=float))
        count = x.shape[0]
        u = np.zeros((count, nu)) if u is None else np.asarray(u, dtype=float).reshape(count, nu)
        t = np.broadcast_to(np.asarray(t, dtype=float), (count,))
        if x.shape[1] != nx:
            raise ValueError(f"x: {nx} states per node ({', '.join(self.states)}), "
                             f"not {x.shape[1]}")
        if xdot is not None:
            xdot = np.asarray(xdot, dtype=float).reshape(count, nx)
        return x, u, t, xdot

    def _evaluated(self, x, u, p, t, jacobian: bool = True):
        """(right-hand side values: N x (nx + n^2 + n), dense Jacobian: N x rows x (x, u,
        p), or None without `jacobian`) at every node."""
        nx, nu, npar, n = self._sizes
        p = self.parameter_values if p is None else np.asarray(p, dtype=float)
        if p.shape != (npar,):
            raise ValueError(f"p: {npar} parameters ({', '.join(self.parameters)}), "
                             f"not {p.shape}")
        n_rhs, count = nx + n * n + n, x.shape[0]
        inputs = np.zeros((count, len(self._input_symbols)))
        inputs[:, self._control_positions] = u
        derivatives = self._formed_derivatives() if jacobian else None
        function = self._values if derivatives is None else derivatives.function
        out = np.empty((count, n_rhs + (0 if derivatives is None else len(derivatives.entries))))
        if self.backend == "c":             # every node in one call of the C
            function.call.rows([np.ascontiguousarray(t).reshape(count, 1),
                                np.ascontiguousarray(x), p, inputs],
                               [True, True, False, True], out)
        else:
            for k in range(count):
                function.call(t[k:k + 1], x[k], p, inputs[k], out[k])
        if derivatives is None:
            return out, None
        jac = np.zeros((count, n_rhs, nx + nu + npar))
        jac[:, derivatives.entries[:, 0], derivatives.entries[:, 1]] = out[:, n_rhs:]
        return out[:, :n_rhs], jac

    def _mass_and_forcing(self, values):
        """M and F at every node, from the right-hand side's values, or (dM, dF) from its
        dense Jacobian (one more axis: the variables)."""
        nx, _, _, n = self._sizes
        return (values[:, nx:nx + n * n].reshape((-1, n, n) + values.shape[2:]),
                values[:, nx + n * n:nx + n * n + n])

    def explicit(self, x, u=None, p=None, t=0.0) -> np.ndarray:
        """x' = f(x, u, p, t) at every node (N x nx)."""
        x, u, t, _ = self._nodes(x, u, t)
        values, _ = self._evaluated(x, u, p, t, jacobian=False)
        return self._rates(values)[0]

    def _rates(self, values):
        nx = self._sizes[0]
        rates = values[:, :nx].copy()
        accelerations = None
        if len(self._dynamic):
            mass, forcing = self._mass_and_forcing(values)
            accelerations = _solved(mass, forcing[..., None])[..., 0]
            rates[:, self._dynamic] = accelerations
        return rates, accelerations

    def residual(self, x, xdot, u=None, p=None, t=0.0) -> np.ndarray:
        """r(x, x', u, p, t) at every node (N x nx): 0 on the motion."""
        x, u, t, xdot = self._nodes(x, u, t, xdot)
        values, _ = self._evaluated(x, u, p, t, jacobian=False)
        return self._residual(values, xdot)

    def _residual(self, values, xdot):
        r = np.empty_like(xdot)
        r[:, self._kinematic] = xdot[:, self._kinematic] - values[:, self._kinematic]
        if len(self._dynamic):
            mass, forcing = self._mass_and_forcing(values)
            r[:, self._dynamic] = np.einsum("nkj,nj->nk", mass, xdot[:, self._dynamic]) - forcing
        return r

    def residual_jacobians(self, x, xdot, u=None, p=None, t=0.0) -> Jacobians:
        """∂r/∂x, ∂r/∂x', ∂r/∂u, ∂r/∂p at every node, sparse (see Jacobians)."""
        x, u, t, xdot = self._nodes(x, u, t, xdot)
        values, jac = self._evaluated(x, u, p, t)
        nx, nu, npar, n = self._sizes
        dense = np.zeros((x.shape[0], nx, nx + nu + npar))
        dense[:, self._kinematic] = -jac[:, self._kinematic]
        ddot = np.zeros((x.shape[0], nx, nx))
        ddot[:, self._kinematic, self._kinematic] = 1.0
        if n:
            mass, _ = self._mass_and_forcing(values)
            dmass, dforcing = self._mass_and_forcing(jac)
            dense[:, self._dynamic] = (np.einsum("nkjw,nj->nkw", dmass, xdot[:, self._dynamic])
                                       - dforcing)
            ddot[:, self._dynamic[:, None], self._dynamic[None, :]] = mass
        return self._sparse(dense, self._formed_derivatives().patterns, ddot)

    def explicit_jacobians(self, x, u=None, p=None, t=0.0) -> Jacobians:
        """∂f/∂x, ∂f/∂u, ∂f/∂p at every node, sparse (see Jacobians): a speed's row is
        M^-1 (∂F - ∂M a), so it has every entry its coupled rows have."""
        x, u, t, _ = self._nodes(x, u, t)
        values, jac = self._evaluated(x, u, p, t)
        nx, _, _, n = self._sizes
        dense = jac[:, :nx].copy()
        if n:
            mass, _ = self._mass_and_forcing(values)
            _, accelerations = self._rates(values)
            dmass, dforcing = self._mass_and_forcing(jac)
            dense[:, self._dynamic] = _solved(
                mass, dforcing - np.einsum("nkjw,nj->nkw", dmass, accelerations))
        return self._sparse(dense, self._formed_derivatives().explicit_patterns)

    def _sparse(self, dense, patterns: dict, xdot=None) -> Jacobians:
        nx, nu, _, _ = self._sizes
        blocks = {"x": dense[:, :, :nx], "u": dense[:, :, nx:nx + nu], "p": dense[:, :, nx + nu:]}
        if xdot is not None:
            blocks["xdot"] = xdot
        return Jacobians({b: m[:, patterns[b].rows, patterns[b].cols] for b, m in blocks.items()},
                         {b: patterns[b] for b in blocks})


def _solved(mass: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """M^-1 rhs at every node; a singular M is the model's, named."""
    try:
        return np.linalg.solve(mass, rhs)
    except np.linalg.LinAlgError:
        raise AutolevModelError("the mass matrix is singular at a node") from None


def dynamics(snapshot: ModelSnapshot, controls=None, specified=None, backend: str = "auto",
             infile=None, overrides=None, missing_values: str = "refuse",
             progress=None) -> Dynamics:
    """The snapshot's command's Dynamics.  `controls`: names of the controls u: specified
    quantities the program reads without a definition (default: all of those) or
    parameters, which then vary from node to node; `specified`: {name: number or sympy
    expression} for the specified quantities that are no controls (the rest are 0).
    The parameters' values come from INPUT, `infile` and `overrides` ({name: value} in
    the quantities' own units), as a run takes them."""
    command, functions, overrides = given_specified(snapshot, snapshot.command, specified,
                                                    overrides)
    if functions:
        raise AutolevModelError("specified: the dynamics take values or expressions for "
                                "specified quantities, not Python functions: "
                                + ", ".join(map(display_name, functions)))
    # a parameter named as a control takes its value from the nodes: its input is never
    # read, so it needs none (gait2d's joint moments are VARIABLES without a value)
    overrides = {**{name: 0.0 for name in controls or ()
                    if isinstance(name, str) and name.strip().upper() not in INTEGRATION
                    and snapshot.names_a_quantity(name)
                    and undefined_specified(snapshot, name) is None},
                 **(overrides or {})}
    prepared = prepare_command(snapshot, command, RunOptions(
        backend=backend, infile=infile, overrides=overrides, missing_values=missing_values,
        progress=progress, recursion=False), warn_unassigned=False, compile_functions=False)
    system = prepared.system
    if not system.nstate:
        raise AutolevModelError(f"CODE DYNAMICS {command.filename} integrates nothing: "
                                "there are no dynamics")
    chosen = _controls(system, controls)
    program = program_of(snapshot, command)

    def definitions():
        return snapshot.definitions.as_of(program.definitions)
    values = prepared.inputs.vector([p for p in system.params if p not in set(chosen)])
    with definitions():
        return Dynamics(system, chosen, values, backend, definitions, progress,
                        f"CODE DYNAMICS {command.filename}")


def _controls(system, names) -> list:
    """The controls named: specified quantities, or parameters (constants, variables
    without a derivative) to vary from node to node."""
    if names is None:
        return list(system.specified)
    by_name = {display_name(s).upper(): s for s in list(system.specified) + system.params}
    chosen = []
    for name in names:
        sym = by_name.get(str(name).upper())
        if sym is None:
            known = ", ".join(display_name(s) for s in system.specified) or "none"
            raise AutolevModelError(
                f"controls: {name!r} is not a specified quantity or a parameter the "
                f"program reads (its specified quantities: {known})")
        chosen.append(sym)
    return chosen
