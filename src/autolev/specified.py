"""Specified quantities given values from outside the model: `--specified F=3*SIN(T)`
and `--set F=2` on the command line.

Autolev's programs leave a SPECIFIED quantity the model never defines as a line
`F = 0` under "Quantities to be specified" for the user to edit.  A value given here is
that edit: a definition of F in Autolev's syntax, an expression of T, numbers, the
model's constants and variables and the elementary functions, taken as if the model
had written `F = ...` before its CODE command.  The text is read with the grammar's
own expression rule and built into a sympy expression in the model's symbols; any
other construct (a vector, a matrix, a user function) is refused with its column.
"""
from __future__ import annotations

import sympy as sm

from . import ir
from .dispatch import Dispatch
from .errors import AutolevError, Diagnostic, Location
from .runtime import symbols as S
from .engine.functions import FUNCTION_BY_NAME


class SpecifiedValueError(AutolevError):
    """A value given for a specified quantity that cannot be one (with its diagnostic)."""

    def __init__(self, diagnostic: Diagnostic) -> None:
        super().__init__(diagnostic.message)
        self.diagnostics = [diagnostic]


def specified_definitions(model, items: dict[str, str], option: str) -> dict:
    """{symbol: sympy expression} for {NAME: Autolev expression} given by `option`
    (the option's name labels the diagnostics: '--specified', '--set')."""
    out = {}
    for name, text in items.items():
        written = f"{name} = {text}"
        where = _Where(option, written)
        statement = _parse(where)
        target = statement.target
        if not isinstance(target, ir.Name) or statement.op != "=":
            raise where.error(statement.span, "T010",
                              f"expected NAME=EXPRESSION, not {name!r}")
        sym = specified_symbol(model, target.name, target.primes)
        if sym is None:
            raise where.error(target.span, "T008", f"{name} is not a SPECIFIED quantity "
                              "of the model that it leaves undefined")
        out[sym] = _Builder(model, where).build(statement.value)
    return out


def specified_symbol(model, name: str, primes: int = 0):
    """The model's SPECIFIED quantity `name` (with `primes`) when the model leaves it
    undefined, else None."""
    try:
        sym = model.quantity(name + "'" * primes)
    except KeyError:
        return None
    base = S.base_and_order(sym)[0]
    if model.kind_of(base) != "specified" or sym in model.defs.rhs:
        return None
    return sym


class _Where:
    """The option and the text it gave, for diagnostics with a caret."""

    def __init__(self, option: str, text: str) -> None:
        self.option = option
        self.text = text

    def error(self, span, code: str, message: str) -> SpecifiedValueError:
        col = span.start.col if span is not None else 1
        return SpecifiedValueError(Diagnostic(Location(self.option, 1, col), code, message,
                                              source_line=self.text))


def _parse(where: _Where) -> ir.Assignment:
    if "\n" in where.text or "\r" in where.text:
        raise where.error(None, "T010", "expected one NAME=EXPRESSION, on one line")
    from .pipeline import parse      # the parser only for a --specified given
    try:
        program = parse(where.text, where.option)
    except AutolevError as exc:
        raise SpecifiedValueError(exc.diagnostics[0]) from None
    statements = program.statements
    if len(statements) != 1 or not isinstance(statements[0], ir.Assignment):
        raise where.error(None, "T010", "expected NAME=EXPRESSION")
    return statements[0]


class _Builder:
    """An Autolev scalar expression as a sympy expression in the model's symbols."""

    def __init__(self, model, where: _Where) -> None:
        self.model = model
        self.where = where

    def build(self, e: ir.Expr):
        return _EXPRESSIONS.lookup(type(e))(self, e)

    def refuse(self, e: ir.Expr, what: str):
        raise self.where.error(e.span, "T001", f"{what} cannot be a specified quantity's "
                               "value (an expression of T, numbers, the model's constants "
                               "and variables and elementary functions can)")


# what the constructs a value cannot hold are called in the refusal
_CONSTRUCTS = {ir.VectorName: "a vector", ir.Matrix: "a matrix", ir.Index: "an element",
               ir.Range: "a range", ir.Equation: "an equation", ir.NameRange: "a range"}


def _unsupported(b: _Builder, e: ir.Expr):
    b.refuse(e, _CONSTRUCTS.get(type(e), f"a {type(e).__name__}"))


_EXPRESSIONS: Dispatch = Dispatch("specified values", _unsupported)


@_EXPRESSIONS.register(ir.Number)
def _number(b: _Builder, e: ir.Number):
    return sm.Integer(e.value) if e.is_integer else sm.Float(e.value)


@_EXPRESSIONS.register(ir.Name)
def _name(b: _Builder, e: ir.Name):
    written = e.name + "'" * e.primes
    try:
        return b.model.quantity(written)
    except KeyError:
        pass
    if e.primes == 0 and e.name.upper() == "T":
        return S.TIME
    if e.primes == 0 and e.name.upper() == "PI":
        return sm.pi
    raise b.where.error(e.span, "T002", f"{written} is not a quantity of the model")


@_EXPRESSIONS.register(ir.Neg)
def _negation(b: _Builder, e: ir.Neg):
    return -b.build(e.operand)


_OPERATORS = {"+": lambda x, y: x + y, "-": lambda x, y: x - y, "*": lambda x, y: x * y,
              "/": lambda x, y: x / y, "^": lambda x, y: x ** y}


@_EXPRESSIONS.register(ir.BinOp)
def _binary(b: _Builder, e: ir.BinOp):
    return _OPERATORS[e.op](b.build(e.left), b.build(e.right))


@_EXPRESSIONS.register(ir.Call)
def _call(b: _Builder, e: ir.Call):
    name = e.name.upper()
    args = [b.build(a) for a in e.args]
    spec = FUNCTION_BY_NAME.get(name)
    # a function the translation writes as sympy's own is built here the same way
    if spec is not None and spec.callee is not None and spec.callee.startswith("sm.") \
            and spec.arity == len(args):
        return getattr(sm, spec.callee.removeprefix("sm."))(*args, *spec.fixed_arguments)
    return b.refuse(e, f"{name} with {len(args)} argument{'s' * (len(args) != 1)}")
