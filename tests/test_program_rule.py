"""The grammar on its own (the `program` rule, with the lexer's own '&' handling)
accepts whole files, so the grammar is a usable description of the language."""
from antlr4 import CommonTokenStream, InputStream
from antlr4.error.ErrorListener import ErrorListener

from autolev import ir
from autolev._antlr.AutolevLexer import AutolevLexer
from autolev._antlr.AutolevParser import AutolevParser
from helpers import EXAMPLES, ROOT, parse


class Collect(ErrorListener):
    def __init__(self):
        self.errors = []

    def syntaxError(self, recognizer, offendingSymbol, line, column, msg, e):  # noqa: N802
        self.errors.append((line, column))


def program_errors(text):
    lexer = AutolevLexer(InputStream(text))
    parser = AutolevParser(CommonTokenStream(lexer))
    errors = Collect()
    for r in (lexer, parser):
        r.removeErrorListeners()
        r.addErrorListener(errors)
    parser.program()
    return errors.errors


def test_program_rule_accepts_the_examples():
    for f in [ROOT / "tests" / "data" / "all_constructs.al", *EXAMPLES.glob("*.al")]:
        assert program_errors(f.read_text()) == [], f


def test_program_rule_rejects_a_broken_line():
    assert program_errors("x = 1\ny = (2\nz = 3\n") != []


def test_all_constructs_statement_kinds():
    p = parse((ROOT / "tests" / "data" / "all_constructs.al").read_text())
    kinds = {s.kind for s in p.statements}
    assert kinds == {"setting", "declaration", "mass", "inertia", "command", "assignment",
                     "unitsystem", "units", "input", "output", "encode", "code", "save",
                     "exit"}
    codes = [s.what for s in p.statements if isinstance(s, ir.Code)]
    assert codes == ["dynamics", "algebraic", "nonlinear", "ode"]
