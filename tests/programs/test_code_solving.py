"""`autolev code` for the CODE commands that solve before they write: ALGEBRAIC(EQ, x, y)
(linear equations), NONLINEAR(EQ, x, y) (Newton's method from the guesses), ALGEBRAIC()
over a swept input, and ODE(EQ, x'', y'') -- in C and in Matlab, checked against values
derived by hand and against `autolev run`."""
import math
import shutil

import pytest

from autolev.cli import main
from helpers import CORPUS
from helpers import programs as P

needs_cc, needs_octave = P.needs_cc, P.needs_octave
rows = P.table_rows

LINEAR = """\
VARIABLES X, Y
CONSTANTS A, B
EQ[1] = A*X + 2*Y - 3
EQ[2] = X - B*Y + 1
S = X + Y
INPUT A = 2, B = 3
OUTPUT X, Y, S
CODE ALGEBRAIC(EQ, X, Y) {name}
"""

# X^2 + Y^2 = R^2 on the line Y = X: from the guesses (1, 2), the root (R/sqrt2, R/sqrt2)
NONLINEAR = """\
VARIABLES X, Y
CONSTANTS R
EQ[1] = X^2 + Y^2 - R^2
EQ[2] = Y - X
INPUT R = 2, X = 1, Y = 2
INPUT ABSERR = 1.0E-10, RELERR = 1.0E-10
OUTPUT X, Y
CODE NONLINEAR(EQ, X, Y) {name}
"""

SWEEP = """\
CONSTANTS L, Q
X = L*COS(Q)
Y = L*SIN(Q)
INPUT L = 2
OUTPUT Q DEG, X, Y
CODE ALGEBRAIC() [Q DEG = 0, 90, 15] {name}
"""

# M X'' + K X = 0 from X = 1, X' = 0: X = cos(w t), w^2 = K/M
ODE = """\
VARIABLES X''
CONSTANTS K, M
EQ[1] = M*X'' + K*X
INPUT K = 4, M = 1, X = 1, X' = 0
INPUT TFINAL = 3, INTEGSTP = 0.1, ABSERR = 1.0E-10, RELERR = 1.0E-10
OUTPUT T, X, X'
CODE ODE(EQ, X'') {name}
"""


def program_rows(tmp_path, text: str, name: str):
    """The model's program written, compiled (C) or run under Octave (Matlab), and the
    rows of its first output file; and the rows `autolev run` writes for the model."""
    model = tmp_path / "model.al"
    model.write_text(text.format(name=name))
    assert main(["code", str(model), "--out", str(tmp_path / "prog"), "-q"]) == 0
    stem = name.rpartition(".")[0]
    folder = tmp_path / "prog"
    ran = P.run_program(folder / name, flags=("-Wall", "-Wextra", "-O2"))
    assert ran.returncode == 0, ran.stdout + ran.stderr
    assert main(["run", str(model), "--out", str(tmp_path / "run"), "-q"]) == 0
    return rows(folder / f"{stem}.1"), rows(tmp_path / "run" / f"{stem}.1")


def check_linear(ours, run):
    # 2x + 2y = 3, x - 3y = -1: y = 5/8, x = 7/8
    assert ours == run
    assert ours == [[pytest.approx(0.875, abs=5e-7), pytest.approx(0.625, abs=5e-7),
                     pytest.approx(1.5, abs=5e-6)]]


def check_nonlinear(ours, run):
    assert ours == run
    root = 2 / math.sqrt(2)
    assert ours == [[pytest.approx(root, rel=1e-6), pytest.approx(root, rel=1e-6)]]


def check_sweep(ours, run):
    assert ours == run
    assert [r[0] for r in ours] == [0, 15, 30, 45, 60, 75, 90]
    for q, x, y in ours:
        assert x == pytest.approx(2 * math.cos(math.radians(q)), rel=1e-6, abs=1e-6)
        assert y == pytest.approx(2 * math.sin(math.radians(q)), rel=1e-6, abs=1e-6)


def check_ode(ours, run):
    assert ours == run
    assert len(ours) == 31
    for t, x, xp in ours:
        assert x == pytest.approx(math.cos(2 * t), abs=2e-6)
        assert xp == pytest.approx(-2 * math.sin(2 * t), abs=4e-6)


CASES = [(LINEAR, "lin", check_linear), (NONLINEAR, "newton", check_nonlinear),
         (SWEEP, "sweep", check_sweep), (ODE, "ode", check_ode)]


def test_run_solves_linear_equations_without_a_compiler_too(tmp_path):
    # found by bench/fuzz.py --mode commands: the Python backend's function of the
    # coefficients read the unknowns' slots from an empty array (an internal error)
    model = tmp_path / "model.al"
    model.write_text(LINEAR.format(name="lin.c"))
    assert main(["run", str(model), "--out", str(tmp_path), "--backend", "python", "-q"]) == 0
    found = rows(tmp_path / "lin.1")
    check_linear(found, found)


@needs_cc
@pytest.mark.parametrize("text, stem, check", CASES, ids=[c[1] for c in CASES])
def test_a_c_program_gives_the_values_derived_by_hand(text, stem, check, tmp_path):
    """...and the rows `autolev run` writes (the same printed digits)."""
    check(*program_rows(tmp_path, text, f"{stem}.c"))


@needs_octave
@pytest.mark.parametrize("text, stem, check", CASES, ids=[c[1] for c in CASES])
def test_a_matlab_program_gives_the_values_derived_by_hand(text, stem, check, tmp_path):
    if stem == "ode":
        # integrated by ode45 over every INTEGSTP, as Autolev's Matlab: the digits of
        # autolev run's ode45-like run are the reference, the analytic ones within 1e-6
        ours, run = program_rows(tmp_path, text, f"{stem}.m")
        assert len(ours) == len(run) == 31
        for a, b in zip(ours, run):
            assert a == pytest.approx(b, abs=1e-6)
        return
    check(*program_rows(tmp_path, text, f"{stem}.m"))


def test_names_the_solving_program_uses_are_renamed(tmp_path, capsys):
    model = tmp_path / "model.al"
    model.write_text(LINEAR.format(name="lin.c").replace("CONSTANTS A, B", "CONSTANTS A, B, "
                                                         "COEF").replace("- 3", "- 3*COEF"))
    assert main(["code", str(model), "--out", str(tmp_path / "out")]) == 0
    assert "COEF is written COEF_ in the C program" in capsys.readouterr().err
    text = (tmp_path / "out" / "lin.c").read_text()
    assert "COEF_" in text and "double   A,B,COEF_" in text


TUTORIALS = CORPUS / "NikhilPappu+autolev-parser" / "test_files"


@pytest.mark.corpus
@needs_cc
@pytest.mark.parametrize("example", ["example5.3", "example5.4", "example5.5", "example5.6"])
def test_the_autolev_tutorials_programs_write_what_autolev_run_writes(example, tmp_path):
    """The tutorial models of Autolev's manual that solve (NONLINEAR for a linkage's
    closure and two statics problems, ODE for a spring pendulum): the program writes
    the rows `autolev run` writes, digit for digit (C; a .m one under Octave)."""
    source = TUTORIALS / f"{example}.txt"
    if not source.exists():
        pytest.skip("the corpus is not here")
    model = tmp_path / f"{example.replace('.', '_')}.al"
    shutil.copy(source, model)
    assert main(["code", str(model), "--out", str(tmp_path / "prog"), "-q"]) == 0
    program = next(p for p in (tmp_path / "prog").iterdir() if p.suffix in (".c", ".m"))
    if program.suffix == ".m" and P.octave() is None:
        pytest.skip("GNU Octave is not installed")
    ran = P.run_program(program)
    assert ran.returncode == 0, ran.stdout + ran.stderr
    assert main(["run", str(model), "--out", str(tmp_path / "run"), "-q"]) == 0
    written = sorted((tmp_path / "run").glob(f"{program.stem}.[0-9]*"))
    assert written
    for ref in written:
        assert rows(program.parent / ref.name) == rows(ref), ref.name
