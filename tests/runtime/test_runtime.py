"""The runtime's Autolev semantics against sympy.physics.mechanics and by hand."""
import random

import pytest
import sympy as sm
import sympy.physics.mechanics as me

import autolev.runtime as al
from autolev.runtime.calculus import NumericPoint
from autolev.runtime.frame import rodrigues


def num(model, expr, values):
    point = NumericPoint(model.defs, values)
    if isinstance(expr, sm.MatrixBase):
        return sm.Matrix(expr.shape[0], expr.shape[1],
                         lambda i, j: model.defs.numeric(expr[i, j], point).real)
    return model.defs.numeric(expr, point).real


def close(a, b, tol=1e-10):
    a, b = sm.Matrix(a), sm.Matrix(b)
    return a.shape == b.shape and all(abs(float(x) - float(y)) < tol for x, y in zip(a, b))


t = me.dynamicsymbols._t


@pytest.fixture
def m():
    return al.Model("test")


# -- orientation ------------------------------------------------------------------------
@pytest.mark.parametrize("axis", [1, 2, 3, -1, -2, -3])
def test_simprot_dcm_and_angular_velocity(m, axis):
    N, A = m.frames("N A")
    q = m.variables("q", order=1)
    A.orient_axis(N, axis, q)
    sN = me.ReferenceFrame("N")
    qq = me.dynamicsymbols("q")
    unit = [sN.x, sN.y, sN.z][abs(axis) - 1] * (1 if axis > 0 else -1)
    sA = sN.orientnew("A", "Axis", (qq, unit))
    vals = {q: 0.73, al.derivative(q): -1.4}
    assert close(num(m, N.dcm(A), vals), sN.dcm(sA).subs({qq: 0.73}))
    w = A.ang_vel_in(N).components_in(N)
    assert close(num(m, sm.Matrix(w), vals),
                 sA.ang_vel_in(sN).to_matrix(sN).subs({qq.diff(t): -1.4, qq: 0.73}))


def test_simprot_about_a_vector_axis(m):
    N, A = m.frames("N A")
    q = m.variables("q", order=1)
    A.orient_axis(N, N.x + N.y, q)
    sN = me.ReferenceFrame("N")
    qq = me.dynamicsymbols("q")
    sA = sN.orientnew("A", "Axis", (qq, sN.x + sN.y))
    assert close(num(m, N.dcm(A), {q: 0.4}), sN.dcm(sA).subs(qq, 0.4))


@pytest.mark.parametrize("seq", ["123", "312", "212", "131"])
@pytest.mark.parametrize("kind", ["body", "space"])
def test_dircos_sequences_match_sympy(m, seq, kind):
    N, B = m.frames("N B")
    q = m.variables("q1 q2 q3", order=1)
    getattr(B, f"orient_{kind}_fixed")(N, q, seq)
    sN, sB = me.ReferenceFrame("N"), me.ReferenceFrame("B")
    qq = me.dynamicsymbols("q1:4")
    getattr(sB, f"orient_{kind}_fixed")(sN, qq, seq)
    rng = random.Random(1)
    vals = {s: rng.uniform(-1, 1) for s in q}
    vals.update({al.derivative(s): rng.uniform(-1, 1) for s in q})
    sub = {qq[i]: vals[q[i]] for i in range(3)}
    sub.update({qq[i].diff(t): vals[al.derivative(q[i])] for i in range(3)})
    assert close(num(m, N.dcm(B), vals), sN.dcm(sB).subs(sub))
    w = sm.Matrix(B.ang_vel_in(N).components_in(B))
    assert close(num(m, w, vals), sB.ang_vel_in(sN).to_matrix(sB).subs(sub))


def test_a_chain_of_orientations_composes_named_entries_to_sympys_matrix(m):
    # N -> A (Rodrigues), A -> B (body-fixed 213), B -> C (Rodrigues): the composed matrix
    # N_C equals sympy's, and each of its entries is a sum of products of named (Z) or
    # short entries: no orientation's long entry is written into a product
    from autolev.runtime.calculus import SMALL, is_small
    N, A, B, C = m.frames("N A B C")
    q = m.variables("q1 q2 q3 q4 q5", order=1)
    k = m.constants("k1 k2 k3")
    A.orient_rodrigues(N, *[sm.tan(q[0] / 2) * kk for kk in k])
    B.orient_body_fixed(A, q[1:4], "213")
    C.orient_rodrigues(B, *[sm.tan(q[4] / 2) * kk for kk in reversed(k)])
    sN, sA, sB, sC = (me.ReferenceFrame(n) for n in "NABC")
    qq = me.dynamicsymbols("q1:6")
    kv = [0.3, -0.5, 0.8]
    axis1 = sum((kk * e for kk, e in zip(kv, (sN.x, sN.y, sN.z))), sm.S.Zero * sN.x)
    axis2 = sum((kk * e for kk, e in zip(reversed(kv), (sB.x, sB.y, sB.z))), 0 * sB.x)
    # a Gibbs vector k tan(angle/2) turns by 2 atan(|k| tan(angle/2)) about k
    sA.orient_axis(sN, axis1, 2 * sm.atan(sm.sqrt(sum(v * v for v in kv)) * sm.tan(qq[0] / 2)))
    sB.orient_body_fixed(sA, qq[1:4], "213")
    sC.orient_axis(sB, axis2, 2 * sm.atan(sm.sqrt(sum(v * v for v in kv)) * sm.tan(qq[4] / 2)))
    values = dict(zip(q, [0.4, -0.7, 1.1, 0.25, -1.2])) | dict(zip(k, kv))
    composed = N.dcm(C)
    assert close(num(m, composed, values), sN.dcm(sC).subs(dict(zip(qq, [0.4, -0.7, 1.1, 0.25,
                                                                         -1.2]))))
    for entry in composed:
        rhs = m.defs.rhs.get(entry, entry)
        for term in sm.Add.make_args(rhs):
            assert all(is_small(f, SMALL) for f in sm.Mul.make_args(term)), term


def test_euler_parameters_match_sympys_quaternion_with_e4_scalar(m):
    N, B = m.frames("N B")
    e = m.variables("e1 e2 e3 e4", order=1)
    B.orient_euler_parameters(N, *e)
    sN, sB = me.ReferenceFrame("N"), me.ReferenceFrame("B")
    ee = me.dynamicsymbols("e1:5")
    sB.orient_quaternion(sN, (ee[3], ee[0], ee[1], ee[2]))
    raw = [0.3, -0.2, 0.5, 0.7]
    norm = sum(x * x for x in raw) ** 0.5
    vals = {s: x / norm for s, x in zip(e, raw)}
    rates = [0.1, 0.2, -0.3, 0.05]
    vals.update({al.derivative(s): r for s, r in zip(e, rates)})
    sub = {ee[i]: vals[e[i]] for i in range(4)}
    sub.update({ee[i].diff(t): rates[i] for i in range(4)})
    assert close(num(m, N.dcm(B), vals), sN.dcm(sB).subs(sub))
    w = sm.Matrix(B.ang_vel_in(N).components_in(B))
    assert close(num(m, w, vals), sB.ang_vel_in(sN).to_matrix(sB).subs(sub))


def test_rodrigues_parameters_rotate_about_their_axis():
    k = sm.Matrix([1, 2, 2]) / 3
    angle = 0.8
    g = [float(x * sm.tan(angle / 2)) for x in k]
    dcm, _ = rodrigues(g, lambda x: 0)
    expected = sm.cos(angle) * sm.eye(3) + sm.sin(angle) * sm.Matrix(
        [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]) + (1 - sm.cos(angle)) * k * k.T
    assert close(dcm.evalf(), expected.evalf())


def test_rodrigues_angular_velocity_agrees_with_its_dcm(m):
    N, B = m.frames("N B")
    g = m.variables("g1 g2 g3", order=1)
    B.orient_rodrigues(N, *g)
    vals = {g[0]: 0.2, g[1]: -0.4, g[2]: 0.3}
    vals.update({al.derivative(s): r for s, r in zip(g, (0.5, 0.1, -0.2))})
    c = N.dcm(B)
    cdot = c.applyfunc(m.defs.dt)
    skew = num(m, c.T * cdot, vals)                  # Poisson: [w]x in B
    w = num(m, sm.Matrix(B.ang_vel_in(N).components_in(B)), vals)
    assert close([skew[2, 1], skew[0, 2], skew[1, 0]], w)


def test_assigned_angular_velocity_overrides_and_chains(m):
    N, A, B = m.frames("N A B")
    q1, q2 = m.variables("q1 q2", order=1)
    u = m.variables("u", order=1)
    A.orient_axis(N, 3, q1)
    B.orient_axis(A, 1, q2)
    A.set_ang_vel(N, u * N.z)
    w = B.ang_vel_in(N)
    vals = {q1: 0.3, q2: 0.4, u: 2.0, al.derivative(q2): 0.5, al.derivative(q1): 9}
    comps = num(m, sm.Matrix(w.components_in(N)), vals)
    # u about N3, plus q2' about A1 = (cos q1, sin q1, 0) in N; q1' is not used
    assert close(comps, [0.5 * sm.cos(0.3), 0.5 * sm.sin(0.3), 2.0])


# -- points and velocities --------------------------------------------------------------
def test_one_and_two_point_theories_match_sympy(m):
    N, A = m.frames("N A")
    O, P = m.points("O P")
    q, x = m.variables("q x", order=2)
    A.orient_axis(N, 3, q)
    O.set_pos(m.newtonian("N0").origin if False else O, 0 * N.x) if False else None
    O.set_vel(N, 0 * N.x + al.vector(N, 1, 2, 0))
    O.set_acc(N, al.vector(N, 0, 0, 0))
    P.set_pos(O, x * A.x)
    v1 = P.v1pt_theory(O, N, A)
    a1 = P.a1pt_theory(O, N, A)
    sN = me.ReferenceFrame("N")
    qq, xx = me.dynamicsymbols("q x")
    sA = sN.orientnew("A", "Axis", (qq, sN.z))
    sO = me.Point("O")
    sO.set_vel(sN, sN.x + 2 * sN.y)
    sO.set_acc(sN, 0)
    sP = sO.locatenew("P", xx * sA.x)
    sP.set_vel(sA, xx.diff(t) * sA.x)
    sP.set_acc(sA, xx.diff(t, 2) * sA.x)
    sv = sP.v1pt_theory(sO, sN, sA)
    sa = sP.a1pt_theory(sO, sN, sA)
    vals = {q: 0.3, x: 1.2, al.derivative(q): 0.7, al.derivative(x): -0.4,
            al.derivative(q, 2): 0.2, al.derivative(x, 2): 1.1}
    sub = {qq: 0.3, xx: 1.2, qq.diff(t): 0.7, xx.diff(t): -0.4, qq.diff(t, 2): 0.2,
           xx.diff(t, 2): 1.1}
    assert close(num(m, v1.to_matrix(N), vals), sv.to_matrix(sN).subs(sub))
    assert close(num(m, a1.to_matrix(N), vals), sa.to_matrix(sN).subs(sub))


def test_vector_dt_uses_the_defined_angular_velocities(m):
    N, A = m.frames("N A")
    q, u = m.variables("q u", order=1)
    A.orient_axis(N, 3, q)
    A.set_ang_vel(N, u * N.z)
    v = q * A.x
    d = v.dt(N)
    vals = {q: 0.5, u: 3.0, al.derivative(q): 1.0}
    # q' A1 + u N3 x q A1 = q' A1 + u q A2
    assert close(num(m, d.to_matrix(A), vals), [1.0, 1.5, 0])


def test_missing_velocity_mass_and_inertia_are_errors_naming_the_quantity(m):
    N = m.newtonian("N")
    B = m.body("B")
    u = m.motion_variables("u", order=1)
    B.set_ang_vel(N, u * N.z)
    with pytest.raises(al.AutolevModelError, match="velocity of BO in N"):
        m.frstar()
    B.masscenter.set_vel(N, u * N.x)
    with pytest.raises(al.AutolevModelError, match="mass of body B"):
        m.frstar()
    B.mass = 2
    with pytest.raises(al.AutolevModelError, match="inertia of body B"):
        m.frstar()


def test_force_and_torque_pairs_act_and_react(m):
    N = m.newtonian("N")
    A, B = m.frames("A B")
    P, Q = m.points("P Q")
    m.force_pair(P, Q, 3 * N.x)
    m.torque_pair(A, B, 2 * N.z)
    m.force(Q, N.y)
    assert m.force_on(Q).components_in(N) == (3, 1, 0)
    assert m.force_on(P).components_in(N) == (-3, 0, 0)
    assert m.torque_on(B).components_in(N) == (0, 0, 2)
    assert m.torque_on(A).components_in(N) == (0, 0, -2)


def test_gravity_on_all_or_the_listed_bodies(m):
    N = m.newtonian("N")
    B, C = m.bodies("B C")
    P = m.particle("P")
    B.mass, C.mass, P.mass = 2, 3, 5
    m.gravity(-10 * N.z, B, P)
    assert m.force_on(B.masscenter).components_in(N) == (0, 0, -20)
    assert m.force_on(C.masscenter).components_in(N) == (0, 0, 0)
    assert m.force_on(P).components_in(N) == (0, 0, -50)


def test_inertia_in_another_frame_and_about_a_point(m):
    N = m.newtonian("N")
    A = m.frame("A")
    B = m.body("B")
    O = m.point("O")
    q = m.variables("q")
    A.orient_axis(N, 3, q)
    B.orient_axis(N, 3, 0)
    B.mass = 2
    B.set_inertia(1, 2, 3, frame=A)          # INERTIA B(A), 1, 2, 3
    inertia_in_a = num(m, B.central_inertia.to_matrix(A), {q: 0.3})
    assert close(inertia_in_a, sm.diag(1, 2, 3))
    B.masscenter.set_pos(O, 0.5 * N.x)
    B.set_inertia(1, 2, 3, frame=N, about=O)   # INERTIA B_O(N), 1, 2, 3
    central = num(m, B.central_inertia.to_matrix(N), {q: 0.3})
    # parallel axes: subtract m (r.r U - r r) with r = 0.5 N1>
    assert close(central, sm.diag(1, 2 - 0.5, 3 - 0.5))


def test_definitions_keep_names_and_differentiate_through(m):
    x, y = m.variables("x y", order=1)
    a = m.constants("a")
    m.define(y, a * x ** 2)
    e = 3 * y
    assert e.free_symbols == {y}                       # the name is kept
    assert m.explicit(m.d(e, x)) == 6 * a * x            # D() goes through it
    assert m.explicit(e) == 3 * a * x ** 2
    assert m.rhs(y) == a * x ** 2


def test_dt_of_a_variable_whose_derivative_is_defined_is_that_derivative(m):
    ea = m.specifieds("EA", order=2)
    m.define(ea, m.t ** 3)
    m.define(al.derivative(ea), m.t ** 3)
    assert m.dt(ea) == al.derivative(ea)                 # EA' has its own definition
    q = m.variables("Q", order=1)
    m.define(q, sm.sin(m.t))
    assert m.dt(q) == sm.cos(m.t)                        # Q' undefined: through Q's


def test_self_referential_definition_is_refused(m):
    x = m.variables("x", order=1)
    with pytest.raises(al.AutolevModelError, match="in terms of itself"):
        m.define(al.derivative(x), 2 * al.derivative(x))


def test_kinetic_energy_and_momentum_match_sympy(m):
    N = m.newtonian("N")
    B = m.body("B")
    q, u = m.motion_variables("q u", order=1)
    B.orient_axis(N, 3, q)
    B.set_ang_vel(N, u * N.z)
    B.masscenter.set_pos(N.origin, 2 * B.x)
    B.masscenter.v2pt_theory(N.origin, N, B)
    B.mass = 3
    B.set_inertia(1, 1, 0.5)
    vals = {q: 0.2, u: 1.5}
    # 1/2 m (2u)^2 + 1/2 Izz u^2
    assert abs(num(m, m.ke(), vals) - (0.5 * 3 * 9 + 0.5 * 0.5 * 2.25)) < 1e-12
    h = m.momentum("angular", N.origin)
    assert close(num(m, h.to_matrix(N), vals), [0, 0, 3 * 4 * 1.5 + 0.5 * 1.5])
    p = m.momentum("linear")
    assert abs(num(m, p.magnitude(), vals) - 3 * 2 * 1.5) < 1e-12


def test_dependent_speeds_are_solved_and_their_rates_defined(m):
    u1, u2 = m.motion_variables("u1 u2", order=1)
    q = m.variables("q", order=1)
    m.constrain(sm.Matrix([u2 - sm.cos(q) * u1]), [u2])
    assert m.rhs(u2) == sm.cos(q) * u1 or m.explicit(u2) == sm.cos(q) * u1
    du2 = m.explicit(al.derivative(u2))
    expected = -sm.sin(q) * al.derivative(q) * u1 + sm.cos(q) * al.derivative(u1)
    assert sm.simplify(du2 - expected) == 0


def test_solve_records_definitions(m):
    x, y = m.variables("x y")
    a, b = m.constants("a b")
    m.solve(sm.Matrix([a * x + y - 1, x - b * y]), [x, y])
    vals = {a: 2.0, b: 3.0}
    xs, ys = num(m, x, {}), None
    assert abs(num(m, m.rhs(x), vals) - 3 / 7) < 1e-12
    assert abs(num(m, m.rhs(y), vals) - 1 / 7) < 1e-12
    assert xs is not None and ys is None


def test_linear_solve_avoids_pivots_that_vanish_at_the_zero_configuration(m):
    q = m.variables("q")
    x, y = m.variables("x y")
    # the first column's first entry, sin(q), is zero at q = 0: pivot on the other
    eqs = sm.Matrix([sm.sin(q) * x + y - 1, x + y])
    m.solve(eqs, [x, y])
    sub = m.defs.substitute(m.rhs(x), {q: 0})
    assert abs(num(m, sub, {}) + 1) < 1e-12


def test_kinematical_equations_written_for_the_speeds_are_inverted(m):
    q1, q2, u1, u2 = m.motion_variables("q1 q2 u1 u2", order=1)
    m.define(u1, al.derivative(q1) + al.derivative(q2))     # U1 = Q1' + Q2'
    assert al.derivative(q1) not in m.defs.rhs              # not determined yet
    m.define(u2, al.derivative(q1) - al.derivative(q2))     # U2 = Q1' - Q2'
    vals = {u1: 3.0, u2: 1.0}
    assert abs(num(m, al.derivative(q1), vals) - 2.0) < 1e-12
    assert abs(num(m, al.derivative(q2), vals) - 1.0) < 1e-12
    assert u1 not in m.defs.rhs                             # the speeds stay free


def test_realness_is_judged_relative_to_the_size_of_the_real_part():
    from autolev.runtime.calculus import is_real_number
    assert is_real_number(1e6 + 1e-7j)          # 1e-13 relative: rounding
    assert not is_real_number(1.0 + 1e-9j)
    assert is_real_number(1e-14j)               # next to 1: rounding
    assert not is_real_number([1.0, 2.0 + 1e-6j])


@pytest.mark.parametrize("sequence", ["123", "312", "131", "232"])
def test_body_and_space_fixed_rotations_agree_with_sympys_frames(sequence):
    """Direction cosines and angular velocity of both kinds of sequence, against
    sympy.physics.vector's own orientation (a second derivation)."""
    import sympy.physics.mechanics as me
    from autolev.runtime.frame import body_fixed, space_fixed

    q = me.dynamicsymbols("q1:4")
    t = me.dynamicsymbols._t
    for ours, orient, in_parent in ((body_fixed, "orient_body_fixed", False),
                                    (space_fixed, "orient_space_fixed", True)):
        n = me.ReferenceFrame("N")
        b = me.ReferenceFrame("B")
        getattr(b, orient)(n, q, sequence)
        dcm, w = ours(q, sequence, lambda x: x.diff(t))
        expected_w = b.ang_vel_in(n).to_matrix(n if in_parent else b)
        assert sm.simplify(dcm - n.dcm(b)) == sm.zeros(3, 3)
        assert sm.simplify(sm.Matrix(w) - expected_w) == sm.zeros(3, 1)
