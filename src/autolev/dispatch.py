"""Choosing a handler by the class of a node: one `Dispatch` table per pass.

Every pass over IR nodes (the translator's statements and expressions, the walks of
`ir`) and over ANTLR parse-tree contexts (the IR builder) keeps its handlers in a
table made here:

    STATEMENTS = Dispatch("translator statements", unsupported_statement)

    @STATEMENTS.register(ir.Assignment)
    def assignment(tr, st): ...

    STATEMENTS.lookup(type(st))(tr, st)

A handler registered for a class also handles its subclasses (the lookup follows the
class's MRO, nearest class first).  A class with no handler anywhere in its MRO gets the
fallback named when the table was made, which reports the node (a diagnostic in the
translator and the builder), so a new node class is never an AttributeError or KeyError.

`lookup` returns the handler and the caller calls it: a table adds no Python frame to
a recursion (an expression nested hundreds deep stays within Python's limit).
"""
from __future__ import annotations

from typing import Any, Callable, Generic, TypeVar

H = TypeVar("H", bound=Callable[..., Any])


class Dispatch(Generic[H]):
    """Handlers of one pass, keyed by node class, with a fallback for the rest."""

    def __init__(self, what: str, fallback: H) -> None:
        self.what = what                    # names the pass in errors about the table
        self.fallback = fallback
        self._handlers: dict[type, H] = {}
        # lookups along the MRO, remembered (the expression passes are hot paths)
        self._found: dict[type, H] = {}

    def register(self, *classes: type) -> Callable[[H], H]:
        """Decorator: the function handles nodes of `classes` and of their subclasses."""
        def add(fn: H) -> H:
            for cls in classes:
                if cls in self._handlers:
                    raise ValueError(f"{self.what}: {cls.__name__} has a handler already")
                self._handlers[cls] = fn
            self._found.clear()
            return fn
        return add

    def registered(self, cls: type) -> H | None:
        """The handler registered for `cls` or its nearest base; None if there is none."""
        return next((self._handlers[c] for c in cls.__mro__ if c in self._handlers), None)

    def lookup(self, cls: type) -> H:
        """The handler for nodes of class `cls`: the registered one, else the fallback."""
        fn = self._found.get(cls)
        if fn is None:
            fn = self._found[cls] = self.registered(cls) or self.fallback
        return fn
