"""INPUT, OUTPUT, UNITS, ENCODE and CODE: what a model records for its numerics
(a mixin of Model).  Running them is autolev.runtime.simulation's."""
from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sm

from ..engine.code_kinds import INTEGRATION_PARAMETERS, CodeKind
from ..engine.errors import AutolevModelError
from .derived import mutation
from .functions import degrees_to_radians
from .units import is_degrees

class IOMixin:
    @mutation
    def input(self, target, value, unit: str | None = None) -> None:
        """INPUT x = value [unit]: a number for the numerics (value may be an expression
        of earlier inputs)."""
        if isinstance(target, str):
            key = target.upper()
            if key not in INTEGRATION_PARAMETERS:
                raise AutolevModelError(f"INPUT {target}: not a declared name")
            self.inputs[key] = (sm.sympify(value), unit)
            return
        if not isinstance(target, sm.Symbol):
            raise AutolevModelError(f"INPUT gives values to names, not to {target}")
        self.inputs[target] = (sm.sympify(value), unit)

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

    @mutation
    def output(self, *items) -> None:
        """OUTPUT e1 [unit], e2, ...: one more output file, these columns."""
        cols = []
        for item in items:
            value, label = item[0], item[1]
            unit = item[2] if len(item) > 2 else None
            cols.append((value, label, unit))
        self.outputs.append(cols)

    @mutation
    def units(self, target, unit: str) -> None:
        """UNITS x = unit."""
        self.unit_of[target if not isinstance(target, str) else target.upper()] = unit

    @mutation
    def unit_system(self, *names: str) -> None:
        self.unit_system_names = tuple(names)

    @mutation
    def encode(self, *items) -> None:
        """ENCODE A, B: quantities the generated program evaluates."""
        self.encoded.extend(items)

    @mutation
    def code(self, kind: str, filename: str, args=None, sweep=None, options=(),
             zero=None) -> None:
        """CODE DYNAMICS|ALGEBRAIC|NONLINEAR|ODE(args) file: a program to run, with the
        INPUT, OUTPUT and ENCODE statements given so far (as Autolev generated it then)."""
        try:
            typed = CodeKind(kind.lower())
        except ValueError:
            raise AutolevModelError(f"CODE {kind.upper()}: not a kind of program "
                                    "(DYNAMICS, ALGEBRAIC, NONLINEAR or ODE)") from None
        self.code_commands.append(CodeCommand(
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
