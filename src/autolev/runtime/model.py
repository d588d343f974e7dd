"""The model: everything a translated .al file declares and computes.

Generated code creates one `Model` and calls it statement by statement.  Here is what
the model declares: the symbol kinds and the definitions table.  What it holds besides
is in parts, each changed only through its own methods (each bumping the revision):
its registry of frames, points, bodies and particles (registry.py), its loads
(loads.py), its constraints (constraints.py), what INPUT, OUTPUT, UNITS, ENCODE and
CODE recorded (io.py's IOStatements) and Kane's equations KANE() took or formed last
(equations.py's FormedEquations).  The commands it runs are its mixins':
Kane's method and its equations (equations.py), mass properties (mass_properties.py),
the algebra functions (algebra.py), the I/O statements (io.py) and running them
(simulation.py).
"""
from __future__ import annotations

import importlib
import types
from types import MappingProxyType
from dataclasses import dataclass, field, replace

import sympy as sm

from . import symbols as S
from .algebra import AlgebraMixin
from .calculus import Definitions
from .constraints import Constraints
from .derived import DerivedCache, Revision, mutation
from .equations import EquationsMixin, FormedEquations
from ..engine.errors import AutolevModelError
from .frame import Frame, Scene, angular_velocity_in_both, euler_parameter_rates
from .interop import to_sympy_expr, to_sympy_vector
from .io import IOMixin, IOStatements
from .kane import SymbolInfo
from .linalg import coefficients, solve_linear
from .loads import Loads
from .mass_properties import MassPropertiesMixin
from .point import Body, Particle, Point
from .registry import Registry
from .simulation import SimulationMixin
from .vectors import Dyadic, Vector, _vector

@dataclass
class Loaded:
    """What loading a model attached to it: its module's namespace, the translation's
    Python names of the Autolev names (by namespace), where each CODE statement is in
    the .al file and which statement defines each quantity, what rebuilds it in
    another process (`source`, the loader's ModelSource) and what writes it back to
    the cache of built models (`keeper`, the loader's ModelKeeper: `added()` when a
    numeric system is built, `flush(model)`)."""

    namespace: dict
    names: dict = field(default_factory=dict)
    namespaces: dict = field(default_factory=dict)
    code_locations: list = field(default_factory=list)
    defined_at: dict = field(default_factory=dict)   # Translation.defined_at
    statements_at: dict = field(default_factory=dict)   # Translation.statements_at
    source: object = None
    keeper: object = None


class Model(EquationsMixin, MassPropertiesMixin, AlgebraMixin, IOMixin, SimulationMixin):
    def __init__(self, name: str = "model", degrees: bool = True, complex: bool = False):
        self.name = name
        # every change to the model bumps it: what is derived is keyed on it alone
        self._revision = Revision()
        self.defs = Definitions(self._revision)
        self.t = S.TIME
        self.degrees = degrees
        self.complex = complex
        self.info: dict[sm.Symbol, SymbolInfo] = {}
        # its parts, each bumping the revision when it changes
        self.registry = Registry(self._revision)
        self.loads = Loads(self._revision)
        self.constraints = Constraints(self._revision)
        self.io = IOStatements(self._revision)
        self.formed_equations = FormedEquations(self._revision)
        self.settings: dict[str, object] = {}
        self._nicheck_work = None
        # what numerics and interop derive from the model (numeric systems, ...)
        self.derived = DerivedCache(self._revision)
        self._kinematics_pending: dict = {}   # U -> f(q') awaiting inversion
        # what its frames and points share; unit_quaternions: (e1, e2, e3, e4) of
        # DIRCOS(..., EULER, ...)
        self.scene = Scene(self.defs, self.info, self.derived, self.point,
                           self._orientation_changed)
        # the expression D(E, x) last differentiated, and the names it was asked about
        self.d_row: tuple = (None, [])
        self.loaded: Loaded | None = None          # set by the loader, None when built here

    def __repr__(self) -> str:
        return f"<autolev Model {self.name}>"

    def _repr_html_(self) -> str:
        """Jupyter's view: what the model declares, with its INPUT values."""
        from .notebook import model_html
        return model_html(self)

    # -- pickling (the cache of built models) --------------------------------------
    def __getstate__(self) -> dict:
        """The model as its statements left it, with the numeric systems built for its
        CODE commands (their compiled code is found again by its digest); the modules
        its namespace holds go by name."""
        state = dict(self.__dict__)     # (the derived tables pickle what they keep)
        if self.loaded is not None:        # the keeper stays with this process
            state["loaded"] = replace(self.loaded, keeper=None, namespace={
                k: (_ModuleName(v.__name__) if isinstance(v, types.ModuleType) else v)
                for k, v in self.loaded.namespace.items() if k != "__builtins__"})
        return state

    def __setstate__(self, state: dict) -> None:
        loaded = state.get("loaded")
        if loaded is not None:
            for k, v in loaded.namespace.items():
                if isinstance(v, _ModuleName):
                    loaded.namespace[k] = importlib.import_module(v.name)
        self.__dict__.update(state)

    def __getitem__(self, name: str):
        """What the model calls `name` (any case), following Autolev's namespaces: a
        name ending in `>` or `>>` is a vector or dyadic (model["P_NO_P>"] too); any
        other name is first a quantity (a constant, variable, matrix or other assigned
        value: model["ZERO"], model["Q1'"]), then a frame, body, point or particle
        (model["N"]).  Where a name is both (a body A and a matrix A), model.quantity
        and model.entity ask for each."""
        if name.endswith(">"):
            return self.vector(name)
        for lookup in (self.quantity, self.entity):
            try:
                return lookup(name)
            except KeyError:
                pass
        raise KeyError(name)

    def _named(self, space: str, name: str):
        if self.loaded is None:
            raise KeyError(name)
        namespace = self.loaded.namespace
        for autolev_name, py in self.loaded.namespaces.get(space, {}).items():
            if autolev_name.lower() == name.lower() and py in namespace:
                return namespace[py]
        raise KeyError(name)

    def quantity(self, name: str):
        """The constant, variable (Q1, Q1'), matrix or assigned value named `name`."""
        try:
            return self._named("quantity", name)
        except KeyError:
            pass
        base = name.rstrip("'")
        for sym, info in self.info.items():
            if S.base_and_order(sym)[1] == 0 and sym.name.lower() == base.lower():
                return S.derivative(sym, len(name) - len(base))
        raise KeyError(name)

    def engine_symbol(self, name: str):
        """The scalar `name` (WCHECK1, WCHECK1') where the translation cannot know it:
        the engine declared it (NICHECK's work integral).  Autolev's responses name it."""
        try:
            value = self.quantity(name)
        except KeyError:
            raise AutolevModelError(f"'{name}' is not a name of this model") from None
        if not isinstance(value, sm.Symbol):
            raise AutolevModelError(f"'{name}' is not a scalar of this model")
        return value

    def entity(self, name: str):
        """The frame, body, point or particle named `name` (NO, BO, AO included)."""
        for table in (self.frames_by_name, self.points_by_name):
            for k, v in table.items():
                if k.lower() == name.lower():
                    return v
        return self._named("entity", name)

    def vector(self, name: str):
        """The vector or dyadic the model assigned to `name` (`V>`, `I>>`, or the name
        without the marks)."""
        return self._named("vector", name.rstrip(">"))

    def note_change(self) -> None:
        """What follows each of the model's `mutation` methods (its frames' and points'
        notices come through their Scene, its definitions' through its Definitions): it
        bumps the one revision."""
        self._revision.bump()

    @property
    def unit_quaternions(self) -> list:
        return self.scene.unit_quaternions

    # -- what its parts hold, read (a list is a copy: changing it changes no part) -----
    @property
    def newtonian_frame(self) -> Frame | None:
        return self.registry.newtonian

    @property
    def frames_by_name(self) -> MappingProxyType:
        return self.registry.frames

    @property
    def points_by_name(self) -> MappingProxyType:
        return self.registry.points

    @property
    def bodies_list(self) -> list:
        return list(self.registry.bodies)

    @property
    def particles_list(self) -> list:
        return list(self.registry.particles)

    @property
    def forces(self) -> MappingProxyType:
        return self.loads.forces

    @property
    def torques(self) -> MappingProxyType:
        return self.loads.torques

    @property
    def gravity_vectors(self) -> list:
        return list(self.loads.gravity_vectors)

    @property
    def dependent_speeds(self) -> list:
        return list(self.constraints.dependent_speeds)

    @property
    def auxiliary_speeds(self) -> list:
        return list(self.constraints.auxiliary_speeds)

    @property
    def dependent_constraints(self) -> list:
        return list(self.constraints.dependent_constraints)

    @property
    def solved_speeds(self) -> frozenset:
        return self.constraints.solved_speeds

    @property
    def solved_rates(self) -> list:
        return list(self.constraints.solved_rates)

    def revision(self) -> tuple:
        """A value that changes whenever the model is changed (a statement, an INPUT,
        a CODE command, a caller's change), so that what was derived from it can be
        known stale; the derived cache is keyed on it."""
        return self._revision.key

    def _orientation_changed(self) -> None:
        """An orientation changes the direction cosines derived along the frames' paths
        (kept until then, not per revision: only orientations change them)."""
        for f in self.frames_by_name.values():
            f.forget_derived()

    # -- declarations ------------------------------------------------------------------
    def newtonian(self, name: str) -> Frame:
        """NEWTONIAN N: the inertial frame and its origin NO (at rest in N)."""
        frame = self.frame(name)
        self.registry.set_newtonian(frame)
        origin = self.point(name + "O")
        origin.set_vel(frame, Vector())
        origin.set_acc(frame, Vector())
        frame.origin = origin
        return frame

    def _newtonian(self) -> Frame:
        if self.newtonian_frame is None:
            raise AutolevModelError("no NEWTONIAN frame was declared")
        return self.newtonian_frame

    def frame(self, name: str) -> Frame:
        f = Frame(name, self.scene)
        self.registry.add_frame(f)
        return f

    def frames(self, *names: str):
        out = tuple(self.frame(n) for n in _split(names))
        return out[0] if len(out) == 1 else out

    def body(self, name: str) -> Body:
        b = Body(name, self.scene, self.point(name + "O"))
        self.registry.add_body(b)
        return b

    def bodies(self, *names: str):
        out = tuple(self.body(n) for n in _split(names))
        return out[0] if len(out) == 1 else out

    def point(self, name: str) -> Point:
        p = Point(name, self.scene)
        self.registry.add_point(p)
        return p

    def points(self, *names: str):
        out = tuple(self.point(n) for n in _split(names))
        return out[0] if len(out) == 1 else out

    def particle(self, name: str) -> Particle:
        p = Particle(name, self.scene)
        self.registry.add_particle(p)
        return p

    def particles(self, *names: str):
        out = tuple(self.particle(n) for n in _split(names))
        return out[0] if len(out) == 1 else out

    @mutation
    def _declare(self, names, kind: str, order: int = 0, sign: str | None = None):
        out = []
        for n in _split(names):
            sym = S.scalar(n, real=not self.complex and kind != "imaginary", sign=sign)
            if kind == "imaginary":
                sym = sm.I
            else:
                self.info[sym] = SymbolInfo(kind, order, len(self.info))
                if kind != "constant":
                    rates = (S.derivative(sym, k) for k in range(1, order + 1))
                    self.defs.mark_varying(sym, *rates)
                    for k in range(1, order + 1):
                        d = S.derivative(sym, k)
                        self.info.setdefault(d, SymbolInfo(kind, order - k, len(self.info)))
            out.append(sym)
        return out[0] if len(out) == 1 else tuple(out)

    def constants(self, *names: str, sign: str | None = None):
        return self._declare(names, "constant", 0, sign)

    def variables(self, *names: str, order: int = 0):
        return self._declare(names, "variable", order)

    def motion_variables(self, *names: str, order: int = 0):
        return self._declare(names, "motionvariable", order)

    def specifieds(self, *names: str, order: int = 0):
        return self._declare(names, "specified", order)

    def imaginary(self, *names: str):
        return self._declare(names, "imaginary")

    def kind_of(self, sym) -> str | None:
        info = self.info.get(sym)
        return info.kind if info else None

    # -- definitions -----------------------------------------------------------------
    @mutation
    def define(self, sym, value) -> None:
        """X = value for a declared X (or X', X''): a definition, not a substitution."""
        if isinstance(sym, sm.Matrix):
            for s, v in zip(sym, sm.Matrix(value)):
                self.define(s, v)
            return
        if not isinstance(sym, sm.Symbol):
            raise AutolevModelError(f"only a declared name can be defined, not {sym}")
        if isinstance(value, (Vector, Dyadic)):
            raise AutolevModelError(f"{sym} is a scalar; it cannot be given a vector or dyadic")
        value = sm.sympify(value)
        if self._is_speed_definition(sym, value):
            # U = Q' (or a combination of rates): a kinematical equation written for
            # the speed; it is solved for the rates once they can all be determined
            self._kinematics_pending[sym] = value
            self._resolve_kinematics()
            return
        self.defs.define(sym, value)

    def _rates_in(self, value) -> set:
        """Undefined first derivatives of variables that appear in value."""
        out = set()
        for f in value.free_symbols:
            base, order = S.base_and_order(f)
            info = self.info.get(base)
            if order == 1 and info is not None and info.kind in ("variable", "motionvariable") \
                    and f not in self.defs.rhs:
                out.add(f)
        return out

    def _is_speed_definition(self, sym, value) -> bool:
        """U = f(Q') for a motion variable U, linear in rates of motion variables."""
        info = self.info.get(sym)
        if info is None or info.kind != "motionvariable" or S.base_and_order(sym)[1]:
            return False
        rates = {r for r in self._rates_in(value)
                 if self.info[S.base_and_order(r)[0]].kind == "motionvariable"}
        if not rates:
            return False
        return all(sm.diff(value, r, 2) == 0 for r in rates)

    def _resolve_kinematics(self) -> None:
        """Solve the pending U = f(q') equations for the q' when they determine them."""
        pending = self._kinematics_pending
        rates = set()
        for v in pending.values():
            rates |= self._rates_in(v)
        if not pending or len(rates) != len(pending):
            return
        rates = sorted(rates, key=lambda r: self.info[S.base_and_order(r)[0]].index)
        eqs = [u - v for u, v in pending.items()]
        a, r = coefficients(eqs, rates, self.defs)
        solution = solve_linear(a, -r, self.defs, "the kinematical equations")
        for rate, val in zip(rates, solution):
            self.defs.define(rate, val)
        pending.clear()

    def rhs(self, value):
        """RHS(x): the stored right-hand side of a declared x.  Names assigned without a
        declaration are translated to Python values, which are their own RHS."""
        if isinstance(value, sm.MatrixBase):
            return value.applyfunc(self.rhs)
        if isinstance(value, (Vector, Dyadic)):
            return value
        value = sm.sympify(value)
        if isinstance(value, sm.Symbol) and not isinstance(value, S.Z):
            if value not in self.defs.rhs:
                raise AutolevModelError(f"{value} has no stored right-hand side")
            return self.defs.rhs[value]
        return value

    def previous(self, sym):
        """X on the right of a new definition of X: its definition so far (X itself
        when it has none, which makes X = f(X) an error)."""
        return self.defs.rhs.get(sym, sym)

    def explicit(self, value, keep=None):
        """EXPLICIT(x): every definition and Z expanded; EXPLICIT(x, [u, v]) keeps the
        listed names (expressed in terms of them)."""
        if keep is None:
            return self.map_scalars(value, self.defs.explicit)
        names = list(keep) if isinstance(keep, (sm.MatrixBase, list, tuple)) else [keep]
        return self.map_scalars(value, lambda e: self.defs.explicit(e, names))

    def map_scalars(self, value, fn):
        if isinstance(value, (Vector, Dyadic)):
            return value.applyfunc(fn)
        if isinstance(value, sm.MatrixBase):
            return value.applyfunc(fn)
        return fn(sm.sympify(value))

    # -- calculus --------------------------------------------------------------------
    def dt(self, value, frame: Frame | None = None):
        """DT(x) of a scalar or matrix; DT(V>, N) of a vector or dyadic in frame N."""
        if isinstance(value, (Vector, Dyadic)):
            if frame is None:
                raise AutolevModelError("DT of a vector needs the frame: DT(V>, N)")
            return value.dt(frame)
        if isinstance(value, sm.MatrixBase):
            return value.applyfunc(self.defs.dt)
        return self.defs.dt(value)

    def d(self, value, var, frame: Frame | None = None):
        """D(x, v): partial derivative through definitions; D(V>, v, N) in frame N;
        D(column, row) is the Jacobian."""
        if isinstance(var, sm.MatrixBase):
            col = value if isinstance(value, sm.MatrixBase) else sm.Matrix([value])
            xs = list(var)
            if not all(isinstance(x, sm.Symbol) for x in xs):
                raise AutolevModelError(f"D(E, [x, ...]) differentiates with respect to "
                                        f"names, not {', '.join(map(str, xs))}")
            # one pass over the definitions for every entry (not one per entry)
            jac = self.defs.jacobian(list(col), xs)
            return sm.Matrix(len(col), len(xs), lambda i, j: jac[i][j])
        if isinstance(value, Vector):
            if frame is None:
                raise AutolevModelError("D of a vector needs the frame: D(V>, x, N)")
            return value.diff(var, frame)
        if isinstance(value, sm.MatrixBase):
            return value.applyfunc(lambda e: self._partial(e, var))
        return self._partial(value, var)

    def _partial(self, value, var):
        """D(E, x); a new E is differentiated in one pass in the names the previous E
        was asked about too: a Jacobian written row by row (A[i,j] = D(X_i', X_j), as
        linearizations are) walks each row's definitions once, not once per element;
        the other derivatives wait in the definitions' cache for the statements that
        ask.  (Column by column, each E is asked one name at a time, as before.)"""
        defs = self.defs
        if not isinstance(var, sm.Symbol) or var in defs.rhs:
            return defs.diff(value, var)
        last, names = self.d_row
        if value == last:
            if var not in names:
                names.append(var)
            return defs.jacobian([value], [var])[0][0]
        others = [x for x in names if x != var and x not in defs.rhs]
        self.d_row = (value, [var])
        return defs.jacobian([value], [var] + others)[0][0]

    # -- kinematics commands -------------------------------------------------------------
    def kindiffs(self, parent: Frame, child: Frame, kind: str, *coords) -> None:
        """KINDIFFS(A, B, BODYijk|SPACEijk|EULER, q...): define the q' so that the
        rotation sequence's angular velocity equals the assigned W_B_A>."""
        if not child.ang_vel_assigned(parent):
            raise AutolevModelError(f"KINDIFFS needs W_{child.name}_{parent.name}> "
                                    "assigned first (in terms of the speeds)")
        kind = kind.lower()
        w_given = child.ang_vel_in(parent)
        coords = [sm.sympify(q) for q in coords]
        rates = [S.derivative(q) for q in coords]
        if kind == "euler":
            if len(coords) != 4:
                raise AutolevModelError("KINDIFFS(..., EULER, e1, e2, e3, e4) takes 4 "
                                        "parameters")
            solution = euler_parameter_rates(coords, w_given.components_in(child))
        else:
            if len(coords) != 3:
                raise AutolevModelError(f"KINDIFFS(..., {kind.upper()}, ...) takes 3 angles")
            # the rates are the unknowns here, even of an angle that is defined (the
            # 3-D pendulum's q4 = 0 with its speed made dependent)
            def rate(q):
                return S.derivative(q) if isinstance(q, sm.Symbol) else self.defs.dt_raw(q)
            if not kind.startswith(("body", "space")):
                raise AutolevModelError(f"KINDIFFS does not know the rotation type "
                                        f"{kind.upper()}")
            w_child, w_parent = angular_velocity_in_both(coords, kind, rate)
            # the equations in the frame W_B_N> is written in (N's axes: in N), where the
            # sequence's angular velocity holds two of the angles and W no direction
            # cosine, so the small solve has little to simplify
            if set(w_given.terms) == {parent}:
                implied, wanted = w_parent, w_given.components_in(parent)
            else:
                implied, wanted = w_child, w_given.components_in(child)
            eqs = [implied[i] - wanted[i] for i in range(3)]
            a, r = coefficients(eqs, rates, self.defs)
            solution = _solve_small(a, -r)
        for rate, value in zip(rates, solution):
            self.define(rate, value)

    # -- loads -----------------------------------------------------------------------
    def force(self, point: Point, value) -> None:
        """FORCE(P, F>): add F> to the resultant force on P."""
        self.add_force(point, value)

    def force_pair(self, a: Point, b: Point, value) -> None:
        """FORCE(A/B, F>): +F> on B, -F> on A."""
        self.add_force(b, value)
        self.add_force(a, -_vector(value))

    def add_force(self, point: Point, value) -> None:
        self.loads.add_force(point, value)

    def set_force(self, point: Point, value) -> None:
        """FORCE_P> = F>"""
        self.loads.set_force(point, value)

    def force_on(self, point: Point) -> Vector:
        """FORCE_P>: the resultant force applied to P so far."""
        return self.loads.force_on(point)

    def torque(self, frame: Frame, value) -> None:
        """TORQUE(A, T>): add T> to the resultant torque on A."""
        self.add_torque(frame, value)

    def torque_pair(self, a: Frame, b: Frame, value) -> None:
        """TORQUE(A/B, T>): +T> on B, -T> on A."""
        self.add_torque(b, value)
        self.add_torque(a, -_vector(value))

    def add_torque(self, frame: Frame, value) -> None:
        self.loads.add_torque(frame, value)

    def set_torque(self, frame: Frame, value) -> None:
        self.loads.set_torque(frame, value)

    def torque_on(self, frame: Frame) -> Vector:
        return self.loads.torque_on(frame)

    def gravity(self, g, *bodies) -> None:
        """GRAVITY(g>[, B, P, ...]): m*g> on the mass center of every body and particle
        (or of those listed)."""
        self.loads.gravity(_vector(g), list(bodies) if bodies
                           else self.bodies_list + self.particles_list)

    # -- constraints -----------------------------------------------------------------
    def constrain(self, equations, dependent) -> None:
        """CONSTRAIN(DEPENDENT[u...]): solve the motion constraints (= 0) for the listed
        speeds, which are then defined in terms of the others."""
        solved = self._solve_speeds(equations, dependent, "DEPENDENT")
        self.constraints.add_dependent(solved, dependent)

    def constrain_auxiliary(self, equations, auxiliary) -> None:
        """CONSTRAIN(AUXILIARY[u...]): the listed speeds bring noncontributing forces into
        evidence; they are solved from their constraints (zero in simulation)."""
        self._solve_speeds(equations, auxiliary, "AUXILIARY")
        self.constraints.add_auxiliary(auxiliary)

    def _solve_speeds(self, equations, speeds, what: str) -> list:
        """Define `speeds` by the constraints `equations` (each = 0), which it returns."""
        eqs = list(sm.Matrix(equations)) if not isinstance(equations, (list, tuple)) \
            else list(equations)
        speeds = list(speeds)
        if len(eqs) != len(speeds):
            raise AutolevModelError(f"{what} has {len(eqs)} equations for {len(speeds)} speeds")
        a, r = coefficients(eqs, speeds, self.defs)
        solution = solve_linear(a, -r, self.defs, f"the {what} constraints")
        for s, v in zip(speeds, solution):
            self.define(s, v)
        for s, v in zip(speeds, solution):
            # the derivative too, which accelerations use (u' of a dependent speed)
            d = S.derivative(s)
            if d not in self.defs.rhs:
                self.define(d, self.defs.zify(self.defs.dt(v)))
        return eqs

    def to_mechanics(self):
        """The model as sympy.physics.mechanics objects (frames, points, particles and
        rigid bodies, loads, kinematical equations) with a KanesMethod whose equations
        sympy formed itself: a Handoff (runtime/handoff.py)."""
        from .handoff import handoff
        return handoff(self)

    def to_pydy(self, infile=None, **overrides):
        """A pydy.system.System (PyDy is an optional extra) of to_mechanics()'s
        KanesMethod, with the constants and initial conditions a run takes (INPUT, the
        .in file `infile`, then `overrides` in the quantities' units)."""
        from .handoff import to_pydy
        return to_pydy(self, infile, overrides or None)

    def to_opty(self, infile=None, controls=None, **overrides):
        """The equations of motion as opty's direct collocation takes them (opty is not
        needed to make them): an OptyParts (runtime/handoff.py) of to_mechanics()'s
        KanesMethod, with the constants' values a run takes; `controls` as
        Model.dynamics takes them (default: the specified quantities)."""
        from .handoff import to_opty
        return to_opty(self, infile, overrides or None, controls)

    def to_sympy(self, value):
        """An expression, matrix or vector as plain sympy (dynamicsymbols, expanded)."""
        if isinstance(value, Vector):
            return to_sympy_vector(value)
        return to_sympy_expr(self.scene, self.explicit(value))


def _split(names) -> list[str]:
    out: list[str] = []
    for n in names:
        out.extend(n.replace(",", " ").split())
    return out


def _solve_small(a: sm.Matrix, b: sm.Matrix) -> list:
    """Exact solve of a small system (kinematical equations) by its adjugate: the
    determinant and the adjugate's entries, a few trigonometric terms each, reduced
    alone by SIN(Q)^2 + COS(Q)^2 = 1 (_pythagorean), never the solution's larger
    expressions."""
    det = _pythagorean(a.det(method="berkowitz"))
    adj = a.adjugate(method="berkowitz").applyfunc(_pythagorean)
    return [sm.cancel(sm.together(sum(adj[i, j] * b[j] for j in range(b.rows)) / det))
            for i in range(a.rows)]


def _pythagorean(e: sm.Expr) -> sm.Expr:
    """e expanded, and with each COS(X)^2 written 1 - SIN(X)^2 where that makes it
    shorter: the reduction the products of an orientation sequence's sines and cosines
    need (a determinant SIN(Q2)^3 + SIN(Q2)*COS(Q2)^2 is SIN(Q2)), by one rule where a
    general simplifier (trigsimp: a third of a small KINDIFFS model's forming) tries
    many."""
    e = sm.expand(e)
    squares = {p: sm.cos(p.base.args[0]) ** (p.exp % 2)
               * (1 - sm.sin(p.base.args[0]) ** 2) ** (p.exp // 2)
               for p in e.atoms(sm.Pow)
               if isinstance(p.base, sm.cos) and p.exp.is_Integer and p.exp >= 2}
    if not squares:
        return e
    reduced = sm.expand(e.xreplace(squares))
    return reduced if sm.count_ops(reduced) < sm.count_ops(e) else e


class _ModuleName:
    """A module in a pickled model's namespace, imported again when it is read."""

    def __init__(self, name: str):
        self.name = name
