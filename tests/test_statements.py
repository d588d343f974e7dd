"""Assignments, INPUT/OUTPUT, UNITS, CODE, SAVE, ENCODE, EXIT and settings."""
import pytest

from autolev import ir
from helpers import errors_of, only, parse


@pytest.mark.parametrize("op", ["=", ":=", "+=", "-=", "*=", "/=", "^="])
def test_assignment_operators(op):
    a = only(parse(f"x {op} 2"))
    assert a.op == op and a.target == ir.Name("x")


@pytest.mark.parametrize("text, target", [
    ("q' = u", ir.Name("q", 1)),
    ("q1'' = -q1", ir.Name("q1", 2)),
    ("Zero[1] = a", ir.Index("Zero", (ir.Number("1"),))),
    ("MO[2,2] := d", ir.Index("MO", (ir.Number("2"), ir.Number("2")))),
    ("X[k] = e", ir.Index("X", (ir.Name("k"),))),
    ("P_A_B> = L*A1>", ir.VectorName("P_A_B")),
    ("I_B_BO>> = 1>>", ir.VectorName("I_B_BO", True)),
    ("Force_P> += F*N1>", ir.VectorName("Force_P")),
    ("N_A = [1,0,0;0,1,0;0,0,1]", ir.Name("N_A")),
])
def test_assignment_targets(text, target):
    assert only(parse(text)).target == target


def test_bare_call_is_a_command_and_bare_expression_a_display():
    p = parse("KANE()\nSIMPROT(N, A, 3, q)\nZero")
    assert [s.kind for s in p.statements] == ["command", "command", "display"]
    assert p.statements[1].call.args[2] == ir.Number("3")


def test_input_with_units_does_not_swallow_the_next_line():
    p = parse("INPUT x = 30 DEG, y = 2\nz = 3")
    assert [s.kind for s in p.statements] == ["input", "assignment"]
    i = p.statements[0]
    assert i.items[0].unit.factors == (("DEG", 1),)
    assert i.items[1].unit is None


def test_input_without_units_followed_by_an_assignment():
    p = parse("INPUT M=1,G=9.81,L=1\nTheta = 2")
    assert [s.kind for s in p.statements] == ["input", "assignment"]
    assert [it.target.name for it in p.statements[0].items] == ["M", "G", "L"]


@pytest.mark.parametrize("unit, factors", [
    ("rad/sec", (("rad", 1), ("sec", -1))),
    ("kg*m^2", (("kg", 1), ("m", 2))),
    ("N/M/S^2", (("N", 1), ("M", -1), ("S", -2))),
    ("KG.M^2/S", (("KG", 1), ("M", 2), ("S", -1))),
    ("n*m*sec/rad", (("n", 1), ("m", 1), ("sec", 1), ("rad", -1))),
])
def test_unit_expressions(unit, factors):
    item = only(parse(f"INPUT x = 1 {unit}")).items[0]
    assert item.unit.factors == factors and item.unit.text == unit


def test_input_values_are_expressions_and_targets_may_be_primed_or_indexed():
    i = only(parse("INPUT lam = 3.14159/10 rad, qA' = 0 rad/sec, M[1,2] = 3, k=2*sqrt(1)"))
    assert isinstance(i.items[0].value, ir.BinOp)
    assert i.items[1].target == ir.Name("qA", 1)
    assert i.items[2].target == ir.Index("M", (ir.Number("1"), ir.Number("2")))
    assert i.items[3].value == ir.BinOp("*", ir.Number("2"),
                                        ir.Call("sqrt", (ir.Number("1"),)))


def test_number_glued_to_its_unit():
    i = only(parse("INPUT qB=30deg"))
    assert i.items[0].value == ir.Number("30") and i.items[0].unit.text == "deg"


def test_output_items_are_expressions_with_optional_units():
    o = only(parse("OUTPUT T sec, q1 deg, ke+pe joules, u1', Config[1], "
                   "dot(V_DO_N>, N2>)"))
    assert [it.unit.text if it.unit else None for it in o.items] == [
        "sec", "deg", "joules", None, None, None]
    assert o.items[2].expr == ir.BinOp("+", ir.Name("ke"), ir.Name("pe"))
    assert o.items[3].expr == ir.Name("u1", 1)


def test_output_without_units_does_not_swallow_the_next_line():
    p = parse("OUTPUT T, Q1\nQ2 = 3")
    assert [s.kind for s in p.statements] == ["output", "assignment"]


def test_units_statement_forms():
    u = only(parse("UNITS T=S, HZ=KG.M^2/S, [A,B]=M, Q1'=RAD/S"))
    assert [tuple(t.name for t in it.targets) for it in u.items] == [
        ("T",), ("HZ",), ("A", "B"), ("Q1",)]
    assert u.items[3].targets[0].primes == 1
    assert u.items[1].unit.factors == (("KG", 1), ("M", 2), ("S", -1))


def test_unitsystem():
    assert only(parse("UnitSystem kg, meter, sec")).units == ("kg", "meter", "sec")


@pytest.mark.parametrize("text, what, filename, options", [
    ("CODE DYNAMICS() bike.c", "dynamics", "bike.c", ()),
    ("Code Algebraic() gait2d_osim/gait2d_FK_raw.c", "algebraic", "gait2d_osim/gait2d_FK_raw.c",
     ()),
    ("CODE DYNAMICS() 7segSprint_raw.f, NOSUBS", "dynamics", "7segSprint_raw.f", ("NOSUBS",)),
    ("CODE DYNAMICS() BICYCLE10.M ,SUBS", "dynamics", "BICYCLE10.M", ("SUBS",)),
    (r"Code Algebraic() dir\file_raw.c", "algebraic", r"dir\file_raw.c", ()),
])
def test_code_statements(text, what, filename, options):
    c = only(parse(text))
    assert (c.what, c.filename, c.options) == (what, filename, options)


def test_code_with_arguments_and_sweep():
    c = only(parse("CODE ALGEBRAIC(EQ, x, y) [q deg=0, 360, 1] tutor2.c"))
    assert c.args == (ir.Name("EQ"), ir.Name("x"), ir.Name("y"))
    assert c.sweep.target == ir.Name("q") and c.sweep.unit.text == "deg"
    assert (c.sweep.start, c.sweep.stop, c.sweep.step) == (
        ir.Number("0"), ir.Number("360"), ir.Number("1"))
    c = only(parse("CODE ODE(Zero, qA'', qB'') tutor6.c"))
    assert c.what == "ode" and c.args[1] == ir.Name("qA", 2)


def test_code_errors():
    (d,) = errors_of("CODE DYNAMIC() x.c")
    assert d.code == "E011" and d.col == 6
    (d,) = errors_of("CODE DYNAMICS() x.c, FAST")
    assert d.code == "E012"
    (d,) = errors_of("CODE DYNAMICS() my file.c")
    assert d.code == "E013"


def test_save_encode_exit_quit():
    p = parse("SAVE tutor6.all\nENCODE A, B, qdd\nEXIT\nQUIT")
    assert [s.kind for s in p.statements] == ["save", "encode", "exit", "exit"]
    assert p.statements[0].filename == "tutor6.all"
    assert p.statements[1].exprs == (ir.Name("A"), ir.Name("B"), ir.Name("qdd"))


@pytest.mark.parametrize("text, name, value", [
    ("AUTOZ ON", "AUTOZ", "ON"), ("autoz off", "AUTOZ", "OFF"),
    ("DEGREES OFF", "DEGREES", "OFF"), ("PAUSE 0", "PAUSE", "0"), ("PAUSE", "PAUSE", None),
    ("OVERWRITE ALL", "OVERWRITE", "ALL"), ("BEEPSOUND OFF", "BEEPSOUND", "OFF"),
    ("DIGITS 10", "DIGITS", "10"), ("AUTORHS ALL", "AUTORHS", "ALL"),
    ("AUTOEPSILON 1.0E-7", "AUTOEPSILON", "1.0E-7"), ("COMPLEX AUTO", "COMPLEX", "AUTO"),
])
def test_settings(text, name, value):
    s = only(parse(text))
    assert (s.kind, s.name, s.value) == ("setting", name, value)


@pytest.mark.parametrize("text, code", [
    ("AUTOZ MAYBE", "E014"), ("DIGITS 2.5", "E014"), ("DIGITS", "E014"),
    ("PAUSE ON", "E014"), ("DEGREES 1", "E014"),
])
def test_bad_setting_values(text, code):
    (d,) = errors_of(text)
    assert d.code == code


def test_unknown_word_word_line_is_a_diagnostic_not_a_setting():
    (d,) = errors_of("AUTOQ ON")
    assert d.code == "E010" and "AUTOQ" in d.message
    assert any("AUTOZ" in n for n in d.notes)


def test_statement_text_and_span_cover_continued_lines():
    p = parse("a = 1\nE = x + &\n    y\nF = 2")
    e = p.statements[1]
    assert e.text == "E = x + y"
    assert (e.span.start.line, e.span.end.line, e.span.end.col) == (2, 3, 5)
