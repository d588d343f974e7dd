"""One revision for everything derived from a model (issue 30, item 2): every kind of
change bumps it, and every cache derived from the model is keyed on it alone."""
import pytest
import sympy as sm

import autolev
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
