"""The fast reader of Autolev's printed arithmetic (printed.read_plain) reads each
response into the tree the grammar's builder makes of it, or leaves it to the grammar:
held to the builder on generated arithmetic, on the transcripts of the shipped examples
and on every response the corpus records."""
import random

import pytest

from autolev import ir
from autolev.errors import Location, Span
from autolev.irbuild import Builder
from autolev.printed import read_plain
from autolev.source import SourceFile
from autolev.transcript import transcript
from autolev.translate import vocabulary
from autolev.verification import read_session
from helpers import EXAMPLES

SPAN = Span(Location("<test>", 1, 1))


def by_grammar(target: str, value: str):
    """(target, value) as the builder reads `target = value`, or None when it refuses."""
    builder = Builder("<test>", None, reserved=vocabulary())
    builder.build_source(SourceFile("<test>", f"{target} = {value}\n"))
    if builder.errors or len(builder.statements) != 1:
        return None
    st = builder.statements[0]
    if not isinstance(st, ir.Assignment) or st.op != "=":
        return None
    return st.target, st.value


def agree(target: str, value: str) -> bool:
    """The fast reader gives the grammar's tree, or nothing (the grammar reads it)."""
    fast = read_plain(target, value, SPAN)
    return fast is None or fast == by_grammar(target, value)


@pytest.mark.parametrize("value, tree", [
    ("-X^2", ir.Neg(ir.BinOp("^", ir.Name("X"), ir.Number("2")))),
    ("-A*B", ir.BinOp("*", ir.Neg(ir.Name("A")), ir.Name("B"))),
    ("A^B^C", ir.BinOp("^", ir.Name("A"), ir.BinOp("^", ir.Name("B"), ir.Name("C")))),
    ("A - B + C", ir.BinOp("+", ir.BinOp("-", ir.Name("A"), ir.Name("B")), ir.Name("C"))),
    ("A*-B^2", ir.BinOp("*", ir.Name("A"),
                        ir.Neg(ir.BinOp("^", ir.Name("B"), ir.Number("2"))))),
    ("A^-B*C", ir.BinOp("*", ir.BinOp("^", ir.Name("A"), ir.Neg(ir.Name("B"))),
                        ir.Name("C"))),
    ("q1''*SIN(q2, 1.5E-3)", ir.BinOp("*", ir.Name("q1", 2),
                                       ir.Call("SIN", (ir.Name("q2"),
                                                       ir.Number("1.5E-3"))))),
    ("+(N1> + ground3>)", ir.BinOp("+", ir.VectorName("N1"), ir.VectorName("ground3"))),
    ("F() / .5", ir.BinOp("/", ir.Call("F", ()), ir.Number(".5"))),
])
def test_the_grammars_precedences_and_atoms(value, tree):
    assert read_plain("Z1", value, SPAN) == (ir.Name("Z1"), tree)
    assert by_grammar("Z1", value) == (ir.Name("Z1"), tree)


@pytest.mark.parametrize("target, value", [
    ("Z1", "2X"), ("Z1", "A '"), ("Z1", "A[1]"), ("Z1", "[A, B]"), ("Z1", "A +"),
    ("Z1", "F(X)'"), ("Z1", "INPUT + 1"), ("Z1", "0>"), ("Z1", "A = B"),
    ("V>", "A*N1>"), ("Z1", "1.2.3"), ("Z1", "X := 2"), ("Z1", "A & B"),
    ("Z1", "(A"), ("Z1", "D(X, T=0)"), ("Mass", "2"), ("Z1", "1" * 401),
])
def test_what_is_not_plain_arithmetic_is_left_to_the_grammar(target, value):
    assert read_plain(target, value, SPAN) is None


def random_arithmetic(rng: random.Random, depth: int = 0) -> str:
    if depth > 4 or rng.random() < 0.3:
        return rng.choice(["X", "q1'", "q2''", "Z12", "N1>", "3", "2.5", ".5E-3", "1E4",
                           "pi", "T", "ground_1>", "SIN(q1)", "F()", "U1'"])
    kind = rng.randrange(5)
    a, b = random_arithmetic(rng, depth + 1), random_arithmetic(rng, depth + 1)
    if kind == 0:
        return f"{a} {rng.choice('+-*/^')} {b}"
    if kind == 1:
        return f"{rng.choice('+-')}{a}"
    if kind == 2:
        return f"({a})"
    if kind == 3:
        return f"COS({a}, {b})"
    return f"{a}{rng.choice(['^', '*-', '^-', '/+', '-'])}{b}"


def test_generated_arithmetic_reads_as_the_grammar_reads_it():
    rng = random.Random(1)
    read = 0
    for _ in range(400):
        value = random_arithmetic(rng)
        assert agree("Z7", value), value
        read += read_plain("Z7", value, SPAN) is not None
    assert read > 300                  # most of it is read fast


def test_the_shipped_examples_transcripts_read_as_the_grammar_reads_them():
    for name in ("rolling_disc", "double_pendulum", "whipple_benchmark"):
        session = read_session(transcript(EXAMPLES / f"{name}.al"), f"{name}.all")
        fast = 0
        for r in session.responses:
            if r.expr:
                assert agree(r.lhs, r.expr), (name, r.line)
                fast += read_plain(r.lhs, r.expr, SPAN) is not None
        assert fast > 0, name


@pytest.mark.corpus
def test_every_response_the_corpus_records_reads_as_the_grammar_reads_it(corpus):
    from autolev.source import decode
    files = [p for p in corpus.rglob("*") if p.suffix.lower() in (".all", ".al")
             and ".overlay" not in p.parts]
    compared = 0
    for path in files:
        session = read_session(decode(path.read_bytes()), str(path))
        for r in session.responses:
            if r.expr and len(r.expr) < 20000:
                assert agree(r.lhs, r.expr), (str(path), r.line)
                compared += 1
    assert compared > 500
