"""One revision for everything derived from a model (issue 30, item 2): every kind of
change bumps it, and every cache derived from the model is keyed on it alone."""
import pytest
import sympy as sm

import autolev
from autolev.engine.errors import AutolevModelError
import autolev.runtime.model  # noqa: F401  (its modules' mutations, listed at import)
from autolev.runtime.constraints import SolvedRates
from autolev.runtime.derived import MUTATIONS
from helpers import EXAMPLES


@pytest.fixture
def model():
    return autolev.load(EXAMPLES / "double_pendulum.al")


def changes(m):
    """One of each kind of change a statement or a caller makes."""
    n, a = m.entity("N"), m.entity("A")
    p1 = m.entity("P1")
    q1 = m.quantity("Q1")
    l1 = m.quantity("L1")
    return {
        "a declaration": lambda: m.constants("EXTRA"),
        "a definition": lambda: m.define(m.variables("W"), 2 * q1),
        "an INPUT": lambda: m.input(l1, 3),
        "an OUTPUT": lambda: m.output((q1, "Q1", None)),
        "UNITS": lambda: m.units(l1, "m"),
        "UNITSYSTEM": lambda: m.unit_system("kg", "m", "s"),
        "ENCODE": lambda: m.encode(("X", q1)),
        "a CODE": lambda: m.code("dynamics", "again.c"),
        "a setting": lambda: m.setting("AUTOZ", "ON"),
        "ZEE_NOT": lambda: m.zee_not([q1]),
        "a force": lambda: m.add_force(p1, l1 * n.x),
        "a torque": lambda: m.add_torque(a, l1 * n.z),
        "a position": lambda: p1.set_pos(m.entity("NO"), 2 * l1 * a.x),
        "an orientation": lambda: a.orient_axis(n, 3, 2 * q1),
        "a mass": lambda: setattr(p1, "mass", 2 * l1),
        "KANE()": lambda: m.kane(),
    }


def test_every_kind_of_change_bumps_the_revision(model):
    for what, change in changes(model).items():
        before = model.revision()
        change()
        assert model.revision() != before, what


def test_every_derived_cache_is_dropped_by_a_change(model):
    # a numeric system, a CODE DYNAMICS of the model as it stands, sympy's frames and
    # Kane's equations formed now
    r = model.simulate(TFINAL=0.1)
    assert r.ok and model.derived.table("numeric systems")
    plain = model.plain_dynamics()
    frame = model.entity("A").to_sympy()
    formed = model.fr()
    model.input(model.quantity("L1"), 2)
    assert model.derived.table("numeric systems") == {}
    assert model.derived.table("sympy frames") == {}
    assert model.plain_dynamics() is not plain
    assert model.entity("A").to_sympy() is not frame
    assert model.fr() is not formed


def test_asking_for_the_equations_changes_nothing(model):
    before = model.revision()
    model.equations(), model.mass_matrix, model.forcing
    assert model.revision() == before
    assert sm.Matrix(model.mass_matrix).shape == (2, 2)


def mutations(m):
    """One call of each method marked `mutation` (derived.MUTATIONS), by its name."""
    n, a = m.entity("N"), m.entity("A")
    p1 = m.entity("P1")
    q1, u1, l1 = m.quantity("Q1"), m.quantity("U1"), m.quantity("L1")

    def body():
        return m.body("C")

    def frame():
        return m.frame("F")
    return {
        "Registry.set_newtonian": lambda: m.newtonian("G"),
        "Registry.add_frame": frame,
        "Registry.add_body": body,
        "Registry.add_point": lambda: m.point("R"),
        "Registry.add_particle": lambda: m.particle("S"),
        "Model._declare": lambda: m.constants("EXTRA"),
        "Model.define": lambda: m.define(m.variables("W"), 2 * q1),
        "Loads.add_force": lambda: m.add_force(p1, l1 * n.x),
        "Loads.set_force": lambda: m.set_force(p1, l1 * n.y),
        "Loads.add_torque": lambda: m.add_torque(a, l1 * n.z),
        "Loads.set_torque": lambda: m.set_torque(a, 2 * l1 * n.z),
        "Loads.gravity": lambda: m.gravity(l1 * n.x),
        "Constraints.add_dependent": lambda: m.constrain([m.quantity("U2") - u1],
                                                         [m.quantity("U2")]),
        "Constraints.add_auxiliary": lambda: m.constrain_auxiliary(
            [m.motion_variables("UA")], [m.quantity("UA")]),
        "Constraints.add_solved_rates": lambda: m.constraints.add_solved_rates(
            SolvedRates((), (), ())),
        "Constraints.keep_speeds": lambda: m._keep_speeds([sm.Symbol("U1'")]),
        "FormedEquations.take": lambda: m.kane(),
        "AlgebraMixin.zee_not": lambda: m.zee_not([q1]),
        "AlgebraMixin.setting": lambda: m.setting("AUTOZ", "ON"),
        "AlgebraMixin.nicheck": lambda: m.nicheck(),
        "IOStatements.input": lambda: m.input(l1, 3),
        "IOStatements.input_unless_given": lambda: m.io.input_unless_given(l1, 3),
        "IOStatements.output": lambda: m.output((q1, "Q1", None)),
        "IOStatements.units": lambda: m.units(l1, "m"),
        "IOStatements.unit_system": lambda: m.unit_system("kg", "m", "s"),
        "IOStatements.encode": lambda: m.encode(("X", q1)),
        "IOStatements.code": lambda: m.code("dynamics", "again.c"),
        "Frame.orient_dcm": lambda: frame().orient_dcm(n, sm.eye(3)),
        "Frame.orient_euler_parameters": lambda: frame().orient_euler_parameters(
            n, *m.variables("E1", "E2", "E3", "E4")),
        "Frame.origin": lambda: setattr(a, "origin", p1),
        "Frame.set_ang_vel": lambda: a.set_ang_vel(n, 2 * u1 * n.z),
        "Frame.set_ang_acc": lambda: a.set_ang_acc(n, l1 * n.z),
        "Point.set_pos": lambda: p1.set_pos(m.entity("NO"), 2 * l1 * a.x),
        "Point.set_vel": lambda: p1.set_vel(n, l1 * a.y),
        "Point.set_acc": lambda: p1.set_acc(n, l1 * a.x),
        "_mass_property.<locals>.give": lambda: setattr(p1, "mass", 2 * l1),
        "Body.set_inertia": lambda: body().set_inertia(1, 2, 3),
        "Body.set_inertia_dyadic": lambda: body().set_inertia_dyadic(m.unit_dyadic()),
    }


def test_every_mutation_has_its_call_here(model):
    assert set(mutations(model)) == {f.__qualname__ for f in MUTATIONS}


@pytest.mark.parametrize("name", sorted({f.__qualname__ for f in MUTATIONS}))
def test_every_mutation_bumps_the_revision_and_drops_what_was_derived(model, name):
    change = mutations(model)[name]
    if name != "Model.newtonian":    # (made before a change: the change itself may ask)
        model.fr()
    model.derived.table("kept")["answer"] = 42
    before = model.revision()
    change()
    assert model.revision() != before
    assert model.derived.table("kept") == {}


def test_a_mutation_that_fails_partway_still_bumps_the_revision(model):
    # GRAVITY adds m g> to P1, then finds P2 without a mass: P1's force is a change
    model.entity("P2")._mass = None
    before = model.revision()
    with pytest.raises(AutolevModelError):
        model.gravity(model.quantity("G") * model.entity("N").x)
    assert model.revision() != before


def test_an_angular_velocity_assigned_later_changes_a_derived_acceleration(model):
    # A_R_N> is DT(V_R_N>, N), which W_A_N> enters (V_R_N> is in A's basis): it was kept
    # past a new W_A_N>, which changed no revision
    n, a, r = model.entity("N"), model.entity("A"), model.point("R")
    r.set_vel(n, model.quantity("L1") * model.quantity("U1") * a.y)
    early = r.acc(n)
    a.set_ang_vel(n, 2 * model.quantity("U1") * n.z)
    assert r.acc(n) != early
    assert r.acc(n) == r.vel(n).dt(n)


def test_what_the_parts_hold_changes_only_through_their_methods(model):
    # a read-only mapping, or a copy: no change can skip the revision
    with pytest.raises(TypeError):
        model.forces[model.entity("P1")] = model.entity("N").x
    with pytest.raises(TypeError):
        model.inputs[model.quantity("L1")] = (2, None)
    model.particles_list.clear()
    model.code_commands.clear()
    assert len(model.particles_list) == 2 and len(model.code_commands) == 1
