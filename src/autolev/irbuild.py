"""From parse trees to the IR: statements with spans, expressions, the symbol table.

The statements come from the include stage (`include.py`), with RUN files, macros
and user functions already read and parsed; every span points into the file its
text came from and back to the statement that brought it in.

Over 600 lines on purpose: one `Builder` is one walk of a parse tree, its statement and
expression handlers sharing the symbol table, the diagnostics and the spans; split, each
half would reach into the other's state.
"""
from __future__ import annotations

import contextlib
import gc
import itertools
from pathlib import Path
from typing import Any, Callable, Iterable

from antlr4 import Token
from antlr4.tree.Tree import TerminalNode

from . import ir
from ._antlr.AutolevParser import AutolevParser as P
from .dispatch import Dispatch
from .errors import Diagnostic, Location, Span
from .include import REFUSED, Includes, Origin, Piece
from .source import SourceFile
from .syntax import KNOWN_SETTINGS

MAX_DECLARED_NAMES = 10000

_DECLARATION_WORDS = {
    P.NEWTONIAN: "newtonian", P.FRAMES: "frames", P.BODIES: "bodies",
    P.PARTICLES: "particles", P.POINTS: "points", P.CONSTANTS: "constants",
    P.VARIABLES: "variables", P.MOTIONVARIABLES: "motionvariables",
    P.SPECIFIED: "specifieds", P.IMAGINARY: "imaginary",
}
_ON_OFF = ("ON", "OFF")
SETTING_VALUES: dict[str, tuple[str, ...] | str] = {
    "AUTOZ": _ON_OFF, "AUTOEXPRESS": _ON_OFF, "DEGREES": _ON_OFF, "FACTORING": _ON_OFF,
    "BEEPSOUND": _ON_OFF, "AUTORHS": ("ON", "OFF", "ALL"), "COMPLEX": ("ON", "OFF", "AUTO"),
    "OVERWRITE": ("ON", "OFF", "ALL"), "PAUSE": "number", "DIGITS": "integer",
    "AUTOEPSILON": "number",
}
assert set(SETTING_VALUES) == set(KNOWN_SETTINGS)
STATEMENT_KEYWORDS = {"NEWTONIAN", "FRAME", "FRAMES", "BODY", "BODIES", "PARTICLE",
                      "PARTICLES", "POINT", "POINTS", "CONSTANT", "CONSTANTS", "VARIABLE",
                      "VARIABLES", "MOTIONVARIABLE", "MOTIONVARIABLES", "SPECIFIED",
                      "SPECIFIEDS", "IMAGINARY", "MASS", "INERTIA", "INPUT", "INPUTS",
                      "OUTPUT", "OUTPUTS", "UNITS", "UNITSYSTEM", "CODE", "SAVE", "ENCODE",
                      "RUN"}
OPTIONAL_VALUE = ("PAUSE",)   # a bare PAUSE stops the session until a key is pressed
# numbers are doubles: 400 characters hold every one (and keep Python's int() fast)
MAX_NUMBER_DIGITS = 400
CODE_KINDS = ("dynamics", "algebraic", "nonlinear", "ode")
CODE_OPTIONS = ("subs", "nosubs")


@contextlib.contextmanager
def _gc_paused():
    """Parse trees are large webs of parent links; the cyclic collector would walk
    them again and again while they are built.  They are freed with the builder."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()


class Builder:
    def __init__(self, filename: str, path: Path | None,
                 reserved: frozenset[str] = frozenset(), folder: Path | None = None):
        """`reserved`, `folder`: Autolev's own commands and functions, and the model's
        folder when not `path`'s (see Includes)."""
        self.filename = filename
        self.includes = Includes(filename, path, reserved=reserved, folder=folder)
        self.symbols = ir.SymbolTable()
        self.statements: list[ir.Statement] = []
        self.diagnostics: list[Diagnostic] = []
        self._error_count = 0      # errors of this builder's own, counted as they come
        self._refused_call = False  # a user function of the statement was refused
        self._ctx: Origin | None = None
        self._piece: Piece | None = None

    # -- driving ---------------------------------------------------------------
    def build_source(self, src: SourceFile) -> None:
        self._build(self.includes.model(src))

    def build_macro_source(self, src: SourceFile) -> None:
        """Check a macro file on its own: each #k# stands for a name ARGk."""
        self._build(self.includes.macro_file(src))

    def _build(self, pieces: Iterable[Piece]) -> None:
        with _gc_paused():
            for piece in pieces:
                self._piece, self._ctx = piece, piece.origin
                self._statement(piece.statement)
        self._piece = self._ctx = None
        self.diagnostics.extend(self.includes.diagnostics)

    def program(self) -> ir.Program:
        return ir.Program(self.statements, self.symbols, self.filename,
                          [d for d in self.diagnostics if d.severity != "error"],
                          self.includes.files, self.includes.sources)

    @property
    def errors(self) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.severity == "error"]

    # -- helpers ---------------------------------------------------------------
    def _span(self, ctx) -> Span:
        stop = ctx.stop if ctx.stop is not None and ctx.stop.type != Token.EOF else ctx.start
        return Span.of(self._ctx.mapped, ctx.start.start, max(stop.stop, ctx.start.start))

    def _text(self, ctx) -> str:
        return self._ctx.mapped.slice(ctx.start.start, ctx.stop.stop + 1)

    def _error(self, ctx_or_token, code: str, message: str, notes=(), severity="error") -> None:
        tok = ctx_or_token if isinstance(ctx_or_token, Token) else ctx_or_token.start
        m = self._ctx.mapped
        self._error_count += severity == "error"
        self.diagnostics.append(Diagnostic(m.locate(tok.start), code, message, severity,
                                           m.source_line(tok.start), tuple(notes)))

    def _warn(self, ctx_or_token, code: str, message: str, notes=()) -> None:
        self._error(ctx_or_token, code, message, notes, severity="warning")

    # -- statements ------------------------------------------------------------
    def _unbuilt(self, ctx) -> None:
        """The fallback of the parse-tree tables: a construct the grammar reads and no
        handler builds is an error at its place, never a crash."""
        self._error(ctx, "E007", f"{_rule(ctx)}: read by the grammar but not supported yet")

    # handler(builder, statement's context) -> the statement, or None when none is added
    _STATEMENTS: Dispatch[Callable[[Builder, Any], ir.Statement | None]] = \
        Dispatch("IR builder statements", _unbuilt)

    def _statement(self, ctx: P.StatementContext) -> None:
        node = ctx.getChild(0)
        handler = self._STATEMENTS.lookup(type(node))
        errors_before = self._error_count
        self._refused_call = False
        try:
            result = handler(self, node)
        except RecursionError:
            # the parser read it, but building it recurses deeper than Python allows
            self._error(ctx, "E004", "this statement is nested too deeply to read")
            return
        # a statement found wrong while built is not handed on: check translates the rest
        if result is not None and self._error_count == errors_before \
                and not self._refused_call:
            self.statements.append(result)

    def _common(self, ctx) -> dict:
        return {"span": self._span(ctx), "text": self._text(ctx)}

    @_STATEMENTS.register(P.DeclarationContext)
    def _declaration(self, ctx: P.DeclarationContext) -> ir.Declaration:
        what = _DECLARATION_WORDS[ctx.declKeyword().start.type]
        kprimes = len(ctx.PRIME())
        items = []
        for d in ctx.declarator():
            item = self._declarator(d)
            if item is None:
                continue
            items.append(item)
            kind = ir.DECLARATION_KINDS[what]
            for name in item.names:
                self._declare(d, ir.Symbol(name, kind, max(item.primes, kprimes), item.sign,
                                           self._span(d)), item.value is not None)
                if kind in ("newtonian", "body"):
                    self._declare(d, ir.Symbol(name + "O", "point", span=self._span(d),
                                               implicit=True, owner=name))
        return ir.Declaration(what=what, items=tuple(items), keyword_primes=kprimes,
                              **self._common(ctx))

    def _declare(self, ctx, symbol: ir.Symbol, has_value: bool = False) -> None:
        previous = self.symbols.add(symbol)
        if previous is None or (previous.implicit and symbol.implicit):
            return
        if previous.implicit and previous.kind == symbol.kind:
            return   # POINTS NO after NEWTONIAN N only repeats what was implied
        where = f" on line {previous.span.line}" if previous.span else ""
        if previous.kind == symbol.kind:
            # 3.2-era files give specifieds their expressions by declaring them again
            if not has_value:
                self._warn(ctx, "W001", f"'{symbol.name}' is declared again (first{where})")
        else:
            what = "created by the declaration" if previous.implicit else "declared"
            self._warn(ctx, "W002", f"'{symbol.name}' was {what} as a {previous.kind}{where}; "
                       f"it is now a {symbol.kind}")

    def _declarator(self, ctx: P.DeclaratorContext) -> ir.Declarator | None:
        primes = len(ctx.PRIME())
        sign = ctx.declSign().getText() if ctx.declSign() else None
        value = self._expr(ctx.expr()) if ctx.expr() else None
        span = self._span(ctx)
        if ctx.name() is not None:
            name = ctx.name().getText()
            return ir.Declarator(name, (name,), primes, sign, value, (), span)
        parts: list = []
        last = ctx.start
        for child in ctx.getChildren():
            if isinstance(child, TerminalNode) and child.symbol.type == P.ID:
                parts.append(child.getText())
                last = child.symbol
            elif isinstance(child, P.DeclRangeContext):
                dims = self._ranges(child)
                if dims is None:
                    return None
                parts.append(dims)
                last = child.stop
        names, shape = self._expand(ctx, parts)
        if names is None:
            return None
        written = self._ctx.mapped.slice(ctx.start.start, last.stop + 1)
        return ir.Declarator(written, tuple(names), primes, sign, value, shape, span)

    def _ranges(self, ctx: P.DeclRangeContext) -> list[range] | None:
        """`{3}` -> [1..3]; `{2:4}` -> [2..4]; `{2,3}` -> [1..2, 1..3]; `{1:2,1:2}`."""
        dims = []
        for b in ctx.rangeBound():
            ints = [int(t.getText()) for t in b.INT()]
            lo, hi = (1, ints[0]) if len(ints) == 1 else (ints[0], ints[1])
            if hi < lo:
                self._error(b, "E040", f"empty range {{{b.getText()}}}: {lo} is above {hi}")
                return None
            dims.append(range(lo, hi + 1))
        return dims

    def _expand(self, ctx, parts: list) -> tuple[list[str] | None, tuple[int, ...]]:
        dims = [d for p in parts if not isinstance(p, str) for d in p]
        count = 1
        for d in dims:
            count *= d.stop - d.start            # not len(): a range may exceed a C size
        if count > MAX_DECLARED_NAMES:
            self._error(ctx, "E041", f"this range declares {count} names; "
                        f"at most {MAX_DECLARED_NAMES} are allowed")
            return None, ()
        pieces = [[p] if isinstance(p, str) else
                  ["".join(map(str, combo)) for combo in itertools.product(*p)] for p in parts]
        names = ["".join(combo) for combo in itertools.product(*pieces)]
        return names, tuple(len(d) for d in dims)

    @_STATEMENTS.register(P.MassStatementContext)
    def _mass(self, ctx: P.MassStatementContext) -> ir.MassStatement:
        items = []
        for it in ctx.massItem():
            exprs = it.expr()
            value = self._expr(exprs[0])
            chained = self._expr(exprs[1]) if len(exprs) > 1 else None
            if chained is not None and not isinstance(value, ir.Name):
                self._error(exprs[0], "E042", "in MASS B=m=value, the middle part must be a name")
            items.append(ir.MassItem(it.name().getText(), value, chained, self._span(it)))
        return ir.MassStatement(items=tuple(items), **self._common(ctx))

    @_STATEMENTS.register(P.InertiaStatementContext)
    def _inertia(self, ctx: P.InertiaStatementContext) -> ir.InertiaStatement:
        names = ctx.name()
        body = names[0].getText()
        frame = names[1].getText() if len(names) > 1 else None
        values, definitions = [], []
        for v in ctx.inertiaValue():
            exprs = v.expr()
            if len(exprs) == 2:
                lhs = self._expr(exprs[0])
                rhs = self._expr(exprs[1])
                if not isinstance(lhs, ir.Name) or lhs.primes:
                    self._error(exprs[0], "E043", "only a name can be defined inside INERTIA")
                    continue
                definitions.append((lhs.name, rhs))
                values.append(lhs)
            else:
                values.append(self._expr(exprs[0]))
        if len(values) not in (1, 3, 6):
            self._error(ctx, "E044", f"INERTIA takes 3 or 6 values (I11, I22, I33[, I12, I23, "
                        f"I31]); this one has {len(values)}")
        return ir.InertiaStatement(body=body, frame=frame, values=tuple(values),
                                   definitions=tuple(definitions), **self._common(ctx))

    @_STATEMENTS.register(P.AssignmentContext)
    def _assignment(self, ctx: P.AssignmentContext) -> ir.Assignment:
        t = ctx.target()
        if isinstance(t, P.VectorTargetContext):
            target = self._vector(t.VECNAME().symbol, t)
        else:
            name = t.name().getText()
            primes = self._primes(t.name(), t.PRIME())
            if t.indexList() is not None:
                target = ir.Index(name, self._indices(t.indexList()), primes, span=self._span(t))
            else:
                target = ir.Name(name, primes, span=self._span(t))
        return ir.Assignment(target=target, op=ctx.assignOp().getText(),
                             value=self._expr(ctx.expr()), **self._common(ctx))

    @_STATEMENTS.register(P.ExpressionStatementContext)
    def _expression_statement(self, ctx: P.ExpressionStatementContext) -> ir.Statement | None:
        macro = self._piece.expansion
        if macro is not None:         # a user macro's call: its statements follow
            if macro.path is None:
                return None
            call = ctx.expr().primary()
            return ir.MacroCall(name=macro.name, args=macro.args, path=str(macro.path),
                                span=self._span(call), text=self._text(call))
        expr = self._expr(ctx.expr())
        if isinstance(expr, ir.Call) and isinstance(ctx.expr().getChild(0), P.PrimaryContext):
            return ir.Command(call=expr, **self._common(ctx))
        if isinstance(expr, ir.Name) and expr.name.upper() in STATEMENT_KEYWORDS:
            self._error(ctx, "E005", f"{expr.name.upper()} needs at least one item after it")
            return None
        return ir.Display(expr=expr, **self._common(ctx))

    @_STATEMENTS.register(P.InputStatementContext)
    def _input(self, ctx: P.InputStatementContext) -> ir.Input:
        items = []
        for it in ctx.inputItem():
            name = it.name().getText()
            primes = len(it.PRIME())
            if it.indexList() is not None:
                target = ir.Index(name, self._indices(it.indexList()), primes,
                                  span=self._span(it.name()))
            else:
                target = ir.Name(name, primes, span=self._span(it.name()))
            items.append(ir.InputItem(target, self._expr(it.expr()), self._unit(it.unit()),
                                      self._span(it)))
        return ir.Input(items=tuple(items), **self._common(ctx))

    @_STATEMENTS.register(P.OutputStatementContext)
    def _output(self, ctx: P.OutputStatementContext) -> ir.Output:
        items = tuple(ir.OutputItem(self._expr(it.expr()), self._unit(it.unit()), self._span(it))
                      for it in ctx.outputItem())
        return ir.Output(items=items, **self._common(ctx))

    @_STATEMENTS.register(P.UnitsStatementContext)
    def _units(self, ctx: P.UnitsStatementContext) -> ir.UnitsStatement:
        items = []
        for it in ctx.unitsItem():
            t = it.unitsTarget()
            targets = []
            for child in t.getChildren():
                if isinstance(child, P.NameContext):
                    targets.append(ir.Name(child.getText(), 0, span=self._span(child)))
                elif isinstance(child, TerminalNode) and child.symbol.type == P.PRIME:
                    last = targets[-1]
                    targets[-1] = ir.Name(last.name, last.primes + 1, span=last.span)
            items.append(ir.UnitsItem(tuple(targets), self._unit(it.unit()), self._span(it)))
        return ir.UnitsStatement(items=tuple(items), **self._common(ctx))

    @_STATEMENTS.register(P.UnitSystemStatementContext)
    def _unit_system(self, ctx: P.UnitSystemStatementContext) -> ir.UnitSystem:
        return ir.UnitSystem(units=tuple(n.getText() for n in ctx.name()), **self._common(ctx))

    @_STATEMENTS.register(P.CodeStatementContext)
    def _code(self, ctx: P.CodeStatementContext) -> ir.Code | None:
        names = ctx.name()
        what = names[0].getText().lower()
        if what not in CODE_KINDS:
            self._error(names[0], "E011", f"unknown CODE kind '{names[0].getText()}'; expected "
                        "DYNAMICS, ALGEBRAIC, NONLINEAR or ODE")
        options = []
        for opt in names[1:]:
            if opt.getText().lower() not in CODE_OPTIONS:
                self._error(opt, "E012", f"unknown CODE option '{opt.getText()}'; expected "
                            "SUBS or NOSUBS")
            options.append(opt.getText().upper())
        args = tuple(self._arg(a) for a in ctx.argList().arg()) if ctx.argList() else ()
        sweep = None
        if ctx.sweep() is not None:
            s = ctx.sweep()
            e = [self._expr(x) for x in s.expr()]
            sweep = ir.Sweep(ir.Name(s.name().getText(), len(s.PRIME()), span=self._span(s.name())),
                             self._unit(s.unit()), e[0], e[1], e[2])
        filename = self._filename(ctx.fileName())
        return ir.Code(what=what, args=args, filename=filename, sweep=sweep,
                       options=tuple(options), **self._common(ctx))

    def _filename(self, ctx: P.FileNameContext) -> str:
        parts = ctx.fileNamePart()
        for a, b in zip(parts, parts[1:]):
            if b.start.start != a.stop.stop + 1:
                self._error(b, "E013", "a file name cannot contain blanks")
                break
        return self._text(ctx)

    @_STATEMENTS.register(P.SaveStatementContext)
    def _save(self, ctx: P.SaveStatementContext) -> ir.Save:
        return ir.Save(filename=self._filename(ctx.fileName()), **self._common(ctx))

    @_STATEMENTS.register(P.EncodeStatementContext)
    def _encode(self, ctx: P.EncodeStatementContext) -> ir.Encode:
        return ir.Encode(exprs=tuple(self._expr(e) for e in ctx.expr()), **self._common(ctx))

    @_STATEMENTS.register(P.ExitStatementContext)
    def _exit(self, ctx: P.ExitStatementContext) -> ir.Exit:
        return ir.Exit(**self._common(ctx))

    @_STATEMENTS.register(P.SettingContext)
    def _setting(self, ctx: P.SettingContext) -> ir.Setting:
        name = ctx.settingName().getText().upper()
        v = ctx.settingValue()
        value = v.getText().upper() if v is not None else None
        allowed = SETTING_VALUES[name]
        if value is None and name in OPTIONAL_VALUE:
            pass
        elif value is None:
            want = " or ".join(allowed) if isinstance(allowed, tuple) else f"a {allowed}"
            self._error(ctx, "E014", f"{name} needs a value: {want}")
        elif isinstance(allowed, tuple):
            if value not in allowed:
                self._error(v, "E014", f"{name} cannot be {v.getText()}; expected "
                            + " or ".join(allowed))
        elif v.number() is None:
            self._error(v, "E014", f"{name} needs a {allowed}, not {v.getText()}")
        elif allowed == "integer" and v.number().INT() is None:
            self._error(v, "E014", f"{name} needs a whole number, not {v.getText()}")
        return ir.Setting(name=name, value=value, **self._common(ctx))

    # -- RUN ----------------------------------------------------------------------
    @_STATEMENTS.register(P.RunStatementContext)
    def _run(self, ctx: P.RunStatementContext) -> ir.Run | None:
        """The included file's statements follow (the include stage read them)."""
        name = self._filename(ctx.fileName())
        included = self._piece.expansion
        if included is None or included.path is None:
            return None
        return ir.Run(filename=name, path=str(included.path), **self._common(ctx))

    # -- expressions -------------------------------------------------------------
    # The hot path: children are read directly, since ANTLR's typed accessors
    # (ctx.expr(0), ctx.name(), ...) scan the children list on every call.
    def _expr(self, ctx: P.ExprContext) -> ir.Expr:
        kids = ctx.children
        if len(kids) == 1:                      # primaryExpr: its primary's handler, called
            primary = kids[0]                   # from here (one Python frame per level)
            return self._PRIMARIES.lookup(type(primary))(self, primary)
        if len(kids) == 2:                      # unaryExpr
            operand = self._expr(kids[1])
            if kids[0].symbol.type == P.PLUS:
                return operand
            return ir.Neg(operand, span=self._span(ctx))
        # a left-associated chain (A + B - C ..., A*B/C) is walked in a loop: a sum of
        # thousands of terms is deeper than Python's recursion
        chain = [ctx]
        if type(ctx) in (P.AddExprContext, P.MulExprContext):
            while type(chain[-1].children[0]) is type(ctx):
                chain.append(chain[-1].children[0])
        result = self._expr(chain[-1].children[0])
        for level in reversed(chain):
            kids = level.children
            result = ir.BinOp(kids[1].symbol.text, result, self._expr(kids[2]),
                              span=self._span(level))
        return result

    def _primes(self, name_ctx, primes: list) -> int:
        """Count primes, which must follow the name directly (q'' not q ' ')."""
        previous = name_ctx.stop
        for p in primes:
            if p.symbol.start != previous.stop + 1:
                self._error(p.symbol, "E006", "a prime must follow the name directly")
                break
            previous = p.symbol
        return len(primes)

    def _vector(self, token, ctx) -> ir.VectorName:
        text = token.text
        dyadic = text.endswith(">>")
        return ir.VectorName(text.rstrip(">"), dyadic, span=self._span(ctx))

    def _unbuilt_primary(self, ctx) -> ir.Expr:
        self._unbuilt(ctx)
        return ir.Number("0", span=self._span(ctx))    # stands in: the error stops the model

    # handler(builder, primary's context) -> the expression
    _PRIMARIES: Dispatch[Callable[[Builder, Any], ir.Expr]] = \
        Dispatch("IR builder primaries", _unbuilt_primary)

    @_PRIMARIES.register(P.NameAtomContext)
    def _name_atom(self, ctx: P.NameAtomContext) -> ir.Expr:
        kids = ctx.children
        return ir.Name(kids[0].start.text, self._primes(kids[0], kids[1:]) if len(kids) > 1
                       else 0, span=self._span(ctx))

    @_PRIMARIES.register(P.NumberAtomContext)
    def _number_atom(self, ctx: P.NumberAtomContext) -> ir.Expr:
        text = ctx.start.text
        if len(text) > MAX_NUMBER_DIGITS:
            self._error(ctx, "E045", f"a number of {len(text)} characters; at most "
                        f"{MAX_NUMBER_DIGITS} are read")
            return ir.Number("0", span=self._span(ctx))
        return ir.Number(text, span=self._span(ctx))

    @_PRIMARIES.register(P.CallAtomContext)
    def _call_atom(self, ctx: P.CallAtomContext) -> ir.Expr:
        kids = ctx.children
        body = self._piece.functions.get(ctx) if self._piece.functions else None
        if body is REFUSED:           # its reading said why: the statement is not built
            self._refused_call = True
            return ir.Number("0", span=self._span(ctx))
        if body is not None:          # a user function NAME.R: its expression, built here
            outer, self._ctx = self._ctx, body.origin
            try:
                return self._expr(body.expr)
            finally:
                self._ctx = outer
        arg_ctxs = kids[2].children[::2] if len(kids) == 4 else []
        return ir.Call(kids[0].start.text, tuple(self._arg(a) for a in arg_ctxs),
                       span=self._span(ctx))

    @_PRIMARIES.register(P.VectorAtomContext)
    def _vector_atom(self, ctx: P.VectorAtomContext) -> ir.Expr:
        return self._vector(ctx.start, ctx)

    @_PRIMARIES.register(P.ParenAtomContext)
    def _paren_atom(self, ctx: P.ParenAtomContext) -> ir.Expr:
        return self._expr(ctx.children[1])

    @_PRIMARIES.register(P.IndexAtomContext)
    def _index_atom(self, ctx: P.IndexAtomContext) -> ir.Expr:
        kids = ctx.children
        return ir.Index(kids[0].start.text, self._indices(kids[-2]), len(kids) - 4,
                        span=self._span(ctx))

    @_PRIMARIES.register(P.MatrixAtomContext)
    def _matrix_atom(self, ctx: P.MatrixAtomContext) -> ir.Expr:
        rows = tuple(tuple(self._expr(e) for e in r.children[::2])
                     for r in ctx.children[1:-1:2])
        return ir.Matrix(rows, span=self._span(ctx))

    @_PRIMARIES.register(P.EmptyMatrixAtomContext)
    def _empty_matrix_atom(self, ctx: P.EmptyMatrixAtomContext) -> ir.Expr:
        return ir.Matrix((), span=self._span(ctx))

    @_PRIMARIES.register(P.RangeAtomContext)
    def _name_range(self, ctx: P.RangeAtomContext) -> ir.Expr:
        span = self._span(ctx)
        primes = len(ctx.PRIME())
        parts: list = [ctx.name().getText()]
        for child in list(ctx.getChildren())[1:]:
            if isinstance(child, TerminalNode) and child.symbol.type == P.ID:
                parts.append(child.getText())
            elif isinstance(child, P.DeclRangeContext):
                dims = self._ranges(child)
                if dims is None:
                    return ir.NameRange(self._text(ctx), (), span=span)
                parts.append(dims)
        names, _ = self._expand(ctx, parts)
        return ir.NameRange(self._text(ctx), tuple(ir.Name(n, primes, span=span)
                                                   for n in names or ()), span=span)

    def _indices(self, ctx: P.IndexListContext) -> tuple[ir.Expr, ...]:
        out = []
        for item in ctx.children[::2]:
            kids = item.children
            if len(kids) == 3:
                out.append(ir.Range(self._expr(kids[0]), self._expr(kids[2]),
                                    span=self._span(item)))
            else:
                out.append(self._expr(kids[0]))
        return tuple(out)

    def _arg(self, ctx: P.ArgContext) -> ir.Expr:
        """`e`, `lo:hi`, `x=v`, `x=a:dx`."""
        kids = ctx.children
        if len(kids) == 1:
            return self._expr(kids[0])
        groups: list[list] = [[]]
        for child in kids:
            if isinstance(child, TerminalNode):
                if child.symbol.type == P.EQUALS:
                    groups.append([])
            else:
                groups[-1].append(child)

        def side(exprs) -> ir.Expr:
            if len(exprs) == 2:
                return ir.Range(self._expr(exprs[0]), self._expr(exprs[1]),
                                span=Span.of(self._ctx.mapped, exprs[0].start.start,
                                             exprs[1].stop.stop))
            return self._expr(exprs[0])

        if len(groups) == 2:
            return ir.Equation(side(groups[0]), side(groups[1]), span=self._span(ctx))
        return side(groups[0])

    def _unit(self, ctx: P.UnitContext | None) -> ir.Unit | None:
        if ctx is None:
            return None
        factors = []
        sign = 1
        for child in ctx.getChildren():
            if isinstance(child, TerminalNode):
                sign = -1 if child.symbol.type == P.SLASH else 1
                continue
            power = 1
            if child.INT() is not None:
                power = int(child.INT().getText()) * (-1 if child.MINUS() else 1)
            factors.append((child.name().getText(), sign * power))
        return ir.Unit(self._text(ctx), tuple(factors), self._span(ctx))


def _rule(ctx) -> str:
    """The grammar rule or labelled alternative a parse-tree context stands for."""
    name = type(ctx).__name__.removesuffix("Context")
    return name[:1].lower() + name[1:]


def sort_key(d: Diagnostic) -> tuple:
    """Order diagnostics by where they are in the main file (through expansions)."""
    chain = []
    loc: Location | None = d.location
    while loc is not None:
        chain.append((loc.line, loc.col))
        loc = loc.via
    return tuple(reversed(chain))
