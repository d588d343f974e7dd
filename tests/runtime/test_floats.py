"""runtime/floats.py: an expression's value at a point, each shared part once, against
sympy's own evaluation."""
import math

import pytest
import sympy as sm

from autolev.runtime.floats import NoRealValue, NotElementary, ValuesAt, complex_value

x, y, z = sm.symbols("x y z")
f = sm.Function("f")
t = sm.Symbol("t")


def _nowhere(e):
    raise LookupError(e)


@pytest.mark.parametrize("expr", [
    sm.sin(x) * sm.cos(y) ** 2 + sm.sqrt(z) / (1 + x ** 2),
    sm.atan2(y, x) - sm.exp(-z) * sm.Abs(x - y),
    sm.asin(x / 2) + sm.acos(y / 3) * sm.tanh(z),
    (x - 2) ** sm.Rational(1, 3) * (x - 2) ** sm.Rational(2, 3),   # complex on the way
    sm.asin(z + 1) + sm.conjugate(sm.asin(z + 1)),                  # past math's domain
    sm.pi * x + sm.E ** y - sm.I * sm.I * sm.GoldenRatio,            # sympy's constants
    sm.atan2(y, x - 3) * sm.sign(y) + sm.Max(x, z),                  # no complex double
    sm.re(sm.log(y) * sm.I),                                         # log on its cut
])
def test_values_equal_sympys(expr):
    point = {x: 0.7, y: -0.4, z: 1.3}
    assert math.isclose(ValuesAt(point, _nowhere)(expr),
                        float(sm.re(expr.subs(point).evalf(30))), rel_tol=1e-13)


def test_a_shared_part_is_computed_once():
    # a tree of 2**60 leaves: sympy's xreplace would walk every one of them
    e = x
    for _ in range(60):
        e = sm.sin(e) * e + y
    value, expected = 0.3, 0.3
    for _ in range(60):
        expected = math.sin(expected) * expected - 0.2
    assert ValuesAt({x: value, y: -0.2}, _nowhere)(e) == pytest.approx(expected, rel=1e-12)


def test_what_the_point_lacks_is_asked_and_definitions_follow_their_order():
    asked = []

    def zero(e):
        asked.append(e)
        return 0.0
    values = ValuesAt({f(t): 2.0}, zero)
    values.define(z, f(t) * 3)
    assert values(z + sm.Derivative(f(t), t) + x) == 6.0
    assert set(asked) == {sm.Derivative(f(t), t), x}
    with pytest.raises(NoRealValue, match="not real"):
        ValuesAt({x: -1.0}, _nowhere)(sm.sqrt(x))


def test_no_value_is_said_and_the_plain_walk_leaves_what_it_does_not_take_to_sympy():
    with pytest.raises(NoRealValue, match="no value"):
        ValuesAt({x: 0.0}, _nowhere)(1 / x)
    with pytest.raises(NoRealValue, match="no finite value"):
        ValuesAt({x: 1e300, y: 1e300}, _nowhere)(x * y)
    for e in (x + y, sm.atan2(x, 1), sm.asin(x), x * 1e300 * 1e300):
        with pytest.raises(NotElementary):
            complex_value(e, {x: 2.0}, {})
