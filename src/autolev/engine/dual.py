"""A generated Python program's values and their partial derivatives at one point, by
running its own code on dual numbers (forward-mode differentiation): one linearization
needs no symbolic Jacobian, no printing of it and no compiler (BICYCLE14's Jacobians
are 10 MB of Python, 17 s to form and compile, for one evaluation).

The code is the one `codegen.python_source` prints for the runs, executed with `math`
and the printed helpers replaced by the functions below, which take a float or a
`Dual`.  A value where the math module raises (a division by zero, a domain error, a
complex power) or a function without a derivative here raises `NotDifferentiable`:
the caller then forms the Jacobians symbolically, where such points are handled.
"""
from __future__ import annotations

import marshal
import math
from types import SimpleNamespace

import numpy as np

from .functions import FUNCTION_SPECS, FunctionSpec
from .pyfunction import MATH_ERRORS, fast_namespace, python_callables


class NotDifferentiable(Exception):
    """The program cannot be differentiated on dual numbers at this point."""


class Dual:
    """A value and its gradient in the varied inputs (an array: d value / d input)."""

    __slots__ = ("v", "g")

    def __init__(self, v: float, g: np.ndarray):
        self.v, self.g = v, g

    def __add__(self, o):
        if isinstance(o, Dual):
            return Dual(self.v + o.v, self.g + o.g)
        return Dual(self.v + o, self.g)

    __radd__ = __add__

    def __sub__(self, o):
        if isinstance(o, Dual):
            return Dual(self.v - o.v, self.g - o.g)
        return Dual(self.v - o, self.g)

    def __rsub__(self, o):
        return Dual(o - self.v, -self.g)

    def __neg__(self):
        return Dual(-self.v, -self.g)

    def __pos__(self):
        return self

    def __mul__(self, o):
        if isinstance(o, Dual):
            return Dual(self.v * o.v, o.v * self.g + self.v * o.g)
        return Dual(self.v * o, o * self.g)

    __rmul__ = __mul__

    def __truediv__(self, o):
        if isinstance(o, Dual):
            q = self.v / o.v
            return Dual(q, (self.g - q * o.g) / o.v)
        return Dual(self.v / o, self.g / o)

    def __rtruediv__(self, o):
        q = o / self.v
        return Dual(q, (-q / self.v) * self.g)

    def __pow__(self, o):
        if isinstance(o, Dual):
            v = _real(self.v ** o.v)
            return Dual(v, v * (math.log(self.v) * o.g + (o.v / self.v) * self.g))
        if o == 0:
            return 1.0
        return Dual(_real(self.v ** o), (o * _real(self.v ** (o - 1))) * self.g)

    def __rpow__(self, o):
        v = _real(o ** self.v)
        return Dual(v, (v * math.log(o)) * self.g)

    # the conditions of a Piecewise, Max and Min: on the values (the branch taken is
    # the one differentiated)
    def __lt__(self, o):
        return self.v < _value(o)

    def __le__(self, o):
        return self.v <= _value(o)

    def __gt__(self, o):
        return self.v > _value(o)

    def __ge__(self, o):
        return self.v >= _value(o)

    def __eq__(self, o):
        return self.v == _value(o)

    def __ne__(self, o):
        return self.v != _value(o)

    __hash__ = None


def _value(x) -> float:
    return x.v if isinstance(x, Dual) else x


def _real(v):
    if isinstance(v, complex):      # a negative base to a fractional power
        raise ValueError("a complex power")
    return v


def _differentiable(f, differential, arity: int | None):
    """f on floats and duals, with d f = differential(the rules' floats, *arguments,
    *their changes)."""
    if arity == 1:              # most calls: without the general case's lists
        def apply_one(x):
            if isinstance(x, Dual):
                return Dual(f(x.v), differential(_FLOATS, x.v, x.g))
            return f(x)
        return apply_one

    def apply(*args):
        if not any(isinstance(a, Dual) for a in args):
            return f(*args)
        values = [_value(a) for a in args]
        changes = [a.g if isinstance(a, Dual) else 0.0 for a in args]
        return Dual(f(*values), differential(_FLOATS, *values, *changes))
    return apply


def _flat(f):
    """A function of zero derivative (floor, sign, a step): its value, a float."""
    def apply(*args):
        return f(*(_value(a) for a in args))
    return apply


def _missing(f, name: str):
    def apply(*args):
        if any(isinstance(a, Dual) for a in args):
            raise NotDifferentiable(f"no derivative of {name} here")
        return f(*args)
    return apply


def _on_duals(spec: FunctionSpec, f):
    """The function of `spec` computed as `f` on floats, on floats and duals."""
    if spec.steps:
        return _flat(f)
    if spec.differential is None:
        return _missing(f, spec.name)
    return _differentiable(f, spec.differential, spec.arity)


_FAST = fast_namespace()
# what the differentials call on floats: the printed Python's functions by sympy's names
_FLOATS = SimpleNamespace(pi=math.pi, **python_callables(_FAST))
# the records by the function of their own their printed Python calls (math.sin, _sign)
_CALLING = {s.python_callee: s for s in FUNCTION_SPECS if s.python_callee is not None}
# `math` for dual numbers (what the printed Python calls as math.NAME)
_DUAL_MATH = SimpleNamespace(pi=math.pi, e=math.e, nan=math.nan, inf=math.inf, **{
    name.removeprefix("math."): _on_duals(s, getattr(math, name.removeprefix("math.")))
    for name, s in _CALLING.items() if name.startswith("math.")})


def _namespace() -> dict:
    names = {name: _on_duals(s, _FAST[name]) for name, s in _CALLING.items()
             if not name.startswith("math.")}
    return dict(names, math=_DUAL_MATH)


class DualJacobian:
    """A generated program (`source`, its function `name`, called as name(*inputs, out))
    evaluated with its values' partial derivatives in the `varied` inputs: {input
    argument's position: the positions of its entries that vary}, numbered in that
    order.  `call(*inputs, out)` fills `out` like the symbolic Jacobian's program: the
    values first when `with_values`, then the gradients row by row."""

    backend = "dual"

    def __init__(self, source: str, name: str, n_in: int, varied: dict[int, list[int]],
                 with_values: bool):
        self.source, self.name, self.n_in = source, name, n_in
        self.varied, self.with_values = varied, with_values
        self.n_varied = sum(len(v) for v in varied.values())
        self._code = None           # Python's compiled code: most of the cost of the first call
        self._function = None

    def __getstate__(self) -> dict:
        return dict(self.__dict__, _function=None,
                    _code=None if self._code is None else marshal.dumps(self._code))

    def __setstate__(self, state: dict) -> None:
        code = state.pop("_code")
        self.__dict__.update(state)
        self._code = None if code is None else marshal.loads(code)

    def call(self, *arrays) -> None:
        if self._function is None:
            if self._code is None:
                self._code = compile(self.source, f"<autolev dual {self.name}>", "exec")
            namespace = _namespace()
            exec(self._code, namespace)
            self._function = namespace[self.name]
        inputs, out = list(arrays[:self.n_in]), arrays[self.n_in]
        k = 0
        for position, entries in self.varied.items():
            values = [float(v) for v in inputs[position]]
            for i in entries:
                g = np.zeros(self.n_varied)
                g[k] = 1.0
                values[i] = Dual(values[i], g)
                k += 1
            inputs[position] = values
        n_out = len(out) // (self.n_varied + self.with_values)
        results = [0.0] * n_out
        try:
            self._function(*[a.tolist() if isinstance(a, np.ndarray) else a
                             for a in inputs], results)
        except MATH_ERRORS as exc:
            raise NotDifferentiable(str(exc)) from None
        grads = out[n_out:] if self.with_values else out
        grads = grads.reshape(n_out, self.n_varied)
        for r, value in enumerate(results):
            if isinstance(value, Dual):
                v, grads[r] = value.v, value.g
            else:
                v, grads[r] = value, 0.0
            if self.with_values:
                out[r] = v
