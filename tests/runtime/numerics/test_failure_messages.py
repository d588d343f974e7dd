"""Failures say why and what to do (issue 15, item 8): a halved-too-often integration
names the stiffness verdict or the zero tolerances; a `.in` cut short names what it
lacks; a `.in` full of strangers is one warning, not one per line."""
import math
import warnings

import numpy as np
import pytest

import autolev
from helpers import EXAMPLES

STIFF = """% X follows COS(T) with a time constant of 1/K; Y decays slowly
VARIABLES X', Y'
CONSTANTS K
INPUT K = 1E9, X = 1, Y = 1, TFINAL = 1, INTEGSTP = 0.1
X' = -K*(X - COS(T))
Y' = -Y
OUTPUT T, X, Y
CODE ODE() stiff.c
"""


@pytest.fixture(scope="module")
def stiff(tmp_path_factory):
    path = tmp_path_factory.mktemp("stiff") / "stiff.al"
    path.write_text(STIFF)
    return autolev.load(path)


def test_a_stiff_model_under_kutta_merson_is_named_stiff(stiff):
    r = stiff.simulate()
    assert not r.ok and "halved too many times" in r.failure
    # the Jacobian there has eigenvalues -K and -1: the verdict quotes K
    assert "the equations are stiff there" in r.failure
    assert "about 1e+09 in size" in r.failure and "--method radau" in r.failure
    # and the advice works: X = cos T + O(1/K) after the first 1/K seconds
    good = stiff.simulate(method="radau")
    assert good.ok
    assert abs(good["X"][-1] - math.cos(1.0)) < 1e-6
    assert abs(good["Y"][-1] - math.exp(-1.0)) < 1e-6


def test_zero_tolerances_are_named(stiff):
    r = stiff.simulate(K=1, ABSERR=0, RELERR=0)
    assert not r.ok and "ABSERR and RELERR are both 0" in r.failure


def test_a_blow_up_is_not_called_stiff(tmp_path):
    path = tmp_path / "blowup.al"
    path.write_text("VARIABLES X'\nINPUT X = 1, TFINAL = 2, INTEGSTP = 0.1\nX' = X^2\n"
                    "OUTPUT T, X\nCODE ODE() blowup.c\n")
    r = autolev.load(path).simulate()
    # X = 1/(1 - T): the failure is near T = 1, where the Jacobian 2X is large but
    # far below what the smallest step can follow
    assert not r.ok and 0.9 < r.failure_time <= 1.0
    assert "not stiff there" in r.failure and "grow without bound" in r.failure


def in_file_of(model, tmp_path):
    model.simulate(out_dir=tmp_path, TFINAL=0.1)
    return tmp_path / f"{model.name}.in"


def test_a_truncated_in_file_names_the_values_it_lacks(stiff, tmp_path):
    lines = in_file_of(stiff, tmp_path).read_text().splitlines()
    cut = [i for i, line in enumerate(lines) if "| " in line and "Y" in line[21:42]][0]
    (tmp_path / "cut.in").write_text("\n".join(lines[:cut]) + "\n")
    with pytest.warns(UserWarning, match=r"cut\.in: no value for Y, TINITIAL, TFINAL, "
                      r"INTEGSTP, PRINTINT, ABSERR, RELERR \(a file cut short\?\)"):
        r = stiff.simulate(infile=tmp_path / "cut.in", method="radau")
    assert len(r.t) == 11 and abs(r.t[-1] - 1.0) < 1e-12    # TFINAL from the INPUT


def test_an_in_file_of_strangers_is_one_warning(stiff, tmp_path):
    lines = in_file_of(stiff, tmp_path).read_text().splitlines()
    head = [line for line in lines if "|" not in line or "Value" in line][:6]
    strangers = [f"{'Constant':<21}{f'W{k}':<21}{'UNITS':<16}| 1.0" for k in range(50000)]
    body = [line for line in lines if line[58:59] == "|" and "Value" not in line
            and not set(line[:58]) <= {"-", " "}]
    (tmp_path / "big.in").write_text("\n".join(head + strangers + body) + "\n")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = stiff.simulate(infile=tmp_path / "big.in", method="radau")
    messages = [str(w.message) for w in caught if "not inputs" in str(w.message)]
    assert len(messages) == 1
    assert "W0, W1, W2, W3, W4, W5, W6, W7, ... and 49992 more" in messages[0]
    assert "(50000 names) are not inputs of this model; ignored" in messages[0]
    # the values were read: the file says TFINAL = 0.1
    assert r.ok and len(r.t) == 2 and np.isclose(r["Y"][-1], math.exp(-0.1), atol=1e-6)


def test_a_verbose_run_reports_the_failure_with_its_summary(tmp_path, capsys):
    path = tmp_path / "blowup.al"
    path.write_text("VARIABLES X'\nINPUT X = 1, TFINAL = 2, INTEGSTP = 0.1\nX' = X^2\n"
                    "OUTPUT T, X\nCODE ODE() blowup.c\n")
    [r] = autolev.load(path).run(out_dir=tmp_path / "out", verbose=True)
    printed = capsys.readouterr().out
    assert printed.startswith("CODE ODE blowup.c: ")
    assert r.failure in printed and "wrote" in printed


def test_a_value_whose_powers_overflow_is_named_where_the_run_fails(tmp_path, capsys):
    # L = 1e308: the mass matrix M L^2 is inf; the run said only "singular"
    from autolev.cli import main
    status = main(["run", str(EXAMPLES / "simple_pendulum.al"), "--out", str(tmp_path),
                   "-q", "--set", "L=1e308"])
    err = capsys.readouterr().err
    assert status == 1
    assert "L = 1e+308: a product or power of so large a value is beyond double " \
           "precision" in err


def test_a_degree_input_that_overflows_in_radians_says_so(tmp_path, capsys):
    # THETA = 1e308 deg is finite; pi*THETA is not: it was "must be finite: THETA = 1e+308"
    from autolev.cli import main
    status = main(["run", str(EXAMPLES / "simple_pendulum.al"), "--out", str(tmp_path),
                   "-q", "--set", "THETA=1e308"])
    err = capsys.readouterr().err
    assert status == 1
    assert "inputs beyond double precision once converted to radians: THETA = 1e+308 deg" \
           in err
