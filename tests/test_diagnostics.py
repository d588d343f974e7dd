"""Diagnostics: every error at once, file:line:col, what was expected, caret context."""
import re

import pytest

import autolev
from helpers import errors_of

ANTLR_WORDS = re.compile(r"mismatched input|extraneous input|no viable alternative|"
                         r"token recognition|expecting|<EOF>|missing '|\bNL\b|\bID\b")


def test_all_errors_are_reported_at_once_in_file_order():
    errs = errors_of("a = (1\nb = 2\nc = )\nNEWTONIAN\nd = 3 $\n", "m.al")
    assert [(d.line, d.code) for d in errs] == [(1, "E003"), (3, "E002"), (4, "E005"),
                                                (5, "E001")]


def test_format_has_location_message_line_and_caret():
    (d,) = errors_of("x = 1\ny = sin(a,\n", "model.al")
    text = d.format()
    lines = text.splitlines()
    assert lines[0].startswith("model.al:2:11: error: unexpected end of line; expected ")
    assert lines[1] == "    y = sin(a,"
    assert lines[2] == "    " + " " * 10 + "^"


def test_caret_follows_tabs():
    (d,) = errors_of("\tx =\t)\n")
    caret_line = d.format().splitlines()[2]
    assert caret_line == "    \t   \t^"


def test_messages_never_carry_antlr_wording():
    bad = ["x = = 3", "CONSTANTS", "a b c", "f(", ")", "INPUT x", "OUTPUT", "MASS B",
           "INERTIA", "CODE DYNAMICS()", "SIMPROT(N,A,3,", "[1;2", "x = 3 4", "Q{3",
           "UNITS T=", "x'' '' = 2", "P_A_B> > 3", ">", "a = 1 +* 2", "RUN", "SAVE",
           "ENCODE", "AUTOZ", "x = 1e", "x = 1.2.3", "VARIABLES x{", "x[1 = 2"]
    for text in bad:
        with pytest.raises(autolev.AutolevSyntaxError) as info:
            autolev.parse(text + "\n", "m.al")
        for d in info.value.diagnostics:
            assert not ANTLR_WORDS.search(d.message), (text, d.message)
            assert d.line == 1 and d.col >= 1, (text, d)


@pytest.mark.parametrize("text", ["NEWTONIAN", "CONSTANTS", "OUTPUT", "INERTIA", "Input"])
def test_statement_keyword_alone(text):
    (d,) = errors_of(text + "\n")
    assert d.code == "E005" and text.upper() in d.message


def test_expected_token_is_named():
    (d,) = errors_of("x = f(a, b\n")
    assert "expected" in d.message and "')'" in d.message
    (d,) = errors_of("x = [1, 2; 3\n")
    assert "']'" in d.message


def test_expected_expression_is_described_in_words():
    (d,) = errors_of("x = \n")
    assert d.message == "unexpected end of line; expected an expression"


def test_missing_ampersand_hint():
    d = errors_of("M = [1, 2;\n 3, 4]\n")[0]
    assert any("'&'" in n for n in d.notes)


def test_extra_token_after_a_complete_statement():
    (d,) = errors_of("x = 3 4\n")
    assert (d.col, d.code) == (7, "E002")
    assert d.message.startswith("unexpected '4'")


def test_stray_ampersand_and_gt():
    (d,) = errors_of("x = a & b\n")
    assert "'&'" in d.message and d.col == 7
    (d,) = errors_of("x = a >\n")
    assert "vector" in d.message


def test_deeply_nested_expression_is_a_diagnostic_not_a_crash():
    depth = 3000
    errs = errors_of("x = " + "(" * depth + "1" + ")" * depth + "\n")
    assert errs[0].code == "E004"


def test_error_exposes_diagnostics_and_a_readable_message():
    with pytest.raises(autolev.AutolevSyntaxError) as info:
        autolev.parse("x = )\ny = (\n", "m.al")
    err = info.value
    assert str(err).startswith("2 errors\nm.al:1:5: error:")
    assert all(isinstance(d, autolev.Diagnostic) for d in err.diagnostics)


def test_warnings_reach_the_program_and_do_not_raise():
    p = autolev.parse("VARIABLES x\nVARIABLES x\n", "m.al")
    assert [d.severity for d in p.diagnostics] == ["warning"]


def test_diagnostic_as_dict():
    (d,) = errors_of("x = )\n", "m.al")
    assert d.as_dict() == {"file": "m.al", "line": 1, "col": 5, "severity": "error",
                           "code": "E002", "message": d.message, "expanded_from": [],
                           "notes": []}


def test_a_name_declared_again_is_pointed_at_not_its_keyword(tmp_path, capsys):
    # `points No,J{6}` (a planar robot model) pointed at POINTS, column 1
    from autolev.cli import main
    path = tmp_path / "w.al"
    path.write_text("NEWTONIAN N\nPOINTS   P, NO\n")
    assert main(["check", str(path)]) == 0
    out = capsys.readouterr()
    said = out.out + out.err
    assert f"{path}:2:13: warning: 'NO' is declared again" in said
    assert "    POINTS   P, NO\n                ^" in said
