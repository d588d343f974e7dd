"""What generated code imports: Autolev semantics on sympy.

    import autolev.runtime as al
    model = al.Model("pendulum")

The names are imported when first used (PEP 562): a warm run from its run plan reads
modules of this package (the integration loop, the output files) without sympy.
"""
from __future__ import annotations

import importlib
import importlib.util

_NAMED = {"AutolevModelError": "..engine.errors", "MissingValues": "..engine.errors",
          "Frame": ".frame", "KaneEquations": ".kane", "Model": ".model", "Body": ".point",
          "Particle": ".point", "Point": ".point", "TIME": ".symbols", "Z": ".symbols",
          "derivative": ".symbols", "derivatives": ".symbols", "Dyadic": ".vectors",
          "Vector": ".vectors", "outer": ".vectors"}


def __getattr__(name: str):
    """A name of the runtime: one of _NAMED, else one of Autolev's functions
    (al.dot, al.express, ...)."""
    if name == "__all__":
        return list(_NAMED) + importlib.import_module(".functions", __name__).__all__
    if name.startswith("__"):
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    if name in _NAMED:
        module = importlib.import_module(_NAMED[name], __name__)
    elif importlib.util.find_spec(f"{__name__}.{name}") is not None:
        # a submodule (`from autolev.runtime import numerics`): the import system
        # loads it once this fails, without the functions (and sympy)
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    else:
        module = importlib.import_module(".functions", __name__)
        if name not in module.__all__:
            raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(module, name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_NAMED)
                  | set(importlib.import_module(".functions", __name__).__all__))
