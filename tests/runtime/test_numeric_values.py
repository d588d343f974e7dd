"""The value of an expression at a point (verify's and the transcript's numbers): taken
in complex double precision where every node is elementary, by sympy otherwise; both
ways give sympy's principal values, checked here against sympy's own evalf."""
import cmath
import math

import pytest
import sympy as sm

from autolev.runtime.calculus import _number_at

x, y, z = sm.symbols("x y z", real=True)
VALUES = {x: sm.Float(0.7), y: sm.Float(-1.3), z: sm.Float(2.5)}


@pytest.mark.parametrize("e", [
    x + y * z, x ** 2 - sm.sqrt(z) / y, sm.sin(x) * sm.cos(y) + sm.tan(z),
    sm.exp(x * y), sm.log(z), sm.asin(x), sm.acos(x) + sm.atan(y), sm.sinh(y) * sm.cosh(z),
    sm.tanh(x), sm.Abs(y), sm.Rational(3, 7) * x + sm.pi * y + sm.E,
    # principal branches: a root or logarithm of a negative number is complex
    sm.sqrt(y), y ** sm.Rational(1, 3), sm.log(y), sm.asin(z), sm.acos(-z),
    sm.atan(sm.I * z), (x + sm.I * y) ** 2,
    # a real product whose zero imaginary part came out negative: the root's branch holds
    sm.sqrt((y + 0 * sm.I) * (-1 + 0 * sm.I) * (-1)), sm.sqrt(-(x * y) * z * (-1) * (-1)),
    # not elementary: left to sympy
    sm.atan2(y, x), sm.Piecewise((x, y < 0), (z, True)), sm.Max(x, y), sm.sign(y),
    sm.floor(z),
])
def test_a_value_is_sympys(e):
    expected = complex(e.xreplace(VALUES).evalf())
    got = _number_at(e, VALUES)
    assert cmath.isclose(got, expected, rel_tol=1e-13, abs_tol=1e-13)


def test_a_repeated_part_is_taken_once_and_the_same():
    part = sm.sin(x) * sm.cos(y) + z
    e = part ** 2 + 3 * part - sm.sqrt(part)
    v = complex(part.xreplace(VALUES))
    assert cmath.isclose(_number_at(e, VALUES), v ** 2 + 3 * v - cmath.sqrt(v), rel_tol=1e-14)


def test_without_a_value_it_is_nan_as_before():
    assert cmath.isnan(_number_at(x + sm.Symbol("w"), VALUES))
    # MAX of a complex number has no value
    assert cmath.isnan(_number_at(sm.Max(sm.sqrt(y), x), VALUES))


def test_beyond_double_precision_sympy_decides():
    # exp(1000) overflows a double: sympy's number is kept (it is finite there)
    got = _number_at(sm.exp(1000 * z) / sm.exp(999 * z), VALUES)
    assert got.real == pytest.approx(math.exp(2.5), rel=1e-12)
    assert cmath.isnan(_number_at(1 / (x - x + 0 * y), VALUES)) or \
        not math.isfinite(abs(_number_at(1 / (x - x + 0 * y), VALUES)))


@pytest.mark.parametrize("e", [sm.sqrt(-x * y), sm.log(-x * y * z), sm.sqrt(x * y * z)])
def test_products_of_negative_numbers_keep_the_principal_branch(e):
    # (-1.3+0j) * (-1+0j) is (1.3-0j) in complex arithmetic: a root of its negative would
    # take the other branch; the value is sympy's
    values = {x: sm.Float(-1.3), y: sm.Float(-1.0), z: sm.Float(-2.0)}
    expected = complex(e.xreplace(values).evalf())
    assert cmath.isclose(_number_at(e, values), expected, rel_tol=1e-13)


def test_the_symbols_of_an_expression_of_shared_parts_are_found_in_one_visit_each():
    from autolev.runtime.calculus import symbols_in
    # 40 levels, each part used twice: 2^40 occurrences, 80 distinct nodes
    e = x + y
    for k in range(40):
        e = sm.Mul(e, sm.Add(e, z, evaluate=False), evaluate=False)
    assert symbols_in(e) == {x, y, z}
    assert symbols_in(sm.sin(x) + 3) == {x} and symbols_in(sm.Integer(2)) == set()
