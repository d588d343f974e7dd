"""Equations for papers (issue 34, item 2): `autolev equations` and Model.latex() show
what autolev integrates, the intermediates as definitions.  The double pendulum's mass
matrix and forcing, read back from the plain text alone, are checked against the
textbook's (derived by hand: absolute angles from N1>, gravity along N1>)."""
import math
import random
import re

import sympy as sm

import autolev
from autolev.cli import main
from helpers import EXAMPLES

PENDULUM = EXAMPLES / "double_pendulum.al"


def read_plain(text: str) -> tuple[sm.Matrix, sm.Matrix, list]:
    """The mass matrix and forcing of `--sympy` text in the model's symbols, every
    definition put in; a derivative Q1' read as the symbol Q1_d."""
    known = {f: getattr(sm, f) for f in ("sin", "cos", "tan", "sqrt", "Matrix", "pi")}

    def parse(expr: str):
        expr = re.sub(r"(\w+)'", r"\1_d", expr)
        names = {n: sm.Symbol(n) for n in re.findall(r"[A-Za-z_]\w*", expr) if n not in known}
        return sm.parse_expr(expr, local_dict=names, global_dict=dict(known),
                             transformations=())
    values: dict = {}
    for line in text.split("\nunknowns = ")[0].splitlines()[1:]:
        name, _, expr = line.partition(" = ")
        values[parse(name)] = parse(expr).subs(values)
    rest = text.split("\nmass_matrix = ")[1]
    mass_text, _, forcing_text = rest.partition("\nforcing = ")
    unknowns = text.split("\nunknowns = ")[1].split("\n")[0]
    return (parse(mass_text).subs(values), parse(forcing_text).subs(values),
            [str(parse(u)) for u in unknowns.strip("[]").split(", ")])


def test_the_plain_text_holds_the_textbook_equations_of_the_double_pendulum(capsys):
    assert main(["equations", str(PENDULUM), "--sympy"]) == 0
    mass, forcing, unknowns = read_plain(capsys.readouterr().out)
    assert unknowns == ["U1_d", "U2_d"]
    q1, q2, u1, u2, l1, l2, m1, m2, g = sm.symbols("Q1 Q2 U1 U2 L1 L2 M1 M2 G")
    textbook_mass = sm.Matrix([[(m1 + m2) * l1**2, m2 * l1 * l2 * sm.cos(q1 - q2)],
                               [m2 * l1 * l2 * sm.cos(q1 - q2), m2 * l2**2]])
    textbook_forcing = sm.Matrix([
        -m2 * l1 * l2 * u2**2 * sm.sin(q1 - q2) - (m1 + m2) * g * l1 * sm.sin(q1),
        m2 * l1 * l2 * u1**2 * sm.sin(q1 - q2) - m2 * g * l2 * sm.sin(q2)])
    rng = random.Random(3)
    for _ in range(5):
        point = {s: rng.uniform(0.3, 2) for s in (q1, q2, u1, u2, l1, l2, m1, m2, g)}
        point.update({sm.Symbol("Q1_d"): point[u1], sm.Symbol("Q2_d"): point[u2]})
        for ours, theirs in ((mass, textbook_mass), (forcing, textbook_forcing)):
            difference = (ours - theirs).subs(point).evalf()
            assert max(abs(float(x)) for x in difference) < 1e-12


def test_latex_shows_definitions_rates_and_the_mass_matrix_equation(tmp_path, capsys):
    text = autolev.load(PENDULUM).latex()
    assert text.startswith("% CODE DYNAMICS double_pendulum.c of double_pendulum")
    align = text.split(r"\begin{align*}")[1].split(r"\end{align*}")[0]
    lines = [line.strip() for line in align.strip().split("\\\\\n")]
    assert r"\dot{Q_{1}} &= U_{1}" in lines and r"\dot{Q_{2}} &= U_{2}" in lines
    assert all(re.fullmatch(r"(z_\{\d+\}|\\dot\{Q_\{[12]\}\}) &= .+", line) for line in lines)
    # every intermediate the matrix equation names is defined above it
    equation = text.split(r"\begin{equation*}")[1]
    assert {z for z in re.findall(r"z_\{\d+\}", equation)} <= \
        {line.split(" &=")[0] for line in lines}
    assert r"\left[\begin{matrix}\dot{U_{1}}\\\dot{U_{2}}\end{matrix}\right] =" in equation
    out = tmp_path / "pendulum.tex"
    assert main(["equations", str(PENDULUM), "--latex", "-o", str(out)]) == 0
    assert out.read_text() == text


def test_equations_do_not_overwrite_a_users_file_and_name_a_wrong_code(tmp_path, capsys):
    mine = tmp_path / "paper.tex"
    mine.write_text("my paper\n")
    assert main(["equations", str(PENDULUM), "-o", str(mine)]) == 1
    assert mine.read_text() == "my paper\n"
    assert "not written by autolev" in capsys.readouterr().err
    assert main(["equations", str(PENDULUM), "--code", "bike.c"]) == 2
    assert "--code: no CODE command 'bike.c'" in capsys.readouterr().err


def test_a_model_without_values_still_shows_its_equations(tmp_path, capsys):
    path = tmp_path / "bare.al"
    path.write_text(re := PENDULUM.read_text().split("UNITSYSTEM")[0])
    assert "INPUT" not in re
    assert main(["equations", str(path), "--sympy"]) == 0
    mass, _, _ = read_plain(capsys.readouterr().out)
    assert mass.shape == (2, 2) and math.isclose(
        float(mass[1, 1].subs({"L2": 2, "M2": 3, "Q2": 0.4})), 12.0)
