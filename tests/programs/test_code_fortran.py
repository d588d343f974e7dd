"""`autolev code` for CODE DYNAMICS() into Fortran: the layout of Autolev 3.2's programs
(fixed form, COMMON blocks, FORMAT-read .in file), checked by compiling them with
gfortran: expressions against sympy's values, runs against `autolev run` and against
the reference runs of Autolev's own Fortran programs."""
import csv
import math
import re
import subprocess
import sys

import pytest
import sympy as sm

import autolev
from autolev.cli import main
from autolev.loader import load_for_run
from autolev.programs import program_texts
from autolev.programs.f import FortranPrinter, statement
from autolev.programs.f_subroutines import kutta_and_solve
from autolev.engine.errors import AutolevModelError
from helpers import CORPUS, EXAMPLES, ROOT, SHARED
from helpers.programs import GFORTRAN, needs_gfortran

# EQNS1(T, VAR, VARp, BOUNDARY) has Autolev's arguments whether the model reads them
FLAGS = ["-Wall", "-Wno-unused-dummy-argument", "-O2"]

PENDULUM = """\
NEWTONIAN N
BODIES A
POINTS O
VARIABLES Q'
VARIABLES U'
CONSTANTS G, L
MASS A = M
INERTIA A, 0, 0, IZ
CONSTANTS M, IZ
SIMPROT(N, A, 3, Q)
Q' = U
W_A_N> = U*N3>
P_O_AO> = L*A1>
V_AO_N> = DT(P_O_AO>, N)
GRAVITY(G*N1>)
ZERO = FR() + FRSTAR()
KANE()
INPUT G = 9.81, L = 0.5, M = 2, IZ = 0.1, Q = 30 DEG, U = 0
INPUT TFINAL = 2, INTEGSTP = 0.05
UNITS Q = DEG
OUTPUT T, Q, U
CODE DYNAMICS() pendulum.f
"""


def compile_and_run(folder, source: str, exe="prog"):
    built = subprocess.run([GFORTRAN, *FLAGS, "-o", exe, source], cwd=folder,
                           capture_output=True, text=True)
    assert built.returncode == 0 and built.stderr == "", built.stderr
    return subprocess.run([f"./{exe}"], cwd=folder, capture_output=True, text=True,
                          timeout=600)


def rows(path):
    """The numbers of an output file, row by row (its heading lines skipped)."""
    out = []
    for line in path.read_text().splitlines():
        try:
            values = [float(v) for v in line.split()]
        except ValueError:
            continue
        if values:
            out.append(values)
    return out


# -- the printer -------------------------------------------------------------------------
@needs_gfortran
def test_printed_expressions_have_the_values_sympy_gives_them(tmp_path):
    """Fortran's traps are integer arithmetic, mixed-kind intrinsics and a unary minus
    after an operator: each expression is printed, compiled and evaluated at x=0.7,
    y=-1.3, and compared with sympy's value."""
    x, y = sm.symbols("x y")
    exprs = [-x * -y, x / 3, sm.Rational(2, 3) * x, x ** 2, x ** -2, y ** 3,
             x ** sm.Rational(1, 3), sm.sqrt(2) * x, 1 / sm.sqrt(x), sm.sin(2) + x,
             -x ** 2, (-y) ** sm.Rational(1, 2) * -x, sm.Max(x, 1, y), sm.Min(y, 0),
             sm.sign(y), sm.sign(0 * x), sm.Heaviside(y), sm.floor(y), sm.ceiling(y),
             sm.Piecewise((x, y > 0), (2 * x, True)), sm.atan2(y, x), sm.exp(1) * x,
             sm.pi * x, 3 * x - 4 * y + 1, x * 10 ** 20, sm.Abs(y) * sm.cosh(x),
             sm.factorial(4) * x, sm.sec(x), 2 ** x, x ** -1 * y ** -1]
    printer = FortranPrinter({x: "X", y: "Y"})
    lines = ["      IMPLICIT DOUBLE PRECISION (A - Z)", "      X = 0.7D0", "      Y = -1.3D0"]
    for e in exprs:
        lines += statement(f"R = {printer(e)}") + ["      WRITE(*,'(ES25.17)') R"]
    (tmp_path / "e.f").write_text("\n".join(lines + ["      END"]) + "\n")
    ran = compile_and_run(tmp_path, "e.f")
    got = [float(v) for v in ran.stdout.split()]
    want = [float(e.subs({x: 0.7, y: -1.3}).evalf(30)) for e in exprs]
    assert len(got) == len(want)
    for e, g, w in zip(exprs, got, want):
        assert math.isclose(g, w, rel_tol=1e-14, abs_tol=1e-300), f"{e}: {g} != {w}"


def test_statements_are_cut_at_column_72_and_continued_in_column_6():
    text = "Z(1) = " + " + ".join(f"A{k}*COS(Q{k})" for k in range(30))
    lines = statement(text, 100)
    assert lines[0].startswith("100   Z(1) = ")
    assert all(len(line) <= 72 for line in lines)
    assert all(line.startswith("     &") for line in lines[1:])
    # the columns 7-72 of the lines, joined, are the statement
    assert "".join(line[6:] for line in lines) == text


# -- the program -------------------------------------------------------------------------
def _texts(tmp_path, text, name="pendulum.al"):
    path = tmp_path / name
    path.write_text(text)
    model = autolev.load(path)
    return {p.as_posix(): t for p, t in program_texts(model, model.code_commands[0]).items()}


def test_the_program_has_autolevs_sections_blocks_and_formats(tmp_path):
    texts = _texts(tmp_path, PENDULUM)
    assert set(texts) == {"pendulum.f", "pendulum.in", "pendulum.dir"}
    f = texts["pendulum.f"]
    for section in ["C**   Read message from input file",
                    "C**   Read values of constants from input file",
                    "C**   Read the initial value of each variable from input file",
                    "C**   Read integration parameters from input file",
                    "C**   Degree to radian conversion", "C**   Evaluate output quantities",
                    "C**   Update variables after integration step",
                    "C**   Update derivative array prior to integration step",
                    "      SUBROUTINE       EQNS1(T, VAR, VARp, BOUNDARY)",
                    "      SUBROUTINE       IO(T)", "      SUBROUTINE       KUTTA(",
                    "      SUBROUTINE       SOLVE(N, A, B, X)",
                    "7010  FORMAT( 1000(59X,E30.0,/) )",
                    "6020  FORMAT( 99(1X, 1PE14.6E3) )",
                    "      COMMON/CONSTNTS/ G,IZ,L,M",
                    "      COMMON/VARIBLES/ Q,U",
                    "      Q = Q*DEGtoRAD"]:
        assert section in f, section
    assert all(len(line) <= 72 for line in f.splitlines() if not line.startswith("C"))
    # the .in file: the message line the program prints, then Autolev 3.2's rows
    lines = texts["pendulum.in"].splitlines()
    assert lines[2] == "Replace this line with a message to appear on all output files."
    assert "Constant:            G                    UNITS           |  9.81" in lines
    assert texts["pendulum.dir"].splitlines()[-1].split() == ["pendulum.1", "T,Q,U"]


def test_nosubs_leaves_kutta_and_solve_to_the_user(tmp_path):
    f = _texts(tmp_path, PENDULUM.replace("pendulum.f", "pendulum.f, NOSUBS"))["pendulum.f"]
    assert "CALL KUTTA(" in f and "SUBROUTINE       KUTTA" not in f
    assert "SUBROUTINE       SOLVE" not in f


def test_code_and_run_name_a_fortran_programs_files_in_lower_case_alike(tmp_path):
    """CODE DYNAMICS() 7segSprint.f made 7segsprint.f, .in, .dir, .1 (the corpus): both
    `autolev code` and `autolev run` write Pendulum.f's files as pendulum.*; a C
    program's keep the name as written."""
    model_path = tmp_path / "pendulum.al"
    model_path.write_text(PENDULUM.replace("pendulum.f", "Pendulum.f"))
    assert main(["code", str(model_path), "--out", str(tmp_path / "prog"), "-q"]) == 0
    assert sorted(p.name for p in (tmp_path / "prog").iterdir()) == \
        ["pendulum.dir", "pendulum.f", "pendulum.in"]
    program = (tmp_path / "prog" / "pendulum.f").read_text()
    assert "FILE='pendulum.in'" in program and "FILE='pendulum.1'" in program
    assert main(["run", str(model_path), "--out", str(tmp_path / "run"), "-q"]) == 0
    assert sorted(p.name for p in (tmp_path / "run").iterdir()) == \
        ["pendulum.1", "pendulum.dir", "pendulum.in"]
    assert "Output files generated by  pendulum.f:" in \
        (tmp_path / "run" / "pendulum.dir").read_text()
    model_path.write_text(PENDULUM.replace("pendulum.f", "Pendulum.c"))
    assert main(["run", str(model_path), "--out", str(tmp_path / "c"), "-q"]) == 0
    assert sorted(p.name for p in (tmp_path / "c").iterdir()) == \
        ["Pendulum.1", "Pendulum.dir", "Pendulum.in"]


def test_encode_and_names_fortran_cannot_tell_apart_are_refused(tmp_path):
    with pytest.raises(AutolevModelError, match="ENCODE in a Fortran program"):
        _texts(tmp_path, PENDULUM.replace("OUTPUT T, Q, U", "OUTPUT T, Q, U\nENCODE U"))
    with pytest.raises(AutolevModelError, match="cannot be a name in the Fortran"):
        _texts(tmp_path, PENDULUM.replace("IZ", "KUTTA"))
    # Fortran has no reserved words: a quantity may be named as an intrinsic function
    # the program does not call (the sprinting model's EX' is EXp), not as one it calls
    assert "pendulum.f" in _texts(tmp_path, PENDULUM.replace("IZ", "EXP"))
    with pytest.raises(AutolevModelError, match="calls the intrinsic function"):
        _texts(tmp_path, PENDULUM.replace("IZ", "SIN"))


@needs_gfortran
def test_the_pendulum_program_integrates_the_pendulum(tmp_path):
    """I q'' = -m g l sin q with I = IZ + m l^2 about O: the rows agree with scipy's
    integration of that equation (tolerance 1e-8) to the printed digits."""
    from scipy.integrate import solve_ivp
    texts = _texts(tmp_path, PENDULUM)
    for name, text in texts.items():
        (tmp_path / name).write_text(text)
    ran = compile_and_run(tmp_path, "pendulum.f")
    assert ran.returncode == 0, ran.stdout + ran.stderr
    table = rows(tmp_path / "pendulum.1")
    g, length, m, iz = 9.81, 0.5, 2.0, 0.1
    inertia = iz + m * length ** 2
    times = [r[0] for r in table]
    sol = solve_ivp(lambda t, s: [s[1], -m * g * length * math.sin(s[0]) / inertia],
                    (0, 2), [math.radians(30), 0], t_eval=times, rtol=1e-11, atol=1e-12)
    assert len(table) == 41 and times[-1] == 2.0
    for row, q, u in zip(table, sol.y[0], sol.y[1]):
        assert row[1] == pytest.approx(math.degrees(q), rel=2e-6, abs=1e-5)
        assert row[2] == pytest.approx(u, rel=2e-6, abs=1e-5)


@needs_gfortran
@pytest.mark.parametrize("example", ["double_pendulum", "whipple_benchmark",
                                     "rolling_disc", "cart_pendulum"])
def test_a_fortran_program_writes_the_rows_autolev_run_writes(example, tmp_path):
    """`autolev run` of a CODE DYNAMICS into a .f file integrates as Autolev's Fortran
    programs did (their Kutta-Merson reuses the last stage's derivatives); the
    program, compiled and run from the .in file it comes with, prints the same
    numbers in every row."""
    source = (EXAMPLES / f"{example}.al").read_text()
    model_path = tmp_path / f"{example}.al"
    model_path.write_text(re.sub(r"(?im)^(\s*CODE\s+DYNAMICS\(\)\s+\S+)\.c\b", r"\1.f",
                                 source))
    assert main(["code", str(model_path), "--out", str(tmp_path / "prog"), "-q"]) == 0
    program = next((tmp_path / "prog").glob("*.f"))
    ran = compile_and_run(tmp_path / "prog", program.name)
    assert ran.returncode == 0, ran.stdout[-500:]
    assert main(["run", str(model_path), "--out", str(tmp_path / "run"), "-q"]) == 0
    compared = 0
    for ref in sorted((tmp_path / "run").glob(f"{program.stem}.[0-9]*")):
        ours = rows(tmp_path / "prog" / ref.name)
        theirs = rows(ref)
        assert ours == theirs, ref.name
        compared += 1
    assert compared


# -- against the reference runs of Autolev's own Fortran programs ---------------------------
def _truth_fortran_runs():
    index = SHARED / "truth" / "index.tsv"
    if not index.exists():
        return []
    return [(r["id"], r["run"]) for r in csv.DictReader(open(index), delimiter="\t")
            if r["kind"] == "f" and r["status"].startswith("ok") and r["run"] != "-"]


@pytest.mark.corpus
@needs_gfortran
@pytest.mark.parametrize("ident, run", _truth_fortran_runs())
def test_a_fortran_program_writes_the_reference_runs_files(ident, run, tmp_path):
    """Our program, compiled with our KUTTA and SOLVE (the corpus's programs were coded
    with NOSUBS) and run from the reference run's own .in file, writes its files: the
    same rows to the printed digits, up to the time after which the reference itself
    depends on the integration error (bench/truth.py finds it: where the run and one
    with tolerances 1000 times tighter part)."""
    sys.path.insert(0, str(ROOT / "bench"))
    from corpus import corpus_models
    from truth import WINDOWS, column_errors, read_table, revision_file, run_one
    models = dict(corpus_models(CORPUS))
    if ident not in models:
        pytest.skip(f"{ident}: not in the corpus")
    row = next(r for r in csv.DictReader(open(SHARED / "truth" / "index.tsv"),
                                         delimiter="\t") if (r["id"], r["run"]) == (ident, run))
    report = run_one(row, models, "kutta-merson", tmp_path / "run")
    window = min(WINDOWS.get((ident, run), math.inf), report.get("trusted", math.inf))
    # the .al revision the program was generated from, where the corpus holds a later one
    revision = revision_file(ident)
    model, _ = load_for_run(revision[0] if revision else models[ident])
    commands = [c for c in model.code_commands if c.kind == "dynamics"
                and c.filename.lower().endswith((".f", ".for"))]
    assert commands, f"{ident}: no CODE DYNAMICS into a Fortran file"
    texts = program_texts(model, commands[0])
    program = next(p for p in texts if p.suffix.lower() in (".f", ".for"))
    text = texts[program]
    if "SUBROUTINE       KUTTA" not in text:
        n = int(re.search(r"DIMENSION        VAR\((\d+)\)", text).group(1))
        text += "\n\n" + "\n".join(kutta_and_solve(n)) + "\n"
    reference = SHARED / "truth" / ident / run
    work = tmp_path / "program"
    (work / program).parent.mkdir(parents=True)
    (work / program).write_text(text)
    (work / program.with_suffix(".in")).write_text(next(reference.glob("*.in")).read_text())
    ran = compile_and_run(work, program.as_posix())
    compared = 0
    for ref in sorted(p for p in reference.iterdir() if p.suffix[1:].isdigit()):
        ours = work / program.parent / ref.name
        assert ours.exists(), ran.stdout[-800:]
        a, b = read_table(ours), read_table(ref)
        assert a.shape == b.shape, ref.name
        errors = column_errors(a, b, None if math.isinf(window) else window)
        assert errors.max() <= 1e-6, f"{ref.name}: {errors.max():.3g} (t <= {window})"
        compared += 1
    assert compared


@needs_gfortran
def test_an_ode_program_in_fortran_integrates_the_equations_given(tmp_path):
    """CODE ODE(EQ, X''): M X'' + K X = 0 from X = 1 is X = cos(2t) for K/M = 4; the
    program's rows are those and `autolev run`'s."""
    from test_code_solving import ODE
    model = tmp_path / "ode.al"
    model.write_text(ODE.format(name="ode.f"))
    assert main(["code", str(model), "--out", str(tmp_path / "prog"), "-q"]) == 0
    ran = compile_and_run(tmp_path / "prog", "ode.f")
    assert ran.returncode == 0, ran.stdout[-500:]
    assert main(["run", str(model), "--out", str(tmp_path / "run"), "-q"]) == 0
    ours = rows(tmp_path / "prog" / "ode.1")
    assert ours == rows(tmp_path / "run" / "ode.1") and len(ours) == 31
    for t, x, xp in ours:
        assert x == pytest.approx(math.cos(2 * t), abs=2e-6)
        assert xp == pytest.approx(-2 * math.sin(2 * t), abs=4e-6)
