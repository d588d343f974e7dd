"""The dispatch tables: every IR node and parse-tree context has its handler, and a
node nobody handles is a diagnostic, never an exception."""
import pytest

from autolev.dispatch import Dispatch


class Base:
    pass


class Derived(Base):
    pass


class Other:
    pass


def test_a_subclass_uses_its_nearest_base_handler_and_the_rest_the_fallback():
    table = Dispatch("test", lambda node: "fallback")
    table.register(Base)(lambda node: "base")
    assert table.lookup(Derived)(Derived()) == "base"
    assert table.registered(Derived) is table.registered(Base)
    assert table.lookup(Other)(Other()) == "fallback"
    assert table.registered(Other) is None


def test_a_handler_of_its_own_wins_over_the_base_even_after_a_lookup():
    table = Dispatch("test", lambda node: "fallback")
    table.register(Base)(lambda node: "base")
    assert table.lookup(Derived)(Derived()) == "base"
    table.register(Derived)(lambda node: "derived")
    assert table.lookup(Derived)(Derived()) == "derived"
    assert table.lookup(Base)(Base()) == "base"


def test_the_fallback_gets_the_arguments_a_handler_would():
    seen = []
    table = Dispatch("test", lambda owner, node, extra: seen.append((owner, node, extra)))
    node = Other()
    table.lookup(type(node))("owner", node, 3)
    assert seen == [("owner", node, 3)]


def test_one_class_cannot_have_two_handlers():
    table = Dispatch("test", lambda node: None)

    @table.register(Base, Other)
    def first(node):
        return 1
    with pytest.raises(ValueError, match="Other has a handler already"):
        table.register(Other)(lambda node: 2)


# -- every IR node class has its handler in every pass over IR nodes ------------------
def ir_classes(base):
    """The concrete node classes of autolev.ir below `base` (its statements or its
    expressions), found by walking the module."""
    from autolev import ir
    found = [c for c in vars(ir).values()
             if isinstance(c, type) and issubclass(c, base) and c is not base]
    assert found
    return found


def ir_passes():
    from autolev import ir
    from autolev.translate import core, io, reads
    return [("translator statements", core.STATEMENTS, ir.Statement),
            ("translator expressions", core.EXPRESSIONS, ir.Expr),
            ("ir.walk", ir.CHILDREN, ir.Expr),
            ("names read", reads.READS, ir.Expr),
            ("heading text", io._TEXT, ir.Expr)]


@pytest.mark.parametrize("what, table, base", ir_passes(), ids=lambda p: p if
                         isinstance(p, str) else "")
def test_every_ir_node_class_has_a_handler(what, table, base):
    missing = [c.__name__ for c in ir_classes(base) if table.registered(c) is None]
    assert missing == [], f"{what} has no handler for {missing}"


# -- every parse-tree context the builder meets has its handler ------------------------
# The contexts irbuild never looks up in a table, and why
NOT_DISPATCHED = {
    # the driver and Builder._build walk these directly: a file, a line, its statements
    "ProgramContext", "SingleLineContext", "StatementLineContext", "StatementContext",
    # parts of one statement, read through accessors by that statement's handler
    "DeclKeywordContext", "DeclaratorContext", "DeclRangeContext", "RangeBoundContext",
    "DeclSignContext", "MassItemContext", "InertiaValueContext", "AssignOpContext",
    "InputItemContext", "OutputItemContext", "UnitsItemContext", "UnitsTargetContext",
    "UnitContext", "UnitFactorContext", "SweepContext", "FileNameContext",
    "FileNamePartContext", "SettingNameContext", "SettingValueContext",
    # an assignment's target: _assignment tells its two alternatives apart by one test
    "TargetContext", "ScalarTargetContext", "VectorTargetContext",
    # _expr tells the alternatives of expr apart by their number of children (one
    # Python frame per level of nesting, as deep as the parser reads)
    "ExprContext", "UnaryExprContext", "PowerExprContext", "PrimaryExprContext",
    "AddExprContext", "MulExprContext",
    # the base of primary's alternatives, which have their handlers; and the parts of
    # a primary, read by its handler
    "PrimaryContext", "MatrixRowContext", "IndexListContext", "IndexItemContext",
    "ArgListContext", "ArgContext", "NumberContext", "NameContext",
}


def parser_contexts() -> dict[str, type]:
    from antlr4 import ParserRuleContext

    from autolev._antlr.AutolevParser import AutolevParser
    return {name: c for name, c in vars(AutolevParser).items()
            if isinstance(c, type) and issubclass(c, ParserRuleContext)}


def test_every_parse_tree_context_irbuild_meets_has_a_handler():
    from autolev.irbuild import Builder
    contexts = parser_contexts()
    assert NOT_DISPATCHED <= set(contexts), "a context listed above left the grammar"
    tables = (Builder._STATEMENTS, Builder._PRIMARIES)
    handled = {name for name, c in contexts.items()
               if any(t.registered(c) is not None for t in tables)}
    assert handled == set(contexts) - NOT_DISPATCHED


def test_every_alternative_of_statement_and_primary_has_its_table():
    from autolev._antlr.AutolevParser import AutolevParser as P
    from autolev.irbuild import Builder
    contexts = parser_contexts()
    # statement's alternatives are the rules StatementContext has accessors for
    statements = [c for name, c in contexts.items()
                  if name[0].lower() + name[1:-len("Context")] in vars(P.StatementContext)]
    assert len(statements) == 15
    assert all(Builder._STATEMENTS.registered(c) for c in statements)
    primaries = [c for c in contexts.values() if issubclass(c, P.PrimaryContext)
                 and c is not P.PrimaryContext]
    assert len(primaries) == 9
    assert all(Builder._PRIMARIES.registered(c) for c in primaries)


# -- a node nobody handles is a diagnostic ------------------------------------------------
def test_an_unknown_ir_expression_or_statement_is_a_translation_diagnostic():
    from dataclasses import dataclass, replace

    import autolev
    from autolev import ir
    from autolev.translate import translate

    @dataclass(frozen=True)
    class Wobble(ir.Expr):
        pass

    @dataclass(frozen=True)
    class Pause(ir.Statement):
        kind = "pause"

    program = autolev.parse("CONSTANTS A\nX = A + 1\nY = A\n", "m.al")
    assignment = program.statements[1]
    wobble = Wobble(span=assignment.value.span)
    program.statements[1] = replace(assignment, value=ir.BinOp("+", wobble, ir.Number("1")))
    program.statements.append(Pause(span=assignment.span))
    result = translate(program)
    errors = [(d.line, d.code, d.message) for d in result.diagnostics]
    assert errors == [(2, "T006", "Wobble expressions are not supported yet"),
                      (2, "T006", "pause statements are not supported yet")]
    assert "Y = A" in result.code


@pytest.mark.parametrize("table, text", [("_STATEMENTS", "X = 1"), ("_PRIMARIES", "X = 1")])
def test_an_unknown_parse_tree_context_is_a_syntax_diagnostic(monkeypatch, table, text):
    from helpers import errors_of

    from autolev.irbuild import Builder
    fallback = getattr(Builder, table).fallback
    monkeypatch.setattr(Builder, table, Dispatch("nothing registered", fallback))
    (d,) = errors_of(text + "\n")
    assert d.code == "E007" and "not supported yet" in d.message
    assert (d.line, d.col) == (1, 1 if table == "_STATEMENTS" else 5)
