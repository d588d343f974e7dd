"""CONSTRAIN(AUXILIARY[U2]) on a speed the motion has (docs/language.md, "Auxiliary
speeds"): the run integrates the motion the constraint allows, U2 solved from it, and
KANE(FY) gives the constraint's force; checked against sympy's KanesMethod of the
unconstrained system with the constraint's multiplier, built here from scratch."""
import numpy as np
import pytest
import sympy as sm
import sympy.physics.mechanics as me

import autolev
from autolev.runtime.numerics.prepare import prepare_command
from helpers import ROOT

SLING = ROOT / "tests" / "data" / "equations" / "sling.al"
VALUES = dict(LA=1.0, LS=0.8, MA=2.0, IA=0.5, MP=0.3, G=9.81)


def _by_lagrange_multiplier():
    """(rates, force) as functions of (q1, q2, u1): the two-speed system's Kane
    equations M u' = f + J^T FY with the constraint J u = 0 (J = d(v_P.N2)/du)
    differentiated, solved for u' and FY."""
    q1, q2, u1, u2 = me.dynamicsymbols("q1 q2 u1 u2")
    la, ls, ma, ia, mp, g, fy = sm.symbols("LA LS MA IA MP G FY")
    n = me.ReferenceFrame("N")
    a = n.orientnew("A", "Axis", (q1, n.z))
    s = a.orientnew("S", "Axis", (q2, a.z))
    a.set_ang_vel(n, u1 * n.z)
    s.set_ang_vel(a, u2 * a.z)
    o = me.Point("O")
    o.set_vel(n, 0)
    ao = o.locatenew("AO", la / 2 * a.y)
    p = o.locatenew("P", la * a.y + ls * s.y)
    ao.v2pt_theory(o, n, a)
    p.set_vel(n, p.pos_from(o).dt(n).subs({q1.diff(): u1, q2.diff(): u2}))
    arm = me.RigidBody("arm", ao, a, ma, (me.inertia(a, ia, ia, ia), ao))
    bob = me.Particle("bob", p, mp)
    loads = [(ao, -ma * g * n.y), (p, -mp * g * n.y + fy * n.y)]
    kane = me.KanesMethod(n, [q1, q2], [u1, u2], kd_eqs=[q1.diff() - u1, q2.diff() - u2])
    kane.kanes_equations([arm, bob], loads)
    mass, forcing = kane.mass_matrix, kane.forcing
    constraint = p.vel(n).dot(n.y)
    jac = sm.Matrix([[constraint.diff(u1), constraint.diff(u2)]])
    # J u' + dJ/dt u = 0 with u2 from J u = 0
    drift = (jac.diff(me.dynamicsymbols._t) * sm.Matrix([u1, u2]))[0].subs(
        {q1.diff(): u1, q2.diff(): u2})
    f_free = forcing.subs(fy, 0)
    f_force = forcing.diff(fy)
    system = sm.Matrix.vstack(sm.Matrix.hstack(mass, -f_force),
                              sm.Matrix.hstack(jac, sm.zeros(1, 1)))
    rhs = sm.Matrix.vstack(f_free, sm.Matrix([-drift]))
    consts = {sm.Symbol(k): v for k, v in VALUES.items()}
    u2_of = sm.solve(constraint, u2)[0]

    def at(x):
        state = {q1: x[0], q2: x[1], u1: x[2]}
        state[u2] = u2_of.subs(consts).subs(state)
        m = np.array(system.subs(consts).subs(state), dtype=float)
        r = np.array(rhs.subs(consts).subs(state), dtype=float).ravel()
        u1d, _, force = np.linalg.solve(m, r)
        return np.array([x[2], float(state[u2]), u1d]), force
    return at


@pytest.fixture(scope="module")
def oracle():
    return _by_lagrange_multiplier()


def test_the_run_integrates_the_motion_the_auxiliary_constraint_allows(oracle):
    # the run held U2 at 0 (Q2' = 0, P left the line); Autolev solved U2 from it
    model = autolev.load(SLING)
    command = model.code_commands[0]
    system = prepare_command(model.snapshot_for(command), command).system
    assert [str(x) for x in system.states] == ["Q1", "Q2", "U1"]
    rng = np.random.default_rng(3)
    for x in [np.array([0.4, 2.2, 0.7])] + [rng.uniform([0, 1.8, -1], [0.8, 2.6, 1])
                                             for _ in range(4)]:
        expected, _ = oracle(x)
        assert np.allclose(system.derivatives(0.0, x), expected, rtol=1e-9, atol=1e-12)


def test_kane_brings_the_constraint_force_into_evidence(oracle, tmp_path):
    model = autolev.load(SLING)
    result = model.simulate(out_dir=tmp_path)
    table = result.outputs[0]
    for k in (0, len(table["T"]) // 2, len(table["T"]) - 1):
        x = np.array([table["Q1"][k], table["Q2"][k], table["U1"][k]])
        assert abs(table["FY"][k] - oracle(x)[1]) <= 1e-7 * max(1.0, abs(oracle(x)[1]))
    # P stays on its line: its height LA cos Q1 + LS cos(Q1 + Q2) keeps its first value
    height = VALUES["LA"] * np.cos(table["Q1"]) + VALUES["LS"] * np.cos(table["Q1"]
                                                                        + table["Q2"])
    assert np.ptp(height) < 1e-6
    assert np.ptp(table["Q2"]) > 0.1                      # the sling turns
