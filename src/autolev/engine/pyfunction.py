"""The generated Python's functions without sympy: what the printed code calls (C's
sign, step, trunc and round, the math module, or numpy where math raises, as C gives
inf and nan), and the callable of a program's source or compiled code.  A run plan's
Python functions are read back with this alone.
"""
from __future__ import annotations

import math

from .functions import FUNCTION_SPECS, written


def _sign(x):
    return (x > 0) - (x < 0)


def _heaviside(x):
    return 1.0 if x > 0 else (0.5 if x == 0 else 0.0)


def _trunc(x):
    return float(math.trunc(x))


def _round(x):
    # C's round: halves away from zero (x - trunc(x) is exact in double precision)
    t = float(math.trunc(x))
    return t + math.copysign(1.0, x) if abs(x - t) >= 0.5 else t


def _np_round(x):
    import numpy as np      # numpy: only for the fallback, and runs (a transcript has none)
    t = np.trunc(x)
    return t + np.copysign(1.0, x) * (np.abs(x - t) >= 0.5)


def _np_heaviside(x):
    import numpy as np
    return np.heaviside(x, 0.5)


# the functions the spellings name that neither math nor numpy has, by their own names
_HELPERS = {f.__name__: f for f in (_sign, _heaviside, _trunc, _round, _np_round,
                                     _np_heaviside)}
# the functions of their own the records' Python calls -> the fallback's spelling
_NUMPY_OF = {s.python_callee: s.numpy for s in FUNCTION_SPECS if s.numpy is not None}
_NUMPY_OF_MATH = {name.removeprefix("math."): numpy for name, numpy in _NUMPY_OF.items()
                  if name.startswith("math.")}
# the helpers it calls -> the fallback's spelling (_sign: numpy's sign)
_NUMPY_OF_HELPER = {name: numpy for name, numpy in _NUMPY_OF.items() if name in _HELPERS}


def _numpy_function(spelling: str):
    if spelling.startswith("scipy.special."):
        import scipy.special   # 0.1 s to import: only where math raised
        return getattr(scipy.special, spelling.removeprefix("scipy.special."))
    import numpy as np
    return _HELPERS[spelling] if spelling in _HELPERS else getattr(np, spelling)


class _NumpyMath:
    """`math` for the fallback evaluation: numpy's functions, which give inf and nan
    where math raises (as the C code does)."""

    def __getattr__(self, name):
        return _numpy_function(_NUMPY_OF_MATH.get(name, name))


# what the math module raises where C gives inf or nan
MATH_ERRORS = (ZeroDivisionError, ValueError, OverflowError, TypeError)


def fast_namespace() -> dict:
    """What the printed Python calls: the math module and C's sign, step, trunc, round."""
    return {"math": math, **{name: _HELPERS[name] for name in _NUMPY_OF_HELPER}}


def safe_namespace() -> dict:
    """The same names on numpy, which gives inf and nan where math raises (as C does)."""
    return {"math": _NumpyMath(), **{name: _numpy_function(numpy)
                                     for name, numpy in _NUMPY_OF_HELPER.items()}}


def python_callables(namespace: dict) -> dict:
    """{sympy's name of a function: what its printed Python computes} in `namespace`
    (fast_namespace's or the dual numbers'): the callee itself, or a template compiled
    as a function of its arguments."""
    out = {}
    for spec in FUNCTION_SPECS:
        if spec.sympy is None or spec.python is None:
            continue
        if "{" in spec.python:
            args = [f"args[{k}]" for k in range(spec.arity)]
            text = "lambda *args: " + written(spec.python, args)
        else:
            text = spec.python
        out[spec.sympy] = eval(text, dict(namespace))
    return out


def python_function(source: str, name: str, n_in: int, code=None):
    """The callable of a generated Python program (codegen.compile_python) from its
    source, or from its compiled `code` (kept as `call.code`: compiling a large program
    is most of the cost)."""
    import numpy as np
    if code is None:
        code = compile(source, f"<autolev generated {name}>", "exec")
    fast_ns, safe_ns = fast_namespace(), safe_namespace()
    exec(code, fast_ns)
    exec(code, safe_ns)
    fast, safe = fast_ns[name], safe_ns[name]

    def call(*arrays):
        try:
            # Python floats: a division by zero or a domain error raises (numpy
            # scalars would warn once per line of the program and go on)
            return fast(*[a.tolist() if isinstance(a, np.ndarray) else a
                          for a in arrays[:n_in]], arrays[n_in])
        except MATH_ERRORS:
            with np.errstate(all="ignore"):
                args = [np.asarray(a, dtype=np.float64) for a in arrays[:n_in]]
                return safe(*args, arrays[n_in])
    def rows(arrays, per_row, out):
        """Every row of `out` from the rows of the inputs that are `per_row`."""
        for i in range(len(out)):
            call(*[a[i] if each else a for a, each in zip(arrays, per_row)], out[i])
        return out
    call.code = code
    call.rows = rows
    return call
