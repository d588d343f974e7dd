"""The functions a model's expressions hold, one record each (`FunctionSpec`): Autolev's
name and arguments, what the translator writes, the sympy function, the values in
double and complex precision, the derivative, and the spelling in every language a
program is printed in.  Every other place that knows a function reads it here: the
translator, the printers (C, Python, Fortran, Matlab), a program's walk and its numpy
fallback, the dual numbers, fastdiff and the complex walk of the definitions; a
function missing from one of them is a failing test (tests/engine/test_function_specs.py),
not a failing run.  Without sympy, so that a warm run reads it too.

A spelling is a callee (`sin`, `math.sin`: called with the printed arguments) or a
template whose `{0}`, `{1}` are the printed arguments; a two-argument template of a
function of any number of arguments nests (fmax(fmax(a, b), c)).  A differential is
d f for changes d of the arguments, written with operations that floats and sympy
both take: `m` is sympy, or the printed Python's functions by sympy's names.
"""
from __future__ import annotations

import cmath
import functools
import math
import re
from collections.abc import Callable
from dataclasses import dataclass


@dataclass(frozen=True)
class FunctionSpec:
    """One function: see the module's docstring."""

    # Autolev's name; None for a function only sympy's calculus writes (Heaviside, from
    # the derivative of MAX)
    autolev: str | None
    # sympy's function of this name (Int and Round: Autolev's own, in
    # runtime/sympy_functions.py); None for one Autolev writes with others (LOG10, SQR)
    sympy: str | None
    arity: int | None = 1                  # None: one or more arguments
    entrywise: bool = False                # of a matrix, entry by entry (else scalars)
    # what the translated Python calls: None for sympy's function (sm.<sympy>); SQR is
    # written as a power by the translator's own writer
    translation: str | None = None
    fixed_arguments: tuple[int, ...] = ()  # given after the model's (LOG10's base)
    # beyond this argument the exact value has more than a thousand digits: refused
    largest_exact_argument: int | None = None
    # the value of a number in double precision, as Autolev computed it (the translator
    # refuses one beyond a double's range)
    double: Callable | None = None
    # in complex double precision on sympy's principal branches, and the arguments on a
    # branch cut where cmath takes the other side (left to sympy)
    complex_double: Callable | None = None
    branch_cut: Callable | None = None
    differential: Callable | None = None   # None: sympy's own; none on dual numbers
    steps: bool = False                    # constant between jumps: its derivative is 0
    real_only: bool = False                # the rule holds of real arguments (else sympy's)
    hoisted: bool = False                  # a repeated call is computed once (codegen)
    c: str | None = None
    python: str | None = None              # on `math` and pyfunction's helpers
    # the numpy fallback's counterpart of the function of its own its Python calls
    # (math.asin: arcsin; _sign: sign); None where it calls another record's (SEC:
    # math.cos) or a builtin (MAX: max)
    numpy: str | None = None
    fortran: str | None = None
    matlab: str | None = None
    casadi: str | None = None              # on `casadi as ca` (symbolic: CasADi's SX)

    @property
    def name(self) -> str:
        """Autolev's name, else sympy's."""
        return self.autolev or self.sympy

    @property
    def callee(self) -> str | None:
        """What the translated Python calls with the arguments (None: SQR's power)."""
        if self.translation is not None:
            return self.translation
        return None if self.sympy is None else f"sm.{self.sympy}"

    @property
    def python_callee(self) -> str | None:
        """The function of its own its printed Python calls (`numpy` stands in for it)."""
        return None if self.numpy is None else self.calls("python")[0]

    def spelling(self, language: str) -> str | None:
        """Its spelling in `language` ("c", "python", "numpy", "fortran", "matlab",
        "casadi")."""
        return {"c": self.c, "python": self.python, "numpy": self.numpy,
                "fortran": self.fortran, "matlab": self.matlab, "casadi": self.casadi}[language]

    def calls(self, language: str) -> list[str]:
        """The names its spelling in `language` calls."""
        spelling = self.spelling(language)
        if spelling is None:
            return []
        return re.findall(r"([A-Za-z_][\w.]*)\(", written(spelling, ["x", "y"]))


def written(spelling: str, args: list[str]) -> str:
    """A call spelt `spelling` of arguments printed as `args`."""
    if "{" not in spelling:
        return f"{spelling}({', '.join(args)})"
    if "{1}" in spelling:
        return functools.reduce(spelling.format, args)
    return spelling.format(*args)


def called_names(language: str) -> frozenset[str]:
    """The names `language`'s spellings call (a program's names must not hide them)."""
    return frozenset(name for spec in FUNCTION_SPECS for name in spec.calls(language))


def _on_a_real_cut(z: complex) -> bool:
    return z.imag == 0 and abs(z.real) > 1


SIN = FunctionSpec(
    "SIN", "sin", entrywise=True, hoisted=True,
    double=math.sin, complex_double=cmath.sin,
    differential=lambda m, x, dx: m.cos(x) * dx,
    c="sin", python="math.sin", numpy="sin", fortran="SIN", matlab="sin", casadi="ca.sin")
COS = FunctionSpec(
    "COS", "cos", entrywise=True, hoisted=True,
    double=math.cos, complex_double=cmath.cos,
    differential=lambda m, x, dx: -m.sin(x) * dx,
    c="cos", python="math.cos", numpy="cos", fortran="COS", matlab="cos", casadi="ca.cos")
TAN = FunctionSpec(
    "TAN", "tan", entrywise=True, hoisted=True,
    double=math.tan, complex_double=cmath.tan,
    differential=lambda m, x, dx: (1 + m.tan(x) ** 2) * dx,
    c="tan", python="math.tan", numpy="tan", fortran="TAN", matlab="tan", casadi="ca.tan")
SEC = FunctionSpec(
    "SEC", "sec", entrywise=True,
    differential=lambda m, x, dx: m.tan(x) * m.sec(x) * dx,
    c="(1.0/cos({0}))", python="(1.0/math.cos({0}))", fortran="(1/COS({0}))",
    matlab="(1.0/cos({0}))", casadi="(1.0/ca.cos({0}))")
CSC = FunctionSpec(
    "CSC", "csc", entrywise=True,
    differential=lambda m, x, dx: -m.cot(x) * m.csc(x) * dx,
    c="(1.0/sin({0}))", python="(1.0/math.sin({0}))", fortran="(1/SIN({0}))",
    matlab="(1.0/sin({0}))", casadi="(1.0/ca.sin({0}))")
COT = FunctionSpec(
    "COT", "cot", entrywise=True,
    differential=lambda m, x, dx: (-1 - m.cot(x) ** 2) * dx,
    c="(1.0/tan({0}))", python="(1.0/math.tan({0}))", fortran="(1/TAN({0}))",
    matlab="(1.0/tan({0}))", casadi="(1.0/ca.tan({0}))")
ASIN = FunctionSpec(
    "ASIN", "asin", entrywise=True, hoisted=True,
    double=math.asin, complex_double=cmath.asin, branch_cut=_on_a_real_cut,
    differential=lambda m, x, dx: 1 / m.sqrt(1 - x * x) * dx,
    c="asin", python="math.asin", numpy="arcsin", fortran="ASIN", matlab="asin", casadi="ca.asin")
ACOS = FunctionSpec(
    "ACOS", "acos", entrywise=True, hoisted=True,
    double=math.acos, complex_double=cmath.acos, branch_cut=_on_a_real_cut,
    differential=lambda m, x, dx: -1 / m.sqrt(1 - x * x) * dx,
    c="acos", python="math.acos", numpy="arccos", fortran="ACOS", matlab="acos", casadi="ca.acos")
ATAN = FunctionSpec(
    "ATAN", "atan", entrywise=True, hoisted=True,
    double=math.atan, complex_double=cmath.atan,
    branch_cut=lambda z: z.real == 0 and abs(z.imag) > 1,
    differential=lambda m, x, dx: 1 / (1 + x * x) * dx,
    c="atan", python="math.atan", numpy="arctan", fortran="ATAN", matlab="atan", casadi="ca.atan")
ATAN2 = FunctionSpec(
    "ATAN2", "atan2", arity=2, hoisted=True,
    differential=lambda m, y, x, dy, dx: (x * dy - y * dx) / (x * x + y * y),
    c="atan2", python="math.atan2", numpy="arctan2", fortran="ATAN2", matlab="atan2",
    casadi="ca.atan2")
SINH = FunctionSpec(
    "SINH", "sinh", entrywise=True, hoisted=True,
    double=math.sinh, complex_double=cmath.sinh,
    differential=lambda m, x, dx: m.cosh(x) * dx,
    c="sinh", python="math.sinh", numpy="sinh", fortran="SINH", matlab="sinh", casadi="ca.sinh")
COSH = FunctionSpec(
    "COSH", "cosh", entrywise=True, hoisted=True,
    double=math.cosh, complex_double=cmath.cosh,
    differential=lambda m, x, dx: m.sinh(x) * dx,
    c="cosh", python="math.cosh", numpy="cosh", fortran="COSH", matlab="cosh", casadi="ca.cosh")
TANH = FunctionSpec(
    "TANH", "tanh", entrywise=True, hoisted=True,
    double=math.tanh, complex_double=cmath.tanh,
    differential=lambda m, x, dx: (1 - m.tanh(x) ** 2) * dx,
    c="tanh", python="math.tanh", numpy="tanh", fortran="TANH", matlab="tanh", casadi="ca.tanh")
ASINH = FunctionSpec(
    "ASINH", "asinh", entrywise=True,
    double=math.asinh,
    differential=lambda m, x, dx: 1 / m.sqrt(x * x + 1) * dx,
    c="asinh", python="math.asinh", numpy="arcsinh", fortran="ASINH", matlab="asinh",
    casadi="ca.asinh")
ACOSH = FunctionSpec(
    "ACOSH", "acosh", entrywise=True,
    double=math.acosh,
    differential=lambda m, x, dx: 1 / (m.sqrt(x - 1) * m.sqrt(x + 1)) * dx,
    c="acosh", python="math.acosh", numpy="arccosh", fortran="ACOSH", matlab="acosh",
    casadi="ca.acosh")
ATANH = FunctionSpec(
    "ATANH", "atanh", entrywise=True,
    double=math.atanh,
    differential=lambda m, x, dx: 1 / (1 - x * x) * dx,
    c="atanh", python="math.atanh", numpy="arctanh", fortran="ATANH", matlab="atanh",
    casadi="ca.atanh")
EXP = FunctionSpec(
    "EXP", "exp", entrywise=True, hoisted=True,
    double=math.exp, complex_double=cmath.exp,
    differential=lambda m, x, dx: m.exp(x) * dx,
    c="exp", python="math.exp", numpy="exp", fortran="EXP", matlab="exp", casadi="ca.exp")
LOG = FunctionSpec(
    "LOG", "log", entrywise=True, hoisted=True,
    double=math.log, complex_double=cmath.log,
    differential=lambda m, x, dx: 1 / x * dx,
    c="log", python="math.log", numpy="log", fortran="LOG", matlab="log", casadi="ca.log")
LOG10 = FunctionSpec("LOG10", None, translation="sm.log", fixed_arguments=(10,))
SQRT = FunctionSpec(
    "SQRT", "sqrt", entrywise=True,
    double=math.sqrt,
    differential=lambda m, x, dx: 1 / (2 * m.sqrt(x)) * dx,
    c="sqrt", python="math.sqrt", numpy="sqrt", fortran="SQRT", matlab="sqrt", casadi="ca.sqrt")
SQR = FunctionSpec("SQR", None)
ABS = FunctionSpec(
    "ABS", "Abs", entrywise=True,
    double=abs, complex_double=abs,
    differential=lambda m, x, dx: m.sign(x) * dx, real_only=True,
    c="fabs", python="math.fabs", numpy="abs", fortran="ABS", matlab="abs",
    casadi="ca.fabs")
SIGN = FunctionSpec(
    "SIGN", "sign", entrywise=True,
    steps=True, real_only=True,
    c="((double)((({0}) > 0) - (({0}) < 0)))", python="_sign", numpy="sign",
    fortran="(MERGE(1.0D0, 0.0D0, {0} .GT. 0) - MERGE(1.0D0, 0.0D0, {0} .LT. 0))", matlab="sign",
    casadi="ca.sign")
# sympy's second argument is its value at 0, which the programs take as 1/2
HEAVISIDE = FunctionSpec(
    None, "Heaviside", arity=2,
    steps=True, real_only=True,
    c="(({0}) > 0 ? 1.0 : (({0}) < 0 ? 0.0 : 0.5))", python="_heaviside({0})",
    numpy="_np_heaviside", fortran="MERGE(1.0D0, MERGE(0.0D0, 0.5D0, {0} .LT. 0), {0} .GT. 0)",
    casadi="ca.if_else({0} > 0, 1.0, ca.if_else({0} < 0, 0.0, 0.5))")
FLOOR = FunctionSpec(
    "FLOOR", "floor", entrywise=True,
    steps=True, real_only=True,
    c="floor", python="math.floor", numpy="floor", fortran="DBLE(FLOOR({0}, 8))", matlab="floor",
    casadi="ca.floor")
CEIL = FunctionSpec(
    "CEIL", "ceiling", entrywise=True,
    steps=True, real_only=True,
    c="ceil", python="math.ceil", numpy="ceil", fortran="DBLE(CEILING({0}, 8))", matlab="ceil",
    casadi="ca.ceil")
INT = FunctionSpec(
    "INT", "Int", translation="al.integer_part",
    steps=True, real_only=True,
    c="trunc", python="_trunc", numpy="trunc", fortran="AINT", matlab="fix",
    casadi="ca.if_else({0} < 0, ca.ceil({0}), ca.floor({0}))")
ROUND = FunctionSpec(
    "ROUND", "Round", translation="al.round_half_away",
    steps=True, real_only=True,
    c="round", python="_round", numpy="_np_round", fortran="ANINT", matlab="round",
    casadi="(ca.sign({0})*ca.floor(ca.fabs({0}) + 0.5))")
MAX = FunctionSpec(
    "MAX", "Max", arity=None, translation="al.maximum",
    c="fmax({0}, {1})", python="max", fortran="MAX", matlab="max({0}, {1})",
    casadi="ca.fmax({0}, {1})")
MIN = FunctionSpec(
    "MIN", "Min", arity=None, translation="al.minimum",
    c="fmin({0}, {1})", python="min", fortran="MIN", matlab="min({0}, {1})",
    casadi="ca.fmin({0}, {1})")
FACTORIAL = FunctionSpec(
    "FACTORIAL", "factorial", entrywise=True, largest_exact_argument=450,
    double=lambda v: math.gamma(v + 1),
    c="tgamma({0} + 1.0)", python="math.gamma({0} + 1.0)", fortran="GAMMA({0} + 1)",
    matlab="gamma({0} + 1.0)")
GAMMA = FunctionSpec(
    None, "gamma",
    c="tgamma", python="math.gamma", numpy="scipy.special.gamma", fortran="GAMMA", matlab="gamma")
ERF = FunctionSpec(
    None, "erf",
    differential=lambda m, x, dx: 2 / m.sqrt(m.pi) * m.exp(-x * x) * dx,
    c="erf", python="math.erf", numpy="scipy.special.erf", fortran="ERF", matlab="erf",
    casadi="ca.erf")

# the records: every FunctionSpec above, in order
FUNCTION_SPECS = tuple(v for v in globals().values() if isinstance(v, FunctionSpec))
FUNCTION_BY_NAME = {s.autolev: s for s in FUNCTION_SPECS if s.autolev is not None}
FUNCTION_BY_SYMPY = {s.sympy: s for s in FUNCTION_SPECS if s.sympy is not None}
