"""The translated examples' equations against independent derivations: hand-derived
equations, sympy's LagrangesMethod and KanesMethod built from scratch, and the
results published in SymPy's documentation (shared/seed-systems.md)."""
import numpy as np
import sympy as sm
import sympy.physics.mechanics as me

import autolev
from autolev.runtime.numerics.prepare import prepare_command
from helpers import EXAMPLES, ROOT
from helpers.mechanics import close, example, random_values, symbols, value

DATA = ROOT / "tests" / "data"

t = me.dynamicsymbols._t


def test_simple_pendulum_by_hand():
    m = example("simple_pendulum")
    th, L, g, M = symbols(m, "THETA", "L", "G", "M")
    for seed in range(3):
        vals = random_values([th, L, g, M, symbols(m, "THETA'")], seed, 0.2, 2.0)
        assert close(value(m, m.mass_matrix, vals), [[vals[M] * vals[L] ** 2]])
        assert close(value(m, m.forcing, vals),
                     [[-vals[M] * vals[g] * vals[L] * sm.sin(vals[th])]])


def test_double_pendulum_rows_equal_autolevs_printed_rows():
    # Autolev's response to ZERO = FR() + FRSTAR() (SymPy's autolev_parser docs), for
    # equal lengths L and masses M
    m = example("double_pendulum")
    q1, q2, u1, u2, u1d, u2d = symbols(m, "Q1", "Q2", "U1", "U2", "U1'", "U2'")
    L1, L2, M1, M2, G = symbols(m, "L1", "L2", "M1", "M2", "G")
    zero = m.loaded.namespace["ZERO"]
    for seed in range(4):
        v = random_values([q1, q2, u1, u2, u1d, u2d], seed)
        L, M, g = 0.7 + seed / 10, 1.3, 9.81
        v.update({L1: L, L2: L, M1: M, M2: M, G: g})
        s12 = sm.sin(v[q1] - v[q2])
        c12 = sm.cos(v[q1] - v[q2])
        autolev = [-L * M * (2 * g * sm.sin(v[q1]) + L * (v[u2] ** 2 * s12 + 2 * v[u1d]
                                                         + c12 * v[u2d])),
                   -L * M * (g * sm.sin(v[q2]) - L * (v[u1] ** 2 * s12 - v[u2d]
                                                     - c12 * v[u1d]))]
        assert close(value(m, zero, v), sm.Matrix(autolev))


def _lagrange(coords, lagrangian, forces=None, frame=None):
    lm = me.LagrangesMethod(lagrangian, coords, forcelist=forces, frame=frame)
    lm.form_lagranges_equations()
    return lm.mass_matrix, lm.forcing


def _compare_with_lagrange(model, ours_q, theirs_q, subs_constants, M_L, f_L, seeds=3,
                           speeds=None):
    """Our mass matrix and forcing equal Lagrange's at random states."""
    speeds = speeds or [symbols(model, q.name + "'") for q in ours_q]
    for seed in range(seeds):
        v = random_values(ours_q + speeds, seed)
        v.update(subs_constants)
        theirs = {}
        for oq, tq, u in zip(ours_q, theirs_q, speeds):
            theirs[tq] = v[oq]
            theirs[tq.diff(t)] = v[u]
        consts = {sm.Symbol(k.name): val for k, val in subs_constants.items()}
        ml = M_L.subs(theirs).subs(consts)
        fl = f_L.subs(theirs).subs(consts)
        assert close(value(model, model.mass_matrix, v), ml.evalf())
        assert close(value(model, model.forcing, v), fl.evalf())


def test_double_pendulum_equals_lagrange():
    m = example("double_pendulum")
    q1, q2 = symbols(m, "Q1", "Q2")
    u = symbols(m, "U1", "U2")
    consts = dict(zip(symbols(m, "L1", "L2", "M1", "M2", "G"), (1.1, 0.6, 2.0, 0.7, 9.81)))
    a, b = me.dynamicsymbols("a b")
    L1, L2, M1, M2, G = sm.symbols("L1 L2 M1 M2 G")
    x1, y1 = L1 * sm.cos(a), L1 * sm.sin(a)
    x2, y2 = x1 + L2 * sm.cos(b), y1 + L2 * sm.sin(b)
    T = M1 * (x1.diff(t) ** 2 + y1.diff(t) ** 2) / 2 + M2 * (x2.diff(t) ** 2 + y2.diff(t) ** 2) / 2
    V = -M1 * G * x1 - M2 * G * x2          # N1> (x) points down
    M_L, f_L = _lagrange([a, b], T - V)
    _compare_with_lagrange(m, [q1, q2], [a, b], consts, M_L, f_L, speeds=u)


def test_double_pendulum_equals_sympy_kanesmethod():
    m = example("double_pendulum")
    q1, q2, u1, u2 = symbols(m, "Q1", "Q2", "U1", "U2")
    L1, L2, M1, M2, G = symbols(m, "L1", "L2", "M1", "M2", "G")
    a, b, wa, wb = me.dynamicsymbols("a b wa wb")
    l1, l2, m1, m2, g = sm.symbols("l1 l2 m1 m2 g")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (a, N.z))
    B = N.orientnew("B", "Axis", (b, N.z))
    A.set_ang_vel(N, wa * N.z)
    B.set_ang_vel(N, wb * N.z)
    O = me.Point("O")
    O.set_vel(N, 0)
    P1 = O.locatenew("P1", l1 * A.x)
    P1.v2pt_theory(O, N, A)
    P2 = P1.locatenew("P2", l2 * B.x)
    P2.v2pt_theory(P1, N, B)
    km = me.KanesMethod(N, [a, b], [wa, wb], kd_eqs=[a.diff() - wa, b.diff() - wb])
    fr, frstar = km.kanes_equations([me.Particle("p1", P1, m1), me.Particle("p2", P2, m2)],
                                    [(P1, m1 * g * N.x), (P2, m2 * g * N.x)])
    for seed in range(3):
        v = random_values([q1, q2, u1, u2], seed)
        consts = {L1: 1.2, L2: 0.4, M1: 1.5, M2: 0.6, G: 9.81}
        v.update(consts)
        theirs = {a: v[q1], b: v[q2], wa: v[u1], wb: v[u2], l1: 1.2, l2: 0.4, m1: 1.5,
                  m2: 0.6, g: 9.81}
        assert close(value(m, m.mass_matrix, v), km.mass_matrix.subs(theirs))
        assert close(value(m, m.forcing, v), km.forcing.subs(theirs))


def test_mass_spring_damper_by_hand():
    m = example("mass_spring_damper")
    x, v_, M, K, B, G, F0, W = symbols(m, "X", "V", "M", "K", "B", "G", "F0", "OMEGA")
    for seed in range(3):
        v = random_values([x, v_, M, K, B, G, F0, W, m.t], seed, 0.1, 2.0)
        expected = -v[K] * v[x] - v[B] * v[v_] + v[F0] * sm.sin(v[W] * v[m.t]) + v[M] * v[G]
        assert close(value(m, m.mass_matrix, v), [[v[M]]])
        assert close(value(m, m.forcing, v), [[expected]])
    assert m.kinematical_equations == {symbols(m, "X'"): v_}


def test_four_link_pendulum_equals_lagrange():
    m = example("nlink_pendulum")
    qs = symbols(m, "Q1", "Q2", "Q3", "Q4")
    us = symbols(m, "U1", "U2", "U3", "U4")
    L_, M_, G_ = symbols(m, "L", "M", "G")
    th = me.dynamicsymbols("th1:5")
    L, M, G = sm.symbols("L M G")
    T, V = 0, 0
    x = y = 0
    angle = 0
    for k in range(4):
        angle = angle + th[k]                      # relative joint angles
        cx, cy = x + L / 2 * sm.cos(angle), y + L / 2 * sm.sin(angle)
        w = sum(s.diff(t) for s in th[:k + 1])
        T += M * (cx.diff(t) ** 2 + cy.diff(t) ** 2) / 2 + M * L ** 2 / 12 * w ** 2 / 2
        V += -M * G * cx                           # N1> (x) points down
        x, y = x + L * sm.cos(angle), y + L * sm.sin(angle)
    M_L, f_L = _lagrange(list(th), T - V)
    _compare_with_lagrange(m, qs, list(th), {L_: 0.5, M_: 1.2, G_: 9.81}, M_L, f_L,
                           seeds=2, speeds=us)


def test_cart_pendulum_qpp_model_equals_lagrange():
    m = example("cart_pendulum")
    X, TH = symbols(m, "X", "TH")
    MC, MB, L_, G_ = symbols(m, "MC", "MB", "L", "G")
    assert m.speeds == symbols(m, "X'", "TH'")
    xx, th = me.dynamicsymbols("x th")
    mc, mb, L, G = sm.symbols("MC MB L G")
    bx, by = xx + L * sm.sin(th), -L * sm.cos(th)
    T = mc * xx.diff(t) ** 2 / 2 + mb * (bx.diff(t) ** 2 + by.diff(t) ** 2) / 2
    V = mb * G * by
    M_L, f_L = _lagrange([xx, th], T - V)
    _compare_with_lagrange(m, [X, TH], [xx, th], {MC: 2.0, MB: 0.5, L_: 0.8, G_: 9.81},
                           M_L, f_L)


def test_euler_parameter_body_kinematics_and_euler_equations():
    m = example("euler_parameters_body")
    e = symbols(m, "E1", "E2", "E3", "E4")
    u = symbols(m, "U1", "U2", "U3")
    I1, I2, I3, T1, T2, T3 = symbols(m, "I1", "I2", "I3", "T1", "T2", "T3")
    assert m.coordinates == e and m.speeds == u
    kin = m.kinematical_equations
    for seed in range(3):
        v = random_values(list(e) + list(u) + [I1, I2, I3, T1, T2, T3], seed, 0.1, 1.0)
        e1, e2, e3, e4 = (v[s] for s in e)
        w1, w2, w3 = (v[s] for s in u)
        # e' = 1/2 E(e) w, with e4 the scalar part
        expected = [(e4 * w1 - e3 * w2 + e2 * w3) / 2, (e3 * w1 + e4 * w2 - e1 * w3) / 2,
                    (-e2 * w1 + e1 * w2 + e4 * w3) / 2, -(e1 * w1 + e2 * w2 + e3 * w3) / 2]
        got = [value(m, kin[symbols(m, f"E{i}'")], v) for i in range(1, 5)]
        assert close(got, expected)
        # Euler's equations: I w' = T - w x I w
        i1, i2, i3 = v[I1], v[I2], v[I3]
        f = [v[T1] - (i3 - i2) * w2 * w3, v[T2] - (i1 - i3) * w3 * w1,
             v[T3] - (i2 - i1) * w1 * w2]
        assert close(value(m, m.mass_matrix, v), sm.diag(i1, i2, i3))
        assert close(value(m, m.forcing, v), f)


def test_rolling_disc_equals_sympy_kanesmethod():
    m = example("rolling_disc")
    q = symbols(m, "Q1", "Q2", "Q3", "Q4", "Q5")
    u = symbols(m, "U1", "U2", "U3", "U4", "U5")
    R_, M_, G_ = symbols(m, "R", "M", "G")
    assert m.speeds == list(u[:3])
    qs = me.dynamicsymbols("q1:6")
    us = me.dynamicsymbols("u1:6")
    r, mass, g = sm.symbols("r m g")
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (qs[0], N.z))
    B = A.orientnew("B", "Axis", (qs[1], A.x))
    C = B.orientnew("C", "Axis", (qs[2], B.y))
    kd = {q_.diff(): u_ for q_, u_ in zip(qs, us)}
    A.set_ang_vel(N, us[0] * N.z)
    B.set_ang_vel(A, us[1] * A.x)
    C.set_ang_vel(B, us[2] * B.y)
    O = me.Point("O")
    O.set_vel(N, 0)
    CO = O.locatenew("CO", qs[3] * N.x + qs[4] * N.y + r * B.z)
    CO.set_vel(N, CO.pos_from(O).dt(N).subs(kd))
    CN = CO.locatenew("CN", -r * B.z)
    CN.v2pt_theory(CO, N, C)
    disc = me.RigidBody("disc", CO, C, mass,
                        (me.inertia(C, mass * r ** 2 / 4, mass * r ** 2 / 2, mass * r ** 2 / 4),
                         CO))
    km = me.KanesMethod(N, list(qs), list(us[:3]), kd_eqs=[q_.diff() - u_ for q_, u_ in
                                                          zip(qs, us)],
                        u_dependent=list(us[3:]),
                        velocity_constraints=[CN.vel(N).dot(N.x), CN.vel(N).dot(N.y)])
    km.kanes_equations([disc], [(CO, -mass * g * N.z)])
    for seed in range(3):
        v = random_values(list(q) + list(u[:3]), seed)
        v.update({R_: 0.3, M_: 2.0, G_: 9.81})
        theirs = {s: v[o] for s, o in zip(qs, q)}
        theirs.update({s: v[o] for s, o in zip(us[:3], u[:3])})
        theirs.update({r: 0.3, mass: 2.0, g: 9.81})
        # sympy's forcing may hold the dependent speeds: give them their values
        theirs[us[3]] = value(m, u[3], v)
        theirs[us[4]] = value(m, u[4], v)
        # sympy stacks the constraint rows under the dynamics; compare accelerations
        theirs_ud = km.mass_matrix.subs(theirs).evalf().LUsolve(km.forcing.subs(theirs).evalf())
        ours_ud = value(m, m.mass_matrix, v).LUsolve(value(m, m.forcing, v))
        assert close(ours_ud, theirs_ud[:3, :])


def test_block_and_pendulums_equal_sympys_published_equations():
    m = example("block_pendulums")
    q1, q2, q3, u1, u2, u3 = symbols(m, "Q1", "Q2", "Q3", "U1", "U2", "U3")
    names = ("MA", "MB", "MC", "IBZZ", "L", "G", "K", "CDAMP", "KT", "F", "TQ")
    ma, mb, mc, ibzz, l, g, k, c, kt, F, T = symbols(m, *names)
    for seed in range(3):
        v = random_values([q1, q2, q3, u1, u2, u3], seed)
        v.update(random_values([ma, mb, mc, ibzz, l, g, k, c, kt, F, T], seed + 10, 0.2, 2))
        Q1, Q2, Q3, U1, U2, U3 = (v[s] for s in (q1, q2, q3, u1, u2, u3))
        MA, MB, MC, IB, Ln, Gn, Kn, Cn, KT, Fn, Tn = (v[s] for s in
                                                      (ma, mb, mc, ibzz, l, g, k, c, kt, F, T))
        cos, sin = sm.cos, sm.sin
        M11 = MA + MB + MC
        M12 = 2 * Ln * MB * cos(Q2) / 3 + MC * (Ln * cos(Q2 + Q3) + Ln * cos(Q2))
        M13 = Ln * MC * cos(Q2 + Q3)
        M22 = IB + 4 * Ln ** 2 * MB / 9 + MC * (2 * Ln ** 2 * cos(Q3) + 2 * Ln ** 2)
        M23 = MC * (Ln ** 2 * cos(Q3) + Ln ** 2)
        M33 = Ln ** 2 * MC
        mm = sm.Matrix([[M11, M12, M13], [M12, M22, M23], [M13, M23, M33]])
        f1 = (-Cn * U1 - Kn * Q1 + sm.Rational(2, 3) * Ln * MB * U2 ** 2 * sin(Q2)
              + Ln * MC * sin(Q2 + Q3) * (U2 + U3) ** 2 + Ln * MC * U2 ** 2 * sin(Q2) + Fn)
        f2 = (-sm.Rational(2, 3) * Gn * Ln * MB * sin(Q2) - Gn * Ln * MC * sin(Q2 + Q3)
              - Gn * Ln * MC * sin(Q2) + Ln ** 2 * MC * (U2 + U3) ** 2 * sin(Q3)
              - Ln ** 2 * MC * U2 ** 2 * sin(Q3) + Tn)
        f3 = -Gn * Ln * MC * sin(Q2 + Q3) - KT * Q3 - Ln ** 2 * MC * U2 ** 2 * sin(Q3)
        full = sm.diag(sm.eye(3), mm)
        assert close(value(m, m.mass_matrix_full, v), full)
        assert close(value(m, m.forcing_full, v), sm.Matrix([U1, U2, U3, f1, f2, f3]))


def test_fourbar_noncontributing_forces_equal_sympys_published_values():
    m = example("fourbar")
    q = symbols(m, "Q1", "Q2", "Q3")
    u1 = symbols(m, "U1")
    F1, F2 = symbols(m, "F1", "F2")
    consts = dict(zip(symbols(m, "L1", "L2", "L3", "L4", "RHO", "G"), (2, 1, 2, 1, 5, 9.81)))
    v = {s: float(sm.pi / 2) for s in q}
    v.update(consts)
    v[u1] = 0.0
    v[symbols(m, "U1'")] = 0.0
    assert abs(value(m, F1, v)) < 1e-9
    assert abs(value(m, F2, v) - (-98.1)) < 1e-9


def _double_pendulum_rates(v, L1, L2, M1, M2, g, torque):
    """(U1', U2') of two point masses on links at absolute angles Q1, Q2 from the
    downward N1> (gravity along N1>), a torque on the first link: by hand, from the
    Lagrangian T = (M1+M2)L1^2 U1^2/2 + M2 L2^2 U2^2/2 + M2 L1 L2 cos(Q2-Q1) U1 U2."""
    q1, q2, u1, u2 = v
    c, s = sm.cos(q2 - q1), sm.sin(q2 - q1)
    mass = sm.Matrix([[(M1 + M2) * L1 ** 2, M2 * L1 * L2 * c], [M2 * L1 * L2 * c, M2 * L2 ** 2]])
    forcing = sm.Matrix([-(M1 + M2) * g * L1 * sm.sin(q1) + M2 * L1 * L2 * s * u2 ** 2 + torque,
                         -M2 * g * L2 * sm.sin(q2) - M2 * L1 * L2 * s * u1 ** 2])
    return list(mass.LUsolve(forcing))


def test_the_equations_of_a_model_formed_by_solve_are_its_motion():
    # SOLVE(ZERO, U1', U2') defines the accelerations; mass_matrix and forcing are
    # still those of Fr + Fr* = 0 in them (they were 0 = 0: M^-1 forcing ~ 1e-15)
    m = autolev.load(DATA / "equations" / "solved_double_pendulum.al")
    names = ["Q1", "Q2", "U1", "U2"]
    state = symbols(m, *names)
    L1, L2, M1, M2, G = symbols(m, "L1", "L2", "M1", "M2", "G")
    command = m.code_commands[0]
    system = prepare_command(m.snapshot_for(command), command).system
    for seed in range(3):
        v = random_values(state, seed)
        consts = {L1: 1, L2: 0.7, M1: 2, M2: 1.5, G: 9.81}
        tt = 0.3 + seed
        point = {**v, **consts, m.t: tt}
        expected = _double_pendulum_rates([v[x] for x in state], 1, 0.7, 2, 1.5, 9.81,
                                          0.5 * sm.sin(tt))
        by_matrices = value(m, m.mass_matrix, point).LUsolve(value(m, m.forcing, point))
        assert close(by_matrices, sm.Matrix(expected))
        assert close(value(m, m.explicit_form(), point),
                     sm.Matrix([v[state[2]], v[state[3]]] + expected))
        ss = m.symbolic_system("combined")
        given = {x: v[state[names.index(str(x.func))]] for x in ss.states}
        given.update({c: consts[symbols(m, str(c))] for c in ss.constant_symbols()})
        given[t] = tt
        rates = ss.comb_implicit_mat.subs(given).LUsolve(ss.comb_implicit_rhs.subs(given))
        assert close(rates, sm.Matrix([v[state[2]], v[state[3]]] + expected))
        x = [v[s] for s in system.states]
        run = system.derivatives(tt, np.array(x, dtype=float))
        assert close(sm.Matrix(list(run)), sm.Matrix([v[state[2]], v[state[3]]] + expected))


def test_a_shared_expression_goes_to_sympy_once_per_distinct_part():
    # a model's expanded forcing shares its parts (the Whipple's: 2 255 distinct, a tree
    # too large to walk); each level here doubles the tree, 2**60 leaves in all
    from autolev.runtime.interop import dynamic_map, to_sympy_expr
    m = example("double_pendulum")
    mapping = dynamic_map(m.scene)
    q1 = symbols(m, "Q1")
    ours, theirs = q1, mapping[q1]
    for _ in range(60):
        ours, theirs = sm.sin(ours) * ours + 1, sm.sin(theirs) * theirs + 1
    assert to_sympy_expr(m.scene, ours, mapping) == theirs


def test_frstar_after_fr_takes_each_partial_velocity_once(monkeypatch):
    # ZERO = FR() + FRSTAR(): FR() forms Fr, FRSTAR() adds Fr* over the same partial
    # velocities (it used to form Fr again, every partial velocity taken twice); the
    # rows stay Autolev's (test_double_pendulum_rows_equal_autolevs_printed_rows)
    from autolev.runtime import kane
    taken = []
    real = kane._Partials._taken

    def counted(partials, v):
        taken.append(v)
        return real(partials, v)
    monkeypatch.setattr(kane._Partials, "_taken", counted)
    m = example("double_pendulum")
    assert "FR() + FRSTAR()" in (EXAMPLES / "double_pendulum.al").read_text().upper()
    assert taken and len(taken) == len({str(v) for v in taken})
    zero = m.loaded.namespace["ZERO"]
    q1, q2, u1, u2, u1d, u2d = symbols(m, "Q1", "Q2", "U1", "U2", "U1'", "U2'")
    fr, frstar = m.fr(), m.frstar()
    v = random_values([q1, q2, u1, u2, u1d, u2d], 5)
    v.update(dict(zip(symbols(m, "L1", "L2", "M1", "M2", "G"), (0.8, 0.6, 1.3, 0.9, 9.81))))
    assert close(value(m, fr + frstar, v), value(m, zero, v))
