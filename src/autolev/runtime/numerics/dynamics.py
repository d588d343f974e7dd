"""A model's equations of motion as trajectory optimization takes them, with their
exact derivatives, compiled, evaluated at many nodes in one call.

The state x is what the model's CODE DYNAMICS integrates, the controls u its specified
quantities (all of those it leaves undefined, or the ones named), the parameters p its
constants without a definition.  Two forms:

    explicit   x' = f(x, u, p, t)                     (Kane's M a = F solved at each node)
    implicit   r(x, x', u, p, t) = 0                  (no mass matrix solved)

r's row for a state whose rate is given (q' = g) is x'_i - g_i; its row for a speed
whose rate Kane's equations give is row k of M a - F (a: those speeds' rates, M and F
of the model's own forming), so r is linear in x'.  For a model whose bodies form a
tree (runtime/articulated.py) r's Jacobians are those of its rows M a - F formed by
the Newton-Euler recursion (the same equations: each body's acceleration from the
root, the wrenches summed from the leaves; n^2 entries of a few terms each, where
Kane's M a - F grows as n^4), and f's are -M^-1 times them at a = f (the
articulated-body recursion's accelerations, as a run integrates them): the program
gives M's entries and those right-hand sides, and each node's M = L^T D L from the
leaves (which fills in nothing) is solved for all of them at once, in loops over the
columns (engine/ltdl.c; numpy's same operations in the Python tier).  Every
derivative is symbolic, through the Z's (`Definitions.jacobian`), printed once and
compiled (C where there is a compiler, else Python); ∂r/∂x' is M's entries and ones.  The
Jacobians are sparse: each comes with its pattern (rows, cols) and values per node.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import sympy as sm

from .. import symbols as S
from ...engine.errors import AutolevModelError
from ...engine.evaluation import pivot_ratios
from ...engine.massmatrix import (LTDL_SOURCE, CompactRows, MassStructure,
                                  compiled_ltdl_columns, ltdl_columns)
from ...engine.options import RunOptions
from . import codegen
from .command import (equations_and_unknowns, given_specified, program_of,
                      with_controls_given)
from .compiled import compile_program
from .inputs import display_name
from .prepare import SystemBuild, numeric_system, prepare_command
from .snapshot import ModelSnapshot
from .system import lower_derivative
from ..printer import LANES
from ..steps import SlowStep

# a tree's Jacobians: the nodes whose outputs fit in 1 MB computed, then solved
_CHUNK_DOUBLES = 1 << 17
_FEW_RUNS = 16              # a block gathered in at most this many runs is copied by them


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
    blocks' patterns ("x", "xdot" (implicit form only), "u", "p"), and what they were
    differentiated from: "recursion" (a tree's M a - F by the Newton-Euler recursion)
    or "mass matrix" (M a - F as Kane's equations form M and F)."""

    values: dict
    patterns: dict
    by: str

    def dense(self, block: str) -> np.ndarray:
        return self.patterns[block].dense(self.values[block])


@dataclass(frozen=True)
class _Derivatives:
    """A Dynamics' Jacobian program: inputs (t, x, p, s, a), a the dynamical rows' rates;
    outputs the right-hand side (rates, M, F), then the structural nonzeros of the
    Jacobian of (-g for a kinematical row, row k of M a - F for a dynamical one) in
    (x, u, p), one per `entries` row (state row of r, column), in row-major order: r's
    own Jacobian, and f's by -M^-1 at a = f's accelerations."""

    function: object
    entries: np.ndarray
    patterns: dict              # r's: "x", "u", "p" (entries' order), "xdot"
    explicit_patterns: dict     # f's: "x", "u", "p"
    blocks: dict                # "x", "u", "p" -> positions in entries
    ones: np.ndarray            # r's "xdot" values: positions that are 1 (kinematical)
    mass_at: np.ndarray         # ... positions that are M's entries
    mass_entries: np.ndarray    # ... and which entry of M (row-major) each one is


@dataclass(frozen=True)
class _Gather:
    """The outputs of a program that make a block's values, in order: copied run by run
    where they lie in a few contiguous runs (a chain's rows of M^-1 B), else one by one."""
    outputs: np.ndarray
    runs: tuple                 # (first output, first value, length); () for one by one

    @classmethod
    def of(cls, outputs: np.ndarray) -> "_Gather":
        cuts = np.nonzero(np.diff(outputs) != 1)[0] + 1
        firsts, ends = np.r_[0, cuts], np.r_[cuts, len(outputs)]
        runs = tuple((int(outputs[a]), int(a), int(b - a)) for a, b in zip(firsts, ends)
                     if b > a)
        return cls(outputs, runs if len(runs) <= _FEW_RUNS else ())

    def into(self, values: np.ndarray, rows: np.ndarray) -> None:
        """values (nodes x the block's entries) from the program's `rows`."""
        if self.runs:
            for first, at, length in self.runs:
                values[:, at:at + length] = rows[:, first:first + length]
        else:
            np.take(rows, self.outputs, axis=1, out=values)


@dataclass(frozen=True)
class _TreeDerivatives:
    """f's Jacobian program of a tree: inputs (t, x, p, s); outputs f's rows by the
    articulated-body recursion, its pivots and the entries they come from (a pivot that
    is not positive makes M singular); from `at_mass` M's entries held compactly
    (`compact`'s rows); from `at_rhs` B = -∂(M a - F) at a = f, the dynamical rows'
    (m x w: rows in the factoring's order, the w columns any of them has); then the
    kinematical rows' structural nonzeros.  `solve` overwrites B with M^-1 B, the
    dynamical rows' Jacobian, at every node.  `blocks`: each block's outputs, in its
    pattern's order (row-major), as _Gather."""

    function: object
    pivot_count: int
    width: int                  # outputs per node
    at_mass: int
    at_rhs: int
    columns: int                # w
    patterns: dict              # "x", "u", "p"
    blocks: dict                # "x", "u", "p" -> outputs
    compact: CompactRows        # M's structure, as the solve reads it

    def solve(self, rows: np.ndarray) -> None:
        """B := M^-1 B at every row (node) of `rows`, in place (ltdl.c where the program
        is C, its numpy twin otherwise: the same operations)."""
        args = (rows, self.at_mass, self.at_rhs, len(self.compact.start) - 1, self.columns,
                self.compact)
        if self.function.backend == "c":
            failed = compiled_ltdl_columns(self.function.call.lib, *args)
        else:
            failed = ltdl_columns(*args)
        if failed:
            raise AutolevModelError("the mass matrix is singular at a node")


@dataclass(frozen=True)
class _TreeForms:
    """A tree's Jacobians, symbolic, formed together in one order whichever is asked for
    first: each Z's name, and so the order of a generated sum, depends on what was
    formed before it, and a fixed order gives each program the same numbers whatever
    the user asked for first.  r's rows are the Newton-Euler recursion's M a - F (and
    -g for a kinematical row); f's Jacobian is -M^-1 times r's at a = f, f the
    articulated-body recursion's rates: M's entries and the right-hand sides are
    formed here, the solve is numeric (_TreeDerivatives.solve)."""

    system: object              # the command's system with the recursion's accelerations
    f_head: list                # f's rates, then the recursion's pivots and their entries
    r_jacobian: list            # r's rows x (x, u, p, a)
    structure: MassStructure    # M's, eliminated from the leaves
    mass: list                  # M's entries held compactly (the structure's)
    rhs: list                   # -∂(M a - F) at a = f: dynamical row k x (x, u, p)


@dataclass(frozen=True)
class _TreeResidual:
    """r's Jacobian program by the Newton-Euler recursion (a tree; r's dynamical rows
    M a - F formed by it): inputs (t, x, p, s, a); outputs the structural nonzeros of
    r's Jacobian in (x, u, p) and in a (M's entries), row-major."""

    function: object
    width: int                  # outputs per node
    patterns: dict              # "x", "u", "p" (the program's order), "xdot"
    blocks: dict                # "x", "u", "p" -> positions in the outputs
    ones: np.ndarray            # "xdot" values: positions that are 1 (kinematical)
    mass_at: np.ndarray         # ... positions that are M's entries
    mass_outputs: np.ndarray    # ... and the output each one is


class Dynamics:
    """The compiled equations of motion of one CODE DYNAMICS, with exact Jacobians (see
    the module's text).  Arrays have one row per node: x (N x nx), x' (N x nx), u (N x
    nu), t (N,) or a number; p (np,) is one parameter set for every node (default: the
    model's values).  One node may be given as 1-D arrays."""

    def __init__(self, system, controls: list, parameter_values: np.ndarray, backend: str,
                 definitions, tree=lambda: None, progress=None, what: str = "CODE DYNAMICS",
                 inverse=lambda speeds: None):
        self._system = system
        # () -> the command's system with the recursion's accelerations, None for a model
        # that is not a tree; taken when f's Jacobians are first asked for
        self._tree = tree
        # (speeds) -> a tree's M a - F by the Newton-Euler recursion (InverseDynamics: a
        # row per speed of `speeds`, the dynamical rows', their rates as the symbols of
        # x', and the speeds from the leaves)
        self._inverse = inverse
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
        # the common factors taken out of each expression, for all of its programs
        self._factored: dict = {}
        self._jacobians_step = SlowStep(progress, f"{what}: forming and compiling its Jacobians")
        with SlowStep(progress, f"{what}: compiling its equations"):
            rhs = codegen.Program(self._given(), list(system.rhs_exprs), system.defs,
                                  dict(system.aux_fixed),
                                  factored_memo=self._factored).build(signed=True)
            self._values = compile_program(rhs, backend, "autolev_dynamics", lanes=True)
        self.backend = self._values.backend
        # formed when a Jacobian is first asked for (f and r alone need none of it), with
        # the parameters' columns or without (True, False)
        self._derivatives: dict[bool, _Derivatives] = {}
        self._by_columns: dict[str, list] = {}     # see _differentiated
        self._tree_derivatives: dict[bool, _TreeDerivatives | None] = {}
        self._tree_residuals: dict[bool, _TreeResidual | None] = {}
        self._trees: _TreeForms | None = None      # see _formed_trees
        self._trees_formed = False

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
    def _formed_derivatives(self, parameters: bool = True) -> "_Derivatives":
        """The Jacobian program and its sparsity (once).  r is linear in x' and its
        dynamical rows are M a - F: differentiated at a given a, their Jacobian is the
        program's, summed in it (no dM, dF per node).  The constants' definitions are in
        the program (they depend on p, which varies).  Without `parameters`, no column
        of p: a collocation with the parameters fixed computes none of them."""
        if parameters in self._derivatives:
            return self._derivatives[parameters]
        system = self._system
        with self._definitions(), self._jacobians_step:
            groups = [self._differentiated("x, u")] + [self._differentiated("p")] * parameters
            jacobian = [[d for part in parts for d in part] for parts in zip(*groups)]
            function, entries = self._compiled(
                system, self._given() | {"a": list(system.implicit_unknowns)},
                list(system.rhs_exprs), jacobian, "autolev_dynamics_jacobian")
        self._derivatives[parameters] = self._sparsity(function, entries, parameters)
        return self._derivatives[parameters]

    def _compiled(self, system, inputs: dict, head: list, jacobian: list, name: str):
        """(the compiled program of `head`'s expressions, then the structural nonzeros of
        `jacobian` row-major; those nonzeros' (row, column))."""
        nonzero = [(i, j, d) for i, row in enumerate(jacobian) for j, d in enumerate(row)
                   if d != 0]
        program = codegen.Program(inputs, head + [d for _, _, d in nonzero], system.defs,
                                  dict(system.aux_fixed),
                                  factored_memo=self._factored).build(signed=True)
        entries = np.array([(i, j) for i, j, _ in nonzero], dtype=int).reshape(-1, 2)
        return compile_program(program, self._backend_asked, name, lanes=True), entries

    def _residual_rows(self, dynamic_rows: list | None = None) -> list:
        """The expressions differentiated, one per state row: -g for a kinematical row,
        for a dynamical one row k of `dynamic_rows`, by default of M a - F as formed (a:
        the symbols of the dynamical rows' rates)."""
        nx, _, _, n = self._sizes
        rhs = list(self._system.rhs_exprs)
        if dynamic_rows is None:
            mass, forcing = rhs[nx:nx + n * n], rhs[nx + n * n:]
            rates = list(self._system.implicit_unknowns)
            dynamic_rows = [sm.Add(*[mass[k * n + j] * rates[j] for j in range(n)
                                     if mass[k * n + j] != 0]) - forcing[k]
                            for k in range(n)]
        rows = [-rhs[i] for i in range(nx)]          # (a dynamical row's is replaced)
        for k, row in enumerate(self._dynamic):
            rows[row] = dynamic_rows[k]
        return rows

    def _differentiated(self, group: str) -> list:
        """The residual rows' derivatives (rows in state order) in the columns of `group`
        ("x, u" or "p"): each group once, for the programs with and without p."""
        if group not in self._by_columns:
            variables = (list(self._system.states) + self._control_symbols if group == "x, u"
                         else self._parameter_symbols)
            self._by_columns[group] = self._system.defs.jacobian(self._residual_rows(),
                                                                 variables)
        return self._by_columns[group]

    def _sparsity(self, function, entries: np.ndarray, parameters: bool) -> "_Derivatives":
        """r's patterns are its entries'; a row of f has every entry of its own, and a
        speed's row every entry of every dynamical row (M^-1 mixes them)."""
        nx, nu, npar, n = self._sizes
        bounds = self._columns(parameters)
        blocks, patterns = self._blocks(entries, parameters)
        mask = np.zeros((nx, nx + nu + npar * parameters), dtype=bool)
        mask[entries[:, 0], entries[:, 1]] = True
        if len(self._dynamic):
            mask[self._dynamic] = mask[self._dynamic].any(0)
        explicit = {name: Pattern.of_mask(mask[:, lo:hi]) for name, (lo, hi) in bounds.items()}
        xdot = np.zeros((nx, nx), dtype=int)            # 1: kinematical, 2: M's entry
        xdot[self._kinematic, self._kinematic] = 1
        exprs = self._system.rhs_exprs[nx:nx + n * n]
        nonzero = np.array([e != 0 for e in exprs], dtype=bool).reshape(n, n)
        xdot[np.ix_(self._dynamic, self._dynamic)] = 2 * nonzero
        patterns["xdot"] = Pattern.of_mask(xdot > 0)
        kinds = xdot[patterns["xdot"].rows, patterns["xdot"].cols]
        where = {int(r): k for k, r in enumerate(self._dynamic)}
        mass_at = np.nonzero(kinds == 2)[0]
        mass_entries = np.array([where[int(patterns["xdot"].rows[i])] * n
                                 + where[int(patterns["xdot"].cols[i])] for i in mass_at],
                                dtype=int)
        return _Derivatives(function, entries, patterns, explicit, blocks,
                            np.nonzero(kinds == 1)[0], mass_at, mass_entries)

    def _blocks(self, entries: np.ndarray, parameters: bool) -> tuple[dict, dict]:
        """Which of the (row, column) `entries` each block ("x", "u", "p") holds, and the
        blocks' patterns."""
        blocks, patterns = {}, {}
        for name, (lo, hi) in self._columns(parameters).items():
            blocks[name] = np.nonzero((entries[:, 1] >= lo) & (entries[:, 1] < hi))[0]
            patterns[name] = Pattern(entries[blocks[name], 0], entries[blocks[name], 1] - lo,
                                     (self._sizes[0], hi - lo))
        return blocks, patterns

    def _formed_trees(self) -> "_TreeForms | None":
        """A tree's Jacobians, symbolic, all formed at once in one order, whichever is
        asked for first (see _TreeForms); None: the model is not a tree, or its recursion
        reads an input the mass matrix's form does not (then both come from M a - F)."""
        if self._trees_formed:
            return self._trees
        nx, _, _, n = self._sizes
        with self._definitions(), self._jacobians_step:
            tree = self._tree()
            if tree is not None and set(tree.params) <= set(self._system.params) \
                    and set(tree.specified) <= set(self._input_symbols):
                rhs = list(tree.rhs_exprs)
                rates = rhs[:nx]
                for k, at in enumerate(tree.unknown_positions):
                    rates[at] = rhs[nx + n * n + k]
                columns = (list(self._system.states) + self._control_symbols
                           + self._parameter_symbols)
                unknowns = list(self._system.implicit_unknowns)
                inverse = self._inverse([lower_derivative(d) for d in unknowns])
                r_jacobian = self._system.defs.jacobian(self._residual_rows(inverse.rows),
                                                        columns + unknowns)
                width = len(columns)
                mass = [[r_jacobian[row][width + j] for j in range(n)]
                        for row in self._dynamic]
                structure = MassStructure.eliminated(
                    [[j for j in range(n) if j != k and (mass[k][j] != 0 or mass[j][k] != 0)]
                     for k in range(n)], reversed(inverse.leaves_first))
                order = structure.order
                compact = [mass[order[k]][order[j]]
                           for k, j in zip(structure.rows, structure.columns)]
                self._trees = _TreeForms(tree, rates + rhs[nx + n * n + n:], r_jacobian,
                                         structure, compact,
                                         self._at_f(r_jacobian, rates, width))
        self._trees_formed = True
        return self._trees

    def _at_f(self, r_jacobian: list, rates: list, width: int) -> list:
        """-∂(M a - F) (the dynamical rows of r's Jacobian, its first `width` columns) at
        a = f's accelerations `rates`, each entry a Z."""
        defs = self._system.defs
        at_f = {a: rates[row] for a, row in zip(self._system.implicit_unknowns, self._dynamic)}
        return [[defs.substitute(-d, at_f) for d in r_jacobian[row][:width]]
                for row in self._dynamic]

    def _tree_kept(self, kept: dict, parameters: bool, make):
        """A tree's program (made once for each `parameters`: `make(forms, parameters)`),
        or None (see _formed_trees)."""
        if parameters not in kept:
            forms = self._formed_trees()
            kept[parameters] = None if forms is None else make(forms, parameters)
        return kept[parameters]

    def _formed_tree_derivatives(self, parameters: bool) -> "_TreeDerivatives | None":
        """f's Jacobian program by the recursion (once), or None (see _formed_trees)."""
        return self._tree_kept(self._tree_derivatives, parameters, self._tree_program)

    def _tree_program(self, forms: "_TreeForms", parameters: bool) -> _TreeDerivatives:
        n = self._sizes[3]
        width = self._width(parameters)
        order = forms.structure.order
        kept = [c for c in range(width) if any(row[c] != 0 for row in forms.rhs)]
        kinematic = [(int(i), c, -d) for i in self._kinematic
                     for c, d in enumerate(forms.r_jacobian[i][:width]) if d != 0]
        at_mass = len(forms.f_head)
        at_rhs = at_mass + len(forms.mass)
        at_kinematic = at_rhs + n * len(kept)
        outputs = (forms.f_head + forms.mass
                   + [forms.rhs[order[k]][c] for k in range(n) for c in kept]
                   + [d for _, _, d in kinematic])
        output_of = {(i, c): at_kinematic + at for at, (i, c, _) in enumerate(kinematic)}
        for k in range(n):
            row = int(self._dynamic[order[k]])
            output_of |= {(row, c): at_rhs + k * len(kept) + at for at, c in enumerate(kept)}
        entries = np.array(sorted(output_of), dtype=int).reshape(-1, 2)
        at_output = np.array([output_of[i, c] for i, c in entries.tolist()], dtype=int)
        with self._definitions(), self._jacobians_step:
            program = codegen.Program(self._given(), outputs, forms.system.defs,
                                      dict(forms.system.aux_fixed),
                                      factored_memo=self._factored).build(signed=True)
            function = compile_program(program, self._backend_asked,
                                       "autolev_dynamics_tree_jacobian",
                                       extra_source=LTDL_SOURCE, lanes=True)
        blocks, patterns = self._blocks(entries, parameters)
        return _TreeDerivatives(function, forms.system.pivot_count, len(outputs),
                                at_mass, at_rhs, len(kept), patterns,
                                {name: _Gather.of(at_output[at])
                                 for name, at in blocks.items()},
                                CompactRows.of(forms.structure))

    def _formed_tree_residual(self, parameters: bool) -> "_TreeResidual | None":
        """r's Jacobian program by the Newton-Euler recursion (once), or None (see
        _formed_trees): then r's Jacobians come from M a - F as formed, whose entries
        grow as n^3 where the recursion's rows grow as n."""
        return self._tree_kept(self._tree_residuals, parameters, self._tree_residual_program)

    def _tree_residual_program(self, forms: "_TreeForms", parameters: bool) -> _TreeResidual:
        nx, nu, npar, _ = self._sizes
        width = self._width(parameters)            # the columns before a's
        jacobian = [row[:width] + row[nx + nu + npar:] for row in forms.r_jacobian]
        rates = list(self._system.implicit_unknowns)
        with self._definitions(), self._jacobians_step:
            function, entries = self._compiled(self._system, self._given() | {"a": rates},
                                               [], jacobian, "autolev_dynamics_tree_residual")
        in_a = entries[:, 1] >= width
        blocks, patterns = self._blocks(entries[~in_a], parameters)
        outputs = np.nonzero(~in_a)[0]
        blocks = {name: outputs[at] for name, at in blocks.items()}
        xdot = np.zeros((nx, nx), dtype=int)            # 1: kinematical, else 2 + output
        xdot[self._kinematic, self._kinematic] = 1
        for at in np.nonzero(in_a)[0]:
            xdot[entries[at, 0], self._dynamic[entries[at, 1] - width]] = 2 + at
        patterns["xdot"] = Pattern.of_mask(xdot > 0)
        kinds = xdot[patterns["xdot"].rows, patterns["xdot"].cols]
        return _TreeResidual(function, len(entries), patterns, blocks,
                             np.nonzero(kinds == 1)[0], np.nonzero(kinds >= 2)[0],
                             kinds[kinds >= 2] - 2)

    def _width(self, parameters: bool) -> int:
        """The Jacobian's columns in x, u and, with `parameters`, p."""
        nx, nu, npar, _ = self._sizes
        return nx + nu + npar * parameters

    def _columns(self, parameters: bool) -> dict:
        """Each block's columns (lo, hi) among the Jacobian's (x, u, p or not)."""
        nx, nu, npar, _ = self._sizes
        return {"x": (0, nx), "u": (nx, nx + nu)} | (
            {"p": (nx + nu, nx + nu + npar)} if parameters else {})

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

    def _evaluated(self, x, u, p, t, rates=None, parameters: bool = True):
        """The right-hand side's values at every node (N x (nx + n^2 + n)), and with
        `rates` (N x n: the dynamical rows' a) the Jacobian program's entries (N x
        entries), else None."""
        nx, _, _, n = self._sizes
        n_rhs = nx + n * n + n
        if rates is None:
            return self._called(self._values, n_rhs, x, u, p, t), None
        derivatives = self._formed_derivatives(parameters)
        out = self._called(derivatives.function, n_rhs + len(derivatives.entries), x, u, p,
                           t, np.ascontiguousarray(rates, dtype=float).reshape(-1, n))
        return out[:, :n_rhs], out[:, n_rhs:]

    def _called(self, function, width: int, x, u, p, t, rates=None,
                out: np.ndarray | None = None) -> np.ndarray:
        """A compiled program's outputs (N x width) at every node, from t, x, p, the
        specified quantities (the controls u, the rest 0) and, when given, a; into
        `out` (C-ordered) when given."""
        npar = self._sizes[2]
        p = self.parameter_values if p is None else np.asarray(p, dtype=float)
        if p.shape != (npar,):
            raise ValueError(f"p: {npar} parameters ({', '.join(self.parameters)}), "
                             f"not {p.shape}")
        count = x.shape[0]
        inputs = np.zeros((count, len(self._input_symbols)))
        inputs[:, self._control_positions] = u
        arrays = [np.ascontiguousarray(t).reshape(count, 1), np.ascontiguousarray(x), p,
                  inputs] + ([] if rates is None else [rates])
        out = np.empty((count, width)) if out is None else out
        if self.backend == "c":             # every node in one call of the C
            function.call.rows(arrays, [True, True, False] + [True] * (len(arrays) - 3), out)
        else:
            for k in range(count):
                function.call(*[a if a.ndim == 1 else a[k] for a in arrays], out[k])
        return out

    def _mass_and_forcing(self, values):
        """M and F at every node, from the right-hand side's values, or (dM, dF) from its
        dense Jacobian (one more axis: the variables)."""
        nx, _, _, n = self._sizes
        return (values[:, nx:nx + n * n].reshape((-1, n, n) + values.shape[2:]),
                values[:, nx + n * n:nx + n * n + n])

    def explicit(self, x, u=None, p=None, t=0.0) -> np.ndarray:
        """x' = f(x, u, p, t) at every node (N x nx)."""
        x, u, t, _ = self._nodes(x, u, t)
        values, _ = self._evaluated(x, u, p, t)
        return self._rates(values)[0]

    def _rates(self, values):
        nx = self._sizes[0]
        rates = values[:, :nx].copy()
        accelerations = None
        if len(self._dynamic):
            mass, forcing = self._mass_and_forcing(values)
            accelerations = _solved_at_nodes(mass, forcing[..., None])[..., 0]
            rates[:, self._dynamic] = accelerations
        return rates, accelerations

    def mass_matrix(self, x, u=None, p=None, t=0.0) -> np.ndarray:
        """M of the dynamical rows at every node (N x n x n; n: the speeds whose rates
        Kane's equations give): r's ∂/∂x' there, and what f's rates solve."""
        x, u, t, _ = self._nodes(x, u, t)
        values, _ = self._evaluated(x, u, p, t)
        return self._mass_and_forcing(values)[0].copy()

    def residual(self, x, xdot, u=None, p=None, t=0.0) -> np.ndarray:
        """r(x, x', u, p, t) at every node (N x nx): 0 on the motion."""
        x, u, t, xdot = self._nodes(x, u, t, xdot)
        values, _ = self._evaluated(x, u, p, t)
        return self._residual(values, xdot)

    def _residual(self, values, xdot):
        r = np.empty_like(xdot)
        r[:, self._kinematic] = xdot[:, self._kinematic] - values[:, self._kinematic]
        if len(self._dynamic):
            mass, forcing = self._mass_and_forcing(values)
            r[:, self._dynamic] = np.einsum("nkj,nj->nk", mass, xdot[:, self._dynamic]) - forcing
        return r

    def residual_jacobians(self, x, xdot, u=None, p=None, t=0.0,
                           parameters: bool = True) -> Jacobians:
        """∂r/∂x, ∂r/∂x', ∂r/∂u, and with `parameters` ∂r/∂p, at every node, sparse (see
        Jacobians)."""
        x, u, t, xdot = self._nodes(x, u, t, xdot)
        tree = self._formed_tree_residual(parameters) if self._sizes[3] else None
        if tree is not None:
            out = self._called(tree.function, tree.width, x, u, p, t,
                               np.ascontiguousarray(xdot[:, self._dynamic]))
            ddot = np.empty((x.shape[0], tree.patterns["xdot"].nnz))
            ddot[:, tree.ones] = 1.0
            ddot[:, tree.mass_at] = out[:, tree.mass_outputs]
            return Jacobians({name: out[:, at] for name, at in tree.blocks.items()}
                             | {"xdot": ddot}, dict(tree.patterns), "recursion")
        values, entries = self._evaluated(x, u, p, t, rates=xdot[:, self._dynamic],
                                          parameters=parameters)
        d = self._formed_derivatives(parameters)
        nx = self._sizes[0]
        blocks = {name: entries[:, at] for name, at in d.blocks.items()}
        ddot = np.empty((x.shape[0], d.patterns["xdot"].nnz))
        ddot[:, d.ones] = 1.0
        ddot[:, d.mass_at] = values[:, nx + d.mass_entries]
        return Jacobians(blocks | {"xdot": ddot}, dict(d.patterns), "mass matrix")

    def explicit_jacobians(self, x, u=None, p=None, t=0.0,
                           parameters: bool = True) -> Jacobians:
        """∂f/∂x, ∂f/∂u, and with `parameters` ∂f/∂p, at every node, sparse (see
        Jacobians): a speed's row is -M^-1 ∂(M a - F) at f's accelerations a, so it
        has every entry its coupled rows have; a tree's M a - F is the Newton-Euler
        recursion's, any other's Kane's."""
        x, u, t, _ = self._nodes(x, u, t)
        nx, nu, npar, n = self._sizes
        tree = self._formed_tree_derivatives(parameters) if n else None
        if tree is not None:
            return self._tree_jacobians(tree, x, u, p, t)
        values, _ = self._evaluated(x, u, p, t)
        _, accelerations = self._rates(values)
        count = x.shape[0]
        _, entries = self._evaluated(x, u, p, t, rates=np.zeros((count, n))
                                     if accelerations is None else accelerations,
                                     parameters=parameters)
        d = self._formed_derivatives(parameters)
        dense = np.zeros((count, nx, nx + nu + npar * parameters))
        dense[:, d.entries[:, 0], d.entries[:, 1]] = -entries
        if n:
            mass, _ = self._mass_and_forcing(values)
            dense[:, self._dynamic] = _solved_at_nodes(mass, dense[:, self._dynamic])
        blocks = {name: dense[:, d.explicit_patterns[name].rows,
                              d.explicit_patterns[name].cols + lo]
                  for name, (lo, _) in self._columns(parameters).items()}
        return Jacobians(blocks, dict(d.explicit_patterns), "mass matrix")

    def _tree_jacobians(self, tree: _TreeDerivatives, x, u, p, t) -> Jacobians:
        nx = self._sizes[0]
        head = nx + 2 * tree.pivot_count
        count = x.shape[0]
        values = {name: np.empty((count, len(gather.outputs)))
                  for name, gather in tree.blocks.items()}
        # a chunk of nodes at a time: computed, solved and gathered while in the cache
        chunk = max(1, _CHUNK_DOUBLES // tree.width // LANES) * LANES   # whole groups
        outputs = np.empty((min(chunk, count), tree.width))
        for lo in range(0, count, chunk):
            nodes = slice(lo, lo + chunk)
            out = outputs[:len(x[nodes])]
            self._called(tree.function, tree.width, x[nodes], u[nodes], p, t[nodes], out=out)
            if not np.all(pivot_ratios(out[:, :head], tree.pivot_count) > 0):
                raise AutolevModelError("the mass matrix is singular at a node")
            tree.solve(out)
            for name, gather in tree.blocks.items():
                gather.into(values[name][nodes], out)
        return Jacobians(values, dict(tree.patterns), "recursion")


def _solved_at_nodes(mass: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """M^-1 rhs at every node; a singular M is the model's, named."""
    try:
        return np.linalg.solve(mass, rhs)
    except np.linalg.LinAlgError:
        raise AutolevModelError("the mass matrix is singular at a node") from None


def dynamics(snapshot: ModelSnapshot, controls=None, specified=None, backend: str = "auto",
             infile=None, overrides=None, missing_values: str = "refuse",
             progress=None, recursion: bool = True) -> Dynamics:
    """The snapshot's command's Dynamics.  `controls`: names of the controls u: specified
    quantities the program reads without a definition (default: all of those) or
    parameters, which then vary from node to node; `specified`: {name: number or sympy
    expression} for the specified quantities that are no controls (the rest are 0).
    The parameters' values come from INPUT, `infile` and `overrides` ({name: value} in
    the quantities' own units), as a run takes them.  `recursion=False`: the Jacobians
    from Kane's M a - F even for a tree (as a run's RunOptions.recursion)."""
    command, functions, overrides = given_specified(snapshot, snapshot.command, specified,
                                                    overrides)
    if functions:
        raise AutolevModelError("specified: the dynamics take values or expressions for "
                                "specified quantities, not Python functions: "
                                + ", ".join(map(display_name, functions)))
    overrides = with_controls_given(snapshot, controls, overrides)
    options = RunOptions(backend=backend, infile=infile, overrides=overrides,
                         missing_values=missing_values, progress=progress, recursion=False)
    prepared = prepare_command(snapshot, command, options, warn_unassigned=False,
                               compile_functions=False)
    system = prepared.system
    if not system.nstate:
        raise AutolevModelError(f"CODE DYNAMICS {command.filename} integrates nothing: "
                                "there are no dynamics")
    chosen = _controls(system, controls)
    program = program_of(snapshot, command)

    def definitions():
        return snapshot.definitions.as_of(program.definitions)

    def tree():
        """The command's system with a tree's accelerations by the recursion (its
        expressions alone: no outputs, nothing compiled), or None."""
        solving = equations_and_unknowns(command.args, command.kind.upper())
        build = SystemBuild.of(replace(options, recursion=True))
        recursive = numeric_system(snapshot, command, (), (), solving, build)
        return recursive if recursive.pivot_count else None

    def inverse(speeds):
        """A tree's M a - F by the Newton-Euler recursion, a row per speed of `speeds`
        (the recursion solves this model: `tree()` said so)."""
        return snapshot.dynamics.joints(speeds).inverse()
    values = prepared.inputs.vector([p for p in system.params if p not in set(chosen)])
    with definitions():
        return Dynamics(system, chosen, values, backend, definitions,
                        tree if recursion else (lambda: None), progress,
                        f"CODE DYNAMICS {command.filename}", inverse)


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
