"""What a statement reads: its expressions, the plain names they read (not the words
some functions take as arguments, nor the left sides of x=v), and the derivatives
(primes) the program uses; the translator reports undeclared names from these."""
from __future__ import annotations

from typing import Callable

from .. import ir
from ..dispatch import Dispatch


def primes_used(program: ir.Program) -> set[tuple[str, int]]:
    used = set()
    for st in program.statements:
        for e in statement_exprs(st):
            for node in ir.walk(e):
                if isinstance(node, (ir.Name, ir.Index)) and node.primes:
                    used.add((node.name.lower(), node.primes))
    return used


def statement_exprs(st: ir.Statement):
    for value in vars(st).values():
        yield from _exprs_in(value)


def _exprs_in(value):
    if isinstance(value, ir.Expr):
        yield value
    elif isinstance(value, (list, tuple)):
        for v in value:
            yield from _exprs_in(v)
    elif hasattr(value, "__dataclass_fields__") and not isinstance(value, (ir.Unit,)):
        for v in vars(value).values():
            yield from _exprs_in(v)


# functions whose arguments hold words that are not names of the model (units,
# LINEAR/ANGULAR, rotation types, rotor shapes)
_WORD_ARGUMENTS = {"UNITS", "MOMENTUM", "GYROSTAT", "DIRCOS", "KINDIFFS", "ANGVEL"}


# the sub-expressions whose names an expression reads: its children, except as below
READS: Dispatch[Callable[[ir.Expr], tuple[ir.Expr, ...]]] = \
    Dispatch("names read", ir.no_children)
READS.register(ir.Expr)(ir.children)
# a range's generated names are not reported one by one
READS.register(ir.NameRange)(ir.no_children)
# the left side of x=v names what is substituted, not something read
READS.register(ir.Equation)(lambda e: (e.rhs,))


@READS.register(ir.Call)
def _arguments_read(c: ir.Call) -> tuple[ir.Expr, ...]:
    return () if c.name.upper() in _WORD_ARGUMENTS else c.args


def expression_names(e: ir.Expr):
    """The plain names read by an expression, in order (not the words some functions
    take as arguments, nor the left sides of x=v arguments)."""
    return (node for node in ir.walk(e, READS) if isinstance(node, ir.Name))
