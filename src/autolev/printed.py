"""Autolev's printed responses read fast.

A response that is plain arithmetic (numbers, names with primes, vectors, calls, + - * /
^ and parentheses) is read here into the IR the grammar's builder makes of it; anything
else gives None and is read by the grammar.  The grammar's Python runtime reads about
40 KB a second, and a 3-D gait model prints 7 MB of Z's: minutes, where this takes
seconds.  tests/test_printed.py holds the two readers to the same trees, on every
response of the corpus's transcripts and on generated arithmetic.

The precedences are the grammar's (grammar/Autolev.g4, `expr`): ^ (right-associated)
binds tighter than a sign, a sign tighter than * and /, those tighter than + and -; the
operand of a sign takes only powers (-X^2 is -(X^2), -A*B is (-A)*B).
"""
from __future__ import annotations

import functools
import re

from . import ir
from .errors import Span

# a number as the lexer reads it; a vector or dyadic name; a name; one-character tokens
_TOKEN = re.compile(r"""[ \t]*(?:
    (?P<number>(?:[0-9]+\.[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?|[0-9]+(?:[eE][+-]?[0-9]+)?)
  | (?P<vector>(?:[A-Za-z_][A-Za-z0-9_]*|[01])>>?)
  | (?P<name>[A-Za-z_][A-Za-z0-9_]*)
  | (?P<mark>[-+*/^(),'])
  )""", re.VERBOSE)
_END = re.compile(r"[ \t]*\Z")

# levels of the binary operators; a sign's operand takes only operators above _SIGN
_LEVEL = {"+": 1, "-": 1, "*": 2, "/": 2, "^": 4}
_SIGN = 3
_MAX_NUMBER_CHARACTERS = 400      # irbuild.MAX_NUMBER_DIGITS: longer ones are refused there


class _NotPlain(Exception):
    """The text is not plain arithmetic: the grammar reads it."""


@functools.cache
def _plain_name(word: str) -> bool:
    """Whether the lexer reads `word` as a name (ID), not as one of its keywords."""
    from antlr4 import InputStream

    from ._antlr.AutolevLexer import AutolevLexer
    lexer = AutolevLexer(InputStream(word))
    lexer.removeErrorListeners()
    tokens = lexer.getAllTokens()
    return len(tokens) == 1 and tokens[0].type == AutolevLexer.ID


def _tokens(text: str) -> list[tuple[str, str, int]]:
    """(kind, text, end offset) of each token; _NotPlain at anything else."""
    out, at = [], 0
    while not _END.match(text, at):
        m = _TOKEN.match(text, at)
        if m is None:
            raise _NotPlain
        kind = m.lastgroup
        out.append((kind, m.group(kind), m.start(kind)))
        at = m.end()
    return out


class _Reader:
    """One response's tokens read into IR, every node carrying the response's span."""

    def __init__(self, tokens: list, span: Span):
        self.tokens = tokens
        self.at = 0
        self.span = span

    def peek(self) -> tuple[str, str, int] | None:
        return self.tokens[self.at] if self.at < len(self.tokens) else None

    def skip(self, mark: str) -> bool:
        """Consume `mark` when it is the next token; whether it was."""
        token = self.peek()
        if token is not None and token[0] == "mark" and token[1] == mark:
            self.at += 1
            return True
        return False

    def take(self, mark: str) -> None:
        if not self.skip(mark):
            raise _NotPlain

    def expr(self, level: int = 1) -> ir.Expr:
        left = self.operand()
        while True:
            token = self.peek()
            if token is None or token[0] != "mark" or token[1] not in _LEVEL:
                return left
            op = token[1]
            if _LEVEL[op] < level:
                return left
            self.at += 1
            # ^ associates to the right; + - * / to the left
            right = self.expr(_LEVEL[op] if op == "^" else _LEVEL[op] + 1)
            left = ir.BinOp(op, left, right, span=self.span)

    def operand(self) -> ir.Expr:
        token = self.peek()
        if token is None:
            raise _NotPlain
        kind, text, start = token
        self.at += 1
        if kind == "mark" and text in "+-":
            inner = self.expr(_SIGN)
            return inner if text == "+" else ir.Neg(inner, span=self.span)
        if kind == "mark" and text == "(":
            inner = self.expr()
            self.take(")")
            return inner
        if kind == "number":
            if len(text) > _MAX_NUMBER_CHARACTERS:
                raise _NotPlain
            return ir.Number(text, span=self.span)
        if kind == "vector":
            name = text.rstrip(">")
            if name not in ("0", "1") and not _plain_name(name):
                raise _NotPlain
            return ir.VectorName(name, text.endswith(">>"), span=self.span)
        if kind != "name" or not _plain_name(text):
            raise _NotPlain
        if self.skip("("):
            args = []
            if not self.skip(")"):
                args.append(self.expr())
                while self.skip(","):
                    args.append(self.expr())
                self.take(")")
            return ir.Call(text, tuple(args), span=self.span)
        primes, end = 0, start + len(text)
        while (following := self.peek()) is not None and following[:2] == ("mark", "'"):
            if following[2] != end:       # a prime must follow the name directly
                raise _NotPlain
            primes, end = primes + 1, end + 1
            self.at += 1
        return ir.Name(text, primes, span=self.span)


def read_plain(target: str, value: str, span: Span) -> tuple[ir.Expr, ir.Expr] | None:
    """(target, value) of the response `target = value` as the grammar's builder would
    read them, when the target is a name (with primes) and the value plain arithmetic;
    else None."""
    try:
        reader = _Reader(_tokens(target), span)
        name = reader.operand()
        if not isinstance(name, ir.Name) or reader.peek() is not None:
            return None
        reader = _Reader(_tokens(value), span)
        expression = reader.expr()
        if reader.peek() is not None:
            return None
    except (_NotPlain, RecursionError):
        return None
    return name, expression
