"""Differentiation of sympy expressions in one memoised pass.

sympy's `diff` builds a `Derivative` at every level and asks each subtree for its
free symbols, which is quadratic in the size of the expression; on the expressions
real models make (pasted Autolev output, long sums of Z products) that dominates.
This walks the tree once, knows which subtrees contain the variable, and applies
the chain rule for the functions models use; anything else falls back to sympy.
"""
from __future__ import annotations

from functools import cmp_to_key

import sympy as sm
from sympy.functions.elementary.exponential import ExpBase

from .sympy_functions import SPEC_OF_FUNCTION

_ONE, _ZERO, _I = sm.S.One, sm.S.Zero, sm.S.ImaginaryUnit


# the records with a rule here: those a model writes (one only sympy's calculus writes,
# as the Heaviside step of MAX's derivative, keeps sympy's own: DiracDelta)
_RULES = {f: s for f, s in SPEC_OF_FUNCTION.items()
          if s.autolev is not None and (s.differential is not None or s.steps)}


def _rule(func, args):
    """The record whose rule differentiates func(*args), or None."""
    spec = _RULES.get(func)
    if spec is None or spec.arity not in (None, len(args)):
        return None
    if spec.real_only and not all(a.is_real for a in args):
        return None
    return spec


def _differential(spec, args, changes):
    """d f for changes of its arguments, by the record's rule."""
    if spec.steps:
        return _ZERO
    return spec.differential(sm, *args, *changes)


def diff(expr: sm.Expr, x: sm.Symbol) -> sm.Expr:
    """d expr / d x (x a Symbol)."""
    contains: dict = {}
    memo: dict = {}

    def has(e) -> bool:
        r = contains.get(e)
        if r is None:
            if e.is_Atom:
                r = e == x
            else:
                r = any(has(a) for a in e.args)
            contains[e] = r
        return r

    def d(e):
        r = memo.get(e)
        if r is not None:
            return r
        if not has(e):
            r = _ZERO
        elif e.is_Symbol:
            r = _ONE
        elif e.is_Add:
            r = sm.Add(*[d(a) for a in e.args if has(a)])
        elif e.is_Mul:
            args = e.args
            terms = []
            for i, a in enumerate(args):
                if has(a):
                    da = d(a)
                    if da != 0:
                        terms.append(sm.Mul(*(args[:i] + (da,) + args[i + 1:])))
            r = sm.Add(*terms)
        elif e.is_Pow:
            b, p = e.args
            if not has(p):
                r = p * b ** (p - 1) * d(b)
            else:
                r = e * (d(p) * sm.log(b) + (p * d(b) / b if has(b) else 0))
        elif (spec := _rule(e.func, e.args)) is not None:
            r = _differential(spec, e.args, [d(a) for a in e.args])
        else:
            r = e.diff(x)
        memo[e] = r
        return r

    return d(expr)


def gradient(expr: sm.Expr, xs) -> dict:
    """{x: d expr / d x} for the symbols xs that expr contains, in one memoised pass
    (differentiating once per x walks the whole expression once per x, which on the
    long definitions of real models is what dominates)."""
    return Gradients(set(xs).__contains__).of(expr)


class Gradients:
    """Gradients of many expressions with respect to the symbols `varies` says vary,
    sharing one memo: a part common to several expressions (a joint's rotation in every
    entry of a chain's positions and their rates) is differentiated once.  Whether a
    symbol varies must be settled before the first expression holding it is asked (the
    definitions in dependency order)."""

    def __init__(self, varies) -> None:
        self._varies = varies
        self._deps: dict = {}
        self._memo: dict = {}

    def of(self, expr) -> dict:
        """{x: d expr / d x} for the varying symbols x of expr, zeros left out."""
        return self._g(sm.sympify(expr))

    def _deps_of(self, e) -> frozenset:
        r = self._deps.get(e)
        if r is None:
            if e.is_Atom:
                r = frozenset((e,)) if self._varies(e) else _NONE
            else:
                r = _NONE.union(*[self._deps_of(a) for a in e.args])
            self._deps[e] = r
        return r

    def _g(self, e) -> dict:
        r = self._memo.get(e)
        if r is not None:
            return r
        deps, g = self._deps_of, self._g
        dep = deps(e)
        if not dep:
            r = {}
        elif e.is_Symbol:
            r = {e: _ONE}
        elif e.is_Add:
            acc: dict = {}
            for a in e.args:
                if deps(a):
                    _add_into(acc, g(a))
            r = {x: total(ts) for x, ts in acc.items()}
        elif e.is_Mul:
            args = e.args
            acc = {}
            for i, a in enumerate(args):
                if deps(a):
                    _add_into(acc, g(a), sm.Mul(*(args[:i] + args[i + 1:])))
            r = {x: total(ts) for x, ts in acc.items()}
        elif e.is_Pow:
            b, p = e.args
            if not deps(p):
                factor = p * b ** (p - 1)
                r = {x: times(factor, v) for x, v in g(b).items()}
            else:
                r = {x: diff(e, x) for x in dep}
        elif (spec := _rule(e.func, e.args)) is not None:
            grads = [g(a) for a in e.args]
            r = {x: _differential(spec, e.args, [ga.get(x, _ZERO) for ga in grads])
                 for x in dict.fromkeys(x for ga in grads for x in ga)}
        else:
            r = {x: e.diff(x) for x in dep}
        r = {x: v for x, v in r.items() if v != 0}
        self._memo[e] = r
        return r


_NONE: frozenset = frozenset()


def _add_into(acc: dict, grad: dict, factor=None) -> None:
    for x, v in grad.items():
        acc.setdefault(x, []).append(v if factor is None else times(factor, v))


def times(a: sm.Expr, b: sm.Expr) -> sm.Expr:
    """a*b; a factor 1 (the derivative of a symbol by itself) costs no product (sympy's
    would flatten a*1 back to a), and the chain rule's commonest products, of two
    symbols (a definition's derivative by a Z times that Z's) or of a number and a
    symbol, are made as sympy's flattening makes them, without it (12 times cheaper)."""
    if b is _ONE:
        return a
    if a is _ONE:
        return b
    if a.is_Symbol:
        if b.is_Symbol:
            if a != b and a.is_commutative and b.is_commutative:
                return sm.Mul._from_args((a, b) if _ORDER(a) < _ORDER(b) else (b, a), True)
        elif _coefficient(b) and a.is_commutative:
            return sm.Mul._from_args((b, a), True)
    elif b.is_Symbol and _coefficient(a) and b.is_commutative:
        return sm.Mul._from_args((a, b), True)
    if not (a.is_Number or b.is_Number):
        joined = _joined_factors(a, b)
        if joined is not None:
            return joined
    return a * b


def _joined_factors(a: sm.Expr, b: sm.Expr) -> sm.Expr | None:
    """a*b as sympy's flattening makes it, when nothing in it combines: the factors of
    both (at most one numeric coefficient, leading), sorted, every base once (x and
    x**2 would make x**3); None for anything else (powers of numbers, exp's, which are
    powers of E, exp_polar's, I, non-commutative or unbounded factors: sympy's own product)."""
    fa = a.args if a.is_Mul else (a,)
    fb = b.args if b.is_Mul else (b,)
    coeff = None
    factors = []
    bases = set()
    for f in fa + fb:
        if f.is_Number:
            if coeff is not None or not _coefficient(f):
                return None
            coeff = f
            continue
        if not f.is_commutative or f is _I or isinstance(f, ExpBase):
            return None
        base = f.base if f.is_Pow else f
        if base.is_Number or base in bases:
            return None
        bases.add(base)
        factors.append(f)
    factors.sort(key=_ORDER)
    return sm.Mul._from_args(factors if coeff is None else [coeff, *factors], True)


# sympy's order of a product's factors (Mul.flatten sorts them so)
_ORDER = cmp_to_key(sm.Basic.compare)


def _coefficient(e) -> bool:
    """A number that leads a product as its coefficient: finite, neither 0 nor 1."""
    return e.is_Number and e.is_finite and e != 0 and e != 1


def sum_of_products(pairs) -> sm.Expr:
    """The sum of a*b over `pairs`, as sympy's sum of the products makes it; a pair with
    a factor 0 is left out (its product is 0: sympy's asks at length whether the other
    factor is finite)."""
    return total([times(a, b) for a, b in pairs if a is not _ZERO and b is not _ZERO])


def total(terms: list) -> sm.Expr:
    """The sum of `terms`; one term is itself (sympy's Add of one term is that term,
    of none 0)."""
    if len(terms) == 1:
        return terms[0]
    summed = _distinct_terms(terms)
    return sm.Add(*terms) if summed is None else summed


def _distinct_terms(terms: list) -> sm.Expr | None:
    """The sum as sympy's flattening makes it when no two terms combine: the terms
    sorted (what is left of each term without its numeric coefficient differs from
    every other's); None for anything else (numbers, sums, powers of numbers, unbounded
    coefficients, non-commutative or other kinds of terms: sympy's own sum)."""
    if len(terms) < 2:
        return None
    rests = set()
    for t in terms:
        if t.is_Mul:
            c, rest = t.as_coeff_Mul()
            if not c.is_finite:
                return None
        elif t.is_Symbol or t.is_Function or t.is_Pow and not t.base.is_Number:
            rest = t
        else:
            return None
        if not t.is_commutative or rest in rests:
            return None
        rests.add(rest)
    return sm.Add._from_args(sorted(terms, key=_ORDER), True)


def value_and_gradient(expr: sm.Expr, values: dict, seeds: dict) -> tuple:
    """expr at a point and its gradient there, in one memoised forward pass: `values`
    {symbol: its value at the point} for the symbols that take one (the rest stay),
    `seeds` {symbol: {x: d symbol / d x there}} for those with a nonzero gradient.
    Each node is put at the point once (as xreplace would) and the chain rule applied
    to the values, so a factor that vanishes there drops its terms before they are
    built.  Returns (value, {x: d expr / d x}), zero derivatives left out."""
    memo: dict = {}
    takes: dict = {}

    def moves(e) -> bool:
        r = takes.get(e)
        if r is None:
            r = e in values if e.is_Atom else any(moves(a) for a in e.args)
            takes[e] = r
        return r

    def scaled(grad: dict, factor) -> dict:
        return {x: t for x, v in grad.items() if (t := factor * v) != 0}

    def at(e) -> tuple:
        r = memo.get(e)
        if r is not None:
            return r
        if not moves(e):
            r = (e, {})
        elif e.is_Symbol:
            r = (values[e], seeds.get(e, {}))
        elif e.is_Add or e.is_Mul:
            parts = [at(a) for a in e.args]
            vals = [v for v, _ in parts]
            grads = [g for _, g in parts]
            r = (e.func(*vals), _sum_gradient(grads) if e.is_Add
                 else _product_gradient(vals, grads))
        elif e.is_Pow and not moves(e.exp):
            vb, gb = at(e.base)
            r = (vb ** e.exp, scaled(gb, e.exp * vb ** (e.exp - 1)))
        elif isinstance(e, sm.Function) and len(e.args) == 1:
            va, ga = at(e.args[0])
            spec = _rule(e.func, [va])
            if spec is None:
                a = sm.Dummy("a")
                outer = e.func(a).diff(a).xreplace({a: va})
            else:
                outer = _differential(spec, [va], [_ONE])
            r = (e.func(va), scaled(ga, outer))
        else:   # not one argument (atan2, a moving exponent, Max): each symbol's part
            acc: dict = {}
            for f in e.free_symbols & seeds.keys():
                partial = diff(e, f).xreplace(values)
                for x, v in seeds[f].items():
                    acc.setdefault(x, []).append(partial * v)
            r = (e.xreplace(values), _totals(acc))
        memo[e] = r
        return r

    return at(sm.sympify(expr))


def _totals(acc: dict) -> dict:
    """{x: the sum of its terms} without the sums that are 0."""
    return {x: t for x, ts in acc.items() if (t := sm.Add(*ts)) != 0}


def _sum_gradient(grads: list) -> dict:
    acc: dict = {}
    for g in grads:
        for x, v in g.items():
            acc.setdefault(x, []).append(v)
    return _totals(acc)


def _product_gradient(vals: list, grads: list) -> dict:
    """The gradient of a product of factors with these values and gradients: a factor
    whose value is 0 leaves only its own term (two leave none)."""
    zeros = [i for i, v in enumerate(vals) if v == 0]
    acc: dict = {}
    for i, g in enumerate(grads):
        if g and (not zeros or zeros == [i]):
            rest = sm.Mul(*(vals[:i] + vals[i + 1:]))
            for x, v in g.items():
                acc.setdefault(x, []).append(rest * v)
    return _totals(acc)
