"""What the translator knows of a name and of an expression it wrote: the kind of
a name (`NameKind`), the type of a value (`ValueType`), a name's entry (`Entry`) and a
written expression with its type and precedence (`Typed`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from enum import Enum
from fractions import Fraction

# precedence of the Python written for an expression
ATOM, POW, UNARY, MUL, ADD = 9, 7, 6, 5, 4


class ValueType(str, Enum):
    """What an expression is (`Typed.type`) and what a name holds (`Entry.type`)."""
    SCALAR = "scalar"
    VECTOR = "vector"
    VECTORS = "vectors"      # a row or column of vectors (PARTIALS, [V1>, V2>])
    DYADIC = "dyadic"
    MATRIX = "matrix"
    FRAME = "frame"
    POINT = "point"
    LIST = "list"
    STRING = "string"
    UNKNOWN = "unknown"      # after an error, or not known until run time

    def __str__(self) -> str:       # messages say "a vector", on every Python version
        return self.value

    def __format__(self, spec: str) -> str:
        return format(self.value, spec)


class NameKind(str, Enum):
    """What a name of the model is (`Entry.kind`): a declared scalar, an assigned value,
    an entity or a vector."""
    CONSTANT = "constant"
    VARIABLE = "variable"
    MOTIONVARIABLE = "motionvariable"
    SPECIFIED = "specified"
    IMAGINARY = "imaginary"
    VALUE = "value"
    NEWTONIAN = "newtonian"
    FRAME = "frame"
    BODY = "body"
    POINT = "point"
    PARTICLE = "particle"
    VECTOR = "vector"

    def __str__(self) -> str:       # messages say "a body", on every Python version
        return self.value

    def __format__(self, spec: str) -> str:
        return format(self.value, spec)


FRAME_KINDS = (NameKind.NEWTONIAN, NameKind.FRAME, NameKind.BODY)
POINT_KINDS = (NameKind.POINT, NameKind.PARTICLE)
ENTITY_KINDS = FRAME_KINDS + POINT_KINDS


@dataclass
class Typed:
    code: str
    type: ValueType
    prec: int = ATOM
    exact: Fraction | None = None      # value of a pure integer/rational expression
    node: object = None
    approx: float | None = None        # double value of a function of numbers (EXP(2))
    shape: tuple[int, int] | None = None   # rows and columns of a matrix, when known
    elements: tuple | None = None      # a matrix literal's elements (IR), row by row

    def wrapped(self, below: int) -> str:
        return f"({self.code})" if self.prec < below else self.code

    @property
    def double(self) -> float | None:
        """The value in double precision when it is a number (inf beyond a double)."""
        if self.approx is not None or self.exact is None:
            return self.approx
        if abs(self.exact) >= 10 ** 308:
            return math.inf if self.exact > 0 else -math.inf
        return float(self.exact)


@dataclass
class Entry:
    py: str
    kind: NameKind
    type: ValueType
    order: int = 0       # derivatives declared (scalars)
    shape: tuple[int, int] | None = None   # of a matrix value, while known
    elements: tuple | None = None      # of a matrix value written as a literal
