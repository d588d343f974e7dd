"""The numeric form of a model: its state, parameters, right-hand side and outputs.

What Autolev integrated: every variable X (or X') that is not itself defined but whose
derivative is (q' = ..., u' = ... from SOLVE, KINDIFFS, a NICHECK work integral), plus
the independent generalized speeds whose derivatives come from Kane's equations.  The
state is sorted alphabetically, as in Autolev's files.  Dependent speeds are computed
from their constraint definitions whenever needed; auxiliary speeds are zero.  Kane's
equations are solved at each evaluation with an LU factorisation of the mass matrix
(never a symbolic inverse).  Specified quantities come from their definitions, from
callables given by the user, or are zero (with a warning).

Three generated functions: the constants (definitions that depend on constants only,
evaluated once per parameter set, as Autolev's "Evaluate constants"), the right-hand
side (only what the state derivatives need), and the outputs (OUTPUT columns and
ENCODE values, evaluated at print times only, with the accelerations found there).
"""
from __future__ import annotations

import inspect

import numpy as np
import sympy as sm

from .. import articulated
from .. import symbols as S
from .. import units
from ..calculus import symbols_in
from ...engine.errors import AutolevModelError
from ...engine import clibrary
from . import codegen
from ...engine.cloop import extra_source as loop_extra_source
from .compiled import WalkedFirst, compile_program, compiling_in_background
from ...engine.evaluation import CompiledEvaluation
from ...engine.massmatrix import MassStructure


def alphabetical(syms) -> list:
    """Autolev's order for constants and states: case-insensitive, lexicographic."""
    return sorted(syms, key=lambda s: (s.name.lower(), s.name))


def read_order(syms, symbols) -> list:
    """Constants, then variables, then their first derivatives, ... (the order in which
    Autolev's ALGEBRAIC programs read their inputs), each group sorted by name ignoring
    case; `symbols`: the declared ones' SymbolInfo."""
    def key(s):
        base, order = S.base_and_order(s)
        info = symbols.get(base)
        return (order, (info.kind if info else None) != "constant", base.name.lower(),
                base.name)
    return sorted(syms, key=key)


class NumericSystem(CompiledEvaluation):
    """State, parameters and compiled functions of a model (what the numerics read of it:
    a ModelSnapshot).

    `outputs`: a list of files, each a list of Column; `encoded`: (name, value) pairs.
    `integrate=False` (ALGEBRAIC/NONLINEAR programs) builds no right-hand side; every
    variable is an input then.  `solving=(equations, unknowns)`: equations solved for
    the unknown derivatives at each evaluation, in place of Kane's equations: a CODE
    ODE's (CODE ODE(EQ, x'', ...)), or those of a SOLVE that defined the speeds'
    derivatives (command.solved_by_lu); with no equations (CODE ODE()) it
    integrates the model's explicit differential equations alone, forming nothing
    else, and a declared derivative without a definition is a constant input.
    `locked`: coordinates held where they are (a rigid joint): each must have Q' = U
    for an independent speed U, which is then 0 with U', its row of Kane's equations
    dropped, and Q a constant of the program.  `solved`:
    symbols whose values the caller supplies at output time (the unknowns of
    ALGEBRAIC/NONLINEAR); `extra`: {name: [expressions]}
    compiled with the outputs' inputs.  `compile_functions=False`: the analysis alone
    (states, inputs, expressions), for a writer of programs in another language or for
    a run that checks its inputs before anything is compiled, then calls `compile()`."""

    def __init__(self, snapshot, outputs=(), encoded=(), backend: str = "auto",
                 integrate: bool = True, solving=None, solved=(), extra=None,
                 zero=None, hidden_in_outputs=(), locked=(), compile_functions: bool = True,
                 recursive: bool = False):
        # what the system reads of the model once built (kept with it in the cache)
        self.defs = snapshot.definitions
        self.symbols = snapshot.symbols
        self.recursive = recursive
        self._zero = zero
        self.backend = backend
        self._fix_speeds(locked, snapshot.dynamics)
        # the recursion's pivots, then the entries they come from, after f
        # (runtime/articulated.py)
        self.pivots: list = []
        rates, unknowns, dyn = (self._integrated(solving, snapshot) if integrate
                                else ({}, [], []))
        self.states = alphabetical(rates)
        self.nstate = len(self.states)
        self.implicit_unknowns = unknowns          # derivatives solved from M a = f
        self.solved = [s for s in solved if s not in unknowns]
        self._n = len(unknowns)
        self.mass_structure = MassStructure.of(dyn[:self._n ** 2], self._n)
        solved_here = set(unknowns)     # their places are filled by the M a = f solve
        rate_exprs = [sm.S.Zero if rates[x] in solved_here else rates[x]
                      for x in self.states]
        # rates (0 where solved), then M row by row, then F, then the pivots and entries
        self.rhs_exprs = rhs_exprs = rate_exprs + dyn + self.pivots
        self.pivot_count = len(self.pivots) // 2
        # a linearization's compiled Jacobians, by (inputs, output columns, backend):
        # kept with the system in the cache of built models
        self.jacobians: dict = {}
        out_exprs, extra = self._output_expressions(outputs, encoded, extra)
        self.extra_exprs = extra
        # what is given: time, state, solved derivatives and unknowns, fixed speeds
        accel_inputs = list(unknowns) + self.solved
        given = set(self.states) | {S.TIME} | set(self.aux_fixed) | set(accel_inputs)
        self.hidden_in_outputs = self._hidden(hidden_in_outputs)
        if self.hidden_in_outputs:
            out_exprs = self._as_output_routine(out_exprs, rhs_exprs, extra, given)
        self.output_exprs = out_exprs
        exprs = [sm.sympify(e) for e in rhs_exprs + out_exprs]
        for v in extra.values():
            exprs += v
        self._find_inputs(exprs, given, integrate)
        self.accel_inputs = accel_inputs
        self._integrate = integrate
        self.compiled = False
        self.rhs_compiling = None      # the C right-hand side being built (compile)
        self.outputs_compiling = None  # and the outputs' C
        self.constants_function = self.rhs_function = self.output_function = None
        self.extra_functions: dict = {}
        self.unknown_positions = [self.states.index(lower_derivative(d))
                                  for d in self.implicit_unknowns]
        self._bind_loop()
        if compile_functions:
            self.compile()
        self.constant_values = None
        self._factoring = None
        self.specified_values = np.zeros(len(self.specified))
        self.specified_functions: list = []

    def _fix_speeds(self, locked, dynamics) -> None:
        """The speeds of locked coordinates: 0, as their rates.  (An auxiliary speed
        takes the value its CONSTRAIN(AUXILIARY[...]) solved for it: 0 when it only
        brings a force into evidence, else the motion the constraint allows.)"""
        self.aux_fixed = {}
        self.locked = list(locked)
        self._locked_speeds = [self._speed_of_locked(q, dynamics) for q in self.locked]
        for u in self._locked_speeds:
            self.aux_fixed[u] = 0.0
            self.aux_fixed[S.derivative(u)] = 0.0

    def _output_expressions(self, outputs, encoded, extra) -> tuple[list, dict]:
        """The OUTPUT columns' and ENCODE values' expressions (derivatives resolved
        through definitions), and the `extra` ones."""
        self.files = [list(cols) for cols in outputs]
        self.degree_columns = [[units.is_degrees(c.unit) for c in cols]
                               for cols in self.files]
        self.encoded = list(encoded)
        out_exprs = [self._resolve(c.expr) for cols in self.files for c in cols]
        self.encode_shapes = []
        for name, value in self.encoded:
            if isinstance(value, sm.MatrixBase):
                self.encode_shapes.append((name, value.shape))
                out_exprs += [self._resolve(v) for v in value]
            else:
                self.encode_shapes.append((name, ()))
                out_exprs.append(self._resolve(value))
        return out_exprs, {k: [self._resolve(e) for e in v] for k, v in (extra or {}).items()}

    def _find_inputs(self, exprs: list, given: set, integrate: bool) -> None:
        """The specified quantities, the parameters (constants without a definition) and
        the definitions of constants that the expressions need."""
        defs = self.defs
        roots = symbols_in(*exprs)
        order, undefined = self._needed_from(roots, given)
        self.specified = alphabetical(s for s in undefined if self.is_specified(s))
        params = [s for s in undefined if not self.is_specified(s)]
        self.params = (alphabetical(params) if integrate
                       else read_order(params, self.symbols))
        pset = set(self.params)
        const_defs = [s for s in order if defs.primitive_deps(s) <= pset]
        cset = set(const_defs)
        used = set(roots)
        for s in order:
            if s not in cset:
                used |= defs.free(s)
        self.constant_defs = [s for s in const_defs if s in used]

    def compile(self, background: bool = False) -> None:
        """Compile the functions the analysis found (with the model's definitions as
        they stand: as_of the command's, like the analysis).  `background`: for a run
        that starts now, the right-hand side is Python first and its C compiles on
        another thread (`compiled_loop` swaps it in): the Python and C back ends give
        the same numbers."""
        self._compile(self.extra_exprs, self.accel_inputs, self._integrate, background)
        self.compiled = True

    def compile_constants(self) -> None:
        """Only the function of the constants computed from the parameters: what a
        linearization, which evaluates Jacobians of its own, needs of the system (the
        rest compiles when a run needs it)."""
        if self.constants_function is None:
            self.constants_function = self._constants_function([])

    def _constants_function(self, lifted: list) -> WalkedFirst:
        """The constant definitions' function, then the `lifted` parts' (evaluated once
        per parameter set: walked, then Python; compiling C would cost more)."""
        return WalkedFirst(
            codegen.Program({"p": self.params}, self.constant_defs + [e for _, e in lifted],
                            self.defs),
            "autolev_constants")

    def _compile(self, extra: dict, accel_inputs: list, integrate: bool,
                 background: bool) -> None:
        defs, backend = self.defs, self.backend
        inputs = {"t": [S.TIME], "x": self.states, "c": self.params + self.constant_defs,
                  "s": self.specified}
        fixed = dict(self.aux_fixed)
        self.rhs_function = None
        lifted = []
        if self.nstate:
            # the parts of the right-hand side in constants alone join the constants
            rhs = codegen.Program(inputs, self.rhs_exprs, defs, fixed).build(lift_into="c")
            lifted = rhs.lifted
            inputs["c"] = rhs.inputs["c"]
        self.constants_function = self._constants_function(lifted)
        self.constant_defs = self.constant_defs + [s for s, _ in lifted]
        if self.nstate:
            # the C right-hand side carries the integration loop (loop.c) with it
            loop_source, loop_flags = loop_extra_source()
            if background and backend == "auto" and clibrary.compiler() is not None:
                self.rhs_function = compile_program(rhs, "python", "autolev_rhs")
                self.rhs_compiling = compiling_in_background(
                    rhs, "autolev_rhs", extra_source=loop_source, extra_flags=loop_flags)
            else:
                self.rhs_function = compile_program(
                    rhs, backend, "autolev_rhs", extra_source=loop_source,
                    extra_flags=loop_flags)
        inputs_out = dict(inputs, a=accel_inputs)
        outputs = codegen.Program(inputs_out, self.output_exprs, defs, fixed)
        if not integrate:
            # ALGEBRAIC/NONLINEAR outputs are evaluated once per solution
            self.output_function = WalkedFirst(outputs, "autolev_outputs")
        elif self.rhs_compiling is not None:
            # the outputs' C too, once the right-hand side's (which the loop waits for)
            # is built: the first rows are the Python's (the same numbers)
            outputs.build()
            self.output_function = compile_program(outputs, "python", "autolev_outputs")
            self.outputs_compiling = compiling_in_background(outputs, "autolev_outputs",
                                                             after=self.rhs_compiling)
        else:
            self.output_function = compile_program(outputs.build(), backend,
                                                   "autolev_outputs")
        self.extra_functions = {
            k: (compile_program(codegen.Program(inputs_out, v, defs, fixed).build(), backend,
                                f"autolev_{k}"), len(v))
            for k, v in extra.items()}
        self._bind_loop()

    @property
    def derived_constants(self) -> int:
        return len(self.constant_defs)

    @property
    def n_rhs(self) -> int:
        return len(self.rhs_exprs)

    @property
    def n_outputs(self) -> int:
        return len(self.output_exprs)

    # -- pickling (with the model, in the cache of built models) ------------------------
    # -- structure ------------------------------------------------------------------------
    def _integrated(self, solving, snapshot) -> tuple[dict, list, list]:
        """({X: rate} for every integrated X, [derivatives solved from M a = f],
        [M entries row by row, then f]).  A rate is X's definition, or the symbol X'
        when X' is itself integrated or solved for, or (CODE ODE()) a constant input."""
        defs, dynamics = self.defs, snapshot.dynamics
        explicit_only = solving is not None and not solving[0]
        if explicit_only:
            unknowns, dyn = [], []
        elif solving is not None:
            equations, unknowns = solving
            unknowns = list(unknowns)
            eqs = [sm.sympify(e) for e in equations]
            if len(eqs) != len(unknowns):
                raise AutolevModelError(f"CODE ODE: {len(eqs)} equations for "
                                        f"{len(unknowns)} unknowns")
            mm = [-d for row in defs.jacobian(eqs, unknowns) for d in row]
            zero = {d: 0 for d in unknowns}
            f = [defs.substitute(e, zero) for e in eqs]
            dyn = mm + f
        else:
            unknowns, dyn = [], []
            speeds = []
            if (snapshot.bodies or snapshot.particles) and dynamics is not None:
                speeds = dynamics.independent_speeds()
            pending = [u for u in speeds if S.derivative(u) not in defs.rhs]
            if pending or self.locked:
                eqs = dynamics.equations()
                if set(eqs.speeds) != set(pending):
                    raise AutolevModelError(
                        "the derivatives of some speeds are defined (SOLVE) and others "
                        "are not: KANE() or SOLVE must give all of "
                        + ", ".join(map(str, eqs.speeds)))
                unknowns = [S.derivative(u) for u in eqs.speeds]
                rows = self._dynamics_rows(eqs)
                if self.locked:     # the free speeds' rows of Kane's equations
                    free = [k for k, u in enumerate(eqs.speeds)
                            if u not in self._locked_speeds]
                    formed = list(eqs.rows[:len(eqs.speeds), 0]) if rows is None else rows
                    rows = [formed[k] for k in free]
                    unknowns = [unknowns[k] for k in free]
                recursion = (self._tree_accelerations(eqs, dynamics)
                             if rows is None and not self.locked else None)
                if recursion is not None:
                    # explicit: the mass matrix of u' = f is the identity
                    mm = [int(i == j) for i in range(len(unknowns))
                          for j in range(len(unknowns))]
                    f = recursion.rates
                    self.pivots = recursion.pivots + recursion.entries
                elif rows is None:
                    mm, f = dynamics.mass_matrix(), dynamics.forcing()
                else:
                    # ZERO as changed after KANE() (Autolev codes the ZERO it has
                    # then: tutorial 8 evaluates constants in ZERO after KANE())
                    mm = [-d for row in defs.jacobian(rows, unknowns) for d in row]
                    at0 = {d: 0 for d in unknowns}
                    f = [defs.substitute(r, at0) for r in rows]
                dyn = list(mm) + list(f)
        rates: dict = {}
        for d in unknowns:
            rates[lower_derivative(d)] = d
        changed = True
        while changed:
            changed = False
            for sym, info in sorted(self.symbols.items(), key=lambda kv: kv[1].index):
                if info.kind not in ("variable", "motionvariable") or sym in defs.rhs \
                        or sym in self.aux_fixed or sym in rates or sym in self.locked:
                    continue
                d = S.derivative(sym)
                if d in defs.rhs:
                    rates[sym] = defs.rhs[d]
                elif d in rates or (explicit_only and info.order >= 1):
                    # Q' integrated too: Q's rate is Q'; or, in CODE ODE(), Q' declared
                    # and never defined: a constant its program reads
                    rates[sym] = d
                else:
                    continue
                changed = True
        return rates, unknowns, dyn

    def _tree_accelerations(self, eqs, dynamics) -> articulated.Recursion | None:
        """The speeds' derivatives by the articulated-body recursion, when this system
        is `recursive` and the model is a tree of joints without constraints (see
        runtime/articulated.py); else None: M u' = f from Kane's equations."""
        if not self.recursive or eqs.dependent or eqs.auxiliary or eqs.unknowns:
            return None
        try:
            return dynamics.joints(eqs.speeds).recursion()
        except articulated.NotATree:
            return None

    def _speed_of_locked(self, q, dynamics):
        """U of a locked coordinate Q, from its kinematical equation Q' = U."""
        rate = self.defs.rhs.get(S.derivative(q))
        independent = dynamics.independent_speeds() if dynamics is not None else []
        if rate not in independent:
            raise AutolevModelError(
                f"{q} cannot be locked: locking needs the kinematical equation {q}' = U "
                f"for an independent generalized speed U (here {q}' = {rate})")
        return rate

    def _dynamics_rows(self, eqs) -> list | None:
        """The rows of ZERO to solve for the speeds' derivatives, when ZERO (as it
        stood at CODE time) is not Kane's equations as formed: one row per independent
        speed, or per independent and auxiliary speed (the first ones are used)."""
        z = self._zero
        if z is None:
            return None
        z = list(z)
        n = len(eqs.speeds)
        if len(z) not in (n, n + len(eqs.auxiliary)):
            return None
        z = z[:n]
        formed = list(eqs.rows[:n, 0])
        if all(sm.sympify(a - b) == 0 for a, b in zip(z, formed)):
            return None
        return z

    def _hidden(self, names) -> list:
        """The model's declared symbols spelt exactly as one of `names`."""
        names = set(names)
        return [s for s in self.symbols
                if S.base_and_order(s)[1] == 0 and s.name in names]

    def _as_output_routine(self, out_exprs, rhs_exprs, extra, given) -> list:
        """The outputs as Autolev's C output routine computed them: its loop counter
        `int i1` hides a model's quantity named i1, which reads 0 there (reference runs
        print that), except in what the derivative (or equations) routine computed
        before and the output routine reuses."""
        roots = [sm.sympify(e) for e in rhs_exprs] + [e for v in extra.values() for e in v]
        shared, _ = self.needed(roots, given) if roots else ([], set())
        keep = frozenset(shared)
        zero = {s: sm.S.Zero for s in self.hidden_in_outputs}
        changed = [self.defs.substitute(e, zero, keep) for e in out_exprs]
        if all(a == b for a, b in zip(changed, out_exprs)):
            self.hidden_in_outputs = []          # no output reads them
        return changed

    def is_specified(self, s) -> bool:
        info = self.symbols.get(S.base_and_order(s)[0])
        return info is not None and info.kind == "specified"

    def needed(self, exprs, given) -> tuple[list, set]:
        return self._needed_from(symbols_in(*exprs), given)

    def _needed_from(self, roots: set, given) -> tuple[list, set]:
        """(the definitions the symbols `roots` need, in evaluation order; the undefined
        symbols they come to, less those `given`)."""
        defs = self.defs
        order = defs.evaluation_order(roots, given)
        syms = set(roots)
        for s in order:
            syms |= defs.free(s)
        undefined = {s for s in syms if s not in defs.rhs and s not in given}
        return order, undefined

    def _resolve(self, expr):
        """An output expression with derivatives of integrated quantities that have no
        definition (Q'' when Q' = U) replaced by their time derivative."""
        defs = self.defs
        expr = sm.sympify(expr)
        for _ in range(4):
            subs = {}
            for s in expr.free_symbols:
                base, k = S.base_and_order(s)
                if k == 0 or s in defs.rhs or s in self.implicit_unknowns \
                        or s in self.aux_fixed or s in self.states or s in self.solved \
                        or self.is_specified(s):
                    continue
                lower = S.derivative(base, k - 1)
                if lower in self.states or lower in defs.rhs:
                    subs[s] = defs.dt(lower)
            if not subs:
                break
            expr = expr.xreplace(subs)
        return expr

    def lacking(self, exprs) -> list:
        """The constants `exprs` need that this run has no value for (the run's inputs
        are only what its equations and outputs use)."""
        exprs = [self._resolve(e) for e in exprs]
        _, undefined = self.needed(exprs, set(self.states) | {S.TIME} | set(self.aux_fixed))
        known = set(self.params) | set(self.specified)
        return alphabetical(s for s in undefined if s not in known)

    def evaluator(self, exprs, name: str = "autolev_quantities", extra_values=None):
        """f(t, x) -> the values of `exprs` (e.g. positions) with this run's constants
        and specified quantities, and `extra_values` ({symbol: value}) for the constants
        the run lacks (see lacking)."""
        extra_values = dict(extra_values or {})
        missing = [s for s in self.lacking(exprs) if s not in extra_values]
        if missing:
            raise AutolevModelError("these quantities have no value in this run: "
                                    + ", ".join(map(str, missing)))
        exprs = [self._resolve(e) for e in exprs]
        extra = list(extra_values)
        inputs = {"t": [S.TIME], "x": self.states, "c": self.params + self.constant_defs,
                  "s": self.specified, "e": extra}
        fn = compile_program(codegen.Program(inputs, exprs, self.defs,
                                             dict(self.aux_fixed)).build(), "python", name)
        extra_array = np.array([float(extra_values[k]) for k in extra])

        def evaluate(t: float, x) -> np.ndarray:
            out = np.empty(len(exprs))
            s = self._fill_specified(t, x) if self.specified_functions \
                else self.specified_values
            fn.call(np.array([t]), np.asarray(x, dtype=float), self.constant_values, s,
                    extra_array, out)
            return out
        return evaluate

    # -- values ---------------------------------------------------------------------------
    def set_specified(self, functions: dict) -> set:
        """{symbol: callable f(t) or f(t, x)} for undefined specified quantities;
        returns the symbols used (a derivative's values come from its lower one's)."""
        self.specified_functions = []
        used = set()
        for i, s in enumerate(self.specified):
            fn = functions.get(s)
            if fn is not None:
                self.specified_functions.append((i, _as_time_state_function(fn)))
                used.add(s)
            else:
                base, k = S.base_and_order(s)
                lower = [(S.derivative(base, j), j) for j in range(k - 1, -1, -1)]
                for low, j in lower:
                    if low in functions:
                        self.specified_functions.append(
                            (i, _finite_difference(_as_time_state_function(functions[low]),
                                                   k - j)))
                        used.add(low)
                        break
        return used


def lower_derivative(d):
    """Q' for Q'' (the symbol one derivative lower)."""
    base, k = S.base_and_order(d)
    if k == 0:
        raise AutolevModelError(f"{d} is not a derivative")
    return S.derivative(base, k - 1)


def _as_time_state_function(fn):
    """f(t) or f(t, x) as f(t, x)."""
    try:
        n = len([p for p in inspect.signature(fn).parameters.values()
                 if p.default is p.empty and p.kind in (p.POSITIONAL_ONLY,
                                                        p.POSITIONAL_OR_KEYWORD)])
    except (TypeError, ValueError):
        n = 1
    if n >= 2:
        return lambda t, x: float(fn(t, x))
    return lambda t, x: float(fn(t))


def _finite_difference(fn, order: int, h: float = 1e-4):
    """The order-th time derivative of fn(t, x) by central differences (x held)."""
    if order == 1:
        return lambda t, x: (fn(t + h, x) - fn(t - h, x)) / (2 * h)
    if order == 2:
        return lambda t, x: (fn(t + h, x) - 2 * fn(t, x) + fn(t - h, x)) / (h * h)
    inner = _finite_difference(fn, order - 1, h)
    return lambda t, x: (inner(t + h, x) - inner(t - h, x)) / (2 * h)
