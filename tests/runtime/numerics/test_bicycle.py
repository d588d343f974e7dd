"""A Whipple bicycle written from the Meijaard et al. (2007) benchmark's description
(autolev_examples/whipple_benchmark.al) linearized upright: the benchmark's eigenvalues at
5 m/s and its weave and capsize speeds (Meijaard, Papadopoulos, Ruina and Schwab, Proc.
R. Soc. A 463, 2007, tables 2 and 3)."""
import math
import warnings

import numpy as np
import pytest

import autolev
from helpers.bicycle import (CAPSIZE, CAPSIZE_SPEED, CASTOR, REAR_RADIUS, WEAVE,
                               WEAVE_SPEED, critical_speeds, lean_and_steer)
from helpers import ROOT

MODEL = ROOT / "autolev_examples" / "whipple_benchmark.al"


@pytest.fixture(scope="module")
def bicycle():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return autolev.load(MODEL)


def upright(model, speed):
    # the rear wheel turns about its axle (to the right) at -v/r to roll forward at v
    return model.linearize({"Q5": math.pi / 10, "U6": -speed / REAR_RADIUS})


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
    weave, capsize = critical_speeds(rows, lambda v: upright(bicycle, v))
    assert weave == pytest.approx(WEAVE_SPEED, abs=1e-9)
    assert capsize == pytest.approx(CAPSIZE_SPEED, abs=1e-9)
