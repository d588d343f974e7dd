"""A CODE command's equations of motion as text for people: LaTeX a paper can paste
(`autolev equations --latex`, `Model.latex()`), or plain sympy text (`--sympy`).

Both show what `autolev run` integrates (equations_of): each intermediate the equations
use (Autolev's Z's, the model's definitions) as a definition, in the order it is
computed; the rates of the states given explicitly (the kinematical differential
equations); and M u' = F for the rates solved from the mass matrix.
"""
from __future__ import annotations

import sympy as sm

from . import symbols as S
from .equations_of import Equations


def _used_definitions(eqs: Equations) -> list:
    """The definitions the rates, mass matrix and forcing need (not the outputs'), in
    the order they are computed."""
    roots = [e for e in eqs.rates if e is not None] + [e for row in eqs.mass for e in row] \
        + list(eqs.forcing)
    wanted = {s for e in roots for s in sm.sympify(e).free_symbols}
    needed = []
    for symbol, value in reversed(eqs.definitions):
        if symbol in wanted:
            needed.append((symbol, value))
            wanted |= sm.sympify(value).free_symbols
    return needed[::-1]


def _rates_not_defined(eqs: Equations, definitions: list) -> list:
    """(rate symbol, its expression) of each state with an explicit rate that is not
    among the definitions already shown (Q1' = U1 is one when an intermediate uses Q1')."""
    shown = {s for s, _ in definitions}
    return [(S.derivative(x), r) for x, r in zip(eqs.states, eqs.rates)
            if r is not None and S.derivative(x) not in shown]


def _latex_names(eqs: Equations, symbols) -> dict:
    """LaTeX of each derivative symbol (U1' as \\dot{U}_{1}, Q'' as \\ddot{Q})."""
    names = {}
    for s in symbols:
        if not isinstance(s, sm.Symbol):
            continue
        base, order = S.base_and_order(s)
        if order and base != s:
            accent = {1: "dot", 2: "ddot", 3: "dddot"}.get(order)
            inner = sm.latex(base)
            names[s] = f"\\{accent}{{{inner}}}" if accent else f"{inner}^{{({order})}}"
    return names


def latex(eqs: Equations) -> str:
    """The equations as LaTeX (amsmath): the definitions and explicit rates in an
    align*, then M u' = F written out."""
    definitions = _used_definitions(eqs)
    symbols = set(eqs.states) | set(eqs.unknowns) | {s for s, _ in definitions} \
        | {S.derivative(x) for x in eqs.states}
    for e in [v for _, v in definitions] + [r for r in eqs.rates if r is not None] \
            + [e for row in eqs.mass for e in row] + list(eqs.forcing):
        symbols |= sm.sympify(e).free_symbols
    names = _latex_names(eqs, symbols)

    def tex(e) -> str:
        return sm.latex(e, symbol_names=names)
    lines = [f"% {eqs.command} of {eqs.model_name}: the equations of motion autolev "
             "integrates", r"\begin{align*}"]
    rows = [f"  {tex(s)} &= {tex(v)}" for s, v in definitions]
    rows += [f"  {tex(rate)} &= {tex(r)}" for rate, r in _rates_not_defined(eqs, definitions)]
    lines.append(" \\\\\n".join(rows))
    lines.append(r"\end{align*}")
    if eqs.unknowns:
        n = len(eqs.unknowns)
        lines += [r"\begin{equation*}",
                  "  " + tex(sm.Matrix(n, n, [e for row in eqs.mass for e in row]))
                  + " " + tex(sm.Matrix(eqs.unknowns)) + " = " + tex(sm.Matrix(eqs.forcing)),
                  r"\end{equation*}"]
    return "\n".join(lines) + "\n"


def plain(eqs: Equations) -> str:
    """The equations as sympy's plain text: `NAME = expression` lines, then the mass
    matrix and forcing of `mass_matrix * unknowns = forcing`."""
    lines = [f"# {eqs.command} of {eqs.model_name}: the equations of motion autolev "
             "integrates"]
    definitions = _used_definitions(eqs)
    lines += [f"{s} = {sm.sstr(v)}" for s, v in definitions]
    lines += [f"{rate} = {sm.sstr(r)}" for rate, r in _rates_not_defined(eqs, definitions)]
    if eqs.unknowns:
        n = len(eqs.unknowns)
        lines += [f"unknowns = [{', '.join(map(str, eqs.unknowns))}]",
                  f"mass_matrix = {sm.sstr(sm.Matrix(n, n, [e for r in eqs.mass for e in r]))}",
                  f"forcing = {sm.sstr(sm.Matrix(eqs.forcing))}"]
    return "\n".join(lines) + "\n"
