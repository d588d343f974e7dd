"""Declarations and the symbol table."""
import pytest

from autolev import ir
from helpers import errors_of, only, parse


def names(text):
    return [n for item in only(parse(text)).items for n in item.names]


@pytest.mark.parametrize("text, expected", [
    ("CONSTANTS Q{3}", ["Q1", "Q2", "Q3"]),
    ("CONSTANTS A{2:4}", ["A2", "A3", "A4"]),
    ("CONSTANTS B{1:2,1:2}", ["B11", "B12", "B21", "B22"]),
    ("CONSTANTS C{2,3}", ["C11", "C12", "C13", "C21", "C22", "C23"]),
    ("CONSTANTS WO{2}RD{1:2}", ["WO1RD1", "WO1RD2", "WO2RD1", "WO2RD2"]),
    ("VARIABLES p{2}o", ["p1o", "p2o"]),
])
def test_ranges(text, expected):
    assert names(text) == expected


def test_two_brace_groups_with_a_matrix_range():
    got = names("CONSTANTS WO{3}RD{2,4}")
    assert len(got) == 3 * 2 * 4
    assert got[:2] == ["WO1RD11", "WO1RD12"] and got[-1] == "WO3RD24"
    assert only(parse("CONSTANTS WO{3}RD{2,4}")).items[0].shape == (3, 2, 4)


def test_signs_values_and_primes():
    d = only(parse("CONSTANTS C+, D-, B = 3, E"))
    assert [(i.written, i.sign) for i in d.items] == [
        ("C", "+"), ("D", "-"), ("B", None), ("E", None)]
    assert d.items[2].value == ir.Number("3")
    v = only(parse("VARIABLES X, Y', Z''"))
    assert [i.primes for i in v.items] == [0, 1, 2]
    p = parse("VARIABLES Z''")
    assert p.symbols.scalar("z").primes == 2


def test_motionvariables_forms():
    p = parse("MOTIONVARIABLES' Q{2}', U{2}'\nMOTIONVARIABLES W{3}\nMOTIONVARIABLES' R{9}''")
    mv = p.statements
    assert [s.keyword_primes for s in mv] == [1, 0, 1]
    assert p.symbols.scalar("q1").kind == "motionvariable"
    assert p.symbols.scalar("r9").primes == 2
    assert p.symbols.scalar("w3").primes == 0


def test_every_declaration_kind_and_implicit_points():
    p = parse("NEWTONIAN N\nFRAMES A\nBODIES B, C\nPARTICLES P\nPOINTS O\n"
              "CONSTANTS k\nVARIABLES x\nSPECIFIED F\nIMAGINARY J")
    kinds = {s.name: s.kind for s in p.symbols}
    assert kinds == {"N": "newtonian", "NO": "point", "A": "frame", "B": "body",
                     "BO": "point", "C": "body", "CO": "point", "P": "particle",
                     "O": "point", "k": "constant", "x": "variable", "F": "specified",
                     "J": "imaginary"}
    no = p.symbols.entity("no")
    assert no.implicit and no.owner == "N"


def test_singular_keywords():
    p = parse("BODY torso\nPOINT hip\nCONSTANT len\nFRAME F\nVARIABLE v\nPARTICLE m")
    assert [s.what for s in p.statements] == ["bodies", "points", "constants", "frames",
                                             "variables", "particles"]


def test_a_body_and_a_constant_may_share_a_name():
    # real models declare body LFF and its length, constant LFF
    p = parse("BODIES lff\nCONSTANTS lff, lffo")
    assert p.symbols.entity("lff").kind == "body"
    assert p.symbols.scalar("lff").kind == "constant"
    assert p.symbols.entity("lffo").kind == "point"
    assert p.diagnostics == []


def test_redeclaration_warns_and_redeclaration_with_value_does_not():
    p = parse("VARIABLES x\nVARIABLES x\nSPECIFIED F\nSPECIFIED F = T")
    assert [(d.code, d.line) for d in p.diagnostics] == [("W001", 2)]


def test_conflicting_kinds_in_one_namespace_warn():
    p = parse("FRAMES A\nPOINTS A")
    (d,) = p.diagnostics
    assert d.code == "W002" and "frame" in d.message and "point" in d.message


def test_explicit_no_after_newtonian_is_quiet():
    p = parse("NEWTONIAN N\nPOINTS NO")
    assert p.diagnostics == []


def test_mass_forms():
    m = only(parse("MASS B=mB, P=M, C=mC=10"))
    assert [(i.target, i.value) for i in m.items] == [
        ("B", ir.Name("mB")), ("P", ir.Name("M")), ("C", ir.Name("mC"))]
    assert m.items[2].value_of_value == ir.Number("10")


def test_inertia_forms():
    i = only(parse("INERTIA B, I11, I22, I33"))
    assert (i.body, i.frame, len(i.values)) == ("B", None, 3)
    i = only(parse("INERTIA C(B), IC1, IC2, IC3, 0, 0, 0"))
    assert (i.body, i.frame, len(i.values)) == ("C", "B", 6)
    i = only(parse("INERTIA B_O(A), 1, 2, 3"))
    assert (i.body, i.frame) == ("B_O", "A")


def test_inertia_with_inline_definition():
    i = only(parse("INERTIA B, IB=MB*L^2/12, 0, IB"))
    assert i.definitions == ((
        "IB", ir.BinOp("/", ir.BinOp("*", ir.Name("MB"), ir.BinOp("^", ir.Name("L"),
                                                                    ir.Number("2"))),
                       ir.Number("12"))),)
    assert i.values == (ir.Name("IB"), ir.Number("0"), ir.Name("IB"))


def test_inertia_with_wrong_number_of_values():
    (d,) = errors_of("INERTIA B, 1, 2")
    assert d.code == "E044" and "3 or 6" in d.message


def test_empty_range_is_an_error():
    (d,) = errors_of("CONSTANTS q{3:1}")
    assert d.code == "E040" and d.col == 13   # at "3:1"


def test_huge_range_is_refused():
    (d,) = errors_of("CONSTANTS q{99999}")
    assert d.code == "E041"


def test_declaration_needs_a_name():
    (d,) = errors_of("CONSTANTS ,a")
    assert d.line == 1 and d.col == 11 and "expected" in d.message
