"""The Dormand-Prince 5(4) tableau of scipy's RK45 (Autolev's Matlab programs call
ode45, the same pair): the compiled loop integrates with these numbers, so a run does
not import scipy.integrate to read them.  Each entry is the fraction evaluated in
double precision as scipy evaluates it; tests/runtime/test_libraries.py compares them."""

STAGES = 6

C = (0.0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1.0)

A = (
    0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
    1 / 5, 0.0, 0.0, 0.0, 0.0, 0.0,
    3 / 40, 9 / 40, 0.0, 0.0, 0.0, 0.0,
    44 / 45, -56 / 15, 32 / 9, 0.0, 0.0, 0.0,
    19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729, 0.0, 0.0,
    9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656, 0.0,
)

B = (35 / 384, 0.0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84)

# the error estimate's weights: the 5th order solution less the embedded 4th's
E = (-71 / 57600, 0.0, 71 / 16695, -71 / 1920, 17253 / 339200, -22 / 525, 1 / 40)
