"""INPUT, OUTPUT, UNITS, ENCODE and CODE: what a model records for its numerics (its
part IOStatements, and the statements' verbs, a mixin of Model).  Running them is
autolev.runtime.simulation's."""
from __future__ import annotations

from dataclasses import dataclass, field
from types import MappingProxyType

import sympy as sm

from ..engine.code_kinds import INTEGRATION_PARAMETERS, CodeKind
from ..engine.errors import AutolevModelError
from .derived import Owned, mutation
from .functions import degrees_to_radians
from .units import is_degrees

class IOStatements(Owned):
    """What INPUT, OUTPUT, UNITS, UNITSYSTEM, ENCODE and CODE recorded, in order (a part of
    Model, changed only through its methods)."""

    def __init__(self, revision) -> None:
        super().__init__(revision)
        self._inputs: dict = {}          # symbol or integration name -> (value, unit)
        self._outputs: tuple = ()        # one list of (expr, label, unit) per OUTPUT
        self._units: dict = {}           # UNITS x = unit
        self._unit_system: tuple = ()
        self._encoded: tuple = ()        # (name, value) of ENCODE
        self._commands: tuple = ()       # each CODE's CodeCommand

    @property
    def inputs(self) -> MappingProxyType:
        return MappingProxyType(self._inputs)

    @property
    def outputs(self) -> tuple:
        return self._outputs

    @property
    def unit_of(self) -> MappingProxyType:
        return MappingProxyType(self._units)

    @property
    def unit_system_names(self) -> tuple:
        return self._unit_system

    @property
    def encoded(self) -> tuple:
        return self._encoded

    @property
    def code_commands(self) -> tuple:
        return self._commands

    @mutation
    def input(self, key, value, unit: str | None) -> None:
        self._inputs[key] = (value, unit)

    @mutation
    def input_unless_given(self, key, value) -> None:
        self._inputs.setdefault(key, (value, None))

    @mutation
    def output(self, columns: list) -> None:
        self._outputs += (columns,)

    @mutation
    def units(self, key, unit: str) -> None:
        self._units[key] = unit

    @mutation
    def unit_system(self, names: tuple) -> None:
        self._unit_system = names

    @mutation
    def encode(self, items: tuple) -> None:
        self._encoded += items

    @mutation
    def code(self, command: CodeCommand) -> None:
        self._commands += (command,)


class IOMixin:
    """The statements' verbs; what they record is the model's `io` (IOStatements)."""

    @property
    def inputs(self) -> MappingProxyType:
        return self.io.inputs

    @property
    def outputs(self) -> list:
        return list(self.io.outputs)

    @property
    def unit_of(self) -> MappingProxyType:
        return self.io.unit_of

    @property
    def unit_system_names(self) -> tuple:
        return self.io.unit_system_names

    @property
    def encoded(self) -> list:
        return list(self.io.encoded)

    @property
    def code_commands(self) -> list:
        return list(self.io.code_commands)

    def input(self, target, value, unit: str | None = None) -> None:
        """INPUT x = value [unit]: a number for the numerics (value may be an expression
        of earlier inputs)."""
        if isinstance(target, str):
            key = target.upper()
            if key not in INTEGRATION_PARAMETERS:
                raise AutolevModelError(f"INPUT {target}: not a declared name")
            self.io.input(key, sm.sympify(value), unit)
            return
        if not isinstance(target, sm.Symbol):
            raise AutolevModelError(f"INPUT gives values to names, not to {target}")
        self.io.input(target, sm.sympify(value), unit)

    def input_value(self, target):
        """INPUT(x): the value INPUT gave to x."""
        key = target.upper() if isinstance(target, str) else target
        if key not in self.inputs:
            if isinstance(key, sm.Symbol) and key in self.defs.rhs:
                return self._input_value_of_definition(key)
            raise AutolevModelError(f"INPUT({target}): no value was input for it")
        value, unit = self.inputs[key]
        if is_degrees(unit):
            # the value the program stores, as Autolev's did: 30 DEG is pi/6; every
            # other unit (DEG/S too) is a label
            value = degrees_to_radians(value)
        return value

    def _input_value_of_definition(self, sym):
        """INPUT(x) of an x that has a definition but no INPUT value (a constant
        assigned `x = pi/2`): the definition's value under the input values."""
        expr = self.defs.explicit(sym)
        values = {}
        for s in sorted(expr.free_symbols, key=str):
            if s not in self.inputs and s not in self.defs.rhs:
                raise AutolevModelError(f"INPUT({sym}): {sym} = {expr} uses {s}, which has "
                                        "no INPUT value")
            values[s] = self.input_value(s)
        return expr.xreplace(values)

    def output(self, *items) -> None:
        """OUTPUT e1 [unit], e2, ...: one more output file, these columns."""
        cols = []
        for item in items:
            value, label = item[0], item[1]
            unit = item[2] if len(item) > 2 else None
            cols.append((value, label, unit))
        self.io.output(cols)

    def units(self, target, unit: str) -> None:
        """UNITS x = unit."""
        self.io.units(target if not isinstance(target, str) else target.upper(), unit)

    def unit_system(self, *names: str) -> None:
        self.io.unit_system(tuple(names))

    def encode(self, *items) -> None:
        """ENCODE A, B: quantities the generated program evaluates."""
        self.io.encode(tuple(items))

    def code(self, kind: str, filename: str, args=None, sweep=None, options=(),
             zero=None) -> None:
        """CODE DYNAMICS|ALGEBRAIC|NONLINEAR|ODE(args) file: a program to run, with the
        INPUT, OUTPUT and ENCODE statements given so far (as Autolev generated it then)."""
        try:
            typed = CodeKind(kind.lower())
        except ValueError:
            raise AutolevModelError(f"CODE {kind.upper()}: not a kind of program "
                                    "(DYNAMICS, ALGEBRAIC, NONLINEAR or ODE)") from None
        self.io.code(CodeCommand(
            typed, filename, list(args or []), sweep, tuple(options),
            n_outputs=len(self.outputs), n_encoded=len(self.encoded),
            inputs=dict(self.inputs), units=dict(self.unit_of),
            zero=None if zero is None else sm.Matrix(zero),
            definitions=self.defs.user_definitions()))


@dataclass
class CodeCommand:
    """One CODE statement and what was given before it."""

    kind: CodeKind
    filename: str
    args: list
    sweep: tuple | None
    options: tuple
    n_outputs: int = 0
    n_encoded: int = 0
    inputs: dict = field(default_factory=dict)
    units: dict = field(default_factory=dict)
    # ZERO as it stood at CODE time, when KANE() had marked it as the dynamics
    zero: object = None
    # the model's definitions at CODE time: a later statement (SOLVE after CODE
    # DYNAMICS) never changes a program already coded
    definitions: dict | None = None
