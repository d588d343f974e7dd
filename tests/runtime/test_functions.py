"""Autolev's functions and settings, translated and run, against values worked out by
hand (reference sections 1.7-1.11), including the cases SymPy's parser gets wrong
(reference 2.2/2.3, noted per test)."""
import math

import pytest
import sympy as sm

import autolev
import autolev.runtime as al


def build(text: str) -> dict:
    code = autolev.transpile(text, "f.al")
    ns = {"__name__": "test_functions_model"}
    exec(compile(code, "f.py", "exec"), ns)
    return ns


def val(ns, expr, **values):
    """Numeric value of an expression of the built model (definitions expanded)."""
    model = ns["model"]
    e = model.explicit(sm.sympify(expr))
    subs = {s: values[s.name] for s in e.free_symbols if s.name in values}
    out = e.xreplace(subs)
    if isinstance(out, sm.MatrixBase):
        return sm.Matrix(out).evalf()
    return complex(out.evalf())


def sym(ns, name):
    return ns[name]


# -- algebra ----------------------------------------------------------------------------
def test_coef_of_a_variable_a_monomial_and_the_matrix_form():
    ns = build("CONSTANTS a,b,c,d\nVARIABLES x,y\nE = a*x^2 + b*x*y + c*y + d\n"
               "C1 = COEF(E, x)\nC2 = COEF(E, x^2)\nC3 = COEF(E, x*y)\n"
               "M = COEF([a*x+b*y; c*x+d*y], [x, y])")
    a, b, c, d, y = (sm.Symbol(n, real=True) for n in "abcdy")
    assert sm.expand(ns["C1"] - b * y) == 0          # the x^1 term, not dE/dx
    assert ns["C2"] == a and ns["C3"] == b
    assert ns["M"] == sm.Matrix([[a, b], [c, d]])     # the peer fails on matrix args


def test_exclude_and_include_split_the_terms():
    ns = build("CONSTANTS a,b\nVARIABLES x\nE = a*SIN(x) + b*x^2 + a*b + 3\n"
               "Ex = EXCLUDE(E, x)\nIn = INCLUDE(E, x)")
    a, b, x = (sm.Symbol(n, real=True) for n in "abx")
    assert ns["Ex"] == a * b + 3                      # not E at x=0 (that adds nothing here,
    assert sm.expand(ns["In"] - (a * sm.sin(x) + b * x**2)) == 0  # but sin would)
    # the peer's INCLUDE returns the coefficient of x, not the terms holding x


def test_exclude_through_intermediate_variables():
    ns = build("VARIABLES u'\nCONSTANTS m,k\nZ1 = m*u' + k*u\nE = 2*Z1 + 5\n"
               "F = EXCLUDE(E, u')")
    u, k = sm.Symbol("u", real=True), sm.Symbol("k", real=True)
    assert sm.expand(ns["model"].explicit(ns["F"]) - (2 * k * u + 5)) == 0


def test_expand_with_a_degree_range_truncates():
    ns = build("CONSTANTS a\nVARIABLES x\nE = (a+x)^3\nE0 = EXPAND(E)\n"
               "E1 = EXPAND(E, 0:1)\nE2 = EXPAND(E, 2:3)\nE3 = EXPAND(E, 1)")
    a, x = sm.Symbol("a", real=True), sm.Symbol("x", real=True)
    assert ns["E0"] == sm.expand((a + x)**3)
    assert ns["E1"] == a**3 + 3 * a**2 * x            # degree counted in the variable x
    assert ns["E2"] == 3 * a * x**2 + x**3
    assert ns["E3"] == ns["E1"]


def test_expand_and_factor_as_statements_change_the_name():
    ns = build("VARIABLES x, y\nE = (x+2*y)^2 + 3*(7+x)*(x+y)\nEXPAND(E)\nG = E\n"
               "FACTOR(E, x)")
    x, y = sm.Symbol("x", real=True), sm.Symbol("y", real=True)
    assert ns["G"] == 4*x**2 + 7*x*y + 4*y**2 + 21*x + 21*y     # tutorial 1, by hand
    assert ns["E"] == 4*x**2 + x*(7*y + 21) + 4*y**2 + 21*y


def test_factor_leaves_function_arguments_as_they_are():
    ns = build("VARIABLES x\nCONSTANTS a, b\nE = a*x + b*x + SIN(x*(a+b))\nFACTOR(E, x)")
    x, a, b = (sm.Symbol(n, real=True) for n in "xab")
    assert ns["E"] == x * (a + b) + sm.sin(x * (a + b))


def test_arrange_replace_and_evaluate():
    ns = build("CONSTANTS a,b\nVARIABLES x\nAr = ARRANGE(a*x + b*x + a*b, 1, x)\n"
               "R = REPLACE(a*x + b, x=SIN(b), a=2)\nV = EVALUATE(a*x^2, x=2, a=3)\n"
               "S = EVALUATE(SIN(x), x=30*UNITS(deg,rad))")
    a, b, x = (sm.Symbol(n, real=True) for n in "abx")
    assert ns["Ar"] == a * b + x * (a + b)
    assert ns["R"] == b + 2 * sm.sin(b)
    assert ns["V"] == 12
    # EVALUATE takes numbers as radians (tutorial 2 writes q=90*Units(deg,rad))
    assert abs(float(ns["S"]) - 0.5) < 1e-15


def test_evaluate_keeps_stored_right_hand_sides_unapplied():
    # the peer silently applies every stored RHS first (reference 2.1/2.2)
    ns = build("VARIABLES x, y\nCONSTANTS c\nx = c*y\nE = x + y\nV = EVALUATE(E, y=2)")
    x, c = sm.Symbol("x", real=True), sm.Symbol("c", real=True)
    assert ns["V"].free_symbols <= {x, c}
    assert val(ns, ns["V"], c=3) == 8                 # x = c*y = 6 through the definition


def test_polynomial_and_roots():
    ns = build("CONSTANTS a\nP = POLYNOMIAL([1, 2, 3], a)\nR = ROOTS([1, -3, 2])\n"
               "R2 = ROOTS(a^2 - 3*a + 2, a, 2)\nR3 = ROOTS([1; 2; 3; 4])\n"
               "C = POLYNOMIAL(3*a^2 + 5, a, 2)")
    a = sm.Symbol("a", real=True)
    assert ns["P"] == a**2 + 2 * a + 3
    assert [float(r) for r in ns["R"]] == [1.0, 2.0]
    assert [float(r) for r in ns["R2"]] == [1.0, 2.0]
    # x^3 + 2x^2 + 3x + 4 (tutorial 1), checked with numpy's companion matrix
    import numpy as np
    want = sorted(np.roots([1, 2, 3, 4]), key=lambda z: (z.real, z.imag))
    got = [complex(r) for r in ns["R3"]]
    assert all(abs(g - w) < 1e-12 for g, w in zip(got, want))
    assert list(ns["C"]) == [3, 0, 5]


def test_taylor_on_constants_variables_and_the_perturbation_form():
    ns = build("VARIABLES q', dq'\nCONSTANTS k\nT1 = TAYLOR(x*COS(k), 0:2, k=0)\n"
               "T2 = TAYLOR(SIN(q), 0:3, q=0)\n"
               "T3 = TAYLOR(COS(q)*q'^2 + SIN(q)*q', 1, q=0:dq, q'=0:dq')\n"
               "T4 = TAYLOR(COS(q), 1, q=k:dq)".replace("x*", "2*"))
    k, q, dq = (sm.Symbol(n, real=True) for n in ("k", "q", "dq"))
    assert sm.expand(ns["T1"] - (2 - k**2)) == 0
    assert ns["T2"] == q - q**3 / 6                    # the peer: only constants work
    assert ns["T3"] == 0 * dq                          # q' terms are of second order
    assert sm.expand(ns["T4"] - (sm.cos(k) - sm.sin(k) * dq)) == 0


def test_taylor_perturbation_linearises_a_pendulum():
    ns = build("VARIABLES q'', dq''\nCONSTANTS g, L\n"
               "Zero = q'' + g/L*SIN(q)\n"
               "P = TAYLOR(Zero, 1, q=0:dq, q'=0:dq', q''=0:dq'')")
    g, L, dq = (sm.Symbol(n, real=True) for n in ("g", "L", "dq"))
    dqdd = al.derivative(dq, 2)
    assert sm.expand(ns["P"] - (dqdd + g / L * dq)) == 0


def test_taylor_in_several_variables_through_definitions_to_second_order():
    # the gradient of each order in one pass over the definitions (W, V in between)
    ns = build("AUTOZ ON\nVARIABLES x, y\nCONSTANTS c\nW = SIN(x + c*y)*COS(x*y)\n"
               "V = EXP(W)*y\nT = TAYLOR(V + x*W, 0:2, x=1, y=2)")
    x, y, c = (sm.Symbol(n, real=True) for n in "xyc")
    f = sm.exp(sm.sin(x + c * y) * sm.cos(x * y)) * y + x * sm.sin(x + c * y) * sm.cos(x * y)
    dx, dy = x - 1, y - 2
    at = {x: 1, y: 2}
    # the textbook second-order expansion, term by term with sympy on the explicit form
    want = (f.subs(at) + f.diff(x).subs(at) * dx + f.diff(y).subs(at) * dy
            + (f.diff(x, 2).subs(at) * dx**2 + 2 * f.diff(x, y).subs(at) * dx * dy
               + f.diff(y, 2).subs(at) * dy**2) / 2)
    got = ns["model"].explicit(ns["T"])
    for point in ({x: 0.3, y: -0.7, c: 1.3}, {x: 2.1, y: 0.4, c: -0.6}):
        assert abs(complex(got.evalf(subs=point)) - complex(want.evalf(subs=point))) < 1e-11


def test_first_order_taylor_is_the_gradient_at_the_point_through_definitions():
    # order 1 takes each definition's value and gradient at the point in one pass
    # (Definitions.at_point): factors vanishing there (SIN(q)*..., u*...), a point
    # given by a constant, atan2 and MAX (no forward rule: their partials) and a
    # definition whose gradient there is 0 while its value is not (W2 at q=0)
    ns = build("AUTOZ ON\nVARIABLES q, u, r, dq, du, dr\nCONSTANTS c, u0\n"
               "W1 = SIN(q)*EXP(u*r) + COS(q + c*u)^3\nW2 = COS(q)*(1 + r^2) + u*W1\n"
               "W3 = ATAN2(W2, 1 + r^2) + MAX(r, c)*W1\n"
               "T = TAYLOR(W3*W2 + q*u, 0:1, q=0, u=u0, r=0.5)\n"
               "P = TAYLOR(W3 - W1^2, 1, q=0:dq, u=u0:du, r=0:dr)\n"
               "L = TAYLOR(W2, 1:1, q=0, u=u0, r=0.5)")
    q, u, r, c, u0, dq, du, dr = (sm.Symbol(n, real=True)
                                 for n in ("q", "u", "r", "c", "u0", "dq", "du", "dr"))
    w1 = sm.sin(q) * sm.exp(u * r) + sm.cos(q + c * u) ** 3
    w2 = sm.cos(q) * (1 + r**2) + u * w1
    w3 = sm.atan2(w2, 1 + r**2) + sm.Max(r, c) * w1

    def linear(f, at, steps):
        """the textbook first-order terms, by sympy on the explicit form"""
        return sum(f.diff(x).subs(at) * step for x, step in steps)

    at = {q: 0, u: u0, r: sm.Rational(1, 2)}
    steps = [(q, q), (u, u - u0), (r, r - sm.Rational(1, 2))]
    f = w3 * w2 + q * u
    want = {"T": f.subs(at) + linear(f, at, steps), "L": linear(w2, at, steps)}
    g = w3 - w1**2
    want["P"] = g.subs({q: 0, u: u0, r: 0}) + linear(g, {q: 0, u: u0, r: 0},
                                                    [(q, dq), (u, du), (r, dr)])
    explicit = ns["model"].explicit
    for name, expected in want.items():
        got = explicit(ns[name])
        for point in ({q: 0.3, u: -0.7, r: 0.2, c: 1.3, u0: 0.4, dq: 0.1, du: -0.2, dr: 0.3},
                      {q: -1.1, u: 0.9, r: 0.8, c: 0.1, u0: -0.5, dq: 0.7, du: 0.6, dr: -0.4}):
            assert abs(complex(got.evalf(subs=point))
                       - complex(expected.evalf(subs=point))) < 1e-11, name


def test_d_of_a_column_by_a_row_is_the_jacobian_through_definitions():
    ns = build("VARIABLES q{2}\nCONSTANTS c\nW = c*q1\nM = D([SIN(q1)*q2; W*q2], [q1, q2])")
    q1, q2, c = (sm.Symbol(n, real=True) for n in ("q1", "q2", "c"))
    m = ns["model"].explicit(ns["M"])
    assert m == sm.Matrix([[q2 * sm.cos(q1), sm.sin(q1)], [c * q2, c * q1]])


def test_a_jacobian_written_element_by_element_follows_every_definition():
    # a new E is differentiated in one pass in the names the previous E was asked about
    # (runtime Model._partial); the later D's take those derivatives, and one asked
    # after E's definitions changed takes the new ones
    ns = build("VARIABLES q{2}\nCONSTANTS c\nW = c*q1^2\nE = W*SIN(q2) + q1*q2\n"
               "J11 = D(W, q1)\nJ12 = D(W, q2)\nJ21 = D(E, q1)\nJ22 = D(E, q2)\n"
               "W = c*q2^3\nE = W*COS(q1)\nK1 = D(E, q1)\nK2 = D(E, q2)")
    q1, q2, c = (sm.Symbol(n, real=True) for n in ("q1", "q2", "c"))
    explicit = ns["model"].explicit
    first, second = c * q1 ** 2 * sm.sin(q2) + q1 * q2, c * q2 ** 3 * sm.cos(q1)
    for name, expected in (("J11", 2 * c * q1), ("J12", 0),
                           ("J21", first.diff(q1)), ("J22", first.diff(q2)),
                           ("K1", second.diff(q1)), ("K2", second.diff(q2))):
        assert sm.simplify(explicit(ns[name]) - expected) == 0, name


# -- solving and definitions --------------------------------------------------------------
def test_solve_records_definitions_that_rhs_and_explicit_return():
    ns = build("VARIABLES x, y\nCONSTANTS a,b,c,d\nZero[1] = a*x+b*y-1\nZero[2] = c*x+d*y-2\n"
               "SOLVE(Zero, x, y)\nRx = RHS(x)\nEx = EXPLICIT(x)\nEy = EXPLICIT(y)")
    a, b, c, d = (sm.Symbol(n, real=True) for n in "abcd")
    det = a * d - b * c
    assert sm.simplify(ns["Ex"] - (d - 2 * b) / det) == 0
    assert sm.simplify(ns["Ey"] - (2 * a - c) / det) == 0
    assert sm.simplify(ns["model"].explicit(ns["Rx"]) - ns["Ex"]) == 0


def test_solve_of_a_matrix_with_a_list_of_unknowns():
    # the peer returns a dict keyed by a matrix here (reference 1.7)
    ns = build("VARIABLES x, y\nCONSTANTS a, b\nEq = [x+y-a; x-y-b]\nSOLVE(Eq, [x, y])\n"
               "Rx = RHS(x)\nRy = RHS(y)")
    a, b = sm.Symbol("a", real=True), sm.Symbol("b", real=True)
    assert sm.expand(ns["Rx"] - (a + b) / 2) == 0 and sm.expand(ns["Ry"] - (a - b) / 2) == 0


def test_rhs_of_a_speed_derivative_after_kane():
    # `RHS(U1')` after KANE() crashes the peer (reference 1.7)
    ns = build("NEWTONIAN N\nPARTICLES P\nPOINTS O\nMOTIONVARIABLES' Q', U'\nCONSTANTS M, K\n"
               "MASS P=M\nQ' = U\nP_O_P> = Q*N1>\nV_O_N> = 0>\nV_P_N> = U*N1>\n"
               "FORCE_P> = -K*Q*N1>\nZERO = FR() + FRSTAR()\nKANE()\n"
               "SOLVE(ZERO, U')\nA = RHS(U')")
    assert val(ns, ns["A"], K=3, M=2, Q=0.5) == -0.75


def test_zee_and_zee_not():
    ns = build("CONSTANTS a, b\nVARIABLES x, w\nZEE_NOT = [w]\n"
               "E = (a+b)^2*SIN(x) + w*(a+b)\nZ = ZEE(E)\nC = COEF(Z, w)")
    a, b, x, w = (sm.Symbol(n, real=True) for n in ("a", "b", "x", "w"))
    assert w in ns["Z"].free_symbols                  # kept visible
    assert sm.expand(ns["model"].explicit(ns["Z"]) - ((a + b)**2 * sm.sin(x) + w * (a + b))) == 0
    assert sm.expand(ns["model"].explicit(ns["C"]) - (a + b)) == 0


def test_input_as_a_function_gives_the_input_value():
    ns = build("CONSTANTS a, b\nINPUT b = 2.5, a = 30 DEG\nX = INPUT(b)*3\nY = INPUT(a)")
    assert ns["X"] == 7.5
    assert abs(float(ns["Y"]) - math.pi / 6) < 1e-15     # in radians, as stored


# -- matrices ------------------------------------------------------------------------------
def test_matrix_functions_by_hand():
    ns = build("CONSTANTS a\nM = [1, 2; 3, 4]\nD1 = DET(M)\nI1 = INV(M)\nT1 = TRACE(M)\n"
               "T2 = TRANSPOSE(M)\nEl = ELEMENT(M, 2, 1)\nR = ROWS(M)\nC = COLS(M)\n"
               "R2 = ROWS(M, 2)\nR3 = ROWS([M; M], 2, 3:4)\nC2 = COLS(M, 2, 1)\n"
               "Dg = DIAGMAT(2, a)\nDg2 = DIAGMAT(2, 3, a)\nB = [M, [5; 6]; [7, 8, 9]]\n"
               "X[3] = a")
    a = sm.Symbol("a", real=True)
    assert ns["D1"] == -2 and ns["T1"] == 5
    assert ns["I1"] == sm.Matrix([[-2, 1], [sm.Rational(3, 2), -sm.Rational(1, 2)]])
    assert ns["T2"] == sm.Matrix([[1, 3], [2, 4]])
    assert ns["El"] == 3                              # 1-based (the peer's docs: M[2,3])
    assert (ns["R"], ns["C"]) == (2, 2)
    assert ns["R2"] == sm.Matrix([[3, 4]])
    assert ns["R3"] == sm.Matrix([[3, 4], [1, 2], [3, 4]])
    assert ns["C2"] == sm.Matrix([[2, 1], [4, 3]])
    assert ns["Dg"] == sm.Matrix([[a, 0], [0, a]])
    assert ns["Dg2"] == sm.Matrix([[a, 0, 0], [0, a, 0]])
    assert ns["B"] == sm.Matrix([[1, 2, 5], [3, 4, 6], [7, 8, 9]])   # block matrix
    assert ns["X"] == sm.Matrix([0, 0, a])           # X[3] is the third row (peer: row 1)


def test_symbolic_det_and_inv_use_intermediates_that_expand_exactly():
    ns = build("CONSTANTS a,b,c,d\nM = [a, b; c, d]\nD1 = DET(M)\nI1 = INV(M)\n"
               "P = EXPLICIT(I1*M)")
    assert sm.simplify(ns["P"]) == sm.eye(2)
    a, b, c, d = (sm.Symbol(n, real=True) for n in "abcd")
    assert sm.expand(ns["model"].explicit(ns["D1"]) - (a * d - b * c)) == 0


def test_eig_values_and_vectors_in_a_documented_order():
    ns = build("M = [2, 1; 1, 2]\nL = EIG(M)\nEIG(M, V, W)\nC = EIG([0, -1; 1, 0])")
    assert [round(float(x), 12) for x in ns["L"]] == [1.0, 3.0]   # ascending real part
    assert [round(float(x), 12) for x in ns["V"]] == [1.0, 3.0]
    w = ns["W"]
    m = sm.Matrix([[2, 1], [1, 2]])
    for k, lam in enumerate((1, 3)):                      # columns are unit eigenvectors
        col = w[:, k]
        assert (m * col - lam * col).norm() < 1e-14 and abs(col.norm() - 1) < 1e-14
    assert [complex(x) for x in ns["C"]] == pytest.approx([-1j, 1j])   # then imaginary


# -- scalars ------------------------------------------------------------------------------
@pytest.mark.parametrize("expr, want", [
    ("INT(2.7)", 2), ("INT(-2.7)", -2), ("ROUND(2.5)", 3), ("ROUND(-2.5)", -3),
    ("ROUND(2.4)", 2), ("INT(3*SQRT(2))", 4), ("ROUND(-3*SQRT(2))", -4),
    ("ROUND(0.49999999999999994)", 0), ("INT(-0.5)", 0), ("SIGN(-3)", -1), ("ABS(-2)", 2),
    ("MAX(1, 3, 2)", 3),
    ("MIN(4, -1)", -1), ("LOG10(1000)", 3), ("SQR(3)", 9), ("EXP(0)", 1),
    ("FACTORIAL(4)", 24), ("CEIL(2.1)", 3), ("FLOOR(-2.1)", -3), ("SQRT(16)", 4),
    ("SEC(0)", 1), ("CSC(PI/2)", 1), ("COT(PI/4)", 1), ("ATAN2(1, 1)", math.pi / 4),
    ("LOG(EXP(2))", 2), ("TANH(0)", 0), ("ASIN(1)", math.pi / 2), ("ACOS(1)", 0),
])
def test_scalar_functions(expr, want):
    ns = build(f"X = {expr}")
    assert abs(complex(sm.sympify(ns["X"]).evalf()) - want) < 1e-14


def test_int_round_sign_abs_max_min_stay_symbolic_and_evaluate_later():
    # the peer emits Python int()/round(), which fail on symbols (reference 2.3)
    ns = build("VARIABLES x\nI = INT(x)\nR = ROUND(x)\nS = SIGN(x)\nA1 = ABS(x)\n"
               "M = MAX(x, 1)\nN = MIN(x, 1)")
    x = sm.Symbol("x", real=True)
    for v, want in ((-2.7, (-2, -3, -1, 2.7, 1, -2.7)), (2.5, (2, 3, 1, 2.5, 2.5, 1))):
        got = [float(ns[k].subs(x, v)) for k in ("I", "R", "S", "A1", "M", "N")]
        assert got == list(want)


def test_int_and_round_are_one_node_each_however_deep():
    # as sign(x)*floor(|x|) the argument appeared twice: 2^depth nodes
    ns = build("VARIABLES x\nE = " + "INT(ROUND(" * 15 + "x" + "))" * 15)
    x = sm.Symbol("x", real=True)
    assert sm.count_ops(ns["E"]) <= 2 and float(ns["E"].subs(x, -2.5)) == -3.0
    assert sm.diff(ns["E"], x) == 0        # constant between the integers


def test_int_of_a_number_beyond_a_double_stays_unevaluated():
    # COS(SINH(1E7)) exactly needs millions of digits; Autolev computed in doubles
    ns = build("VARIABLES x\nE = INT(COS(SINH(x)))\nF = EVALUATE(E, x = 10^7)")
    assert not ns["F"].is_Integer and ns["F"].free_symbols == set()


def test_negative_exponent_binds_to_the_power():
    # `A^-2` becomes a**-1*2 in the peer (reference 2.3)
    ns = build("CONSTANTS a\nX = a^-2\nY = -a^2")
    a = sm.Symbol("a", real=True)
    assert ns["X"] == a**-2 and ns["Y"] == -a**2


# -- units ---------------------------------------------------------------------------------
@pytest.mark.parametrize("args, want", [
    ("deg, rad", sm.pi / 180), ("rad, deg", 180 / sm.pi),
    ("ft, m", sm.Rational(3048, 10000)), ("in, cm", sm.Rational(254, 100)),
    ("lbf, n", sm.Rational(44482216152605, 10**13)), ("slug, kg", None),
    ("n*m, lbf*ft", 1 / (sm.Rational(44482216152605, 10**13) * sm.Rational(3048, 10000))),
    ("rpm, rad/sec", sm.pi / 30), ("min, sec", 60), ("km, m", 1000),
    ("g, kg", sm.Rational(1, 1000)),
])
def test_units_factors_are_exact(args, want):
    # the peer knows only deg<->rad, rounded to 0.0174533
    ns = build(f"U = UNITS({args})")
    if want is None:   # slug = lbf*s^2/ft
        want = sm.Rational(44482216152605, 10**13) / sm.Rational(3048, 10000)
    assert sm.simplify(ns["U"] - want) == 0


def test_units_of_unlike_dimensions_is_an_error():
    with pytest.raises(autolev.AutolevTranslationError, match="UNITS"):
        build("U = UNITS(kg, m)")


def test_unitsystem_is_recorded_for_headers():
    ns = build("UNITSYSTEM kg, meter, sec\nCONSTANTS a")
    assert [u.lower() for u in ns["model"].unit_system_names] == ["kg", "meter", "sec"]


# -- energy and momentum ---------------------------------------------------------------------
PENDULUM = """NEWTONIAN N
BODIES A
PARTICLES P
POINTS O
MOTIONVARIABLES' Q', U'
CONSTANTS L, M, MA, IA, G
MASS A=MA, P=M
INERTIA A, 0, 0, IA
SIMPROT(N, A, 3, Q)
Q' = U
W_A_N> = U*A3>
P_O_AO> = L/2*A1>
P_O_P> = L*A1>
V_O_N> = 0>
V2PTS(N, A, O, AO)
V2PTS(N, A, O, P)
"""


def test_kinetic_energy_of_all_and_of_listed_bodies():
    ns = build(PENDULUM + "K = KE()\nKA = KE(A)\nKP = KE(P)")
    v = dict(L=2.0, M=3.0, MA=5.0, IA=0.7, U=1.5, Q=0.3)
    ka = 0.5 * 5.0 * (1.0 * 1.5)**2 + 0.5 * 0.7 * 1.5**2     # v_AO = L/2*U
    kp = 0.5 * 3.0 * (2.0 * 1.5)**2
    assert abs(val(ns, ns["KA"], **v) - ka) < 1e-12
    assert abs(val(ns, ns["KP"], **v) - kp) < 1e-12
    assert abs(val(ns, ns["K"], **v) - (ka + kp)) < 1e-12


def test_linear_and_angular_momentum():
    ns = build(PENDULUM + "LM> = MOMENTUM(LINEAR)\nH> = MOMENTUM(ANGULAR, O)\n"
               "LM2 = DOT(LM>, A2>)\nH3 = DOT(H>, N3>)")
    v = dict(L=2.0, M=3.0, MA=5.0, IA=0.7, U=1.5, Q=0.3)
    assert abs(val(ns, ns["LM2"], **v) - (5.0 * 1.0 * 1.5 + 3.0 * 2.0 * 1.5)) < 1e-12
    h = 5.0 * 1.0**2 * 1.5 + 0.7 * 1.5 + 3.0 * 2.0**2 * 1.5
    assert abs(val(ns, ns["H3"], **v) - h) < 1e-12


def test_nicheck_is_constant_along_a_conservative_motion():
    # NICHECK = KE - (work of the active forces since TINITIAL): constant, here with a
    # damper too (tutorials 6 and 7 print it as an energy check)
    ns = build(PENDULUM + "CONSTANTS C\nGRAVITY(G*N1>)\nTORQUE_A> = -C*U*A3>\n"
               "ZERO = FR() + FRSTAR()\nKANE()\nE = NICHECK()\nK = KE()\n"
               "INPUT L=1, M=1, MA=2, IA=0.1, G=9.81, C=0.5, Q=60 DEG, U=2\n"
               "INPUT TFINAL=2, INTEGSTP=0.01\nOUTPUT T, E, K\nCODE DYNAMICS() p.c")
    r = ns["model"].simulate(method="rk45", RELERR=1e-10, ABSERR=1e-10)
    e, k = r.outputs[0]["E"], r.outputs[0]["K"]
    ke0 = 0.5 * (2 * 0.25 * 4 + 0.1 * 4) + 0.5 * 1 * 4          # by hand at U=2
    assert abs(k[0] - ke0) < 1e-12 and abs(e[0] - ke0) < 1e-12
    assert abs(e.max() - e.min()) < 1e-7 and k.max() - k.min() > 1   # KE itself varies


def test_gyrostat_adds_the_rotor_spin_times_its_axial_inertia():
    ns = build("NEWTONIAN N\nBODIES A\nFRAMES B\nMOTIONVARIABLES' W{3}'\n"
               "CONSTANTS OMEGA, J\nMASS A=M\nINERTIA A, I1, I2, I3\n"
               "W_A_N> = VECTOR(A, W1, W2, W3)\nW_B_A> = OMEGA*A3>\n"
               "P_NO_AO> = 0>\n"
               "H> = MOMENTUM(ANGULAR, AO) + GYROSTAT(ANGMOM, CYLINDER, A, B, J)\n"
               "H3 = DOT(H>, A3>)\nH1 = DOT(H>, A1>)".replace("MASS A=M\n",
                                                            "CONSTANTS M, I{3}\nMASS A=M\n"))
    v = dict(W1=0.1, W2=0.2, W3=1.0, OMEGA=-20.0, J=0.07634, I1=1.25, I2=4.25, I3=5.0)
    assert abs(val(ns, ns["H3"], **v) - (5.0 * 1.0 + 0.07634 * -20.0)) < 1e-12
    assert abs(val(ns, ns["H1"], **v) - 1.25 * 0.1) < 1e-12


def test_gyrostat_of_an_unknown_kind_is_a_diagnostic():
    with pytest.raises(autolev.AutolevTranslationError, match="only ANGMOM"):
        build("NEWTONIAN N\nFRAMES A, B\nCONSTANTS J\nH> = GYROSTAT(KE, CYLINDER, A, B, J)")


# -- settings ----------------------------------------------------------------------------------
def test_display_settings_are_accepted_quietly():
    code = autolev.transpile("DIGITS 5\nFACTORING ON\nPAUSE 0\nBEEPSOUND OFF\n"
                             "OVERWRITE ALL\nAUTOEPSILON 1E-14\nAUTOEXPRESS ON\n"
                             "CONSTANTS a\nX = a", "s.al")
    assert "X = a" in code


def test_degrees_setting_governs_numeric_angles_only_in_rotations():
    ns = build("NEWTONIAN N\nFRAMES A, B\nSIMPROT(N, A, 3, 90)\nDEGREES OFF\n"
               "SIMPROT(N, B, 3, PI/2)\nC = N_A[1,2]\nD = N_B[1,2]\nS = SIN(90)")
    assert ns["C"] == -1 and ns["D"] == -1
    assert ns["S"] == sm.sin(90)                         # SIN takes radians always


def test_complex_setting_decides_whether_names_are_real():
    off = build("CONSTANTS a\nX = a")
    on = build("COMPLEX ON\nCONSTANTS a\nX = a")
    assert off["X"].is_real and on["X"].is_real is None


def test_autorhs_on_reads_definitions_and_off_keeps_names():
    on = build("AUTORHS ON\nVARIABLES x, y\nx = 2*y\nE = x + 1")
    off = build("VARIABLES x, y\nx = 2*y\nE = x + 1")
    y = sm.Symbol("y", real=True)
    x = sm.Symbol("x", real=True)
    assert on["E"] == 2 * y + 1 and off["E"] == x + 1
