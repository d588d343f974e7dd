"""The commands on a model's CODE commands build it through its last CODE statement:
the programs Autolev wrote depend on nothing after their line (docs/language.md, "A
later statement never rewrites an earlier CODE")."""
import subprocess
import sys

import numpy as np
import pytest

import autolev
from autolev import loader
from autolev.errors import AutolevRuntimeError
from autolev.pipeline import translation

PENDULUM = """\
NEWTONIAN N
BODIES A
VARIABLES Q', U'
CONSTANTS G, L, M
MASS A = M
INERTIA A, 0, 0, M*L^2/12
SIMPROT(N, A, 3, Q)
Q' = U
W_A_N> = U*A3>
P_NO_AO> = L/2*A1>
V_AO_N> = DT(P_NO_AO>, N)
GRAVITY(-G*N2>)
ZERO = FR() + FRSTAR()
KANE()
INPUT G = 9.81, L = 2, M = 1, Q = 0.3, U = 0, TFINAL = 1, INTEGSTP = 0.1
OUTPUT Q, U
"""
# after the CODE: a constant nothing gives, and a statement that fails when executed
TAIL = "CONSTANTS K\nX = INV([0, 0; 0, 0])\n"


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("AUTOLEV_CACHE", str(tmp_path / "cache"))


def _write(folder, name, text):
    path = folder / name
    path.write_text(text)
    return path


def test_a_run_executes_nothing_after_the_last_code(cache, tmp_path):
    model = _write(tmp_path, "tail.al", PENDULUM + "CODE DYNAMICS() tail.c\n" + TAIL)
    with pytest.raises(AutolevRuntimeError, match=":19:1: .*R001"):
        autolev.load(model)                     # the whole model fails at line 19
    out = subprocess.run([sys.executable, "-m", "autolev", "run", str(model), "--out",
                          str(tmp_path / "o")], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert "K" not in out.stderr and "warning" not in out.stderr
    # the rows are those of the model without its tail
    plain = _write(tmp_path, "plain.al", PENDULUM + "CODE DYNAMICS() tail.c\n")
    subprocess.run([sys.executable, "-m", "autolev", "run", str(plain), "--out",
                    str(tmp_path / "p")], check=True, capture_output=True)
    rows = np.loadtxt(tmp_path / "o" / "tail.1", comments="%")
    assert rows.shape == (11, 2)
    assert np.array_equal(rows, np.loadtxt(tmp_path / "p" / "tail.1", comments="%"))


def test_the_missing_values_named_are_those_of_the_last_codes_program(tmp_path):
    model = _write(tmp_path, "tail.al", PENDULUM.replace("G = 9.81, ", "")
                   + "CODE DYNAMICS() tail.c\nINPUT G = 9.81\n" + TAIL)
    whole = translation(model)
    # an INPUT after the CODE is not its program's: G lacks a value there, K is not known
    assert whole.inputs_without_value == ["K"]
    assert whole.through_last_code().inputs_without_value == ["G"]


def test_the_module_is_cut_after_the_last_code_call(tmp_path):
    model = _write(tmp_path, "two.al", PENDULUM + "CODE DYNAMICS() one.c\nY = 2*G\n"
                   "CODE ALGEBRAIC() two.c\n" + TAIL)
    whole = translation(model)
    cut = whole.through_last_code()
    lines = cut.code.splitlines()
    assert len(whole.code_lines) == 2 and lines[-1].startswith("model.code('algebraic'")
    assert whole.code.startswith(cut.code) and "INV" in whole.code and "INV" not in cut.code
    assert max(cut.line_map) == len(lines)


@pytest.mark.parametrize("ending", ["CODE DYNAMICS() tail.c\n",          # nothing after it
                                    "CODE ALGEBRAIC() tail.c\n" + TAIL])  # none integrates
def test_the_module_is_whole_when_nothing_follows_or_no_code_integrates(tmp_path, ending):
    whole = translation(_write(tmp_path, "m.al", PENDULUM + ending))
    assert whole.through_last_code() is whole


def test_linearizing_a_model_whose_codes_do_not_integrate_takes_its_whole_equations(
        cache, tmp_path):
    # KANE() after the only CODE (an ALGEBRAIC): the equations as they stand at the end
    text = PENDULUM.replace("ZERO = FR() + FRSTAR()\nKANE()\n", "")
    model = _write(tmp_path, "late.al", text + "CODE ALGEBRAIC() late.c\n"
                   "ZERO = FR() + FRSTAR()\nKANE()\n")
    built, _ = loader.load_for_run(model)
    lin = built.linearize({"Q": 0.5})
    # the rod about its end, level at Q = 0: Q'' = -(3 G / 2 L) cos(Q)
    g, length = 9.81, 2.0
    assert np.allclose(lin.A, [[0, 1], [3 * g / (2 * length) * np.sin(0.5), 0]],
                       rtol=1e-12)


def test_a_value_for_a_constant_declared_after_the_last_code_is_refused_as_such(tmp_path):
    model = _write(tmp_path, "tail.al", PENDULUM + "CODE DYNAMICS() tail.c\n" + TAIL)
    out = subprocess.run([sys.executable, "-m", "autolev", "run", str(model), "--out",
                          str(tmp_path / "o"), "--set", "K=2"], capture_output=True,
                         text=True)
    assert out.returncode == 2 and "--set K: declared after the model's last CODE" \
        in out.stderr
    out = subprocess.run([sys.executable, "-m", "autolev", "run", str(model), "--out",
                          str(tmp_path / "o"), "--set", "KK=2"], capture_output=True,
                         text=True)
    assert out.returncode == 2 and "--set KK: the model has no quantity" in out.stderr
