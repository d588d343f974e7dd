"""Helpers for equation tests: load an example, evaluate its expressions at
random states through the model's definitions, and build the same system with
sympy for an independent derivation."""
from __future__ import annotations

import random

import sympy as sm

import autolev
from autolev.runtime.calculus import NumericPoint
from autolev.runtime.symbols import derivative
from helpers import EXAMPLES


def example(name: str):
    """A fresh model of autolev_examples (tests may change it: none is shared)."""
    return autolev.load(EXAMPLES / f"{name}.al")


def symbols(model, *names):
    """The model's symbols by Autolev name; "Q1'" gives the derivative symbol."""
    out = []
    for n in names:
        base = n.rstrip("'")
        sym = model.loaded.namespace[model.loaded.names[base]]
        out.append(derivative(sym, len(n) - len(base)))
    return out if len(out) > 1 else out[0]


def value(model, expr, values: dict) -> float | sm.Matrix:
    """expr evaluated through the model's definitions at `values` (symbol -> number)."""
    point = NumericPoint(model.defs, values)
    if isinstance(expr, sm.MatrixBase):
        return expr.applyfunc(lambda e: sm.Float(model.defs.numeric(e, point).real))
    z = model.defs.numeric(expr, point)
    assert abs(z.imag) < 1e-12
    return z.real


def random_values(symbols, seed: int, low=-1.5, high=1.5) -> dict:
    rng = random.Random(seed)
    return {s: rng.uniform(low, high) for s in symbols}


def close(a, b, tol=1e-9) -> bool:
    a, b = sm.Matrix(a), sm.Matrix(b)
    scale = max(1.0, max(abs(float(x)) for x in b))
    return a.shape == b.shape and all(abs(float(x) - float(y)) <= tol * scale
                                      for x, y in zip(a, b))
