"""The private parts of sympy and scipy autolev leans on (runtime/libraries.py) are still
what autolev needs: a release that changes one fails here, by name."""
import numpy as np
import pytest
import sympy as sm

from autolev.runtime.libraries import (AutolevModelError, dormand_prince_853,
                                       sum_or_product_as_given)
from autolev.engine.integrate import SCIPY_METHODS, _scipy_method


def test_a_sum_is_rebuilt_from_its_terms_as_given_not_sorted_again():
    x, y = sm.symbols("x y")
    terms = (y, x)                       # not sympy's order
    built = sum_or_product_as_given(sm.Add, terms, True)
    assert type(built) is sm.Add and built.args == terms
    assert sm.expand(built - (x + y)) == 0


def test_a_product_is_rebuilt_without_combining_its_factors():
    x = sm.Symbol("x")
    built = sum_or_product_as_given(sm.Mul, (x, x), True)
    assert type(built) is sm.Mul and built.args == (x, x)    # x*x, not x**2
    assert built.subs(x, 3) == 9


def test_only_sums_and_products_are_rebuilt_so():
    with pytest.raises(AutolevModelError):
        sum_or_product_as_given(sm.Pow, (sm.Symbol("x"), 2), True)


def test_the_dop853_tableau_is_the_published_one():
    k = dormand_prince_853()
    assert (k.stages, k.extended) == (12, 16)
    # a Runge-Kutta method's nodes are the row sums of its coefficients, its weights sum
    # to 1, and an error estimate's weights to 0 (consistency, order 1)
    assert np.allclose(k.a.sum(axis=1), k.c)
    assert k.b.sum() == pytest.approx(1.0)
    assert k.e5.sum() == pytest.approx(0.0, abs=1e-12)
    assert k.c[1] == pytest.approx(0.0526001519587677318785587544488)   # Hairer's c2


def test_the_shipped_dop853_tableau_is_scipys_to_the_last_bit():
    from autolev.engine import dop853_tableau as shipped
    k = dormand_prince_853()
    assert (shipped.STAGES, shipped.EXTENDED) == (k.stages, k.extended)
    for name, theirs in (("A", k.a), ("B", k.b), ("C", k.c), ("E3", k.e3), ("E5", k.e5),
                         ("D", k.d)):
        assert np.array_equal(np.array(getattr(shipped, name)), theirs.ravel()), name


def test_the_shipped_rk45_tableau_is_scipys_to_the_last_bit():
    from scipy.integrate import RK45
    from autolev.engine import rk45_tableau as shipped
    assert shipped.STAGES == RK45.n_stages
    a = np.array(shipped.A).reshape(6, 6)       # scipy's is 6 x 5: no stage uses the last
    assert np.array_equal(a[:, :5], RK45.A) and not a[:, 5].any()
    for name, theirs in (("B", RK45.B), ("C", RK45.C), ("E", RK45.E)):
        assert np.array_equal(np.array(getattr(shipped, name)), theirs), name


def test_the_compiled_loop_reads_the_tableau_without_importing_scipy_integrate():
    import subprocess
    import sys
    code = ("import sys; from autolev.engine import cloop; t = cloop._table(); "
            "print(len(t), 'scipy.integrate' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.split()
    assert out == [str(16 * 16 + 12 + 16 + 13 + 13 + 4 * 16), "False"]


def test_the_dop853_tableau_integrates_to_eighth_order():
    # one step of y' = y from y(0) = 1 with the tableau: e^h to within h^9
    k, h = dormand_prince_853(), 0.1
    stages = np.zeros(k.stages)
    for i in range(k.stages):
        stages[i] = 1 + h * k.a[i, :i] @ stages[:i]
    assert 1 + h * k.b @ stages == pytest.approx(np.exp(h), abs=10 * h ** 9)


@pytest.mark.parametrize("name", sorted(SCIPY_METHODS.values()))
def test_each_scipy_method_is_a_public_solver_class(name):
    import scipy.integrate
    solver = _scipy_method(name)
    assert issubclass(solver, scipy.integrate.OdeSolver) and solver.__name__ == name
