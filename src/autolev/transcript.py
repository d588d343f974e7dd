"""What Autolev displayed: a model's session transcript, laid out as its `.all` files.

Every input line but a blank one is numbered `(n)`; after each assignment, and each
command that defines something, come the responses Autolev printed for it: the
intermediate Z variables its values use that were not shown before (`-> (n) Z3 = ...`),
then `-> (n) NAME = value` for each name it defined (SIMPROT's `N_A`, INERTIA's
`I_A_AO>>`, SOLVE's `U1'`, GRAVITY's `FORCE_AO>`, ...; docs/language.md "The responses
of a session" has the list and its evidence).  Values are written in Autolev's syntax
(`SIN(Q1)`, `Q1^2`, `L*A1>`, `c*A1>*B2>`), every number that is not an integer as a
decimal of 7 significant digits (`PI/2` is `1.570796`, a square root `X^0.5`), a matrix
one element a line (`ZERO[2] = ...`) but a direction-cosine matrix or a 1x1 matrix
whole (`[a, b; c, d]`).  Our Z variables are ours: their numbering need not be
Autolev's (and a large value's repeated parts get Z's of the transcript's own), and
`autolev verify` judges a transcript by value.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, replace
from pathlib import Path

import sympy as sm
from sympy.printing.precedence import PRECEDENCE, precedence
from sympy.printing.str import StrPrinter

from . import ir
from .errors import AutolevError
from .loader import load
from .pipeline import parse
from .engine import reading
from .engine.functions import FUNCTION_BY_SYMPY
from .runtime.calculus import is_small
from .runtime.symbols import TIME, Z, derivative, new_z
from .runtime.vectors import Dyadic, Vector
from .source import decode
from .translate.commands import IN_PLACE
from .verification import Response, Session, parse_responses, replay


class AutolevPrinter(StrPrinter):
    """sympy expressions in Autolev's printed syntax."""

    printmethod = "_autolevstr"          # not the objects' own _sympystr (Z's: z1)

    def _print_Symbol(self, expr) -> str:
        return "T" if expr == TIME else expr.name

    def _print_Dummy(self, expr) -> str:
        return expr.name.upper() if isinstance(expr, Z) else expr.name

    def _print_Add(self, expr, order=None) -> str:
        """Terms in sympy's own order, those with a sign of their own last, as Autolev
        wrote them (`1 - 2*e2^2 - 2*e3^2`, TD-all (22)); sorting them for display cost
        most of a large model's transcript."""
        terms = sorted(expr.args, key=lambda t: t.could_extract_minus_sign())
        out = ""
        for term in terms:
            text = self._print(term)
            negative = text.startswith("-")
            if negative:
                text = text[1:]
            if precedence(term) < PRECEDENCE["Add"]:
                text = f"({text})"
            if not out:
                out = ("-" if negative else "") + text
            else:
                out += (" - " if negative else " + ") + text
        return out

    def _print_Float(self, expr) -> str:
        return f"{float(expr):.7g}".upper()          # 7E-06, as Autolev wrote it

    def _print_Pi(self, expr) -> str:
        return "PI"

    def _print_ImaginaryUnit(self, expr) -> str:
        return "I"

    def _print_Function(self, expr) -> str:
        # Autolev's own name (CEIL, not sympy's ceiling)
        spec = FUNCTION_BY_SYMPY.get(type(expr).__name__)
        name = spec.autolev if spec is not None and spec.autolev else type(expr).__name__.upper()
        return f"{name}({', '.join(self._print(a) for a in expr.args)})"

    def _print_Abs(self, expr) -> str:
        return f"ABS({self._print(expr.args[0])})"

    def _print_Pow(self, expr, rational=False) -> str:
        base, exp = expr.as_base_exp()
        if exp == -1:
            return f"1/{self.parenthesize(base, PRECEDENCE['Pow'])}"
        if exp.is_number and exp.is_negative:
            return f"1/{self._print(sm.Pow(base, -exp, evaluate=False))}"
        return (f"{self.parenthesize(base, PRECEDENCE['Pow'], strict=True)}^"
                f"{self.parenthesize(exp, PRECEDENCE['Pow'], strict=True)}")

    def _print_MatrixBase(self, expr) -> str:
        return "[" + "; ".join(", ".join(self._print(expr[i, j]) for j in range(expr.cols))
                               for i in range(expr.rows)) + "]"

    _print_MutableDenseMatrix = _print_ImmutableDenseMatrix = _print_MatrixBase


_PRINTER = AutolevPrinter({"order": "none"})


def expression(value, scalar=sm.sympify) -> str:
    """A value (scalar, Vector, Dyadic, matrix) as Autolev printed it; `scalar` gives
    each of its scalars as printed (with Z's for the repeated parts of a large one)."""
    if isinstance(value, Vector):
        return _terms([(scalar(c), f"{frame.name}{i + 1}>")
                       for frame, comps in value.terms.items()
                       for i, c in enumerate(comps)], "0>")
    if isinstance(value, Dyadic):
        return _terms([(scalar(m[i, j]), f"{a.name}{i + 1}>*{b.name}{j + 1}>")
                       for (a, b), m in value.terms.items()
                       for i in range(3) for j in range(3)], "0>>")
    if isinstance(value, (list, tuple)):
        value = sm.Matrix(value)
    if isinstance(value, sm.MatrixBase):
        return _PRINTER.doprint(value.applyfunc(lambda e: _decimal(scalar(e))))
    return _PRINTER.doprint(_decimal(scalar(sm.sympify(value))))


def _decimal(expr):
    """Every real number that is not an integer as a Float: Autolev displayed `PI/2`
    as 1.570796 and `SQRT(2)*RAD` as 1.414214*RAD (TD-all (11), (13))."""
    return expr.replace(lambda e: e.is_number and e.is_real is True and
                        not e.is_Integer and not e.is_Float,
                        lambda e: sm.Float(e.evalf(15)))


def _terms(terms, zero: str) -> str:
    """coefficient*unit terms joined with their signs (`Z15*A3> - Z16*N3>`)."""
    out = ""
    for coef, unit in terms:
        coef = _decimal(sm.sympify(coef))
        if coef == 0:
            continue
        negative = coef.could_extract_minus_sign()
        magnitude = -coef if negative else coef
        if magnitude == 1:
            text = unit
        elif precedence(magnitude) < PRECEDENCE["Mul"]:
            text = f"({_PRINTER.doprint(magnitude)})*{unit}"
        else:
            text = f"{_PRINTER.doprint(magnitude)}*{unit}"
        out += (" - " if negative else " + ") + text if out else ("-" if negative else "") + text
    return out or zero


def _z_used(value) -> list:
    """The Z variables a value's expressions name directly."""
    return _by_number({s for e in _scalars_of(value) for s in getattr(e, "free_symbols", ())
                       if isinstance(s, Z)})


def _by_number(zs) -> list:
    return sorted(zs, key=lambda z: int(z.name[1:]) if z.name[1:].isdigit() else 0)


def _scalars_of(value) -> list:
    """The scalar expressions a value holds: a vector's or dyadic's measure numbers, a
    matrix's elements (which may themselves be vectors: `M = [N1>, N2>]`)."""
    if isinstance(value, Vector):
        return [c for comps in value.terms.values() for c in comps]
    if isinstance(value, Dyadic):
        return [x for m in value.terms.values() for x in m]
    if isinstance(value, (sm.MatrixBase, list, tuple)):
        elements = value if isinstance(value, (list, tuple)) else list(value)
        return [x for element in elements for x in _scalars_of(element)]
    return [sm.sympify(value)]


@dataclass(frozen=True)
class _Shown:
    """One response Autolev printed for an input: the name it displayed and the Autolev
    expression that reads our value of it right after that input."""

    name: str                 # N_A, I_A_AO>>, U1', FORCE_AO>, ZERO
    capture: str              # N_A, U1', ZERO
    whole: bool = False       # a matrix shown whole (a direction-cosine matrix)
    definition: bool = False  # a declared name: its definition then is shown
    work: bool = False        # NICHECK() in it: WCHECK1' (its work integral's rate) first


def transcript(path) -> str:
    """The `.all` transcript of the model at `path` (raises as autolev.load does)."""
    p = Path(path)
    program = parse(p)
    lines, line_of = _as_run(decode(reading.read_bytes(p)).splitlines(), program)
    responses: list[Response] = []
    shown_as: list[_Shown] = []
    massive: list[str] = []         # the mass centres and particles declared so far
    for st in program.statements:
        if isinstance(st, ir.Declaration) and st.what in ("bodies", "particles"):
            massive += [n + "O" if st.what == "bodies" else n
                        for item in st.items for n in item.names]
        if id(st) not in line_of:
            continue
        for s in _responses(st, program, massive):
            responses.append(Response(len(responses) + 1, line_of[id(st)], s.capture, "",
                                      line_of[id(st)]))
            shown_as.append(s)
    session = Session("\n".join(lines) + "\n", responses, str(p))
    parsed, refused = parse_responses(session)
    if refused:
        raise AutolevError(next(iter(refused.values())))
    replayed = replay(session, p, parsed)
    if replayed.error is not None:
        _raise_the_models_own_fault(p)
        raise AutolevError(replayed.error)
    model, captured = replayed.model, replayed.ours
    after: dict[int, list[int]] = {}
    for k, r in enumerate(responses):
        if k in captured:
            after.setdefault(r.after, []).append(k)
    out, number, response_lines = [], 0, _ResponseLines(model)
    for no, line in enumerate(lines, 1):
        if line.strip():                 # Autolev numbered no blank line (TD-all (3))
            number += 1
            out.append(f"   ({number}) {line}")
        for k in after.get(no, []):
            value, known = captured[k]
            if shown_as[k].definition and isinstance(value, sm.Symbol) and value in known:
                value = known[value]      # the definition then, not a later one
            # NICHECK() showed the rate of its work integral first (SSOpt (312))
            work = [(_Shown(f"{w.name}'", ""), known[derivative(w)])
                    for w in _work_integrals(value, known)] if shown_as[k].work else []
            for response, v in work + [(shown_as[k], value)]:
                for name, text in response_lines.lines(response, v):
                    number += 1
                    out.append(f"-> ({number}) {name} = {text}")
        if after.get(no):
            out.append("")
    return "\n".join(out) + "\n"


def _as_run(lines: list[str], program: ir.Program) -> tuple[list[str], dict[int, int]]:
    """The session's input lines as Autolev ran them: a RUN or a macro call replaced
    by the statements it brought in, one a line (a macro's with its #k# replaced), as
    SAVE recorded the lines of a file run (docs/language.md, "The responses of a
    session"); and the line each statement ends at, by the statement's id."""
    brought: dict[int, list[ir.Statement]] = {}     # by the RUN's or the call's line
    for st in program.statements:
        if isinstance(st, (ir.Run, ir.MacroCall)):
            continue      # a RUN or call inside a RUN file: its statements are brought too
        if st.span is not None and st.span.start.via is not None:
            where = st.span.start.via
            while where.via is not None:
                where = where.via
            brought.setdefault(where.line, []).append(st)
    ends: dict[int, list[ir.Statement]] = {}
    for st in program.statements:
        if st.span is not None and st.span.start.via is None:
            ends.setdefault(st.span.end.line, []).append(st)
    out: list[str] = []
    line_of: dict[int, int] = {}
    for no, line in enumerate(lines, 1):
        if no in brought:
            for st in brought[no]:
                out.append(" ".join(st.span.text.split("\n")))
                line_of[id(st)] = len(out)
            continue
        out.append(line)
        for st in ends.get(no, []):
            line_of[id(st)] = len(out)
    return out, line_of


def _raise_the_models_own_fault(p: Path) -> None:
    """Raise what loading the model itself raises, at the statement at fault: the text
    run with the captures has a line of its own after each response, so its lines are
    not the model's."""
    load(p)


# nodes of a scalar counted with every repetition (about 4 characters each printed):
# above this, each part it repeats is shown as a Z of its own first
LARGE = 2000


class _ResponseLines:
    """The responses' lines: each value after the Z variables it uses that were not
    shown yet.  Our model's Z's can be large where Autolev's were many and small (a
    derivative of a solved speed has a million nodes, 900 of them distinct); a large
    one is shown as AUTOZ showed such values, its repeated parts named by Z's of the
    transcript's own, numbered after the model's."""

    def __init__(self, model):
        self.model = model
        self.shown: set = set()                   # the model's Z's shown
        self.named: dict = {}                     # a repeated part -> its added Z
        self.pending: list = []                   # (Z, definition) to show next
        numbers = [int(z.name[1:]) for z in model.defs.rhs
                   if isinstance(z, Z) and z.name[1:].isdigit()]
        self.next_z = max(numbers, default=0) + 1

    def lines(self, shown: _Shown, value) -> list[tuple[str, str]]:
        """(name, text) of each line of a response: the Z's first, then a matrix of more
        than one element one element a line (`ZERO[1] = ...`, `A[1,2] = ...`), unless
        shown whole."""
        out = []
        for z in _z_chain(self.model, value, self.shown):
            out += self._line(expression(z), self.model.defs.rhs[z])
        if isinstance(value, (list, tuple)) and \
                any(isinstance(x, (Vector, Dyadic)) for x in value):
            # a column of vectors ([N1>; N2>]): one element a line, as a matrix's
            return out + [x for i, v in enumerate(value)
                          for x in self._line(f"{shown.name}[{i + 1}]", v)]
        if isinstance(value, (list, tuple)):
            value = sm.Matrix(value)
        if not isinstance(value, sm.MatrixBase) or shown.whole or len(value) == 1:
            return out + self._line(shown.name, value)
        if value.cols == 1:
            return out + [x for i in range(value.rows)
                          for x in self._line(f"{shown.name}[{i + 1}]", value[i, 0])]
        return out + [x for i in range(value.rows) for j in range(value.cols)
                      for x in self._line(f"{shown.name}[{i + 1},{j + 1}]", value[i, j])]

    def _line(self, name: str, value) -> list[tuple[str, str]]:
        text = expression(value, self._named)
        added, self.pending = self.pending, []
        return [(expression(z), expression(d)) for z, d in added] + [(name, text)]

    def _named(self, e):
        """e with its repeated parts named (`pending` gets their definitions), if large."""
        e = sm.sympify(e)
        order = _post_order(e)
        size: dict = {}
        for node in order:
            size[node] = 1 + sum(size[a] for a in node.args)
        if size[e] <= LARGE:
            return e
        uses = dict.fromkeys(order, 0)
        uses[e] = 1
        for node in reversed(order):             # each part before its own parts
            for a in node.args:
                uses[a] += uses[node]
        rebuilt: dict = {}
        for node in order:
            if node in self.named:
                rebuilt[node] = self.named[node]
                continue
            new = node.func(*(rebuilt[a] for a in node.args)) if node.args else node
            if uses[node] > 1 and not is_small(new):
                z = new_z(self.next_z)
                self.next_z += 1
                self.named[node] = z
                self.pending.append((z, new))
                new = z
            rebuilt[node] = new
        return rebuilt[e]


def _post_order(e) -> list:
    """The distinct subexpressions of e, each after its arguments."""
    order, seen, stack = [], set(), [(e, False)]
    while stack:
        node, done = stack.pop()
        if done:
            order.append(node)
            continue
        if node in seen:
            continue
        seen.add(node)
        stack.append((node, True))
        stack.extend((a, False) for a in node.args if a not in seen)
    return order


def _written(e: ir.Expr) -> str:
    """A name as the model wrote it (Q1', P_O_P>)."""
    if isinstance(e, ir.Name):
        return e.name + "'" * e.primes
    if isinstance(e, ir.VectorName):
        return e.text
    raise TypeError(f"not a name: {e!r}")


def _defined(program: ir.Program, name: str, target: ir.Expr) -> _Shown:
    """The response to a new value of `name`: a declared variable, constant or
    specified quantity shows its definition (`TORQUE = 10*SIN(...)`, SSOpt (287)),
    anything else its value."""
    declared = isinstance(target, ir.Name) and program.symbols.scalar(target.name) is not None
    return _Shown(name, name, definition=declared)


def _work_integrals(value, known: dict) -> list:
    """The integrals of NICHECK() in a value: WCHECK1, its rate defined (SSOpt (312))."""
    if not isinstance(value, sm.Expr):           # NICHECK() is a scalar
        return []
    return sorted((s for s in value.free_symbols if isinstance(s, sm.Symbol) and
                   re.fullmatch(r"WCHECK\d+", s.name) and derivative(s) in known),
                  key=lambda s: s.name)


def _responses(st: ir.Statement, program: ir.Program, massive: list[str]) -> list[_Shown]:
    """What Autolev displayed after the statement (docs/language.md, "The responses of
    a session"): nothing for most commands and declarations."""
    if isinstance(st, ir.Assignment):
        name = st.text.partition("=")[0].rstrip(":+-*/^ ").strip()
        nicheck = any(isinstance(e, ir.Call) and e.name.upper() == "NICHECK"
                      for e in ir.walk(st.value))
        return [replace(_defined(program, name, st.target), work=nicheck)]
    if isinstance(st, ir.InertiaStatement):
        return _inertia_responses(st, program)
    if not isinstance(st, ir.Command):
        return []
    c = st.call
    what, args = c.name.upper(), c.args
    names = [_written(a) if isinstance(a, (ir.Name, ir.VectorName)) else None for a in args]
    if what in ("SIMPROT", "DIRCOS") and len(args) >= 2 and None not in names[:2]:
        return [_Shown(f"{names[0]}_{names[1]}", f"{names[0]}_{names[1]}", whole=True)]
    if what == "KINDIFFS":
        return [_Shown(f"{n}'", f"{n}'", definition=True) for n in names[3:] if n is not None]
    if what == "SOLVE":
        unknowns = []
        for a in args[1:]:
            if isinstance(a, ir.NameRange):
                unknowns += a.names
            elif isinstance(a, ir.Matrix):
                unknowns += [x for row in a.rows for x in row]
            else:
                unknowns.append(a)
        return [_Shown(_written(u), _written(u), definition=True) for u in unknowns
                if isinstance(u, ir.Name)]
    if what in ("CONSTRAIN", "CONSTRAINT"):
        speeds = [_written(i) for a in args if isinstance(a, ir.Index)
                  for i in a.indices if isinstance(i, ir.Name)]
        return [_Shown(n, n, definition=True) for n in speeds + [f"{n}'" for n in speeds]]
    if what == "ANGVEL" and len(args) >= 2 and None not in names[:2]:
        return [_Shown(f"W_{names[1]}_{names[0]}>", f"W_{names[1]}_{names[0]}>")]
    if what in ("V2PTS", "V1PT", "A2PTS", "A1PT") and len(args) == 4 \
            and None not in (names[0], names[3]):
        vector = f"{what[0]}_{names[3]}_{names[0]}>"
        return [_Shown(vector, vector)]
    if what == "GRAVITY":
        targets = [n + "O" if _is_body(program, n) else n for n in names[1:] if n] \
            if len(args) > 1 else massive
        return [_Shown(f"FORCE_{t}>", f"FORCE_{t}>") for t in targets]
    if what in IN_PLACE and args and names[0] is not None:
        return [_defined(program, names[0], args[0])]
    return []


def _is_body(program: ir.Program, name: str) -> bool:
    entity = program.symbols.entity(name)
    return entity is not None and entity.kind == "body"


def _inertia_responses(st: ir.InertiaStatement, program: ir.Program) -> list[_Shown]:
    """INERTIA B, ... displayed `I_B_BO>>` (SSOpt (171), TD-all (18)); `INERTIA B_O`
    (about a point O) `I_B_O>>`; a value defined inline (`IB=expr`) before it."""
    shown = [_defined(program, name, ir.Name(name)) for name, _ in st.definitions]
    if _is_body(program, st.body):
        return shown + [_Shown(f"I_{st.body}_{st.body}O>>", f"I_{st.body}_{st.body}O>>")]
    pieces = st.body.split("_")
    for i in range(1, len(pieces)):
        body, point = "_".join(pieces[:i]), "_".join(pieces[i:])
        if _is_body(program, body) and program.symbols.entity(point) is not None:
            return shown + [_Shown(f"I_{body}_{point}>>", f"I_{body}_{point}>>")]
    return shown


def _z_chain(model, value, shown: set) -> list:
    """The Z variables a value needs that were not shown yet, each after those its own
    definition needs."""
    order: list = []

    def visit(z):
        if z in shown:
            return
        shown.add(z)
        # the definitions' own cache of their symbols: each Z's expression is walked once
        inner = model.defs.free(z) if z in model.defs.rhs else ()
        for used in _by_number(s for s in inner if isinstance(s, Z)):
            visit(used)
        order.append(z)
    for z in _z_used(value):
        visit(z)
    return [z for z in order if z in model.defs.rhs]
