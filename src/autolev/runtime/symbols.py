"""Symbols of a model: time, constants, time-varying variables and their derivatives,
and the intermediate Z variables the engine introduces.

Time-varying quantities are plain sympy Symbols (fast to differentiate); the link
between a variable and its derivatives is kept here, by name: the derivative of the
symbol `Q1` is the symbol `Q1'`, whatever model asks.  So `Q1'` prints as Autolev
wrote it, and `dt(Q1) == Q1'` holds everywhere.
"""
from __future__ import annotations

import functools

import sympy as sm

class _Time(sm.Symbol):
    """The class of Autolev's T alone: a model's own quantity named t or T (CONSTANTS t)
    is a symbol of another class, so the two are never the same sympy symbol."""


#: Autolev's T: the independent variable.
TIME = _Time("t", real=True)



class Z(sm.Dummy):
    """An intermediate variable (Autolev's Z): a name for a subexpression, defined in
    a model's definitions table.  Unique per creation, printed as z<n>."""

    def _sympystr(self, printer) -> str:
        return self.name

    def _latex(self, printer) -> str:
        return "z_{%s}" % self.name[1:]


def new_z(number: int) -> Z:
    """Z number `number` of a definitions table.  Numbered per table, not per process:
    the names decide the order of terms in sums, so a model's generated code (and its
    rounding) must not depend on what else the process built before."""
    return Z(f"z{number}", real=True)


def _assumptions(sym: sm.Symbol) -> dict:
    return {k: v for k, v in sym.assumptions0.items()
            if k in ("real", "complex", "nonnegative", "nonpositive", "positive",
                     "negative") and v is not None}


def scalar(name: str, real: bool = True, sign: str | None = None) -> sm.Symbol:
    """A constant or variable named as the user declared it."""
    kw: dict = {"real": True} if real else {}
    if sign == "+":
        kw["nonnegative"] = True
    elif sign == "-":
        kw["nonpositive"] = True
    return sm.Symbol(name, **kw)


def derivative(sym: sm.Symbol, n: int = 1) -> sm.Symbol:
    """The symbol of the n-th time derivative of `sym` (`Q1` -> `Q1'`)."""
    if n == 0:
        return sym
    base, order = base_and_order(sym)
    return sm.Symbol(base.name + "'" * (order + n), **_assumptions(base))


@functools.lru_cache(maxsize=8192)
def base_and_order(sym: sm.Symbol) -> tuple[sm.Symbol, int]:
    """(`Q1`, 2) for `Q1''`; (`x`, 0) for any symbol that is not a derivative.  Read
    from the name (no Autolev name has a quote; a derivative symbol has the base's
    assumptions), so that no registry of every derivative made grows with the process."""
    if type(sym) is not sm.Symbol:
        return sym, 0
    name = sym.name
    base = name.rstrip("'")
    if base == name or not base:
        return sym, 0
    return sm.Symbol(base, **_assumptions(sym)), len(name) - len(base)


def derivatives(*syms: sm.Symbol, order: int = 1) -> tuple[sm.Symbol, ...] | sm.Symbol:
    """Derivative symbols of several variables: `Q1p, Q2p = derivatives(Q1, Q2)`."""
    out = tuple(derivative(s, order) for s in syms)
    return out[0] if len(out) == 1 else out
