"""`autolev convert --to sympy` at the mechanics level (issue 33): each shipped example the
level takes becomes frames, points, bodies, loads and a KanesMethod in a script that needs
only sympy, numpy and scipy.  Run with autolev unimportable, its mass matrix and forcing
equal our own Kane's equations' at 20 random states and constants, and `python OUT.py`
writes `autolev run`'s rows over 1 s (same method and tolerances)."""
import runpy
from pathlib import Path

import pytest
import sympy as sm

import autolev
from autolev.cli import main
from autolev.export_mechanics import export_sympy
from autolev.runtime.interop import simple_rotation
from autolev.engine.errors import AutolevModelError
from helpers import EXAMPLES
from helpers.sympy_scripts import equations_difference, rows_difference, run_script

# fourbar, rolling_disc and whipple_benchmark have dependent speeds, fourbar auxiliary ones
MECHANICS = ["simple_pendulum", "double_pendulum", "cart_pendulum", "mass_spring_damper",
             "block_pendulums", "nlink_pendulum", "euler_parameters_body", "fourbar",
             "rolling_disc", "whipple_benchmark"]
# tolerances at which two integrators (ours of the independent speeds, the script's of
# sympy's dependent ones too) follow the same motion to 1e-6
OVER_1S = {"TFINAL": 1, "ABSERR": 1e-10, "RELERR": 1e-10}
# the linkage straightens at T = 0.93 (Q2 = 0, Q3 = 180 deg): its dependent speeds are
# singular there, and both integrations stop
SHORTER = {"fourbar": 0.9}


def over(name: str) -> dict:
    return OVER_1S | {"TFINAL": SHORTER.get(name, 1)}


def exported(name: str, folder, *options) -> Path:
    out = folder / f"{name}_sympy.py"
    assert main(["convert", "--to", "sympy", str(EXAMPLES / f"{name}.al"), "-o", str(out),
                 "-q", *[f"--set={k}={v}" for k, v in over(name).items()], *options]) == 0
    return out


def script_of(folder, name: str, text: str) -> str:
    """The SymPy script of a model written here (`text`, saved as `name`)."""
    path = folder / name
    path.write_text(text)
    return export_sympy(autolev.load(path), name)


@pytest.mark.parametrize("name", MECHANICS)
def test_the_scripts_kane_equals_our_equations_and_runs_as_autolev_run(name, tmp_path):
    script = exported(name, tmp_path)
    assert "\nLevel: mechanics." in script.read_text()
    model = autolev.load(EXAMPLES / f"{name}.al")
    found = run_script(script, tmp_path / "rows.csv")
    assert found["level"] == "mechanics"
    assert equations_difference(model, model.code_commands[0], found) <= 1e-10
    assert rows_difference(model, tmp_path / "rows.csv", **over(name)) <= 1e-6


@pytest.mark.parametrize("schedule, times", [
    # a step while T + INTEGSTP/100 falls short of TFINAL: the last row passes TFINAL
    ("TFINAL=0.25 INTEGSTP=0.1 PRINTINT=1", [0, 0.1, 0.2, 0.3]),
    ("TFINAL=0.5 INTEGSTP=0.1 PRINTINT=2", [0, 0.2, 0.4, 0.5]),
    ("TFINAL=1 INTEGSTP=1500 PRINTINT=1", [0]),          # SSOpt's 1500 s step: no step
])
def test_the_script_prints_the_rows_autolevs_programs_print(schedule, times, tmp_path):
    # the runner printed every INTEGSTP*PRINTINT and at TFINAL: a row more than Autolev
    settings = [f"--set={item}" for item in schedule.split()]
    out = tmp_path / "simple_pendulum_sympy.py"
    assert main(["convert", "--to", "sympy", str(EXAMPLES / "simple_pendulum.al"), "-o",
                 str(out), "-q", *settings]) == 0
    run_script(out, tmp_path / "rows.csv")
    written = [float(line.split(",")[0]) for line in
               (tmp_path / "rows.csv").read_text().splitlines()[1:]]
    assert written == pytest.approx(times, abs=1e-12)
    model = autolev.load(EXAMPLES / "simple_pendulum.al")
    inputs = dict(item.split("=") for item in schedule.split())
    assert list(model.simulate(**{k: float(v) for k, v in inputs.items()}).t) == \
        pytest.approx(times, abs=1e-12)


def test_asking_the_mechanics_level_of_a_model_it_does_not_take_is_refused_writing_nothing(
        tmp_path, capsys):
    out, model = tmp_path / "x.py", tmp_path / "extra.al"
    model.write_text(EXTRA_TERM)
    assert main(["convert", "--to", "sympy", "--level", "mechanics", str(model),
                 "-o", str(out)]) == 1
    err = capsys.readouterr().err
    assert "the mechanics level does not take this model" in err
    assert "they are not FR() + FRSTAR() alone" in err
    assert not out.exists()
    assert main(["convert", "--level", "mechanics", str(model)]) == 2
    assert "--level chooses the level of a --to sympy script" in capsys.readouterr().err


def test_the_equations_level_is_there_by_option(tmp_path):
    text = exported("double_pendulum", tmp_path, "--level", "equations").read_text()
    assert "\nLevel: equations." in text and "Not the mechanics level" not in text
    assert "system = me.SymbolicSystem(" in text


def test_a_simple_rotation_is_an_axis_and_its_angle():
    # SIMPROT(N, A, 2, Q): A3> = cos(Q) N3> + sin(Q) N1>, so N.dcm(A)[0, 2] = sin(Q)
    q = sm.Symbol("Q")
    c, s = sm.cos(q), sm.sin(q)
    about_y = sm.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    assert simple_rotation(about_y) == (1, q)
    assert simple_rotation(about_y.T) == (1, -q)
    assert simple_rotation(sm.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])) == (2, q)
    assert simple_rotation(sm.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])) == (0, q)
    assert simple_rotation(about_y * sm.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])) is None


EXTRA_TERM = """NEWTONIAN N
PARTICLES P
MOTIONVARIABLES' X', U'
CONSTANTS M, K
X' = U
P_NO_P> = X*N1>
V_P_N> = U*N1>
MASS P = M
ZERO = FR() + FRSTAR()
ZERO[1] = ZERO[1] - K*X
KANE()
INPUT M = 1, K = 2, X = 1, U = 0, TFINAL = 1
OUTPUT X
CODE DYNAMICS() extra.c
"""


def test_equations_beyond_fr_plus_frstar_are_not_written_as_sympys_kane(tmp_path):
    # ZERO has a spring term no load gives: KanesMethod on the bodies and loads would drop
    # it, so auto writes the equations, and mechanics is refused
    text = script_of(tmp_path, "extra.al", EXTRA_TERM)
    assert "Not the mechanics level: sympy's KanesMethod on the model's bodies and loads " \
           "does not give the equations the run integrates" in " ".join(text.split())
    with pytest.raises(AutolevModelError, match="does not give the equations"):
        export_sympy(autolev.load(tmp_path / "extra.al"), "extra.al", level="mechanics")


def test_the_rate_of_a_specified_quantity_is_its_derivative_in_sympys_kane(tmp_path):
    # a pendulum on a base moving as PX(t) along N1 (dogtail's base), gravity along -N1:
    # by Lagrange's equations, by hand, M L^2 Q'' = M L (G + PX'') sin Q; PX'' is
    # px(t).diff(t, 2) for KanesMethod
    path = tmp_path / "base.al"
    path.write_text("NEWTONIAN N\nFRAMES A\nPARTICLES P\nPOINTS B\nMOTIONVARIABLES' Q'\n"
                    "SPECIFIED PX''\nCONSTANTS M, L, G\nSIMPROT(N, A, 3, Q)\n"
                    "W_A_N> = Q'*N3>\nP_NO_B> = PX*N1>\nP_B_P> = L*A1>\n"
                    "V_P_N> = DT(P_NO_P>, N)\nA_P_N> = DT(V_P_N>, N)\nMASS P = M\n"
                    "GRAVITY(-G*N1>)\nZERO = FR() + FRSTAR()\nKANE()\n"
                    "INPUT M = 2, L = 1.5, G = 9.81, Q = 0.4, Q' = 0, TFINAL = 1\n"
                    "OUTPUT T, Q\nCODE DYNAMICS() base.c\n")
    script = tmp_path / "base_sympy.py"
    script.write_text(export_sympy(autolev.load(path), "base.al"))
    text = script.read_text()
    assert "\nLevel: mechanics." in text and "PXpp = PX.diff(t, 2)" in text
    ns = runpy.run_path(str(script))
    t, q, m, lk, g = (ns[n] for n in ("t", "Q", "M", "L", "G"))
    u, = ns["kane"].u
    px = ns["PX"]
    mass = sm.diag(1, m * lk ** 2)
    forcing = sm.Matrix([u, m * lk * (g + px.diff(t, 2)) * sm.sin(q)])
    assert sm.simplify(ns["full_mass"] - mass) == sm.zeros(2, 2)
    assert sm.simplify(ns["full_forcing"] - forcing) == sm.zeros(2, 1)
    assert set(ns["specified"]) == {px.diff(t, 2)}
    # at random values of PX'' too, and integrated as `autolev run` does
    model = autolev.load(path)
    found = run_script(script, tmp_path / "rows.csv")
    assert found["specified"] == ["PX''"]
    assert equations_difference(model, model.code_commands[0], found) <= 1e-10
    assert rows_difference(model, tmp_path / "rows.csv") <= 1e-6


def test_the_first_seed_systems_script_gives_sympys_published_equations(tmp_path):
    # shared/seed-systems.md 1: block, compound and simple pendulum, symbolically
    ns = runpy.run_path(str(exported("block_pendulums", tmp_path, "--level", "mechanics")))
    q1, q2, q3, u1, u2, u3 = (ns[n] for n in ("Q1", "Q2", "Q3", "U1", "U2", "U3"))
    ma, mb, mc, ibzz, lk, g, k, c, kt, force, torque = (
        ns[n] for n in ("MA", "MB", "MC", "IBZZ", "L", "G", "K", "CDAMP", "KT", "F", "TQ"))
    cos, sin = sm.cos, sm.sin
    m12 = 2 * lk * mb * cos(q2) / 3 + mc * (lk * cos(q2 + q3) + lk * cos(q2))
    m13, m23 = lk * mc * cos(q2 + q3), mc * (lk ** 2 * cos(q3) + lk ** 2)
    mass = sm.Matrix([[ma + mb + mc, m12, m13],
                      [m12, ibzz + 4 * lk ** 2 * mb / 9 + mc * (2 * lk ** 2 * cos(q3)
                                                                + 2 * lk ** 2), m23],
                      [m13, m23, lk ** 2 * mc]])
    forcing = sm.Matrix([
        -c * u1 - k * q1 + sm.Rational(2, 3) * lk * mb * u2 ** 2 * sin(q2)
        + lk * mc * sin(q2 + q3) * (u2 + u3) ** 2 + lk * mc * u2 ** 2 * sin(q2) + force,
        -sm.Rational(2, 3) * g * lk * mb * sin(q2) - g * lk * mc * sin(q2 + q3)
        - g * lk * mc * sin(q2) + lk ** 2 * mc * (u2 + u3) ** 2 * sin(q3)
        - lk ** 2 * mc * u2 ** 2 * sin(q3) + torque,
        -g * lk * mc * sin(q2 + q3) - kt * q3 - lk ** 2 * mc * u2 ** 2 * sin(q3)])
    kane = ns["kane"]
    assert list(kane.q) + list(kane.u) == [q1, q2, q3, u1, u2, u3]
    assert sm.simplify(kane.mass_matrix_full - sm.diag(sm.eye(3), mass)) == sm.zeros(6, 6)
    assert sm.simplify(kane.forcing_full - sm.Matrix([u1, u2, u3, *forcing])) == \
        sm.zeros(6, 1)


def test_the_second_seed_systems_script_gives_sympys_published_closing_force(tmp_path):
    # shared/seed-systems.md 2: the four-bar's auxiliary speeds in sympy's KanesMethod
    # reveal the force at the closing joint: [F1, F2] = [0, -98.1] at rest, links upright
    text = exported("fourbar", tmp_path, "--level", "mechanics").read_text()
    assert "u_dependent=dependent, velocity_constraints=velocity_constraints, " \
           "constraint_solver='CRAMER', u_auxiliary=auxiliary" in text
    ns = runpy.run_path(str(tmp_path / "fourbar_sympy.py"))
    kane, t = ns["kane"], ns["t"]
    speeds = list(kane.u) + ns["auxiliary"]
    at_rest = {u.diff(t): 0 for u in speeds} | dict.fromkeys(speeds, 0)
    upright = dict.fromkeys(kane.q, sm.pi / 2) | {
        ns[n]: v for n, v in dict(L1=2, L2=1, L3=2, L4=1, RHO=5, G=sm.Rational(981, 100))
        .items()}
    equations = kane.auxiliary_eqs.xreplace(at_rest).xreplace(upright)
    forces = sm.solve(equations, [ns["F1"], ns["F2"]])
    assert forces == {ns["F1"]: 0, ns["F2"]: -sm.Rational(981, 10)}


def test_each_object_says_the_statements_it_comes_from(tmp_path):
    lines = exported("fourbar", tmp_path).read_text().splitlines()

    def said_before(code: str) -> list[str]:
        at = next(k for k, line in enumerate(lines) if line.strip().startswith(code))
        k = at
        while lines[k - 1].strip().startswith("# fourbar.al:"):
            k -= 1
        return [line.strip()[2:] for line in lines[k:at]]
    assert said_before("B3 = me.ReferenceFrame") == [
        "fourbar.al:20: SIMPROT(B2, B3, 3, Q2)", "fourbar.al:26: W_B3_B2> = U2*N3>"]
    assert said_before("P3.set_pos(P2") == ["fourbar.al:31: P_P2_P3> = L2*B21>"]
    assert said_before("B4O.set_vel(N") == ["fourbar.al:42: V2PTS(N, B4, P4, B4O)"]
    assert said_before("B3_body = ") == ["fourbar.al:14: MASS B2 = RHO*L2, B3 = RHO*L3, "
                                         "B4 = RHO*L4", "fourbar.al:16: INERTIA B3, 0, 0, "
                                         "RHO*L3^3/12"]
    assert said_before("loads = [") == ["fourbar.al:54: GRAVITY(-G*N2>)"]
    assert said_before("(PA, F1*N.x") == ["fourbar.al:55: FORCE_PA> = F1*N1> + F2*N2>"]
    assert said_before("velocity_constraints = [") == [
        "fourbar.al:46: DEPENDENT[1] = DOT(V_P5_N>, N1>) + UA1",
        "fourbar.al:47: DEPENDENT[2] = DOT(V_P5_N>, N2>) + UA2",
        "fourbar.al:48: CONSTRAIN(DEPENDENT[U2, U3])"]


def test_a_coordinate_the_model_defines_is_a_prescribed_motion_in_sympys_kane(tmp_path):
    # an arm turned at a prescribed rate (QA = OMEGA*T, as the sprinters prescribe their
    # joint angles) carrying a pendulum; by Lagrange's equations, by hand:
    # L2^2 Q'' = -L1 L2 OMEGA^2 sin Q
    path = tmp_path / "arm.al"
    path.write_text("NEWTONIAN N\nFRAMES A, B\nPARTICLES P\nPOINTS E\n"
                    "VARIABLES QA''\nMOTIONVARIABLES' Q'\nCONSTANTS M, L1, L2, OMEGA\n"
                    "QA = OMEGA*T\nQA' = OMEGA\nQA'' = 0\n"
                    "SIMPROT(N, A, 3, QA)\nSIMPROT(A, B, 3, Q)\n"
                    "W_A_N> = QA'*N3>\nW_B_A> = Q'*N3>\nP_NO_E> = L1*A1>\nP_E_P> = L2*B1>\n"
                    "V_P_N> = DT(P_NO_P>, N)\nA_P_N> = DT(V_P_N>, N)\nMASS P = M\n"
                    "ZERO = FR() + FRSTAR()\nKANE()\n"
                    "INPUT M = 2, L1 = 1, L2 = 0.5, OMEGA = 3, Q = 0.4, Q' = 0, TFINAL = 1\n"
                    "OUTPUT T, Q\nCODE DYNAMICS() arm.c\n")
    script = tmp_path / "arm_sympy.py"
    script.write_text(export_sympy(autolev.load(path), "arm.al"))
    text = script.read_text()
    assert "\nLevel: mechanics." in text
    assert "A.orient_axis(N, N.z, OMEGA*t)" in text
    ns = runpy.run_path(str(script))
    t, q, m, l1, l2, omega = (ns[n] for n in ("t", "Q", "M", "L1", "L2", "OMEGA"))
    assert list(ns["kane"].q) == [q]
    u, = ns["kane"].u
    x = sm.Symbol("x")          # Q, for Lagrange's partial derivatives
    angle = omega * t
    position = sm.Matrix([l1 * sm.cos(angle) + l2 * sm.cos(angle + q),
                          l1 * sm.sin(angle) + l2 * sm.sin(angle + q)])
    kinetic = (m * position.diff(t).dot(position.diff(t)) / 2).subs(q.diff(t), u)
    lagrange = (kinetic.diff(u).diff(t).subs(q.diff(t), u)
                - kinetic.subs(q, x).diff(x).subs(x, q))
    # lagrange = 0 is mass * u' - forcing = 0
    mass = lagrange.diff(u.diff(t))
    forcing = -(lagrange - mass * u.diff(t))
    assert sm.simplify(mass - m * l2 ** 2) == 0
    assert sm.simplify(forcing + m * l1 * l2 * omega ** 2 * sm.sin(q)) == 0
    assert sm.simplify(ns["full_mass"] - sm.diag(1, mass)) == sm.zeros(2, 2)
    assert sm.simplify(ns["full_forcing"] - sm.Matrix([u, forcing])) == sm.zeros(2, 1)
    model = autolev.load(path)
    found = run_script(script, tmp_path / "rows.csv")
    assert equations_difference(model, model.code_commands[0], found) <= 1e-10
    assert rows_difference(model, tmp_path / "rows.csv") <= 1e-6


def test_accelerations_the_model_defines_are_named_when_sympys_equations_differ(tmp_path):
    # MAE-223's bicycles write ALF_B_A> = DT(W_B_A>, N): differentiated in N, not in A,
    # which Autolev's FRSTAR takes as given; sympy derives the angular acceleration
    spun = ("NEWTONIAN N\nFRAMES A\nBODIES B\nMOTIONVARIABLES' Q{2}', U{2}'\n"
            "CONSTANTS I1, I2, I3, M\nSIMPROT(N, A, 3, Q1)\nSIMPROT(A, B, 1, Q2)\n"
            "Q1' = U1\nQ2' = U2\nW_A_N> = U1*N3>\nW_B_A> = U2*A1>\n"
            "ALF_A_N> = DT(W_A_N>, N)\nALF_B_A> = DT(W_B_A>, N)\n"
            "MASS B = M\nINERTIA B, I1, I2, I3\nV_BO_N> = 0>\n"
            "ZERO = FR() + FRSTAR()\nKANE()\n"
            "INPUT I1 = 1, I2 = 2, I3 = 3, M = 1, U1 = 1, U2 = 1\n"
            "OUTPUT Q1, Q2\nCODE DYNAMICS() spun.c\n")
    raw = script_of(tmp_path, "spun.al", spun)
    assert "\nLevel: equations." in raw
    text = " ".join(raw.split())
    assert "the model defines accelerations of its own, which KanesMethod derives from " \
           "the velocities instead (spun.al:12: ALF_A_N> = DT(W_A_N>, N); " \
           "spun.al:13: ALF_B_A> = DT(W_B_A>, N))" in text
    # differentiated in A, the angular acceleration is sympy's, and so are the equations
    assert "\nLevel: mechanics." in script_of(tmp_path, "spun.al",
                                              spun.replace("DT(W_B_A>, N)", "DT(W_B_A>, A)"))


NO_VALUES = """NEWTONIAN N
FRAMES A
PARTICLES P
MOTIONVARIABLES' Q', U'
CONSTANTS L, G, M, kane, loads, bodies, kd_eqs, sin
MASS P = M
SIMPROT(N, A, 3, Q)
Q' = U
P_NO_P> = L*A1>
V_P_N> = DT(P_NO_P>, N)
GRAVITY(G*N1>)
TORQUE(N/A, -kane*U*A3> - (loads + bodies*kd_eqs)*SIN(Q)*sin*A3>)
ZERO = FR() + FRSTAR()
KANE()
INPUT Q = 0.5, U = 0.1, TFINAL = 1, INTEGSTP = 0.1
OUTPUT Q, U
CODE DYNAMICS() novalues.c
"""


def test_a_model_without_values_is_exported_and_its_script_names_them(tmp_path, capsys):
    # it was refused ("8 constants ... have no value"); constants named as the script's
    # own variables (kane, loads, bodies, kd_eqs) or numpy's sin crashed the script
    import subprocess
    import sys
    path = tmp_path / "novalues.al"
    path.write_text(NO_VALUES)
    script = tmp_path / "novalues_sympy.py"
    assert main(["convert", "--to", "sympy", str(path), "-o", str(script)]) == 0
    assert "no value given for bodies, G, kane, kd_eqs, L, loads, M, sin" in \
        capsys.readouterr().err
    ran = subprocess.run([sys.executable, str(script)], capture_output=True, text=True)
    assert ran.returncode == 1 and "no value for" in ran.stderr and "sin" in ran.stderr
    assert "Traceback" not in ran.stderr
    # given values, its equations are ours and its rows those of a run
    text = script.read_text()
    line = next(x for x in text.splitlines() if x.startswith("constants = {"))
    script.write_text(text.replace(line, line.replace("None", "0.7")))
    model = autolev.load(path)
    values = dict.fromkeys(["L", "G", "M", "kane", "loads", "bodies", "kd_eqs", "sin"], 0.7)
    found = run_script(script, tmp_path / "rows.csv")
    assert equations_difference(model, model.code_commands[0], found) <= 1e-10
    assert rows_difference(model, tmp_path / "rows.csv", **values) <= 1e-6


def test_pi_in_a_torque_is_checked_and_exported_at_the_mechanics_level(tmp_path):
    # the sprint models' MTOR = MTPK*(PI - MANG): the check of sympy's equations at a
    # state took PI for a value the point lacks (an internal error).  Under -G N1 the
    # potential is M G L cos Q: by hand, M L^2 Q'' = M G L sin Q + K (PI - Q)
    path = tmp_path / "sprung.al"
    path.write_text("NEWTONIAN N\nBODIES A\nMOTIONVARIABLES' Q'\nCONSTANTS M, L, G, K\n"
                    "SIMPROT(N, A, 3, Q)\nW_A_N> = Q'*N3>\nP_NO_AO> = L*A1>\n"
                    "V_AO_N> = DT(P_NO_AO>, N)\nMASS A = M\nINERTIA A, 0, 0, 0\n"
                    "GRAVITY(-G*N1>)\nTORQUE_A> = K*(PI - Q)*N3>\n"
                    "ZERO = FR() + FRSTAR()\nKANE()\n"
                    "INPUT M = 2, L = 1.5, G = 9.81, K = 3, Q = 0.4, Q' = 0, TFINAL = 1\n"
                    "OUTPUT T, Q\nCODE DYNAMICS() sprung.c\n")
    script = tmp_path / "sprung_sympy.py"
    script.write_text(export_sympy(autolev.load(path), "sprung.al"))
    ns = runpy.run_path(str(script))
    assert "\nLevel: mechanics." in script.read_text()
    m, lk, g, k, q = (ns[n] for n in ("M", "L", "G", "K", "Q"))
    ratio = ns["full_forcing"][1] / ns["full_mass"][1, 1]
    by_hand = (m * g * lk * sm.sin(q) + k * (sm.pi - q)) / (m * lk ** 2)
    assert sm.simplify(ratio - by_hand) == 0
