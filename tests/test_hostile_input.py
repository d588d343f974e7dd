"""Input that once ended in a Python traceback is a diagnostic at its line now (issue 15,
item 5, the cases fixed so far)."""
import math
import os
from pathlib import Path

import pytest

import autolev


def diagnostics_of(tmp_path, text):
    path = tmp_path / "m.al"
    path.write_text(text)
    with pytest.raises(autolev.AutolevError) as info:
        autolev.transpile(path)
    return [d for d in info.value.diagnostics if d.severity == "error"]


def test_leading_zeros_are_a_decimal_number(tmp_path):
    path = tmp_path / "m.al"
    path.write_text("CONSTANTS A\nX = 007*A\n")
    model = autolev.load(path)
    assert model["X"] == 7 * model["A"]


def test_a_number_too_long_to_be_a_double(tmp_path):
    (d,) = diagnostics_of(tmp_path, "X = " + "9" * 5000 + "\n")
    assert d.code == "E045" and (d.location.line, d.location.col) == (1, 5)


def test_a_range_too_large_to_count(tmp_path):
    (d,) = diagnostics_of(tmp_path, "CONSTANTS C{1:99999999999999999999}\n")
    assert d.code == "E041" and "99999999999999999999 names" in d.message


def test_a_signed_call_on_its_own_line_is_displayed(tmp_path):
    program = autolev.parse("VARIABLES X\n+SIN(X)\n-COS(X)\n", "m.al")
    assert [s.kind for s in program.statements] == ["declaration", "display", "display"]


def test_a_compound_assignment_to_an_element_of_nothing(tmp_path):
    (d,) = diagnostics_of(tmp_path, "Q[1] += 1\n")
    assert d.code == "T002" and "Q has no value yet" in d.message


def test_long_sums_and_continued_lines_translate(tmp_path):
    path = tmp_path / "m.al"
    path.write_text("CONSTANTS A, B\nX = " + " + ".join(["A"] * 500) + " - B*B*B/B\n"
                    "Y = A &\n" + "+ B &\n" * 800 + "+ A\n")
    model = autolev.load(path)
    a, b = model["A"], model["B"]
    assert model["X"] == 500 * a - b ** 2 and model["Y"] == 2 * a + 800 * b


@pytest.mark.parametrize("text", ["-" * 500 + "A", "^".join(["A"] * 500)])
def test_signs_and_powers_nested_hundreds_deep(tmp_path, text):
    (d,) = diagnostics_of(tmp_path, "CONSTANTS A\nX = " + text + "\n")
    assert d.code == "T004" and d.location.line == 2


def test_a_file_where_the_output_folder_should_be(tmp_path):
    from helpers import EXAMPLES
    model = autolev.load(EXAMPLES / "double_pendulum.al")
    (tmp_path / "out").write_text("not a folder")
    for out in (tmp_path / "out", tmp_path / "out" / "sub"):
        with pytest.raises(autolev.runtime.AutolevModelError,
                           match="cannot write the output files into"):
            model.simulate(out_dir=out, TFINAL=0.1)


def test_a_full_disk_while_writing_rows(tmp_path, monkeypatch):
    import errno

    from autolev.engine import files
    from helpers import EXAMPLES
    model = autolev.load(EXAMPLES / "double_pendulum.al")

    class Full:                     # the disk, full once the rows begin
        def __init__(self, handle):
            self.handle = handle

        def write(self, text):
            raise OSError(errno.ENOSPC, "No space left on device", "double_pendulum.1")

        def close(self):
            self.handle.close()

    def full(real):
        def writing(self, k, rows):
            if not isinstance(self._handles[k], Full):
                self._handles[k] = Full(self._handles[k])
            return real(self, k, rows)
        return writing
    monkeypatch.setattr(files.OutputFiles, "write", full(files.OutputFiles.write))
    monkeypatch.setattr(files.OutputFiles, "write_rows",              # a block of rows
                        full(files.OutputFiles.write_rows))
    with pytest.raises(autolev.runtime.AutolevModelError, match="No space left on device"):
        model.simulate(out_dir=tmp_path / "out", TFINAL=0.1)


def test_nested_functions_translate_each_argument_once(monkeypatch):
    from autolev.translate.core import Translator
    calls = []
    real = Translator.expr

    def counting(self, e, want="value"):
        calls.append(e)
        return real(self, e, want)
    monkeypatch.setattr(Translator, "expr", counting)
    text = "CONSTANTS A\nX = " + "SIN(COS(" * 16 + "A" + "))" * 16 + "\n"
    autolev.transpile(text, "m.al")
    assert len(calls) <= 2 * 32 + 10        # linear in the depth, not 2^32


def test_functions_nested_beyond_the_limit_are_a_diagnostic_at_the_innermost_call(tmp_path):
    text = "CONSTANTS A\nX = " + "TANH(SINH(" * 17 + "A" + "))" * 17 + "\n"
    (d,) = diagnostics_of(tmp_path, text)
    assert d.code == "T004" and "nested more than 32 deep" in d.message
    assert (d.location.line, d.location.col) == (2, 5 + 32 * 5)


@pytest.mark.parametrize("text, line", [
    ("X = 10^10^10", 1), ("X = 9^9^9", 1), ("X = 2^2^2^2^2^2", 1), ("X = (10^900)^(10^6)", 1),
    ("X = FACTORIAL(100000000)", 1), ("CONSTANTS A\nX = TAYLOR(SIN(A), 99999, A=0)", 2),
    ("X = 2^(10^310)", 1), ("X = " + "9" * 350 + "^" + "9" * 350, 1)])
def test_exact_numbers_and_series_too_large_to_compute(tmp_path, text, line):
    (d,) = diagnostics_of(tmp_path, text + "\n")
    assert d.code == "T005" and d.location.line == line


def test_exact_numbers_of_ordinary_size_stay_exact(tmp_path):
    path = tmp_path / "m.al"
    path.write_text("X = 2^10 + 1/3 + (1/2)^3 + 10^300\nY = FACTORIAL(20)\n")
    model = autolev.load(path)
    import sympy as sm
    assert model["X"] == sm.Integer(1024) + sm.Rational(1, 3) + sm.Rational(1, 8) \
        + sm.Integer(10) ** 300
    assert model["Y"] == sm.factorial(20)


def test_an_integstp_that_cannot_advance_the_time(tmp_path):
    from helpers import EXAMPLES
    model = autolev.load(EXAMPLES / "double_pendulum.al")
    with pytest.raises(autolev.runtime.AutolevModelError, match="too small to advance"):
        model.simulate(INTEGSTP=1e-300)


# -- found by bench/fuzz.py --mode grammar ------------------------------------------
def load_error(tmp_path, text):
    """The one error diagnostic of loading (parse, translate, run) a model."""
    path = tmp_path / "m.al"
    path.write_text(text)
    with pytest.raises(autolev.AutolevError) as info:
        autolev.load(path)
    (d,) = [d for d in info.value.diagnostics if d.severity == "error"]
    return d


def test_sums_and_products_of_thousands_of_terms_load(tmp_path):
    path = tmp_path / "m.al"
    path.write_text("CONSTANTS A, B\nX = " + " + ".join(["A", "B"] * 900) + "\n"
                    "Y = " + "*".join(["A"] * 1500) + "/B\n")
    model = autolev.load(path)
    a, b = model["A"], model["B"]
    assert model["X"] == 900 * (a + b) and model["Y"] == a ** 1500 / b


def test_a_sum_longer_than_python_compiles(tmp_path):
    (d,) = diagnostics_of(tmp_path, "CONSTANTS A\nX = " + " + ".join(["A"] * 5000) + "\n")
    assert d.code == "T004" and d.location.line == 2 and "5000 terms" in d.message


def test_statements_nested_deeper_than_python_compiles(tmp_path):
    # (functions nested this deep are refused before: T004)
    text = "(" + " + ".join(["A"] * 1999) + ")*" + "*".join(["A"] * 1999)
    d = load_error(tmp_path, "CONSTANTS A\nX = " + text + "\n")
    assert d.code == "R001" and "nested too deeply" in d.message
    assert (d.location.line, d.location.col) == (2, 1)


def test_a_function_of_a_matrix_expression_applies_to_each_element(tmp_path):
    path = tmp_path / "m.al"
    path.write_text("CONSTANTS A, B\nM = [A, 0; 0, B]\nC = COS(-M)\nS = SIN([A]^2)\n"
                    "E = ELEMENT(M*2 + M, 2, 2)\n")
    model = autolev.load(path)
    import sympy as sm
    a, b = model["A"], model["B"]
    assert model["C"] == sm.Matrix([[sm.cos(a), 1], [1, sm.cos(b)]])
    assert model["S"] == sm.Matrix([[sm.sin(a ** 2)]]) and model["E"] == 3 * b


@pytest.mark.parametrize("text", ["RUN " + "x" * 300 + ".al", "X = " + "F" * 300 + "(1)"])
def test_file_names_too_long_for_the_file_system(tmp_path, text):
    with pytest.raises(autolev.AutolevError) as info:
        autolev.transpile(text + "\n", str(tmp_path / "m.al"))
    assert [d.location.line for d in info.value.diagnostics] == [1]


@pytest.mark.parametrize("text, message", [
    ("X = DIAGMAT(99999999, 1)", "more than 1000000 elements"),
    ("M[3903042726] = 1", "more than 1000000 elements"),
    # a product: its shape is not known to the translation (of [1, 2] itself, check
    # reports the index: tests/translate/test_function_kinds.py)
    ("M = 2*[1, 2]\nX = ROWS(M, 1:99999999)", "indices 1:99999999 are outside 1..1")])
def test_matrices_too_large_to_build(tmp_path, text, message):
    d = load_error(tmp_path, text + "\n")
    assert d.code == "R001" and message in d.message
    assert d.location.line == text.count("\n") + 1


def test_names_longer_than_a_line_of_the_translation(tmp_path):
    long = "L" + "x" * 100
    path = tmp_path / "m.al"
    path.write_text(f"CONSTANTS A, {long}, B{'y' * 80}\nBODIES {long}\nMASS {long} = A\n"
                    f"E = {long}^2 + A\n")
    model = autolev.load(path)
    assert model["E"] == model[long] ** 2 + model["A"]
    assert model.entity(long).mass == model["A"]


def test_a_statement_the_parser_reads_but_nested_too_deeply_to_build(tmp_path):
    text = "A"
    for _ in range(400):
        text = f"({text})^2"
    from helpers import errors_of
    (d,) = errors_of("CONSTANTS A\nX = " + text + "\n")
    assert d.code == "E004" and (d.location.line, d.location.col) == (2, 1)


@pytest.mark.parametrize("text", ["X = EXP(1000000)", "X = COS(SINH(FACTORIAL(11)))",
                                  "X = EXP(EXP(20))", "X = COSH(-10^400)",
                                  "X = SINH(COSH(34.1))", "X = EXP(2.0*COSH(17.0 + 17.1))",
                                  "X = EXP(1.0E3^2)", "X = TANH(EXP(1E3)/2)"])
def test_functions_of_numbers_beyond_a_double_are_refused(tmp_path, text):
    (d,) = diagnostics_of(tmp_path, text + "\n")
    assert d.code == "T005" and "beyond double precision" in d.message


def test_functions_of_numbers_within_a_double_stay_exact(tmp_path):
    path = tmp_path / "m.al"
    path.write_text("X = EXP(700) + SIN(10^400) + EXP(-10^6)\n")
    import sympy as sm
    x = autolev.load(path)["X"]
    assert x == sm.exp(700) + sm.sin(sm.Integer(10) ** 400) + sm.exp(-10 ** 6)


def test_functions_of_decimal_numbers_within_a_double_keep_their_value(tmp_path):
    path = tmp_path / "m.al"
    path.write_text("X = EXP(2.5)*SIN(1.5) + COS(-1.0E3^2) + EXP(709.0 - 0.5)\n")
    x = float(autolev.load(path)["X"])
    expected = math.exp(2.5) * math.sin(1.5) + math.cos(-1.0e6) + math.exp(708.5)
    assert x == pytest.approx(expected, rel=1e-14)


@pytest.mark.parametrize("text", ["X = MIN(1, ATAN2(1E3, ASIN(2)))", "X = MAX(2, SQRT(-2.0))"])
def test_the_extreme_of_a_complex_number_is_an_error(tmp_path, text):
    d = load_error(tmp_path, text + "\n")
    assert d.code == "R001" and "complex numbers have no order" in d.message
    assert d.message.startswith(("MIN's argument 2", "MAX's argument 2"))


def test_the_extreme_of_real_closed_forms_stays_exact(tmp_path):
    path = tmp_path / "m.al"
    path.write_text("X = MAX(PI, 3, SQRT(2))\nY = MIN(EXP(1), 2.5)\n")
    import sympy as sm
    model = autolev.load(path)
    assert model["X"] == sm.pi and model["Y"] == 2.5


@pytest.mark.parametrize("text", ["VARIABLES X'\nE = EVALUATE(X^4294967297, X = 2)",
                                  "VARIABLES X'\nZ = X + 1\nE = EVALUATE(Z^99999, X = 1)",
                                  "VARIABLES X'\nE = REPLACE(X^(-4294967297), X = 1/3)"])
def test_substituting_a_number_into_a_huge_exact_power_is_refused(tmp_path, text):
    d = load_error(tmp_path, text + "\n")
    assert d.code == "R001" and "exact numbers of more than 1000 digits" in d.message
    assert d.location.line == text.count("\n") + 1


def test_substituting_into_powers_that_stay_small(tmp_path):
    path = tmp_path / "m.al"
    path.write_text("VARIABLES X'\nA = EVALUATE(X^4294967297, X = 1)\n"
                    "B = EVALUATE(X^4294967297, X = 2.0)\nC = EVALUATE(X^900, X = 10)\n")
    import sympy as sm
    m = autolev.load(path)
    assert m["A"] == 1 and m["C"] == sm.Integer(10) ** 900
    assert float(sm.log(m["B"], 2)) == pytest.approx(4294967297)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs: POSIX")
@pytest.mark.parametrize("kind", ["fifo", "folder", "device"])
@pytest.mark.parametrize("command", ["check", "run", "convert", "transcript", "verify"])
def test_a_model_that_is_no_regular_file_is_refused_at_once(tmp_path, kind, command):
    # `check` of a FIFO named .al waited for a writer forever
    import subprocess
    import sys
    if kind == "fifo":
        path = tmp_path / "pipe.al"
        os.mkfifo(path)
    elif kind == "folder":
        path = tmp_path / "folder.al"
        path.mkdir()
    else:
        path = Path("/dev/null")
    args = [command, str(path)] + (["--out", str(tmp_path / "o")]
                                   if command in ("run", "transcript") else [])
    done = subprocess.run([sys.executable, "-m", "autolev", *args], capture_output=True,
                          text=True, timeout=60, cwd=tmp_path)
    said = done.stdout + done.stderr
    assert done.returncode == 1, said
    assert "internal error" not in said
    # check searches a folder for models: a folder named .al holds none
    assert ("no .al files found" if (command, kind) == ("check", "folder")
            else "not a regular file") in said


@pytest.mark.skipif(os.name != "posix", reason="symbolic links: POSIX")
@pytest.mark.parametrize("command", ["run", "code", "linearize", "animate", "equations",
                                     "check", "convert"])
def test_a_model_that_is_a_link_to_itself_is_refused(tmp_path, command):
    # the name of the lock of a background compile resolved the model's path first:
    # RuntimeError (a symlink loop), exit 70, before the read said what was wrong
    import subprocess
    import sys
    os.symlink("loop.al", tmp_path / "loop.al")
    args = [command, "loop.al"] + (["--out", str(tmp_path / "o")]
                                   if command in ("run", "code", "animate") else [])
    done = subprocess.run([sys.executable, "-m", "autolev", *args], capture_output=True,
                          text=True, timeout=60, cwd=tmp_path,
                          env=dict(os.environ, AUTOLEV_CACHE=str(tmp_path / "cache")))
    said = done.stdout + done.stderr
    assert done.returncode == 1, said
    assert "internal error" not in said
    assert "loop.al" in said and "Too many levels of symbolic links" in said


def test_a_folder_where_a_table_goes_is_named(tmp_path):
    # told to overwrite, the run's rename of its table onto a folder fails: the message
    # named the table's temporary (.double_pendulum.1.PID.HEX.autolev-part), not the folder
    from helpers import EXAMPLES
    model = autolev.load(EXAMPLES / "double_pendulum.al")
    (tmp_path / "double_pendulum.1").mkdir()
    with pytest.raises(autolev.runtime.AutolevModelError) as info:
        model.simulate(out_dir=tmp_path, TFINAL=0.1, overwrite=True)
    said = str(info.value)
    assert str(tmp_path / "double_pendulum.1") + ")" in said and "autolev-part" not in said
    # no temporary left, and no .dir: the set does not pass for complete
    names = sorted(p.name for p in tmp_path.iterdir())
    assert "double_pendulum.dir" not in names and not [n for n in names if n[0] == "."]


def test_check_names_the_included_file_it_cannot_read(tmp_path, monkeypatch, capsys):
    # a RUN file that cannot be read was said of the model: "m.al: error: cannot read:
    # Permission denied" of a model that reads
    from autolev.cli import main
    from autolev.engine import reading
    (tmp_path / "values.al").write_text("INPUT A = 1\n")
    model = tmp_path / "m.al"
    model.write_text("CONSTANTS A\nRUN values.al\nX = 2*A\n")
    really_reads = reading._regular_file_bytes

    def unreadable(path):
        if Path(path).name == "values.al":
            raise PermissionError(13, "Permission denied", str(path))
        return really_reads(path)
    monkeypatch.setattr(reading, "_regular_file_bytes", unreadable)
    assert main(["check", str(model)]) == 1
    said = capsys.readouterr().out
    assert "values.al: cannot read: Permission denied" in said, said


def test_check_of_a_folder_named_as_a_model_names_it(tmp_path, capsys):
    from autolev.cli import main
    (tmp_path / "x.al").mkdir()
    assert main(["check", str(tmp_path / "x.al")]) == 1
    assert f"no .al files found in {tmp_path / 'x.al'}" in capsys.readouterr().err


@pytest.mark.parametrize("command, name", [("code", "pendulum.c"), ("code", "pendulum.in"),
                                           ("animate", "pendulum.html")])
def test_a_folder_where_an_output_goes_is_named(tmp_path, capsys, command, name):
    # told to overwrite, the rename onto the folder failed: "cannot write into OUT: Is a
    # directory", without the name
    from autolev.cli import main
    model = tmp_path / "pendulum.al"
    model.write_text("NEWTONIAN N\nFRAMES A\nPARTICLES P\nMOTIONVARIABLES' Q''\n"
                     "CONSTANTS L, M, G\nSIMPROT(N, A, 3, Q)\nP_NO_P> = L*A1>\n"
                     "V2PTS(N, A, NO, P)\nMASS P = M\nGRAVITY(G*N1>)\n"
                     "ZERO = FR() + FRSTAR()\nKANE()\nINPUT L = 1, M = 1, G = 9.8, Q = 0.1\n"
                     "INPUT TFINAL = 0.1, INTEGSTP = 0.01\nOUTPUT T, Q\n"
                     "CODE DYNAMICS() pendulum.c\n")
    out = tmp_path / "out"
    (out / name).mkdir(parents=True)
    args = [command, "--overwrite", "--out", str(out), str(model)]
    if command == "animate":
        args[1:1] = ["--format", "html", "--backend", "python"]
    assert main(args) == 1
    said = capsys.readouterr().err
    assert f"Is a directory ({out / name})" in said, said
