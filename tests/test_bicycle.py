"""A Whipple bicycle written from the Meijaard et al. (2007) benchmark's description
(autolev_examples/whipple_benchmark.al) linearized upright: the benchmark's eigenvalues at
5 m/s and its weave and capsize speeds (Meijaard, Papadopoulos, Ruina and Schwab, Proc.
R. Soc. A 463, 2007, tables 2 and 3)."""
import math
import warnings

import numpy as np
import pytest
from scipy.optimize import brentq

import autolev
from conftest import ROOT

MODEL = ROOT / "autolev_examples" / "whipple_benchmark.al"
REAR_RADIUS = 0.3
WEAVE = complex(-0.775341882195845, 4.46486771378823)
CAPSIZE = -0.322866429004087
CASTOR = -14.0783896927982


@pytest.fixture(scope="module")
def bicycle():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return autolev.load(MODEL)


def upright(model, speed):
    # the rear wheel turns about its axle (to the right) at -v/r to roll forward at v
    return model.linearize({"Q5": math.pi / 10, "U6": -speed / REAR_RADIUS})


def lean_and_steer(lin) -> np.ndarray:
    """The eigenvalues of roll, steer and their rates: the other coordinates are
    ignorable (position, yaw, wheel angles) or dependent (pitch), their eigenvalues 0."""
    idx = [lin.states.index(n) for n in ("Q4", "Q7", "U4", "U7")]
    return np.linalg.eigvals(lin.A[np.ix_(idx, idx)])


def test_the_whipple_bicycle_gives_the_benchmark_eigenvalues(bicycle):
    lin = upright(bicycle, 5.0)
    assert lin.steady
    values = lin.eigenvalues()
    want = [CASTOR, WEAVE.conjugate(), WEAVE, CAPSIZE]
    assert np.allclose(values[:4], want, rtol=0, atol=1e-10)
    assert np.allclose(values[4:], 0, atol=1e-12)        # 7 ignorable or dependent
    assert np.allclose(np.sort_complex(lean_and_steer(lin)), np.sort_complex(want),
                       rtol=0, atol=1e-10)


def test_weave_and_capsize_speeds_from_a_sweep_and_root_finding(bicycle, tmp_path, capsys):
    from autolev.cli import main
    # bracket from the command's sweep over the rear wheel's rate, refine by root finding
    assert main(["linearize", str(MODEL), "--at", f"Q5={math.pi / 10!r}",
                 "--sweep", "U6=-10:-25:16", "--out", str(tmp_path)]) == 0
    rows = (tmp_path / "whipple_benchmark-sweep.csv").read_text().splitlines()[1:]
    speeds, weave_re, capsize_re = [], [], []
    for row in rows:
        cells = [float(c) for c in row.split(",")]
        ev = np.array(cells[1::2]) + 1j * np.array(cells[2::2])
        speeds.append(-cells[0] * REAR_RADIUS)
        weave_re.append(max(ev[np.abs(ev.imag) > 1e-9].real))
        real = ev[np.abs(ev.imag) <= 1e-9].real
        capsize_re.append(max(real[np.abs(real) > 1e-9]))      # not the zeros

    def bracket(values):
        k = next(i for i in range(len(values) - 1) if values[i] * values[i + 1] < 0)
        return speeds[k], speeds[k + 1]

    def weave(v):
        ev = lean_and_steer(upright(bicycle, v))
        return max(ev[np.abs(ev.imag) > 1e-9].real)

    def capsize(v):
        ev = lean_and_steer(upright(bicycle, v))
        return max(ev[np.abs(ev.imag) <= 1e-9].real)

    assert brentq(weave, *bracket(weave_re), xtol=1e-13) == pytest.approx(
        4.29238253634111, abs=1e-9)
    assert brentq(capsize, *bracket(capsize_re), xtol=1e-13) == pytest.approx(
        6.02426201538837, abs=1e-9)
