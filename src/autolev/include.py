"""The include stage: a model's statements in the order Autolev runs them, with every
`RUN file`, user macro call (NAME.A) and user function (NAME.R) read, expanded and
parsed here, so the IR builder takes one stream of parsed statements and never goes
back to the files.

Each `Piece` is one statement's parse tree with the text it was parsed from.  A RUN or
a macro call comes as its own piece (its `expansion` says what it brought in, or that
it was refused after a diagnostic) followed by the pieces of the included text.  User
functions sit inside expressions, so their parsed bodies travel with the piece whose
statement calls them (`Piece.functions`, keyed by the call's parse-tree node).

Rules (docs/language.md, "RUN, macros and user functions"): a statement that is only
a call NAME(args), where NAME.A is next to the calling file or the model, is a macro
call; NAME(args) anywhere in an expression, where NAME.R is, is a user function (it
wins over a macro of the same name); #k# in either file stands for the text of the
k-th argument.
"""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterator

from antlr4 import ParserRuleContext
from antlr4.tree.Tree import TerminalNode

from ._antlr.AutolevParser import AutolevParser as P
from .engine.reading import names_with_suffix
from .errors import Diagnostic
from .source import (MAX_INCLUDE_DEPTH, MappedText, RunRefused, SourceFile, expand_macro,
                     find_macro, is_within, mapped_source, placeholders, resolve_run)
from .syntax import ParsedText, Parser


# the most text and statements a model expands to with its RUN files, macros and
# functions (the largest corpus model: 23 KB, 310 statements); beyond, files that include
# each other many times would take minutes and gigabytes
MAX_EXPANDED_BYTES = 1_000_000
MAX_EXPANDED_STATEMENTS = 20_000


def statement_starts(text: str) -> list[int]:
    """The offsets of the lines of `text` (continuations joined) that hold code."""
    starts, offset = [], 0
    for line in text.splitlines(keepends=True):
        if line.split("%", 1)[0].strip():
            starts.append(offset)
        offset += len(line)
    return starts


@dataclass(frozen=True)
class Origin:
    """The text a parse tree was read from and the file it belongs to."""

    mapped: MappedText
    path: Path | None
    display: str


@dataclass(frozen=True)
class Expansion:
    """What a RUN statement or a macro call brought in; `path` is None when it was
    refused (its diagnostic is already given)."""

    name: str
    args: tuple[str, ...] = ()
    path: Path | None = None


@dataclass(frozen=True)
class FunctionBody:
    """The expression a user function call stands for, parsed from its NAME.R."""

    expr: P.ExprContext
    origin: Origin


# a user function's call whose body was refused, after its diagnostic (a file leading
# outside, an argument missing, recursion, the size limit): nothing more to say of it
REFUSED = "refused"


@dataclass
class Piece:
    """One statement of the expanded model."""

    statement: P.StatementContext
    origin: Origin
    expansion: Expansion | None = None
    # each user function's call: its body, or REFUSED
    functions: dict[ParserRuleContext, FunctionBody | str] = field(default_factory=dict)


class Includes:
    """Reads a model and everything it includes, statement by statement; collects the
    files read (`files`, `sources`) and the diagnostics of reading them."""

    def __init__(self, filename: str, path: Path | None, parser: Parser | None = None,
                 reserved: frozenset[str] = frozenset(), folder: Path | None = None):
        """`reserved`: Autolev's own commands and functions (upper case), which a file
        of the same name beside the model does not replace; `folder`: the model's folder
        (its macros, functions and RUN files) when not `path`'s (a session kept apart)."""
        self.filename = filename
        self.reserved = reserved
        self.root_path = path.resolve() if path is not None else None
        self.model_root = Path(folder).resolve() if folder is not None else \
            self.root_path.parent if self.root_path is not None else None
        self.parser = parser or Parser()
        self.diagnostics: list[Diagnostic] = []
        self.files: list[str] = [filename]
        self.sources: dict[str, list[str]] = {}
        self._stack: list[Path] = [self.root_path] if self.root_path else []
        self._function_files: dict[tuple[str, Path | None], Path | None] = {}
        self._function_names: dict[Path, frozenset[str]] = {}
        # parsed texts by their text: a file included many times is parsed once (its
        # trees' offsets hold for every inclusion, each located by its own mapping)
        self._parsed: dict[str, ParsedText] = {}
        self._read_files: dict[str, SourceFile] = {}       # by display name
        self._run_targets: dict[tuple[Path | None, str], Path] = {}
        self._expanded_bytes = 0
        self._expanded_statements = 0
        self._exhausted = False             # the budget is spent: nothing more is read

    # -- entry points ------------------------------------------------------------
    def model(self, src: SourceFile) -> Iterator[Piece]:
        """The statements of a model file, with its inclusions in place."""
        self.sources[src.name] = src.lines
        return self._pieces(mapped_source(src), self.root_path, src.name)

    def macro_file(self, src: SourceFile) -> Iterator[Piece]:
        """A macro file read on its own (for `check`): each #k# stands for a name ARGk."""
        used = placeholders(src)
        args = [f"ARG{k}" for k in range(1, max(used, default=0) + 1)]
        return self._pieces(expand_macro(src, args, None, ""), self.root_path, src.name)

    # -- the stream ----------------------------------------------------------------
    def _pieces(self, mapped: MappedText, path: Path | None, display: str) -> Iterator[Piece]:
        origin = Origin(mapped, path, display)
        # the budget is judged before parsing: a parse holds some 500 bytes a byte of text
        if not self._spend(origin, len(mapped.text), statement_starts(mapped.text)):
            return
        for line in self._parse(mapped).lines:
            body = line.tree.statementLine()
            if body is None:
                continue
            calls = self._may_call_functions(line.tokens, path)
            for statement in body.statement():
                piece = Piece(statement, origin)
                if calls:
                    self._find_functions(statement, origin, piece.functions)
                node = statement.getChild(0)
                if isinstance(node, P.RunStatementContext):
                    yield from self._run(piece, node)
                elif (macro := self._macro_call(node, path, piece)) is not None:
                    yield from self._macro(piece, *macro)
                else:
                    yield piece

    def _parse(self, mapped: MappedText) -> ParsedText:
        """The parsed text, its diagnostics given the first time it is read."""
        parsed = self._parsed.get(mapped.text)
        if parsed is None:
            parsed = self._parsed[mapped.text] = self.parser.parse(mapped)
            self.diagnostics.extend(parsed.diagnostics)
        return parsed

    def _spend(self, origin: Origin, size: int, starts: list[int]) -> bool:
        """Count a text of `size` bytes whose statements start at `starts` (offsets in
        `origin`: a function's body counts at its call) against the model's budget;
        False, after the one diagnostic naming the chain of files, when it is spent."""
        if self._exhausted:
            return False
        self._expanded_bytes += size
        room = MAX_EXPANDED_STATEMENTS - self._expanded_statements
        self._expanded_statements += len(starts)
        if self._expanded_bytes <= MAX_EXPANDED_BYTES and len(starts) <= room:
            return True
        offset = starts[min(room, len(starts) - 1)] if starts else 0
        self._exhausted = True
        chain = " -> ".join(os.path.relpath(p, self.model_root) for p in self._stack) \
            if self.model_root is not None else origin.display
        self.diagnostics.append(Diagnostic(
            origin.mapped.locate(offset), "E033",
            f"the model with its RUN files, macros and functions expands to more than "
            f"{MAX_EXPANDED_BYTES // 10 ** 6} MB of text or {MAX_EXPANDED_STATEMENTS} "
            f"statements (here: {chain}); files that include each other many times? "
            "Nothing more is read", "error", origin.mapped.source_line(offset)))
        return False

    def _search_dirs(self, path: Path | None) -> list[Path]:
        dirs = [path.parent] if path is not None else []
        return dirs + ([self.model_root] if self.model_root is not None else [])

    def _display_name(self, found: Path) -> str:
        rel = os.path.relpath(found, self.model_root)
        return os.path.join(os.path.dirname(self.filename), rel)

    def _error(self, origin: Origin, ctx, code: str, message: str) -> None:
        offset = ctx.start.start
        self.diagnostics.append(Diagnostic(origin.mapped.locate(offset), code, message, "error",
                                           origin.mapped.source_line(offset)))

    # -- RUN -----------------------------------------------------------------------
    def _run(self, piece: Piece, ctx: P.RunStatementContext) -> Iterator[Piece]:
        origin = piece.origin
        name = origin.mapped.slice(ctx.fileName().start.start, ctx.fileName().stop.stop + 1)
        found = self._run_target(origin, ctx.fileName(), name)
        piece.expansion = Expansion(name, path=found)
        yield piece
        if found is None:
            return
        display = self._display_name(found)
        src = self._read(found, display)
        where = origin.mapped.locate(ctx.start.start)
        self._stack.append(found)
        yield from self._pieces(mapped_source(src, where, f"the file included by RUN {name}"),
                                found, display)
        self._stack.pop()

    def _read(self, found: Path, display: str) -> SourceFile:
        """A file to include, read once however often it is included."""
        if display not in self._read_files:
            self._read_files[display] = SourceFile.read(found, display)
            self.files.append(display)
            self.sources[display] = self._read_files[display].lines
        return self._read_files[display]

    def _run_target(self, origin: Origin, ctx: P.FileNameContext, name: str) -> Path | None:
        """The file `RUN name` includes; None, after its diagnostic, when there is none."""
        key = (origin.path, name)
        found = self._run_targets.get(key) or self._find_run_target(origin, ctx, name)
        if found is None:
            return None
        self._run_targets[key] = found      # a file found once is not looked for again
        if found in self._stack:
            self._error(origin, ctx, "E023", f"RUN {name}: the file includes itself")
            return None
        if len(self._stack) >= MAX_INCLUDE_DEPTH:
            self._error(origin, ctx, "E024", f"RUN {name}: files nested deeper than "
                        f"{MAX_INCLUDE_DEPTH} levels")
            return None
        return found

    def _find_run_target(self, origin: Origin, ctx: P.FileNameContext,
                         name: str) -> Path | None:
        """Where `RUN name` leads from the file `origin`, resolved, or None after why."""
        if origin.path is None or self.model_root is None:
            self._error(origin, ctx, "E020", f"RUN {name}: a model given as text has no "
                        "folder to look in; parse the file itself, or pass filename=")
            return None
        try:
            found = resolve_run(name, origin.path, self.model_root)
        except RunRefused:
            self._error(origin, ctx, "E021", f"RUN {name}: refused, the path leaves the "
                        f"model's folder ({self.model_root})")
            return None
        if found is None:
            self._error(origin, ctx, "E022", f"RUN {name}: no such file next to the model "
                        f"(looked in {origin.path.parent} and the folders above it)")
            return None
        return found.resolve()

    # -- macros --------------------------------------------------------------------
    def _macro_call(self, node, path: Path | None,
                    piece: Piece) -> tuple[P.CallAtomContext, Path] | None:
        """The call of a statement that is only NAME(args), and the NAME.A it expands."""
        if self.model_root is None or not isinstance(node, P.ExpressionStatementContext):
            return None
        primary = node.expr().getChild(0)
        if not isinstance(primary, P.CallAtomContext) or primary in piece.functions:
            return None
        found = find_macro(primary.start.text, self._search_dirs(path))
        if found is None or self._builtin(piece.origin, primary, found, "command"):
            return None
        return primary, found

    def _builtin(self, origin: Origin, call: P.CallAtomContext, found: Path,
                 what: str) -> bool:
        """Whether the called name is Autolev's own (its file then unread, said so)."""
        name = call.start.text
        if name.upper() not in self.reserved:
            return False
        offset = call.start.start
        self.diagnostics.append(Diagnostic(
            origin.mapped.locate(offset), "W106",
            f"{self._display_name(found.resolve())} has the name of Autolev's own {what} "
            f"{name.upper()}: the {what} is meant here, the file is not read (rename the "
            "file to call it)", "warning", origin.mapped.source_line(offset)))
        return True

    def _macro(self, piece: Piece, call: P.CallAtomContext, found: Path) -> Iterator[Piece]:
        origin = piece.origin
        name = call.start.text
        args = self._args(call, origin)
        got = self._expansion_source(origin, call, "macro", name, found, args)
        piece.expansion = Expansion(name, tuple(args), got[0] if got else None)
        yield piece
        if got is None:
            return
        found, src, display = got
        where = origin.mapped.locate(call.start.start)
        what = f"macro {name}({', '.join(args)})"
        self._stack.append(found)
        yield from self._pieces(expand_macro(src, args, where, what), found, display)
        self._stack.pop()

    @staticmethod
    def _args(call: P.CallAtomContext, origin: Origin) -> list[str]:
        arg_ctxs = call.argList().arg() if call.argList() else []
        return [origin.mapped.slice(a.start.start, a.stop.stop + 1).strip() for a in arg_ctxs]

    def _expansion_source(self, origin: Origin, ctx, what: str, name: str, found: Path,
                          args: list[str], own_text: bool = True
                          ) -> tuple[Path, SourceFile, str] | None:
        """(path, source, display name) of the macro or function file `found` for a call
        with `args`, read and registered; None, after its diagnostic, when the file
        leads outside the model's folder, wants more arguments, or calls itself.  A call
        that is not the file's `own_text` (it came in as an argument: F(F(X))) is the
        caller's, not a call of the function in whose body it now stands."""
        link = found
        found = found.resolve()
        if not is_within(found, self.model_root):
            self._error(origin, ctx, "E025", f"{what} {name}: refused, its file "
                        f"{self._display_name(link)} leads outside the model's folder "
                        f"({self.model_root}), through a link")
            return None
        display = self._display_name(found)
        src = self._read(found, display)
        used = placeholders(src)
        if used and max(used) > len(args):
            self._error(origin, ctx, "E030", f"{what} {name} ({display}) uses #{max(used)}# "
                        f"but this call gives {len(args)} argument"
                        f"{'s' if len(args) != 1 else ''}")
            return None
        if (own_text and found in self._stack) or len(self._stack) >= MAX_INCLUDE_DEPTH:
            self._error(origin, ctx, "E031", f"{what} {name} calls itself (directly or through "
                        f"other {what}s)")
            return None
        return found, src, display

    # -- user functions --------------------------------------------------------------
    def _may_call_functions(self, tokens, path: Path | None) -> bool:
        """Whether a line names a NAME.R file at all (most models have none): only then
        are its parse trees searched for calls."""
        if self.model_root is None:
            return False
        names = frozenset().union(*(self._function_names_in(d) for d in self._search_dirs(path)))
        return bool(names) and any(t.type == P.ID and t.text.lower() in names for t in tokens)

    def _function_names_in(self, folder: Path) -> frozenset[str]:
        if folder not in self._function_names:
            self._function_names[folder] = names_with_suffix(folder, ".r")
        return self._function_names[folder]

    def _find_functions(self, tree, origin: Origin,
                        found: dict[ParserRuleContext, FunctionBody | str]) -> None:
        """Parse the body of every user function called in `tree` (and in those bodies)."""
        todo = [tree]
        while todo:
            node = todo.pop()
            if isinstance(node, TerminalNode) or node.children is None:
                continue
            if isinstance(node, P.CallAtomContext):
                body = self._function_body(node, origin)
                if body is REFUSED:
                    found[node] = REFUSED
                    continue
                if body is not None:   # its arguments are read again inside the body
                    found[node] = body
                    self._stack.append(body.origin.path)
                    self._find_functions(body.expr, body.origin, found)
                    self._stack.pop()
                    continue
            todo.extend(node.children)

    def _function_body(self, call: P.CallAtomContext, origin: Origin) -> FunctionBody | str | None:
        """The call's body; None when it is no user function's; REFUSED after the
        diagnostic of one that cannot be expanded."""
        name = call.start.text
        key = (name.lower(), origin.path.parent if origin.path is not None else None)
        if key not in self._function_files:
            self._function_files[key] = find_macro(name, self._search_dirs(origin.path), ".r")
        if self._function_files[key] is None or \
                self._builtin(origin, call, self._function_files[key], "function"):
            return None
        args = self._args(call, origin)
        got = self._expansion_source(origin, call, "function", name, self._function_files[key],
                                     args, not origin.mapped.substituted(call.start.start))
        if got is None:
            return REFUSED
        found, src, display = got
        where = origin.mapped.locate(call.start.start)
        mapped = expand_macro(src, args, where, f"function {name}({', '.join(args)})")
        if not self._spend(origin, len(mapped.text), [call.start.start]):
            return REFUSED
        parsed = self._parse(mapped)
        bodies = [st.getChild(0) for line in parsed.lines
                  if line.tree.statementLine() is not None
                  for st in line.tree.statementLine().statement()]
        if len(bodies) != 1 or not isinstance(bodies[0], P.ExpressionStatementContext):
            if not parsed.diagnostics:
                self._error(origin, call, "E032", f"function {name} ({display}) must hold one "
                            f"expression, not {len(bodies)} statements")
            return REFUSED
        return FunctionBody(bodies[0].expr(), Origin(mapped, found, display))
