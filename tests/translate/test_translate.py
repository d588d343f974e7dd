"""The translator: names, special names, indexing, numbers, diagnostics."""
import pytest

import autolev
from helpers import parse


def translate(text: str) -> str:
    return autolev.transpile(text, "m.al")


def build(text: str):
    """Translate and execute; the module namespace."""
    code = translate(text)
    ns = {"__name__": "test_model"}
    exec(compile(code, "m.py", "exec"), ns)
    return ns


def errors(text: str):
    with pytest.raises(autolev.AutolevTranslationError) as info:
        translate(text)
    return [d for d in info.value.diagnostics if d.severity == "error"]


def test_python_keywords_and_reserved_aliases_are_renamed():
    ns = build("CONSTANTS lambda, if, sm, al, t_\nX = lambda + if + sm + al + t_")
    assert "lambda_" in ns and "if_" in ns and "sm_" in ns and "al_" in ns
    assert str(ns["X"]) == "al + if + lambda + sm + t_"


def test_scalar_frame_and_vector_namesakes_do_not_collide():
    code = translate("NEWTONIAN N\nBODIES lff\nCONSTANTS lff\nFRAMES A\nA = 2\nA> = lff*N1>")
    ns = {"__name__": "x"}
    exec(compile(code, "m.py", "exec"), ns)
    assert str(ns["lff"]) == "lff"                 # the constant keeps the name
    assert type(ns["lff_body"]).__name__ == "Body"
    assert ns["A"] == 2 and type(ns["A_frame"]).__name__ == "Frame"
    assert type(ns["A_vec"]).__name__ == "Vector"


def test_names_are_case_insensitive_and_keep_the_declared_spelling():
    ns = build("CONSTANTS Mass_Cart\nX = mass_cart*2 + MASS_CART")
    assert str(ns["X"]) == "3*Mass_Cart"


def test_derivative_names_and_a_clash_with_a_user_name():
    code = translate("VARIABLES Q1'\nCONSTANTS Q1P\nX = Q1' + Q1P")
    assert "Q1p_ = al.derivatives(Q1)" in code and "Q1P = model.constants" in code
    ns = {"__name__": "x"}
    exec(compile(code, "m.py", "exec"), ns)
    assert str(ns["X"]) == "Q1' + Q1P"


def test_each_statement_is_preceded_by_its_autolev_line():
    code = translate("% a comment\nCONSTANTS A   % mass\nB = A^2")
    lines = code.splitlines()
    i = lines.index("# CONSTANTS A   % mass")
    assert lines[i - 1] == "# a comment"
    assert lines[i + 1].startswith("A = model.constants(")
    assert lines[i + 2] == "# B = A^2" and lines[i + 3] == "B = A**2"


def test_exact_numbers():
    ns = build("X = 1/12\nY = 2^-1\nZ = -1/2 + 3\nW = 0.5")
    assert str(ns["X"]) == "1/12" and str(ns["Y"]) == "1/2" and str(ns["Z"]) == "5/2"
    assert ns["W"] == 0.5


def test_one_based_indexing_and_growing_matrices():
    ns = build("M = [1, 2; 3, 4]\nA = M[2, 1]\nZ[3] = 7\nZ[1] = 1\nB = Z[3]\nM[2,2] := 9")
    assert ns["A"] == 3 and ns["B"] == 7
    assert list(ns["Z"]) == [1, 0, 7]
    assert ns["M"][1, 1] == 9


def test_special_vector_names():
    code = translate("""NEWTONIAN N
FRAMES A
POINTS O, P
VARIABLES Q'
SIMPROT(N, A, 3, Q)
P_O_P> = 2*A1>
X> = P_O_P> + W_A_N> + ALF_A_N>
V_P_N> = Q'*A2>
Y> = V_P_N> + A_P_N> + FORCE_P> + TORQUE_A>
FORCE_P> += N1>
TORQUE(N/A, N3>)
D = N_A[1, 2]""")
    assert "P.set_pos(O, 2*A.x)" in code
    assert "X_vec = P.pos_from(O) + A.ang_vel_in(N) + A.ang_acc_in(N)" in code or \
        "X = P.pos_from(O) + A.ang_vel_in(N) + A.ang_acc_in(N)" in code
    assert "P.set_vel(N, Qp*A.y)" in code
    assert "model.add_force(P, N.x)" in code
    assert "model.torque_pair(N, A, N.z)" in code
    assert "N.dcm(A)[0, 1]" in code


def test_assigning_a_direction_cosine_matrix_orients():
    ns = build("NEWTONIAN N\nFRAMES A\nN_A = [0, -1, 0; 1, 0, 0; 0, 0, 1]\nX = DOT(A1>, N2>)")
    assert ns["X"] == 1


def test_degrees_on_and_off_for_numeric_angles():
    on = build("NEWTONIAN N\nFRAMES A\nSIMPROT(N, A, 1, 90)\nX = DOT(A2>, N3>)")
    off = build("NEWTONIAN N\nFRAMES A\nDEGREES OFF\nSIMPROT(N, A, 1, PI/2)\n"
                "X = DOT(A2>, N3>)")
    assert on["X"] == 1 and off["X"] == 1


def test_unknown_function_is_a_diagnostic_at_its_line():
    (d,) = errors("CONSTANTS A\nX = FOO(A)\nY = 2")
    assert (d.line, d.code) == (2, "T003") and "FOO" in d.message


def test_undefined_names_are_diagnosed_and_every_error_reported():
    errs = errors("X = Y + 1\nZ = W\nNEWTONIAN N\nV> = Q>")
    assert [(d.line, d.code) for d in errs] == [(1, "T002"), (2, "T002"), (4, "T002")]


def test_type_errors_are_diagnosed():
    errs = errors("NEWTONIAN N\nX = N1> + 1\nY = DOT(1, N1>)\nZ = SIN(N1>)")
    assert [d.line for d in errs] == [2, 3, 4]
    assert {d.code for d in errs} == {"T001"}


@pytest.mark.parametrize("text, code, message", [
    ("CONSTANTS A\nX = A + 1\nX += Y", "T002", "'Y' is not declared or defined"),
    ("CONSTANTS A\nX += A", "T002", "X has no value yet"),
    ("X = MOMENTUM(FOO)", "T003", "MOMENTUM takes LINEAR or ANGULAR, not FOO"),
    ("X = [1, 2]\nY = X'[1]", "T006", "a prime on an indexed name is not supported"),
    ("CONSTANTS A\nX = SIN(A, A)", "T007", "SIN takes 1 argument, not 2"),
    ("NEWTONIAN N, M", "T007", "NEWTONIAN declares one frame"),
    ("CONSTANTS A\nX = A\nY = X'", "T008", "X is not a declared variable, so X' has no meaning"),
    ("MASS Q = 1", "T008", "MASS is given to bodies and particles; 'Q' is not one"),
    ("CONSTANTS A\nX = EVALUATE(A, A)", "T009", "expected name=value"),
    ("X = SIN(1:2)", "T009", "a range n:m is only allowed in some function arguments"),
    ("NEWTONIAN N\nN1> = N2>", "T010", "N1> cannot be assigned"),
    ("BODIES B = 3", "T010", "BODIES names take no value, sign or prime")])
def test_each_kind_of_translation_error_has_its_code(text, code, message):
    (d,) = errors(text)
    assert (d.code, d.message) == (code, message)


def test_runtime_failure_points_at_the_autolev_statement(tmp_path):
    f = tmp_path / "m.al"
    f.write_text("NEWTONIAN N\nBODIES B\nMOTIONVARIABLES' Q', U'\nQ' = U\n"
                 "SIMPROT(N, B, 3, Q)\nW_B_N> = U*N3>\nV_BO_N> = 0>\n"
                 "ZERO = FR() + FRSTAR()\n")
    with pytest.raises(autolev.AutolevRuntimeError) as info:
        autolev.load(f)
    d = info.value.diagnostic
    assert d.line == 8 and "mass of body B" in d.message


def test_statements_after_exit_are_ignored_with_a_warning():
    result = autolev.translation("X = 1\nEXIT\nY = 2\n", "m.al")
    assert "Y = 2" not in result.code.split("# (EXIT")[1]
    assert any(d.code == "W103" for d in result.diagnostics)


def test_input_of_an_undeclared_name_warns_and_is_kept_as_a_comment():
    result = autolev.translation("INPUT integstp = 0.1, foo = 3\n", "m.al")
    assert "model.input('INTEGSTP', 0.1)" in result.code
    assert any(d.code == "W104" and "foo" in d.message for d in result.diagnostics)


def test_autorhs_on_reads_stored_right_hand_sides():
    ns = build("VARIABLES X', Y\nAUTORHS ON\nX' = 2*Y\nZ = X' + 1\nAUTORHS OFF\nW = X' + 1")
    assert str(ns["Z"]) == "2*Y + 1" and str(ns["W"]) == "X' + 1"


def test_parse_and_translate_agree_on_all_constructs_file():
    from helpers import ROOT
    text = (ROOT / "tests" / "data" / "all_constructs.al").read_text()
    parse(text)
    # the file is a syntax sample, not a consistent model: it must translate or
    # report translation diagnostics, never crash
    try:
        autolev.transpile(text, "all_constructs.al")
    except autolev.AutolevTranslationError as exc:
        assert all(d.line >= 1 for d in exc.diagnostics)


def test_the_module_imports_sympy_only_when_it_uses_it():
    plain = autolev.transpile("CONSTANTS A, B\nC = A*B\n")
    assert "import sympy" not in plain and "sm." not in plain
    matrix = autolev.transpile("CONSTANTS A, B\nM = [A, B; B, A]\nD = DET(M)\n")
    assert "import sympy as sm\n" in matrix and "sm.Matrix" in matrix
    for text in (plain, matrix):         # both build their model
        namespace: dict = {}
        exec(compile(text, "<generated>", "exec"), namespace)
        assert namespace["model"] is not None


def test_a_new_column_set_element_by_element_in_a_row_is_one_matrix():
    code = translate("CONSTANTS A, B\nD[1] = A\nD[2] = B\nX = D[2]")
    assert "D = sm.Matrix([A, B])" in code and "set_element" not in code
    assert build("CONSTANTS A, B\nD[1] = A\nD[2] = B\nX = D[2]")["X"] == build(
        "CONSTANTS A, B\nD[1] = A\nD[2] = B")["D"][1]


@pytest.mark.parametrize("text", [
    "CONSTANTS A, B\nD = [0; 0]\nD[1] = A\nD[2] = B",     # D has a value already
    "CONSTANTS A, B\nD[1] = A\nD[2] = D[1] + B",          # an element reads D
    "CONSTANTS A, B\nD[2] = A\nD[1] = B",                 # not in order 1..n
    "CONSTANTS A, B\nD[1] = A\nD[1] = B",                 # an element set twice
    "CONSTANTS A, B\nD[1] = A\nX = 1\nD[2] = B",          # not consecutive
    "CONSTANTS A, B\nD[1] = A\nD[2] += B",
])
def test_a_run_that_is_not_plainly_a_new_column_is_set_element_by_element(text):
    code = translate(text)
    assert "sm.Matrix([A, B])" not in code and "D = al.set_element(" in code
