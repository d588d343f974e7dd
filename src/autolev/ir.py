"""The intermediate representation: statements, expressions and the symbol table.

Knows nothing of ANTLR's parse tree or of the Python that is printed from it.
Names keep the spelling the user wrote; lookups go through `key()` (lower case),
because Autolev names are case-insensitive.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from typing import Callable, Iterator

from .dispatch import Dispatch
from .errors import Diagnostic, Span


def key(name: str) -> str:
    """The case-insensitive identity of an Autolev name."""
    return name.lower()


# ---------------------------------------------------------------------------
# Expressions.  Spans do not take part in equality, so trees compare by shape.

@dataclass(frozen=True)
class Expr:
    span: Span | None = field(default=None, compare=False, repr=False, kw_only=True)


@dataclass(frozen=True)
class Number(Expr):
    text: str                      # as written: '1.0E-07', '.5', '3'

    @property
    def is_integer(self) -> bool:
        return self.text.isdigit()

    @property
    def value(self) -> int | float:
        return int(self.text) if self.is_integer else float(self.text)

    @property
    def exact(self) -> Fraction:
        """The decimal as written, exactly (1.1 is 11/10, not the nearest double)."""
        return Fraction(self.text)


@dataclass(frozen=True)
class Name(Expr):
    name: str
    primes: int = 0                # q'' is Name('q', 2)

    @property
    def key(self) -> str:
        return key(self.name)


@dataclass(frozen=True)
class VectorName(Expr):
    """`N1>`, `P_A_B>`, `I_B_BO>>`; `0>` is the zero vector and `1>>` the unit dyadic."""

    name: str                      # without the '>' marks
    dyadic: bool = False

    @property
    def key(self) -> str:
        return key(self.name)

    @property
    def text(self) -> str:
        return self.name + (">>" if self.dyadic else ">")


@dataclass(frozen=True)
class Range(Expr):
    """`lo:hi` in argument lists and indices (degree ranges, row ranges, `x=a:dx`)."""

    lo: Expr
    hi: Expr


@dataclass(frozen=True)
class Equation(Expr):
    """`x=v` inside an argument list (EVALUATE, TAYLOR, REPLACE ...)."""

    lhs: Expr
    rhs: Expr


@dataclass(frozen=True)
class Call(Expr):
    name: str
    args: tuple[Expr, ...] = ()

    @property
    def key(self) -> str:
        return key(self.name)


@dataclass(frozen=True)
class Index(Expr):
    """`M[i]`, `M[i,j]` (1-based, as Autolev counts)."""

    name: str
    indices: tuple[Expr, ...]
    primes: int = 0

    @property
    def key(self) -> str:
        return key(self.name)


@dataclass(frozen=True)
class NameRange(Expr):
    """`dw{1:3}'` in an expression: the names dw1', dw2', dw3'."""

    text: str
    names: tuple[Name, ...]


@dataclass(frozen=True)
class Matrix(Expr):
    rows: tuple[tuple[Expr, ...], ...]


@dataclass(frozen=True)
class BinOp(Expr):
    op: str                        # one of + - * / ^
    left: Expr
    right: Expr


@dataclass(frozen=True)
class Neg(Expr):
    operand: Expr


def no_children(expr: Expr) -> tuple[Expr, ...]:
    return ()


# the sub-expressions of each node class, in the order they are written; a class
# registered nowhere is walked as a leaf (the translator reports it as unsupported)
CHILDREN: Dispatch[Callable[[Expr], tuple[Expr, ...]]] = Dispatch("children", no_children)
CHILDREN.register(Number, Name, VectorName)(no_children)
CHILDREN.register(BinOp)(lambda e: (e.left, e.right))
CHILDREN.register(Neg)(lambda e: (e.operand,))
CHILDREN.register(Range)(lambda e: (e.lo, e.hi))
CHILDREN.register(Equation)(lambda e: (e.lhs, e.rhs))
CHILDREN.register(Call)(lambda e: e.args)
CHILDREN.register(Index)(lambda e: e.indices)
CHILDREN.register(NameRange)(lambda e: e.names)
CHILDREN.register(Matrix)(lambda e: tuple(x for row in e.rows for x in row))


def children(expr: Expr) -> tuple[Expr, ...]:
    return CHILDREN.lookup(type(expr))(expr)


def walk(expr: Expr, table: Dispatch = CHILDREN) -> Iterator[Expr]:
    """Every node of an expression tree, parents first, descending into what `table`
    gives for each node (in a loop: a sum of thousands of terms is deeper than Python's
    recursion)."""
    stack = [expr]
    while stack:
        node = stack.pop()
        yield node
        stack.extend(reversed(table.lookup(type(node))(node)))


# ---------------------------------------------------------------------------
# Units: `kg*m^2`, `N/M/S^2`, `KG.M^2/S` become ((name, power), ...)

@dataclass(frozen=True)
class Unit:
    text: str                              # as written
    factors: tuple[tuple[str, int], ...]   # ('m', 1), ('sec', -2)
    span: Span | None = field(default=None, compare=False, repr=False)


# ---------------------------------------------------------------------------
# Statements

@dataclass(frozen=True)
class Statement:
    kind = "statement"
    span: Span | None = field(default=None, compare=False, repr=False, kw_only=True)
    text: str = field(default="", compare=False, repr=False, kw_only=True)  # the line as written


@dataclass(frozen=True)
class Declarator:
    """One declared item: `Q{3}'` declares q1', q2', q3'; `C+`; `B = 3`."""

    written: str
    names: tuple[str, ...]
    primes: int = 0
    sign: str | None = None        # '+' (nonnegative) or '-' (nonpositive)
    value: Expr | None = None
    shape: tuple[int, ...] = ()    # (3,) for Q{3}, (2, 3) for C{2,3}
    span: Span | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True)
class Declaration(Statement):
    kind = "declaration"
    what: str                      # newtonian frames bodies particles points constants
    #                                variables motionvariables specifieds imaginary
    items: tuple[Declarator, ...]
    keyword_primes: int = 0        # MOTIONVARIABLES' has 1


@dataclass(frozen=True)
class MassItem:
    target: str
    value: Expr
    value_of_value: Expr | None = None   # MASS B=mB=10 gives mB the value 10
    span: Span | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True)
class MassStatement(Statement):
    kind = "mass"
    items: tuple[MassItem, ...]


@dataclass(frozen=True)
class InertiaStatement(Statement):
    """INERTIA B, I11, I22, I33[, I12, I23, I31]; `B(A)` gives the frame of the
    components, `B_O(A)` the point.  `IB=expr` among the values defines IB inline."""

    kind = "inertia"
    body: str
    frame: str | None
    values: tuple[Expr, ...]
    definitions: tuple[tuple[str, Expr], ...] = ()


@dataclass(frozen=True)
class Assignment(Statement):
    kind = "assignment"
    target: Expr                   # Name (with primes), Index or VectorName
    op: str                        # = := += -= *= /= ^=
    value: Expr


@dataclass(frozen=True)
class Command(Statement):
    """A bare call: KANE(), SIMPROT(N, A, 3, q), EXPAND(E, 1:2), CONSTRAIN(...)."""

    kind = "command"
    call: Call


@dataclass(frozen=True)
class Display(Statement):
    """A bare expression: Autolev displays its value."""

    kind = "display"
    expr: Expr


@dataclass(frozen=True)
class InputItem:
    target: Expr                   # Name (maybe primed) or Index
    value: Expr
    unit: Unit | None = None
    span: Span | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True)
class Input(Statement):
    kind = "input"
    items: tuple[InputItem, ...]


@dataclass(frozen=True)
class OutputItem:
    expr: Expr
    unit: Unit | None = None
    span: Span | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True)
class Output(Statement):
    kind = "output"
    items: tuple[OutputItem, ...]


@dataclass(frozen=True)
class UnitsItem:
    targets: tuple[Name, ...]
    unit: Unit | None
    span: Span | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True)
class UnitsStatement(Statement):
    kind = "units"
    items: tuple[UnitsItem, ...]


@dataclass(frozen=True)
class UnitSystem(Statement):
    kind = "unitsystem"
    units: tuple[str, ...]


@dataclass(frozen=True)
class Sweep:
    """`[q deg = 0, 360, 1]` of CODE ALGEBRAIC: sweep an input over a range."""

    target: Name
    unit: Unit | None
    start: Expr
    stop: Expr
    step: Expr


@dataclass(frozen=True)
class Code(Statement):
    kind = "code"
    what: str                      # dynamics algebraic nonlinear ode
    args: tuple[Expr, ...]
    filename: str
    sweep: Sweep | None = None
    options: tuple[str, ...] = ()  # SUBS / NOSUBS


@dataclass(frozen=True)
class Save(Statement):
    kind = "save"
    filename: str


@dataclass(frozen=True)
class Encode(Statement):
    kind = "encode"
    exprs: tuple[Expr, ...]


@dataclass(frozen=True)
class Run(Statement):
    """RUN file: the included file's statements follow this one in the program."""

    kind = "run"
    filename: str
    path: str | None = None


@dataclass(frozen=True)
class MacroCall(Statement):
    """A call of a user macro NAME.A: its expanded statements follow this one."""

    kind = "macro"
    name: str
    args: tuple[str, ...]
    path: str | None = None


@dataclass(frozen=True)
class Exit(Statement):
    kind = "exit"


@dataclass(frozen=True)
class Setting(Statement):
    kind = "setting"
    name: str                      # upper case: AUTOZ, DEGREES, ...
    value: str | None              # upper case word or the number as written


# ---------------------------------------------------------------------------
# Symbols

FRAME_KINDS = ("newtonian", "frame", "body")
ENTITY_KINDS = ("newtonian", "frame", "body", "particle", "point")
SCALAR_KINDS = ("constant", "variable", "motionvariable", "specified", "imaginary")

DECLARATION_KINDS = {
    "newtonian": "newtonian", "frames": "frame", "bodies": "body",
    "particles": "particle", "points": "point", "constants": "constant",
    "variables": "variable", "motionvariables": "motionvariable",
    "specifieds": "specified", "imaginary": "imaginary",
}


@dataclass
class Symbol:
    name: str                      # declared spelling
    kind: str                      # newtonian frame body particle point constant variable
    #                                motionvariable specified imaginary
    primes: int = 0                # highest derivative declared (q'' -> 2)
    sign: str | None = None
    span: Span | None = field(default=None, compare=False, repr=False)
    implicit: bool = False         # NO, BO: created by NEWTONIAN N, BODIES B
    owner: str | None = None       # the frame or body an implicit point belongs to

    @property
    def key(self) -> str:
        return key(self.name)

    @property
    def namespace(self) -> str:
        """'entity' (frames, bodies, particles, points) or 'scalar'.

        Autolev keeps the two apart: a model may declare body LFF and constant LFF
        (its length), or body G and constant G (gravity)."""
        return "entity" if self.kind in ENTITY_KINDS else "scalar"


class SymbolTable:
    """Declared names by namespace and case-insensitive key, in declaration order."""

    def __init__(self) -> None:
        self._symbols: dict[tuple[str, str], Symbol] = {}

    def add(self, symbol: Symbol) -> Symbol | None:
        """Add or replace; returns the symbol it replaced, if any."""
        k = (symbol.namespace, symbol.key)
        previous = self._symbols.get(k)
        self._symbols[k] = symbol
        return previous

    def entity(self, name: str) -> Symbol | None:
        """The frame, body, particle or point of that name."""
        return self._symbols.get(("entity", key(name)))

    def scalar(self, name: str) -> Symbol | None:
        """The constant, variable, motion variable, specified or imaginary of that name."""
        return self._symbols.get(("scalar", key(name)))

    def lookup(self, name: str) -> list[Symbol]:
        """Every symbol of that name (an entity and a scalar may share one)."""
        return [s for s in (self.entity(name), self.scalar(name)) if s is not None]

    def __contains__(self, name: str) -> bool:
        return bool(self.lookup(name))

    def __iter__(self) -> Iterator[Symbol]:
        return iter(self._symbols.values())

    def __len__(self) -> int:
        return len(self._symbols)

    def of_kind(self, *kinds: str) -> list[Symbol]:
        return [s for s in self._symbols.values() if s.kind in kinds]


@dataclass
class Program:
    statements: list[Statement]
    symbols: SymbolTable
    filename: str
    diagnostics: list[Diagnostic] = field(default_factory=list)   # warnings only
    files: list[str] = field(default_factory=list)                # every file read
    sources: dict[str, list[str]] = field(default_factory=dict, repr=False)  # their lines

    def of_kind(self, kind: str) -> list[Statement]:
        return [s for s in self.statements if s.kind == kind]
