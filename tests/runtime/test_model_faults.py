"""What a model gets wrong is said where it goes wrong: an R001 diagnostic at the
statement, with what the runtime function was given (not a Python exception that
escaped from inside it), and at its line when sympy refuses the statement's own
arithmetic."""
import pytest

import autolev
from autolev.cli import main

# (model, the failing statement's line, the diagnostic's message): the model's faults.
# Each reaches the runtime: the matrix is a product (its shape is not followed by the
# translation) and the number a name given a symbol; a literal matrix of the wrong shape
# or a declared name where a number is needed are reported by check
# (tests/translate/test_function_kinds.py)
MODEL_FAULTS = [
    ("X = TRACE(2*[1, 2])", 1, "TRACE needs a square matrix, not 1x2"),
    ("CONSTANTS K\nN = K\nX = DIAGMAT(N, 1)", 3,
     "DIAGMAT's number of rows must be a number, not K"),
    ("X = DIAGMAT(-1, 1)", 1, "DIAGMAT: a matrix cannot have -1 x -1 elements"),
    ("CONSTANTS K\nN = K\nM = [1, 2; 3, 4]\nX = ROWS(M, N)", 4,
     "an index must be a number, not K"),
    ("M = [1, 2; 3, 4]\nX = [M, 1]", 2, "the blocks of this matrix do not fit together"),
    ("VARIABLES X\nE = ROOTS(SIN(X) + X, X, 2)", 2,
     "ROOTS: X + sin(X) is not a polynomial in X"),
    ("CONSTANTS K\nN = K\nVARIABLES X\nE = POLYNOMIAL(X^2 + 1, X, N)", 4,
     "POLYNOMIAL's degree must be a number, not K"),
    ("CONSTANTS K\nT1 = K\nVARIABLES X\nE = EPSILON(X, T1)", 4,
     "EPSILON's tolerance must be a number, not K"),
    ("VARIABLES X\nE = EVALUATE(X^2, X = [1; 2])", 2,
     "EVALUATE: X is a scalar; it cannot be replaced by a matrix"),
    ("NEWTONIAN N\nVARIABLES X\nE = REPLACE(X^2, X = N1>)", 3,
     "REPLACE: X is a scalar; it cannot be replaced by a vector"),
    ("CONSTANTS A\nVARIABLES X\nB = A + 1\nE = D(X^2, B)", 4,
     "D differentiates with respect to a name, not A + 1"),
    ("CONSTANTS K\nN = K\nVARIABLES X\nE = TAYLOR(SIN(X), 0:N, X = 0)", 4,
     "TAYLOR's order must be a number, not K"),
    ("CONSTANTS A\nB = A\nE = EXPAND(A^2, 1:B)", 3, "EXPAND's degree must be a number, not A"),
    ("NEWTONIAN N\nVARIABLES X\nX = N1>", 3,
     "X is a scalar; it cannot be given a vector or dyadic"),
    ("NEWTONIAN N\nFRAMES A\nCONSTANTS K\nSIMPROT(N, A, N2>, CSC(PI) + K)", 4,
     "SIMPROT: the angle is infinite or undefined (zoo)"),
    # a redefinition through a definition that uses it was accepted, and a later
    # statement failed with a KeyError of the engine
    ("VARIABLES Q', U, W\nQ' = U\nW = Q' + U\nQ' = W\nE = DT(W)", 4,
     "Q' cannot be defined in terms of itself: Q' = W"),
    # SOLVE's determinant test met MIN of a complex number and failed inside sympy
    ("VARIABLES X\nCONSTANTS K\nE = MIN((-K)^(1/2), 1)*X - 1\nSOLVE(E, X)", 4,
     "cannot solve SOLVE: the determinant of its equations has no value for generic "
     "values of its names"),
    # a substitution that leaves MAX of 1/0 failed inside sympy
    ("VARIABLES X\nE = EVALUATE(MAX(1/X, 2), X = 0)", 2,
     "substituting X = 0 leaves an expression without a value"),
    ("VARIABLES X\nE = REPLACE(MAX(1/X, 2), X = 0)", 2,
     "substituting X = 0 leaves an expression without a value"),
    # SOLVE of a nonlinear equation was reported as a definition in terms of itself
    ("VARIABLES X\nCONSTANTS A\nE = X^2 - A\nSOLVE(E, X)", 4,
     "SOLVE solves equations linear in their unknowns; these are not linear in X"),
    ("VARIABLES X, Y\nCONSTANTS A\nE = [X + Y - 1; X*Y - A]\nSOLVE(E, X, Y)", 4,
     "SOLVE solves equations linear in their unknowns; these are not linear in X, Y"),
    # sympy refusing what the statement's own Python does with the model's values
    ("M = [1, 2] + [1; 2]", 1, "this statement failed: ShapeError: Matrix size mismatch"),
    ("M = 2*[1, 2; 3, 4]\nE = ELEMENT(M, 3, 3)", 2, "this statement failed: IndexError"),
    ("CONSTANTS N\nM = [1, 2; 3, 4]\nX = M[N, 1]", 3,
     "this statement failed: TypeError: Cannot convert symbols to int"),
    ("CONSTANTS K-\nX = MIN(LOG(K), 1)", 2,
     "MIN's argument 1, log(K), is not real: complex numbers have no order"),
    # arithmetic on the model's values
    ("X = INT(1/0)", 1, "this statement failed: ZeroDivisionError: division by zero"),
    ("X = INV([1, 1; 1, 1])", 1, "this statement failed: NonInvertibleMatrixError"),
]


@pytest.mark.parametrize("text, line, message", MODEL_FAULTS)
def test_the_models_faults_stay_diagnostics_at_their_line(tmp_path, text, line, message):
    path = tmp_path / "m.al"
    path.write_text(text + "\n")
    with pytest.raises(autolev.AutolevRuntimeError) as info:
        autolev.load(path)
    (d,) = info.value.diagnostics
    assert (d.code, d.location.line) == ("R001", line)
    assert d.message.startswith(message)


def test_the_cli_reports_the_models_fault_without_a_traceback(tmp_path, capsys):
    path = tmp_path / "m.al"
    path.write_text("X = 1\nY = TRACE(2*[1, 2])\n")
    assert main(["run", str(path), "--out", str(tmp_path)]) == 1
    err = capsys.readouterr().err
    assert f"{path}:2:1: error: TRACE needs a square matrix, not 1x2 [R001]" in err
    assert "Traceback" not in err and "internal error" not in err
