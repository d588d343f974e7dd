"""Model.linearize: A, B, C, D at an operating point, checked against a hand derivation
(pendulum), against central differences of the integrated right-hand side (a second
method), and against the classical stability speed of a rolling disc."""
import math
import warnings

import numpy as np
import sympy as sm
import pytest

import autolev
import autolev.runtime as al
from autolev.runtime.numerics.prepare import prepare_command
from helpers import EXAMPLES
from helpers.models import PENDULUM


@pytest.fixture(scope="module")
def pendulum(tmp_path_factory):
    path = tmp_path_factory.mktemp("lin") / "pendulum.al"
    path.write_text(PENDULUM)
    return autolev.load(path)


def test_a_pendulum_by_hand(pendulum):
    # m L^2 u' = -m g L sin(q) + TQ, X = L cos(q): by hand at q = 0.3 rad
    g, L, m, q = 9.81, 2.0, 3.0, 0.3
    lin = pendulum.linearize({"Q": q})
    assert lin.states == ["Q", "U"] and lin.inputs == ["TQ"]
    assert lin.outputs == ["Q", "X", "U'"]
    assert np.allclose(lin.A, [[0, 1], [-g / L * math.cos(q), 0]], rtol=1e-14)
    assert np.allclose(lin.B, [[0], [1 / (m * L * L)]], rtol=1e-14)
    assert np.allclose(lin.C, [[1, 0], [-L * math.sin(q), 0], [-g / L * math.cos(q), 0]],
                       rtol=1e-14)
    assert np.allclose(lin.D, [[0], [0], [1 / (m * L * L)]], rtol=1e-14)
    assert lin.accelerations == pytest.approx([-g / L * math.sin(q)], rel=1e-14)
    assert not lin.steady


def test_a_mass_matrix_in_tiny_units_is_not_singular(pendulum):
    # a cell model's masses are 1e-23 kg: M = m L^2 is far below any absolute threshold,
    # yet A is the same (g/L) and B scales as 1/m
    g, L, m, q = 9.81, 2.0, 3.5e-23, 0.3
    lin = pendulum.linearize({"Q": q, "M": m})
    assert np.allclose(lin.A, [[0, 1], [-g / L * math.cos(q), 0]], rtol=1e-12)
    assert lin.B[1, 0] == pytest.approx(1 / (m * L * L), rel=1e-12)


def test_a_zero_mass_matrix_is_singular(pendulum):
    # by the mass matrix, and by the recursion's pivot (runtime/articulated.py)
    with pytest.raises(al.AutolevModelError, match="mass matrix is singular"):
        pendulum.linearize({"Q": 0.3, "M": 0})


def test_operating_point_in_radians_and_the_rest_from_input(pendulum):
    hanging = pendulum.linearize({"Q": 0})
    assert hanging.steady and hanging.point["M"] == 3.0 and hanging.point["Q"] == 0.0
    w = math.sqrt(9.81 / 2)
    assert np.allclose(hanging.eigenvalues(), [-1j * w, 1j * w], rtol=1e-14)
    upright = pendulum.linearize({"Q": math.pi, "L": 1.0})
    assert np.allclose(upright.eigenvalues(), [-math.sqrt(9.81), math.sqrt(9.81)])
    # INPUT Q = 10 deg when the point leaves Q out
    assert pendulum.linearize().point["Q"] == pytest.approx(math.radians(10), rel=1e-15)
    torqued = pendulum.linearize({"Q": 0.0, "TQ": 6.0})
    assert torqued.accelerations == pytest.approx([6.0 / 12.0])


def test_inputs_and_names_are_checked(pendulum):
    assert pendulum.linearize({"Q": 0}, inputs=[]).B.shape == (2, 0)
    with pytest.raises(autolev.runtime.AutolevModelError, match="'Q' is not a specified"):
        pendulum.linearize(inputs=["Q"])
    with pytest.raises(autolev.runtime.AutolevModelError, match="no quantity named 'K'"):
        pendulum.linearize({"K": 1.0})


def central_differences(system, t, x, h=1e-6):
    cols = []
    for k in range(len(x)):
        e = np.zeros(len(x))
        e[k] = h * max(1.0, abs(x[k]))
        cols.append((system.derivatives(t, x + e) - system.derivatives(t, x - e)) / (2 * e[k]))
    return np.array(cols).T


@pytest.mark.parametrize("name, point", [
    ("double_pendulum", {"Q1": 0.4, "Q2": -1.1, "U1": 0.7, "U2": -0.2}),
    ("rolling_disc", {"Q2": 0.3, "Q3": 1.0, "U1": 0.5, "U2": -0.4, "U3": 6.0}),
])
def test_jacobians_agree_with_differences_of_the_right_hand_side(name, point):
    model = autolev.load(EXAMPLES / f"{name}.al")
    lin = model.linearize(point)
    command = model.command_to_run()
    system = prepare_command(model.snapshot_for(command), command, internal_values=point).system
    x = np.array([lin.point[s] for s in lin.states])
    assert np.allclose(system.derivatives(0.0, x), lin.rates, rtol=1e-13, atol=1e-13)
    assert np.allclose(lin.A, central_differences(system, 0.0, x), rtol=1e-6, atol=1e-7)


def test_a_rolling_disc_is_stable_upright_above_the_classical_speed():
    # a thin disc rolling upright is stable when its spin exceeds sqrt(g / (3 r))
    model = autolev.load(EXAMPLES / "rolling_disc.al")       # r = 0.3, g = 9.81
    critical = math.sqrt(9.81 / (3 * 0.3))
    below = model.linearize({"Q2": 0, "U3": critical * (1 - 1e-6)})
    above = model.linearize({"Q2": 0, "U3": critical * (1 + 1e-6)})
    assert below.steady and above.steady
    assert max(below.eigenvalues().real) > 1e-4
    assert max(above.eigenvalues().real) < 1e-9
    assert max(abs(above.eigenvalues().imag)) > 1e-4


def test_only_a_dynamics_program_is_linearized(tmp_path):
    path = tmp_path / "alg.al"
    path.write_text("CONSTANTS A\nVARIABLES X\nE = X - A\nINPUT A = 1\n"
                    "CODE ALGEBRAIC(E, X) alg.c\n")
    model = autolev.load(path)
    with pytest.raises(autolev.runtime.AutolevModelError, match="only a CODE DYNAMICS"):
        model.linearize(code="alg.c")
    # without CODE DYNAMICS, the model's equations as they stand: here no motion at all
    with pytest.raises(autolev.runtime.AutolevModelError, match="no state to linearize"):
        model.linearize()


def test_a_model_without_code_dynamics_is_linearized_as_it_stands(tmp_path):
    path = tmp_path / "bare.al"
    path.write_text(PENDULUM.replace("CODE DYNAMICS() pendulum.c\n", ""))
    lin = autolev.load(path).linearize({"Q": 0})
    w = math.sqrt(9.81 / 2)
    assert np.allclose(lin.eigenvalues(), [-1j * w, 1j * w], rtol=1e-14)


def test_the_command_prints_and_writes_the_eigenvalues(pendulum, tmp_path, capsys):
    from autolev.cli import main
    model_file = tmp_path / "pendulum.al"
    model_file.write_text(PENDULUM)
    assert main(["linearize", str(model_file), "--at", "Q=0", "--set", "L=8",
                 "--out", str(tmp_path / "out")]) == 0
    printed = capsys.readouterr().out
    assert "2 states (Q, U); inputs: TQ" in printed
    rows = (tmp_path / "out" / "pendulum-eigenvalues.csv").read_text().splitlines()
    assert rows[0] == "real,imaginary,frequency_hz,damping_ratio,note"
    w = math.sqrt(9.81 / 8)                              # --set L=8 (metres, as given)
    values = [[float(v) for v in row.split(",")[:4]] for row in rows[1:]]
    assert [v[1] for v in values] == pytest.approx([-w, w], rel=1e-14)
    assert [v[2] for v in values] == pytest.approx([w / (2 * math.pi)] * 2, rel=1e-12)
    assert [v[3] for v in values] == [0.0, 0.0]


@pytest.mark.parametrize("args, status, message", [
    (["--at", "Q=x"], 2, "--at Q=x: not a finite number"),
    (["--at", "Q"], 2, "--at expects NAME=VALUE"),
    (["--at", "K=1"], 1, "no quantity named 'K' here (known: G, L, M, Q, U)"),
    (["--inputs", "M"], 1, "'M' is not a specified quantity"),
])
def test_the_command_refuses_what_it_cannot_use(tmp_path, capsys, args, status, message):
    from autolev.cli import main
    model_file = tmp_path / "pendulum.al"
    model_file.write_text(PENDULUM)
    assert main(["linearize", str(model_file), *args]) == status
    assert message in capsys.readouterr().err


def test_a_sweep_finds_the_rolling_discs_critical_spin(tmp_path, capsys):
    from autolev.cli import main
    assert main(["linearize", str(EXAMPLES / "rolling_disc.al"), "--at", "Q2=0",
                 "--sweep", "U3=2:5:7", "--out", str(tmp_path)]) == 0
    rows = (tmp_path / "rolling_disc-sweep.csv").read_text().splitlines()
    assert rows[0].startswith("U3,re1,im1,re2,im2,") and len(rows) == 8
    critical = math.sqrt(9.81 / (3 * 0.3))                    # 3.30 rad/s
    for row in rows[1:]:
        cells = [float(c) for c in row.split(",")]
        spin, real_parts = cells[0], cells[1::2]
        assert len(real_parts) == 8
        assert (max(real_parts) > 1e-3) == (spin < critical)


@pytest.mark.parametrize("text", ["U3=2:5", "U3=2:5:0", "=1:2:3", "U3=a:2:3", "U3=1:inf:3"])
def test_a_malformed_sweep_is_refused(tmp_path, capsys, text):
    from autolev.cli import main
    assert main(["linearize", str(EXAMPLES / "rolling_disc.al"), "--sweep", text]) == 2
    assert "--sweep expects NAME=START:STOP:N" in capsys.readouterr().err


def loop_closure(model):
    r = model["P5"].pos_from(model["NO"])
    return [r.dot(model["N"].x), r.dot(model["N"].y)]


def test_a_four_bar_reduced_by_its_loop_closure():
    # the example is a parallelogram (links 1 m, 2 m, 1 m on a 2 m base, 5 kg/m): links
    # 2 and 4 swing alike and link 3 translates, so hanging (Q1 = -90 deg) it is a
    # pendulum with V = 15 g sin(Q1) and T = (5/3 + 5/3 + 10)/2 U1^2: w^2 = 15 g / (40/3)
    model = autolev.load(EXAMPLES / "fourbar.al")
    near = {"Q1": -math.pi / 2, "Q2": 1.5 * math.pi + 0.1, "Q3": -math.pi / 2 - 0.1, "U1": 0}
    lin = model.linearize(near, constraints=loop_closure(model))
    assert lin.states == ["Q1", "U1"] and lin.dependent == ["Q2", "Q3"]
    assert lin.point["Q2"] == pytest.approx(1.5 * math.pi, abs=1e-12)   # put on the loop
    assert lin.point["Q3"] == pytest.approx(-math.pi / 2, abs=1e-12)
    assert lin.steady and lin.A.shape == (2, 2) and lin.C.shape == (6, 2)
    w = math.sqrt(15 * 9.81 / (40 / 3))
    assert np.allclose(lin.eigenvalues(), [-1j * w, 1j * w], atol=1e-12)
    # unreduced, each constraint adds an eigenvalue 0
    full = model.linearize(dict(near, Q2=1.5 * math.pi, Q3=-math.pi / 2))
    assert np.allclose(sorted(full.eigenvalues(), key=abs), [0, 0, -1j * w, 1j * w],
                       atol=1e-12)


def test_dependent_coordinates_named_or_refused():
    model = autolev.load(EXAMPLES / "fourbar.al")
    point = {"Q1": -math.pi / 2, "Q2": 1.5 * math.pi, "Q3": -math.pi / 2, "U1": 0}
    lin = model.linearize(point, constraints=loop_closure(model), dependent=["q1", "Q3"])
    assert lin.states == ["Q2", "U1"] and lin.dependent == ["Q1", "Q3"]
    w = math.sqrt(15 * 9.81 / (40 / 3))
    assert np.allclose(lin.eigenvalues(), [-1j * w, 1j * w], atol=1e-12)
    with pytest.raises(autolev.runtime.AutolevModelError, match="2 state names are needed"):
        model.linearize(point, constraints=loop_closure(model), dependent=["Q2"])


def test_a_sweep_too_long_for_the_command_line_is_refused_before_any_work(capsys):
    from autolev.cli import main
    # a billion points would hold gigabytes of rows: refused as a usage error at once
    assert main(["linearize", str(EXAMPLES / "rolling_disc.al"), "--sweep",
                 "U3=2:5:1000000000"]) == 2
    err = capsys.readouterr().err
    assert "1000000000 points" in err and "at most 100000" in err


def test_a_sweep_is_drawn_with_plot(tmp_path, capsys):
    pytest.importorskip("matplotlib", reason="--plot needs the optional matplotlib")
    from autolev.cli import main
    model_file = tmp_path / "pendulum.al"
    model_file.write_text(PENDULUM)
    assert main(["linearize", str(model_file), "--sweep", "Q=0:3:7", "--plot",
                 "--out", str(tmp_path / "out")]) == 0
    png = tmp_path / "out" / "pendulum-sweep.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 5000
    assert "not an equilibrium or a steady motion at Q = 0.5" in capsys.readouterr().err


def test_plot_without_a_sweep_is_refused(tmp_path, capsys):
    from autolev.cli import main
    model_file = tmp_path / "pendulum.al"
    model_file.write_text(PENDULUM)
    assert main(["linearize", str(model_file), "--plot"]) == 2
    assert "--plot draws a --sweep" in capsys.readouterr().err


def test_equations_undefined_at_the_point_are_a_clear_error(tmp_path):
    path = tmp_path / "bad.al"
    path.write_text("VARIABLES Q''\nCONSTANTS G, L\nQ'' = -G/L*SIN(Q)\n"
                    "INPUT G = 9.81, L = 0, Q = 0, Q' = 0\nCODE DYNAMICS() bad.c\n")
    with pytest.raises(autolev.runtime.AutolevModelError,
                       match="not finite at the operating point: the derivatives of Q'"):
        autolev.load(path).linearize()


def test_a_model_without_kanes_equations_and_its_accelerations(tmp_path):
    # X'' written out: the rate of X' is its acceleration, as Kane's would be
    path = tmp_path / "plain.al"
    path.write_text("VARIABLES Q''\nCONSTANTS G, L\nQ'' = -G/L*SIN(Q)\n"
                    "INPUT G = 9.81, L = 2, Q = 0, Q' = 0\nCODE DYNAMICS() plain.c\n")
    model = autolev.load(path)
    hanging = model.linearize()
    assert hanging.states == ["Q", "Q'"] and hanging.steady
    w = math.sqrt(9.81 / 2)
    assert np.allclose(hanging.eigenvalues(), [-1j * w, 1j * w], rtol=1e-14)
    tilted = model.linearize({"Q": 0.3})
    assert not tilted.steady
    assert tilted.accelerations == pytest.approx([-9.81 / 2 * math.sin(0.3)], rel=1e-14)


DOUBLE_PENDULUM = """NEWTONIAN N
FRAMES A, B
PARTICLES P1, P2
MOTIONVARIABLES' Q{2}', U{2}'
CONSTANTS G, L1, L2, M1, M2
SIMPROT(N, A, 3, Q1)
SIMPROT(A, B, 3, Q2)
Q1' = U1
Q2' = U2
W_A_N> = U1*A3>
W_B_A> = U2*A3>
P_NO_P1> = L1*A1>
P_P1_P2> = L2*B1>
V_P1_N> = DT(P_NO_P1>, N)
V_P2_N> = DT(P_NO_P1> + P_P1_P2>, N)
MASS P1 = M1, P2 = M2
GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
SOLVE(ZERO, U1', U2')
INPUT G = 9.81, L1 = 1.5, L2 = 0.7, M1 = 2, M2 = 3
"""


def test_a_locked_joint_makes_one_rigid_pendulum(tmp_path):
    # Q2 held at b: one body, masses at L1 a1 and L1 a1 + L2 (cos b a1 + sin b a2);
    # it hangs with its mass centre below O and swings at w^2 = g |sum m r| / sum m r^2
    path = tmp_path / "double.al"
    path.write_text(DOUBLE_PENDULUM)
    model = autolev.load(path)
    g, l1, l2, m1, m2, b = 9.81, 1.5, 0.7, 2.0, 3.0, 0.4
    cx, cy = m1 * l1 + m2 * (l1 + l2 * math.cos(b)), m2 * l2 * math.sin(b)
    inertia = m1 * l1 ** 2 + m2 * (l1 ** 2 + l2 ** 2 + 2 * l1 * l2 * math.cos(b))
    w = math.sqrt(g * math.hypot(cx, cy) / inertia)
    lin = model.linearize({"Q1": -math.atan2(cy, cx), "Q2": b}, locked=["Q2"])
    assert lin.states == ["Q1", "U1"] and lin.locked == ["Q2"]
    assert lin.steady and lin.point["Q2"] == b
    assert np.allclose(lin.eigenvalues(), [-1j * w, 1j * w], rtol=1e-13)
    # unlocked, the same point is no equilibrium: the second link swings down
    free = model.linearize({"Q1": -math.atan2(cy, cx), "Q2": b})
    assert free.states == ["Q1", "Q2", "U1", "U2"] and not free.steady


def test_only_a_coordinate_with_its_own_speed_can_be_locked(tmp_path):
    path = tmp_path / "double.al"
    path.write_text(DOUBLE_PENDULUM.replace("Q2' = U2", "Q2' = U2 - U1")
                    .replace("W_B_A> = U2*A3>", "W_B_A> = (U2 - U1)*A3>"))
    model = autolev.load(path)
    with pytest.raises(autolev.runtime.AutolevModelError, match="Q2' = U for an independent"):
        model.linearize(locked=["Q2"])
    with pytest.raises(autolev.runtime.AutolevModelError, match="'G' is not a coordinate"):
        model.linearize(locked=["G"])


def test_symbolic_a_and_b_by_hand(pendulum):
    lin = pendulum.linearize_symbolic()
    g, length, m, q = (pendulum.quantity(n) for n in ("G", "L", "M", "Q"))
    assert lin.states == ["Q", "U"] and lin.inputs == ["TQ"]
    assert sm.simplify(lin.A - sm.Matrix([[0, 1], [-g / length * sm.cos(q), 0]])) == \
        sm.zeros(2, 2)
    assert sm.simplify(lin.B - sm.Matrix([0, 1 / (m * length ** 2)])) == sm.zeros(2, 1)


def test_symbolic_jacobians_agree_with_the_numbers(tmp_path):
    path = tmp_path / "double.al"
    path.write_text(DOUBLE_PENDULUM)
    model = autolev.load(path)
    point = {"Q1": 0.3, "Q2": -0.5, "U1": 0.7, "U2": 0.2}
    constants = {"G": 9.81, "L1": 1.5, "L2": 0.7, "M1": 2, "M2": 3}
    numeric = model.linearize(point)
    symbolic = model.linearize_symbolic(dict(point, **constants))
    assert symbolic.states == numeric.states
    assert np.allclose(np.array(symbolic.A, dtype=float), numeric.A, rtol=0, atol=1e-12)
    held = model.linearize_symbolic(locked=["Q2"])        # one body: no U1 in its A
    assert held.states == ["Q1", "U1"] and sm.simplify(held.A[1, 1]) == 0
    with pytest.raises(autolev.runtime.AutolevModelError, match="at most 2 states"):
        model.linearize_symbolic(max_states=2)


def test_the_command_locks_and_names_constraints(tmp_path, capsys):
    from autolev.cli import main
    path = tmp_path / "double.al"
    path.write_text(DOUBLE_PENDULUM + "LOOP = L1*SIN(Q1)\n")
    assert main(["linearize", str(path), "--lock", "Q2"]) == 0
    assert capsys.readouterr().out.startswith("2 states (Q1, U1)")
    assert main(["linearize", str(path), "--constraint", "NOPE"]) == 2
    assert "--constraint NOPE: the model has no quantity" in capsys.readouterr().err
    # L1 sin(Q1) = 0 fixes Q1 (at 0): the state is Q2 and the two speeds
    assert main(["linearize", str(path), "--constraint", "LOOP", "--dependent", "Q1"]) == 0
    assert capsys.readouterr().out.startswith("3 states (Q2, U1, U2)")


CART = """NEWTONIAN N
FRAMES A
PARTICLES C, P
MOTIONVARIABLES' X'', Q''
CONSTANTS G, L, MC, MP
SIMPROT(N, A, 3, Q)
P_NO_C> = X*N1>
P_C_P> = L*A1>
V_C_N> = DT(P_NO_C>, N)
V_P_N> = DT(P_NO_C> + P_C_P>, N)
MASS C = MC, P = MP
GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
KANE()
INPUT G = 9.81, L = 0.5, MC = 2, MP = 1
CODE DYNAMICS() cart.c
"""


def test_eigenvalues_show_roundoff_as_zero_and_name_the_ignorable_coordinate(tmp_path):
    # a pendulum (gravity along N1) on a free cart: the cart's position is ignorable;
    # by hand, the swing's frequency is sqrt(g (mc + mp) / (mc L))
    path = tmp_path / "cart.al"
    path.write_text(CART.replace("GRAVITY(G*N1>)", "GRAVITY(G*N2>)"))
    lin = autolev.load(path).linearize({"X": 0, "Q": math.pi / 2})   # hanging
    rows = [row.split(",") for row in lin.eigenvalue_table().splitlines()[1:]]
    w = math.sqrt(9.81 * 3 / (2 * 0.5))
    swing = [complex(float(r[0]), float(r[1])) for r in rows if r[1] != "0"]
    assert swing == pytest.approx([-1j * w, 1j * w], rel=1e-12)
    zeros = [r for r in rows if r[:2] == ["0", "0"]]
    assert len(zeros) == 2                   # X and its speed: a double zero, shown as 0
    assert any(r[4] == "X is ignorable (nothing depends on it)" for r in zeros)
    assert 1e-9 < lin.zero_tolerance() < 1e-5


TWO_SPRINGS = """NEWTONIAN N
PARTICLES P1, P2
MOTIONVARIABLES' X1'', X2''
CONSTANTS K1, K2, M, C
P_NO_P1> = X1*N1>
P_NO_P2> = X2*N2>
MASS P1 = M, P2 = M
FORCE_P1> = -K1*X1*N1> - C*X1'*N1>
FORCE_P2> = -K2*X2*N2> - C*X2'*N2>
ZERO = FR() + FRSTAR()
KANE()
INPUT K1 = 1, K2 = 4, M = 1, C = 0.01
CODE DYNAMICS() springs.c
"""


def test_a_sweep_follows_each_mode_across_a_crossing(tmp_path, capsys):
    # two uncoupled oscillators of equal damping: as K1 passes K2 = 4 their frequencies
    # cross, and sorted by value the columns would swap; by hand, the first
    # oscillator's eigenvalues are -C/2M +- i sqrt(K1/M - (C/2M)^2) all along
    from autolev.cli import main
    path = tmp_path / "springs.al"
    path.write_text(TWO_SPRINGS)
    assert main(["linearize", str(path), "--sweep", "K1=1:9:10"]) == 0
    rows = [[float(x) for x in line.split(",")]
            for line in capsys.readouterr().out.splitlines()[1:]]
    first = [k for k in range(4) if math.isclose(abs(rows[0][2 + 2 * k]), 1, rel_tol=1e-3)]
    assert len(first) == 2                    # the first oscillator's pair, at K1 = 1
    for row in rows:
        w = math.sqrt(row[0] - 0.005 ** 2)
        assert [row[1 + 2 * k] for k in first] == pytest.approx([-0.005] * 2, abs=1e-9)
        assert sorted(row[2 + 2 * k] for k in first) == pytest.approx([-w, w], rel=1e-9)
    # sorted by value the pair would have moved: at K1 = 9 it is the outermost
    last = sorted(rows[-1][2::2])
    assert [last.index(rows[-1][2 + 2 * k]) for k in first] != first


def test_follow_modes_keeps_a_mode_in_its_column_where_sorting_swaps_them():
    from autolev.runtime.studies import follow_modes
    p = np.linspace(0, 1, 11)
    values = np.column_stack([np.minimum(p, 1 - p), np.maximum(p, 1 - p)]).astype(complex)
    # the mode of eigenvalue p is e1, that of 1 - p is e2: sorted, they swap at 0.5
    vectors = np.array([np.eye(2) if pk <= 0.5 else np.eye(2)[:, ::-1] for pk in p],
                       dtype=complex)
    order = follow_modes(values, vectors)
    followed = np.take_along_axis(values, order, axis=1)
    assert np.allclose(followed[:, 0].real, p) and np.allclose(followed[:, 1].real, 1 - p)


def _jacobians_of(model) -> dict:
    """The Jacobians of the model's one linearized system, by tier."""
    systems = [entry[1] for entry in model.derived.table("numeric systems").values()]
    found = {key[-1]: j for system in systems for key, j in system.jacobians.items()}
    return found


def test_one_linearization_waits_for_no_compiler_and_a_large_sweep_compiles(
        tmp_path, monkeypatch):
    # BICYCLE14: one linearization spent 4 minutes in gcc on 11 MB of C, evaluated once
    from autolev.engine import clibrary
    from autolev.runtime.numerics import linearize as linearize_module
    path = tmp_path / "pendulum.al"
    path.write_text(PENDULUM)
    model = autolev.load(path)
    g, L = 9.81, 2.0
    points = [0.1, 0.3, 0.5]
    first = model.linearize({"Q": points[1]})
    # the right-hand side's Python on dual numbers: no Jacobian formed, nothing compiled
    assert {tier: j.rhs.backend for tier, j in _jacobians_of(model).items()} == {
        "dual": "dual"}
    for _ in range(3):                  # however many come after, one stays on dual numbers
        model.linearize({"Q": points[1]})
    assert list(_jacobians_of(model)) == ["dual"]
    if clibrary.compiler() is None:
        pytest.skip("no C compiler: the Jacobians stay on dual numbers (tested above)")
    # compiling set to cost three evaluations (1 + 3 varied: Q, U, TQ; 3/4 of one
    # each): a sweep of three compiles, one of two does not
    monkeypatch.setattr(linearize_module, "C_SECONDS_PER_SOURCE_BYTE",
                        linearize_module.DUAL_SECONDS_PER_SOURCE_BYTE * 3 / 4)
    table = model.sweep([{"Q": q} for q in points], what="linearize", workers=1,
                        as_frame=False, collect=lambda lin: {"a": lin.A[1, 0]})
    assert _jacobians_of(model)["c"].rhs.backend == "c"
    assert np.allclose(table["a"], [-g / L * math.cos(q) for q in points], rtol=1e-14)
    small = model.sweep([{"Q": q} for q in points[:2]], what="linearize", workers=1,
                        as_frame=False, collect=lambda lin: {"a": lin.A[1, 0]})
    assert list(small["a"]) == [model.linearize({"Q": q}).A[1, 0] for q in points[:2]]
    assert np.allclose(first.A, [[0, 1], [-g / L * math.cos(points[1]), 0]], rtol=1e-14)


FUNCTIONS = """NEWTONIAN N
BODIES A
MOTIONVARIABLES' Q{2}', U{2}'
CONSTANTS G, L, M, K
SPECIFIED TQ
SIMPROT(N, A, 3, Q1)
Q1' = U1
Q2' = U2
W_A_N> = U1*A3>
P_NO_AO> = L*A1> + Q2*A2>
V_AO_N> = DT(P_NO_AO>, N)
MASS A = M
INERTIA A, 0, 0, M*L^2/12
GRAVITY(G*N1>)
% a force and a torque through every function the dual numbers differentiate
FORCE_AO> = -K*(SINH(Q2) + ATAN2(Q2, L) + EXP(Q2/5)*LOG(2 + Q2^2) + TANH(U2))*A2>
T1 = TQ - SQRT(1 + U1^2)*ABS(U1) + ASIN(Q2/9) + ACOS(Q2/7) + ATAN(U2) + COSH(Q2/3)
T2 = TAN(Q2/4) + (2 + Q2^2)^(Q2/3) + 3^U1 + (1 + Q1^2)^1.5
TORQUE(A, (T1 + T2)*A3>)
ZERO = FR() + FRSTAR()
KANE()
X = L*COS(Q1) + MAX(Q2, U2)
OUTPUT Q1, X, U2', ASINH(Q2), ACOSH(2 + Q2^2), ATANH(Q2/5)
INPUT G = 9.81, L = 2, M = 3, K = 5, Q1 = 0.3, Q2 = 0.4, U1 = -0.7, U2 = 0.2, TFINAL = 1
CODE DYNAMICS() functions.c
"""


def test_a_point_gets_one_answer_whatever_linearizations_came_before(tmp_path,
                                                                     monkeypatch):
    # the symbolic Jacobians compiled for a sweep differ from dual numbers' by ulps here;
    # they once replaced them for every later linearization of the model
    from autolev.engine import clibrary
    from autolev.runtime.numerics import linearize as linearize_module
    if clibrary.compiler() is None:
        pytest.skip("no C compiler: there is one tier, dual numbers")
    path = tmp_path / "functions.al"
    path.write_text(FUNCTIONS)
    fresh = autolev.load(path).linearize()
    # compiling set to cost three evaluations (1 + 5 varied: Q1, Q2, U1, U2, TQ; half of
    # one each): a sweep of three compiles, one linearization does not
    monkeypatch.setattr(linearize_module, "C_SECONDS_PER_SOURCE_BYTE",
                        linearize_module.DUAL_SECONDS_PER_SOURCE_BYTE / 2)
    model = autolev.load(path)
    model.sweep([{"Q1": 0.3 + 0.1 * k} for k in range(3)], what="linearize", workers=1,
                as_frame=False)
    assert set(_jacobians_of(model)) == {"c"}
    after = model.linearize()
    assert set(_jacobians_of(model)) == {"c", "dual"}
    assert np.array_equal(after.A, fresh.A) and np.array_equal(after.C, fresh.C)
    compiled = autolev.load(path).linearize(backend="c")
    assert not np.array_equal(compiled.A, fresh.A)      # the tiers do differ here
    assert np.allclose(compiled.A, fresh.A, rtol=1e-13, atol=1e-13)


def test_dual_numbers_give_the_symbolic_jacobians(tmp_path):
    # a second method: sympy's derivatives of the same equations, printed and compiled
    path = tmp_path / "functions.al"
    path.write_text(FUNCTIONS)
    model = autolev.load(path)
    dual = model.linearize()
    assert _jacobians_of(model)["dual"].rhs.backend == "dual"
    symbolic = autolev.load(path).linearize(backend="python")
    for m in "ABCD":
        got, want = getattr(dual, m), getattr(symbolic, m)
        assert got.shape == want.shape and np.count_nonzero(want) >= 1
        assert np.allclose(got, want, rtol=1e-12, atol=1e-12), m
    assert np.allclose(dual.rates, symbolic.rates, rtol=1e-14)


def test_a_point_dual_numbers_cannot_differentiate_is_left_to_the_symbolic_form(tmp_path):
    # SQRT(Q) at Q < 0: the math module refuses; the symbolic Jacobians say what C says
    path = tmp_path / "root.al"
    path.write_text(PENDULUM.replace("TORQUE(A, TQ*A3>)", "TORQUE(A, (TQ + SQRT(Q))*A3>)"))
    model = autolev.load(path)
    with pytest.raises(al.AutolevModelError, match="not finite at the operating point"):
        model.linearize({"Q": -0.5})
    systems = [entry[1] for entry in model.derived.table("numeric systems").values()]
    kept = {key[-1] if key[-1] == "symbolic" else "default": j.rhs.backend
            for system in systems for key, j in system.jacobians.items()}
    # the symbolic ones kept apart: a later point dual numbers take is theirs, as it is
    # a fresh model's (an answer must not depend on which point came first)
    assert kept == {"default": "dual", "symbolic": "python"}
    lin = model.linearize({"Q": 0.5})
    g, L, m, q = 9.81, 2.0, 3.0, 0.5
    assert lin.A[1, 0] == pytest.approx(-g / L * math.cos(q)
                                        + 0.5 / math.sqrt(q) / (m * L * L), rel=1e-13)
    assert np.array_equal(lin.A, autolev.load(path).linearize({"Q": 0.5}).A)


def test_a_run_after_a_linearization_compiles_what_the_linearization_did_not(tmp_path):
    path = tmp_path / "pendulum.al"
    path.write_text(PENDULUM)
    model = autolev.load(path)
    model.linearize({"Q": 0.3})
    system = next(iter(model.derived.table("numeric systems").values()))[1]
    assert not system.compiled and system.rhs_function is None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        after = model.simulate(TFINAL=1)
        alone = autolev.load(path).simulate(TFINAL=1)
    assert after.system is system and system.compiled
    assert np.array_equal(after.states, alone.states)


def test_a_sweep_of_a_name_the_model_lacks_is_a_usage_error(tmp_path, capsys):
    from autolev.cli import main
    from helpers import EXAMPLES
    status = main(["linearize", str(EXAMPLES / "double_pendulum.al"), "--sweep",
                   "NOPE=0:1:3"])
    assert status == 2
    assert "--sweep NOPE: the model has no quantity of that name" in capsys.readouterr().err


FREE_CART = """NEWTONIAN N
FRAMES A
PARTICLES C, P, R
MOTIONVARIABLES' X'', Y'', Q'', Z''
CONSTANTS L, MC, MP, K, MR
SIMPROT(N, A, 3, Q)
P_NO_C> = X*N1> + Y*N2>
P_C_P> = L*A1>
P_NO_R> = Z*N3>
V_C_N> = DT(P_NO_C>, N)
V_P_N> = DT(P_NO_C> + P_C_P>, N)
V_R_N> = DT(P_NO_R>, N)
MASS C = MC, P = MP, R = MR
FORCE(C/P, -K*Q*A2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L = 0.5, MC = 2, MP = 1, K = 3, MR = 1
CODE DYNAMICS() cart.c
"""


def test_each_ignorable_coordinate_is_named_once_among_the_zero_eigenvalues(tmp_path):
    # a cart free in the plane with a sprung pendulum, and a particle free along N3: by
    # hand, nothing depends on X, Y or Z (three double zeros); the pendulum pushes the
    # cart along A2 = N2 to first order, so X'' and Z'' are 0 and Y'' is not
    path = tmp_path / "cart.al"
    path.write_text(FREE_CART)
    lin = autolev.load(path).linearize({"X": 0, "Y": 0, "Q": 0, "Z": 0})
    rows = [row.split(",") for row in lin.eigenvalue_table().splitlines()[1:]]
    notes = [r[4] for r in rows if r[:2] == ["0", "0"]]
    assert len(notes) == 6
    assert sorted(notes) == sorted([
        "X is ignorable (nothing depends on it)", "Y is ignorable (nothing depends on it)",
        "Z is ignorable (nothing depends on it)",
        "X' is constant (its rate depends on nothing)",
        "Z' is constant (its rate depends on nothing)", "zero"])


@pytest.mark.parametrize("point", [None, {}])
def test_linearizing_without_an_operating_point_says_where_it_linearized(tmp_path, point):
    path = tmp_path / "cart.al"
    path.write_text(FREE_CART)
    model = autolev.load(path)
    with pytest.warns(UserWarning, match="no operating point given: linearized where the "
                      "INPUT values put the state"):
        lin = model.linearize(point)
    assert lin.point["X"] == 0 and lin.point["Q"] == 0       # no INPUT for them: 0
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        model.linearize({"Q": 0.1})


CHAIN = """NEWTONIAN N
FRAMES A1, A2
PARTICLES P1, P2
MOTIONVARIABLES' Q1'', Q2''
CONSTANTS G, L1, M1, L2, M2
SIMPROT(N, A1, 3, Q1)
P_NO_P1> = 1.0*L1*A11>
V2PTS(N, A1, NO, P1)
MASS P1 = M1
SIMPROT(N, A2, 3, Q2)
P_P1_P2> = 1.0*L2*A21>
V2PTS(N, A2, P1, P2)
MASS P2 = M2
TORQUE(N/A2, -0.25*Q2'*N3>)
TORQUE(N/A1, -0.2*Q1'*N3>)
GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
KANE()
INPUT G = 9.81, L1 = 1.0, L2 = 0.5, M1 = 1.0, M2 = 2.0
INPUT Q1 = 0.3, Q2 = -0.2, Q1' = 0.0, Q2' = 0.0
CODE DYNAMICS() chain.c
"""


def test_a_point_dual_numbers_cannot_take_leaves_the_next_points_answer_as_it_was(tmp_path):
    # bench/fuzz.py --mode stale, seed 1 case 1582: M2 = 0 (a singular mass matrix:
    # dual numbers give no derivative there, the symbolic Jacobians were formed) made
    # them the system's for every later point, and M2 = 0.3's A then differed from a
    # fresh model's by an ulp (the eigenvalues printed otherwise in the 15th digit)
    path = tmp_path / "chain.al"
    path.write_text(CHAIN)
    warnings.simplefilter("ignore")
    model = autolev.load(path)
    with pytest.raises(al.AutolevModelError, match="singular"):
        model.linearize(overrides={"M2": 0})
    after = model.linearize(overrides={"M2": 0.3})
    fresh = autolev.load(path).linearize(overrides={"M2": 0.3})
    assert np.array_equal(np.asarray(after.A, float), np.asarray(fresh.A, float))
