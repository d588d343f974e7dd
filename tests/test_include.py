"""The include stage: RUN files, macros (NAME.A) and user functions (NAME.R) are read
and parsed before the IR is built, and the IR builder reads no file."""
import ast
from pathlib import Path

import pytest

import autolev
from autolev import ir
from autolev.include import Includes
from autolev.source import SourceFile

SRC = Path(autolev.__file__).parent


def write(path, text):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def pieces_of(path):
    includes = Includes(str(path), path)
    return includes, list(includes.model(SourceFile.read(path, str(path))))


def errors(path):
    with pytest.raises(autolev.AutolevSyntaxError) as info:
        autolev.parse(path)
    return [d for d in info.value.diagnostics if d.severity == "error"]


def test_the_stream_follows_run_and_macro_in_place(tmp_path):
    write(tmp_path / "kin.al", "NEWTONIAN N\n")
    write(tmp_path / "twice.a", "X#1# = 2*#1#\n")
    f = write(tmp_path / "m.al", "CONSTANTS A\nRUN kin.al\ntwice(A)\nY = 1\n")
    includes, pieces = pieces_of(f)
    texts = [p.origin.mapped.slice(p.statement.start.start, p.statement.stop.stop + 1)
             for p in pieces]
    assert texts == ["CONSTANTS A", "RUN kin.al", "NEWTONIAN N", "twice(A)", "XA = 2*A", "Y = 1"]
    run, macro = pieces[1].expansion, pieces[3].expansion
    assert run.path == (tmp_path / "kin.al").resolve() and run.name == "kin.al"
    assert macro.name == "twice" and macro.args == ("A",)
    assert [p.origin.display for p in pieces][2].endswith("kin.al")
    assert len(includes.files) == 3 and not includes.diagnostics


def test_a_refused_run_is_marked_and_brings_nothing(tmp_path):
    f = write(tmp_path / "m.al", "RUN missing.al\nY = 1\n")
    includes, pieces = pieces_of(f)
    assert len(pieces) == 2 and pieces[0].expansion.path is None
    assert [d.code for d in includes.diagnostics] == ["E022"]


def test_a_user_function_stands_for_its_expression(tmp_path):
    write(tmp_path / "sq.r", "#1#*#1# + 1\n")
    f = write(tmp_path / "m.al", "CONSTANTS A\nX = 3*sq(A)\n")
    value = autolev.parse(f).statements[-1].value
    # 3*(A*A + 1): the body is one expression, kept together as a call's value is
    assert value.left == ir.Number("3")
    assert value.right == ir.BinOp("+", ir.BinOp("*", ir.Name("A"), ir.Name("A")),
                                   ir.Number("1"))
    assert value.right.span.file.endswith("sq.r")


def test_user_functions_nest_through_their_arguments(tmp_path):
    write(tmp_path / "inc.r", "#1# + 1\n")
    write(tmp_path / "dbl.r", "2*#1#\n")
    f = write(tmp_path / "m.al", "CONSTANTS A\nX = dbl(inc(A))\n")
    value = autolev.parse(f).statements[-1].value
    assert value == ir.BinOp("*", ir.Number("2"),
                             ir.BinOp("+", ir.Name("A"), ir.Number("1")))


def test_a_function_called_within_its_own_argument_is_no_recursion(tmp_path):
    # FN1(FN1(X, Y), Y): the inner call is the caller's text, put where #1# stands; it
    # was taken for FN1 calling itself (E031, and a false "unknown function" after it)
    write(tmp_path / "fn1.r", "#1#*#2#\n")
    write(tmp_path / "fn0.r", "FN1(FN1(#1#, #2#), #2#)\n")
    f = write(tmp_path / "m.al", "CONSTANTS Q, K\nX = FN0(Q, K)\nY = FN1(FN1(Q, K), K)\n")
    first, second = autolev.parse(f).statements[-2:]
    expected = ir.BinOp("*", ir.BinOp("*", ir.Name("Q"), ir.Name("K")), ir.Name("K"))
    assert first.value == expected and second.value == expected


def test_a_function_fan_out_past_the_budget_is_one_error(tmp_path):
    # each of seven files calls the next twelve times: past the size limit, its one
    # error and no other (thousands of false "calls itself" and "unknown function")
    names = [f"f{c}" for c in "abcdefgh"]
    for name, callee in zip(names, names[1:]):
        write(tmp_path / f"{name}.r", "+".join([f"{callee}(#1#)"] * 12) + "\n")
    write(tmp_path / "fh.r", "#1#*2\n")
    f = write(tmp_path / "m.al", "CONSTANTS X\nY = fa(X)\nZ = 2*X\n")
    assert [d.code for d in errors(f)] == ["E033"]


def test_a_run_file_that_is_a_link_to_itself_is_no_file(tmp_path):
    # found by bench/fuzz.py --mode files: a RuntimeError ("Symlink loop") from resolve()
    (tmp_path / "loop.al").symlink_to("loop.al")
    f = write(tmp_path / "m.al", "CONSTANTS A\nRUN loop.al\n")
    assert [(d.code, d.line) for d in errors(f)] == [("E022", 2)]


def test_a_function_calling_itself_and_one_with_two_statements(tmp_path):
    write(tmp_path / "loop.r", "loop(#1#)\n")
    write(tmp_path / "two.r", "#1# + 1; #1# + 2\n")
    f = write(tmp_path / "m.al", "CONSTANTS A\nX = loop(A)\nY = two(A)\n")
    assert sorted(d.code for d in errors(f)) == ["E031", "E032"]


def test_a_function_wins_over_a_macro_of_the_same_name(tmp_path):
    write(tmp_path / "f.r", "#1# + 1\n")
    write(tmp_path / "f.a", "Z = #1#\n")
    f = write(tmp_path / "m.al", "CONSTANTS A\nf(A)\n")
    (st,) = autolev.parse(f).statements[1:]
    assert st.kind == "display"
    assert st.expr == ir.BinOp("+", ir.Name("A"), ir.Number("1"))


def test_a_call_with_no_file_is_a_command(tmp_path):
    f = write(tmp_path / "m.al", "CONSTANTS A\nexplicit(A)\n")
    assert autolev.parse(f).statements[-1].kind == "command"


def test_the_ir_builder_reads_no_file():
    tree = ast.parse((SRC / "irbuild.py").read_text())
    imported = {alias.name for node in ast.walk(tree) if isinstance(node, ast.ImportFrom)
                and node.module == "source" for alias in node.names}
    assert imported == {"SourceFile"}          # the type of what it is given, nothing more
    calls = {node.func.attr for node in ast.walk(tree)
             if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)}
    assert not calls & {"read", "read_text", "read_bytes", "parse"}


def test_a_stray_file_never_replaces_autolevs_own_words(tmp_path):
    # an empty gravity.a and a cos.r holding 42 beside a pendulum (issue 31, item 3):
    # Autolev's command and function are meant; each file is named in a warning
    import subprocess
    import sys
    import numpy as np
    from helpers import EXAMPLES
    text = (EXAMPLES / "simple_pendulum.al").read_text()
    assert "GRAVITY(G*N1>)" in text
    (tmp_path / "pend.al").write_text(text + "CX = COS(THETA)\n")
    clean = tmp_path / "clean"
    clean.mkdir()
    (clean / "pend.al").write_text(text)
    (tmp_path / "gravity.a").write_text("")
    (tmp_path / "cos.r").write_text("42\n")

    def cli(*args):
        return subprocess.run([sys.executable, "-m", "autolev", *map(str, args)],
                              capture_output=True, text=True)
    checked = cli("check", tmp_path / "pend.al")
    said = checked.stdout + checked.stderr
    assert checked.returncode == 0
    assert "gravity.a has the name of Autolev's own command GRAVITY" in said
    assert "cos.r has the name of Autolev's own function COS" in said
    ran = cli("run", tmp_path / "pend.al", "--out", tmp_path / "o", "-q")
    assert ran.returncode == 0 and "[W106]" in ran.stderr
    assert cli("run", clean / "pend.al", "--out", clean / "o", "-q").returncode == 0
    rows = np.loadtxt(tmp_path / "o" / "simple_pendulum.1", comments="%")
    assert np.array_equal(rows, np.loadtxt(clean / "o" / "simple_pendulum.1", comments="%"))
    assert np.ptp(rows[:, 1]) > 1.0          # it swings
    model = autolev.load(tmp_path / "pend.al")
    assert str(model["CX"]) == "cos(THETA)"


def test_files_that_include_each_other_many_times_stop_at_the_budget(tmp_path):
    # seven files under 100 bytes, each RUN eight times by the one before: 8^6
    # inclusions (issue 31, item 6); the budget stops them with the chain named
    from autolev.include import MAX_EXPANDED_STATEMENTS
    for i in range(1, 7):
        write(tmp_path / f"f{i}.al", f"RUN f{i + 1}.al\n" * 8)
    write(tmp_path / "f7.al", "X = 1\n")
    top = write(tmp_path / "top.al", "RUN f1.al\n")
    found = errors(top)
    assert [d.code for d in found] == ["E033"]
    assert (f"more than 1 MB of text or {MAX_EXPANDED_STATEMENTS} statements (here: top.al "
            "-> f1.al -> f2.al -> f3.al -> f4.al -> f5.al -> f6.al") in found[0].message


def test_a_file_included_many_times_is_read_and_parsed_once(tmp_path, monkeypatch):
    from autolev import include
    reads = []
    real = include.SourceFile.read
    monkeypatch.setattr(include.SourceFile, "read",
                        classmethod(lambda cls, p, n=None: reads.append(n) or real(p, n)))
    write(tmp_path / "part.al", "X = X + 1\n")
    top = write(tmp_path / "top.al", "VARIABLES X\nX = 0\n" + "RUN part.al\n" * 5)
    program = autolev.parse(top)
    assert [Path(n).name for n in reads].count("part.al") == 1
    assert sum(st.kind == "assignment" for st in program.statements) == 6


def test_a_file_past_the_statement_budget_is_refused_before_it_is_parsed(tmp_path,
                                                                         monkeypatch):
    # a parse holds some 500 bytes a byte of text: the budget is judged on the lines
    # that hold code (comments and blank lines free), before the parser sees the file
    from autolev import include
    monkeypatch.setattr(include, "MAX_EXPANDED_STATEMENTS", 50)
    text = "% a comment\n\nVARIABLES X\n" + "".join(f"E{k} = {k}*X % note\n" for k in range(60))
    top = write(tmp_path / "top.al", text)
    seen = []
    monkeypatch.setattr(include.Parser, "parse", lambda self, mapped: seen.append(mapped))
    found = errors(top)
    assert [d.code for d in found] == ["E033"] and seen == []
    # the 51st statement (VARIABLES, then E0 ... E49) is the first past the budget: line 53
    assert found[0].line == 53
