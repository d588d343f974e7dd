"""The one-pass differentiation helpers against sympy's own diff, numerically."""
import random

import sympy as sm

from autolev.runtime import fastdiff

X, Y, Z, A = sm.symbols("x y z a", real=True)


def _random_expr(rng, depth):
    if depth == 0:
        return rng.choice([X, Y, Z, A, sm.Integer(rng.randint(1, 5)), sm.Rational(1, 3)])
    kind = rng.randrange(8)
    a, b = _random_expr(rng, depth - 1), _random_expr(rng, depth - 1)
    if kind == 0:
        return a + b
    if kind == 1:
        return a * b
    if kind == 2:
        return a * b * X - Y
    if kind == 3:
        return sm.sin(a) * sm.cos(b)
    if kind == 4:
        return a ** 2 + sm.sqrt(b ** 2 + 1)
    if kind == 5:
        return sm.exp(a / 4) - sm.atan(b)
    if kind == 6:
        return sm.atan2(a, b ** 2 + 2)
    return (a + 1) ** 3 / (b ** 2 + 1)


def _close(u, v, point):
    fu, fv = complex(u.evalf(subs=point)), complex(v.evalf(subs=point))
    return abs(fu - fv) <= 1e-10 * max(1.0, abs(fv))


def test_gradient_equals_sympy_diff_for_every_variable():
    rng = random.Random(7)
    point = {X: 0.3, Y: -0.7, Z: 1.1, A: 0.45}
    for _ in range(60):
        e = _random_expr(rng, 3)
        grad = fastdiff.gradient(e, [X, Y, Z])
        for v in (X, Y, Z):
            want = sm.diff(e, v)
            got = grad.get(v, sm.S.Zero)
            assert _close(got, want, point), (e, v)
        assert A not in grad                    # only the symbols asked for


def test_gradient_and_diff_agree():
    rng = random.Random(11)
    for _ in range(30):
        e = _random_expr(rng, 3)
        grad = fastdiff.gradient(e, [X, Y])
        for v in (X, Y):
            assert _close(grad.get(v, sm.S.Zero), fastdiff.diff(e, v), {X: 0.2, Y: 0.9,
                                                                        Z: -0.4, A: 1.3})


def test_value_and_gradient_at_a_point_equal_sympy_substituting_its_derivatives():
    # the point: x at 0 (sin(0), x*... vanish there), y at a symbol's value, z's value
    # an expression in a (a chain: z stands for z(a) with dz/dx = a, dz/dy = 0)
    rng = random.Random(5)
    values = {X: sm.S.Zero, Y: A + 1, Z: A**2}
    seeds = {X: {X: sm.S.One}, Y: {Y: sm.S.One}, Z: {X: A}}
    for _ in range(60):
        e = _random_expr(rng, 3)
        value, grad = fastdiff.value_and_gradient(e, values, seeds)
        chained = {X: sm.diff(e, X) + sm.diff(e, Z) * A, Y: sm.diff(e, Y)}
        assert _close(value, e.xreplace(values), {A: 0.45}), e
        for v in (X, Y):
            want = chained[v].xreplace(values)
            assert _close(grad.get(v, sm.S.Zero), want, {A: 0.45}), (e, v)
        assert set(grad) <= {X, Y}


def test_gradients_sharing_one_memo_equal_sympy_diff_of_each_expression():
    # expressions sharing parts (as a chain's positions share its joints' rotations),
    # asked one after another of one Gradients: each its own gradient
    rng = random.Random(11)
    point = {X: 0.3, Y: -0.7, Z: 1.1, A: 0.45}
    shared = [_random_expr(rng, 2) for _ in range(3)]
    gradients = fastdiff.Gradients({X, Y, Z}.__contains__)
    for k in range(12):
        e = _random_expr(rng, 2) * shared[k % 3] + shared[(k + 1) % 3] ** 2 + A * X
        g = gradients.of(e)
        assert set(g) <= {X, Y, Z}
        for x in (X, Y, Z):
            assert _close(g.get(x, sm.S.Zero), sm.diff(e, x), point), (e, x)


def test_a_product_made_without_flattening_is_the_one_sympy_makes():
    import itertools
    import sympy as sm
    from autolev.runtime.fastdiff import times
    symbols = list(sm.symbols("Z2 Z10 q1 U1 a_b x")) + [sm.Dummy("d")]
    numbers = [sm.Integer(-1), sm.Integer(3), sm.Rational(-1, 2), sm.Float(0.25),
               sm.Integer(0), sm.Integer(1), sm.Float(1.0), sm.oo]
    odd = [sm.Symbol("A", commutative=False), sm.sin(symbols[0]), symbols[0] ** 2]
    for a, b in itertools.product(symbols + numbers + odd, repeat=2):
        ours, sympys = times(a, b), a * b
        assert (type(ours), ours.args) == (type(sympys), sympys.args), (a, b)
        assert ours == sympys and hash(ours) == hash(sympys)


def _factors(rng):
    """A product sympy makes of a few factors: symbols, powers, calls, sums, numbers."""
    pool = [X, Y, Z, A, X ** 2, 1 / Y, sm.sqrt(Z), sm.cos(X), sm.exp(Y), sm.I,
            sm.Integer(-2), sm.Rational(3, 4), sm.Float(0.5), X + Y, sm.sqrt(2), A - 1,
            sm.exp_polar(Z), sm.pi, sm.pi ** 2]
    return sm.Mul(*rng.sample(pool, rng.randint(1, 3)))


def test_products_of_products_made_without_flattening_are_the_ones_sympy_makes():
    from autolev.runtime.fastdiff import times
    rng = random.Random(7)
    for _ in range(3000):
        a, b = _factors(rng), _factors(rng)
        ours, sympys = times(a, b), a * b
        assert (type(ours), ours.args) == (type(sympys), sympys.args), (a, b)
        assert ours == sympys and hash(ours) == hash(sympys)


def test_a_sum_of_products_is_the_one_sympy_makes():
    from autolev.runtime.fastdiff import sum_of_products
    rng = random.Random(8)
    for _ in range(500):
        pairs = [(_factors(rng) if rng.random() < 0.8 else sm.S.Zero, _factors(rng))
                 for _ in range(rng.randint(0, 4))]
        sympys = sum((a * b for a, b in pairs), sm.S.Zero)
        ours = sum_of_products(pairs)
        assert (type(ours), ours.args) == (type(sympys), sympys.args), pairs


def test_a_matrix_product_has_sympys_entries_in_sympys_order():
    # the order of the stored entries is the order a walk over them names Z's in
    from autolev.runtime.frame import product_as_sympy
    rng = random.Random(9)
    pool = [X, Y * Z, sm.cos(A), 2 * X + 1, sm.S.One, sm.Integer(-1), sm.S.Zero,
            sm.S.Zero, sm.S.Zero]
    for _ in range(400):
        n, k, m = rng.randint(1, 4), rng.randint(1, 4), rng.randint(1, 4)
        a = sm.Matrix(n, k, lambda i, j: rng.choice(pool))
        b = sm.Matrix(k, m, lambda i, j: rng.choice(pool))
        if rng.random() < 0.5:          # a matrix whose entries were stored out of order
            b = (b.T * b.T.T).T if k == m else b
        ours, sympys = product_as_sympy(a, b), a * b
        assert ours == sympys
        assert list(ours.todok().items()) == list(sympys.todok().items()), (a, b)


def test_a_sum_made_without_flattening_is_the_one_sympy_makes():
    from autolev.runtime.fastdiff import total
    rng = random.Random(10)
    pool = [X, Y, 2 * X, -X * Y, X * Y, 3 * Z ** 2, sm.cos(X), -sm.cos(X), X ** 2,
            sm.Rational(1, 2) * A * X, sm.Float(0.5) * Y, sm.sqrt(2), sm.Integer(3), X + Y,
            sm.oo * X, sm.pi, 2 ** sm.Rational(-1, 2), -(X + 1) * Y, sm.exp(Z), Y * Z]
    for _ in range(3000):
        terms = [rng.choice(pool) for _ in range(rng.randint(1, 5))]
        ours, sympys = total(terms), sm.Add(*terms)
        assert (type(ours), ours.args) == (type(sympys), sympys.args), terms
        assert ours == sympys and hash(ours) == hash(sympys)
