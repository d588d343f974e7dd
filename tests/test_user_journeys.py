"""The first steps users took off the tested paths (issue 29): each test a rule the
commands keep on models of every kind, with values derived independently."""
import math
import subprocess
import sys

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import autolev

# a compound pendulum in the plane N1-N2 whose body keeps a full 3-D INERTIA statement:
# its planar equations read only I33 of the six
PLANAR_FULL_INERTIA = """NEWTONIAN N
BODIES A
MOTIONVARIABLES' Q', U'
CONSTANTS L, M, G, I11, I22, I33, I12, I23, I31
SIMPROT(N, A, 3, Q)
Q' = U
W_A_N> = U*N3>
P_NO_AO> = L*A1>
V_AO_N> = DT(P_NO_AO>, N)
MASS A = M
INERTIA A, I11, I22, I33, I12, I23, I31
GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
KANE()
INPUT L=1.5, M=2, G=9.81, I33=0.3, Q=40 DEG, U=0, TFINAL=2, INTEGSTP=0.05
OUTPUT T, Q, U
CODE DYNAMICS() planar.c
"""


def cli(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "autolev", *map(str, args)],
                          capture_output=True, text=True, cwd=cwd)


def compound_pendulum(t_end, q0, m=2.0, length=1.5, g=9.81, i33=0.3):
    """Q(t), U(t) of (I33 + M L^2) Q'' = -M G L sin Q, integrated by scipy alone."""
    k = m * g * length / (i33 + m * length ** 2)
    sol = solve_ivp(lambda t, y: [y[1], -k * math.sin(y[0])], (0, t_end), [q0, 0.0],
                    rtol=1e-11, atol=1e-12, dense_output=True)
    return sol.sol


@pytest.fixture
def planar(tmp_path):
    path = tmp_path / "planar.al"
    path.write_text(PLANAR_FULL_INERTIA)
    return path


def test_a_planar_model_with_a_full_inertia_runs_without_the_constants_it_never_reads(
        planar, tmp_path):
    # I11, I22, I12, I23, I31 have no value anywhere: the run reads none of them, so
    # the check of the inertia must not judge values it would have to invent
    r = cli("run", planar, "--out", tmp_path / "out")
    assert r.returncode == 0, r.stderr
    rows = np.loadtxt(tmp_path / "out" / "planar.1", comments="%")
    exact = compound_pendulum(2.0, math.radians(40))
    assert np.allclose(rows[:, 1:], exact(rows[:, 0]).T, atol=1e-6)


def test_products_of_inertia_the_run_never_reads_do_not_refuse_it(planar):
    # given values that make the 3-D inertia indefinite: a planar run never sees them
    text = PLANAR_FULL_INERTIA.replace("I33=0.3,", "I33=0.3, I11=0.1, I22=0.1, I12=5,")
    planar.write_text(text)
    r = autolev.load(planar).simulate()
    assert r.ok
    exact = compound_pendulum(2.0, math.radians(40))
    assert np.allclose(r.states[-1], exact(2.0), atol=1e-6)


def test_an_inertia_the_run_reads_is_still_judged(planar):
    # I33 is in the planar equations: a negative one is refused before the build
    planar.write_text(PLANAR_FULL_INERTIA.replace("I33=0.3", "I33=-4"))
    with pytest.raises(autolev.runtime.AutolevModelError,
                       match="body A has principal inertias -4"):
        autolev.load(planar).simulate()


# a unit mass on a unit spring driven by a SPECIFIED force the model leaves undefined
DRIVEN = """NEWTONIAN N
PARTICLES P
MOTIONVARIABLES' X', V'
CONSTANTS M, K
SPECIFIED F
X' = V
P_NO_P> = X*N1>
V_P_N> = V*N1>
MASS P = M
FORCE(P, (F - K*X)*N1>)
ZERO = FR() + FRSTAR()
KANE()
INPUT M=1, K=1, X=0, V=0, TFINAL=2, INTEGSTP=0.25
OUTPUT T, X, F
CODE DYNAMICS() driven.c
"""


@pytest.fixture
def driven(tmp_path):
    path = tmp_path / "driven.al"
    path.write_text(DRIVEN)
    return path


def rows_of(path):
    return np.loadtxt(path, comments="%", ndmin=2)


def test_set_gives_a_specified_quantity_a_constant_value(driven, tmp_path):
    # X'' + X = 2 from rest: X = 2 (1 - cos T)
    r = cli("run", driven, "--set", "F=2", "--out", tmp_path / "o")
    assert r.returncode == 0, r.stderr
    assert "ignored" not in r.stderr and "set to 0" not in r.stderr
    rows = rows_of(tmp_path / "o" / "driven.1")
    assert np.allclose(rows[:, 1], 2 * (1 - np.cos(rows[:, 0])), atol=1e-7)
    assert np.all(rows[:, 2] == 2)


def test_specified_gives_a_function_of_time(driven, tmp_path):
    # X'' + X = 3 sin 2T from rest: X = 2 sin T - sin 2T
    r = cli("run", driven, "--specified", "F=3*SIN(2*T)", "--out", tmp_path / "o")
    assert r.returncode == 0, r.stderr
    t, x, f = rows_of(tmp_path / "o" / "driven.1").T
    assert np.allclose(x, 2 * np.sin(t) - np.sin(2 * t), atol=1e-7)
    assert np.allclose(f, 3 * np.sin(2 * t), atol=1e-12)


def test_the_api_takes_the_same_values(driven):
    model = autolev.load(driven)
    by_override = model.simulate(F=2)
    by_value = model.simulate(specified={"F": 2.0})
    t = by_value.t
    assert np.allclose(by_override["X"], 2 * (1 - np.cos(t)), atol=1e-7)
    assert np.allclose(by_value["X"], by_override["X"], atol=1e-12)


def test_a_specified_expression_of_the_state_is_linearized_with_it(driven):
    # F = -3 X: X'' = -4 X, eigenvalues +-2i; F is then no input of B
    r = cli("linearize", driven, "--specified", "F=-3*X")
    assert r.returncode == 0, r.stderr
    assert "inputs: none" in r.stdout
    rows = [line.split(",") for line in r.stdout.splitlines()[2:]]
    assert sorted(float(im) for _, im, *_ in rows) == pytest.approx([-2, 2])
    assert all(abs(float(re)) < 1e-12 for re, *_ in rows)


def test_an_algebraic_output_of_a_specified_quantity_takes_its_value(tmp_path):
    path = tmp_path / "alg.al"
    path.write_text("SPECIFIED F\nCONSTANTS C\nY = C*F^2\nINPUT C=3\nOUTPUT Y\n"
                    "CODE ALGEBRAIC() alg.c\n")
    r = cli("run", path, "--set", "F=2", "--out", tmp_path / "o")
    assert r.returncode == 0, r.stderr
    assert rows_of(tmp_path / "o" / "alg.1")[0, 0] == 12


@pytest.mark.parametrize("value, message", [
    ("M=3", "M is not a SPECIFIED quantity of the model that it leaves undefined"),
    ("F=3*SIN(2*T", "expected ')'"),
    ("F=N1>", "a vector cannot be a specified quantity's value"),
    ("F=3*Q9", "Q9 is not a quantity of the model"),
])
def test_a_value_that_cannot_be_a_specified_one_is_a_usage_error(driven, tmp_path, value,
                                                                   message):
    r = cli("run", driven, "--specified", value, "--out", tmp_path / "o")
    assert r.returncode == 2
    assert message in r.stderr and "--specified:1:" in r.stderr
    assert not (tmp_path / "o").exists()


def test_run_and_code_read_the_time_of_an_algebraic_program_alike(tmp_path):
    path = tmp_path / "clock.al"
    path.write_text("CONSTANTS A\nY = A*T\nZ = A^2\nINPUT A=2\nOUTPUT Y, Z\n"
                    "CODE ALGEBRAIC() clock.c\n")
    note = ("CODE ALGEBRAIC clock.c: Y depends on T, which a program without time reads "
            "from its .in file as it reads its variables: T = 0")
    ran = cli("run", path, "--out", tmp_path / "run")
    assert ran.returncode == 0 and note in ran.stderr
    assert rows_of(tmp_path / "run" / "clock.1").tolist() == [[0.0, 4.0]]
    given = cli("run", path, "--set", "T=3", "--out", tmp_path / "given")
    assert given.returncode == 0 and note not in given.stderr
    assert rows_of(tmp_path / "given" / "clock.1").tolist() == [[6.0, 4.0]]
    coded = cli("code", path, "--out", tmp_path / "code")
    assert coded.returncode == 0 and note in coded.stderr
    # the program reads T after A, as the run's .in file lists it
    in_lines = (tmp_path / "given" / "clock.in").read_text().splitlines()
    assert [line[21:42].strip() for line in in_lines
            if line.startswith("Constant")] == ["A", "T"]
    program = (tmp_path / "code" / "clock.c").read_text()
    assert "readf(Fptr[0],&A,&T,NULL);" in program


# SymPy's examples name a torque T: declared, it is the model's quantity, not the time
TORQUE_T = DRIVEN.replace("SPECIFIED F", "SPECIFIED T").replace("(F - K*X)", "(T - K*X)") \
    .replace("OUTPUT T, X, F", "OUTPUT T, X")


def test_a_declared_t_is_named_at_its_declaration_in_check_and_run(tmp_path):
    path = tmp_path / "torque.al"
    path.write_text(TORQUE_T)
    warning = (f"{path}:5:11: warning: 'T' is declared as a specified quantity: in this "
               "model T is that specified quantity, not the time")
    checked = cli("check", path)
    assert checked.returncode == 0 and warning in checked.stdout + checked.stderr
    ran = cli("run", path, "--set", "T=2", "--out", tmp_path / "o")
    assert ran.returncode == 0 and warning in ran.stderr
    # OUTPUT T prints the torque; X'' + X = 2 from rest is 2 (1 - cos t) at the run's t
    rows = rows_of(tmp_path / "o" / "driven.1")
    t = np.arange(len(rows)) * 0.25
    assert np.all(rows[:, 0] == 2)
    assert np.allclose(rows[:, 1], 2 * (1 - np.cos(t)), atol=1e-7)


def test_a_run_is_plotted_against_its_time_not_a_column_named_t(tmp_path):
    pytest.importorskip("matplotlib")
    from autolev.plots import figure
    path = tmp_path / "torque.al"
    path.write_text(TORQUE_T)
    r = autolev.load(path).simulate(T=2)
    fig = figure(r.outputs[0], r.t)
    lines = {line.get_label(): line for ax in fig.axes for line in ax.get_lines()}
    assert set(lines) == {"T", "X"}            # the torque is data, not the axis
    assert np.array_equal(lines["X"].get_xdata(), r.t) and r.t[-1] == 2.0
    assert fig.axes[-1].get_xlabel() == "time"


def test_the_time_column_is_the_axis_and_not_drawn(driven):
    pytest.importorskip("matplotlib")
    from autolev.plots import figure
    r = autolev.load(driven).simulate(F=2)
    fig = figure(r.outputs[0], r.t)
    assert {line.get_label() for ax in fig.axes for line in ax.get_lines()} == {"X", "F"}
    assert fig.axes[-1].get_xlabel() == "T"


def test_check_reports_in_one_round(tmp_path):
    # a syntax error no longer hides the translation's findings on the lines that read,
    # and a name whose declaration did not read is not reported again
    path = tmp_path / "rounds.al"
    path.write_text("NEWTONIAN N\nBODIES A\nMOTIONVARIABLES' Q', U'\nCONSTANTS L, K M\n"
                    "SIMPORT(N, A, 3, Q)\nQ' = U\nX = SINN(Q) + M\nCODE DYNAMIC() r.c\n")
    r = cli("check", path)
    found = [line for line in (r.stdout + r.stderr).splitlines() if ": error: " in line]
    assert r.returncode == 1
    assert [f.split(": error: ")[0] for f in found] == [
        f"{path}:4:16", f"{path}:5:1", f"{path}:7:5", f"{path}:8:6"]
    assert "unknown command SIMPORT(): not one of Autolev's, and no macro file simport.a " \
        "(any case) next to rounds.al; did you mean SIMPROT?" in found[1]
    assert "did you mean SIN, SINH or SIGN?" in found[2]
    assert "unknown CODE kind 'DYNAMIC'" in found[3]


def test_a_call_of_a_missing_macro_says_which_file_was_looked_for(tmp_path):
    # CONTACT() meant contact.a, which is not beside the model: the file is what is missing
    path = tmp_path / "m.al"
    path.write_text("NEWTONIAN N\nCONTACT()\n")
    r = cli("check", path)
    assert r.returncode == 1
    assert f"{path}:2:1: error: unknown command CONTACT(): not one of Autolev's, and no " \
        "macro file contact.a (any case) next to m.al" in r.stdout + r.stderr
    (tmp_path / "CONTACT.A").write_text("% a macro of nothing\n")
    assert cli("check", path).returncode == 0


@pytest.mark.parametrize("command", ["run", "linearize", "animate"])
def test_a_value_that_is_not_a_number_is_a_usage_error(driven, tmp_path, command):
    r = cli(command, driven, "--set", "X=abc", "--out", tmp_path / "o")
    assert r.returncode == 2
    assert "--set X=abc: abc is not a finite number" in r.stderr


# a kinematics model: bodies with no mass, no Kane's equations; UA' declared, never
# defined, is a constant the program reads
KINEMATICS = """NEWTONIAN N
BODIES A, D
POINTS G
VARIABLES Q1'', X'
VARIABLES UA'
CONSTANTS R
SIMPROT(N, A, 3, Q1)
SIMPROT(A, D, 1, Q1)
Q1' = UA
W_A_N> = UA*N3>
P_NO_G> = R*A1>
V_G_N> = DT(P_NO_G>, N)
X' = DOT(V_G_N>, N1>)
INPUT R=2, UA=3, Q1=0, X=0, UA'=0.5, TFINAL=1, INTEGSTP=0.25
OUTPUT T, Q1, X, UA
CODE ODE() kin.c
"""


def test_code_ode_integrates_the_explicit_equations_and_forms_nothing_else(tmp_path):
    path = tmp_path / "kin.al"
    path.write_text(KINEMATICS)
    r = cli("run", path, "--out", tmp_path / "o")
    assert r.returncode == 0, r.stderr
    t, q1, x, ua = rows_of(tmp_path / "o" / "kin.1").T
    # UA' = 1/2: UA = 3 + T/2, Q1 = 3T + T^2/4; X' = -R sin(Q1) Q1': X = R (cos Q1 - 1)
    assert np.allclose(ua, 3 + t / 2, atol=1e-9)
    assert np.allclose(q1, 3 * t + t ** 2 / 4, atol=1e-7)
    assert np.allclose(x, 2 * (np.cos(q1) - 1), atol=1e-6)
    in_text = (tmp_path / "o" / "kin.in").read_text()
    assert "Constant             UA'" in in_text


@pytest.mark.skipif(not __import__("shutil").which("cc"), reason="needs a C compiler (cc)")
def test_the_program_of_code_ode_reads_the_undefined_derivative(tmp_path):
    path = tmp_path / "kin.al"
    path.write_text(KINEMATICS)
    assert cli("run", path, "--out", tmp_path / "run").returncode == 0
    assert cli("code", path, "--out", tmp_path / "prog").returncode == 0
    program = (tmp_path / "prog" / "kin.c").read_text()
    assert "readf(Fptr[0],&R,&UAp,NULL);" in program and "double   Q1p,Xp;" in program
    subprocess.run(["cc", "-O0", "-o", "kin", "kin.c", "-lm"], cwd=tmp_path / "prog",
                   check=True)
    (tmp_path / "prog" / "kin.in").write_text((tmp_path / "run" / "kin.in").read_text())
    subprocess.run(["./kin"], cwd=tmp_path / "prog", check=True, capture_output=True)
    assert np.array_equal(rows_of(tmp_path / "prog" / "kin.1"),
                          rows_of(tmp_path / "run" / "kin.1"))


@pytest.mark.parametrize("command", [["run"], ["linearize"], ["convert", "--to", "sympy"]])
def test_an_input_file_that_is_not_there_is_a_usage_error(tmp_path, command):
    # the command line names a file that is not there: exit 2 before the model is read
    path = tmp_path / "m.al"
    path.write_text("NEWTONIAN N\n")
    r = cli(*command, path, "--in", tmp_path / "gone.in")
    assert r.returncode == 2
    assert f"--in {tmp_path / 'gone.in'}: no such file" in r.stderr


@pytest.mark.parametrize("command", [["run"], ["linearize"], ["code"], ["equations"],
                                     ["transcript"], ["convert", "--to", "sympy"],
                                     ["convert"]])
def test_every_command_shows_the_errors_check_shows(tmp_path, command):
    # a syntax error (line 4) and, on lines that read, an unknown function and an unknown
    # CODE kind: each command stops with all three, as check lists them
    path = tmp_path / "three.al"
    path.write_text("NEWTONIAN N\nBODIES A\nMOTIONVARIABLES' Q', U'\nCONSTANTS L, K M\n"
                    "SIMPROT(N, A, 3, Q)\nQ' = U\nX = SINN(Q) + M\nZERO = FR() + FRSTAR()\n"
                    "KANE()\nCODE DYNAMIC() r.c\n")
    r = cli(*command, path, cwd=tmp_path)
    assert r.returncode == 1
    found = [line.split(": error: ")[0] for line in r.stderr.splitlines() if ": error: " in line]
    assert found == [f"{path}:4:16", f"{path}:7:5", f"{path}:10:6"]
