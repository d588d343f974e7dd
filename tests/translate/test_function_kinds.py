"""Every function the translator knows, called with one and with two arguments of every
kind (issue 29): `check` reports a diagnostic at the call, or the model builds.  Never an
internal error, and never a clean check that the build then refuses, except where the
refusal depends on the model's state at that line (whether a name has an INPUT value or a
definition), which check does not follow.

The check of all the calls is one model (one statement a call); building each call that
check passes is the `slow` sweep, the default run builds a fixed sample of them.  Rules
and evidence: docs/language.md, "Functions"."""
import itertools

import pytest
import sympy as sm

import autolev
from autolev.loader import load_translation
from autolev.translate import translate
from autolev.translate.functions.table import FUNCTIONS

# one name of every kind: Q a variable, K a constant, V> a vector, N1> a unit vector, D>> a
# dyadic, M a matrix, C a column, A a frame, B a body, P a point, Q' a derivative
FIXTURE = """\
NEWTONIAN N
FRAMES A
BODIES B
POINTS P
VARIABLES Q'
CONSTANTS K
SIMPROT(N, A, 3, Q)
SIMPROT(A, B, 1, Q)
W_A_N> = Q'*N3>
W_B_A> = Q'*A1>
P_NO_P> = Q*N1> + K*A2>
P_NO_BO> = K*A1>
V_BO_N> = DT(P_NO_BO>, N)
V_P_N> = DT(P_NO_P>, N)
MASS B = 2
INERTIA B, 1, 2, 3
V> = Q*N1> + K*A2>
D>> = K*N1>*N1> + Q*N2>*A3>
M = [1, Q; K, 2]
C = [Q; K; 1]
"""
KINDS = ["Q", "K", "2", "V>", "N1>", "D>>", "M", "C", "A", "B", "P", "Q'"]

# the calls check passes whose build refuses them for the model's state at the call (no
# INPUT value, no definition), with the refusal
STATE_REFUSALS = {
    "INPUT(Q)": "INPUT(Q): no value was input for it",
    "INPUT(K)": "INPUT(K): no value was input for it",
    "INPUT(Q')": "INPUT(Q'): no value was input for it",
    "RHS(Q)": "Q has no stored right-hand side",
    "RHS(K)": "K has no stored right-hand side",
    "RHS(Q')": "Q' has no stored right-hand side",
    "RHS(M)": "Q has no stored right-hand side",
    "RHS(C)": "Q has no stored right-hand side",
}
# the default run builds every SAMPLE-th call that check passes
SAMPLE = 8


def calls() -> list[str]:
    """Every function with one argument of each kind and two of each pair of kinds."""
    out = []
    for name in sorted(FUNCTIONS):
        out += [f"{name}({k})" for k in KINDS]
        out += [f"{name}({a}, {b})" for a, b in itertools.product(KINDS, repeat=2)]
    return out


@pytest.fixture(scope="module")
def checked() -> dict[str, list]:
    """Each call's error diagnostics, from one model holding every call on its own line."""
    every = calls()
    text = FIXTURE + "".join(f"X{n} = {call}\n" for n, call in enumerate(every))
    first = FIXTURE.count("\n") + 1
    errors: dict[str, list] = {call: [] for call in every}
    for d in translate(autolev.parse(text, "kinds.al")).diagnostics:
        if d.severity == "error":
            assert d.line >= first, f"the fixture itself is refused: {d}"
            errors[every[d.line - first]].append(d)
    return errors


def build(call: str) -> str | None:
    """None when the fixture with `X = call` builds; the message of its R001 if not.  An
    internal error is raised."""
    text = FIXTURE + f"X = {call}\n"
    try:
        load_translation(autolev.translation(text, "kinds.al"), "kinds.al")
    except autolev.AutolevRuntimeError as exc:
        (d,) = exc.diagnostics
        assert (d.code, d.line) == ("R001", FIXTURE.count("\n") + 1), d
        return d.message
    return None


def test_every_function_joins_the_matrix(checked):
    assert len(checked) == len(FUNCTIONS) * (len(KINDS) + len(KINDS) ** 2) == 12324


def test_a_refused_call_is_refused_at_its_statement(checked):
    refused = {call: ds for call, ds in checked.items() if ds}
    # most calls are refused (a frame where an expression is wanted, three arguments to
    # SIN, ...); each diagnostic points into its own statement, `X = ` and the call
    for call, ds in refused.items():
        for d in ds:
            assert d.source_line.endswith(f" = {call}"), (call, d)
            assert d.code.startswith("T") and 1 <= d.col <= len(d.source_line), (call, d)
    assert 11000 < len(refused) < len(checked) - 500


def _sweep(checked, sample: int) -> tuple[dict, dict]:
    """The internal errors and the refusals of building every sample-th clean call."""
    clean = [call for call, ds in checked.items() if not ds][::sample]
    internal, refusals = {}, {}
    for call in clean:
        try:
            message = build(call)
        except autolev.AutolevInternalError as exc:
            internal[call] = exc.error
            continue
        if message is not None:
            refusals[call] = message
    return internal, refusals


def _assert_only_state_refusals(refusals: dict) -> None:
    unexpected = {c: m for c, m in refusals.items() if STATE_REFUSALS.get(c) != m}
    assert unexpected == {}


def test_a_sample_of_the_calls_check_passes_builds(checked):
    internal, refusals = _sweep(checked, SAMPLE)
    assert internal == {}
    _assert_only_state_refusals(refusals)


@pytest.mark.slow
def test_every_call_check_passes_builds(checked):
    internal, refusals = _sweep(checked, 1)
    assert internal == {}
    _assert_only_state_refusals(refusals)
    assert set(refusals) == set(STATE_REFUSALS)


# -- what check says of the calls it refuses -------------------------------------------------
@pytest.mark.parametrize("call, code, column, message", [
    # the argument's kind, at the argument
    ("FACTOR(Q, A)", "T001", 15, "FACTOR takes a name or a list of names ([x, y]) here, not "
     "a frame"),
    ("EXCLUDE(B, Q)", "T001", 13, "EXCLUDE takes an expression, not a body"),
    ("ZEE(Q, P)", "T001", 12, "ZEE takes a name or a list of names ([x, y]) here, not a point"),
    ("AUTOZ(V>, D>>)", "T001", 15, "AUTOZ takes a name or a list of names ([x, y]) here, not "
     "a dyadic"),
    ("EXPLICIT(Q, V>)", "T001", 17, "EXPLICIT takes a name or a list of names"),
    ("INCLUDE(Q, 2)", "T001", 16, "INCLUDE takes a name or a list of names ([x, y]) here, "
     "not a number"),
    ("ROOTS(Q)", "T001", 11, "ROOTS([a, b, ...]) takes a matrix, not a scalar"),
    ("POLYNOMIAL(Q, Q)", "T001", 16, "POLYNOMIAL([a, b, ...], x) takes a matrix, not a scalar"),
    ("VECTOR(A, Q)", "T001", 15, "VECTOR(A, M) takes a matrix, not a scalar"),
    ("DYADIC(A, K)", "T001", 15, "DYADIC takes a matrix, not a scalar"),
    ("INPUT(M)", "T008", 11, "INPUT(x) is the value INPUT gave to a declared name x, not to "
     "a matrix"),
    ("INPUT(2)", "T008", 11, "INPUT(x) is the value INPUT gave to a declared name x, not to "
     "a number"),
    # a declared name is a symbol, never a count, degree, index or tolerance
    ("EXPAND(Q, K)", "T009", 15, "EXPAND's degree must be a number, not K (a constant)"),
    ("EPSILON(V>, Q')", "T009", 17, "EPSILON's tolerance must be a number, not Q' (a variable)"),
    ("DIAGMAT(K, 1)", "T009", 13, "DIAGMAT's size must be a number, not K (a constant)"),
    ("ELEMENT(C, Q)", "T009", 16, "an index must be a number, not Q (a variable)"),
    ("D(Q, 2)", "T009", 10, "D differentiates with respect to a name or a list of names, not "
     "a number"),
    ("D(Q, Q^2)", "T009", 10, "D differentiates with respect to a name or a list of names, "
     "not an expression"),
    # the shape and elements of a matrix written as a literal
    ("DET(C)", "T001", 9, "DET takes a square matrix, not a 3x1 one"),
    ("INV(C)", "T001", 9, "INV takes a square matrix, not a 3x1 one"),
    ("DYADIC(A, M)", "T001", 15, "DYADIC takes a 3x3 matrix, not a 2x2 one"),
    ("VECTOR(A, M)", "T001", 15, "VECTOR(A, M) takes the 3 measure numbers, not a 2x2 matrix"),
    ("COLS(C, 2)", "T001", 13, "index 2 is outside 1..1"),
    ("ROWS([1, 2], 1:99999999)", "T001", 20, "index 99999999 is outside 1..1"),
    ("COEF(Q, M)", "T001", 13, "COEF takes a list of names ([x, y]) here; this one holds a "
     "number"),
    ("D(Q, C)", "T009", 10, "D differentiates with respect to a list of names; this one "
     "holds an expression"),
    ("EIG(M)", "T001", 9, "EIG takes a matrix of numbers; this one holds Q, a variable"),
    ("ROOTS(M)", "T001", 11, "ROOTS of a polynomial of degree 3 takes numbers; this one "
     "holds Q"),
    # COEF of a vector takes a unit vector; of a unit vector, a vector
    ("COEF(V>, V>)", "T001", 14, "COEF(V>, V>): the coefficient is taken of a unit vector of "
     "a frame (N1>, N2>, N3>)"),
    ("COEF(Q, N1>)", "T001", 10, "COEF(E, N1>) takes a vector E, not a scalar"),
    ("COEF(D>>, N1>)", "T001", 10, "COEF(E, N1>) takes a vector E, not a dyadic"),
    ("COEF(V>, [Q, K])", "T001", 10, "COEF(E, [x, y]) takes a scalar or a column E, not a "
     "vector"),
])
def test_check_says_what_kind_of_argument_the_function_takes(call, code, column, message):
    text = FIXTURE + f"X = {call}\n"
    (d,) = [d for d in translate(autolev.parse(text, "kinds.al")).diagnostics
            if d.severity == "error"]
    assert (d.code, d.line, d.col) == (code, FIXTURE.count("\n") + 1, column)
    assert d.message.startswith(message)


# -- COEF of a vector, a dyadic, a matrix --------------------------------------------------------
def load(tmp_path, text: str):
    path = tmp_path / "m.al"
    path.write_text(text)
    return autolev.load(path)


# the trebuchet of a public Autolev session (docs/language.md, "COEF"): the projectile P
# at the end of the sling S, on the arm A
TREBUCHET = """\
NEWTONIAN N
BODIES A
FRAMES S
PARTICLES P
VARIABLES AQ', SQ', U{3}'
CONSTANTS LAL, LS
AQ' = U1
SQ' = U3
SIMPROT(N, A, 3, AQ)
SIMPROT(A, S, 3, SQ)
W_A_N> = AQ'*N3>
W_S_A> = SQ'*A3>
P_NO_P> = LAL*A2> + LS*S2>
V_P_N> = DT(P_NO_P>, N)
PROJECTILE_VX = COEF(EXPRESS(V_P_N>, N), N1>)
PROJECTILE_VY = COEF(EXPRESS(V_P_N>, N), N2>)
AUXILIARY[1] = PROJECTILE_VY
"""


def test_coef_of_a_vector_on_a_unit_vector_is_its_measure_number(tmp_path):
    model = load(tmp_path, TREBUCHET)
    aq, sq, lal, ls, u1, u3 = (model[n] for n in ("AQ", "SQ", "LAL", "LS", "U1", "U3"))
    # Autolev's responses (79) and (81) of the session
    vx = -lal * sm.cos(aq) * u1 - ls * sm.cos(aq + sq) * (u1 + u3)
    vy = -lal * sm.sin(aq) * u1 - ls * sm.sin(aq + sq) * (u1 + u3)
    for name, value in (("PROJECTILE_VX", vx), ("PROJECTILE_VY", vy)):
        got = model.explicit(model[name])
        assert sm.simplify(sm.expand_trig(got - value)) == 0


def test_the_measure_number_is_a_scalar_to_the_statements_after_it():
    # check called PROJECTILE_VY a vector, and AUXILIARY[1] = PROJECTILE_VY an error
    diagnostics = translate(autolev.parse(TREBUCHET, "m.al")).diagnostics
    assert [d for d in diagnostics if d.severity == "error"] == []


def test_coef_on_a_unit_vector_takes_the_term_as_written(tmp_path):
    model = load(tmp_path, "NEWTONIAN N\nFRAMES A\nVARIABLES Q\nCONSTANTS K\n"
                           "SIMPROT(N, A, 3, Q)\nV> = Q*N1> + K*A2>\n"
                           "X1 = COEF(V>, N1>)\nX2 = COEF(V>, N2>)\nX3 = COEF(V>, A2>)\n"
                           "Y2 = COEF(EXPRESS(V>, N), N2>)\n")
    q, k = model["Q"], model["K"]
    # the A2> term is not expressed in N (EXPRESS first, as the session does)
    assert (model["X1"], model["X2"], model["X3"]) == (q, 0, k)
    # A2> = -sin(Q)*N1> + cos(Q)*N2> (SIMPROT about 3)
    assert sm.simplify(model.explicit(model["Y2"]) - k * sm.cos(q)) == 0


def test_coef_of_a_vector_or_dyadic_in_a_name_is_taken_of_each_measure_number(tmp_path):
    model = load(tmp_path, "NEWTONIAN N\nVARIABLES X\nCONSTANTS A, B\n"
                           "V> = (A*X + B)*N1> + X^2*N2> + A*B*N3>\n"
                           "D>> = A*X*N1>*N2> + B*N3>*N3>\n"
                           "CV> = COEF(V>, X)\nCD>> = COEF(D>>, X)\n"
                           "M = [A*X + B, B*X; X^2, 1]\nCM = COEF(M, X)\n")
    a, b = model["A"], model["B"]
    n = model.entity("N")
    # of x^1: A from A*X + B, 0 from X^2 and from A*B
    assert model.vector("CV").to_matrix(n) == sm.Matrix([a, 0, 0])
    assert model.vector("CD").to_matrix(n) == sm.Matrix([[0, a, 0], [0, 0, 0], [0, 0, 0]])
    assert model["CM"] == sm.Matrix([[a, b], [0, 0]])


def test_explicit_of_a_vector_keeping_the_speeds(tmp_path):
    # the SSOpt session's (129)-(130): V_GO_N> = EXPLICIT(DT(P_NO_GO>, N), [U7, U8, U9])
    # answered U8*N1> + U9*N2>
    model = load(tmp_path, "NEWTONIAN N\nPOINTS GO\nVARIABLES Q8', Q9', U7, U8, U9\n"
                           "Q8' = U8\nQ9' = U9\nP_NO_GO> = Q8*N1> + Q9*N2>\n"
                           "V> = EXPLICIT(DT(P_NO_GO>, N), [U7, U8, U9])\n")
    n = model.entity("N")
    assert model.vector("V").to_matrix(n) == sm.Matrix([model["U8"], model["U9"], 0])


def test_polynomial_of_an_expression_is_a_row_of_coefficients(tmp_path):
    model = load(tmp_path, "CONSTANTS A, B, C\nVARIABLES X\n"
                           "R = POLYNOMIAL(A*X^2 + B*X + C, X, 2)\nY = ELEMENT(R, 1, 2)\n")
    assert model["R"] == sm.Matrix([[model["A"], model["B"], model["C"]]])
    assert model["Y"] == model["B"]


def test_partials_of_a_list_of_speeds_is_a_column_of_vectors(tmp_path):
    model = load(tmp_path, "NEWTONIAN N\nVARIABLES U1, U2\nCONSTANTS K\n"
                           "V> = K*U1*N1> + U2*N2>\nW = DOT(PARTIALS(V>, [U1, U2]), N1>)\n")
    assert model["W"] == sm.Matrix([model["K"], 0])


