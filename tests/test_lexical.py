"""Lexical structure: numbers, comments, line ends, continuation, case, primes, vectors."""
import pytest

from autolev import ir
from helpers import errors_of, expr, only, parse


@pytest.mark.parametrize("text, value", [
    ("1", 1), (".5", 0.5), ("1.", 1.0), ("1E-7", 1e-7), ("1.0e-08", 1e-8),
    ("2.5E+3", 2500.0), ("1.0E-07", 1e-7), ("12e2", 1200.0), ("0.25", 0.25),
])
def test_numbers_keep_their_text_and_value(text, value):
    n = expr(text)
    assert isinstance(n, ir.Number)
    assert n.text == text
    assert n.value == value


def test_number_exact_value_is_the_decimal_written():
    assert expr("1.1").exact == ir.Number("11").exact / 10


def test_integer_and_float_are_distinguished():
    assert expr("3").is_integer and not expr("3.").is_integer


def test_comments_anywhere_and_on_a_last_line_without_newline():
    p = parse("% header\nCONSTANTS a   % mass\nb = a % trailing\n% last line, no newline")
    assert [s.kind for s in p.statements] == ["declaration", "assignment"]


def test_crlf_and_lone_cr_line_ends():
    p = parse("CONSTANTS a\r\nb = a\r\nc = b\rd = c\r\n")
    assert [s.kind for s in p.statements] == ["declaration"] + ["assignment"] * 3
    assert p.statements[3].span.line == 4


def test_newline_ends_a_statement():
    # the peer's grammar treats newlines as blanks and reads these two lines as one
    p = parse("E = A1\n-B1")
    assert [s.kind for s in p.statements] == ["assignment", "display"]
    assert p.statements[0].value == ir.Name("A1")


def test_ampersand_continues_a_statement():
    p = parse("E = A1 &\n  - B1\nF = 2")
    first = p.statements[0]
    assert first.value == ir.BinOp("-", ir.Name("A1"), ir.Name("B1"))
    assert p.statements[1].span.line == 3


def test_continuation_glues_a_token_split_across_lines():
    # Autolev printed long responses broken mid-token; users pasted them back
    p = parse("X = SIN(THE&\n     TA) + COS(Q&\n   4)")
    assert p.statements[0].value == ir.BinOp(
        "+", ir.Call("SIN", (ir.Name("THETA"),)), ir.Call("COS", (ir.Name("Q4"),)))


def test_continuation_with_comment_after_ampersand():
    p = parse("M = [1, 2; & % first row\n 3, 4]")
    assert only(p).value == ir.Matrix(((ir.Number("1"), ir.Number("2")),
                                       (ir.Number("3"), ir.Number("4"))))


def test_semicolon_ends_or_separates_statements():
    p = parse("a = 1;\nb = 2; c = 3;;\n;")
    assert [s.target.name for s in p.statements] == ["a", "b", "c"]


def test_keywords_are_case_insensitive_and_names_keep_their_spelling():
    p = parse("newtonian Ground\nBoDiEs RThigh\nconstants IBxx")
    assert [s.what for s in p.statements] == ["newtonian", "bodies", "constants"]
    assert p.symbols.entity("ground").name == "Ground"
    assert p.symbols.entity("RTHIGH").name == "RThigh"
    assert p.symbols.scalar("ibxx").name == "IBxx"


def test_primes_on_names():
    assert expr("q'") == ir.Name("q", 1)
    assert expr("q''") == ir.Name("q", 2)
    assert expr("q1'' + q2'") == ir.BinOp("+", ir.Name("q1", 2), ir.Name("q2", 1))


@pytest.mark.parametrize("text, name, dyadic", [
    ("X>", "X", False), ("X>>", "X", True), ("0>", "0", False), ("1>>", "1", True),
    ("N1>", "N1", False), ("P_A_B>", "P_A_B", False), ("I_B_BO>>", "I_B_BO", True),
    ("W_A_N>", "W_A_N", False),
])
def test_vector_and_dyadic_names(text, name, dyadic):
    v = expr(text)
    assert v == ir.VectorName(name, dyadic)


def test_keywords_are_names_outside_statement_starts():
    # INPUT(x) and UNITS(deg, rad) are functions; MASS() and INERTIA() too
    assert expr("INPUT(x)") == ir.Call("INPUT", (ir.Name("x"),))
    assert expr("Units(deg, rad)") == ir.Call("Units", (ir.Name("deg"), ir.Name("rad")))
    assert expr("Mass() + Points") == ir.BinOp("+", ir.Call("Mass"), ir.Name("Points"))


def test_unexpected_character_is_reported_with_its_column():
    (d,) = errors_of("a = 1\nb = 2 $ 3\n")
    assert (d.line, d.col) == (2, 7)
    assert "'$'" in d.message


def test_hash_outside_a_macro_explains_itself():
    (d,) = errors_of("y#1# = 3")
    assert "macro" in d.message
