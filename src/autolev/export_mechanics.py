"""`autolev convert --to sympy` at the mechanics level: the model written as a SymPy user
writes one, in sympy.physics.mechanics (issue 33).

The script is printed from the mechanics hand-off (runtime/handoff.py, which builds the
same objects in memory): ReferenceFrames oriented as the model orients them
(`orient_axis` for a simple rotation, else `orient_explicit` with the direction cosines)
with the model's angular velocities, Points with their positions and velocities,
Particles and RigidBodies with masses and central inertias, the loads, the kinematical
differential equations and a KanesMethod whose equations sympy forms at import.  The
values, the OUTPUT columns and the runner are the equations-level script's (export.py),
so `python OUT.py` integrates and writes as that script does.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import sympy as sm
import sympy.physics.mechanics as me
from sympy.core.function import AppliedUndef
from sympy.printing.precedence import PRECEDENCE

from .export import (EquationsScript, Script, ScriptPrinter, identifier, quoted_text,
                     split_at_the_unknowns)
from .runtime import symbols as S
from .runtime.equations_of import Equations, equations_of, state_of
from .engine.errors import AutolevModelError
from .runtime.handoff import CONSTRAINT_SOLVER, Handoff, handoff
from .runtime.floats import NoRealValue, ValuesAt
from .runtime.interop import simple_rotation
from .runtime.model import Model

LEVELS = ("auto", "mechanics", "equations")
# KanesMethod forms and inverts symbolic matrices: beyond this many speeds it is slow
MOST_SPEEDS = 12

AXES = "xyz"


class MechanicsPrinter(ScriptPrinter):
    """Expressions, vectors and dyadics of sympy.physics.mechanics as the Python that
    builds them, each dynamicsymbol, constant, frame and point by its identifier."""

    def _print_Function(self, expr):
        if isinstance(expr, AppliedUndef):
            if expr not in self.names:
                raise AutolevModelError(f"the SymPy export has no value for {expr}")
            return self.names[expr]
        return super()._print_Function(expr)

    def _print_Derivative(self, expr):
        (variable, count), = expr.variable_count
        if variable != me.dynamicsymbols._t or not isinstance(expr.expr, AppliedUndef):
            raise AutolevModelError(f"the SymPy export cannot write the derivative {expr}")
        order = f", {count}" if count > 1 else ""
        return f"{self._print(expr.expr)}.diff(t{order})"

    def unit(self, frame, k: int) -> str:
        return f"{self.names[frame]}.{AXES[k]}"

    def vector(self, v) -> str:
        """`c1*A.x + c2*B.y ...` (each term in the frame the model gave it)."""
        terms = []
        for components, frame in v.args:
            for k, c in enumerate(components):
                if c != 0:
                    terms.append(self._term(c, self.unit(frame, k)))
        return _joined(terms, "me.Vector(0)")

    def dyadic(self, d, frame=None) -> str:
        """`me.inertia(B, ...)` for a symmetric dyadic in `frame` alone, else the sum of
        its terms `c*(A.x|B.y)`."""
        in_frame = frame is not None and all(
            a.args[0][1] == frame and b.args[0][1] == frame for _, a, b in d.args)
        if in_frame:
            m = d.to_matrix(frame)
            if m == m.T:
                values = [m[0, 0], m[1, 1], m[2, 2], m[0, 1], m[1, 2], m[2, 0]]
                while len(values) > 3 and values[-1] == 0:
                    values.pop()
                return (f"me.inertia({self.names[frame]}, "
                        + ", ".join(self._print(v) for v in values) + ")")
        terms = []
        for c, a, b in d.args:
            terms.append(self._term(c, f"({self._unit_of(a)}|{self._unit_of(b)})"))
        return _joined(terms, "me.Dyadic(0)")

    def _unit_of(self, v) -> str:
        (components, frame), = v.args
        return self.unit(frame, list(components).index(1))

    def _term(self, coefficient, unit: str) -> str:
        if coefficient == 1:
            return unit
        if coefficient == -1:
            return f"-{unit}"
        return f"{self.parenthesize(coefficient, PRECEDENCE['Mul'], strict=True)}*{unit}"


def _joined(terms: list, zero: str) -> str:
    return " + ".join(terms).replace("+ -", "- ") if terms else zero


class MechanicsScript(Script):
    """The mechanics level (see the module's docstring), from the hand-off: the values,
    the OUTPUT columns and the runner are the equations level's."""

    SECTIONS = ("docstring", "imports", "symbols", "frames", "points", "bodies", "loads",
                "kinematics", "constraints", "kanes_method", "intermediates", "values",
                "runner")
    TITLE = "the model in sympy.physics.mechanics"

    h: Handoff                  # the model's frames, points, bodies and loads in sympy
    model: Model                # the loaded model, for its speeds and statements
    coordinates: list           # the model's coordinates KanesMethod takes (not those it defines)
    rates_of_specified: list    # (rate, its quantity's function, order) of each specified rate
    declared: set               # what the symbols section declares before the intermediates
    where: dict                 # each quantity's name -> the statement that defines it
    statements: dict            # (what, name) -> the statements that give it
    printer: MechanicsPrinter

    def __init__(self, h: Handoff, eqs: Equations, model: Model, source: str):
        self.h, self.eqs, self.model, self.source = h, eqs, model, source
        self.taken, self.names, self.unknown_names = set(), {S.TIME: "t", sm.Symbol("t"): "t"}, {}
        self.coordinates = [x for x, f in h.states.items() if f in h.coordinates]
        self.rates_of_specified = []
        self.name_the_mechanics()
        self.before, self.after = split_at_the_unknowns(eqs)
        wanted = _definitions_wanted(eqs, self.before + self.after)
        self.before = [(z, e) for z, e in self.before if z in wanted]
        self.after = [(z, e) for z, e in self.after if z in wanted]
        self.declared = set(self.names)
        for z, _ in self.before + self.after:
            if z not in self.declared:
                base, order = S.base_and_order(z)
                self.names[z] = identifier(base.name + "p" * order, self.taken)
        self.printer = MechanicsPrinter(self.names)
        loaded = model.loaded
        self.where = loaded.defined_at if loaded is not None else {}
        self.statements = loaded.statements_at if loaded is not None else {}

    def name_the_mechanics(self):
        """Identifiers for the frames, the states, KANE's unknowns, the specified
        quantities, the constants, the points, the bodies and the solved rates."""
        h, eqs, model, names, taken = self.h, self.eqs, self.model, self.names, self.taken
        frames = [h.newtonian] + [child for _, child, _, _ in h.orientations]
        for f in frames:
            names[f] = identifier(f.name, taken)
        for q in self.coordinates:
            names[q] = names[h.states[q]] = identifier(q.name, taken)
        for u in model.speeds:
            names[u] = names[h.states[u]] = identifier(str(h.states[u].func), taken)
        for u in h.dependent + h.auxiliary:
            names[u] = identifier(str(u.func), taken)
        for ours, force in zip(model.kane_equations.unknowns if h.unknowns else [], h.unknowns):
            # one name for KANE's unknown in the loads and as the run computes it
            names[ours] = names[force] = identifier(str(force.func), taken)
        for s in eqs.specified:
            base, order = S.base_and_order(s)
            f = h.specified_of(base)
            names.setdefault(f, identifier(base.name, taken))
            if order:
                # a rate of a specified quantity: its derivative, given a value of its own
                names[s] = identifier(base.name + "p" * order, taken)
                self.rates_of_specified.append((s, f, order))
            else:
                names[s] = names[f]
        for c in h.constants:
            names[c] = identifier(c.name, taken)
        plain = {c.name: c for c in h.constants}
        for c in eqs.constants:
            names[c] = names[plain[c.name]]
        for name, point in h.points.items():
            names[point] = identifier(name, taken)
        for body in h.bodies:
            names[body] = identifier(body.name + ("_body" if isinstance(body, me.RigidBody)
                                                  else "_particle"), taken)
        for u in eqs.unknowns:
            base, order = S.base_and_order(u)
            self.unknown_names[u] = names[u] = identifier(base.name + "p" * order, taken)

    def said(self, *keys) -> list[str]:
        """The statements that give (what, name) of each key, as comment lines."""
        lines = [f"# {quoted_text(at)}" for what, name in keys
                 for at in self.statements.get((what, name.upper()), [])]
        return list(dict.fromkeys(lines))

    def description(self) -> list:
        return ["Level: mechanics.  Frames, points, particles and rigid bodies, loads and the",
                "kinematical differential equations as the model gives them; sympy's KanesMethod",
                "forms the equations of motion when the script is imported.  Importing defines",
                "`kane` (its equations formed), `constants`, `initial_conditions` and "
                "`specified`;"]

    def symbols(self) -> list:
        """The coordinates and speeds, auxiliary speeds, KANE's unknowns, specified
        quantities (and their rates) and constants."""
        h, names = self.h, self.names
        out = ["# generalized coordinates and speeds: functions of time"]
        out += [f"{names[q]} = me.dynamicsymbols({str(q.func)!r})"
                for q in h.coordinates + h.speeds + h.dependent]
        if h.auxiliary:
            out += ["", "# auxiliary speeds: zero in motion, they bring noncontributing forces "
                    "into evidence"]
            out += self.said(("assigned", "AUXILIARY"), ("constrain", "AUXILIARY"))
            out += [f"{names[u]} = me.dynamicsymbols({str(u.func)!r})" for u in h.auxiliary]
            out.append("auxiliary = [" + ", ".join(names[u] for u in h.auxiliary) + "]")
        if h.unknowns:
            out += ["", "# KANE's unknowns: noncontributing forces, which kane.auxiliary_eqs "
                    "(= 0) give"]
            out += [f"{names[f]} = me.dynamicsymbols({str(f.func)!r})" for f in h.unknowns]
        if self.eqs.specified:
            out += ["", "# specified quantities: functions of time (values in `specified`)"]
            out += [f"{names[s]} = me.dynamicsymbols({str(s.func)!r})" for s in h.specified
                    if s in names]
            out += [f"{names[s]} = {names[f]}.diff(t{f', {order}' if order > 1 else ''})"
                    for s, f, order in self.rates_of_specified]
        if h.constants:
            out += ["", "# constants"]
            out += [f"{names[c]} = sm.Symbol({c.name!r})" for c in h.constants]
        return out

    def frames(self) -> list:
        """The frames, oriented (orient_axis for a simple rotation), with their angular
        velocities."""
        h, names, p = self.h, self.names, self.printed
        out = ["", "# reference frames, oriented as the model orients them, with its angular "
               "velocities", f"{names[h.newtonian]} = me.ReferenceFrame({h.newtonian.name!r})"]
        for parent, child, dcm, w in h.orientations:
            out += self.said(("orientation", child.name), ("angular velocity", child.name))
            out.append(f"{names[child]} = me.ReferenceFrame({child.name!r})")
            rotation = simple_rotation(dcm)
            if rotation is not None:
                k, angle = rotation
                out.append(f"{names[child]}.orient_axis({names[parent]}, "
                           f"{self.printer.unit(parent, k)}, {p(angle)})")
            else:
                out.append(f"{names[child]}.orient_explicit({names[parent]}, sm.Matrix(["
                           + ", ".join("[" + ", ".join(p(e) for e in dcm.row(r)) + "]"
                                       for r in range(3)) + "]))")
            if w is not None:
                out.append(f"{names[child]}.set_ang_vel({names[parent]}, "
                           f"{self.printer.vector(w)})")
        return out

    def points(self) -> list:
        h, names = self.h, self.names
        out = ["", "# points: positions from the Newtonian origin, velocities in "
               f"{h.newtonian.name} of those with a mass or a load"]
        out += [f"{names[pt]} = me.Point({name!r})" for name, pt in h.points.items()]
        for point, base, r in h.positions:
            out += self.said(("position", f"{base.name}/{point.name}"),
                             ("position", f"{point.name}/{base.name}"))
            out.append(f"{names[point]}.set_pos({names[base]}, {self.printer.vector(r)})")
        for name, v in h.velocities.items():
            out += self.said(("velocity", name))
            out.append(f"{names[h.points[name]]}.set_vel({names[h.newtonian]}, "
                       f"{self.printer.vector(v)})")
        return out

    def bodies(self) -> list:
        """The particles and rigid bodies (a body's inertia about its mass center)."""
        h, names, p = self.h, self.names, self.printed
        out = ["", "# particles and rigid bodies: masses and central inertias"]
        for body in h.bodies:
            out += self.said(("mass", body.name), ("inertia", body.name))
            if isinstance(body, me.RigidBody):
                dyadic, about = body.inertia
                out.append(f"{names[body]} = me.RigidBody({body.name!r}, "
                           f"{names[body.masscenter]}, {names[body.frame]}, {p(body.mass)}, "
                           f"({self.printer.dyadic(dyadic, body.frame)}, {names[about]}))")
            else:
                out.append(f"{names[body]} = me.Particle({body.name!r}, "
                           f"{names[body.point]}, {p(body.mass)})")
        return out + ["bodies = [" + ", ".join(names[b] for b in h.bodies) + "]"]

    def loads(self) -> list:
        out = ["", "# loads: forces on points, torques on frames",
               *self.said(("gravity", "*")), "loads = ["]
        for on, v in self.h.loads:
            out += ["    " + line for line in self.said(("load", on.name))]
            out.append(f"    ({self.names[on]}, {self.printer.vector(v)}),")
        return out + ["]"]

    def kinematics(self) -> list:
        """`kd_eqs`: each coordinate's rate less what the model says it is."""
        out = ["", "# kinematical differential equations (each = 0)", "kd_eqs = ["]
        for q, equation in zip(self.coordinates, self.h.kinematical_equations):
            defined = self.where.get(q.name.upper() + "P")
            out += [f"    # {quoted_text(defined)}"] if defined else []
            rate = self.h.states[q].diff(me.dynamicsymbols._t) - equation
            out.append(f"    {self.names[q]}.diff(t) - "
                       f"{self.printer.parenthesize(rate, PRECEDENCE['Add'])},")
        return out + ["]"]

    def constraints(self) -> list:
        """The velocity constraints that give the dependent speeds (none without)."""
        h = self.h
        if not h.dependent:
            return []
        return (["", "# velocity constraints (each = 0), which give the dependent speeds "
                 "(CONSTRAIN(DEPENDENT[...]));",
                 "# KanesMethod solves them by Cramer's rule: its default LU divides by "
                 "pivots that",
                 "# vanish at some states where the constraints are regular (0/0)",
                 *self.said(("assigned", "DEPENDENT"), ("constrain", "DEPENDENT")),
                 "velocity_constraints = ["]
                + [f"    {self.printed(c)}," for c in h.velocity_constraints] + ["]"]
                + ["dependent = [" + ", ".join(self.names[u] for u in h.dependent) + "]"])

    def kanes_method(self) -> list:
        """`kane`, its equations formed, and them as one system."""
        h, names = self.h, self.names
        constrained = ""
        if h.dependent:
            constrained += (", u_dependent=dependent, velocity_constraints="
                            f"velocity_constraints, constraint_solver={CONSTRAINT_SOLVER!r}")
        if h.auxiliary:
            constrained += ", u_auxiliary=auxiliary"
        out = ["",
               f"kane = me.KanesMethod({names[h.newtonian]}, q_ind=["
               + ", ".join(names[q] for q in h.coordinates) + "], u_ind=["
               + ", ".join(names[u] for u in h.speeds) + "], kd_eqs=kd_eqs"
               + constrained + ")",
               "kane.kanes_equations(bodies, loads)", "",
               "# as one system: full_mass * d(states)/dt = full_forcing",
               "states = list(kane.q) + list(kane.u)"]
        if h.auxiliary:
            return out + [
                "# the auxiliary speeds, which the velocity constraints read, are zero in "
                "motion",
                "full_mass, full_forcing = (",
                "    m.xreplace({u.diff(t): 0 for u in auxiliary}).xreplace("
                "dict.fromkeys(auxiliary, 0))",
                "    for m in (kane.mass_matrix_full, kane.forcing_full))", ""]
        return out + ["full_mass = kane.mass_matrix_full", "full_forcing = kane.forcing_full",
                      ""]

    def intermediates(self) -> list:
        """The solved rates and the definitions the outputs use, and where the solved
        rates are in the state."""
        h, eqs, names = self.h, self.eqs, self.names
        out = []
        if eqs.unknowns:
            out += ["# the rates solved from the mass matrix, as the outputs use them"]
            out += [f"{self.unknown_names[u]} = {names[state_of(u)]}.diff(t)"
                    for u in eqs.unknowns]
        if self.before or self.after:
            out += ["# intermediates the outputs use (Autolev's Z's, the model's definitions), "
                    "as",
                    "# functions of time, and what each is, in the order they are computed"]
            out += [f"{names[z]} = me.dynamicsymbols({names[z]!r})"
                    for z, _ in self.before + self.after if z not in self.declared]
        out += self.definition_lists("# those that need the solved rates")
        state_names = [names[s] for s in h.coordinates + h.speeds + h.dependent]
        return out + [
            "unknowns = [" + ", ".join(self.unknown_names[u] for u in eqs.unknowns) + "]",
            "unknown_states = [" + ", ".join(
                str(state_names.index(names[state_of(u)])) for u in eqs.unknowns) + "]",
            ""]

    def values(self) -> list:
        """The equations level's values, and the dependent speeds' where the velocity
        constraints hold."""
        out = super().values()
        if not self.h.dependent:
            return out
        return out + [
            "# the dependent speeds start where the velocity constraints hold (once every",
            "# constant has a value)",
            "if None not in constants.values():",
            "    at_start = {t: integration['TINITIAL'], **constants, **initial_conditions,",
            "                **{s: v(integration['TINITIAL']) if callable(v) else v",
            "                   for s, v in specified.items()}"
            + (", **dict.fromkeys(auxiliary, 0)}" if self.h.auxiliary else "}"),
            "    coefficients, rest = sm.linear_eq_to_matrix(",
            "        [me.msubs(c, kane.kindiffdict()) for c in velocity_constraints], "
            "dependent)",
            "    initial_conditions.update(zip(dependent, np.linalg.solve(",
            "        np.array(coefficients.xreplace(at_start), dtype=float),",
            "        np.array(rest.xreplace(at_start), dtype=float).ravel())))"]


def _definitions_wanted(eqs: Equations, definitions: list) -> set:
    """The definitions the outputs need, directly or through others."""
    value = dict(definitions)
    wanted, todo = set(), [s for _, _, e, _ in eqs.outputs for s in e.free_symbols]
    while todo:
        s = todo.pop()
        if s in value and s not in wanted:
            wanted.add(s)
            todo.extend(sm.sympify(value[s]).free_symbols)
    return wanted


@dataclass(frozen=True)
class SympyExport:
    """A SymPy script, the constants it holds without a value (None there), and what it
    exports (a CODE command, or the model's equations as they stand)."""

    text: str
    lacking: list
    exported: str


# what a script of a model that writes no CODE DYNAMICS or ODE holds (linearize's rule)
AS_THEY_STAND = ("no CODE DYNAMICS or ODE: the model's equations as they stand, as "
                 "linearize takes them")
# and why it is at the equations level unless the mechanics level is asked for
NOT_ASKED = ("the model writes no CODE DYNAMICS or ODE (--level mechanics, or "
             "level=\"mechanics\", asks for sympy's KanesMethod of its bodies and loads)")


def export_sympy(model, source: str, command=None, infile=None, overrides=None,
                 level: str = "auto", missing_values: str = "keep") -> str:
    """The SymPy script of the model's first integrating CODE command (or `command`;
    without one, the model's equations as they stand, as linearize takes them);
    `source`: the model's file, named in the script; its values as a run takes them
    (INPUT, then the .in file `infile`, then `overrides` in the quantities' units).
    `level`: "mechanics", "equations", or "auto" (mechanics when the model allows it,
    else equations with the reason in the script); AutolevModelError when "mechanics"
    is asked of a model it cannot take.  The equations need no numbers: a constant
    without a value stays a symbol (`missing_values="keep"`: None in `constants`, the
    script says so when it is run; "refuse": as a run refuses it)."""
    return sympy_export(model, source, command, infile, overrides, level,
                        missing_values).text


def sympy_export(model, source: str, command=None, infile=None, overrides=None,
                 level: str = "auto", missing_values: str = "keep") -> SympyExport:
    """export_sympy's script, with the names of the constants it has no value for."""
    if level not in LEVELS:
        raise ValueError(f"level is one of {', '.join(LEVELS)}, not {level!r}")
    if command is None:
        command = next((c for c in model.code_commands if c.kind.integrates), None)
    as_they_stand = command is None
    try:
        if as_they_stand:
            command = model.plain_dynamics()
        eqs = equations_of(model, command, infile=infile, overrides=overrides,
                           missing_values=missing_values)
    except AutolevModelError as exc:
        if not as_they_stand:
            raise
        raise AutolevModelError(f"the model writes no CODE DYNAMICS or ODE, and its "
                                f"equations as they stand are not formed: {exc}") from None
    if as_they_stand:
        if not eqs.states:
            raise AutolevModelError("the model writes no CODE DYNAMICS or ODE, and has no "
                                    "equations of motion to export (no motion variables)")
        eqs = replace(eqs, command=AS_THEY_STAND)
    lacking = [c.name for c, v in eqs.constants.items() if v is None]
    if level == "equations":
        return SympyExport(EquationsScript(eqs, source).text(), lacking, eqs.command)
    if as_they_stand and level == "auto":
        # sympy's KanesMethod on a model that never asked for its dynamics can take
        # longer than anyone waits (MAE-223's BICYCLE4: over 20 minutes)
        return SympyExport(EquationsScript(eqs, source, NOT_ASKED).text(), lacking,
                           eqs.command)
    why, h = mechanics_handoff(model, command, eqs)
    if h is not None:
        return SympyExport(MechanicsScript(h, eqs, model, source).text(), lacking,
                           eqs.command)
    if level == "mechanics":
        raise AutolevModelError(f"the mechanics level does not take this model: {why} "
                                "(--level equations writes its equations)")
    return SympyExport(EquationsScript(eqs, source, why).text(), lacking, eqs.command)


def mechanics_handoff(model, command, eqs: Equations) -> tuple[str | None, Handoff | None]:
    """(None, the hand-off) when the mechanics level takes the command's equations, else
    (why not, None)."""
    if command.kind.upper() != "DYNAMICS":
        return f"CODE {command.kind.upper()} integrates equations of its own, not Kane's", None
    speeds = len(model.speeds) + len(model.dependent_speeds)
    if speeds > MOST_SPEEDS:
        return (f"it has {speeds} speeds, more than the {MOST_SPEEDS} sympy's "
                "KanesMethod forms in reasonable time"), None
    extra = set(eqs.states) - set(model.coordinates) - set(model.speeds)
    if extra:
        return ("its state has " + ", ".join(sorted(s.name for s in extra))
                + " beyond the coordinates and speeds"), None
    fixed = set(model.speeds) - set(eqs.states)
    if fixed:
        return ("it defines " + ", ".join(sorted(s.name for s in fixed)) + ", which "
                "KanesMethod would take as speeds and the run does not integrate"), None
    try:
        h = handoff(model, set(eqs.states))
    except AutolevModelError as exc:
        return str(exc), None
    try:
        why = _unlike_the_run(h, eqs)
    except NoRealValue as exc:
        why = f"the check of sympy's equations against the run's found no value ({exc})"
    if why is None:
        return None, h
    statements = model.loaded.statements_at if model.loaded is not None else {}
    defined = [at for (what, _), ats in statements.items() if what == "acceleration"
               for at in ats]
    if defined:
        # MAE-223's bicycles: ALF_B_A> = DT(W_B_A>, N), a derivative in N, not in A
        why += ("; the model defines accelerations of its own, which KanesMethod derives "
                "from the velocities instead (" + "; ".join(defined[:3])
                + ("; ..." if len(defined) > 3 else "") + ")")
    return why, None


def _unlike_the_run(h: Handoff, eqs: Equations) -> str | None:
    """Why sympy's equations are not the run's, found at a random state, constants and
    values of the specified quantities and their rates; None when they give its rates."""
    rng = np.random.default_rng(33)
    ours = {x: v for x, v in zip(eqs.states, rng.uniform(-1, 1, len(eqs.states)))}
    ours |= {c: v for c, v in zip(eqs.constants, rng.uniform(0.5, 1.5, len(eqs.constants)))}
    given = rng.uniform(-1, 1, len(eqs.specified))
    ours |= {s: v for s, v in zip(eqs.specified, given)} | {S.TIME: 0.3}

    def unknown(e):
        raise LookupError(f"the check of sympy's equations has no value for {e}")
    run = ValuesAt(ours, unknown)
    before, _ = split_at_the_unknowns(eqs)
    for z, e in before:
        run.define(z, e)
    n = len(eqs.unknowns)
    mass = np.array([[run(e) for e in row] for row in eqs.mass]).reshape(n, n)
    forcing = np.array([run(e) for e in eqs.forcing])
    solved = dict(zip(eqs.unknowns, np.linalg.solve(mass, forcing) if n else []))
    rates = np.array([run(r) if r is not None else
                      solved[next(u for u in eqs.unknowns if state_of(u) == x)]
                      for x, r in zip(eqs.states, eqs.rates)])
    theirs = {h.states[x]: ours[x] for x in eqs.states}
    theirs |= {sm.Symbol(c.name): ours[c] for c in eqs.constants}
    theirs |= {h.specified_of(s): ours[s] for s in eqs.specified}
    at = {k: sm.Float(v) for k, v in theirs.items()} | {me.dynamicsymbols._t: sm.Float(0.3)}
    theirs |= {u: float(v) for u, v in h.dependent_speeds_at(at).items()}
    theirs[me.dynamicsymbols._t] = 0.3
    kept: set = set()

    def zero_or_kept(e):
        # a rate or a function of time the state does not give is 0; a symbol is a
        # constant sympy's equations have and the run's do not
        if isinstance(e, (sm.Derivative, AppliedUndef)):
            return 0.0
        kept.add(e)
        return 0.0
    sympy_at = ValuesAt(theirs, zero_or_kept)
    full = np.array([[sympy_at(e) for e in row] for row in
                     sm.Matrix.hstack(h.kane.mass_matrix_full, h.kane.forcing_full).tolist()])
    if kept:
        return ("sympy's equations keep constants the run's do not have ("
                + ", ".join(sorted(str(c) for c in kept)) + ")")
    order = [(h.coordinates + h.speeds + h.dependent).index(h.states[x]) for x in eqs.states]
    sympys = np.linalg.solve(full[:, :-1], full[:, -1])[order]
    if np.all(np.abs(sympys - rates) <= 1e-8 * max(1.0, float(np.abs(rates).max()))):
        return None
    return ("sympy's KanesMethod on the model's bodies and loads does not give the "
            "equations the run integrates (they are not FR() + FRSTAR() alone)")
