"""IR -> Python: the translator.

One `Translator` walks the program's statements in order, keeping what every name is
(a declared scalar, a frame or point, a value assigned earlier, a user vector) and
writing a line or two of Python per statement, preceded by the Autolev line as a
comment.  Expressions are written with their type (scalar, vector, dyadic, matrix,
frame, point) so each construct can be checked and written the way its types need.
Expressions, functions and vector names are written by handlers in `expressions.py`,
`functions/` and `special.py`, statements by one module per family (`declarations.py`,
`assignments.py`, `commands.py`, `kinematics.py`, `dynamics.py`, `io.py`, `session.py`),
registered in the tables `EXPRESSIONS` and `STATEMENTS` defined here (importing the
package imports them).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Callable

from .. import ir
from ..dispatch import Dispatch
from ..errors import Diagnostic, Location, Span
from .emit import comment, docstring, quote
from .kinds import ATOM, ENTITY_KINDS, Entry, FRAME_KINDS, NameKind, Typed, ValueType
from .names import NameTable, UnsafeName
from .reads import expression_names, primes_used, statement_exprs


# the generated module imports sympy only when some line uses it
_SYMPY_IMPORT = "import sympy as sm"
_USES_SYMPY = re.compile(r"\bsm\.")
# the NameTable's spaces as Autolev's namespaces (derivative names are not Autolev's)
_NAMESPACE = {"scalar": "quantity", "value": "quantity", "entity": "entity",
              "vector": "vector"}


class TranslationError(Exception):
    """Raised inside the translator to stop one statement with a diagnostic."""

    def __init__(self, message: str, node, code: str):
        super().__init__(message)
        self.node = node
        self.code = code


@dataclass
class Line:
    code: str
    span: Span | None = None


@dataclass
class Translation:
    code: str
    line_map: dict[int, Span]
    diagnostics: list[Diagnostic]
    names: dict[str, str] = field(default_factory=dict)   # Autolev name -> Python name
    # Autolev's namespaces: "quantity" (scalars, matrices and other assigned values),
    # "entity" (frames, bodies, points, particles), "vector" (vectors and dyadics),
    # each Autolev name -> Python name
    namespaces: dict[str, dict[str, str]] = field(default_factory=dict)
    files: list[str] = field(default_factory=list)    # every file read, the model's first
    # where each CODE statement is, in order (the messages of its run point there)
    code_spans: list[Span] = field(default_factory=list)
    # {NAME: "file:line: statement"}: the statement that last defines each scalar (X' as
    # XP, upper case), for the comment before its line in a written program
    defined_at: dict[str, str] = field(default_factory=dict)
    # the probes the translator could not write: {key: why}
    probe_errors: dict[str, str] = field(default_factory=dict)
    # {(what, NAME): ["file:line: statement", ...]}: the statements that give a frame its
    # orientation or angular velocity, a point its position or velocity, a body its mass
    # or inertia, a point or frame a load ("gravity", "*" for GRAVITY); the CONSTRAINs
    # ("constrain", "DEPENDENT" or "AUXILIARY"), every assignment to a name or its
    # elements ("assigned"): for the comments of a SymPy script
    statements_at: dict[tuple[str, str], list[str]] = field(default_factory=dict)
    # the constants declared that no INPUT gives a value and no statement defines, and
    # (after a CODE ALGEBRAIC or NONLINEAR) such variables, as the model spells them: a
    # run needs values for those its programs read (named before the model is built,
    # which forms its equations)
    inputs_without_value: list[str] = field(default_factory=list)
    # the Python line of each CODE statement's call, and inputs_without_value as it
    # stood at the last (what the last CODE command's program could read)
    code_lines: list[int] = field(default_factory=list)
    lacking_at_last_code: list[str] = field(default_factory=list)
    # whether some CODE statement is a DYNAMICS or ODE (the equations a linearization,
    # an animation or an export takes before the model's equations as they stand)
    code_integrates: bool = False

    def through_last_code(self) -> Translation:
        """The module up to its last CODE statement: what every CODE command's program
        depends on (Autolev wrote each when it read its line), without the statements
        after it (a SOLVE, TAYLOR or EVALUATE of the equations can cost most of a
        model's forming).  Itself when nothing follows that statement, or when no CODE
        statement integrates (then the model's equations as they stand at its end are
        those of `autolev linearize`, `animate` and `convert`)."""
        if not self.code_lines or not self.code_integrates:
            return self
        last = self.code_lines[-1]
        lines = self.code.splitlines()
        if last == len(lines):
            return self
        return replace(self, code="\n".join(lines[:last]) + "\n",
                       line_map={n: s for n, s in self.line_map.items() if n <= last},
                       inputs_without_value=list(self.lacking_at_last_code))


# the generated module's dictionary of probes' values (a dunder name: no Autolev name
# is translated to one)
PROBES = "__probes__"


@dataclass(frozen=True)
class Probe:
    """A value a consumer of the module reads from it (autolev verify, transcript): the
    value of `expr` after the model's statements up to line `after` of its file, kept
    with the definitions made then as `PROBES[key] = (value, model.defs.user_definitions())`.
    `binds` names the value for the probes after it (Autolev's Z7 of a response)."""

    key: str
    after: int
    expr: ir.Expr
    span: Span
    binds: str | None = None


def _unsupported_statement(tr: Translator, st: ir.Statement) -> None:
    raise tr.error(f"{st.kind} statements are not supported yet", st, "T006")


def _unsupported_expression(tr: Translator, e: ir.Expr, want: str) -> Typed:
    raise tr.error(f"{type(e).__name__} expressions are not supported yet", e, "T006")


# handler(translator, statement) and handler(translator, expression, want) -> Typed
STATEMENTS: Dispatch[Callable[[Translator, Any], None]] = \
    Dispatch("translator statements", _unsupported_statement)
EXPRESSIONS: Dispatch[Callable[[Translator, Any, str], Typed]] = \
    Dispatch("translator expressions", _unsupported_expression)


@dataclass
class Session:
    """The switches of an Autolev session the statements so far have set: what a later
    statement means depends on them."""

    degrees: bool = True        # DEGREES ON: a numeric angle is in degrees
    autorhs: bool = False       # AUTORHS ON: a declared name's stored RHS replaces it
    exited: bool = False        # EXIT: the statements after it are ignored
    kane_called: bool = False   # a KANE() so far


class Translator:
    def __init__(self, program: ir.Program, module_name: str = "model",
                 probes: tuple[Probe, ...] = ()):
        self.program = program
        self.module_name = module_name
        self.probes = sorted(probes, key=lambda probe: probe.after)    # stable
        self.probe_errors: dict[str, str] = {}
        # the names probes bind, seen by the probes only (not by the model's statements)
        self.probe_names: dict[str, Entry] = {}
        self._probing = False
        self.names = NameTable()
        self.scalars: dict[str, Entry] = {}
        self.values: dict[str, Entry] = {}
        self.entities: dict[str, Entry] = {}
        self.vectors: dict[str, Entry] = {}
        self.derivs: dict[tuple[str, int], str] = {}
        self.lines: list[Line] = []
        # reading's warnings first: the Translation holds every diagnostic of the model
        self.diagnostics: list[Diagnostic] = list(program.diagnostics)
        self.session = Session()
        self.call_depth = 0
        self.defined: set[tuple[str, int]] = set()
        # names INPUT or a CODE ALGEBRAIC sweep gives values, lower case, with their primes
        self.given_by_input: set[str] = set()
        # a CODE ALGEBRAIC or NONLINEAR came: its program reads variables from its .in
        self.code_reads_variables = False
        # the declared name (key, primes) whose new definition is being read
        self.redefining: tuple[str, int] | None = None
        # made when first asked for: runs X[1] = a, X[2] = b, ... by their statements'
        # ids (assignments.py), and the words of the model's text (declarations.py)
        self.column_runs: dict | None = None
        self.words: set[str] | None = None
        self.code_spans: list[Span] = []           # see Translation
        self.code_calls: list[Line] = []           # each CODE statement's line of Python
        self.lacking_at_last_code: list[str] = []
        self.code_integrates = False
        self.defined_at: dict[str, str] = {}
        self.statements_at: dict[tuple[str, str], list[str]] = {}
        self._statement: ir.Statement | None = None
        self._span: Span | None = None
        self._used_primes = primes_used(program)
        self.autolev_names: dict[str, str] = {}
        self.spelled: dict[str, str] = {}          # each Python name -> its Autolev name
        self.namespaces: dict[str, dict[str, str]] = {}
        # declared scalars keep their names: they are allocated before anything that
        # could clash with them (frames, vectors, derivative names)
        for sym in program.symbols:
            if sym.namespace == "scalar":
                self._reserve("scalar", sym.name)
        for st in program.statements:
            if isinstance(st, ir.Assignment) and isinstance(st.target, (ir.Name, ir.Index)) \
                    and program.symbols.scalar(st.target.name) is None:
                self._reserve("value", st.target.name)

    def _reserve(self, space: str, name: str) -> None:
        try:
            self.names.assign(space, name)
        except UnsafeName:
            pass        # reported where the name is used

    # -- output ----------------------------------------------------------------------
    def emit(self, code: str) -> None:
        for part in code.split("\n"):
            self.lines.append(Line(part, self._span))

    def error(self, message: str, node, code: str) -> TranslationError:
        """The exception that stops a statement with a diagnostic: `raise tr.error(...)`;
        `code` is one of the T codes listed in docs/language.md."""
        return TranslationError(message, node, code)

    def warn(self, message: str, node=None, code: str = "W101") -> None:
        """A warning, unless one was given at that place already (reading's 'declared
        again' is the translation's too)."""
        found = self._diagnostic(message, node, code, "warning")
        if not any(d.severity == "warning" and d.location == found.location
                   for d in self.diagnostics):
            self.diagnostics.append(found)

    def _diagnostic(self, message, node, code, severity) -> Diagnostic:
        span = getattr(node, "span", None) or self._span
        loc = span.start if span is not None else None
        source = None
        if loc is not None:
            lines = self.program.sources.get(loc.file)
            if lines and 1 <= loc.line <= len(lines):
                source = lines[loc.line - 1]
        return Diagnostic(loc or Location(self.program.filename, 1, 1), code, message,
                          severity, source)

    # -- names -------------------------------------------------------------------------
    def py_name(self, space: str, name: str, kind: str | None = None) -> str:
        try:
            py = self.names.assign(space, name, kind)
        except UnsafeName:
            raise self.error(f"'{name}' cannot be used as a name", None, "T008") from None
        self.autolev_names.setdefault(name, py)
        self.spelled[py] = name
        public = _NAMESPACE.get(space)
        if public is not None:
            self.namespaces.setdefault(public, {}).setdefault(name, py)
        return py

    def declare_scalar(self, name: str, kind: NameKind, order: int) -> Entry:
        py = self.py_name("scalar", name)
        e = Entry(py, kind, ValueType.SCALAR, order)
        self.scalars[name.lower()] = e
        return e

    def derivative_name(self, name: str, order: int) -> str:
        """Python name of the order-th derivative of the scalar `name` (Q1p, Q1pp)."""
        k = (name.lower(), order)
        if k in self.derivs:
            return self.derivs[k]
        base = self.scalars[name.lower()]
        py = self.py_name("derivative", base.py + "p" * order, "derivative")
        self.derivs[k] = py
        return py

    def ensure_derivative(self, name: str, order: int) -> str:
        """The derivative's Python name, writing its definition line if it is new."""
        k = (name.lower(), order)
        if k in self.derivs:
            return self.derivs[k]
        py = self.derivative_name(name, order)
        base = self.scalars[name.lower()].py
        suffix = f", {order}" if order > 1 else ""
        self.emit(f"{py} = al.derivative({base}{suffix})")
        return py

    # -- driving -----------------------------------------------------------------------
    def translate(self) -> Translation:
        self._header()
        previous_end: dict[str, int] = {}
        statements = self.program.statements
        probes = iter(self.probes)
        probe = next(probes, None)
        for n, st in enumerate(statements):
            while probe is not None and st.span is not None and \
                    probe.after < _line_in_model(st.span) and not self._within_run(st):
                self._write_probe(probe)
                probe = next(probes, None)
            if self.session.exited:
                self.warn(f"{len(statements) - n} statement(s) after EXIT are ignored, as "
                          "Autolev ignored them", st, "W103")
                break
            self._span, self._statement = st.span, st
            self._comments_before(st, previous_end)
            try:
                STATEMENTS.lookup(type(st))(self, st)
            except RecursionError:
                # unary signs or powers nested hundreds deep (a chain of sums is a loop)
                self.diagnostics.append(self._diagnostic(
                    "this statement's expression is nested too deeply to translate", st,
                    "T004", "error"))
                self._known_after_failure(st)
            except TranslationError as exc:
                self.diagnostics.append(self._diagnostic(str(exc), exc.node or st, exc.code,
                                                         "error"))
                if exc.code == "T002":
                    self._report_other_undeclared(st, exc.node)
                self._known_after_failure(st)
        while probe is not None:
            self._write_probe(probe)
            probe = next(probes, None)
        self._span = self._statement = None
        code, line_map, code_lines = self._render()
        return Translation(code, line_map, self.diagnostics, dict(self.autolev_names),
                           {k: dict(v) for k, v in self.namespaces.items()},
                           list(self.program.files), list(self.code_spans),
                           dict(self.defined_at), dict(self.probe_errors),
                           {k: list(v) for k, v in self.statements_at.items()},
                           self.inputs_without_value(), code_lines,
                           list(self.lacking_at_last_code), self.code_integrates)

    def inputs_without_value(self) -> list[str]:
        """The constants declared so far that no INPUT gives a value and no statement
        defines; once a CODE statement that does not integrate came (ALGEBRAIC,
        NONLINEAR: its program reads the variables its outputs use, as it reads the
        constants, from its .in file), the variables and their declared derivatives
        likewise (Translation's)."""
        lacking = [self.autolev_name(e) for key, e in self.scalars.items()
                   if e.kind == NameKind.CONSTANT and key not in self.given_by_input
                   and (key, 0) not in self.defined]
        if self.code_reads_variables:
            lacking += [self.autolev_name(e) + "'" * k for key, e in self.scalars.items()
                        if e.kind in (NameKind.VARIABLE, NameKind.MOTIONVARIABLE)
                        for k in range(e.order + 1)
                        if key + "'" * k not in self.given_by_input
                        and (key, k) not in self.defined]
        return lacking

    def code_call(self, call: str, integrates: bool) -> None:
        """Write a CODE statement's call, noting where it is and what lacks a value."""
        self.code_spans.append(self._span)
        self.code_integrates = self.code_integrates or integrates
        self.code_reads_variables = self.code_reads_variables or not integrates
        self.emit(call)
        self.code_calls.append(self.lines[-1])
        self.lacking_at_last_code = self.inputs_without_value()

    @staticmethod
    def location(st: ir.Statement) -> str:
        """'file:line: statement' (the statement as written, shortened), for a comment."""
        text = " ".join((st.text or "").split())
        text = text if len(text) <= 70 else text[:67] + "..."
        return f"{Path(st.span.file).name}:{st.span.line}: {text}"

    def note_statement(self, what: str, *names: str) -> None:
        """The statement being translated gives `what` (statements_at's) of each of the
        Autolev `names`."""
        st = self._statement
        if st is None or st.span is None:
            return
        where = self.location(st)
        for name in names:
            kept = self.statements_at.setdefault((what, name.upper()), [])
            if where not in kept:
                kept.append(where)

    def autolev_name(self, entry: Entry) -> str:
        """The Autolev name of a declared frame, point or body."""
        return self.spelled[entry.py]

    def _within_run(self, st: ir.Statement) -> bool:
        """Whether st continues a run X[1] = a, X[2] = b, ... (assignments.py): X is
        written with the run's last statement, so a probe waits for it."""
        run = self.column_runs.get(id(st)) if self.column_runs else None
        return run is not None and st is not run[0]

    def _write_probe(self, probe: Probe) -> None:
        """The line keeping a probe's value, or why there is none (`probe_errors`)."""
        self._span = probe.span
        self._probing = True
        try:
            value = self.expr(probe.expr)
        except TranslationError as exc:
            self.probe_errors[probe.key] = f"{exc} [{exc.code}]"
            return
        except RecursionError:
            self.probe_errors[probe.key] = "nested too deeply to translate"
            return
        finally:
            self._probing = False
        self.emit(f"{PROBES}[{probe.key!r}] = ({value.code}, model.defs.user_definitions())")
        if probe.binds is not None:
            self.probe_names[probe.binds.lower()] = Entry(
                f"{PROBES}[{probe.key!r}][0]", NameKind.VALUE, value.type)

    def _report_other_undeclared(self, st: ir.Statement, first) -> None:
        """The names after the first undeclared one in the statement that are not
        declared or defined either (every one is reported, not only the first)."""
        seen = {first.name.lower()} if isinstance(first, ir.Name) else set()
        if isinstance(st, ir.Assignment):       # what it reads, not what it assigns
            target = st.target
            read = [st.value] + (list(target.indices) if isinstance(target, ir.Index) else [])
        else:
            read = list(statement_exprs(st))
        for e in read:
            for node in expression_names(e):
                key = node.name.lower()
                if node is first or key in seen or self._resolvable(node):
                    continue
                seen.add(key)
                self.diagnostics.append(self._diagnostic(
                    f"'{node.name}' is not declared or defined", node, "T002", "error"))

    def _resolvable(self, node: ir.Name) -> bool:
        key = node.name.lower()
        return (key in self.scalars or key in self.entities
                or (key in self.values and not node.primes)
                or key in ("t", "pi", "u_independent", "u_dependent", "u_auxiliary")
                or self.split_entities(node.name, FRAME_KINDS, 2)
                is not None)

    def _known_after_failure(self, st: ir.Statement) -> None:
        """A name whose assignment failed is still known afterwards (of unknown type),
        so that one error does not bring others on every line that uses the name."""
        if not isinstance(st, ir.Assignment):
            return
        target = st.target
        if isinstance(target, ir.VectorName):
            if target.name.lower() not in self.vectors:
                self.vectors[target.name.lower()] = Entry(
                    target.name, NameKind.VECTOR,
                    ValueType.DYADIC if target.dyadic else ValueType.VECTOR)
        elif isinstance(target, (ir.Name, ir.Index)) and not target.primes:
            key = target.name.lower()
            if key not in self.scalars and key not in self.values:
                self.values[key] = Entry(target.name, NameKind.VALUE, ValueType.UNKNOWN)

    def _comments_before(self, st: ir.Statement, previous_end: dict[str, int]) -> None:
        """The user's comment lines and the statement's own lines, as comments."""
        span = st.span
        if span is None:
            return
        lines = self.program.sources.get(span.file)
        if not lines:
            return
        start, end = span.start.line, span.end.line
        via = span.start.via is not None
        if not via:
            prev = previous_end.get(span.file, 0)
            blank = False
            for i in range(prev + 1, start):
                text = lines[i - 1].strip()
                if not text:
                    blank = True
                    continue
                if text.startswith("%"):
                    if blank and self.lines and self.lines[-1].code:
                        self.emit("")
                    blank = False
                    body = text.lstrip("%").rstrip()
                    self.emit("#" + (" " + comment(body.strip()) if body.strip() else ""))
            if blank and self.lines and self.lines[-1].code:
                self.emit("")
            previous_end[span.file] = max(end, prev)
        for i in range(start, end + 1):
            self.emit("# " + comment(lines[i - 1].rstrip()))

    def _header(self) -> None:
        src = self.program.filename
        self.emit(f'"""Translated from {docstring(_basename(src))} by autolev.\n\n'
                  "Importing this module builds the model; running it performs the model's\n"
                  'CODE commands with its INPUT values."""')
        self.emit(_SYMPY_IMPORT)
        self.emit("")
        self.emit("import autolev.runtime as al")
        self.emit("")
        self.emit('if __name__ == "__main__":')
        self.emit("    # `python this.py [options]` is `autolev run this.py [options]`: the same")
        self.emit("    # messages, files and exit status")
        self.emit("    import sys")
        self.emit("")
        self.emit("    from autolev.cli import main")
        self.emit('    sys.exit(main(["run", __file__, *sys.argv[1:]]))')
        self.emit("")
        self.emit(f"model = al.Model({quote(self.module_name)})")
        self.emit("t = model.t")
        if self.probes:
            self.emit(f"{PROBES} = {{}}")
        self.emit("")

    def _render(self) -> tuple[str, dict[int, Span], list[int]]:
        """The module's text, its line map, and the line of each CODE call."""
        lines = self.lines
        if not any(_USES_SYMPY.search(line.code) for line in lines
                   if line.code != _SYMPY_IMPORT):     # the header's import, unused
            k = next(i for i, line in enumerate(lines) if line.code == _SYMPY_IMPORT)
            lines = lines[:k] + lines[k + 2:]
        calls = {id(line) for line in self.code_calls}
        out, line_map, code_lines = [], {}, []
        for n, line in enumerate(lines, 1):
            out.append(line.code)
            if line.span is not None:
                line_map[n] = line.span
            if id(line) in calls:
                code_lines.append(n)
        return "\n".join(out) + "\n", line_map, code_lines

    # -- expressions ---------------------------------------------------------------------
    def expr(self, e: ir.Expr, want: str = "value") -> Typed:
        result = EXPRESSIONS.lookup(type(e))(self, e, want)
        result.node = e
        return result

    def scalar(self, e: ir.Expr) -> Typed:
        x = self.expr(e)
        if x.type not in (ValueType.SCALAR, ValueType.UNKNOWN):
            raise self.error(f"a scalar is needed here, not a {x.type}", e, "T001")
        return x

    def name(self, name: str, primes: int, node, want: str = "value") -> Typed:
        key = name.lower()
        if self._probing and not primes and key in self.probe_names:
            entry = self.probe_names[key]
            return Typed(entry.py, entry.type)
        if want in ("frame", "point", "entity") and key in self.entities:
            ent = self.entities[key]
            return Typed(ent.py, ent.type)
        if key in self.scalars:
            entry = self.scalars[key]
            code = self.ensure_derivative(name, primes) if primes else entry.py
            if (key, primes) == self.redefining:
                # X = f(X): on the right, X stands for its previous definition
                return Typed(f"model.previous({code})", ValueType.SCALAR)
            if self.session.autorhs and (key, primes) in self.defined:
                return Typed(f"model.rhs({code})", ValueType.SCALAR)
            return Typed(code, ValueType.SCALAR)
        if key in self.values:
            entry = self.values[key]
            if primes:
                raise self.error(f"{name} is not a declared variable, so {name}"
                                 f"{chr(39) * primes} has no meaning", node, "T008")
            return Typed(entry.py, entry.type, shape=entry.shape, elements=entry.elements)
        if key in ("u_independent", "u_dependent", "u_auxiliary"):
            order = f", {primes}" if primes else ""
            return Typed(f"model.speed_column({key[2:]!r}{order})", ValueType.MATRIX)
        if key == "t" and not primes:
            return Typed("t", ValueType.SCALAR)
        if key == "pi" and not primes:
            return Typed("sm.pi", ValueType.SCALAR)
        if key in self.entities:
            ent = self.entities[key]
            return Typed(ent.py, ent.type)
        dcm = self.dcm_name(name)
        if dcm is not None:
            return dcm
        if self._probing:
            # a response may name what the engine declared (NICHECK's WCHECK1)
            return Typed(f"model.engine_symbol({quote(name + chr(39) * primes)})",
                         ValueType.SCALAR)
        raise self.error(f"'{name}' is not declared or defined", node, "T002")

    def symbol(self, e: ir.Expr) -> str:
        """A declared name as the symbol itself (never its RHS, whatever AUTORHS says)."""
        if isinstance(e, ir.Name) and e.name.lower() in self.scalars:
            return self.ensure_derivative(e.name, e.primes) if e.primes else \
                self.scalars[e.name.lower()].py
        return self.expr(e).code

    def dcm_name(self, name: str) -> Typed | None:
        """A_B: the direction cosine matrix of two frames (A_i . B_j)."""
        parts = self.split_entities(name, FRAME_KINDS, 2)
        if parts is None:
            return None
        a, b = parts
        return Typed(f"{a.py}.dcm({b.py})", ValueType.MATRIX, ATOM)

    def split_entities(self, text: str, kinds, count: int) -> list[Entry] | None:
        """Split `text` at underscores into `count` entity names of the given kinds."""
        pieces = text.split("_")
        return _split_into(pieces, count, lambda s: self._entity_of(s, kinds))

    def _entity_of(self, name: str, kinds) -> Entry | None:
        ent = self.entities.get(name.lower())
        if ent is not None and ent.kind in kinds:
            return ent
        return None

    def index_code(self, e: ir.Expr) -> str:
        """A 1-based Autolev index as a 0-based Python index."""
        if isinstance(e, ir.Range):
            lo, hi = self.index_code(e.lo), self.index_code(e.hi)
            return f"{lo}:{_plus_one(hi)}"
        x = self.scalar(e)
        if x.exact is not None and x.exact.denominator == 1:
            return str(int(x.exact) - 1)
        return f"int({x.code}) - 1"

    def frame(self, e: ir.Expr) -> Typed:
        """An expression that must name a frame (or a body)."""
        if isinstance(e, ir.Name) and not e.primes:
            ent = self.entities.get(e.name.lower())
            if ent is not None and ent.kind in FRAME_KINDS:
                return Typed(ent.py, ValueType.FRAME)
        raise self.error("a frame or body is needed here", e, "T008")

    def point(self, e: ir.Expr) -> Typed:
        """An expression that must name a point (or particle)."""
        if isinstance(e, ir.Name) and not e.primes:
            ent = self.entities.get(e.name.lower())
            if ent is not None and ent.kind in (NameKind.POINT, NameKind.PARTICLE):
                return Typed(ent.py, ValueType.POINT)
        raise self.error("a point or particle is needed here", e, "T008")

    def entity(self, e: ir.Expr, kinds=ENTITY_KINDS) -> Entry:
        if isinstance(e, ir.Name) and not e.primes:
            ent = self.entities.get(e.name.lower())
            if ent is not None and ent.kind in kinds:
                return ent
        raise self.error("a " + " or ".join(sorted(set(kinds) - {NameKind.NEWTONIAN})) +
                         " is needed here", e, "T008")


def _line_in_model(span: Span) -> int:
    """The line of the model's own file a statement is at (a RUN's or a macro call's
    line for the statements it brought in)."""
    where = span.start
    while where.via is not None:
        where = where.via
    return where.line


def _split_into(pieces: list[str], count: int, accept) -> list | None:
    """Join consecutive pieces into `count` groups that `accept` recognises."""
    if count == 1:
        return [accept("_".join(pieces))] if pieces and accept("_".join(pieces)) else None
    for i in range(1, len(pieces) - count + 2):
        head = accept("_".join(pieces[:i]))
        if head is None:
            continue
        rest = _split_into(pieces[i:], count - 1, accept)
        if rest is not None:
            return [head] + rest
    return None


def _plus_one(code: str) -> str:
    try:
        return str(int(code) + 1)
    except ValueError:
        return f"{code} + 1"


def _basename(path: str) -> str:
    return path.replace("\\", "/").rsplit("/", 1)[-1]
