"""Expressions: precedence, unary minus and powers, calls, indexing, matrices, ranges."""
import pytest

from autolev import ir
from helpers import errors_of, expr

N, B = ir.Name, ir.BinOp


def num(t):
    return ir.Number(t)


def test_power_of_negative_exponent():
    # the peer turns a^-2 into a**-1*2
    assert expr("a^-2") == B("^", N("a"), ir.Neg(num("2")))


def test_unary_minus_binds_looser_than_power():
    assert expr("-a^2") == ir.Neg(B("^", N("a"), num("2")))


def test_power_is_right_associative():
    assert expr("a^b^c") == B("^", N("a"), B("^", N("b"), N("c")))


def test_negative_exponent_does_not_swallow_the_product():
    assert expr("a^-2*b") == B("*", B("^", N("a"), ir.Neg(num("2"))), N("b"))


def test_usual_precedence_and_left_associativity():
    assert expr("a - b - c") == B("-", B("-", N("a"), N("b")), N("c"))
    assert expr("a / b * c") == B("*", B("/", N("a"), N("b")), N("c"))
    assert expr("a + b * c") == B("+", N("a"), B("*", N("b"), N("c")))
    assert expr("(a + b) * c") == B("*", B("+", N("a"), N("b")), N("c"))


def test_unary_plus_is_dropped_and_double_minus_kept():
    assert expr("+a") == N("a")
    assert expr("a - -b") == B("-", N("a"), ir.Neg(N("b")))


def test_function_calls_and_nested_calls():
    assert expr("ATAN2(y, x)") == ir.Call("ATAN2", (N("y"), N("x")))
    assert expr("KANE()") == ir.Call("KANE", ())
    assert expr("Dot(V_P_N>, N1>)") == ir.Call("Dot", (ir.VectorName("V_P_N"),
                                                       ir.VectorName("N1")))


def test_arguments_with_ranges_and_equations():
    e = expr("TAYLOR(x*COS(y), 0:7, x=0, y=0)")
    assert e.args[1] == ir.Range(num("0"), num("7"))
    assert e.args[2] == ir.Equation(N("x"), num("0"))


def test_perturbation_argument():
    e = expr("TAYLOR(Zero, 1, x=0:dx, x'=0:dx')")
    assert e.args[2] == ir.Equation(N("x"), ir.Range(num("0"), N("dx")))
    assert e.args[3] == ir.Equation(N("x", 1), ir.Range(num("0"), N("dx", 1)))


def test_replace_argument_with_function_on_the_left():
    e = expr("REPLACE(E, SIN(x)=3)")
    assert e.args[1] == ir.Equation(ir.Call("SIN", (N("x"),)), num("3"))


def test_name_range_in_argument_list():
    e = expr("SOLVE(Perturb, dw{1:3}')")
    r = e.args[1]
    assert isinstance(r, ir.NameRange)
    assert r.names == (N("dw1", 1), N("dw2", 1), N("dw3", 1))


def test_indexing_one_and_two_dimensional_and_symbolic():
    assert expr("M[2]") == ir.Index("M", (num("2"),))
    assert expr("M[I, J]") == ir.Index("M", (N("I"), N("J")))
    assert expr("Rows(MO, 2, 1:2)").args[2] == ir.Range(num("1"), num("2"))


def test_matrix_literals_rows_and_columns():
    assert expr("[a, b; c, d]") == ir.Matrix(((N("a"), N("b")), (N("c"), N("d"))))
    assert expr("[1; 2; 3]") == ir.Matrix(((num("1"),), (num("2"),), (num("3"),)))
    assert expr("[]") == ir.Matrix(())


def test_block_matrix():
    e = expr("[MO, [1,2;3,4]]")
    assert e.rows[0][0] == N("MO")
    assert isinstance(e.rows[0][1], ir.Matrix)


def test_vector_expressions_and_outer_product_parse_as_products():
    e = expr("L*A1> + (N1> * N2>)")
    assert e == B("+", B("*", N("L"), ir.VectorName("A1")),
                  B("*", ir.VectorName("N1"), ir.VectorName("N2")))


def test_walk_visits_every_node():
    e = expr("f(a, [b; c^2])")
    names = {n.name for n in ir.walk(e) if isinstance(n, ir.Name)}
    assert names == {"a", "b", "c"}


def test_spans_point_into_the_source():
    e = expr("aa + COS(bb)")
    assert (e.span.line, e.span.col) == (1, 6)
    assert (e.right.span.col, e.right.args[0].span.col) == (11, 15)


@pytest.mark.parametrize("text", ["a +", "(a", "f(a,", "[1, 2", "a ^"])
def test_incomplete_expressions_are_diagnosed_at_the_end_of_the_line(text):
    (d,) = errors_of(f"x = {text}\n")
    assert d.message.startswith("unexpected end of line")
    assert d.col == len("x = " + text) + 1
