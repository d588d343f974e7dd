"""Input values of a run: INPUT statements, Autolev's defaults, `.in` files, overrides.

Every value is kept twice: as the user gives it (in the quantity's unit, degrees for
a `DEG` input) and internally (radians).  INPUT values may be expressions of other
inputs and of definitions (`INPUT IA3 = (1/12)*MA*L^2`, `INPUT E4 = COS(Q1/2)`); they
are evaluated with the other inputs' internal values.

The `.in` file is Autolev's: six header lines, then one line per value with the
description, the name and the unit in fixed columns and the value after the `|` in
column 59 (read from column 60).  Constants come first, then the initial values of the
states, then the integration parameters, each group alphabetical.  Legacy files are
read by name (`Q1'` and `Q1p` both name Q1'), so a file from another revision of the
model still works for the names it shares (the others are reported).
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from pathlib import Path

import sympy as sm

from ...engine import reading
from .. import units
from ..calculus import is_real_number
from ...errors import some_names
from ...engine.errors import AutolevModelError
from ..io import INTEGRATION_PARAMETERS as INTEGRATION
from ..symbols import TIME
from ...engine.numbers import format_value, in_file_lines, parse_number

DEFAULTS = {"TINITIAL": 0.0, "TFINAL": 1.0, "INTEGSTP": 0.1, "PRINTINT": 1,
            "ABSERR": 1.0e-8, "RELERR": 1.0e-7}
DESCRIPTIONS = {"TINITIAL": "Initial Time", "TFINAL": "Final Time",
                "INTEGSTP": "Integration Step", "PRINTINT": "Print-Integer",
                "ABSERR": "Absolute Error", "RELERR": "Relative Error"}


# where a value nothing gave comes from (0, as Autolev's programs took it)
DEFAULT_SOURCE = "default (no INPUT)"

class InputFileError(AutolevModelError):
    """A malformed `.in` file (carries file and line)."""


@dataclass
class Value:
    """One input: its value as given (in `unit`) and where it came from."""

    given: float
    unit: str | None
    source: str             # INPUT, default, file:line, override

    @property
    def internal(self) -> float:
        return units.to_internal(self.given, self.unit)


def key_of(sym_or_name):
    return sym_or_name.upper() if isinstance(sym_or_name, str) else sym_or_name


def display_name(key) -> str:
    return key if isinstance(key, str) else "T" if key == TIME else key.name


class Inputs:
    """The values of one run, keyed by symbol (or integration parameter name)."""

    def __init__(self, defs, names: list, given: dict, unit_table: dict,
                 integration=INTEGRATION):
        """`defs`: the definitions an INPUT expression reads; `given`: the INPUT
        statements' {key: (value, unit)}; `unit_table`: UNITS {key: unit}."""
        self.defs = defs
        self.given = given
        self.unit_table = unit_table
        self.integration = tuple(integration)
        self.names = tuple(names) + self.integration   # file order
        # each key by its name in capitals (a lookup per name of a long .in file)
        self._by_name = {display_name(k).upper(): k for k in self.names}
        self.values: dict = {}
        self._evaluate_model_inputs()

    # -- from the model ---------------------------------------------------------------
    def unit_of(self, key) -> str | None:
        given = self.given.get(key)
        if given is not None and given[1]:
            return given[1]
        return self.unit_table.get(key if not isinstance(key, str) else key.upper())

    def _evaluate_model_inputs(self) -> None:
        cache: dict = {}
        for key in list(self.given):
            self._evaluate(key, cache, ())
        for key, v in cache.items():
            self.values[key] = Value(v, self.unit_of(key), "INPUT")
        for name in self.integration:
            if name not in self.values:
                self.values[name] = Value(DEFAULTS[name], None, "default")

    def _evaluate(self, key, cache: dict, stack: tuple) -> float:
        """The value of an INPUT as given (its unit), evaluating expressions."""
        if key in cache:
            return cache[key]
        if key in stack:
            raise AutolevModelError("INPUT values refer to each other: "
                                    + " -> ".join(display_name(k) for k in stack + (key,)))
        expr, unit = self.given[key]
        value = self._number(sm.sympify(expr), cache, stack + (key,))
        cache[key] = value
        return value

    def _number(self, expr, cache, stack) -> float:
        # INPUT L = 0.5 or N = 3: the double N() gives (sympy's evaluation is most of
        # a warm run's set-up; N() rounds other rationals and larger integers its way)
        if expr.is_Float and expr.is_finite or expr.is_Integer and abs(expr) <= 2 ** 53:
            return float(expr)
        defs = self.defs
        subs = {}
        for f in expr.free_symbols:
            subs[f] = self._symbol_value(f, cache, stack, defs)
        v = complex(sm.N(expr.xreplace(subs)) if subs else sm.N(expr))
        if not is_real_number(v):
            raise AutolevModelError(f"INPUT {display_name(stack[-1])} is not a real number "
                                    f"({v})")
        return v.real

    def _symbol_value(self, f, cache, stack, defs) -> float:
        if f in self.given:
            given = self._evaluate(f, cache, stack)
            return units.to_internal(given, self.unit_of(f))
        if f in defs.rhs:
            return self._number(defs.rhs[f], cache, stack)
        raise AutolevModelError(f"INPUT {display_name(stack[-1])}: {f} has no value "
                                "(give it an INPUT value first)")

    # -- access ----------------------------------------------------------------------
    def internal(self, key) -> float:
        return self.values[key].internal

    def vector(self, keys) -> list[float]:
        return [self.internal(k) for k in keys]

    def check_finite(self) -> None:
        """Every value a number: NaN or an infinity (from an .in file, an override or
        an INPUT expression) is refused, naming the quantity and where it came from;
        PRINTINT a count the programs can hold."""
        printint = self.values.get("PRINTINT")
        if printint is not None and not is_print_integer(printint.given):
            raise AutolevModelError(f"{PRINTINT_RULE}, not {printint.given:g} (from "
                                    f"{printint.source})")
        negative = [(k, v) for k, v in self.values.items()
                    if k in ("ABSERR", "RELERR") and v.given < 0]
        if negative:
            raise AutolevModelError("error tolerances cannot be negative: " + "; ".join(
                f"{k} = {v.given:g} (from {v.source})" for k, v in negative))
        bad = [(k, v) for k, v in self.values.items() if not math.isfinite(v.given)]
        if bad:
            raise AutolevModelError(
                "inputs must be finite numbers: " + "; ".join(
                    f"{display_name(k)} = {v.given} (from {v.source})" for k, v in bad))
        overflowing = [(k, v) for k, v in self.values.items() if not math.isfinite(v.internal)]
        if overflowing:
            raise AutolevModelError("inputs beyond double precision once converted to "
                                    "radians: " + "; ".join(
                                        f"{display_name(k)} = {v.given:g} {self.unit_of(k)} "
                                        f"(from {v.source})" for k, v in overflowing))

    def missing(self, keys) -> list:
        return [k for k in keys if k not in self.values]

    def fill_missing(self, keys, source: str = DEFAULT_SOURCE) -> list:
        """Give 0 to keys without a value; returns them."""
        missing = self.missing(keys)
        for k in missing:
            self.values[k] = Value(0.0, self.unit_of(k), source)
        return missing

    def set(self, name: str, value, source: str = "override") -> None:
        """NAME=VALUE from the command line or the API: value in the quantity's unit."""
        key = self.lookup(name)
        if key is None:
            known = ", ".join(display_name(k) for k in self.names)
            raise AutolevModelError(f"no input named {name!r} (inputs: {known})")
        if isinstance(value, str):
            number = parse_number(value)
            if number is None:
                raise AutolevModelError(f"{name}={value}: not a number")
            value = number
        value = float(value)
        if key == "PRINTINT" and not is_print_integer(value):
            raise AutolevModelError(PRINTINT_RULE)
        self.values[key] = Value(value, self.unit_of(key), source)

    def set_internal(self, name: str, value: float, source: str = "operating point") -> None:
        """NAME=VALUE in SI units and radians (whatever unit the input was given in)."""
        key = self.lookup(name)
        if key is None or key in self.integration:
            known = ", ".join(display_name(k) for k in self.names if k not in self.integration)
            raise AutolevModelError(f"no quantity named {name!r} here (known: {known})")
        unit = self.unit_of(key)
        given = units.to_output(float(value), unit)
        self.values[key] = Value(given, unit, source)

    def lookup(self, name: str):
        """The key called `name` (any case; Q1p and Q1' are the same)."""
        wanted = name.strip()
        up = wanted.upper()
        if up == "INTEGSTEP":
            up = "INTEGSTP"
        if up in self.integration:
            return up
        cands = self._by_name
        if up in cands:
            return cands[up]
        for k in range(1, len(up) - len(up.rstrip("P")) + 1):
            primed = up[:-k] + "'" * k          # Q1P -> Q1', Q1PP -> Q1''
            if primed in cands:
                return cands[primed]
        if up.endswith("_") and up.rstrip("_"):
            # a program of `autolev code` writes a name its language uses with _ added
            return self.lookup(wanted.rstrip("_"))
        return None

    # -- .in files ---------------------------------------------------------------------
    def read_file(self, path, elsewhere=lambda name: False, program: str = "") -> list[str]:
        """Values from an Autolev `.in` file; returns warnings (unknown names).  A name
        `elsewhere` knows (the model's, an input of another of its programs) is said to
        be no input of `program` (e.g. "CODE ALGEBRAIC fk.c"), not of the model."""
        path = Path(path)
        try:
            raw = reading.read_bytes(path)
        except OSError as exc:
            raise InputFileError(f"{path}: cannot read ({exc.strerror})") from None
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError:
            text = raw.decode("latin-1")
        notes = []
        entries = []                       # (lineno, name, value, file unit)
        for lineno, name, raw, file_unit in in_file_lines(text):
            value = parse_number(raw)
            if value is None:
                raise InputFileError(f"{path}:{lineno}:60: expected a number for {name}, "
                                     f"found {raw!r}")
            entries.append((lineno, name, value, file_unit))
        if not entries:
            raise InputFileError(f"{path}: no values found (expected Autolev's layout: "
                                 "a '|' in column 59 and the value from column 60)")
        keys = [self.lookup(name) for _, name, _, _ in entries]
        if None in keys and len(entries) == len(self.names):
            # Autolev's programs read the values in order, whatever the labels say
            keys = list(self.names)
            notes.append(f"{path}: its names do not all match this model's; its "
                         f"{len(entries)} values are taken in Autolev's order (constants, "
                         "initial values, integration parameters), as Autolev's programs "
                         "read them")
        strangers = []                     # (line, name) not inputs of this model
        others = []                        # ... the model's, but not this program's
        first_line: dict = {}              # key -> the line that gave it
        for key, (lineno, name, value, file_unit) in zip(keys, entries):
            if key is None:
                (others if program and elsewhere(name) else strangers).append((lineno, name))
                continue
            if key in first_line:
                raise InputFileError(f"{path}:{lineno}:22: {name} is given twice (line "
                                     f"{first_line[key]} and here)")
            first_line[key] = lineno
            if key == "PRINTINT" and not is_print_integer(value):
                raise InputFileError(f"{path}:{lineno}:60: {PRINTINT_RULE}")
            unit = self.unit_of(key)
            if units.is_degrees(file_unit) != units.is_degrees(unit) and file_unit.upper() \
                    not in ("", "UNITS"):
                notes.append(f"{path}:{lineno}: {name} is given in {file_unit} but the model "
                             f"uses {unit or 'no unit'}; read as {unit or 'a plain number'}")
            self.values[key] = Value(value, unit, f"{path.name}:{lineno}")
        for unread, whose, how in ((others, program, "ignored there"),
                                   (strangers, "this model", "ignored")):
            if unread:
                notes.append(f"{path}:{unread[0][0]}: " + some_names(n for _, n in unread)
                             + (" is not an input" if len(unread) == 1 else
                                f" ({len(unread)} names) are not inputs")
                             + f" of {whose}; {how}")
        found = set(keys)
        absent = [k for k in self.names if k not in found]
        if absent:
            notes.append(f"{path}: no value for " + some_names(map(display_name, absent))
                         + " (a file cut short?); "
                         + ("it keeps its" if len(absent) == 1 else "they keep their")
                         + " INPUT value or default")
        return notes

    def read_file_over_model(self, path, constants, elsewhere=lambda name: False,
                             program: str = "") -> list[str]:
        """read_file, except that a file whose constants are all 0 (the template many
        repositories ship, never filled in) gives none of them: they keep the model's
        INPUT values, or have none."""
        before = {k: self.values[k] for k in constants if k in self.values}
        notes = self.read_file(path, elsewhere, program)
        name = Path(path).name
        read = [k for k in constants
                if k in self.values and self.values[k].source.startswith(name + ":")]
        if read and all(self.values[k].given == 0 for k in read):
            notes.append(f"{path}: every constant in it is 0 (a template never filled "
                         "in?): taken as giving none")
            for k in read:
                if k in before:
                    self.values[k] = before[k]
                else:
                    del self.values[k]
        return notes

    def file_text(self, title: str, kinds: dict, fortran: bool = False) -> str:
        """The `.in` file of these values, in Autolev 4.1's layout; kinds: key ->
        description ("Constant", ...).  `fortran`: in the layout of Autolev 3.2's Fortran
        programs, whose third line is the message they copy into every output file
        and whose descriptions end in a colon."""
        lines = [f"File: {title}",
                 "-" * 77,
                 FORTRAN_MESSAGE if fortran else
                 "Note: Use spaces not tabs while editing this file.",
                 "-" * 58 + "+" + "-" * 18,
                 f"{'Description':<21}{'Quantity':<21}{'Units':<16}| Value",
                 "-" * 58 + "|" + "-" * 18]
        previous = None
        for key in self.names:
            kind = DESCRIPTIONS[key] if key in INTEGRATION else kinds[key]
            group = "integration" if key in INTEGRATION else kind
            if previous is not None and group != previous:
                lines.append("")
            previous = group
            v = self.values[key]
            if key in INTEGRATION:
                unit = {"PRINTINT": "Positive Integer", "ABSERR": "",
                        "RELERR": ""}.get(key, (self.unit_of("T") or "UNITS").upper())
                text = f" {int(v.given)}" if key == "PRINTINT" else format_value(v.given)
            else:
                unit = (v.unit or "UNITS").upper()
                text = format_value(v.given)
            name = display_name(key)
            if fortran:
                kind, text = kind + ":", " " + text
            lines.append(f"{kind:<21}{name:<21}{unit[:16]:<16}|{text}")
        lines.append("-" * 58 + "+" + "-" * 18)
        if fortran:
            lines += ["", "Note: Use spaces not tabs while editing this file; the message "
                      "line above", "      is printed at the top of every output file."]
        if "INTEGSTP" in self.integration:
            lines += ["", "  INTEGSTP*PRINTINT is the time-interval for writing of output.",
                      "  ABSERR and RELERR are the absolute and relative error tolerances of "
                      "the integrator."]
        return "\n".join(lines) + "\n"


# the third line of the .in file of Autolev 3.2's Fortran programs, which they read
# as a message (99 characters) and print at the top of every output file
FORTRAN_MESSAGE = "Replace this line with a message to appear on all output files."


# Autolev's programs count PRINTINT steps in a C int
MAX_PRINT_INTEGER = 2 ** 31 - 1
PRINTINT_RULE = f"PRINTINT must be a whole number from 1 to {MAX_PRINT_INTEGER}"


def is_print_integer(value: float) -> bool:
    return math.isfinite(value) and value == int(value) and 1 <= value <= MAX_PRINT_INTEGER


def warn_zero(keys, what: str) -> None:
    if keys:
        names = ", ".join(display_name(k) for k in keys)
        warnings.warn(f"no INPUT value for {what} {names}: using 0", stacklevel=3)
