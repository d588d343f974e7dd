"""The corpus's Whipple-plus-rider-lean bicycle (moorepants/RiderModel,
WhipplePlusRiderLean.AL: five bodies, rider lean Q9 on a hinge, SOLVE(ZERO, U4', U6',
U7', U9') and no program to integrate) linearized upright.  With the rider massless and
the lean locked it is the Meijaard et al. (2007) benchmark bicycle: its eigenvalues at
5 m/s and weave and capsize speeds (tables 2 and 3).  With a rider of mass, locked, it
is our own Whipple model (autolev_examples/whipple_benchmark.al) with the rider's mass
and inertia added to the rear frame by hand."""
import math
import warnings

import numpy as np
import pytest

import autolev
from helpers.bicycle import (CAPSIZE, CAPSIZE_SPEED, CASTOR, REAR_RADIUS, WEAVE,
                               WEAVE_SPEED, critical_speeds, lean_and_steer)
from helpers import ROOT

pytestmark = pytest.mark.corpus

RIDER_MODEL = "moorepants+RiderModel/autolev/WhipplePlusRiderLean.AL"
# the benchmark's parameters in the model's names (its INPUT lines are commented out)
BENCHMARK = dict(W=1.02, C=0.08, LAMBDA=math.pi / 10, G=9.81, RR=0.3, M_R=2, IRXX=0.0603,
                 IRYY=0.12, XB=0.3, ZB=-0.9, M_B=85, IBXX=9.2, IBYY=11, IBZZ=2.8,
                 IBXZ=2.4, XH=0.9, ZH=-0.7, M_H=4, IHXX=0.05892, IHYY=0.06,
                 IHZZ=0.00708, IHXZ=-0.00756, RF=0.35, M_F=3, IFXX=0.1405, IFYY=0.28)
MASSLESS_RIDER = dict(HH=0.9, XBR=0.3, ZBR=-1.0, M_BR=0, IBRXX=0, IBRYY=0, IBRZZ=0,
                      IBRXZ=0)


@pytest.fixture(scope="module")
def rider_bicycle(corpus):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return autolev.load(corpus / RIDER_MODEL)


def upright(model, speed, **changes):
    # the rear wheel turns about C2> at -v/r to roll forward at v
    point = dict(BENCHMARK, **MASSLESS_RIDER, U6=-speed / REAR_RADIUS)
    point.update(changes)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")        # V: declared, used by no equation
        return model.linearize(point, locked=["Q9"])


def test_the_massless_rider_locked_is_the_benchmark_bicycle(rider_bicycle):
    lin = upright(rider_bicycle, 5.0)
    assert "Q9" not in lin.states and "U9" not in lin.states and lin.locked == ["Q9"]
    assert lin.steady
    values = lin.eigenvalues()
    assert np.allclose(values[:4], [CASTOR, WEAVE.conjugate(), WEAVE, CAPSIZE],
                       rtol=0, atol=1e-10)
    assert np.allclose(values[4:], 0, atol=1e-12)        # ignorable or dependent


def test_free_rider_lean_of_a_massless_rider_is_a_clear_error(rider_bicycle):
    point = dict(BENCHMARK, **MASSLESS_RIDER, U6=-5 / REAR_RADIUS)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(autolev.runtime.AutolevModelError,
                           match="mass matrix is singular at the operating point"):
            rider_bicycle.linearize(point)


def test_weave_and_capsize_speeds_from_the_command(rider_bicycle, corpus, tmp_path):
    from autolev.cli import main
    at = [a for k, v in dict(BENCHMARK, **MASSLESS_RIDER).items()
          for a in ("--at", f"{k}={v!r}")]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert main(["linearize", str(corpus / RIDER_MODEL), *at, "--lock", "Q9",
                     "--constraint", "PZERO", "--dependent", "Q5",
                     "--sweep", "U6=-10:-25:16", "--out", str(tmp_path)]) == 0
    lines = (tmp_path / "WhipplePlusRiderLean-sweep.csv").read_text().splitlines()
    assert lines[0].startswith("U6,re1,im1,")
    for row in lines[1:]:                       # pitch Q5 reduced away by PZERO = 0
        assert len(row.split(",")) == 1 + 2 * 10
    weave, capsize = critical_speeds(lines[1:], lambda v: upright(rider_bicycle, v))
    assert weave == pytest.approx(WEAVE_SPEED, abs=1e-9)
    assert capsize == pytest.approx(CAPSIZE_SPEED, abs=1e-9)


def test_a_locked_rider_of_mass_is_a_heavier_rear_frame(rider_bicycle):
    # the rider (mass centre at XBR, ZBR; inertia about it in the bicycle's axes) added
    # to the rear frame by the parallel-axis theorem, in our own Whipple model
    rider = dict(HH=0.9, XBR=0.35, ZBR=-1.2, M_BR=40, IBRXX=3.1, IBRYY=2.9, IBRZZ=0.9,
                 IBRXZ=0.4)
    mb, xb, zb = BENCHMARK["M_B"], BENCHMARK["XB"], BENCHMARK["ZB"]
    mr, xr, zr = rider["M_BR"], rider["XBR"], rider["ZBR"]
    mass = mb + mr
    x, z = (mb * xb + mr * xr) / mass, (mb * zb + mr * zr) / mass

    def moved(m, dx, dz):     # inertia of a point mass about the combined mass centre
        return np.array([[m * dz * dz, -m * dx * dz], [-m * dx * dz, m * dx * dx]])
    frame = moved(mb, xb - x, zb - z) + moved(mr, xr - x, zr - z)
    ixx = BENCHMARK["IBXX"] + rider["IBRXX"] + frame[0, 0]
    izz = BENCHMARK["IBZZ"] + rider["IBRZZ"] + frame[1, 1]
    ixz = BENCHMARK["IBXZ"] + rider["IBRXZ"] + frame[0, 1]
    iyy = (BENCHMARK["IBYY"] + rider["IBRYY"] + mb * ((xb - x) ** 2 + (zb - z) ** 2)
           + mr * ((xr - x) ** 2 + (zr - z) ** 2))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        whipple = autolev.load(ROOT / "autolev_examples" / "whipple_benchmark.al")
        ours = whipple.linearize({"Q5": math.pi / 10, "U6": -4.0 / REAR_RADIUS, "MB": mass,
                                  "XB": x, "ZB": z, "IBXX": ixx, "IBYY": iyy, "IBZZ": izz,
                                  "IBXZ": ixz})
    theirs = upright(rider_bicycle, 4.0, **rider)
    want = np.sort_complex(lean_and_steer(ours))
    assert np.allclose(np.sort_complex(lean_and_steer(theirs)), want, rtol=0, atol=1e-10)
    # and not the benchmark: the rider's mass changes the motion
    assert not np.allclose(want, np.sort_complex(lean_and_steer(upright(rider_bicycle, 4.0))),
                           atol=1e-3)
