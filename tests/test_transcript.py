"""What Autolev displayed for a model without a CODE command (issue 19, item 2): the
numbered inputs and each assignment's response, in Autolev's syntax, that `autolev
verify` can replay."""
import subprocess
import sys

import pytest
import sympy as sm

from autolev.transcript import expression, transcript
from helpers import EXAMPLES

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
    assert lines[7] == "   (8) P_O_P> = R*D1>"
    assert lines[8] == "-> (9) P_O_P> = R*D1>"
    assert "-> (11) X = SQRT(M)/R + R*SIN(Q)^2" in lines
    assert "-> (13) V = [1, SQRT(M)/R + R*SIN(Q)^2; Q, 2*R]" in lines
    # by hand: W x P = Q' N3> x R D1> = R Q' D2>, and D2> = -SIN(Q) N1> + COS(Q) N2>
    assert "-> (17) V_P_N> = -Q'*R*SIN(Q)*N1> + Q'*R*COS(Q)*N2>" in lines
    assert "-> (19) Y = -Q'*R*SIN(Q)" in lines
    assert "-> (21) Z0> = 0>" in lines


def test_the_printer_writes_autolev_not_python():
    q, r = sm.symbols("Q R")
    assert expression(q ** 2 / r + sm.Float(1.0 / 3)) == "Q^2/R + 0.3333333"
    assert expression(sm.sqrt(q) * sm.pi) == "PI*SQRT(Q)"
    assert expression(sm.Matrix([[1, q], [r, 0]])) == "[1, Q; R, 0]"
    assert expression(sm.cos(q) ** -1) == "1/COS(Q)"


def test_z_variables_are_shown_before_what_uses_them_and_the_transcript_replays(tmp_path):
    text = transcript(EXAMPLES / "double_pendulum.al")
    responses = [line for line in text.splitlines() if line.startswith("->")]
    assert "-> (21) Q1' = U1" in responses
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
    assert "19 match, 0 mismatch, 0 not comparable" in r.stdout


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
