"""The Meijaard, Papadopoulos, Ruina and Schwab (2007) benchmark bicycle's published
results (Proc. R. Soc. A 463, tables 2 and 3), and how the bicycle tests read weave and
capsize speeds from a linearization sweep."""
import numpy as np
from scipy.optimize import brentq

REAR_RADIUS = 0.3
WEAVE = complex(-0.775341882195845, 4.46486771378823)      # at 5 m/s
CAPSIZE = -0.322866429004087
CASTOR = -14.0783896927982
WEAVE_SPEED = 4.29238253634111
CAPSIZE_SPEED = 6.02426201538837


def lean_and_steer(lin) -> np.ndarray:
    """The eigenvalues of roll, steer and their rates: the other coordinates are
    ignorable (position, yaw, wheel angles) or dependent (pitch), their eigenvalues 0."""
    idx = [lin.states.index(n) for n in ("Q4", "Q7", "U4", "U7")]
    return np.linalg.eigvals(lin.A[np.ix_(idx, idx)])


def critical_speeds(sweep_rows, upright) -> tuple[float, float]:
    """(weave speed, capsize speed): bracketed by the rows of a `--sweep U6=...` CSV
    (rear wheel rate -v/r), refined by root finding on upright(v), the linearization
    at speed v."""
    speeds, weave_re, capsize_re = [], [], []
    for row in sweep_rows:
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
        ev = lean_and_steer(upright(v))
        return max(ev[np.abs(ev.imag) > 1e-9].real)

    def capsize(v):
        ev = lean_and_steer(upright(v))
        return max(ev[np.abs(ev.imag) <= 1e-9].real)

    return (brentq(weave, *bracket(weave_re), xtol=1e-13),
            brentq(capsize, *bracket(capsize_re), xtol=1e-13))
