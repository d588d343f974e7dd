"""autolev verify: replaying Autolev's recorded responses against our translation."""
import json
from pathlib import Path

import pytest

import autolev
from autolev.cli import main
from autolev.verification import read_session

DATA = Path(__file__).parent / "data" / "verify"


def edited(tmp_path, session: str, *replacements) -> Path:
    """A copy of the session DATA/session with each (old, new) text replaced."""
    text = (DATA / session).read_text()
    for old, new in replacements:
        assert old in text
        text = text.replace(old, new)
    f = tmp_path / session
    f.write_text(text)
    return f


def test_reader_takes_inputs_responses_and_continuation_lines():
    s = read_session((DATA / "pendulum.all").read_text())
    assert s.source.splitlines()[1] == "MOTIONVARIABLES' Q{2}', U{2}'"
    zero1 = next(r for r in s.responses if r.lhs == "ZERO[1]")
    assert zero1.number == 37 and zero1.expr.endswith("U2')")     # two lines joined
    assert zero1.after == s.source.splitlines().index("ZERO = FR() + FRSTAR()") + 1
    forces = [r for r in s.responses if r.lhs.startswith("FORCE_")]
    assert [r.after for r in forces] == [forces[0].after] * 2     # both after GRAVITY


def test_a_correct_session_matches_every_response():
    report = autolev.verify(DATA / "pendulum.all")
    assert report.error is None and report.ok
    assert report.count("match") == 18 and report.count("mismatch") == 0
    kinds = {o.response.lhs for o in report.outcomes}
    assert {"N_A", "V_R_N>", "ZERO[2]", "KE", "H>"} <= kinds


def test_a_wrong_response_is_a_mismatch_with_both_values(tmp_path):
    f = edited(tmp_path, "pendulum.all",
               ("-> (23) V_P_N> = L*U1*A2>", "-> (23) V_P_N> = L*U1*A1>"))
    report = autolev.verify(f)
    bad = [o for o in report.outcomes if o.status == "mismatch"]
    assert [o.response.lhs for o in bad] == ["V_P_N>"] and not report.ok
    assert bad[0].ours is not None and bad[0].theirs is not None


def test_z_responses_assigned_names_and_euler_parameters_are_compared():
    # P> mixes the frames N and A: comparable only where the Euler parameters have
    # unit length (orthogonal direction cosines) and the square root is real
    report = autolev.verify(DATA / "euler_session.all")
    assert report.error is None and report.ok
    assert report.count("match") == len(report.outcomes) == 14
    z10 = next(o for o in report.outcomes if o.response.lhs == "Z10")
    assert "as part of (22) S" in z10.detail
    z1 = next(o for o in report.outcomes if o.response.lhs == "Z1")
    assert "as part of (17) N_A" in z1.detail


def test_a_wrong_response_through_z_and_names_is_a_mismatch(tmp_path):
    f = edited(tmp_path, "euler_session.all",
               ("-> (21) Z10 = 1 - C^2", "-> (21) Z10 = 1 - 2*C^2"))
    report = autolev.verify(f)
    bad = sorted(o.response.lhs for o in report.outcomes if o.status == "mismatch")
    assert bad == ["S", "Z10"]


def test_a_deliberately_wrong_translation_is_caught(monkeypatch):
    import autolev.runtime.model as model_mod
    real_ke = model_mod.Model.ke

    def doubled(self, *items):          # a translation bug: twice the kinetic energy
        return 2 * real_ke(self, *items)
    monkeypatch.setattr(model_mod.Model, "ke", doubled)
    report = autolev.verify(DATA / "pendulum.all")
    assert [o.response.lhs for o in report.outcomes if o.status == "mismatch"] == ["KE"]


def test_response_comments_in_an_al_file():
    report = autolev.verify(DATA / "comments.al")
    assert report.count("match") == 5 and report.ok


def test_names_our_model_lacks_are_not_comparable_and_do_not_fail(tmp_path):
    text = (DATA / "comments.al").read_text() + "% -> W = 2*NOSUCH\n"
    f = tmp_path / "extra.al"
    f.write_text(text)
    report = autolev.verify(f)
    nc = [o for o in report.outcomes if o.status == "not comparable"]
    assert len(nc) == 1 and "W" in nc[0].response.lhs and report.ok


def test_cli_exit_status_and_json(tmp_path, capsys):
    assert main(["verify", str(DATA / "pendulum.all")]) == 0
    assert "18 match, 0 mismatch" in capsys.readouterr().out
    f = edited(tmp_path, "pendulum.all", ("0.5*M*L^2", "0.6*M*L^2"))
    assert main(["verify", str(f), "--json"]) == 1
    data = json.loads(capsys.readouterr().out)
    assert data["mismatch"] == 1 and data["match"] == 17
    ke = next(r for r in data["responses"] if r["name"] == "KE")
    assert ke["status"] == "mismatch" and abs(ke["ours"] / ke["autolev"] - 5 / 6) < 1e-9


def test_a_file_without_responses_is_an_error(tmp_path):
    f = tmp_path / "plain.al"
    f.write_text("CONSTANTS A\n")
    report = autolev.verify(f)
    assert report.error and not report.ok


def test_a_session_of_declarations_has_nothing_to_compare_and_is_not_wrong(tmp_path, capsys):
    # Autolev printed nothing for a declaration (SSOpt's session, its inputs (7)-(12))
    f = tmp_path / "decl.all"
    f.write_text("   (1) % declarations only\n   (2) VARIABLES X1,X2\n   (3) CONSTANTS A\n")
    report = autolev.verify(f)
    assert report.ok and report.error is None and report.outcomes == []
    assert main(["verify", str(f)]) == 0
    assert "nothing to compare" in capsys.readouterr().out


def test_the_elements_of_a_column_assigned_one_by_one_are_each_compared(tmp_path):
    # X[1] = L, X[2] = 2*L is one column of the translation, written at its last element
    f = tmp_path / "col.all"
    f.write_text("   (1) CONSTANTS L\n   (2) X[1] = L\n-> (3) X[1] = L\n\n"
                 "   (4) X[2] = 2*L\n-> (5) X[2] = 3*L\n\n")
    report = autolev.verify(f)
    assert [(o.response.lhs, o.status) for o in report.outcomes] == [
        ("X[1]", "match"), ("X[2]", "mismatch")]


def test_a_response_the_grammar_cannot_read_names_its_line(tmp_path):
    f = tmp_path / "bad.all"
    f.write_text("   (1) CONSTANTS L\n   (2) X = L\n-> (3) X = L +* 2\n\n"
                 "   (4) Y = L\n-> (5) Y = L\n\n")
    x, y = autolev.verify(f).outcomes
    assert x.status == "not comparable" and x.detail.startswith(
        f"Autolev's response does not read: {f}:3: unexpected '*'")
    assert y.status == "match"


@pytest.mark.corpus
def test_every_corpus_session_verifies(corpus):
    files = sorted(corpus.rglob("*.all"))
    assert files
    for f in files:
        report = autolev.verify(f)
        assert report.ok and report.count("match") > 100, report.summary()


def test_the_models_own_names_never_stand_for_the_captures(tmp_path):
    # a model's VERIFY0 and _verify_defs are its own: a wrong response stays wrong
    f = edited(tmp_path, "pendulum.all",
               ("-> (23) V_P_N> = L*U1*A2>", "-> (23) V_P_N> = L*U1*A1>"),
               ("   (3) CONSTANTS L,M,G", "   (3) CONSTANTS L,M,G\n   (3) VERIFY0 = 7\n"
                "   (3) VERIFY1 = 7\n   (3) _verify_defs = 1"))
    report = autolev.verify(f)
    assert report.error is None
    assert [o.response.lhs for o in report.outcomes if o.status == "mismatch"] == ["V_P_N>"]


@pytest.mark.parametrize("response, reason", [
    ("(" * 5000 + "L" + ")" * 5000, "{f}:3: this statement is nested too deeply to read"),
    ("L +* 2", "{f}:3: unexpected '*'"),
    ("ATAN2(L)", "does not translate: ATAN2 takes 2 arguments, not 1 [T007]"),
    ("SIN(L, L)", "does not translate: SIN takes 1 argument, not 2 [T007]"),
    ("2*NOSUCH", "cannot be evaluated there: 'NOSUCH' is not a name of this model"),
    ("LOG(L - L)", "cannot evaluate: no value at the points tried"),
    ("-[L, L]", "shapes differ: ours (), Autolev's (1, 2)"),
    ("[L, 2] + 1", "cannot add a scalar to a matrix"),
    ("1/(L - L)", "cannot evaluate: no value at the points tried")])
def test_unreadable_responses_are_not_comparable_with_the_reason(tmp_path, response, reason):
    # the grammar reads the response, the translator gives it its meaning
    f = tmp_path / "m.al"
    f.write_text(f"CONSTANTS L\nX = L\n% -> X = {response}\n")
    (o,) = autolev.verify(f).outcomes
    assert o.status == "not comparable" and reason.format(f=f) in o.detail


def test_a_vector_given_to_a_function_of_a_response_is_not_comparable(tmp_path):
    f = tmp_path / "m.al"
    f.write_text("NEWTONIAN N\nCONSTANTS L\nX = L\n% -> X = SIN(N1>)\n")
    (o,) = autolev.verify(f).outcomes
    assert o.status == "not comparable"
    assert o.detail.startswith("Autolev's response does not translate: ") and "T001" in o.detail


@pytest.fixture
def broken_numeric(monkeypatch):
    """A bug in the runtime: every numeric evaluation raises KeyError."""
    from autolev.runtime.calculus import Definitions

    def numeric(self, expr, point):
        raise KeyError("bogus")
    monkeypatch.setattr(Definitions, "numeric", numeric)


def test_a_bug_while_comparing_is_an_internal_error_not_a_verdict(tmp_path, broken_numeric,
                                                                    capsys):
    f = tmp_path / "m.al"
    f.write_text("CONSTANTS L\nX = L\n% -> X = 2*L\n")
    with pytest.raises(autolev.AutolevInternalError) as info:
        autolev.verify(f)
    assert str(info.value).splitlines()[0] == (
        f"{f}:3:1: internal error: a bug in autolev, not in the model, while comparing "
        "response (1) X: KeyError: 'bogus'")
    assert main(["verify", str(f)]) == 70
    err = capsys.readouterr().err
    assert "internal error" in err and "Traceback" not in err


def test_points_where_a_value_has_none_are_skipped(tmp_path):
    # MIN of a complex number has no value: X has one only where K < 0, Y nowhere
    f = tmp_path / "m.al"
    f.write_text("CONSTANTS K\nX = MIN((-K)^(1/2), 1)\n% -> X = SQRT(-K)\n"
                 "Y = MIN((-K - 2)^(1/2), 1)\n% -> Y = 1\n")
    x, y = autolev.verify(f).outcomes
    assert x.status == "match"
    assert (y.status, y.detail) == ("not comparable", "cannot evaluate: no value at the "
                                    "points tried")


def test_zee_not_is_answered_and_its_answer_compared(tmp_path):
    # Autolev answered ZEE_NOT = [...] with the row of the names it keeps out of Z's
    session = tmp_path / "zee.all"
    session.write_text("   (1) MOTIONVARIABLES' U{2}'\n   (2) CONSTANTS GRAV\n"
                       "   (3) ZEE_NOT = [U1', U2', GRAV]\n"
                       "-> (4) ZEE_NOT = [U1', U2', GRAV]\n\n")
    report = autolev.verify(session)
    assert report.error is None and report.ok and report.count("match") == 1
    wrong = tmp_path / "wrong.all"
    wrong.write_text(session.read_text().replace("-> (4) ZEE_NOT = [U1', U2', GRAV]",
                                                 "-> (4) ZEE_NOT = [U2', U1', GRAV]"))
    assert autolev.verify(wrong).count("mismatch") == 1


# A session laid out as Autolev saved it, with the responses of commands written by hand
# for a link A turning about N3> at the fixed point O, a particle P at its tip
COMMAND_SESSION = """\
   (1) NEWTONIAN N
   (2) BODIES A
   (3) FRAMES B
   (4) PARTICLES P
   (5) POINTS O
   (6) MOTIONVARIABLES' Q', U'
   (7) CONSTANTS L, M, K, G, IA
   (8) SPECIFIED TAU
   (9) SIMPROT(N, A, 3, Q)
-> (10) N_A = [COS(Q), -SIN(Q), 0; SIN(Q), COS(Q), 0; 0, 0, 1]

   (11) DIRCOS(N, B, BODY123, PI/2, 0, 0)
-> (12) N_B = [1, 0, 0; 0, 0, -1; 0, 1, 0]

   (13) Q' = U
-> (14) Q' = U

   (15) W_A_N> = U*A3>
-> (16) W_A_N> = U*A3>

   (17) MASS A = M, P = K
   (18) INERTIA A, IA, IA, 2*IA
-> (19) I_A_AO>> = IA*A1>*A1> + IA*A2>*A2> + 2*IA*A3>*A3>

   (20) P_O_AO> = L*A1>
-> (21) P_O_AO> = L*A1>

   (22) P_O_P> = 2*L*A1>
-> (23) P_O_P> = 2*L*A1>

   (24) V_O_N> = 0>
-> (25) V_O_N> = 0>

   (26) V2PTS(N, A, O, AO)
-> (27) V_AO_N> = L*U*A2>

   (28) V2PTS(N, A, O, P)
-> (29) V_P_N> = 2*L*U*A2>

   (30) GRAVITY(-G*N2>)
-> (31) FORCE_AO> = -G*M*N2>
-> (32) FORCE_P> = -G*K*N2>

   (33) TAU = 10*SIN(2*PI*T + PI/6)
-> (34) TAU = 10*SIN(0.5235988+6.283185*T)

   (35) TORQUE(A, TAU*A3>)
   (36) ZERO = FR() + FRSTAR()
-> (37) ZERO = [TAU - G*L*(M+2*K)*COS(Q) - (2*IA+M*L^2+4*K*L^2)*U']

   (38) SOLVE(ZERO, U')
-> (39) U' = (TAU-G*L*(M+2*K)*COS(Q))/(2*IA+M*L^2+4*K*L^2)

"""


def test_the_responses_of_commands_are_compared(tmp_path):
    # by hand: about O the inertia is 2 IA + M L^2 + K (2L)^2 and gravity's moment
    # -G L (M + 2K) COS(Q) N3>; TAU is shown by its definition, PI/6 and 2 PI as decimals
    session = tmp_path / "link.all"
    session.write_text(COMMAND_SESSION)
    report = autolev.verify(session)
    assert report.error is None and report.ok
    assert report.count("match") == len(report.outcomes) == 15
    assert {"N_A", "N_B", "I_A_AO>>", "V_P_N>", "FORCE_P>", "TAU", "ZERO", "U'"} <= \
        {o.response.lhs for o in report.outcomes}


def test_a_wrong_response_of_a_command_is_a_mismatch(tmp_path):
    wrong = tmp_path / "wrong.all"
    wrong.write_text(COMMAND_SESSION.replace(
        "N_A = [COS(Q), -SIN(Q), 0; SIN(Q), COS(Q), 0; 0, 0, 1]",   # the transpose
        "N_A = [COS(Q), SIN(Q), 0; -SIN(Q), COS(Q), 0; 0, 0, 1]").replace(
        "IA*A1>*A1> + IA*A2>*A2> + 2*IA*A3>*A3>", "2*IA*A1>*A1> + IA*A2>*A2> + IA*A3>*A3>").replace(
        "FORCE_P> = -G*K*N2>", "FORCE_P> = -G*M*N2>").replace(
        "10*SIN(0.5235988+6.283185*T)", "10*SIN(6.283185+0.5235988*T)").replace(
        "U' = (TAU-G*L*(M+2*K)", "U' = (TAU+G*L*(M+2*K)"))
    report = autolev.verify(wrong)
    bad = {o.response.lhs for o in report.outcomes if o.status == "mismatch"}
    assert bad == {"N_A", "I_A_AO>>", "FORCE_P>", "TAU", "U'"} and not report.ok
    assert report.count("not comparable") == 0


def test_responses_read_in_chunks_keep_their_places(tmp_path, monkeypatch):
    # a large transcript is read a chunk at a time (a model's reading budget holds for
    # each): every response stays with its own line
    import autolev.verification as verification
    monkeypatch.setattr(verification, "_CHUNK_RESPONSES", 3)
    lines = ["   (1) CONSTANTS L"]
    for k in range(1, 9):
        shown = 9 * k if k == 5 else k           # the fifth response is wrong
        lines += [f"   ({2 * k}) X{k} = {k}*L", f"-> ({2 * k + 1}) X{k} = {shown}*L", ""]
    f = tmp_path / "chunks.all"
    f.write_text("\n".join(lines) + "\n")
    report = autolev.verify(f)
    assert [o.status for o in report.outcomes] == ["match"] * 4 + ["mismatch"] + ["match"] * 3


def test_a_sum_printed_with_rounded_coefficients_matches_its_zero(tmp_path):
    # X is 0 for every A; Autolev printed it with eight digits, so it cancels only to
    # about 1e-8 of its largest term: equal as far as the printed digits go.  A sum whose
    # difference is larger than that stays a mismatch.
    f = tmp_path / "zero.al"
    f.write_text("CONSTANTS A\nX = SIN(A)^2 + COS(A)^2 - 1\n"
                 "% -> X = 1.0000000*SIN(A)^2 + 0.99999999*COS(A)^2 - 1\n"
                 "Y = SIN(A)^2 + COS(A)^2 - 1\n"
                 "% -> Y = SIN(A)^2 + 0.999*COS(A)^2 - 1\n")
    report = autolev.verify(f)
    x, y = report.outcomes
    assert x.status == "match" and "largest term" in x.detail
    assert y.status == "mismatch"


def test_a_speed_defined_after_a_response_is_free_there(tmp_path):
    # (3) printed U1 + U2 before CONSTRAIN defined U2 = K*U1: Autolev's response keeps
    # U2 a name of its own, so ours is taken with U2 free there, not with its later value
    session = tmp_path / "later.all"
    session.write_text(
        "   (1) NEWTONIAN N\n"
        "   (2) VARIABLES U{2}'\n"
        "   (3) CONSTANTS K\n"
        "   (4) W = U1 + U2\n"
        "-> (5) W = U1 + U2\n\n"
        "   (6) DEPENDENT[1] = U2 - K*U1\n"
        "-> (7) DEPENDENT[1] = U2 - K*U1\n\n"
        "   (8) CONSTRAIN(DEPENDENT[U2])\n"
        "-> (9) U2 = K*U1\n\n"
        "  (10) V = U1 + U2\n"
        "-> (11) V = U1 + K*U1\n\n")
    report = autolev.verify(session)
    assert report.error is None
    by_name = {o.response.lhs: o.status for o in report.outcomes}
    # V's response, after the CONSTRAIN, is U2 = K*U1 worked in: were the value U2 was
    # given free at (5) kept for (11), ours (U1 + U2, U2 free) would differ from it
    assert by_name["W"] == "match" and by_name["V"] == "match"


def test_responses_share_one_record_of_the_definitions_known_between_definitions():
    # thousands of responses each kept the whole table (3 GB for BioMAC's gait3d FK)
    from autolev.runtime.calculus import Definitions
    from autolev.runtime.symbols import Z
    import sympy as sm
    defs = Definitions()
    a, b, x = sm.symbols("a b x")
    defs.define(a, x + 1)
    first = defs.user_definitions()
    defs.define(Z("Z1"), x ** 2)                  # a Z names an expression: no new record
    assert defs.user_definitions() is first and first == {a: x + 1}
    defs.define(b, 2 * a)
    assert defs.user_definitions() == {a: x + 1, b: 2 * a}
    assert first == {a: x + 1}                    # the earlier record as it was


def test_a_response_of_two_statements_is_not_comparable(tmp_path):
    # `X = 1 + A; X = 7` was replayed as X = 7
    from autolev.verification import verify
    path = tmp_path / "m.al"
    path.write_text("CONSTANTS A\nX = 1 + A\n% -> X = 1 + A; X = 7\n")
    report = verify(path)
    (outcome,) = report.outcomes
    assert outcome.status == "not comparable"
    assert "holds 2 statements" in outcome.detail


def test_a_long_verification_says_how_far_it_is(tmp_path, monkeypatch):
    # a clock that runs 10 s a reading: the responses compared are counted as they go
    import io
    from autolev.engine import progress
    clock = iter(range(0, 10 ** 6, 10))
    monkeypatch.setattr(progress.time, "monotonic", lambda: float(next(clock)))
    said = io.StringIO()
    report = autolev.verify(DATA / "pendulum.all", progress=said)
    lines = said.getvalue().splitlines()
    total = len(report.outcomes)
    counted = [line for line in lines if "responses compared = " in line]
    assert counted and all(f" of {total} (" in line for line in counted)
