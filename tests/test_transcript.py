"""What Autolev displayed for a model (issue 19, item 2; issue 29): the numbered inputs
and the responses of each assignment and command, in Autolev's syntax, that `autolev
verify` can replay."""
import subprocess
import sys

import pytest
import sympy as sm

import autolev
from autolev.transcript import expression, transcript
from helpers import EXAMPLES, ROOT

sys.path.insert(0, str(ROOT / "bench"))

DISC = """% a point on a turning disc
NEWTONIAN N
FRAMES D
POINTS O, P
VARIABLES Q'
CONSTANTS R, M
SIMPROT(N, D, 3, Q)
P_O_P> = R*D1>
X = R*SIN(Q)^2 + SQRT(M)/R
V = [1, X; Q, 2*R]
W_D_N> = Q'*N3>
V_P_N> = CROSS(W_D_N>, P_O_P>)
Y = DOT(V_P_N>, N1>)
Z0> = 0>
"""


@pytest.fixture
def disc(tmp_path):
    path = tmp_path / "disc.al"
    path.write_text(DISC)
    return path


def test_the_responses_of_each_assignment_in_autolevs_syntax(disc):
    lines = transcript(disc).splitlines()
    assert lines[0] == "   (1) % a point on a turning disc"
    # SIMPROT about N3>: D1> = COS(Q) N1> + SIN(Q) N2>, and N_D[i,j] = Ni>.Dj>
    assert lines[7] == "-> (8) N_D = [COS(Q), -SIN(Q), 0; SIN(Q), COS(Q), 0; 0, 0, 1]"
    assert lines[9:11] == ["   (9) P_O_P> = R*D1>", "-> (10) P_O_P> = R*D1>"]
    assert "-> (12) X = R*SIN(Q)^2 + M^0.5/R" in lines
    # a matrix one element a line, row by row
    assert [x for x in lines if x.startswith(("-> (14)", "-> (15)", "-> (16)", "-> (17)"))] \
        == ["-> (14) V[1,1] = 1", "-> (15) V[1,2] = R*SIN(Q)^2 + M^0.5/R",
            "-> (16) V[2,1] = Q", "-> (17) V[2,2] = 2*R"]
    # by hand: W x P = Q' N3> x R D1> = R Q' D2>, and D2> = -SIN(Q) N1> + COS(Q) N2>
    assert "-> (21) V_P_N> = -Q'*R*SIN(Q)*N1> + Q'*R*COS(Q)*N2>" in lines
    assert "-> (23) Y = -Q'*R*SIN(Q)" in lines
    assert "-> (25) Z0> = 0>" in lines


def test_the_printer_writes_autolev_not_python():
    q, r = sm.symbols("Q R")
    assert expression(q ** 2 / r + sm.Float(1.0 / 3)) == "0.3333333 + Q^2/R"
    assert expression(sm.Matrix([[1, q], [r, 0]])) == "[1, Q; R, 0]"
    assert expression(sm.cos(q) ** -1) == "1/COS(Q)"
    # every number not an integer as a decimal, a root as a power, a capital E, the
    # terms with a sign last (TD-all (13), (37), (22); SSOpt (287))
    assert expression(sm.sqrt(q) * sm.pi) == "3.141593*Q^0.5"
    assert expression(q / sm.sqrt(r)) == "Q/R^0.5"
    assert expression(r / 4) == "0.25*R" and expression(q ** sm.Rational(3, 2)) == "Q^1.5"
    assert expression(sm.Float(7e-6) * q) == "7E-06*Q"
    assert expression(1 - 2 * q ** 2 - 2 * r ** 2) == "1 - 2*Q^2 - 2*R^2"
    # Autolev's names of functions, not sympy's (CEIL, not CEILING)
    assert expression(sm.ceiling(q) + sm.floor(r)) == "CEIL(Q) + FLOOR(R)"


def test_z_variables_are_shown_before_what_uses_them_and_the_transcript_replays(tmp_path):
    text = transcript(EXAMPLES / "double_pendulum.al")
    responses = [line for line in text.splitlines() if line.startswith("->")]
    # blank lines get no number: Q1' = U1 is the model's 20th line, the 17th input
    assert "-> (18) Q1' = U1" in responses
    z = [k for k, line in enumerate(responses) if line.split()[2].startswith("Z")]
    assert z and responses[z[0]].split()[2] == "Z1"
    for k in z:                             # each Z is defined before a later line uses it
        name = responses[k].split()[2]
        assert not any(f"{name}*" in line or line.endswith(name)
                       for line in responses[:k])
    saved = tmp_path / "double_pendulum.all"
    saved.write_text(text)
    r = subprocess.run([sys.executable, "-m", "autolev", "verify", str(saved)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    assert f"{len(responses)} match, 0 mismatch, 0 not comparable" in r.stdout


def test_autolev_run_of_a_model_without_code_prints_its_transcript(disc, tmp_path):
    r = subprocess.run([sys.executable, "-m", "autolev", "run", str(disc), "--out",
                        str(tmp_path / "out")], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout == transcript(disc)
    assert "no CODE command: the responses Autolev displayed follow" in r.stderr
    r = subprocess.run([sys.executable, "-m", "autolev", "transcript", str(disc), "--out",
                        str(tmp_path / "t")], capture_output=True, text=True)
    assert r.returncode == 0
    assert (tmp_path / "t" / "disc.all").read_text() == transcript(disc)


def test_a_derivative_defined_twice_shows_each_definition(tmp_path):
    path = tmp_path / "twice.al"
    path.write_text("VARIABLES X'\nCONSTANTS A\nX' = A*X\nX' = 2*A\n")
    responses = [x for x in transcript(path).splitlines() if x.startswith("->")]
    assert responses == ["-> (4) X' = A*X", "-> (6) X' = 2*A"]


COMMANDS = """NEWTONIAN N
BODIES A
FRAMES B, C
PARTICLES P
POINTS O
MOTIONVARIABLES' Q', U'
VARIABLES X, Y
CONSTANTS L, K, M, G, IA, C12, H
SPECIFIED TORQUE

SIMPROT(N, A, 3, Q)
SIMPROT(A, B, -2, Q)
DIRCOS(N, C, BODY123, PI/2, 0, 0)
Q' = U
W_A_N> = U*A3>
MASS A = M, P = K
INERTIA A, IA, 2*IA, 3*IA, C12, 0, 0
P_O_AO> = L*A1>
V_O_N> = 0>
V2PTS(N, A, O, AO)
P_AO_P> = L*A1>
V2PTS(N, A, AO, P)
GRAVITY(-G*N2>)
ZERO = [X + Y - L; X - Y - K]
SOLVE(ZERO, X, Y)
H = PI/2
TORQUE = 10*SIN(2*PI*T + PI/6)
KANE()
"""


@pytest.fixture
def commands(tmp_path):
    path = tmp_path / "commands.al"
    path.write_text(COMMANDS)
    return path


def test_the_responses_of_commands(commands):
    lines = transcript(commands).splitlines()
    # by hand, with N_A[i,j] = Ni>.Aj> (SSOpt (34)): A1> = COS(Q) N1> + SIN(Q) N2>
    assert "-> (11) N_A = [COS(Q), -SIN(Q), 0; SIN(Q), COS(Q), 0; 0, 0, 1]" in lines
    # about -A2> by Q: B1> = COS(Q) A1> + SIN(Q) A3>, B3> = -SIN(Q) A1> + COS(Q) A3>
    assert "-> (13) A_B = [COS(Q), 0, -SIN(Q); 0, 1, 0; SIN(Q), 0, COS(Q)]" in lines
    # BODY123 with (PI/2, 0, 0): a quarter turn about N1> (TD-all (33))
    assert "-> (15) N_C = [1, 0, 0; 0, 0, -1; 0, 1, 0]" in lines
    # INERTIA: the moments and the product I12 on both sides of the diagonal
    assert ("-> (22) I_A_AO>> = IA*A1>*A1> + C12*A1>*A2> + C12*A2>*A1> + 2*IA*A2>*A2> + "
            "3*IA*A3>*A3>") in lines
    # V = W x r: U A3> x L A1> = L U A2>, and twice that at P, 2L from O
    assert "-> (28) V_AO_N> = L*U*A2>" in lines
    assert "-> (32) V_P_N> = 2*L*U*A2>" in lines
    # GRAVITY: mass times g> on A's mass centre and on P, in declaration order
    assert lines[lines.index("   (33) GRAVITY(-G*N2>)") + 1:][:2] == [
        "-> (34) FORCE_AO> = -G*M*N2>", "-> (35) FORCE_P> = -G*K*N2>"]
    # X + Y = L and X - Y = K: X = (L + K)/2, Y = (L - K)/2
    assert lines[lines.index("   (39) SOLVE(ZERO, X, Y)") + 1:][:2] == [
        "-> (40) X = 0.5*K + 0.5*L", "-> (41) Y = 0.5*L - 0.5*K"]
    # a constant and a specified quantity show their definitions, numbers as decimals
    assert "-> (43) H = 1.570796" in lines
    assert "-> (45) TORQUE = 10*SIN(0.5235988 + 6.283185*T)" in lines
    # MASS, KANE and declarations answer nothing; a blank line has no number
    assert lines[lines.index("   (20) MASS A = M, P = K") + 1] == \
        "   (21) INERTIA A, IA, 2*IA, 3*IA, C12, 0, 0"
    assert lines[-1] == "   (46) KANE()" and "   (10) SIMPROT(N, A, 3, Q)" in lines


def test_the_transcript_of_commands_replays(commands, tmp_path):
    saved = tmp_path / "commands.all"
    saved.write_text(transcript(commands))
    report = autolev.verify(saved)
    assert report.error is None and report.ok
    assert report.count("match") == len(report.outcomes) == 19


def _autolev_expr(text: str, names: dict):
    """A response's right side read back into sympy (^ is a power, ' a derivative)."""
    functions = {"SIN": sm.sin, "COS": sm.cos, "TAN": sm.tan}
    return sm.sympify(text.replace("^", "**").replace("'", "p"), locals=names | functions)


def test_kindiffs_constrain_and_explicit_show_what_they_define(tmp_path):
    path = tmp_path / "kin.al"
    path.write_text("NEWTONIAN N\nBODIES A\nMOTIONVARIABLES' Q{3}', U{3}', V{2}'\n"
                    "CONSTANTS R\nW_A_N> = U1*A1> + U2*A2> + U3*A3>\n"
                    "KINDIFFS(N, A, BODY123, Q1, Q2, Q3)\n"
                    "DEP[1] = V1 - R*V2\nCONSTRAIN(DEP[V1])\nE = (V2 + R)^2\nEXPAND(E)\n")
    shown = dict(line.split(") ", 1)[1].split(" = ", 1)
                 for line in transcript(path).splitlines() if line.startswith("->"))
    assert list(shown) == ["W_A_N>", "Q1'", "Q2'", "Q3'", "DEP[1]", "V1", "V1'", "E"]
    names = {n: sm.Symbol(n) for n in ("Q1", "Q2", "Q3", "U1", "U2", "U3", "V1", "V2",
                                       "V2p", "R")}
    q1, q2, q3, u1, u2, u3, v1, v2, v2p, r = names.values()
    # body-fixed 1-2-3 angles: W = (Q1' C2 C3 + Q2' S3) A1> + (Q2' C3 - Q1' C2 S3) A2>
    # + (Q3' + Q1' S2) A3>, solved for the rates
    by_hand = {"Q1'": (u1 * sm.cos(q3) - u2 * sm.sin(q3)) / sm.cos(q2),
               "Q2'": u1 * sm.sin(q3) + u2 * sm.cos(q3),
               "Q3'": u3 - (u1 * sm.cos(q3) - u2 * sm.sin(q3)) * sm.tan(q2),
               "V1": r * v2, "V1'": r * v2p, "E": r ** 2 + 2 * r * v2 + v2 ** 2}
    for name, expected in by_hand.items():
        assert sm.simplify(_autolev_expr(shown[name], names) - expected) == 0, name
    assert "(V2 + R)" not in shown["E"]            # EXPAND rewrote E in place


def test_a_declared_name_shows_its_definition_then_under_autorhs_too(tmp_path):
    # AUTORHS ON reads Q' as its definition U: the response is still Q' = U
    path = tmp_path / "autorhs.al"
    path.write_text("AUTORHS ON\nVARIABLES Q'\nMOTIONVARIABLES U'\nCONSTANTS K\nQ' = U\n"
                    "SPECIFIED F\nF = K*Q\nE = Q' + F\nF = 2*K\n")
    responses = [x for x in transcript(path).splitlines() if x.startswith("->")]
    assert responses == ["-> (6) Q' = U", "-> (9) F = K*Q", "-> (11) E = U + K*Q",
                         "-> (13) F = 2*K"]


def test_the_repeated_parts_of_a_large_value_are_shown_as_z_variables(tmp_path):
    # A(k+1) = f(Ak) with f(Z) = Z^2*COS(Z) + Z*SIN(Z): A5 printed out has thousands of
    # nodes, each level repeated four times in the next; as AUTOZ showed such values it
    # is Z1 = A1, Z(k+1) = f(Zk), A5 = f(Z4)
    path = tmp_path / "nested.al"
    path.write_text("VARIABLES X, Y\nA1 = SIN(X) + X*COS(Y) + Y^3\n" + "".join(
        f"A{k + 1} = A{k}*SIN(A{k}) + A{k}^2*COS(A{k})\n" for k in range(1, 5)))
    text = transcript(path)
    assert text.splitlines()[-6:] == [
        "-> (11) Z1 = Y^3 + X*COS(Y) + SIN(X)",
        "-> (12) Z2 = Z1^2*COS(Z1) + Z1*SIN(Z1)",
        "-> (13) Z3 = Z2^2*COS(Z2) + Z2*SIN(Z2)",
        "-> (14) Z4 = Z3^2*COS(Z3) + Z3*SIN(Z3)",
        "-> (15) A5 = Z4^2*COS(Z4) + Z4*SIN(Z4)", ""]
    assert "Z" not in text.split("(10) A5")[0]      # A4 is small enough to show whole
    saved = tmp_path / "nested.all"
    saved.write_text(text)
    report = autolev.verify(saved)
    assert report.ok and report.count("match") == len(report.outcomes) == 9


def test_nicheck_shows_the_rate_of_its_work_integral_first(tmp_path):
    # a particle on a spring: Fr = -K*Q, so WCHECK1' = -Fr*U = K*Q*U, and the check is
    # the kinetic energy M*U^2/2 plus that integral (SSOpt (311)-(313))
    path = tmp_path / "spring.al"
    path.write_text("NEWTONIAN N\nPARTICLES P\nMOTIONVARIABLES' Q', U'\nCONSTANTS M, K\n"
                    "Q' = U\nP_NO_P> = Q*N1>\nV_P_N> = U*N1>\nMASS P = M\n"
                    "FORCE_P> = -K*Q*N1>\nE = NICHECK()\n")
    lines = transcript(path).splitlines()
    assert lines[-3:] == ["-> (15) WCHECK1' = K*Q*U", "-> (16) E = WCHECK1 + 0.5*M*U^2", ""]


@pytest.mark.corpus
def test_every_corpus_model_without_code_transcribes_and_verifies(corpus, tmp_path):
    # bench/corpus.py lists the models as tests/test_corpus.py reads them; a model that
    # does not translate is one test_corpus.py names with its reason
    import corpus as corpus_bench
    from test_corpus import NOT_BUILDING
    not_translating, checked = [], 0
    for ident, path in corpus_bench.corpus_models(corpus):
        try:
            if autolev.parse(path).of_kind("code"):
                continue
            text = transcript(path)
        except autolev.AutolevError:
            not_translating.append(ident)
            continue
        saved = tmp_path / f"{ident}.all"
        saved.write_text(text)
        report = autolev.verify(saved)
        assert report.error is None or not text.count("\n-> ("), report.summary()
        assert report.count("mismatch") == 0, report.summary()
        checked += 1
    assert checked >= 49 and set(not_translating) <= set(NOT_BUILDING), not_translating


def test_run_files_and_macros_are_shown_as_they_ran_and_the_transcript_replays(tmp_path):
    # SAVE recorded the lines of a file run, not the RUN (SSOpt's session begins with its
    # model's lines): the transcript replays away from the model's folder
    model = tmp_path / "model"
    model.mkdir()
    (model / "parts.al").write_text("CONSTANTS L\nX = 2*L\n")
    (model / "twice.a").write_text("#2# = 2*#1#\n")
    (model / "main.al").write_text("RUN parts.al\ntwice(X, Y)\nW = Y + 1\n")
    text = transcript(model / "main.al")
    assert text.splitlines() == [
        "   (1) CONSTANTS L", "   (2) X = 2*L", "-> (3) X = 2*L", "",
        "   (4) Y = 2*X", "-> (5) Y = 4*L", "", "   (6) W = Y + 1", "-> (7) W = 1 + 4*L", ""]
    elsewhere = tmp_path / "tr"
    elsewhere.mkdir()
    (elsewhere / "main.all").write_text(text)
    report = autolev.verify(elsewhere / "main.all")
    assert report.error is None and report.count("match") == 3


def test_a_transcript_with_user_functions_replays_from_another_folder(tmp_path):
    # a user function's call is shown as typed (Autolev echoed its input): the session,
    # kept elsewhere, is replayed with --model-folder, and without it the message says so
    # on lines of their own
    model = tmp_path / "model"
    model.mkdir()
    (model / "sq.r").write_text("#1#^2\n")
    (model / "main.al").write_text("CONSTANTS L\nX = sq(L) + 1\n")
    out = tmp_path / "tr"
    wrote = subprocess.run([sys.executable, "-m", "autolev", "transcript", model / "main.al",
                            "--out", out], capture_output=True, text=True)
    assert wrote.returncode == 0, wrote.stderr
    assert f"--model-folder {model}" in wrote.stdout
    assert "   (2) X = sq(L) + 1" in (out / "main.all").read_text()
    alone = subprocess.run([sys.executable, "-m", "autolev", "verify", out / "main.all"],
                           capture_output=True, text=True)
    assert alone.returncode == 1 and "\\x0a" not in alone.stderr
    assert "unknown function SQ()" in alone.stderr.splitlines()[0]
    assert alone.stderr.splitlines()[-1] == "(a session kept apart from its model finds " \
        "the model's .a, .R and RUN files with --model-folder DIR)"
    found = subprocess.run([sys.executable, "-m", "autolev", "verify", out / "main.all",
                            "--model-folder", model], capture_output=True, text=True)
    assert found.returncode == 0, found.stderr
    assert autolev.verify(out / "main.all", folder=model).count("match") == 1


def test_a_run_file_run_by_a_run_file_is_shown_once_as_it_ran(tmp_path):
    # BioMAC's gait2dc_stick.al RUNs gait2dc_FK.al, which RUNs gait2dc_kin.al: the inner
    # RUN's statements stand in its place, the RUN itself is not shown (it would run the
    # file a second time, declaring every body again, or not be found elsewhere)
    model = tmp_path / "model"
    model.mkdir()
    (model / "kin.al").write_text("CONSTANTS L\n")
    (model / "fk.al").write_text("RUN kin.al\nX = 3*L\n")
    (model / "main.al").write_text("RUN fk.al\nW = X + 1\n")
    text = transcript(model / "main.al")
    assert "RUN" not in text
    assert text.splitlines()[:3] == ["   (1) CONSTANTS L", "   (2) X = 3*L", "-> (3) X = 3*L"]
    elsewhere = tmp_path / "tr"
    elsewhere.mkdir()
    (elsewhere / "main.all").write_text(text)
    report = autolev.verify(elsewhere / "main.all")
    assert report.error is None and report.count("match") == 2


@pytest.mark.parametrize("text, said", [
    ("CONSTANTS A, B\nX = A + B\nY = A*B\n\nM = [1, 2, 3]\nN = INV(M)\n",
     ":6:9: error: INV takes a square matrix"),
    ("NEWTONIAN N\nFRAMES A\nPOINTS O, P\nCONSTANTS L\nX = 2*L\nY = 3*L\n"
     "P_O_P> = L*A1>\nV2PTS(N, A, O, P)\n",
     ":8:1: error: the velocity of O in N is not defined")])
def test_a_model_that_does_not_load_is_refused_at_the_statement_at_fault(text, said,
                                                                          tmp_path, capsys):
    """The statement at fault (a translation's error, then a run's) is named at its own
    line, however many responses come before it (the text run with the captures has a
    line of its own after each of X, Y, M or P_O_P>)."""
    from autolev.cli import main
    path = tmp_path / "bad.al"
    path.write_text(text)
    assert main(["transcript", str(path)]) == 1
    err = capsys.readouterr().err
    assert f"{path}{said}" in err, err


def test_a_column_of_vectors_is_shown_an_element_a_line_and_verifies(tmp_path):
    # hazelnusse/Slotted-Discs builds [COEF(V>, U2), ...] columns of vectors; the
    # transcript stopped with an internal error (a vector is not a matrix element)
    path = tmp_path / "m.al"
    path.write_text("NEWTONIAN N\nM = [N1>, N2>]\nVARIABLES U\n"
                    "K = [COEF(N1> + U*N2>, U), N3>]\n")
    lines = transcript(path).splitlines()
    assert lines[2:4] == ["-> (3) M[1] = N1>", "-> (4) M[2] = N2>"]
    assert lines[7:9] == ["-> (7) K[1] = N2>", "-> (8) K[2] = N3>"]
    (tmp_path / "m.all").write_text("\n".join(lines) + "\n")
    report = autolev.verify(tmp_path / "m.all")
    assert report.error is None and report.count("match") == 4


def test_a_comments_terminal_escapes_are_printed_as_text(tmp_path, capsys):
    # the transcript on a terminal: a comment's escape sequences written out, not run
    from autolev.cli import main
    model = tmp_path / "esc.al"
    model.write_text("% \x1b[31mRED\x1b[0m comment\nCONSTANTS A\nX = 2*A\n")
    assert main(["transcript", str(model)]) == 0
    out = capsys.readouterr().out
    assert "\x1b" not in out and "\\x1b[31mRED" in out
    # the file keeps the model's text as Autolev's .all did
    assert main(["transcript", str(model), "--out", str(tmp_path / "t")]) == 0
    assert "\x1b[31mRED" in (tmp_path / "t" / "esc.all").read_text()


def test_a_transcript_imports_no_numpy(tmp_path):
    # the run machinery and numpy are imported where a model computes numbers; a
    # transcript forms the model and prints its responses (0.1 s of its cold start)
    import os
    import subprocess
    import sys
    model = tmp_path / "one.al"
    model.write_text("NEWTONIAN N\nBODIES B\nVARIABLES Q{3}', U{3}'\nCONSTANTS M, I1\n"
                     "MASS B = M\nINERTIA B, I1, I1, I1\nP_NO_BO> = 0>\n"
                     "DIRCOS(N, B, SPACE313, Q1, Q2, Q3)\n"
                     "W_B_N> = U1*B1> + U2*B2> + U3*B3>\n"
                     "KINDIFFS(N, B, SPACE313, Q1, Q2, Q3)\nZERO = FR() + FRSTAR()\n")
    probe = ("import sys, runpy\n"
             f"sys.argv = ['autolev', 'transcript', {str(model)!r}, '--out', "
             f"{str(tmp_path / 'out')!r}]\n"
             "try:\n    runpy.run_module('autolev', run_name='__main__')\n"
             "except SystemExit as exc:\n    assert not exc.code, exc.code\n"
             "print('numpy' in sys.modules)\n")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                          env={**os.environ, "AUTOLEV_CACHE": str(tmp_path / "cache")})
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[-1] == "False"
    assert (tmp_path / "out" / "one.all").is_file()
