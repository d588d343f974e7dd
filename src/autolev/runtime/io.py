"""INPUT, OUTPUT, UNITS, ENCODE and CODE: what a model records for its numerics
(a mixin of Model).  The simulation itself lives in autolev.runtime.numerics."""
from __future__ import annotations

import sympy as sm

from .vector import AutolevModelError

INTEGRATION_PARAMETERS = ("TINITIAL", "TFINAL", "INTEGSTP", "PRINTINT", "ABSERR", "RELERR")


class IOMixin:
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
            raise AutolevModelError(f"INPUT({target}): no value was input for it")
        return self.inputs[key][0]

    def output(self, *items) -> None:
        """OUTPUT e1 [unit], e2, ...: one more output file, these columns."""
        cols = []
        for item in items:
            value, label = item[0], item[1]
            unit = item[2] if len(item) > 2 else None
            cols.append((value, label, unit))
        self.outputs.append(cols)

    def units(self, target, unit: str) -> None:
        """UNITS x = unit."""
        self.unit_of[target if not isinstance(target, str) else target.upper()] = unit

    def unit_system(self, *names: str) -> None:
        self.unit_system_names = tuple(names)

    def encode(self, *items) -> None:
        """ENCODE A, B: quantities the generated program evaluates."""
        self.encoded.extend(items)

    def code(self, kind: str, filename: str, args=None, sweep=None, options=()) -> None:
        """CODE DYNAMICS|ALGEBRAIC|NONLINEAR|ODE(args) file: a program to run."""
        self.code_commands.append((kind.lower(), filename, list(args or []), sweep,
                                   tuple(options)))
