"""Autolev's implicit rules (docs/language.md), each on a small model written here, with
the expected values worked out by hand or with sympy.physics.mechanics."""
import itertools
import math
import textwrap
import warnings

import numpy as np
import pytest
import sympy as sm

import autolev
from autolev.runtime.calculus import NumericPoint


def load(tmp_path, text: str, name: str = "model.al", **files):
    """Write the model (and any other files, name -> text) and load it."""
    for fname, body in files.items():
        (tmp_path / fname.replace("__", ".")).write_text(textwrap.dedent(body))
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return autolev.load(path)


def num(model, expr, values: dict):
    """expr at values {Autolev name: number} (names of the model's quantities)."""
    point = NumericPoint(model.defs, {model.quantity(k): v for k, v in values.items()})
    if isinstance(expr, sm.MatrixBase):
        return sm.Matrix(expr.shape[0], expr.shape[1],
                         lambda i, j: model.defs.numeric(expr[i, j], point).real)
    return model.defs.numeric(sm.sympify(expr), point).real


def close(a, b, tol=1e-10) -> bool:
    a, b = sm.Matrix(a), sm.Matrix(b)
    return a.shape == b.shape and all(abs(float(x) - float(y)) < tol for x, y in zip(a, b))


def rot3(angle):
    """parent.dcm(child) for a turn by `angle` about axis 3."""
    c, s = math.cos(angle), math.sin(angle)
    return sm.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


# -- 1. every frame has an origin point ---------------------------------------------------
def test_frames_have_an_origin_fixed_in_them(tmp_path):
    m = load(tmp_path, """
        NEWTONIAN N
        FRAMES A
        POINTS P
        VARIABLES X', Q'
        CONSTANTS L
        SIMPROT(N, A, 3, Q)
        P_AO_P> = L*A1> + X*A2>
        V> = V_P_A>
        """)
    a, ao = m.entity("A"), m.entity("AO")
    assert ao is a.origin and ao.name == "AO"
    # AO is fixed in A: P's velocity in A is the rate of its position in A
    v = m.vector("V")
    assert close(num(m, v.to_matrix(a), {"X'": 0.7, "X": 0.1, "Q": 0.3, "L": 2}),
                 [0, 0.7, 0])


def test_a_declared_point_keeps_the_origins_name(tmp_path):
    m = load(tmp_path, """
        NEWTONIAN N
        POINTS AO
        FRAMES A
        """)
    assert m.entity("AO") is not m.entity("A").origin


# -- 2. positions, velocities, angular velocities and DCMs along chains -------------------
CHAIN = """
    NEWTONIAN N
    FRAMES DA, DB
    POINTS CA, CB
    VARIABLES Q{2}'
    CONSTANTS L{3}
    SIMPROT(N, DA, 3, Q1)
    SIMPROT(DA, DB, 3, Q2)
    P_NO_CA> = 0>
    P_CA_DAO> = L1*DA1>
    P_DAO_DBO> = L2*DA2>
    P_DBO_CB> = L3*DB1>
    X> = P_CA_CB>
    Y> = P_CB_CA>
    V> = V_CB_N>
    ACC> = A_CB_N>
    W> = W_DB_N>
    M = DB_N
    """


def test_positions_add_along_the_chain_either_way(tmp_path):
    m = load(tmp_path, CHAIN)
    n = m.entity("N")
    q1, q2, l1, l2, l3 = 0.4, -0.9, 1.5, 0.7, 2.0
    vals = {"Q1": q1, "Q2": q2, "L1": l1, "L2": l2, "L3": l3}
    a = q1 + q2
    by_hand = [l1 * math.cos(q1) - l2 * math.sin(q1) + l3 * math.cos(a),
               l1 * math.sin(q1) + l2 * math.cos(q1) + l3 * math.sin(a), 0]
    assert close(num(m, m.vector("X").to_matrix(n), vals), by_hand)
    assert close(num(m, m.vector("Y").to_matrix(n), vals), [-c for c in by_hand])


def test_velocity_and_acceleration_come_from_the_positions(tmp_path):
    m = load(tmp_path, CHAIN)
    n = m.entity("N")
    q1, q2, d1, d2, dd1, dd2 = 0.4, -0.9, 0.3, -1.1, 0.5, 0.25
    l1, l2, l3 = 1.5, 0.7, 2.0
    vals = {"Q1": q1, "Q2": q2, "Q1'": d1, "Q2'": d2, "Q1''": dd1, "Q2''": dd2,
            "L1": l1, "L2": l2, "L3": l3}
    t = sm.Symbol("t")
    f1, f2 = sm.Function("f1")(t), sm.Function("f2")(t)
    r = sm.Matrix([l1 * sm.cos(f1) - l2 * sm.sin(f1) + l3 * sm.cos(f1 + f2),
                   l1 * sm.sin(f1) + l2 * sm.cos(f1) + l3 * sm.sin(f1 + f2), 0])
    at = {f1.diff(t, 2): dd1, f2.diff(t, 2): dd2, f1.diff(t): d1, f2.diff(t): d2,
          f1: q1, f2: q2}
    assert close(num(m, m.vector("V").to_matrix(n), vals), r.diff(t).subs(at))
    assert close(num(m, m.vector("ACC").to_matrix(n), vals), r.diff(t, 2).subs(at))


def test_angular_velocities_and_dcms_chain(tmp_path):
    m = load(tmp_path, CHAIN)
    vals = {"Q1": 0.4, "Q2": -0.9, "Q1'": 0.3, "Q2'": -1.1}
    assert close(num(m, m.vector("W").to_matrix(m.entity("N")), vals), [0, 0, 0.3 - 1.1])
    assert close(num(m, m.quantity("M"), vals), rot3(0.4 - 0.9).T)


def test_an_undefined_link_names_the_two_points(tmp_path):
    with pytest.raises(autolev.AutolevRuntimeError) as info:
        load(tmp_path, """
            NEWTONIAN N
            POINTS P, R
            CONSTANTS L
            P_NO_P> = L*N1>
            X> = P_P_R>
            """)
    message = str(info.value)
    assert "position of R relative to P" in message and "model.al:6:" in message


# -- 3. inertia about any point, and of a set ----------------------------------------------
INERTIAS = """
    NEWTONIAN N
    BODIES DA, DB
    PARTICLES PP
    POINTS SO, P
    CONSTANTS M{3}, L, I{3}
    MASS DA=M1, DB=M2, PP=M3
    INERTIA DA, I1, I2, I3
    INERTIA DB, I1, I2, I3
    DEGREES OFF
    SIMPROT(N, DA, 3, PI/2)
    SIMPROT(N, DB, 1, PI/2)
    P_NO_DAO> = L*N1>
    P_DAO_DBO> = L*N2>
    P_NO_PP> = L*N3>
    P_NO_P> = L*(N1> + N2> + N3>)
    P_DAO_SO> = CM(DAO, DA, DB)
    I_S_SO>> = I_DA_SO>> + I_DB_SO>>
    J>> = I_DA_P>>
    K>> = I_PP_P>>
    T>> = INERTIA(SO, DA, DB)
    R> = P_NO_SO>
    """


def _parallel_axis(mass, r):
    r = sm.Matrix(r)
    return mass * ((r.T * r)[0] * sm.eye(3) - r * r.T)


def test_inertia_about_any_point_is_central_plus_parallel_axes(tmp_path):
    m = load(tmp_path, INERTIAS.replace("PI/2", "0"))
    vals = {"M1": 2.0, "M2": 3.0, "M3": 5.0, "L": 0.5, "I1": 1.0, "I2": 2.0, "I3": 4.0}
    n = m.entity("N")
    central = sm.diag(1.0, 2.0, 4.0)
    # r from P to DAO: L N1> - L (N1> + N2> + N3>)
    expected = central + _parallel_axis(2.0, [0, -0.5, -0.5])
    assert close(num(m, m.vector("J").to_matrix(n), vals), expected)
    # a particle: the parallel-axis term alone (r from P to PP)
    assert close(num(m, m.vector("K").to_matrix(n), vals),
                 _parallel_axis(5.0, [-0.5, -0.5, 0]))


def test_inertia_of_a_set_about_its_mass_centre(tmp_path):
    m = load(tmp_path, INERTIAS)
    vals = {"M1": 2.0, "M2": 3.0, "M3": 5.0, "L": 0.5, "I1": 1.0, "I2": 2.0, "I3": 4.0}
    n = m.entity("N")
    # mass centre of DA and DB: from NO, (2*(L,0,0) + 3*(L,L,0))/5
    so = [0.5, 0.3, 0]
    assert close(num(m, m.vector("R").to_matrix(n), vals), so)
    central = sm.diag(1.0, 2.0, 4.0)
    da = rot3(math.pi / 2) * central * rot3(math.pi / 2).T
    rx = sm.Matrix([[1, 0, 0], [0, 0, -1], [0, 1, 0]])        # N.dcm(DB), turn about N1
    db = rx * central * rx.T
    expected = (da + _parallel_axis(2.0, [0.5 - so[0], -so[1], 0])
                + db + _parallel_axis(3.0, [0.5 - so[0], 0.5 - so[1], 0]))
    assert close(num(m, m.vector("I_S_SO").to_matrix(n), vals), expected)
    assert close(num(m, m.vector("T").to_matrix(n), vals), expected)


# -- 4. SOLVE after KANE(F1, ...) ----------------------------------------------------------
PENDULUM_TENSION = """
    NEWTONIAN N
    FRAMES A
    PARTICLES P
    MOTIONVARIABLES' Q', U{2}
    VARIABLES TENSION
    CONSTANTS L, M, G
    SIMPROT(N, A, 3, Q)
    Q' = U1
    W_A_N> = U1*A3>
    P_NO_P> = L*A1>
    V_P_N> = L*U1*A2> + U2*A1>
    AUXILIARY[1] = U2
    CONSTRAIN(AUXILIARY[U2])
    MASS P = M
    GRAVITY(G*N1>)
    FORCE(P, -TENSION*A1>)
    ZERO = FR() + FRSTAR()
    KANE(TENSION)
    SOLVE(ZERO, U1')
    INPUT L=2, M=3, G=9.81, Q=30 DEG, U1=0.5
    OUTPUT Q, U1, TENSION
    CODE DYNAMICS() tension.c
    """


def test_solve_after_kane_with_unknowns_uses_the_dynamical_rows(tmp_path):
    m = load(tmp_path, PENDULUM_TENSION)
    assert len(m.quantity("ZERO")) == 2
    vals = {"Q": 0.4, "U1": 0.9, "L": 2.0, "M": 3.0, "G": 9.81}
    assert num(m, m.quantity("U1'"), vals) == pytest.approx(-9.81 / 2 * math.sin(0.4))
    # the rod's tension: m g cos(q) + m L u1^2, from the auxiliary row
    assert num(m, m.quantity("TENSION"), vals) == pytest.approx(
        3 * 9.81 * math.cos(0.4) + 3 * 2 * 0.9 ** 2)
    r = m.simulate(TFINAL=0.5)
    assert r.outputs[0]["TENSION"][0] == pytest.approx(
        3 * 9.81 * math.cos(math.pi / 6) + 3 * 2 * 0.25, rel=1e-6)


# -- 5. INPUT(x) of a defined name -----------------------------------------------------------
def test_input_of_a_defined_name_is_its_value_under_the_inputs(tmp_path):
    m = load(tmp_path, """
        CONSTANTS A, B, C
        A = PI/2
        B = 2*A + C
        INPUT C = 30 DEG
        X = INPUT(A)
        Y = INPUT(B)
        """)
    assert m.quantity("X") == sm.pi / 2
    assert m.quantity("Y") == sm.pi + sm.pi / 6


def test_input_of_a_definition_using_a_name_without_value_is_an_error(tmp_path):
    with pytest.raises(autolev.AutolevRuntimeError, match="uses C, which has no INPUT"):
        load(tmp_path, """
            CONSTANTS A, C
            A = 2*C
            X = INPUT(A)
            """)


# -- 6. a later statement never rewrites an earlier CODE ---------------------------------------
PENDULUM = """
    NEWTONIAN N
    FRAMES A
    PARTICLES P
    MOTIONVARIABLES' Q', U'
    CONSTANTS L, M, G
    SIMPROT(N, A, 3, Q)
    Q' = U
    W_A_N> = U*A3>
    P_NO_P> = L*A1>
    V_P_N> = L*U*A2>
    MASS P = M
    GRAVITY(G*N1>)
    ZERO = FR() + FRSTAR()
    INPUT L=2, M=3, G=9.81, Q=30 DEG, U=0
    OUTPUT Q, U
    CODE DYNAMICS() first.c
    SOLVE(ZERO, U')
    CODE DYNAMICS() second.c
    """


def test_solve_after_code_leaves_the_coded_program_alone(tmp_path):
    m = load(tmp_path, PENDULUM)
    first, second = m.run(out_dir=tmp_path / "out")
    assert first.state_names == second.state_names == ["Q", "U"]
    # the pendulum swings: U is integrated from Kane's equations, not a constant
    assert first.states[-1, 1] < -0.5
    # the same motion (M u' = f solved numerically there, SOLVE's closed form here)
    assert np.allclose(first.states, second.states, rtol=1e-12, atol=1e-14)


def test_equations_are_there_after_solve(tmp_path):
    m = load(tmp_path, PENDULUM)
    vals = {"Q": 0.4, "L": 2.0, "M": 3.0, "G": 9.81}
    assert m.speeds == [m.quantity("U")] and m.coordinates == [m.quantity("Q")]
    assert close(num(m, m.mass_matrix, vals), [[12.0]])
    assert close(num(m, m.forcing, vals), [[-9.81 * 2 * 3 * math.sin(0.4)]])
    assert m.symbolic_system("combined").comb_implicit_mat.shape == (2, 2)


# -- 7. dependent speeds at any regular configuration -----------------------------------
TWO_LOOPS = """
    % five links in the plane, closed twice: A-B-C-D back to the ground, A-B-C-E too
    NEWTONIAN N
    FRAMES A, B, C, D, E
    MOTIONVARIABLES' Q{5}', U{5}
    SIMPROT(N, A, 3, Q1)
    SIMPROT(N, B, 3, Q2)
    SIMPROT(N, C, 3, Q3)
    SIMPROT(N, D, 3, Q4)
    SIMPROT(N, E, 3, Q5)
    LOOP1> = U1*A2> + U2*B2> + U3*C2> + U4*D2>
    LOOP2> = U1*A2> + U2*B2> + U3*C2> + U5*E2>
    DEPENDENT[1] = DOT(LOOP1>, N1>)
    DEPENDENT[2] = DOT(LOOP1>, N2>)
    DEPENDENT[3] = DOT(LOOP2>, N1>)
    DEPENDENT[4] = DOT(LOOP2>, N2>)
    CONSTRAIN(DEPENDENT[U2, U3, U4, U5])
    """


def test_dependent_speeds_wherever_the_constraints_are_regular(tmp_path):
    m = load(tmp_path, TWO_LOOPS)
    args = [m.quantity(f"Q{k}") for k in range(1, 6)] + [m.quantity("U1")]
    # the dependent speeds' definitions, every Z expanded, as one numeric function
    dependent = sm.lambdify(args, [m.explicit(m.quantity(f"U{k}")) for k in range(2, 6)])
    angles = (0, 45, 90, 135, 180, -45, -90)
    checked = 0
    for qs in itertools.product(angles, repeat=5):
        q = [math.radians(a) for a in qs]
        # the velocity of the loops' ends: sum of u_k (-sin q_k, cos q_k)
        a = np.array([[-math.sin(q[k]) for k in (1, 2, 3)] + [0],
                      [math.cos(q[k]) for k in (1, 2, 3)] + [0],
                      [-math.sin(q[k]) for k in (1, 2)] + [0, -math.sin(q[4])],
                      [math.cos(q[k]) for k in (1, 2)] + [0, math.cos(q[4])]])
        if abs(np.linalg.det(a)) < 1e-6:
            continue
        b = -np.array([-math.sin(q[0]), math.cos(q[0])] * 2)
        assert np.allclose(dependent(*q, 1.0), np.linalg.solve(a, b), atol=1e-9), qs
        checked += 1
    assert checked > 5000


# -- 8. functions Autolev does not know --------------------------------------------------------
def test_a_function_file_is_expanded_like_autolevs_user_functions(tmp_path):
    m = load(tmp_path, """
        CONSTANTS X, Y
        A = 2*MYATAN2(Y, -X)
        """, MYATAN2__R="""
        % a function file: one expression, #1# and #2# the arguments' text
        atan(#1#/#2#) + pi/2*sign(#1#)*(1 - sign(#2#))
        """)
    for x, y in ((1.0, 0.5), (-1.0, 0.5), (-1.0, -0.5)):
        value = num(m, m.quantity("A"), {"X": x, "Y": y})
        assert value == pytest.approx(2 * math.atan2(y, -x))


def test_an_unknown_function_is_one_error_with_a_suggestion(tmp_path):
    path = tmp_path / "m.al"
    path.write_text("CONSTANTS A\nX = SYN(A)\nY = X + 1\nZ = 2*Y\n")
    with pytest.raises(autolev.AutolevTranslationError) as info:
        autolev.transpile(path)
    errors = [d for d in info.value.diagnostics if d.severity == "error"]
    assert len(errors) == 1
    assert "SYN()" in errors[0].message and "did you mean SIN" in errors[0].message
    assert errors[0].location.line == 2


# -- 9. what Autolev's programs printed --------------------------------------------------
DRIVEN_PENDULUM = """
    NEWTONIAN N
    BODIES A, B
    CONSTANTS g, l{2}, m{2}, i{2}
    VARIABLES theta{2}'
    MOTIONVARIABLES' omega{2}'
    MASS A=m1, B=m2
    INERTIA A, 0, 0, i1
    INERTIA B, 0, 0, i2
    SIMPROT(N, A, 3, theta1)
    SIMPROT(A, B, 3, theta2)
    theta1' = omega1
    theta2' = omega2
    P_NO_AO> = l1/2*A2>
    P_NO_BO> = l1*A2> + l2/2*B2>
    W_A_N> = omega1*N3>
    W_B_N> = (omega1 + omega2)*N3>
    V_AO_N> = DT(P_NO_AO>, N)
    V_BO_N> = DT(P_NO_BO>, N)
    GRAVITY(g*N2>)
    SPECIFIED torque
    torque = 10*SIN(2*PI*T + PI/6)
    TORQUE(N/A, torque*N3>)
    ZERO = FR() + FRSTAR()
    SOLVE(ZERO, omega1', omega2')
    kinetic = KE(A, B)
    INPUT g=9.81, l1=2, m1=4, i1=0.5, l2=2, m2=4, i2=0.5
    OUTPUT omega1, omega2, theta2, kinetic
    CODE DYNAMICS() FILE
    """


def _kinetic(row, with_i1: bool):
    """The double pendulum's kinetic energy by hand (row: omega1, omega2, theta2)."""
    w1, w2, th2 = row
    m1 = m2 = 4.0
    l1 = l2 = 2.0
    i1 = i2 = 0.5
    v2 = l1 ** 2 * w1 ** 2 + l2 ** 2 / 4 * (w1 + w2) ** 2 + l1 * l2 * w1 * (w1 + w2) * math.cos(th2)
    return (m1 * (l1 / 2 * w1) ** 2 / 2 + (i1 * w1 ** 2 / 2 if with_i1 else 0.0)
            + i2 * (w1 + w2) ** 2 / 2 + m2 * v2 / 2)


@pytest.mark.parametrize("program, quirks, with_i1", [
    ("pendulum.c", True, False), ("pendulum.c", False, True), ("pendulum.m", True, True)])
def test_outputs_as_autolevs_c_output_routine_computed_them(tmp_path, program, quirks,
                                                            with_i1):
    m = load(tmp_path, DRIVEN_PENDULUM.replace("FILE", program))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = m.simulate(quirks=quirks)
    table = r.outputs[0]
    rows = np.column_stack([table["omega1"], table["omega2"], table["theta2"]])
    assert abs(rows[3, 0]) > 0.1                 # it has started to swing
    expected = [_kinetic(row, with_i1) for row in rows]
    assert np.allclose(table["kinetic"], expected, rtol=1e-6, atol=1e-9)
    said = any("int i1" in str(w.message) for w in caught)
    assert said == (program.endswith(".c") and quirks)


@pytest.mark.parametrize("quirks", [True, False])
def test_the_written_c_program_and_the_run_compute_the_same_outputs(tmp_path, quirks, capsys):
    # `autolev code` and `autolev run` both give Autolev's values (i1 read as 0 in
    # the output routine) and both say so; with --no-quirks both give the values meant
    import shutil
    import subprocess

    from autolev.cli import main
    from autolev.engine.clibrary import compiler
    if compiler() is None:
        pytest.skip("no C compiler")
    model = tmp_path / "pendulum.al"
    model.write_text(textwrap.dedent(DRIVEN_PENDULUM.replace("FILE", "pendulum.c")))
    flags = [] if quirks else ["--no-quirks"]
    assert main(["run", str(model), "--out", str(tmp_path / "run"), *flags]) == 0
    said_by_run = capsys.readouterr().err
    assert main(["code", str(model), "--out", str(tmp_path / "code"), *flags]) == 0
    said_by_code = capsys.readouterr().err
    for said in (said_by_run, said_by_code):
        assert ("i1 = 0" in said and "`autolev code`" in said) == quirks, said
    code = tmp_path / "code"
    shutil.copy(tmp_path / "run" / "pendulum.in", code / "pendulum.in")
    subprocess.run([compiler(), "-O0", "-o", "program", "pendulum.c", "-lm"], cwd=code,
                   check=True, capture_output=True)
    subprocess.run(["./program"], cwd=code, check=True, capture_output=True)
    ran = np.loadtxt(tmp_path / "run" / "pendulum.1", comments="%")
    written = np.loadtxt(code / "pendulum.1", comments="%")
    assert np.allclose(ran, written, rtol=1e-6, atol=1e-9)
    kinetic = [_kinetic(row[:3], with_i1=not quirks) for row in ran]
    assert np.allclose(ran[:, 3], kinetic, rtol=1e-6, atol=1e-9)


DECAY = """
    VARIABLES X'
    X' = -3*X
    INPUT X = 1, TFINAL = 1, INTEGSTP = 0.1, ABSERR = 1E-4, RELERR = 1E-4
    OUTPUT X
    CODE DYNAMICS() FILE
    """


def test_a_matlab_program_integrates_with_ode45_over_every_integstp(tmp_path):
    import scipy.integrate
    m = load(tmp_path, DECAY.replace("FILE", "decay.m"))
    r = m.simulate()
    assert r.stats["method"] == "rk45"
    # Autolev's Matlab loop: ode45(@f, [T T+INTEGSTP], VAR, RelTol, AbsTol, MaxStep)
    y, t, expected = 1.0, 0.0, [1.0]
    for _ in range(10):
        sol = scipy.integrate.solve_ivp(lambda t, y: -3 * y, (t, t + 0.1), [y],
                                        method="RK45", rtol=1e-4, atol=1e-4, max_step=0.1)
        y, t = sol.y[0, -1], t + 0.1
        expected.append(y)
    # scipy's steps, or the compiled loop's once its C is built (the cache may hold it
    # already): the same steps, their sums differing at rounding level
    assert np.allclose(r.states[:, 0], expected, rtol=1e-13, atol=0)
    c = load(tmp_path, DECAY.replace("FILE", "decay.c"), name="c.al").simulate()
    assert c.stats["method"] == "kutta-merson" and not np.allclose(
        c.states[:, 0], expected, rtol=1e-8, atol=0)


def test_numeric_angles_are_degrees_unless_written_with_pi(tmp_path):
    m = load(tmp_path, """
        NEWTONIAN N
        FRAMES A, B, C
        SIMPROT(N, A, 3, PI/2)
        SIMPROT(N, B, 3, 90)
        DEGREES OFF
        SIMPROT(N, C, 3, 0.5)
        """)
    n = m.entity("N")
    assert close(num(m, n.dcm(m.entity("A")), {}), rot3(math.pi / 2))
    assert close(num(m, n.dcm(m.entity("B")), {}), rot3(math.pi / 2))
    assert close(num(m, n.dcm(m.entity("C")), {}), rot3(0.5))


# -- 10. a definition in terms of its previous self --------------------------------------------
def test_the_name_on_the_right_of_a_redefinition_is_its_previous_definition(tmp_path):
    m = load(tmp_path, """
        VARIABLES DELTA', WH3, WB3, Y
        SPECIFIED TDELTA
        CONSTANTS C, TM, TF
        TDELTA = TM + C*DELTA' + TF
        TDELTA = REPLACE(TDELTA, DELTA'=WH3-WB3)
        X = RHS(TDELTA)
        Y = C
        Y = Y + 1
        Y := 2*Y
        Z = RHS(Y)
        """)
    c, tm, tf, wh3, wb3 = (m.quantity(n) for n in ("C", "TM", "TF", "WH3", "WB3"))
    assert sm.expand(m.quantity("X") - (tm + c * (wh3 - wb3) + tf)) == 0
    assert sm.expand(m.quantity("Z") - (2 * c + 2)) == 0


def test_a_definition_that_refers_to_itself_is_still_an_error(tmp_path):
    with pytest.raises(autolev.AutolevRuntimeError, match="in terms of itself"):
        load(tmp_path, "VARIABLES Y\nY = Y + 1\n")


def test_a_declared_t_is_the_models_own_not_time(tmp_path):
    for name in ("t", "T"):
        m = load(tmp_path, f"""
            CONSTANTS {name}, K
            VARIABLES X'
            X' = -K*X + {name}
            INPUT X = 1, K = 1, {name} = 5
            Y = DT({name})
            OUTPUT X
            CODE DYNAMICS() decay.c
            """, name=f"m{name}.al")
        assert m.quantity(name) != m.t and m.quantity("Y") == 0
        r = m.simulate()
        # X' = 5 - X from X = 1: X = 5 - 4 exp(-t)
        assert r.states[-1, 0] == pytest.approx(5 - 4 * math.exp(-1), rel=1e-6)


# -- 11. names of two kinds ------------------------------------------------------------------
def test_a_name_that_is_a_body_and_a_matrix(tmp_path):
    m = load(tmp_path, """
        NEWTONIAN N
        BODIES A
        CONSTANTS K
        VARIABLES Q'
        A[1,1] = K
        A[1,2] = 2
        VEC> = K*N1>
        """)
    k = m.quantity("K")
    assert m["A"] == sm.Matrix([[k, 2]]) and m.quantity("A") == m["A"]
    assert m.entity("A").name == "A" and m["AO"] is m.entity("A").masscenter
    assert m["Q'"] == m.quantity("Q'") and str(m["Q'"]) == "Q'"
    assert str(m["VEC>"]) == "K*N1>" and m["N"] is m.entity("N")
    with pytest.raises(KeyError):
        m["NOSUCH"]


@pytest.mark.parametrize("line", ["E = [A1] + B1", "E = B1 - [A1, B1]", "E = [A1; B1] + A1"])
def test_a_matrix_and_a_scalar_do_not_add(line):
    with pytest.raises(autolev.AutolevTranslationError) as info:
        autolev.transpile(f"CONSTANTS A1, B1\n{line}\n")
    (d,) = [d for d in info.value.diagnostics if d.severity == "error"]
    assert d.code == "T001" and (d.line, d.col) == (2, 5)
    assert "1x1 matrix is not a scalar" in d.message


def test_matrices_of_one_size_still_add():
    code = autolev.transpile("CONSTANTS A1, B1\nE = [A1] + [B1]\nF = 2*[A1, B1] - [B1, A1]\n")
    namespace = {}
    exec(compile(code, "m.py", "exec"), namespace)
    a1, b1 = namespace["A1"], namespace["B1"]
    assert namespace["E"] == sm.Matrix([[a1 + b1]])
    assert sm.expand(namespace["F"] - sm.Matrix([[2 * a1 - b1, 2 * b1 - a1]])) == \
        sm.zeros(1, 2)


# -- 12. a run solves SOLVE's accelerations by LU ---------------------------------------------
def _chain(links: int) -> str:
    """A planar chain of uniform rods, joint angles relative, SOLVE(ZERO, U1', ...)."""
    names = "ABCDEFGH"[:links]
    k = range(1, links + 1)
    lines = ["NEWTONIAN N", f"BODIES {', '.join(names)}", f"POINTS P{{{links - 1}}}",
             f"MOTIONVARIABLES' Q{{{links}}}', U{{{links}}}'",
             f"CONSTANTS L{{{links}}}, M{{{links}}}, G"]
    lines += [f"MASS {b} = M{i}" for b, i in zip(names, k)]
    lines += [f"INERTIA {b}, 0, 0, M{i}*L{i}^2/12" for b, i in zip(names, k)]
    lines += [f"SIMPROT({p}, {b}, 3, Q{i})" for p, b, i in zip("N" + names, names, k)]
    lines += [f"Q{i}' = U{i}" for i in k]
    lines += [f"W_{b}_{p}> = U{i}*N3>" for p, b, i in zip("N" + names, names, k)]
    joints = ["NO"] + [f"P{i}" for i in k]
    for b, i in zip(names, k):
        lines += [f"P_{joints[i - 1]}_{b}O> = L{i}/2*{b}1>",
                  f"V2PTS(N, {b}, {joints[i - 1]}, {b}O)"]
        if i < links:
            lines += [f"P_{joints[i - 1]}_{joints[i]}> = L{i}*{b}1>",
                      f"V2PTS(N, {b}, {joints[i - 1]}, {joints[i]})"]
    rates = ", ".join(f"U{i}'" for i in k)
    lines += ["GRAVITY(G*N1>)", "ZERO = FR() + FRSTAR()", "KANE()", f"SOLVE(ZERO, {rates})",
              "INPUT " + ", ".join([f"L{i}=1, M{i}=1" for i in k] + ["G=9.81"]),
              "OUTPUT Q1", "CODE DYNAMICS() chain.c"]
    return "\n".join(lines) + "\n"


def _chain_by_sympy(links: int):
    """The chain's mass matrix and forcing by sympy.physics.mechanics (an independent
    derivation), as a function of (q, u, L, M, G) evaluated with mpmath."""
    import sympy.physics.mechanics as me
    q, u = me.dynamicsymbols(f"q1:{links + 1}"), me.dynamicsymbols(f"u1:{links + 1}")
    lengths, masses = sm.symbols(f"l1:{links + 1}"), sm.symbols(f"m1:{links + 1}")
    g = sm.Symbol("g")
    newtonian = frame = me.ReferenceFrame("N")
    joint = me.Point("O")
    joint.set_vel(newtonian, 0)
    bodies = []
    for i in range(links):
        link = me.ReferenceFrame(f"F{i}")
        link.orient_axis(frame, frame.z, q[i])
        link.set_ang_vel(frame, u[i] * frame.z)
        centre = joint.locatenew(f"C{i}", lengths[i] / 2 * link.x)
        centre.v2pt_theory(joint, newtonian, link)
        inertia = me.inertia(link, 0, 0, masses[i] * lengths[i]**2 / 12)
        bodies.append(me.RigidBody(f"B{i}", centre, link, masses[i], (inertia, centre)))
        following = joint.locatenew(f"J{i}", lengths[i] * link.x)
        following.v2pt_theory(joint, newtonian, link)
        joint, frame = following, link
    kane = me.KanesMethod(newtonian, q, u, kd_eqs=[a.diff() - b for a, b in zip(q, u)])
    kane.kanes_equations(bodies, [(b.masscenter, b.mass * g * newtonian.x) for b in bodies])
    return sm.lambdify([*q, *u, *lengths, *masses, g], [kane.mass_matrix, kane.forcing],
                       "mpmath")


def test_solves_accelerations_as_accurately_as_the_mass_matrix_allows(tmp_path):
    # a straight chain whose last rod carries nearly all the mass: its mass matrix is
    # close to rank one, and SOLVE's closed form (a ratio of determinants, Autolev's
    # answer) cancels; the run solves SOLVE's equations by LU, whose error is bounded
    # by the condition number times the rounding unit
    import mpmath
    from autolev.runtime.numerics.prepare import prepare_command
    links = 4
    model = load(tmp_path, _chain(links), "chain.al")
    command = model.code_commands[0]
    system = prepare_command(model.snapshot_for(command), command).system
    by_sympy = _chain_by_sympy(links)
    lengths, masses = [1.0] * links, [1e-6, 1e-4, 1e-2, 1.0]
    values = {f"L{i + 1}": v for i, v in enumerate(lengths)}
    values.update({f"M{i + 1}": v for i, v in enumerate(masses)}, G=9.81)
    system.set_parameters(np.array([values[str(p)] for p in system.params]))
    where = {str(x): k for k, x in enumerate(system.states)}
    rng = np.random.default_rng(4)
    mpmath.mp.dps = 50
    for _ in range(5):
        q = rng.uniform(-1, 1, links) * np.array([1] + [0.05] * (links - 1))
        u = rng.uniform(-1, 1, links)
        state = np.zeros(2 * links)
        for i in range(links):
            state[where[f"Q{i + 1}"]], state[where[f"U{i + 1}"]] = q[i], u[i]
        ours = system.derivatives(0.0, state)[[where[f"U{i + 1}"] for i in range(links)]]
        mass, forcing = by_sympy(*map(mpmath.mpf, [*q, *u, *lengths, *masses, 9.81]))
        exact = np.array(mpmath.lu_solve(mpmath.matrix(mass), mpmath.matrix(forcing)),
                         dtype=float).ravel()
        condition = np.linalg.cond(np.array(mass.tolist(), dtype=float))
        assert condition > 1e4                  # the case that matters
        error = np.abs(ours - exact).max() / np.abs(exact).max()
        assert error < 2 * condition * np.finfo(float).eps, (error, condition)


SECOND_ORDER_PENDULUM = """NEWTONIAN N
FRAMES A, B
PARTICLES P1, P2
MOTIONVARIABLES' Q{2}''
CONSTANTS L1, L2, M1, M2, G
SIMPROT(N, A, 3, Q1)
SIMPROT(N, B, 3, Q2)
W_A_N> = Q1'*N3>
W_B_N> = Q2'*N3>
P_NO_P1> = L1*A1>
P_P1_P2> = L2*B1>
V_P1_N> = DT(P_NO_P1>, N)
V_P2_N> = DT(P_NO_P2>, N)
MASS P1 = M1, P2 = M2
GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
QDD = [Q1''; Q2'']
SOLVE(ZERO, QDD)
INPUT L1 = 1.1, L2 = 0.7, M1 = 2, M2 = 0.5, G = 9.81, Q1 = 0.4, Q2 = -0.3
OUTPUT Q1, Q2
CODE DYNAMICS() pendulum2.c
"""


def test_solve_of_second_derivatives_is_solved_by_lu_as_speeds_rates_are(tmp_path):
    # MOTIONVARIABLES' Q{2}'' and SOLVE(ZERO, [Q1''; Q2'']) (gait2d's form): the speeds
    # are Q1', Q2', and their rates are SOLVE's equations solved at each evaluation, so
    # the implicit form's rows are M Q'' - F: the double pendulum by Lagrange, by hand
    model = load(tmp_path, SECOND_ORDER_PENDULUM, "pendulum2.al")
    l1, l2, m1, m2, g = 1.1, 0.7, 2.0, 0.5, 9.81
    q1, q2, w1, w2 = 0.4, -0.3, 0.8, -1.3
    c, s = math.cos(q1 - q2), math.sin(q1 - q2)
    mass = np.array([[(m1 + m2) * l1 ** 2, m2 * l1 * l2 * c], [m2 * l1 * l2 * c, m2 * l2 ** 2]])
    forcing = np.array([-m2 * l1 * l2 * s * w2 ** 2 - (m1 + m2) * g * l1 * math.sin(q1),
                        m2 * l1 * l2 * s * w1 ** 2 - m2 * g * l2 * math.sin(q2)])
    accelerations = np.linalg.solve(mass, forcing)
    dynamics = model.dynamics()
    assert dynamics.states == ["Q1", "Q1'", "Q2", "Q2'"]
    x = np.array([q1, w1, q2, w2])
    assert np.allclose(dynamics.explicit(x)[0], [w1, accelerations[0], w2, accelerations[1]],
                       rtol=1e-13)
    jac = dynamics.residual_jacobians(x, np.zeros(4)).dense("xdot")[0]
    speeds = [1, 3]
    assert np.allclose(jac[np.ix_(speeds, speeds)], mass, rtol=1e-13)
    # the model's own mass matrix and forcing (a Python user's path) are the same
    expand = model.defs.explicit
    symbols = {str(s): s for s in model.mass_matrix.applyfunc(expand).free_symbols
               | model.forcing.applyfunc(expand).free_symbols}
    point = {symbols[k]: v for k, v in dict(L1=l1, L2=l2, M1=m1, M2=m2, G=g, Q1=q1, Q2=q2,
                                            **{"Q1'": w1, "Q2'": w2}).items() if k in symbols}
    assert np.allclose(np.array(model.mass_matrix.applyfunc(expand).subs(point), dtype=float),
                       mass, rtol=1e-13)
    assert np.allclose(np.array(model.forcing.applyfunc(expand).subs(point),
                                dtype=float).ravel(), forcing, rtol=1e-13)
    # the run integrates the same motion: scipy on the equations by hand
    from scipy.integrate import solve_ivp

    def by_hand(t, y):
        a, wa, b, wb = y
        c, s = math.cos(a - b), math.sin(a - b)
        m = [[(m1 + m2) * l1 ** 2, m2 * l1 * l2 * c], [m2 * l1 * l2 * c, m2 * l2 ** 2]]
        f = [-m2 * l1 * l2 * s * wb ** 2 - (m1 + m2) * g * l1 * math.sin(a),
             m2 * l1 * l2 * s * wa ** 2 - m2 * g * l2 * math.sin(b)]
        aa, ab = np.linalg.solve(m, f)
        return [wa, aa, wb, ab]
    result = model.simulate(TFINAL=0.5, ABSERR=1e-10, RELERR=1e-10, **{"Q1'": w1, "Q2'": w2})
    expected = solve_ivp(by_hand, (0, 0.5), x, rtol=1e-11, atol=1e-11, t_eval=result.t).y.T
    assert np.allclose(result.states, expected, atol=1e-7)
