"""Text from outside (file names, the model's lines and comments, labels, units, CODE
file names) never becomes code in the generated module."""
import ast
import os

import pytest

import autolev
from autolev.translate.emit import comment, docstring, quote

HOSTILE = ['"""', "'''", "\\", "\\N{", "\x00", "\r", "\n", "\x0b", "\x0c", "\x1c", "\x85",
           "\u2028", "\udc80", "é", "\t", '"""if __import__("os").system("id")else"""']


@pytest.mark.parametrize("text", HOSTILE)
def test_quoting_functions_keep_text_inert(text):
    assert ast.literal_eval(quote(text)) == text
    line = f"# {comment(text)}\nX = 1\n"
    assert ast.parse(line).body[0].targets[0].id == "X"     # one comment, one statement
    module = f'"""from {docstring(text)} by"""\nX = 1\n'
    tree = ast.parse(module)
    assert len(tree.body) == 2 and isinstance(tree.body[0].value, ast.Constant)


MODEL = """% a comment with {evil}
NEWTONIAN N
BODIES A
CONSTANTS M, G
VARIABLES Q'
MASS A = M
INERTIA A, 1, 1, 1
SIMPROT(N, A, 3, Q)   % {evil}
UNITSYSTEM KG, METER, SEC
INPUT M = 2 KG, G = 9.81 METER/SEC^2
OUTPUT Q DEG, M KG
CODE DYNAMICS() out.c
"""


@pytest.mark.parametrize("evil", [
    '"""; __import__("pathlib").Path("PWNED").touch(); """',
    "\\\x00\x0c\x1c\u2028 é \\N{",
])
def test_a_hostile_file_name_and_comments_run_no_code(tmp_path, evil, monkeypatch):
    monkeypatch.chdir(tmp_path)
    name = 'p"""if __import__("pathlib").Path("PWNED").touch()else"""q.al'
    path = tmp_path / name
    path.write_text(MODEL.format(evil=evil), encoding="utf-8", errors="surrogateescape")
    code = autolev.transpile(path)
    compile(code, "generated.py", "exec")                 # valid Python
    model = autolev.load(path)
    assert model["M"].name == "M"
    assert not os.path.exists(tmp_path / "PWNED")
