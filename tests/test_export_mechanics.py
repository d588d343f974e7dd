"""`autolev convert --to sympy` at the mechanics level (issue 33): each shipped example the
level takes becomes frames, points, bodies, loads and a KanesMethod in a script that needs
only sympy, numpy and scipy.  Run with autolev unimportable, its mass matrix and forcing
equal our own Kane's equations' at 20 random states and constants, and `python OUT.py`
writes `autolev run`'s rows over 1 s (same method and tolerances)."""
import json
import subprocess
import sys

import numpy as np
import pytest
import sympy as sm
import sympy.physics.mechanics as me

import autolev
from autolev.cli import main
from autolev.export_mechanics import export_sympy, simple_rotation
from autolev.runtime.errors import AutolevModelError
from helpers import EXAMPLES

MECHANICS = ["simple_pendulum", "double_pendulum", "cart_pendulum", "mass_spring_damper",
             "block_pendulums", "nlink_pendulum", "euler_parameters_body"]
# their speeds are constrained: dependent speeds (fourbar, whipple), auxiliary ones
EQUATIONS = {"rolling_disc": "auxiliary speeds", "fourbar": "dependent or auxiliary speeds",
             "whipple_benchmark": "dependent or auxiliary speeds"}

# in a process where autolev cannot be imported: the script's full mass matrix and forcing
# at the given states and constants, then `python OUT.py OUT.csv`
DRIVER = """
import json, runpy, sys
sys.modules['autolev'] = None
import numpy as np, sympy as sm
script, points, csv = sys.argv[1:4]
ns = runpy.run_path(script)
kane = ns['kane']
states, constants = list(kane.q) + list(kane.u), list(ns['constants'])
specified = list(ns['specified'])
f = sm.lambdify([ns['t'], states, constants, specified],
                [kane.mass_matrix_full, kane.forcing_full])
values = [[np.asarray(m, dtype=float).tolist()
           for m in f(t, x, [p[str(c)] for c in constants],
                      [given[str(s.func)] for s in specified])]
          for t, x, p, given in json.loads(open(points).read())]
print(json.dumps({'states': [str(s.func) for s in states],
                  'constants': [str(c) for c in constants], 'values': values}))
sys.argv = [script, csv]
runpy.run_path(script, run_name='__main__')      # ends with sys.exit(main(...))
"""


def exported(name: str, folder, *options) -> str:
    out = folder / f"{name}_sympy.py"
    assert main(["convert", "--to", "sympy", str(EXAMPLES / f"{name}.al"), "-o", str(out),
                 "-q", "--set", "TFINAL=1", *options]) == 0
    return str(out)


def specified_names(model) -> list:
    return [s.name for s, info in model.info.items() if info.kind == "specified"
            and "'" not in s.name]


def our_full_equations(model, names_of_states, names_of_constants):
    """Our Kane's equations (Model.symbolic_system) as a numeric function of the state
    (coordinates then speeds, as the script's) and the constants (by name)."""
    system = model.symbolic_system("combined")
    ours = [str(s.args[0].func) + "_rate" if isinstance(s, sm.Derivative) else str(s.func)
            for s in system.states]       # a speed that is a coordinate's rate: X_rate
    assert ours == names_of_states
    constants = {c.name: c for c, info in model.info.items() if info.kind == "constant"}
    specified = [me.dynamicsymbols(n) for n in specified_names(model)]
    return sm.lambdify([me.dynamicsymbols._t, system.states,
                        [constants[n] for n in names_of_constants], specified],
                       [system.comb_implicit_mat, system.comb_implicit_rhs])


@pytest.mark.parametrize("name", MECHANICS)
def test_the_scripts_kane_equals_our_equations_and_runs_as_autolev_run(name, tmp_path):
    script = exported(name, tmp_path)
    assert "\nLevel: mechanics." in open(script).read()
    model = autolev.load(EXAMPLES / f"{name}.al")
    rng = np.random.default_rng(33)
    n_states = len(model.coordinates) + len(model.speeds)
    constants = [c.name for c, info in model.info.items() if info.kind == "constant"]
    points = [(rng.uniform(0, 2), rng.uniform(-1, 1, n_states).tolist(),
               {n: rng.uniform(0.5, 1.5) for n in constants},
               {n: rng.uniform(-1, 1) for n in specified_names(model)}) for _ in range(20)]
    (tmp_path / "points.json").write_text(json.dumps(points))
    csv = tmp_path / "rows.csv"
    done = subprocess.run([sys.executable, "-c", DRIVER, script, str(tmp_path / "points.json"),
                           str(csv)], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    theirs = json.loads(done.stdout)
    assert set(theirs["constants"]) <= set(constants)
    ours = our_full_equations(model, theirs["states"], theirs["constants"])
    for (t, x, p, given), (mass, forcing) in zip(points, theirs["values"]):
        values = [given[n] for n in specified_names(model)]
        p = [p[n] for n in theirs["constants"]]
        our_mass, our_forcing = (np.asarray(m, dtype=float) for m in ours(t, x, p, values))
        for a, b in ((mass, our_mass), (forcing, our_forcing)):
            a = np.asarray(a)
            assert a.shape == b.shape
            assert np.all(np.abs(a - b) <= 1e-10 * max(1.0, np.abs(b).max()))
    rows = np.loadtxt(csv, delimiter=",", skiprows=1, ndmin=2)
    result = model.simulate(TFINAL=1, method="dop853")
    ours_rows = np.column_stack([t.data for t in result.outputs])
    assert csv.read_text().splitlines()[0].split(",") == [
        label for t in result.outputs for label in t.labels]
    assert rows.shape == ours_rows.shape
    assert np.all(np.abs(rows - ours_rows) <= 1e-6 * np.maximum(1.0, np.abs(ours_rows).max(0)))


@pytest.mark.parametrize("name", sorted(EQUATIONS))
def test_a_model_with_constrained_speeds_goes_at_the_equations_level_saying_why(name, tmp_path):
    text = open(exported(name, tmp_path)).read()
    assert "\nLevel: equations." in text
    assert "Not the mechanics level: sympy's KanesMethod here takes no dependent or " \
           "auxiliary speeds" in " ".join(text.split())


def test_asking_the_mechanics_level_of_such_a_model_is_refused_and_writes_nothing(
        tmp_path, capsys):
    out = tmp_path / "x.py"
    assert main(["convert", "--to", "sympy", "--level", "mechanics",
                 str(EXAMPLES / "rolling_disc.al"), "-o", str(out)]) == 1
    err = capsys.readouterr().err
    assert "the mechanics level does not take this model" in err and "(U4, U5)" in err
    assert not out.exists()
    assert main(["convert", "--level", "mechanics", str(EXAMPLES / "rolling_disc.al")]) == 2
    assert "--level chooses the level of a --to sympy script" in capsys.readouterr().err


def test_the_equations_level_is_there_by_option(tmp_path):
    text = open(exported("double_pendulum", tmp_path, "--level", "equations")).read()
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
    path = tmp_path / "extra.al"
    path.write_text(EXTRA_TERM)
    model = autolev.load(path)
    text = export_sympy(model, "extra.al")
    assert "Not the mechanics level: sympy's KanesMethod on the model's bodies and loads " \
           "does not give the equations the run integrates" in " ".join(text.split())
    with pytest.raises(AutolevModelError, match="does not give the equations"):
        export_sympy(model, "extra.al", level="mechanics")
