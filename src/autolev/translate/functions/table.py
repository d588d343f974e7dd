"""The table of Autolev's functions: each name's writer, registered by its family's
module with `@function("NAME")`, and what a name the table lacks is told (T003)."""
from __future__ import annotations

import difflib

from ... import ir
from ..core import EXPRESSIONS, Translator
from ..kinds import Typed

FUNCTIONS: dict = {}
# functions nested deeper than this make sympy's automatic evaluation exponential (the
# real-imaginary split of TANH(SINH(...)) 150 deep runs for hours); models nest three
MAX_CALL_NESTING = 32


def function(*names):
    def register(fn):
        for n in names:
            FUNCTIONS[n] = fn
        return fn
    return register


@EXPRESSIONS.register(ir.Call)
def call_expression(tr: Translator, e: ir.Call, want: str) -> Typed:
    if tr.call_depth >= MAX_CALL_NESTING:
        raise tr.error(f"functions nested more than {MAX_CALL_NESTING} deep; at most "
                       f"{MAX_CALL_NESTING} are translated (name the inner parts)",
                       e, "T004")
    tr.call_depth += 1
    try:
        return call(tr, e)
    finally:
        tr.call_depth -= 1


def call(tr: Translator, c: ir.Call) -> Typed:
    fn = FUNCTIONS.get(c.name.upper())
    if fn is None:
        raise tr.error(f"unknown function {c.name.upper()}(): Autolev has no such function, "
                       f"and no user function file {c.name}.R is next to the model"
                       + did_you_mean(c.name, FUNCTIONS), c, "T003")
    return fn(tr, c)


def did_you_mean(word: str, known) -> str:
    """'; did you mean A, B or C?' for the known words closest to a misspelt one."""
    close = difflib.get_close_matches(word.upper(), known, n=3, cutoff=0.6)
    if not close:
        return ""
    return "; did you mean " + (" or ".join(close) if len(close) < 3 else
                                f"{close[0]}, {close[1]} or {close[2]}") + "?"


def nargs(tr: Translator, c: ir.Call, *counts: int) -> list:
    if len(c.args) not in counts:
        want = " or ".join(str(n) for n in counts)
        raise tr.error(f"{c.name.upper()} takes {want} argument"
                       f"{'s' if counts != (1,) else ''}, not {len(c.args)}", c, "T007")
    return list(c.args)
