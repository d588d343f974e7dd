"""One answer on every path (bench/paths.py): a fast subset of the path table, and the
harness's own comparisons shown to catch what they are there to catch."""
import importlib.util
import shutil
import sys

import numpy as np
import pytest

from helpers import EXAMPLES, ROOT

sys.path.insert(0, str(ROOT / "bench"))
spec = importlib.util.spec_from_file_location("paths", ROOT / "bench" / "paths.py")
paths = importlib.util.module_from_spec(spec)
sys.modules["paths"] = paths
spec.loader.exec_module(paths)

pytestmark = pytest.mark.skipif(shutil.which("gcc") is None and shutil.which("cc") is None,
                                reason="the paths include the C back end and written C")

MODELS = [EXAMPLES / "double_pendulum.al",
          # formed by SOLVE(ZERO, U1', U2'): model.mass_matrix/forcing were 0 = 0
          ROOT / "tests" / "data" / "equations" / "solved_double_pendulum.al",
          # a tree of joints: the articulated-body recursion against the mass matrix
          EXAMPLES / "nlink_pendulum.al"]


@pytest.mark.parametrize("model", MODELS, ids=lambda p: p.stem)
def test_every_path_gives_the_answer_of_a_cold_run(model, tmp_path):
    row = paths.ModelPaths(model.stem, model, None, tmp_path, 300, 2).all()
    differing = {p: f"{c.mark}: {c.detail}" for p, c in row.cells.items() if c.differs}
    assert differing == {}
    # the paths that compute the same numbers give the same bytes
    for p in ("warm", "no-cache", "foreground", "python", "api", "module", "r:python",
              "r:module", "l:warm", "l:no-cache", "r:df-python"):
        assert row.cells[p].mark == "=", (p, row.cells[p])
    # the model-level equations and the exported script were compared, not skipped
    for p in ("r:M,f", "r:explicit", "r:symsys", "r:script", "r:dynamics", "code", "script",
              "l:c"):
        assert row.cells[p].mark in ("=", "~"), (p, row.cells[p])
    # the trees' f's and r's Jacobians by their recursions and by the mass matrix
    if model.stem != "solved_double_pendulum":
        for p in ("r:df", "r:dr"):
            assert row.cells[p].mark in ("=", "~"), (p, row.cells[p])


def _files(folder, text):
    folder.mkdir()
    (folder / "m.1").write_text(text)
    return folder


def test_identical_files_are_required_where_the_numbers_are_the_same(tmp_path):
    one = _files(tmp_path / "one", "% t x\n 0.0 1.000000E+00\n 0.1 9.950042E-01\n")
    assert paths.same_files(one, one).mark == "="
    two = _files(tmp_path / "two", "% t x\n 0.0 1.000000E+00\n 0.1 9.950043E-01\n")
    cell = paths.same_files(one, two)
    assert cell.mark == "DIFF" and "m.1 line 3" in cell.detail
    three = tmp_path / "three"
    three.mkdir()
    assert paths.same_files(one, three).mark == "DIFF"


def test_rates_within_the_tolerance_and_beyond_it():
    reference = {"states": ["Q1", "U1"], "rates": [[0.5, -2.0]]}
    assert paths.compare_rates(reference, {"states": ["U1", "Q1"],
                                           "rates": [[-2.0, 0.5]]}).mark == "="
    near = {"states": ["Q1", "U1"], "rates": [[0.5, -2.0 * (1 + 1e-12)]]}
    assert paths.compare_rates(reference, near).mark == "~"
    far = {"states": ["Q1", "U1"], "rates": [[0.5, -2.0 * (1 + 1e-6)]]}
    assert paths.compare_rates(reference, far).mark == "DIFF"
    missing = {"states": ["Q1"], "rates": [[0.5]]}
    assert paths.compare_rates(reference, missing).mark == "-"
    broken = {"states": ["Q1", "U1"], "rates": [[0.5, float("nan")]]}
    assert paths.compare_rates(reference, broken).mark == "DIFF"


def test_jacobians_within_the_tolerance_and_beyond_it():
    by_mass = [[[0.0, 1.0], [-4905.0, -0.25]]]
    same = {"x": (by_mass, by_mass), "u": ([[[], []]], [[[], []]])}
    assert paths.compare_jacobians({"form": "f", "blocks": same}).mark == "="
    near = [[[0.0, 1.0], [-4905.0 * (1 + 1e-13), -0.25]]]
    assert paths.compare_jacobians({"form": "f", "blocks": {"x": (near, by_mass)}}).mark == "~"
    far = [[[0.0, 1.0], [-4905.0, -0.25 + 1e-3]]]
    differing = paths.compare_jacobians({"form": "r", "blocks": {"x": (far, by_mass)}})
    assert differing.mark == "DIFF" and differing.detail.startswith("r's Jacobians differ")
    broken = [[[0.0, 1.0], [float("nan"), -0.25]]]
    assert paths.compare_jacobians({"form": "f", "blocks": {"x": (broken, by_mass)}}).mark == "DIFF"
    # the C and Python tiers do the same operations: a last bit apart is a difference
    assert paths.compare_jacobians({"form": "f", "exact": True,
                                    "blocks": {"x": (near, by_mass)}}).mark == "DIFF"
    assert paths.compare_jacobians({"form": "f", "exact": True, "blocks": same}).mark == "="


def _linear(folder, a):
    folder.mkdir()
    (folder / "m-A.csv").write_text("A,Q,U\nQ,0,1\nU," + ",".join(map(repr, a)) + "\n")
    (folder / "m-B.csv").write_text("B\nQ\nU\n")
    return folder


def test_linearizations_within_the_tolerance_and_beyond_it(tmp_path):
    reference = _linear(tmp_path / "dual", [-4905.0, -0.25])
    assert paths.compare_matrices(reference, reference).mark == "="
    # rounding amplified by cancellation: far from an ulp, well inside the tolerance
    near = _linear(tmp_path / "near", [-4905.0 * (1 + 1e-12), -0.25 + 1e-9])
    assert paths.compare_matrices(reference, near).mark == "~"
    far = _linear(tmp_path / "far", [-4905.0, -0.25 + 1e-4])
    assert paths.compare_matrices(reference, far).mark == "DIFF"
    matrix = _linear(tmp_path / "matrix", [-4905.0, -0.25])
    (matrix / "m-C.csv").write_text('C,Q,U\n"X[1,2]",1,0\n')
    assert paths.compare_matrices(matrix, matrix).mark == "="
    other = tmp_path / "other"
    other.mkdir()
    (other / "m-A.csv").write_text("A,U,Q\nU,1,0\nQ,-4905.0,-0.25\n")
    (other / "m-B.csv").write_text("B\nQ\nU\n")
    assert paths.compare_matrices(reference, other).mark == "DIFF"


def test_a_stale_answer_is_a_difference(tmp_path):
    # a warm run that repeats another input's rows is caught by the warm path
    model = EXAMPLES / "simple_pendulum.al"
    other = tmp_path / "m.al"
    other.write_text(model.read_text().replace("INPUT THETA = 10 deg",
                                               "INPUT THETA = 20 deg"))
    assert other.read_text() != model.read_text()
    harness = paths.ModelPaths("m", other, None, tmp_path / "work", 300, 1)
    (tmp_path / "work").mkdir()
    assert harness.reference().returncode == 0
    stale = tmp_path / "stale"
    outcome = paths.run_process(paths.autolev_cli("run", model, "--out", stale, "-q"),
                                tmp_path, 300)
    assert outcome.returncode == 0
    harness.status = 0
    cell = harness.compare_outcome("warm", outcome, stale, tmp_path / "work" / "run")
    assert cell.mark == "DIFF"


def test_the_rates_of_a_path_are_those_of_its_model(tmp_path):
    # the rates process reads its model: another model's rates differ
    model = EXAMPLES / "simple_pendulum.al"
    found = paths.rates(model, [], 2, None, None)
    other = paths.rates(model, ["--set", "L=2"], 2, None, None)
    assert found["run"]["states"] == other["run"]["states"]
    assert not np.allclose(found["run"]["rates"], other["run"]["rates"])
    assert paths.compare_rates(found["run"], other["run"]).mark == "DIFF"


def test_rates_of_an_ill_conditioned_mass_matrix_are_compared_to_its_rounding():
    # two solves of M u' = f in another order part by about eps cond(M), no more
    reference = {"states": ["U"], "rates": [[1.0]], "condition": 4.5e10}
    near = {"states": ["U"], "rates": [[1.0 + 1.2e-8]]}
    far = {"states": ["U"], "rates": [[1.0 + 1e-3]]}
    assert paths.compare_rates(reference, near).mark == "~"
    assert paths.compare_rates(dict(reference, condition=1.0), near).mark == "DIFF"
    assert paths.compare_rates(reference, far).mark == "DIFF"


def test_the_equations_level_scripts_primed_names_are_the_runs_states(tmp_path):
    # the script names Y' Yp (the equations level: Y, Y' are beyond the coordinates and
    # speeds); its rates were not compared ('-'), so its rows' parting was not explained
    model = tmp_path / "xy.al"
    model.write_text("NEWTONIAN N\nPARTICLES P\nMOTIONVARIABLES' X''\nVARIABLES Y''\n"
                     "CONSTANTS K\nMASS P = 1\nP_NO_P> = X*N1>\nV_P_N> = DT(P_NO_P>, N)\n"
                     "A_P_N> = DT(V_P_N>, N)\nFORCE_P> = -K*X*N1>\n"
                     "ZERO = FR() + FRSTAR()\nKANE()\nY'' = -K*Y\n"
                     "INPUT K = 4, X = 1, X' = 0, Y = 0.5, Y' = 0, TFINAL = 1\n"
                     "OUTPUT T, X, Y\nCODE DYNAMICS() xy.c\n")
    script = tmp_path / "xy_sympy.py"
    made = paths.run_process(paths.autolev_cli("convert", model, "--to", "sympy", "-q",
                                               "-o", script), tmp_path, 300)
    assert made.returncode == 0 and "Level: equations." in script.read_text()
    assert "Yp = me.dynamicsymbols('Yp')" in script.read_text()
    found = paths.rates(model, [], 2, None, script)
    assert sorted(found["script"]["states"]) == sorted(found["run"]["states"])
    assert paths.compare_rates(found["run"], found["script"]).mark in ("=", "~")
