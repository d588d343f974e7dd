"""The ANTLR driver: lex mapped text, parse it one logical line at a time, and turn
ANTLR's errors into our own diagnostics (no ANTLR message text reaches the user).

Each logical line (the tokens between two NL tokens) is parsed on its own with the
`singleLine` rule, so one bad statement gives one precise diagnostic and the rest of
the file is still checked.
"""
from __future__ import annotations

import difflib

from dataclasses import dataclass

from antlr4 import CommonTokenStream, InputStream, Token
from antlr4.error.ErrorListener import ErrorListener
from antlr4.error.ErrorStrategy import BailErrorStrategy
from antlr4.error.Errors import ParseCancellationException, RecognitionException
from antlr4.ListTokenSource import ListTokenSource
from antlr4.atn.PredictionMode import PredictionMode

from ._antlr.AutolevLexer import AutolevLexer
from ._antlr.AutolevParser import AutolevParser
from .errors import Diagnostic
from .source import MappedText

KNOWN_SETTINGS = ("AUTOZ", "AUTORHS", "AUTOEPSILON", "AUTOEXPRESS", "COMPLEX", "DEGREES",
                  "DIGITS", "FACTORING", "OVERWRITE", "BEEPSOUND", "PAUSE")

_P = AutolevParser
_KEYWORDS = {getattr(_P, n) for n in (
    "NEWTONIAN", "FRAMES", "BODIES", "PARTICLES", "POINTS", "CONSTANTS", "VARIABLES",
    "MOTIONVARIABLES", "SPECIFIED", "IMAGINARY", "MASS", "INERTIA", "INPUT", "OUTPUT",
    "UNITS", "UNITSYSTEM", "CODE", "SAVE", "ENCODE", "RUN", "EXIT", "QUIT",
    *KNOWN_SETTINGS)}
_WORDS = _KEYWORDS | {_P.ID}
# the words a statement can begin with (for "did you mean" on a misspelt one)
_STATEMENT_WORDS = ("NEWTONIAN", "FRAMES", "BODIES", "PARTICLES", "POINTS", "CONSTANTS",
                    "VARIABLES", "MOTIONVARIABLES", "SPECIFIED", "IMAGINARY", "MASS",
                    "INERTIA", "INPUT", "OUTPUT", "UNITS", "UNITSYSTEM", "CODE", "SAVE",
                    "ENCODE", "RUN", "EXIT", *KNOWN_SETTINGS)
_EXPRESSION_START = {_P.ID, _P.INT, _P.FLOAT, _P.LPAREN, _P.MINUS}
_STATEMENT_START = {_P.ID, _P.NEWTONIAN, _P.INPUT}
_DESCRIPTIONS = {
    _P.ID: "a name", _P.INT: "a number", _P.FLOAT: "a number", _P.VECNAME: "a vector",
    _P.NL: "end of line", Token.EOF: "end of line",
}


@dataclass
class LogicalLine:
    tree: AutolevParser.SingleLineContext
    tokens: list[Token]


@dataclass
class ParsedText:
    mapped: MappedText
    lines: list[LogicalLine]
    diagnostics: list[Diagnostic]


class _Bail(BailErrorStrategy):
    """Stop at the first error of a line; we write the message ourselves."""

    def reportError(self, recognizer, e):  # noqa: N802 (ANTLR's name)
        pass


class _LexerErrors(ErrorListener):
    def __init__(self) -> None:
        self.offsets: list[int] = []

    def syntaxError(self, recognizer, offendingSymbol, line, column, msg, e):  # noqa: N802
        self.offsets.append(recognizer._tokenStartCharIndex)


def _token_name(ttype: int) -> str:
    if ttype in _DESCRIPTIONS:
        return _DESCRIPTIONS[ttype]
    if ttype in _KEYWORDS:
        return _P.symbolicNames[ttype]
    lit = _P.literalNames[ttype] if ttype < len(_P.literalNames) else "<INVALID>"
    if lit != "<INVALID>":
        return lit
    return _P.symbolicNames[ttype]


def describe_expected(types: set[int], at_start: bool = False) -> str:
    """'an expression or ')'', 'a name', ... from a set of token types."""
    if not types:
        return ""
    parts: list[str] = []
    rest = set(types)
    if at_start and _STATEMENT_START <= rest:
        return "a statement"
    if _EXPRESSION_START <= rest:
        parts.append("an expression")
        rest -= _EXPRESSION_START | {_P.PLUS, _P.VECNAME, _P.LBRACK} | _KEYWORDS
    elif _P.ID in rest:
        parts.append("a name")
        rest -= _WORDS
    if _P.INT in rest or _P.FLOAT in rest:
        parts.append("a number")
        rest -= {_P.INT, _P.FLOAT}
    names = sorted({_token_name(t) for t in rest}, key=lambda s: (len(s) > 3, s))
    parts.extend(names)
    if len(parts) > 6:
        parts = parts[:6] + ["..."]
    if len(parts) == 1:
        return parts[0]
    return ", ".join(parts[:-1]) + " or " + parts[-1]


def _expected_of(error: RecognitionException | None) -> set[int]:
    if error is None:
        return set()
    try:
        expected = set(error.getExpectedTokens() or [])
    except (TypeError, AttributeError, IndexError):   # no ATN state to ask
        return set()
    expected.discard(Token.EPSILON)
    return expected


def _shown(token: Token) -> str:
    if token.type == Token.EOF:
        return "end of line"
    text = token.text
    if len(text) > 30:
        text = text[:27] + "..."
    return f"'{text}'"


class Parser:
    """Parses mapped text into logical lines; reusable."""

    def __init__(self) -> None:
        self._parser = AutolevParser(CommonTokenStream(ListTokenSource([])))
        self._parser.removeErrorListeners()
        self._parser._errHandler = _Bail()
        self._parser._interp.predictionMode = PredictionMode.SLL

    def parse(self, mapped: MappedText) -> ParsedText:
        lexer = AutolevLexer(InputStream(mapped.text))
        lexer.removeErrorListeners()
        lex_errors = _LexerErrors()
        lexer.addErrorListener(lex_errors)
        tokens = lexer.getAllTokens()

        diagnostics: list[Diagnostic] = []
        bad_offsets = sorted(set(lex_errors.offsets))
        first_per_line: dict[int, int] = {}
        for off in bad_offsets:   # one report per line: the first bad character
            first_per_line.setdefault(mapped.text.count("\n", 0, off), off)
        for off in first_per_line.values():
            ch = mapped.text[off] if off < len(mapped.text) else ""
            shown = (repr(ch) if ch.isprintable() and ch not in "'\""
                     else f"U+{ord(ch):04X}" if ch else "?")
            if ch == "#":
                msg = ("unexpected character '#' (macro placeholders #1#, #2#... are only "
                       "replaced in a .a file called as a macro)")
            elif ch == "&":
                msg = "'&' continues a statement only at the end of a line"
            elif ch == ">":
                msg = "unexpected '>': a vector name is a name followed directly by '>' or '>>'"
            else:
                msg = f"unexpected character {shown}"
            diagnostics.append(self._diagnostic(mapped, off, "E001", msg))

        lines: list[LogicalLine] = []
        chunk: list[Token] = []
        for tok in tokens + [None]:
            if tok is not None and tok.type != AutolevLexer.NL:
                chunk.append(tok)
                continue
            if chunk:
                lo, hi = chunk[0].start, chunk[-1].stop
                if not any(lo <= o <= hi + 1 for o in bad_offsets):
                    line = self._parse_line(mapped, chunk, diagnostics)
                    if line is not None:
                        lines.append(line)
            chunk = []
        return ParsedText(mapped, lines, diagnostics)

    def _parse_line(self, mapped: MappedText, chunk: list[Token],
                    diagnostics: list[Diagnostic]) -> LogicalLine | None:
        p = self._parser
        for mode in (PredictionMode.SLL, PredictionMode.LL):
            p.setTokenStream(CommonTokenStream(ListTokenSource(list(chunk))))
            p._interp.predictionMode = mode
            try:
                tree = p.singleLine()
                return LogicalLine(tree, chunk)
            except ParseCancellationException as exc:
                error = exc.args[0] if exc.args else None
            except RecursionError:
                diagnostics.append(self._diagnostic(
                    mapped, chunk[0].start, "E004",
                    "this statement is nested too deeply to read"))
                return None
        diagnostics.append(self._syntax_diagnostic(mapped, chunk, error))
        return None

    def _furthest_failure(self, chunk: list[Token]) -> tuple[Token, set[int]] | None:
        """Where the statement rules that could apply stop, and what they expected there.

        At the start of a line the parser only knows that no statement matches; trying
        the likely statement rules one by one tells how far the line made sense."""
        p = self._parser
        best: tuple[int, Token, set[int]] | None = None
        for rule in (p.assignment, p.expressionStatement):
            p.setTokenStream(CommonTokenStream(ListTokenSource(list(chunk))))
            p._interp.predictionMode = PredictionMode.LL
            try:
                rule()
                stop = p.getCurrentToken()
                expected = {Token.EOF}
            except ParseCancellationException as exc:
                error = exc.args[0] if exc.args else None
                stop = getattr(error, "offendingToken", None)
                if stop is None:
                    continue
                expected = _expected_of(error)
            except RecursionError:
                continue
            index = next((i for i, t in enumerate(chunk) if t is stop), len(chunk))
            if best is None or index > best[0]:
                best = (index, stop, expected)
        return None if best is None else (best[1], best[2])

    def _syntax_diagnostic(self, mapped: MappedText, chunk: list[Token],
                           error: RecognitionException | None) -> Diagnostic:
        offending = getattr(error, "offendingToken", None) or chunk[-1]
        expected = _expected_of(error)
        notes: list[str] = []
        start = getattr(error, "startToken", None)
        if start is not None and start is chunk[0] and offending is not chunk[0]:
            refined = self._furthest_failure(chunk)
            if refined is not None:
                offending, expected = refined
            else:
                expected = set()
        index = next((i for i, t in enumerate(chunk) if t is offending), len(chunk))

        if offending.type == Token.EOF or index >= len(chunk):
            offset = chunk[-1].stop + 1
            msg = "unexpected end of line"
            if expected - {Token.EOF}:
                msg += f"; expected {describe_expected(expected - {Token.EOF})}"
            depth = sum(1 for t in chunk if t.type in (_P.LPAREN, _P.LBRACK)) - \
                sum(1 for t in chunk if t.type in (_P.RPAREN, _P.RBRACK))
            if depth > 0:
                notes.append("a statement continued on the next line needs '&' at the "
                             "end of this line")
            return self._diagnostic(mapped, offset, "E003", msg, notes)

        offset = offending.start
        if (index == 1 and chunk[0].type == _P.ID
                and offending.type in _WORDS | {_P.INT, _P.FLOAT}):
            msg = f"unknown setting or command '{chunk[0].text}'"
            close = difflib.get_close_matches(chunk[0].text.upper(), _STATEMENT_WORDS,
                                              n=1, cutoff=0.75)
            if close:
                msg += f"; did you mean {close[0]}?"
            notes.append("known settings: " + ", ".join(KNOWN_SETTINGS))
            notes.append("if this is an assignment, '=' is missing")
            return self._diagnostic(mapped, chunk[0].start, "E010", msg, notes)
        msg = f"unexpected {_shown(offending)}"
        if expected:
            msg += f"; expected {describe_expected(expected, at_start=index == 0)}"
        return self._diagnostic(mapped, offset, "E002", msg, notes)

    @staticmethod
    def _diagnostic(mapped: MappedText, offset: int, code: str, message: str,
                    notes: list[str] | None = None) -> Diagnostic:
        return Diagnostic(mapped.locate(offset), code, message, "error",
                          mapped.source_line(offset), tuple(notes or ()))
