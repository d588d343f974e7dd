"""A model handed over to sympy.physics.mechanics (and PyDy): its frames oriented as the
model orients them, its points with their velocities, its particles and rigid bodies
with masses and central inertias, its loads, the kinematical differential equations,
and a KanesMethod with Kane's equations formed by sympy itself.

Everything is plain sympy: variables become dynamicsymbols, constants plain symbols of
their names (`sm.Symbol('K')` is the model's K), every definition and Z is expanded
(interop.py) but those of the dependent and auxiliary speeds and of KANE's unknowns,
which stay sympy's: CONSTRAIN(DEPENDENT[...]) becomes KanesMethod's u_dependent and
velocity_constraints (the equations as the model gives them), CONSTRAIN(AUXILIARY[...])
its u_auxiliary, whose equations (`kane.auxiliary_eqs`) give KANE's unknowns.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sm

from . import symbols as S
from ..engine.errors import AutolevModelError
from .interop import dynamic_map, to_sympy_expr, to_sympy_frame, to_sympy_vector

# the dependent speeds solved from the velocity constraints by Cramer's rule: sympy's
# default LU divides by pivots that vanish at some states (0/0 at the upright Whipple
# bicycle, whose constraint matrix is regular there)
CONSTRAINT_SOLVER = "CRAMER"


@dataclass
class Handoff:
    """The model as sympy.physics.mechanics objects; `kane` has its equations formed."""

    newtonian: object           # the Newtonian ReferenceFrame
    frames: dict                # name -> ReferenceFrame
    # (parent, child, parent.dcm(child), angular velocity or None), parents first
    orientations: list
    points: dict                # name -> Point (those with a mass, a load or a position)
    velocities: dict            # name -> velocity in N (the points of masses and loads)
    # (point, from, position vector): the points located from the Newtonian origin
    positions: list
    bodies: list                # Particle and RigidBody objects
    loads: list                 # (Point, force) and (ReferenceFrame, torque)
    coordinates: list           # dynamicsymbols
    speeds: list                # dynamicsymbols
    kinematical_equations: list  # q' - f(q, u), each 0
    kane: object                # KanesMethod, kanes_equations done
    dependent: list             # dynamicsymbols of the dependent speeds
    velocity_constraints: list  # each = 0, linear in the speeds (the model's CONSTRAINs)
    auxiliary: list             # dynamicsymbols of the auxiliary speeds
    unknowns: list              # dynamicsymbols of KANE's unknowns (noncontributing forces)
    specified: list             # dynamicsymbols of the specified quantities
    constants: list             # the constants as plain symbols, in declaration order
    states: dict                # the model's coordinate or speed -> its dynamicsymbol

    def motion(self):
        """A KanesMethod of the motion alone: `kane` without the auxiliary speeds (zero in
        motion, read by its velocity constraints), for what integrates (PyDy)."""
        import sympy.physics.mechanics as me
        if not self.auxiliary:
            return self.kane
        time = me.dynamicsymbols._t
        zero = dict.fromkeys(self.auxiliary, 0)
        derivatives = {u.diff(time): 0 for u in self.auxiliary}
        return kanes_method(self.newtonian, self.coordinates, self.speeds,
                            self.kinematical_equations, self.dependent,
                            [c.xreplace(derivatives).xreplace(zero)
                             for c in self.velocity_constraints], [], self.bodies, self.loads)

    def specified_of(self, quantity):
        """The sympy counterpart of the model's specified quantity or of one of its rates
        (PX'' is px(t).diff(t, 2)); AutolevModelError when the model specifies no such
        quantity."""
        import sympy.physics.mechanics as me
        base, order = S.base_and_order(quantity)
        found = [s for s in self.specified if str(s.func) == base.name]
        if not found:
            raise AutolevModelError(f"the mechanics level has no specified quantity "
                                    f"{base.name}")
        return found[0].diff(me.dynamicsymbols._t, order) if order else found[0]

    def dependent_speeds_at(self, values: dict) -> dict:
        """{dependent speed: its value} where the velocity constraints hold, at `values`
        ({dynamicsymbol or constant: number}: the coordinates, independent speeds,
        constants, specified quantities and time); the auxiliary speeds are 0."""
        if not self.dependent:
            return {}
        at = values | {u: 0 for u in self.auxiliary}
        rates = self.kane.kindiffdict()
        coefficients, rest = sm.linear_eq_to_matrix(
            [c.subs(rates) for c in self.velocity_constraints], self.dependent)
        solved = np.linalg.solve(np.array(coefficients.xreplace(at), dtype=float),
                                 np.array(rest.xreplace(at), dtype=float).ravel())
        return dict(zip(self.dependent, solved))


def _dyadic(model, dyadic, made: dict, mapping: dict, keep: frozenset):
    """A sympy dyadic equal to the model's: sum m_ij a_i|b_j over its frame pairs."""
    import sympy.physics.mechanics as me
    total = me.Dyadic(0)
    for (fa, fb), m in dyadic.terms.items():
        unoriented = [f.name for f in dict.fromkeys((fa, fb)) if f not in made]
        if unoriented:
            raise AutolevModelError(f"an inertia is given in frame {' and '.join(unoriented)}"
                                    ", not oriented in the Newtonian frame")
        sa, sb = made[fa], made[fb]
        units_a, units_b = (sa.x, sa.y, sa.z), (sb.x, sb.y, sb.z)
        for i in range(3):
            for j in range(3):
                value = to_sympy_expr(model.scene, m[i, j], mapping, keep)
                if value != 0:
                    total += value * (units_a[i] | units_b[j])
    return total


def _frames(model, mapping: dict, orientations: list, keep: frozenset) -> dict:
    """Every frame oriented, through others, in the Newtonian one: {Frame: its sympy
    ReferenceFrame}, made with `mapping` (one tree of orientations from N, its edges
    appended to `orientations`)."""
    made: dict = {}
    to_sympy_frame(model.newtonian_frame, mapping, made, orientations, keep)
    return made


def handoff(model, integrated=None) -> Handoff:
    """The model as sympy.physics.mechanics objects, Kane's equations formed by sympy's
    KanesMethod (AutolevModelError for what it does not take: an auxiliary speed not
    zero in motion, a body or load in a frame not oriented in the Newtonian frame).
    `integrated`: the variables a CODE command integrates (its state), when the
    hand-off is of that command; the coordinates are those among them.  A variable the
    model defines (Q4 = 0, a prescribed joint angle) is no coordinate (Model.coordinates):
    its definition enters the orientations and positions, as in a run."""
    import sympy.physics.mechanics as me
    if model.newtonian_frame is None:
        raise AutolevModelError("the mechanics hand-off needs a NEWTONIAN frame")
    keep = _kept(model)
    mapping = dynamic_map(model.scene)
    free = [q for q in model.coordinates if integrated is None or q in integrated]
    # a variable nothing defines is a constant of the run (its value from INPUT), and here
    unset = _undefined_variables(model, keep, set(free) | set(model.speeds))
    mapping |= {v: sm.Symbol(v.name) for v in unset}
    orientations: list = []
    made = _frames(model, mapping, orientations, keep)
    frames = {f.name: sf for f, sf in made.items()}
    n_frame = model.newtonian_frame
    newtonian = made[n_frame]

    def frame_of(f):
        if f not in made:
            raise AutolevModelError(f"frame {f.name} is not oriented in the Newtonian "
                                    f"frame {n_frame.name}")
        return made[f]

    def vector(v):
        for f in v.terms:
            frame_of(f)
        return to_sympy_vector(v, frames=made, mapping=mapping, keep=keep)
    points: dict = {}
    velocities: dict = {}

    def sympy_point(p):
        if p.name not in points:
            points[p.name] = me.Point(p.name)
        return points[p.name]

    def point_of(p):
        """The point with its velocity in N."""
        if p.name not in velocities:
            velocities[p.name] = vector(p.vel(n_frame))
            sympy_point(p).set_vel(newtonian, velocities[p.name])
        return points[p.name]
    bodies = []
    for particle in model.particles_list:
        if particle.mass is None:
            raise AutolevModelError(f"the mass of particle {particle.name} is not given")
        bodies.append(me.Particle(particle.name, point_of(particle.point),
                                  to_sympy_expr(model.scene, particle.mass, mapping, keep)))
    for body in model.bodies_list:
        inertia = _dyadic(model, body.central_inertia, made, mapping, keep)
        bodies.append(me.RigidBody(body.name, point_of(body.masscenter), frame_of(body),
                                   to_sympy_expr(model.scene, body.mass_checked(), mapping,
                                                 keep),
                                   (inertia, point_of(body.masscenter))))
    loads = [(point_of(p), vector(v)) for p, v in model.forces.items()]
    loads += [(frame_of(f), vector(v)) for f, v in model.torques.items()]
    positions = _positions(n_frame, made, mapping, sympy_point, keep)
    coordinates = [mapping[q] for q in free]
    speeds, kinematics = [], []
    kin = model.kinematical_equations
    time = me.dynamicsymbols._t
    for u in model.speeds:
        base, order = S.base_and_order(u)
        # a speed that is a coordinate's rate (Q'' declared): a speed of its own in sympy
        speeds.append(me.dynamicsymbols(f"{base.name}_rate") if order else mapping[u])
    for q in free:
        rate = kin[S.derivative(q)]
        if rate in model.speeds:
            rate_expr = speeds[model.speeds.index(rate)]
        else:
            rate_expr = to_sympy_expr(model.scene, rate, mapping, keep)
        kinematics.append(mapping[q].diff(time) - rate_expr)
    dependent = [mapping[u] for u in model.dependent_speeds]
    _linear_in_speeds(free, kinematics, speeds + dependent)
    constraints = [to_sympy_expr(model.scene, e, mapping, keep)
                   for e in model.dependent_constraints]
    auxiliary = [mapping[u] for u in model.auxiliary_speeds]
    kane = kanes_method(newtonian, coordinates, speeds, kinematics, dependent, constraints,
                        auxiliary, bodies, loads)
    unknowns = [mapping[f] for f in model.kane_equations.unknowns] \
        if model.kane_equations is not None else []
    specified = [mapping[s] for s, info in model.info.items()
                 if info.kind == "specified" and not S.base_and_order(s)[1]]
    constants = [mapping[c] for c, info in model.info.items()
                 if info.kind == "constant" or c in unset]
    states = {q: mapping[q] for q in free} | dict(zip(model.speeds, speeds))
    return Handoff(newtonian, frames, orientations, points, velocities, positions, bodies, loads,
                   coordinates, speeds, kinematics, kane, dependent, constraints, auxiliary,
                   unknowns, specified, constants, states)


def kanes_method(newtonian, coordinates: list, speeds: list, kinematics: list,
                 dependent: list, constraints: list, auxiliary: list, bodies: list,
                 loads: list):
    """sympy's KanesMethod of these, its equations formed."""
    import sympy.physics.mechanics as me
    kane = me.KanesMethod(newtonian, q_ind=coordinates, u_ind=speeds, kd_eqs=kinematics,
                          u_dependent=dependent, velocity_constraints=constraints,
                          u_auxiliary=auxiliary, constraint_solver=CONSTRAINT_SOLVER)
    kane.kanes_equations(bodies, loads)
    return kane


def _linear_in_speeds(coordinates: list, kinematics: list, speeds: list) -> None:
    """AutolevModelError unless each kinematical equation is linear in the speeds, as
    KanesMethod takes them."""
    for q, equation in zip(coordinates, kinematics):
        if any(equation.diff(u).has(*speeds) for u in speeds):
            raise AutolevModelError(f"the kinematical equation of {q.name}' is not linear in "
                                    "the speeds, as sympy's KanesMethod takes them")


def _undefined_variables(model, keep: frozenset, states: set) -> list:
    """The VARIABLES that are neither defined, nor in `states` (the coordinates and
    speeds), nor kept by the hand-off: what a run takes as constants."""
    return [v for v, info in model.info.items()
            if info.kind == "variable" and not S.base_and_order(v)[1] and v not in states
            and v not in keep and v not in model.defs.rhs]


def _kept(model) -> frozenset:
    """The symbols whose definitions the hand-off keeps as sympy's own: the dependent and
    auxiliary speeds (with their derivatives) and KANE's unknowns."""
    constrained = model.dependent_speeds + model.auxiliary_speeds
    for u in constrained:
        if S.base_and_order(u)[1]:
            raise AutolevModelError(f"the dependent or auxiliary speed {u} is a "
                                    "coordinate's rate, which KanesMethod's speeds are not")
    for u in model.auxiliary_speeds:
        if model.defs.explicit(u) != 0:
            raise AutolevModelError(f"the auxiliary speed {u} is {model.defs.explicit(u)} in "
                                    "motion; KanesMethod's auxiliary speeds are zero")
    unknowns = model.kane_equations.unknowns if model.kane_equations is not None else []
    return frozenset(constrained + [S.derivative(u, k) for u in constrained for k in (1, 2)]
                     + list(unknowns))


def _positions(n_frame, made: dict, mapping: dict, sympy_point, keep: frozenset) -> list:
    """Each point the model locates from the Newtonian origin, through others, with its
    position from the point it was located from: one tree, as sympy points
    (`sympy_point`) with set_pos; a position in a frame not oriented in N is left out
    with the points located from it."""
    origin = n_frame.declared_origin
    if origin is None:
        return []
    positions, seen, todo = [], {origin}, [origin]
    while todo:
        p = todo.pop(0)
        for other in p.linked_points():
            value = other.pos_from(p)
            if other in seen or any(f not in made for f in value.terms):
                continue
            seen.add(other)
            vector = to_sympy_vector(value, frames=made, mapping=mapping, keep=keep)
            sympy_point(other).set_pos(sympy_point(p), vector)
            positions.append((sympy_point(other), sympy_point(p), vector))
            todo.append(other)
    return positions


def to_pydy(model, infile=None, overrides=None):
    """A pydy.system.System of the model (PyDy is an optional extra): sympy's
    KanesMethod of `handoff`; the constants and initial conditions a run of its first
    CODE DYNAMICS takes (INPUT, then the .in file `infile`, then `overrides` in the
    quantities' units: AutolevModelError naming those without a value), the dependent
    speeds' where the velocity constraints hold; specified quantities 0; times from
    TINITIAL to TFINAL as a run prints them (every PRINTINT-th step of INTEGSTP), the
    integration parameters refused as a run refuses them."""
    try:
        from pydy.system import System
    except ImportError:
        raise ImportError("Model.to_pydy needs PyDy (pip install pydy)") from None
    import sympy.physics.mechanics as me

    eqs, h, constants = _with_values(model, infile, overrides)
    run = eqs.integration
    times = _printed_times(run, len(eqs.states))
    initial = {h.states[x]: v for x, v in eqs.initial.items() if x in h.states}
    at_start = constants | initial | {s: 0.0 for s in h.specified} | {
        me.dynamicsymbols._t: run["TINITIAL"]}
    initial |= h.dependent_speeds_at(at_start)
    return System(h.motion(), constants=constants,
                  specifieds={s: 0.0 for s in h.specified} or None,
                  initial_conditions=initial, times=times)


def _with_values(model, infile, overrides) -> tuple:
    """(the equations of the command a run integrates, with its values; the Handoff of
    its state; {constant as a plain symbol: value})."""
    from .equations_of import equations_of
    eqs = equations_of(model, model.command_to_linearize(), infile=infile,
                      overrides=overrides)
    return (eqs, handoff(model, set(eqs.states)),
            {sm.Symbol(c.name): v for c, v in eqs.constants.items()})


def _printed_times(run: dict, states: int) -> np.ndarray:
    """The times a run of these integration parameters prints."""
    from ..engine.files import check_memory
    from ..engine.integrate import Schedule
    schedule = Schedule(run["TINITIAL"], run["TFINAL"], run["INTEGSTP"], run["PRINTINT"])
    try:
        schedule.check()
    except ValueError as exc:
        raise AutolevModelError(str(exc)) from None
    check_memory(schedule.printed_rows(), states + 1)
    return np.concatenate([[run["TINITIAL"]]] + list(schedule.print_blocks()))


@dataclass
class OptyParts:
    """What opty's direct collocation (opty.Problem) takes of a model, from
    to_mechanics()'s KanesMethod: `equations_of_motion` (each 0 on the motion: the
    kinematical equations, then M u' - F, in the states and their time derivatives),
    `states` (the coordinates, then the speeds), `controls` (the specified quantities:
    opty's unknown trajectories unless given), `parameters` ({constant: value}: opty's
    known_parameter_map) and `time` (the time symbol)."""

    equations_of_motion: sm.Matrix
    states: list
    controls: list
    parameters: dict
    time: object


def to_opty(model, infile=None, overrides=None, controls=None) -> OptyParts:
    """The model's equations of motion as opty takes them (see OptyParts), with the
    constants' values a run of its first CODE DYNAMICS takes.  `controls`: names of the
    controls, specified quantities or constants (as Model.dynamics takes them; a
    constant named becomes a trajectory of its own and needs no value); default: the
    specified quantities.  A model with dependent or auxiliary speeds is refused: opty
    integrates ordinary differential equations in the state."""
    import sympy.physics.mechanics as me

    from .numerics.command import with_controls_given

    varying = [str(name) for name in controls or ()]
    given = with_controls_given(model.snapshot_for(model.command_to_linearize()), varying,
                                overrides)
    _, h, constants = _with_values(model, infile, given or None)
    if h.dependent or h.auxiliary:
        raise AutolevModelError("opty integrates ordinary differential equations in the "
                                "state: this model has dependent or auxiliary speeds ("
                                + ", ".join(str(u.func) for u in h.dependent + h.auxiliary)
                                + ")")
    time = me.dynamicsymbols._t
    states = list(h.coordinates) + list(h.speeds)
    rates = sm.Matrix([x.diff(time) for x in states])
    kane = h.kane
    equations = kane.mass_matrix_full * rates - kane.forcing_full
    if controls is None:
        return OptyParts(equations, states, list(h.specified), constants, time)
    specified = {str(s.func).upper(): s for s in h.specified}
    by_name = {str(c).upper(): c for c in constants}
    chosen, made = [], {}
    for name in varying:
        if name.upper() in specified:
            chosen.append(specified[name.upper()])
        elif name.upper() in by_name:
            made[by_name[name.upper()]] = sm.Function(str(by_name[name.upper()]))(time)
            chosen.append(made[by_name[name.upper()]])
        else:
            raise AutolevModelError(
                f"controls: {name!r} is not a specified quantity or a constant of the "
                "equations (its specified quantities: "
                + (", ".join(str(s.func) for s in h.specified) or "none") + ")")
    return OptyParts(equations.xreplace(made), states, chosen,
                     {c: v for c, v in constants.items() if c not in made}, time)
