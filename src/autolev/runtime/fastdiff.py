"""Differentiation of sympy expressions in one memoised pass.

sympy's `diff` builds a `Derivative` at every level and asks each subtree for its
free symbols, which is quadratic in the size of the expression; on the expressions
real models make (pasted Autolev output, long sums of Z products) that dominates.
This walks the tree once, knows which subtrees contain the variable, and applies
the chain rule for the functions models use; anything else falls back to sympy.
"""
from __future__ import annotations

import sympy as sm

_ONE, _ZERO = sm.S.One, sm.S.Zero


def _function_derivative(f, arg):
    """d f(arg) / d arg for the elementary functions, or None."""
    if isinstance(f, sm.sin):
        return sm.cos(arg)
    if isinstance(f, sm.cos):
        return -sm.sin(arg)
    if isinstance(f, sm.tan):
        return 1 + sm.tan(arg) ** 2
    if isinstance(f, sm.exp):
        return f
    if isinstance(f, sm.log) and len(f.args) == 1:
        return 1 / arg
    if isinstance(f, sm.asin):
        return 1 / sm.sqrt(1 - arg ** 2)
    if isinstance(f, sm.acos):
        return -1 / sm.sqrt(1 - arg ** 2)
    if isinstance(f, sm.atan):
        return 1 / (1 + arg ** 2)
    if isinstance(f, sm.sinh):
        return sm.cosh(arg)
    if isinstance(f, sm.cosh):
        return sm.sinh(arg)
    if isinstance(f, sm.tanh):
        return 1 - sm.tanh(arg) ** 2
    if isinstance(f, sm.Abs) and arg.is_real:
        return sm.sign(arg)
    if isinstance(f, (sm.sign, sm.floor, sm.ceiling)) and arg.is_real:
        return _ZERO
    return None


def diff(expr: sm.Expr, x: sm.Symbol) -> sm.Expr:
    """d expr / d x (x a Symbol)."""
    if x not in expr.free_symbols:
        return _ZERO
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
        elif isinstance(e, sm.Function) and len(e.args) == 1:
            (arg,) = e.args
            outer = _function_derivative(e, arg)
            r = outer * d(arg) if outer is not None else e.diff(x)
        elif isinstance(e, sm.atan2):
            y, xx = e.args
            r = (xx * d(y) - y * d(xx)) / (xx ** 2 + y ** 2)
        else:
            r = e.diff(x)
        memo[e] = r
        return r

    return d(expr)


def gradient(expr: sm.Expr, xs) -> dict:
    """{x: d expr / d x} for the symbols xs that expr contains, in one memoised pass
    (differentiating once per x walks the whole expression once per x, which on the
    long definitions of real models is what dominates)."""
    xs = set(xs)
    empty: frozenset = frozenset()
    deps_memo: dict = {}
    memo: dict = {}

    def deps(e) -> frozenset:
        r = deps_memo.get(e)
        if r is None:
            if e.is_Atom:
                r = frozenset((e,)) if e in xs else empty
            else:
                r = empty.union(*[deps(a) for a in e.args])
            deps_memo[e] = r
        return r

    def add_into(acc: dict, grad: dict, factor=None) -> None:
        for x, v in grad.items():
            acc.setdefault(x, []).append(v if factor is None else factor * v)

    def g(e) -> dict:
        r = memo.get(e)
        if r is not None:
            return r
        dep = deps(e)
        if not dep:
            r = {}
        elif e.is_Symbol:
            r = {e: _ONE}
        elif e.is_Add:
            acc: dict = {}
            for a in e.args:
                if deps(a):
                    add_into(acc, g(a))
            r = {x: sm.Add(*ts) for x, ts in acc.items()}
        elif e.is_Mul:
            args = e.args
            acc = {}
            for i, a in enumerate(args):
                if deps(a):
                    add_into(acc, g(a), sm.Mul(*(args[:i] + args[i + 1:])))
            r = {x: sm.Add(*ts) for x, ts in acc.items()}
        elif e.is_Pow:
            b, p = e.args
            if not deps(p):
                acc = {}
                add_into(acc, g(b), p * b ** (p - 1))
                r = {x: ts[0] for x, ts in acc.items()}
            else:
                r = {x: diff(e, x) for x in dep}
        elif isinstance(e, sm.Function) and len(e.args) == 1:
            (arg,) = e.args
            outer = _function_derivative(e, arg)
            if outer is None:
                r = {x: e.diff(x) for x in dep}
            else:
                r = {x: outer * v for x, v in g(arg).items()}
        elif isinstance(e, sm.atan2):
            y, xx = e.args
            gy, gx = g(y), g(xx)
            den = xx ** 2 + y ** 2
            r = {x: (xx * gy.get(x, _ZERO) - y * gx.get(x, _ZERO)) / den for x in dep}
        else:
            r = {x: e.diff(x) for x in dep}
        r = {x: v for x, v in r.items() if v != 0}
        memo[e] = r
        return r

    return g(sm.sympify(expr))
