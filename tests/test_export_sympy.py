"""`autolev convert --to sympy --level equations` (issue 33): every shipped example with
equations of motion becomes a script that needs only sympy, numpy and scipy; its
equations give our compiled right-hand side's rates at random states and constants, and
its integration gives `simulate`'s rows (the same method and tolerances)."""
import runpy
import subprocess
import sys

import numpy as np
import pytest

import autolev
from autolev.cli import main
from autolev.runtime.numerics.prepare import prepare_command
from helpers import EXAMPLES

EXAMPLES_WITH_DYNAMICS = ["simple_pendulum", "double_pendulum", "cart_pendulum",
                          "mass_spring_damper", "block_pendulums", "nlink_pendulum",
                          "rolling_disc", "euler_parameters_body", "fourbar",
                          "whipple_benchmark"]

# a script run with autolev made unimportable: it must not need it
WITHOUT_AUTOLEV = ("import runpy, sys; sys.modules['autolev'] = None; "
                   "sys.argv = sys.argv[1:]; runpy.run_path(sys.argv[0], run_name='__main__')")


@pytest.fixture(scope="module")
def scripts(tmp_path_factory):
    folder = tmp_path_factory.mktemp("sympy")
    for name in EXAMPLES_WITH_DYNAMICS:
        assert main(["convert", "--to", "sympy", "--level", "equations",
                     str(EXAMPLES / f"{name}.al"), "-o", str(folder / f"{name}_sympy.py"),
                     "-q"]) == 0
    return folder


@pytest.mark.parametrize("name", EXAMPLES_WITH_DYNAMICS)
def test_the_scripts_equations_give_our_rates(scripts, name):
    script = runpy.run_path(str(scripts / f"{name}_sympy.py"))     # defines, integrates not
    model = autolev.load(EXAMPLES / f"{name}.al")
    command = next(c for c in model.code_commands if c.kind.integrates)
    system = prepare_command(model.snapshot_for(command), command).system
    states, constants = script["states"], list(script["constants"])
    assert [str(s.func) for s in states] == [str(x).replace("'", "p") for x in system.states]
    assert [str(c) for c in constants] == [str(p) for p in system.params]
    mass, force, _ = script["numeric_functions"]()
    rng = np.random.default_rng(7)
    for _ in range(20):
        p = rng.uniform(0.5, 1.5, len(constants))
        x = rng.uniform(-1.0, 1.0, len(states))
        t = rng.uniform(0.0, 2.0)
        system.set_parameters(p)
        ours = system.derivatives(t, x)
        specified = [0.0] * len(script["specified"])
        theirs = np.linalg.solve(np.asarray(mass(t, x, list(p), specified), dtype=float),
                                 np.asarray(force(t, x, list(p), specified),
                                            dtype=float).ravel())
        assert np.allclose(theirs, ours, rtol=0, atol=1e-10 * max(1.0, np.abs(ours).max()))


@pytest.mark.parametrize("name", ["double_pendulum", "mass_spring_damper", "cart_pendulum"])
def test_the_script_integrates_as_autolev_run_does(scripts, name, tmp_path):
    csv = tmp_path / "rows.csv"
    done = subprocess.run([sys.executable, "-c", WITHOUT_AUTOLEV,
                           str(scripts / f"{name}_sympy.py"), str(csv)],
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    rows = np.loadtxt(csv, delimiter=",", skiprows=1, ndmin=2)
    result = autolev.load(EXAMPLES / f"{name}.al").simulate(method="dop853")
    ours = np.column_stack([t.data for t in result.outputs])
    header = csv.read_text().splitlines()[0].split(",")
    labels = [label for t in result.outputs for label in t.labels]
    assert header == labels and rows.shape == ours.shape
    scale = np.maximum(1.0, np.abs(ours).max(axis=0))
    assert np.all(np.abs(rows - ours) <= 1e-6 * scale)


def test_a_model_without_equations_of_motion_is_refused(tmp_path, capsys):
    path = tmp_path / "algebra.al"
    path.write_text("CONSTANTS A\nVARIABLES X\nX = 2*A\nINPUT A = 1\nOUTPUT X\n"
                    "CODE ALGEBRAIC() algebra.c\n")
    assert main(["convert", "--to", "sympy", str(path), "-o", str(tmp_path / "x.py")]) == 1
    assert "writes no CODE DYNAMICS or ODE, and has no equations of motion to export" \
        in capsys.readouterr().err
    assert not (tmp_path / "x.py").exists()


def test_a_model_writing_no_code_dynamics_exports_its_equations_as_they_stand(tmp_path,
                                                                              capsys):
    # 18 corpus models form Kane's equations and write only CODE ALGEBRAIC (gait2d's
    # implicit f) or nothing: their script is what a CODE DYNAMICS() at the end would
    # give, as linearize takes such a model
    text = "\n".join(line for line in (EXAMPLES / "double_pendulum.al").read_text()
                     .splitlines() if not line.upper().startswith("CODE")) + "\n"
    bare, coded = tmp_path / "bare.al", tmp_path / "coded.al"
    bare.write_text(text)
    coded.write_text(text + "CODE DYNAMICS() bare.c\n")
    outs = []
    # at the equations level unless asked: sympy's KanesMethod of a model that never
    # asked for its dynamics took over 20 minutes on MAE-223's BICYCLE4
    for path, level in ((bare, []), (coded, ["--level", "equations"])):
        out = tmp_path / f"{path.stem}.py"
        assert main(["convert", "--to", "sympy", str(path), "-o", str(out), "-q",
                     *level]) == 0
        outs.append(out.read_text().replace(path.name, "MODEL"))
    assert "Not the mechanics level: the model writes no CODE DYNAMICS or ODE" in \
        " ".join(outs[0].split())
    err = capsys.readouterr().err
    assert "bare.al: note: the model writes no CODE DYNAMICS or ODE" in err
    assert "coded.al: note" not in err
    # the same script but for what it says it exports
    said = "(no CODE DYNAMICS or ODE: the model's equations as they stand, as linearize"
    assert said in " ".join(outs[0].split())
    first, second = (o.split('"""', 2)[2] for o in outs)       # after the docstring
    assert first == second
    asked = tmp_path / "asked.py"
    assert main(["convert", "--to", "sympy", str(bare), "-o", str(asked), "-q", "--level",
                 "mechanics"]) == 0
    assert "\nLevel: mechanics." in asked.read_text()


def test_names_from_the_model_become_identifiers_never_code():
    from autolev.export import identifier
    taken: set = set()
    assert identifier("K", taken) == "K" and identifier("K", taken) == "K_2"
    assert identifier("Q1'", taken) == "Q1p"
    assert identifier("lambda", taken) == "lambda_2"        # a keyword
    assert identifier("t", taken) == "t_2"                  # the script's time
    assert identifier("x); import os", taken).isidentifier()


def test_values_come_from_an_in_file_and_set_as_a_run_takes_them(tmp_path, capsys):
    source = EXAMPLES / "double_pendulum.al"
    assert main(["run", str(source), "--out", str(tmp_path / "run"), "-q",
                 "--set", "L2=2"]) == 0
    script = tmp_path / "dp_sympy.py"
    # the .in the run wrote has L2 = 2; --set then makes M1 3 (kg)
    assert main(["convert", "--to", "sympy", str(source), "--in",
                 str(tmp_path / "run" / "double_pendulum.in"), "--set", "M1=3",
                 "-o", str(script), "-q"]) == 0
    constants = {str(k): v for k, v in runpy.run_path(str(script))["constants"].items()}
    assert constants["L2"] == 2.0 and constants["M1"] == 3.0 and constants["L1"] == 1.0
    assert main(["convert", str(source), "--in",
                 str(tmp_path / "run" / "double_pendulum.in")]) == 2
    assert "--in and --set give the values of a --to sympy script" in capsys.readouterr().err


def test_the_script_of_a_matlab_program_integrates_as_its_ode45(tmp_path):
    # CODE DYNAMICS() into a .m: Autolev's program calls ode45, the run integrates with
    # RK45, and so must the script (DOP853 gave up on a stiff corpus model the run ran)
    text = (EXAMPLES / "double_pendulum.al").read_text()
    model = tmp_path / "dp_matlab.al"
    model.write_text(text.replace("double_pendulum.c", "dp_matlab.m"))
    assert "dp_matlab.m" in model.read_text()
    script, csv = tmp_path / "dp_sympy.py", tmp_path / "rows.csv"
    assert main(["convert", "--to", "sympy", "--level", "equations", str(model),
                 "-o", str(script), "-q"]) == 0
    assert runpy.run_path(str(script))["integration_method"] == "RK45"
    done = subprocess.run([sys.executable, "-c", WITHOUT_AUTOLEV, str(script), str(csv)],
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    rows = np.loadtxt(csv, delimiter=",", skiprows=1, ndmin=2)
    result = autolev.load(model).simulate()
    ours = np.column_stack([t.data for t in result.outputs])
    assert rows.shape == ours.shape
    # one method and tolerances (the run's RK45 restarts at each output, as ode45's
    # program integrates step by step): within the digits the rows print
    scale = np.maximum(1.0, np.abs(ours).max(axis=0))
    assert np.all(np.abs(rows - ours) <= 1e-6 * scale)
