"""Autolev's algebra functions that work through the definitions table (a mixin of
Model): EVALUATE, COEF, EXCLUDE, INCLUDE, TAYLOR, SOLVE, ZEE, INV, DET, NICHECK."""
from __future__ import annotations

import sympy as sm

from . import symbols as S
from .functions import scalar_values, whole_number
from .constraints import SolvedRates
from .linalg import coefficients, solve_linear
from ..engine.errors import AutolevModelError
from .derived import mutation
from .frame import body_fixed, rodrigues, space_fixed
from .vectors import Dyadic, Vector


class AlgebraMixin:
    def evaluate(self, value, mapping: dict):
        """EVALUATE(E, x=v, ...): E with the values substituted, also inside the
        definitions E uses (names are kept where nothing changes)."""
        mapping = scalar_values(mapping, "EVALUATE")
        return self.map_scalars(value, lambda e: self.defs.substitute(e, mapping))

    def coef(self, value, var):
        """COEF(E, x): the coefficient of x in E (of x^1, through definitions: E may be
        in Z form), in every element of a matrix and measure number of a vector or
        dyadic; COEF(E, x^2) or COEF(E, x*y): the coefficient of that monomial in the
        expanded E; COEF([E1;E2], [x, y]): the coefficient matrix; COEF(V>, N1>): the
        measure number of N1> in V> as V> is written (no other frame's unit vectors
        expressed in N)."""
        if isinstance(var, Vector):
            return _unit_vector_coefficient(value, var)
        if isinstance(var, (sm.MatrixBase, list, tuple)):
            vs = _name_list(var, "COEF")
            if isinstance(value, (Vector, Dyadic)):
                raise AutolevModelError("COEF(E, [x, y]) takes a scalar or a column E, not "
                                        "a vector")
            col = value if isinstance(value, sm.MatrixBase) else sm.Matrix([value])
            return sm.Matrix(len(col), len(vs), lambda i, j: self._coef1(col[i], vs[j]))
        (var,) = _name_list(var, "COEF")
        return self.map_scalars(value, lambda e: self._coef1(e, var))

    def _coef1(self, e, var):
        if isinstance(var, sm.Symbol):
            return self.defs.substitute(self.defs.diff(e, var), {var: 0})
        if not var.free_symbols:
            raise AutolevModelError(f"COEF: {var} is a number, not a term to take the "
                                    "coefficient of")
        # a monomial: expand (names and Z's kept) and collect the terms holding it,
        # factors that are free of var's symbols only
        out = []
        for term in sm.Add.make_args(sm.expand(sm.sympify(e))):
            rest = sm.cancel(term / var)
            if not any(self.defs.depends_on(rest, x) for x in var.free_symbols):
                out.append(rest)
        return sm.Add(*out)

    def _terms_free_of(self, e, vs) -> sm.Expr:
        """The terms of the expanded e free of vs.  A term holding one of vs only
        inside intermediate variables contributes what is left of it at vs = 0 (the
        engine's Z's are linear in the speeds' derivatives, which is what EXCLUDE is
        used to split off)."""
        out = []
        for t in sm.Add.make_args(sm.expand(sm.sympify(e))):
            if not any(self.defs.depends_on(t, v) for v in vs):
                out.append(t)
            elif not any(v in t.free_symbols for v in vs):
                out.append(self.defs.substitute(t, {v: 0 for v in vs}))
        return sm.Add(*out)

    def exclude(self, value, var):
        """EXCLUDE(E, x) (or [x, y]): the terms of the expanded E that do not contain x
        (through definitions)."""
        vs = _name_list(var, "EXCLUDE")
        return self.map_scalars(value, lambda e: self._terms_free_of(e, vs))

    def include(self, value, var):
        """INCLUDE(E, x): the terms of the expanded E that contain x."""
        vs = _name_list(var, "INCLUDE")
        return self.map_scalars(
            value, lambda e: sm.expand(sm.sympify(e)) - self._terms_free_of(e, vs))

    def expand(self, value, lo=None, hi=None):
        """EXPAND(E): E multiplied out.  EXPAND(E, n:m): only the terms whose degree
        lies in n..m (EXPAND(E, n): 0..n), the degree counted in the time-varying
        quantities (variables, specifieds and their derivatives) when E has any,
        otherwise in all its symbols: a truncation, as of a Taylor series.  (No
        Autolev source defines the range; this is the reading tutorial 1 fits.)"""
        if lo is None:
            return self.map_scalars(value, sm.expand)
        if hi is None:
            lo, hi = 0, lo
        lo, hi = whole_number(lo, "EXPAND's degree"), whole_number(hi, "EXPAND's degree")

        def varying(sym) -> bool:
            base = S.base_and_order(sym)[0]
            return self.kind_of(base) in ("variable", "motionvariable", "specified")

        def one(e):
            e = sm.expand(sm.sympify(e))
            syms = {s for s in e.free_symbols if varying(s)} or e.free_symbols
            keep = []
            for term in sm.Add.make_args(e):
                powers = term.as_powers_dict()
                degree = sum(p for b, p in powers.items() if b in syms)
                if lo <= degree <= hi:
                    keep.append(term)
            return sm.Add(*keep)
        return self.map_scalars(value, one)

    def taylor(self, value, order, points):
        """TAYLOR(E, n, x=a, ...) up to total degree n (or degrees lo..hi, given as
        (lo, hi)); with x=a:dx the expansion is in the increment dx (perturbation
        about a), otherwise in x-a.  Works through definitions, so expressions in Z
        form stay in Z form: term k is (D^k E)(a)/k! with D = sum_i d_i d/dx_i."""
        lo, hi = (0, order) if not isinstance(order, tuple) else order
        lo, hi = whole_number(lo, "TAYLOR's order"), whole_number(hi, "TAYLOR's order")
        at, steps, increments = {}, [], {}
        for var, a, inc in points:
            a = sm.sympify(a)
            at[var] = a
            d = sm.Dummy("d")                      # stands for the increment meanwhile
            steps.append((var, d))
            increments[d] = inc if inc is not None else var - a

        def one(e):
            if hi == 1 and lo <= 1:     # the linear terms: the gradient at the point
                value, grad = self.defs.at_point(e, at)
                linear = sm.Add(*[d * grad.get(var, 0) for var, d in steps])
                return (linear + value if lo == 0 else linear).xreplace(increments)
            total = []
            term = sm.sympify(e)
            factorial = 1
            for k in range(hi + 1):
                if k > 0:
                    # the gradient in one pass over the definitions, not one per variable
                    grad = self.defs.jacobian([term], [var for var, _ in steps])[0]
                    term = sm.Add(*[d * g for (_, d), g in zip(steps, grad)])
                    factorial *= k
                if k >= lo:
                    total.append(self.defs.substitute(term, at) / factorial)
            return sm.Add(*total).xreplace(increments)
        return self.map_scalars(value, one)

    def solve(self, equations, unknowns) -> None:
        """SOLVE(E, x, y, ...): solve equations linear in the unknowns; the solutions
        become the definitions (RHS) of the unknowns."""
        unknowns = list(unknowns)
        if len(unknowns) == 1 and isinstance(unknowns[0], sm.MatrixBase):
            unknowns = list(unknowns[0])
        eqs = list(equations) if isinstance(equations, (sm.MatrixBase, list, tuple)) \
            else [equations]
        eqs = self._dynamical_rows(eqs, unknowns)
        if len(eqs) != len(unknowns):
            raise AutolevModelError(f"SOLVE has {len(eqs)} equations for {len(unknowns)} "
                                    "unknowns")
        for u in unknowns:
            if not isinstance(u, sm.Symbol):
                raise AutolevModelError(f"SOLVE's unknowns are names, not {u}")
        a, r = coefficients(eqs, unknowns, self.defs)
        solution = solve_linear(a, -r, self.defs, "SOLVE")
        # a coefficient that holds an unknown leaves it in the solution
        left = [u for u in unknowns if any(self.defs.depends_on(v, u) for v in solution)]
        if left:
            raise AutolevModelError(f"SOLVE solves equations linear in their unknowns; "
                                    f"these are not linear in {', '.join(map(str, left))}")
        self._keep_speeds(unknowns)
        for u, v in zip(unknowns, solution):
            self.define(u, v)
        # speeds' rates: of the speeds SOLVE keeps, and of the motion variables declared
        # X'' (X' is the speed); CODE DYNAMICS takes such a SOLVE when it is Kane's
        rates = {S.derivative(b) for b in self.solved_speeds}
        if all(u in rates or S.base_and_order(u)[1] == 2 for u in unknowns):
            self.constraints.add_solved_rates(SolvedRates(
                tuple(unknowns), tuple(eqs), tuple(self.defs.rhs[u] for u in unknowns)))

    def _keep_speeds(self, unknowns) -> None:
        """A generalized speed u stays one when SOLVE defines u' (SOLVE(ZERO, U')), although
        a variable whose derivative is defined is otherwise a coordinate."""
        bases = [S.base_and_order(u)[0] for u in unknowns
                 if S.base_and_order(u)[1] == 1 and u not in self.defs.rhs]
        if not bases or self.newtonian_frame is None:
            return
        speeds = set(self.generalized_speeds(complete=False)[0])
        self.constraints.keep_speeds(b for b in bases if b in speeds)

    def _dynamical_rows(self, eqs: list, unknowns: list) -> list:
        """After KANE(F1, ..., Fk), ZERO holds the n dynamical rows and then the k rows
        of the auxiliary speeds, which KANE made the definitions of the F's; SOLVE(ZERO,
        u1', ..., un') solves the dynamical rows (as Autolev's programs did: first the
        u', then the F's from them)."""
        kane = self.kane_equations
        if kane is None or not kane.unknowns:
            return eqs
        n, k = len(kane.speeds), len(kane.auxiliary)
        if len(eqs) == n + k and len(unknowns) == n:
            return eqs[:n]
        return eqs

    def zee(self, value, *keep):
        """ZEE(E) / ZEE(E, x): E in the compact Z form, with the names of ZEE_NOT (and
        x) kept visible: E is written as a sum over the monomials in those names, each
        with a Z for its coefficient (a name inside a non-polynomial function stays
        hidden in its Z)."""
        names = [n for k in list(self.settings.get("ZEE_NOT", [])) + list(keep)
                 for n in _name_list(k, "ZEE")]

        def one(e):
            e = sm.sympify(e)
            present = [n for n in names if n in e.free_symbols]
            if not present:
                return self.defs.zify(e)
            parts = sm.collect(sm.expand(e), present, evaluate=False)
            return sm.Add(*[self.defs.zify(c) * m for m, c in parts.items()])
        return self.map_scalars(value, one)

    @mutation
    def zee_not(self, names) -> sm.Matrix:
        """ZEE_NOT = [x, y]: names kept visible (never hidden in a Z); its value, what
        Autolev answered and what a later ZEE_NOT reads, is the row of those names."""
        kept = list(names) if not isinstance(names, sm.Basic) else [names]
        self.settings["ZEE_NOT"] = kept
        return sm.Matrix([kept])

    def inv(self, m):
        """INV(M) (entries named by Z's when symbolic)."""
        m = sm.Matrix(m)
        if m.rows != m.cols:
            raise AutolevModelError("INV needs a square matrix")
        if all(e.is_number for e in m):
            return m.inv()
        cols = [solve_linear(m, sm.eye(m.rows)[:, j], self.defs, "INV") for j in range(m.cols)]
        return sm.Matrix(m.rows, m.cols, lambda i, j: cols[j][i])

    def det(self, m):
        m = sm.Matrix(m)
        if m.rows != m.cols:
            raise AutolevModelError("DET needs a square matrix")
        if m.rows <= 3 or all(e.is_number for e in m):
            return self.defs.zify(m.det(method="berkowitz"))
        return self.defs.zify(m.det(method="bareiss"))

    @mutation
    def nicheck(self):
        """NICHECK(): kinetic energy minus the work done on the system since TINITIAL
        (the sum over r of the integral of F_r u_r), written as Autolev's programs and
        sessions did: KE + WCHECK1 with WCHECK1' = -sum F_r u_r.  It stays constant
        along an exact solution, so its drift measures the integration error."""
        eqs = self._form(inertia=False)
        power = sm.Add(*[f * u for f, u in zip(eqs.fr, eqs.speeds)])
        work = self._nicheck_work
        if work is None:
            # Autolev's programs call this integral WCHECK1
            taken = {s.name.upper() for s in self.info}
            name = next(f"WCHECK{k}" for k in range(1, 1000) if f"WCHECK{k}" not in taken)
            work = self.variables(name)
            self._nicheck_work = work
        self.define(S.derivative(work), self.defs.zify(-power))
        self.io.input_unless_given(work, sm.S.Zero)
        return self.ke() + work

    @mutation
    def setting(self, name: str, value) -> None:
        self.settings[name] = value
        if name == "DEGREES":
            self.degrees = value != "OFF"
        elif name == "COMPLEX":
            self.complex = value == "ON"

    def angvel(self, parent, child, kind: str, *angles) -> None:
        """ANGVEL(A, B, BODYijk, a, b, c): W_B_A> from a rotation sequence's rates."""
        kind = kind.lower()
        if kind == "rodrigues":
            _, w = rodrigues(angles, self.defs.dt_raw)
            child.set_ang_vel(parent, Vector({child: w}))
        elif kind.startswith("body"):
            _, w = body_fixed(angles, kind[4:], self.defs.dt_raw)
            child.set_ang_vel(parent, Vector({child: w}))
        elif kind.startswith("space"):
            _, w = space_fixed(angles, kind[5:], self.defs.dt_raw)
            child.set_ang_vel(parent, Vector({parent: w}))
        else:
            raise AutolevModelError(f"ANGVEL does not know the rotation type {kind.upper()}")


def _name_list(x, what: str) -> list:
    """x, or the entries of a matrix or list x, as sympy expressions (names, or products
    of names)."""
    items = list(x) if isinstance(x, (sm.MatrixBase, list, tuple)) else [x]
    for v in items:
        if not isinstance(v, (sm.Expr, int, float)):
            raise AutolevModelError(f"{what} takes names (x or [x, y]), not {v}")
    return [sm.sympify(v) for v in items]


def _unit_vector_coefficient(value, unit: Vector):
    """COEF(V>, N1>): the measure number of V> on N1>, from V>'s terms in N only."""
    terms = list(unit.terms.items())
    if len(terms) != 1 or sorted(terms[0][1], key=str) != [0, 0, 1]:
        raise AutolevModelError(f"COEF(V>, x>) takes a unit vector x> of a frame, not {unit}")
    frame, axes = terms[0]
    if not isinstance(value, Vector):
        raise AutolevModelError(f"COEF(E, {unit}) takes a vector E, not {value}")
    return value.terms.get(frame, (0, 0, 0))[list(axes).index(1)]
