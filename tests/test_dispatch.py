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
