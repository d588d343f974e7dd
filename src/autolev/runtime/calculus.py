"""The definitions table and calculus through it.

Autolev keeps names: after `Q1' = U1`, `X = expr` (X declared) or an intermediate
Z's definition, later expressions still hold the *symbol*, and the definition is
used by D(), DT(), RHS(), EXPLICIT() and the generated numerics.  This module is
that table and the calculus over it:

* `diff(e, x)`  partial derivative of e with respect to x, through every definition
* `dt(e)`       total time derivative, through every definition
* `substitute(e, {x: v})`  e with x replaced, also inside the definitions e uses
* `explicit(e)` e with every definition expanded (EXPLICIT)
* `zify(e)`     a Z name for e when e is not trivial (hash-consed: one Z per value)

Derived quantities of a defined symbol (its derivatives, its restrictions) become
new Z's, cached, so expressions stay small however deep the model.  Everything is
computed iteratively in dependency order (no recursion on the depth of the chain).
"""
from __future__ import annotations

import functools
import math
import zlib
from collections.abc import Iterable, Mapping
from contextlib import contextmanager

import sympy as sm

from ..errors import MAX_EXACT_DIGITS
from .derived import Revision
from .symbols import TIME, Z, derivative, new_z
from ..engine.errors import AutolevModelError
from .fastdiff import diff as fast_diff
from .fastdiff import Gradients, times, total, value_and_gradient
from .floats import NotElementary, complex_value


@functools.lru_cache(maxsize=1 << 16)
def _order_key(s) -> tuple:
    # asked again for the same symbols at every dependency walk: kept (a Z's number is
    # read from its name)
    if isinstance(s, Z):
        return (1, int(s.name[1:]) if s.name[1:].isdigit() else 0, s.name)
    # a Symbol prints as its name (asking the printer costs a tenth of a cold run's order)
    return (0, 0, str(s) if isinstance(s, sm.Dummy) or not s.is_Symbol else s.name)


def ordered(symbols) -> list:
    """Symbols in a fixed order: by name, Z's after the others in creation order."""
    return sorted(symbols, key=_order_key)


# an imaginary part this small next to the real part (or 1) is rounding, not a value
REAL_TOLERANCE = 1e-12


def is_real_number(z) -> bool:
    """Whether a complex number (or every entry of an array) is real up to rounding."""
    import numpy as np      # here: a model's forming and a transcript need no numpy
    z = np.asarray(z, dtype=complex)
    return bool(np.all(np.abs(z.imag) <= REAL_TOLERANCE * np.maximum(1.0, np.abs(z.real))))


class NumericPoint:
    """Values for a numeric evaluation: given ones, else a fixed pseudo-random value
    per symbol (the same for a symbol every time), or 0 for the time-varying ones when
    `zero_varying` (the configuration where models are usually linearised)."""

    def __init__(self, defs: "Definitions", values: Mapping | None = None,
                 zero_varying: bool = False, seed: int = 0, varying=None,
                 span: tuple[float, float] = (0.5, 1.5)):
        """`varying`: None (pseudo-random in `span` like the constants), a number for
        every time-varying symbol, or "wide" (pseudo-random in [-pi, pi])."""
        self.defs = defs
        self.values = dict(values or {})
        self.varying_value = 0 if zero_varying else varying
        self.seed = seed
        self.span = span
        self.cache: dict = {}

    def value(self, sym, cache):
        if sym in cache:
            return cache[sym]
        if sym in self.values:
            return self.values[sym]
        h = zlib.crc32(f"{sym.name}/{self.seed}".encode()) / 2 ** 32
        if self.varying_value is not None and sym in self.defs.varying:
            if self.varying_value == "wide":
                return sm.Float(math.pi * (2 * h - 1))
            return sm.sympify(self.varying_value)
        lo, hi = self.span
        return sm.Float(lo + (hi - lo) * h)


def _number_at(e, values: dict) -> complex:
    """The value of e with numbers for its symbols; NaN where it has none there (a
    symbol left, or a function refusing the argument it gets, as MIN a complex one).
    Taken in complex double precision where every node is elementary, else by sympy."""
    try:
        return complex_value(e, values, {})
    except (NotElementary, ArithmeticError, ValueError, TypeError, RecursionError):
        pass
    try:
        return complex(e.xreplace(values))
    except (TypeError, ValueError):
        return complex("nan")


def symbols_in(*exprs) -> set:
    """The expressions' symbols, each shared part visited once (free_symbols walks a
    part as often as it occurs: a response built of repeated parts took minutes)."""
    seen, found, stack = set(), set(), list(exprs)
    while stack:
        e = stack.pop()
        if e in seen:
            continue
        seen.add(e)
        if e.is_Symbol:
            found.add(e)
        else:
            stack.extend(e.args)
    return found


class _CachedFor:
    """`s in _CachedFor(cache, k)` is `(s, k) in cache`: the done-set of one key."""

    __slots__ = ("cache", "k")

    def __init__(self, cache: dict, k) -> None:
        self.cache, self.k = cache, k

    def __contains__(self, s) -> bool:
        return (s, self.k) in self.cache


SMALL = 7   # expressions of at most this many nodes stay inline (a*x**2 is 5)


def is_small(e: sm.Basic, limit: int = SMALL) -> bool:
    """Expressions kept inline rather than named: a handful of nodes (-x, 2*a*x,
    cos(q), x + y*z); anything bigger gets a Z."""
    count = 0
    stack = [e]
    while stack:
        node = stack.pop()
        count += 1
        if count > limit:
            return False
        stack.extend(node.args)
    return True


def refused_substitution(mapping: Mapping, exc: ValueError) -> AutolevModelError:
    """The error of substituting values that a function then refuses (MAX of 1/0)."""
    given = ", ".join(f"{k} = {v}" for k, v in mapping.items())
    return AutolevModelError(f"substituting {given} leaves an expression without a value "
                             f"({exc})")


def _exact_number(v) -> bool:
    return v.is_Rational or v.is_Pow and v.base.is_Rational and v.exp.is_Rational


# an exponent below this cannot give MAX_EXACT_DIGITS digits from an exact base
_LARGE_EXPONENT = MAX_EXACT_DIGITS / math.log10(2)


def refuse_huge_powers(expr, repl: dict) -> None:
    """Refuse a substitution that would make sympy compute an exact power of more than
    MAX_EXACT_DIGITS digits (EVALUATE(X^4294967297, X=2) takes gigabytes)."""
    seen: set = set()
    stack = [expr]
    while stack:
        e = stack.pop()
        if e.is_Atom or e in seen:
            continue
        seen.add(e)
        stack.extend(e.args)
        if not (e.is_Pow and e.exp.is_Integer and abs(e.exp) > _LARGE_EXPONENT):
            continue
        base, power = e.base.xreplace(repl), abs(int(e.exp))
        if base.is_Pow and base.base.is_Rational and base.exp.is_Rational:
            base, power = base.base, power * abs(base.exp)
        if not base.is_Rational or base in (0, 1, -1):
            continue
        digits = float(power) * math.log10(max(abs(base.p), base.q))
        if digits > MAX_EXACT_DIGITS:
            values = ", ".join(f"{k} = {v}" for k, v in repl.items() if k in e.free_symbols)
            raise AutolevModelError(
                f"{str(e).replace('**', '^')} with {values} is an exact number of about "
                f"{digits:.3g} digits; exact numbers of more than "
                f"{MAX_EXACT_DIGITS} digits are refused (give a decimal value, 2.0, for a "
                "floating-point result)")


class Definitions:
    """Definitions of symbols (user definitions and Z's) and calculus through them."""

    def __init__(self, revision: Revision | None = None) -> None:
        """`revision`: the model's, bumped by each user definition."""
        self.revision = revision if revision is not None else Revision()
        self.rhs: dict[sm.Symbol, sm.Expr] = {}
        self.varying: set[sm.Symbol] = {TIME}       # symbols with a time derivative
        self._z_of: dict[sm.Expr, Z] = {}           # hash-consing of Z definitions
        self._pdeps: dict[sm.Symbol, frozenset] = {}
        self._dt: dict[sm.Symbol, sm.Expr] = {}
        self._dt_raw: dict[sm.Symbol, sm.Expr] = {}
        self._diff: dict[tuple[sm.Symbol, sm.Symbol], sm.Expr] = {}
        self._subs: dict[tuple[sm.Symbol, frozenset], sm.Expr] = {}
        # the gradients at a point: {(symbol, point's key): {x: derivative there}}
        self._grad_at: dict[tuple[sm.Symbol, frozenset], dict] = {}
        # the expansions, per set of symbols kept (EXPLICIT(x, [u]), the hand-off's
        # dependent speeds): {frozenset kept: {symbol: its expansion}}
        self._explicit: dict[frozenset, dict[sm.Symbol, sm.Expr]] = {}
        self._fs: dict[sm.Symbol, frozenset] = {}   # free symbols of each definition
        self._fo: dict[sm.Symbol, tuple] = {}       # the same, in a fixed order
        # every symbol some definition, as made, holds (never shrinks): a new definition
        # of a symbol none holds leaves everything derived as it was
        self._referenced: set[sm.Symbol] = set()
        self.z_count = 0
        # counts the user definitions made: what was derived from the table is stale
        # when it changes (a Z added names an expression and changes nothing)
        self.user_version = 0
        self._views: dict = {}      # id of an as_of snapshot -> (snapshot, its version)
        self._view_count = 0
        self._user_definitions: tuple = (None, {})   # (user_version, the definitions then)

    # -- the table -------------------------------------------------------------
    def define(self, sym: sm.Symbol, expr) -> None:
        """Record `sym := expr`.  A user definition drops derived caches when what was
        derived may have used sym (a new definition of X' changes what DT(X) is): sym
        was defined before, or a definition holds it."""
        expr = sm.sympify(expr)
        # through the definitions as they stand: a redefined sym is among them
        if self.depends_on(expr, sym):
            raise AutolevModelError(f"{sym} cannot be defined in terms of itself: {sym} = "
                                    f"{expr}")
        if not isinstance(sym, Z):
            if sym in self.rhs or sym in self._referenced:
                self._invalidate()
            self.user_version += 1
            self.revision.bump()
        self.rhs[sym] = expr
        self._fs.pop(sym, None)
        self._fo.pop(sym, None)
        self._referenced |= self.free(sym)

    def user_definitions(self) -> dict:
        """The definitions the model made (not the Z's), as they stand now: one dict while
        no definition is made, never to be changed (verify keeps one with each of
        thousands of responses, and as_of knows a snapshot by its identity)."""
        if self._user_definitions[0] != self.user_version:
            self._user_definitions = (self.user_version, {
                s: e for s, e in self.rhs.items() if not isinstance(s, Z)})
        return self._user_definitions[1]

    @contextmanager
    def as_of(self, user_definitions: Mapping | None):
        """The table as it stood when `user_definitions` (a `user_definitions()` taken
        then) was taken: later definitions hidden, changed ones as they were.  Z's stay:
        each names an expression, whatever is defined.  (A CODE command's program is
        built from what was defined when the CODE line came.)"""
        if user_definitions is None:
            yield self
            return
        now = self.user_definitions()
        if len(now) == len(user_definitions) and all(
                user_definitions.get(s) is e for s, e in now.items()):
            yield self
            return
        outside, outside_view = self.user_version, self.revision.view
        self._replace_user_definitions(user_definitions)
        self.user_version = self.revision.view = self._view_version(user_definitions)
        try:
            yield self
        finally:
            self._replace_user_definitions(now)
            self.user_version, self.revision.view = outside, outside_view

    def _view_version(self, user_definitions: Mapping):
        """A version for the table seen through `as_of(user_definitions)`: the same
        each time that snapshot is viewed, never one the table itself takes."""
        kept = self._views.get(id(user_definitions))
        if kept is None or kept[0] is not user_definitions:
            self._view_count += 1
            kept = self._views[id(user_definitions)] = (user_definitions,
                                                        ("view", self._view_count))
        return kept[1]

    def _replace_user_definitions(self, user_definitions: Mapping) -> None:
        for s in [s for s in self.rhs if not isinstance(s, Z)]:
            del self.rhs[s]
        self.rhs.update(user_definitions)
        self._fs = {s: v for s, v in self._fs.items() if isinstance(s, Z)}
        self._fo = {s: v for s, v in self._fo.items() if isinstance(s, Z)}
        # (each of these definitions was made by `define`: its symbols are referenced)
        self._invalidate()

    def _invalidate(self) -> None:
        self._pdeps.clear()
        self._dt.clear()
        self._dt_raw.clear()
        self._diff.clear()
        self._subs.clear()
        self._grad_at.clear()
        self._explicit.clear()

    def mark_varying(self, *syms: sm.Symbol) -> None:
        self.varying.update(syms)


    def zify(self, expr) -> sm.Expr:
        """A Z standing for `expr`, unless `expr` is small enough to keep inline."""
        expr = sm.sympify(expr)
        if is_small(expr):
            return expr
        z = self._z_of.get(expr)
        if z is None:
            self.z_count += 1
            z = new_z(self.z_count)
            self.rhs[z] = expr
            self._z_of[expr] = z
            self._referenced |= self.free(z)
        return z

    # -- dependency order ------------------------------------------------------
    def _defined_in(self, expr) -> list[sm.Symbol]:
        return ordered(s for s in symbols_in(expr) if s in self.rhs)

    def free(self, sym: sm.Symbol) -> frozenset:
        """Free symbols of the definition of sym (cached: definitions do not change)."""
        fs = self._fs.get(sym)
        if fs is None:
            fs = self._fs[sym] = frozenset(symbols_in(self.rhs[sym]))
        return fs

    def free_ordered(self, sym: sm.Symbol) -> tuple:
        """free(sym) in a fixed order (names, then Z's in creation order), so that what
        is built by walking definitions -- Z's, generated code -- is the same in every
        run, whatever Python's hash seed."""
        fo = self._fo.get(sym)
        if fo is None:
            fo = self._fo[sym] = tuple(ordered(self.free(sym)))
        return fo

    def _post_order(self, roots: Iterable[sm.Symbol], done, prune=None) -> list[sm.Symbol]:
        """Defined symbols reachable from roots, dependencies first.

        Symbols `in done` are skipped; so are those for which `prune(s)` is true,
        and what lies only beyond them."""
        order: list[sm.Symbol] = []
        seen: set[sm.Symbol] = set()
        stack = [(r, False) for r in reversed(ordered(roots)) if r in self.rhs]
        while stack:
            s, expanded = stack.pop()
            if expanded:
                order.append(s)
                continue
            if s in seen or s in done or (prune is not None and prune(s)):
                continue
            seen.add(s)
            stack.append((s, True))
            for f in reversed(self.free_ordered(s)):
                if f in self.rhs and f not in seen and f not in done:
                    stack.append((f, False))
        return order

    def primitive_deps(self, sym: sm.Symbol) -> frozenset:
        """The undefined symbols a defined symbol depends on (through definitions)."""
        known = self._pdeps.get(sym)
        if known is not None:
            return known
        for s in self._post_order([sym], self._pdeps):
            deps: set = set()
            for f in self.free(s):
                if f in self.rhs:
                    deps |= self._pdeps[f]
                else:
                    deps.add(f)
            self._pdeps[s] = frozenset(deps)
        return self._pdeps[sym]

    def depends_on(self, expr, x: sm.Symbol) -> bool:
        """Whether expr depends on x, directly or through definitions."""
        return self.reaches(symbols_in(sm.sympify(expr)), x)

    def reaches(self, fs, x: sm.Symbol) -> bool:
        """Whether any of the symbols `fs` is x or depends on it through definitions."""
        if x in fs:
            return True
        # a walk through the definitions that stops where it finds x; the undefined
        # symbols a definition depends on, where known, settle it for an undefined x
        known = {} if x in self.rhs else self._pdeps
        stack = [s for s in fs if s in self.rhs]
        seen = set(stack)
        while stack:
            s = stack.pop()
            if s in known:
                if x in known[s]:
                    return True
                continue
            free = self.free(s)
            if x in free:
                return True
            for f in free:
                if f in self.rhs and f not in seen:
                    seen.add(f)
                    stack.append(f)
        return False

    # -- differentiation ---------------------------------------------------------
    def diff(self, expr, x: sm.Symbol) -> sm.Expr:
        """d expr / d x, through every definition (x itself is not expanded)."""
        expr = sm.sympify(expr)
        if not isinstance(x, sm.Symbol):
            raise AutolevModelError(f"D differentiates with respect to a name, not {x}")
        relevant = [s for s in self._defined_in(expr) if s != x]
        if x in self.rhs:
            def depends(s):
                return self.depends_on(s, x)
        else:
            def depends(s):
                return x in self.primitive_deps(s)
        for s in self._post_order(relevant, _CachedFor(self._diff, x),
                                  prune=lambda s: s == x or not depends(s)):
            self._diff[(s, x)] = self.zify(self._diff_shallow(self.rhs[s], x, self.free(s)))
        return self._diff_shallow(expr, x)

    def jacobian(self, exprs, xs) -> list[list]:
        """[[d e / d x for x in xs] for e in exprs] through every definition, in one
        forward pass over the definitions: each definition is differentiated once per
        symbol it uses that depends on some x (not once per x, as n calls of `diff`
        would), and its derivatives are combined by the chain rule for all the x's
        together.  The results also fill `diff`'s cache."""
        exprs = [sm.sympify(e) for e in exprs]
        xs = list(xs)
        xset = set(xs)
        if any(x in self.rhs for x in xs):      # defined x's: the general route
            return [[self.diff(e, x) for x in xs] for e in exprs]
        roots = set()
        for e in exprs:
            roots |= {s for s in symbols_in(e) if s in self.rhs}
        order = self._post_order(roots, {}, prune=lambda s: not (self.primitive_deps(s)
                                                                  & xset))
        grads: dict = {}          # defined symbol -> {x: derivative (zified)}
        # one memo for every definition: the parts they share are differentiated once (a
        # symbol's liveness is settled before the definitions that use it, in this order)
        differentiate = Gradients(lambda f: f in xset or bool(grads.get(f)))

        def gradient(expr, fs):
            acc: dict = {}
            live = [f for f in fs if f in xset or grads.get(f)]
            if not live:
                return {}
            dfs = differentiate.of(expr)
            for f in live:
                df = dfs.get(f)
                if df is None:
                    continue
                parts = {f: sm.S.One} if f in xset else grads[f]
                for x, g in parts.items():
                    acc.setdefault(x, []).append(times(df, g))
            return {x: total(ts) for x, ts in acc.items()}

        for s in order:
            known = {x: self._diff[(s, x)] for x in xs if (s, x) in self._diff}
            if len(known) == len(xs):
                grads[s] = {x: d for x, d in known.items() if d != 0}
                continue
            g = gradient(self.rhs[s], self.free_ordered(s))
            out = {}
            for x in xs:
                d = known[x] if x in known else self.zify(g.get(x, sm.S.Zero))
                self._diff[(s, x)] = d
                if d != 0:
                    out[x] = d
            grads[s] = out
        rows = []
        for e in exprs:
            g = gradient(e, ordered(symbols_in(e)))
            rows.append([g.get(x, sm.S.Zero) for x in xs])
        return rows

    def at_point(self, expr, point: Mapping) -> tuple:
        """(expr at the point, {x: d expr / d x there}) for the symbols x of `point`
        ({x: value}), in one forward pass over the definitions that depend on them:
        each is put at the point and differentiated there at once
        (`value_and_gradient`), so what vanishes at the point (sin(0), speeds set to 0)
        drops out before the chain rule multiplies it; differentiating everywhere and
        then substituting builds every derivative in full first.  The values there
        fill `substitute`'s cache."""
        point = {sm.sympify(k): sm.sympify(v) for k, v in point.items()}
        if any(x in self.rhs for x in point):      # defined x's: the general route
            return self.substitute(expr, point), {
                x: self.substitute(d, point)
                for x, d in zip(point, self.jacobian([expr], list(point))[0])}
        expr = sm.sympify(expr)
        key = frozenset(point.items())
        xs = set(point)
        roots = {s for s in symbols_in(expr) if s in self.rhs}
        for s in self._post_order(roots, _CachedFor(self._grad_at, key),
                                  prune=lambda s: not (self.primitive_deps(s) & xs)):
            value, grad = self._at_point(self.rhs[s], self.free(s), point, key)
            if (s, key) not in self._subs:
                self._subs[(s, key)] = self.zify(value)
            self._grad_at[(s, key)] = {x: self.zify(d) for x, d in grad.items()}
        return self._at_point(expr, symbols_in(expr), point, key)

    def _at_point(self, expr, fs, point: dict, key) -> tuple:
        """(expr, its gradient) at the point, from the values and gradients there of
        the definitions it holds."""
        values, seeds = {}, {}
        for f in fs:
            if f in point:
                values[f], seeds[f] = point[f], {f: sm.S.One}
            elif (f, key) in self._grad_at:
                values[f] = self._subs[(f, key)]
                if self._grad_at[(f, key)]:
                    seeds[f] = self._grad_at[(f, key)]
        if any(_exact_number(v) for v in values.values()):
            refuse_huge_powers(expr, values)
        try:
            return value_and_gradient(expr, values, seeds)
        except ValueError as exc:    # sympy's refusal of a function's new argument
            raise refused_substitution(point, exc) from None

    def _diff_shallow(self, expr, x, fs=None) -> sm.Expr:
        """Chain rule one level deep, using the cached derivatives of defined symbols."""
        fs = symbols_in(expr) if fs is None else fs
        terms = [fast_diff(expr, x)] if x in fs else []
        for s in fs:
            if s not in self.rhs:
                continue
            if s == x:
                continue
            ds = self._diff.get((s, x))
            if ds is None:
                if not self.depends_on(s, x):
                    continue
                ds = self._diff[(s, x)] = self.zify(self._diff_shallow(self.rhs[s], x,
                                                                        self.free(s)))
            if ds != 0:
                terms.append(fast_diff(expr, s) * ds)
        return sm.Add(*terms)

    def dt(self, expr, through_definitions: bool = True) -> sm.Expr:
        """Total time derivative of a scalar expression.

        A variable X differentiates to its derivative symbol X' when X' has a
        definition of its own or X has none (Autolev: with SPECIFIED EA'' and EA,
        EA', EA'' each defined, DT(EA') is EA''); otherwise through X's definition
        (`Q6' = DT(Q6)` after Q6 was solved for).  A Z always goes through.  With
        through_definitions=False every variable gives its derivative symbol (the
        angular velocity an orientation implies is in the angles' own rates)."""
        expr = sm.sympify(expr)
        cache = self._dt if through_definitions else self._dt_raw
        through = self._dt_through if through_definitions else self._dt_raw_through
        def rate(s):
            return self._rate(s, cache, through)
        # one memo for every definition: the parts they share are differentiated once
        # (each symbol's rate is settled before the definitions that use it, in this order)
        gradients = Gradients(lambda s: s.is_Symbol and rate(s) != 0)
        for s in self._post_order(self._defined_in(expr), cache,
                                  prune=lambda s: not through(s)):
            cache[s] = self.zify(self._dt_shallow(self.rhs[s], rate, gradients,
                                                  self.free(s)))
        return self._dt_shallow(expr, rate, gradients)

    def dt_raw(self, expr) -> sm.Expr:
        return self.dt(expr, through_definitions=False)

    def _dt_raw_through(self, s) -> bool:
        # Z's, and a defined variable whose derivative is not (an angle given as a
        # function of other coordinates, bicycle pitch = f(roll, steer)): its rate is
        # the derivative of its definition
        return s in self.rhs and (isinstance(s, Z) or (s in self.varying
                                                       and derivative(s) not in self.rhs))

    def _dt_through(self, s) -> bool:
        return s in self.rhs and (isinstance(s, Z) or s not in self.varying
                                  or derivative(s) not in self.rhs)

    def _rate(self, s, cache, through) -> sm.Expr:
        """d s / dt one level deep: a defined symbol's from `cache` (when `through` it),
        T's 1, a varying symbol's its derivative symbol, anything else 0."""
        if through(s):
            return cache[s]
        if s is TIME:
            return sm.S.One
        if s in self.varying:
            return derivative(s)
        return sm.S.Zero

    def _dt_shallow(self, expr, rate, gradients: Gradients, fs=None) -> sm.Expr:
        partials = gradients.of(expr)
        terms = [times(partials[s], rate(s))
                 for s in (symbols_in(expr) if fs is None else fs) if s in partials]
        return sm.Add(*terms)

    # -- substitution and expansion ----------------------------------------------
    def substitute(self, expr, mapping: Mapping, keep: frozenset = frozenset()) -> sm.Expr:
        """expr with the symbols of `mapping` replaced, inside definitions too (except
        inside the definitions in `keep`, which stay as they are)."""
        expr = sm.sympify(expr)
        if not mapping:
            return expr
        mapping = {sm.sympify(k): sm.sympify(v) for k, v in mapping.items()}
        key = (frozenset(mapping.items()), keep) if keep else frozenset(mapping.items())
        keys = set(mapping)
        touched = [s for s in self._defined_in(expr) if s not in keys and s not in keep]
        for s in self._post_order(touched, _CachedFor(self._subs, key),
                                  prune=lambda s: s in keys or s in keep
                                  or not (self.primitive_deps(s) & keys)):
            self._subs[(s, key)] = self.zify(self._subs_shallow(self.rhs[s], mapping, key,
                                                                 self.free(s)))
        return self._subs_shallow(expr, mapping, key)

    def _subs_shallow(self, expr, mapping, key, fs=None) -> sm.Expr:
        repl = dict(mapping)
        for s in (symbols_in(expr) if fs is None else fs):
            if s not in self.rhs:
                continue
            if s in mapping:
                continue
            r = self._subs.get((s, key))
            if r is not None:
                repl[s] = r
        if not repl:
            return expr
        if any(_exact_number(v) for v in repl.values()):
            refuse_huge_powers(expr, repl)
        try:
            return expr.xreplace(repl)
        except ValueError as exc:    # sympy's refusal of a function's new argument
            raise refused_substitution(mapping, exc) from None

    def explicit(self, expr, keep: Iterable[sm.Symbol] = ()) -> sm.Expr:
        """expr with every definition (and Z) expanded, except the symbols in `keep`."""
        expr = sm.sympify(expr)
        keep = frozenset(keep)
        cache = self._explicit.setdefault(keep, {})
        roots = [s for s in self._defined_in(expr) if s not in keep]
        for s in self._post_order(roots, cache):
            if s in keep:
                continue
            rhs = self.rhs[s]
            repl = {f: cache[f] for f in rhs.free_symbols if f in cache}
            cache[s] = rhs.xreplace(repl) if repl else rhs
        repl = {s: cache[s] for s in roots if s in cache}
        return expr.xreplace(repl) if repl else expr

    # -- numbers -----------------------------------------------------------------
    def numeric(self, expr, point: "NumericPoint") -> complex:
        """The value of expr at a point (values of the undefined symbols), evaluating
        the definitions it uses once per point."""
        expr = sm.sympify(expr)
        cache = point.cache
        free = symbols_in(expr)
        for s in self._post_order(ordered(s for s in free if s in self.rhs), cache):
            rhs = self.rhs[s]
            cache[s] = _number_at(rhs, {f: point.value(f, cache) for f in self.free(s)})
        return _number_at(expr, {f: point.value(f, cache) for f in free})

    def evaluation_order(self, roots: Iterable[sm.Symbol], given=()) -> list[sm.Symbol]:
        """Defined symbols needed to evaluate `roots`, dependencies first; symbols in
        `given` (values known otherwise) are not expanded."""
        given = set(given)
        return self._post_order([r for r in roots if r in self.rhs], {},
                                prune=given.__contains__ if given else None)
