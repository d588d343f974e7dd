"""Kane's method on a model and the equations it gives (a mixin of Model): the
generalized speeds, FR(), FRSTAR(), KANE(), PARTIALS, and the equations in the forms
sympy users know (mass matrix, forcing, explicit form, SymbolicSystem).  kane.py does
the forming; here the model's state is gathered for it, and its answer kept with the
model's revision in the model's part FormedEquations."""
from __future__ import annotations

import sympy as sm

from . import kane
from . import symbols as S
from ..engine.errors import AutolevModelError
from .functions import VectorColumn
from .interop import symbolic_system
from .derived import Owned, mutation
from .kane import KaneEquations
from .linalg import coefficients, solve_linear


class FormedEquations(Owned):
    """Kane's equations KANE() took (None before it), and the last forming, kept for the
    revision it was made at (a part of Model)."""

    def __init__(self, revision) -> None:
        super().__init__(revision)
        self._taken: KaneEquations | None = None
        self._forming: tuple | None = None       # (revision key, kane.Forming)

    @property
    def taken(self) -> KaneEquations | None:
        return self._taken

    @mutation
    def take(self, equations: KaneEquations) -> None:
        self._taken = equations

    def formed(self, inertia: bool, system: kane.System, speeds) -> KaneEquations:
        """The equations of `system` formed at this revision (with Fr* when `inertia`), by
        the forming kept for it, else by a new one over `speeds()`."""
        key = self.revision.key
        kept = self._forming
        if kept is None or kept[0] != key:
            kept = self._forming = (key, kane.Forming(system.defs, speeds()))
        return kept[1].equations(system, inertia)


class EquationsMixin:
    def kane_system(self) -> kane.System:
        """What Kane's method reads from this model."""
        return kane.System(self._newtonian(), self.forces, self.torques,
                           self.particles_list, self.bodies_list, self.defs)

    def generalized_speeds(self, complete: bool = True) -> tuple[list, list, list]:
        """(independent, dependent, auxiliary) generalized speeds (see kane.py); with
        `complete`, the kinematical equations must determine every coordinate's rate."""
        if complete and self._kinematics_pending:
            raise AutolevModelError(
                "the kinematical equations written as U = f(Q') do not determine every Q'"
                f" ({', '.join(f'{u} = {v}' for u, v in self._kinematics_pending.items())})")
        declared = kane.SpeedDeclarations(self.info, self.solved_speeds,
                                          self.dependent_speeds, self.auxiliary_speeds)
        return kane.generalized_speeds(self.kane_system(), declared)

    def _form(self, inertia: bool = True) -> KaneEquations:
        return self.formed_equations.formed(inertia, self.kane_system(),
                                            self.generalized_speeds)

    @property
    def kane_equations(self) -> KaneEquations | None:
        """The equations KANE() took, None before it."""
        return self.formed_equations.taken

    def speed_column(self, which: str, order: int = 0) -> sm.Matrix:
        """U_INDEPENDENT, U_DEPENDENT, U_AUXILIARY (primed: their derivatives)."""
        indep, dep, aux = self.generalized_speeds()
        speeds = {"independent": indep, "dependent": dep, "auxiliary": aux}[which]
        return sm.Matrix([S.derivative(u, order) for u in speeds])

    def partials(self, value, *speeds):
        """PARTIALS(V>, u1, ...): the partial velocities of V> with respect to the speeds."""
        if len(speeds) == 1 and isinstance(speeds[0], (sm.MatrixBase, list, tuple)):
            speeds = tuple(speeds[0])
        if not speeds:
            speeds = tuple(self.generalized_speeds()[0])
        return VectorColumn([kane.partial_velocity(value, u, self.defs) for u in speeds])

    def fr(self) -> sm.Matrix:
        """FR(): generalized active forces, one row per independent (then auxiliary) speed."""
        return self._form(inertia=False).fr

    def frstar(self) -> sm.Matrix:
        """FRSTAR(): generalized inertia forces."""
        return self._form().frstar

    def kane(self, *unknowns) -> KaneEquations:
        """KANE(): take Fr + Fr* = 0 as the dynamical equations; KANE(F1, ...) also solves
        the auxiliary rows for the listed unknowns (noncontributing forces)."""
        eqs = self._formed_for(unknowns)
        if unknowns:
            # the auxiliary rows, linear in the unknowns, define them (in terms of the
            # state and the speeds' derivatives, which the dynamics give)
            aux_rows = list(eqs.rows[len(eqs.speeds):, 0])
            a, r = coefficients(aux_rows, eqs.unknowns, self.defs)
            solution = solve_linear(a, -r, self.defs, "the auxiliary equations (KANE)")
            for sym, val in zip(eqs.unknowns, solution):
                self.define(sym, val)
        self.formed_equations.take(eqs)
        return eqs

    def _formed_for(self, unknowns) -> KaneEquations:
        """Kane's equations formed now, for KANE(unknowns): one unknown per auxiliary
        speed."""
        eqs = self._form()
        eqs.unknowns = list(unknowns)
        if len(unknowns) != len(eqs.auxiliary):
            raise AutolevModelError(f"KANE solves one unknown per auxiliary speed: "
                                    f"{len(unknowns)} unknowns, {len(eqs.auxiliary)} "
                                    "auxiliary speeds")
        return eqs

    # the equations, in the forms sympy users know ---------------------------------------
    def equations(self) -> KaneEquations:
        """Kane's equations: those KANE() took, else formed from the model as it stands
        (asking changes nothing: they are kept with the model's revision)."""
        if self.kane_equations is None:
            return self._formed_for(())
        return self.kane_equations

    @property
    def speeds(self) -> list:
        return self.equations().speeds

    @property
    def speed_derivatives(self) -> list:
        return [self._speed_derivative(u) for u in self.speeds]

    def _speed_derivative(self, u):
        return S.derivative(u)

    @property
    def coordinates(self) -> list:
        """Every variable the integration carries besides the speeds: those whose first
        derivative is defined (q' = ...) or is itself a speed (q''-only models), in
        declaration order.  Dependent and auxiliary speeds are not among them, nor a
        variable the model defines (a prescribed motion: QA = OMEGA*T, QA' = OMEGA)."""
        speeds = set(self.speeds)
        not_coordinates = set(self.dependent_speeds) | set(self.auxiliary_speeds) | speeds
        out = []
        for sym, info in sorted(self.info.items(), key=lambda kv: kv[1].index):
            if info.kind not in ("variable", "motionvariable") or \
                    S.base_and_order(sym)[1] != 0 or sym in not_coordinates or \
                    sym in self.defs.rhs:
                continue
            d = S.derivative(sym)
            if d in self.defs.rhs or d in speeds:
                out.append(sym)
        return out

    @property
    def kinematical_equations(self) -> dict:
        """{q': f(q, u)} for every coordinate (q' itself when q' is a speed)."""
        return {S.derivative(q): self.defs.rhs.get(S.derivative(q), S.derivative(q))
                for q in self.coordinates}

    @property
    def mass_matrix(self) -> sm.Matrix:
        """M in M*u' = forcing (independent speeds; Z-named entries)."""
        ud = self.speed_derivatives
        with self._rates_unknown():
            jac = self.defs.jacobian(self._kane_rows(), ud)
        return sm.Matrix(len(ud), len(ud), lambda i, j: -jac[i][j])

    @property
    def forcing(self) -> sm.Matrix:
        zero = {u: 0 for u in self.speed_derivatives}
        with self._rates_unknown():
            return sm.Matrix([self.defs.substitute(e, zero) for e in self._kane_rows()])

    def _kane_rows(self) -> list:
        eqs = self.equations()
        return list(eqs.rows[:len(eqs.speeds), 0])

    def _rates_unknown(self):
        """The definitions with the speeds' derivatives undefined: Fr + Fr* = 0 holds
        them as unknowns, which a SOLVE(ZERO, U1', ...) of the model has defined as its
        solution (the rows would then be 0 = 0, and M^-1 forcing 0)."""
        rates = set(self.speed_derivatives)
        now = self.defs.user_definitions()
        return self.defs.as_of({s: e for s, e in now.items() if s not in rates}
                               if rates & set(now) else None)

    @property
    def mass_matrix_full(self) -> sm.Matrix:
        """[[K, 0], [0, M]] for the state [q; u], K from the kinematical equations."""
        qs = self.coordinates
        m = self.mass_matrix
        k = len(qs)
        full = sm.zeros(k + m.rows, k + m.cols)
        full[:k, :k] = sm.eye(k)
        full[k:, k:] = m
        return full

    @property
    def forcing_full(self) -> sm.Matrix:
        kin = self.kinematical_equations
        return sm.Matrix([kin[S.derivative(q)] for q in self.coordinates] + list(self.forcing))

    def explicit_form(self) -> sm.Matrix:
        """[q'; u'] as functions of the state: the kinematical equations over the
        accelerations solved from M u' = forcing (Z-named Gaussian elimination)."""
        kin = self.kinematical_equations
        udot = solve_linear(self.mass_matrix, self.forcing, self.defs, "the dynamics")
        return sm.Matrix([kin[S.derivative(q)] for q in self.coordinates] + udot)

    def symbolic_system(self, form: str = "combined"):
        """A sympy SymbolicSystem ('explicit', 'combined' or 'separate'), in
        dynamicsymbols with every definition expanded."""
        return symbolic_system(self, form)
