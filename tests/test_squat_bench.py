"""bench/squat.py hands IPOPT our gait problem's constraint Jacobian assembled from
Model.dynamics' sparse blocks (r at each node in x_k, x_k-1 through the backward Euler
rates, and u_k, each node's block given whole): it equals central differences of the
constraints, and nothing outside the pattern it declares moves them."""
import sys

import numpy as np
import pytest

from helpers import ROOT

pytestmark = pytest.mark.corpus


def test_the_squat_problems_jacobian_is_central_differences_of_its_constraints(corpus):
    sys.path.insert(0, str(ROOT / "bench"))
    try:
        import squat
    finally:
        sys.path.remove(str(ROOT / "bench"))
    problem = squat.OurSquat(corpus / squat.GAIT2DE, nodes=4)
    rng = np.random.default_rng(43)
    z = problem.guess(1) + 0.01 * rng.normal(size=problem.n)
    z[problem.n_x:] = 20 * rng.normal(size=problem.n - problem.n_x)
    rows, cols = problem.jacobianstructure()
    exact = np.zeros((problem.m, problem.n))
    exact[rows, cols] = problem.jacobian(z)
    differences = np.zeros_like(exact)
    for i in range(problem.n):
        step = 1e-6 * max(1.0, abs(z[i]))
        up, down = z.copy(), z.copy()
        up[i] += step
        down[i] -= step
        differences[:, i] = (problem.constraints(up) - problem.constraints(down)) / (2 * step)
    scale = np.maximum(1.0, np.abs(exact).max(axis=1, keepdims=True))
    assert np.all(np.abs(exact - differences) <= 1e-6 * scale)
    outside = np.ones_like(exact, dtype=bool)
    outside[rows, cols] = False
    assert not np.any(differences[outside])
