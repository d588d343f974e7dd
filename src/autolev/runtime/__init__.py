"""What generated code imports: Autolev semantics on sympy.

    import autolev.runtime as al
    model = al.Model("pendulum")
"""
from .errors import AutolevModelError, MissingValues
from .frame import Frame
from .kane import KaneEquations
from .model import Model
from .point import Body, Particle, Point
from .symbols import TIME, Z, derivative, derivatives
from .vector import Dyadic, Vector, outer

__all__ = ["Model", "KaneEquations", "Frame", "Vector", "Dyadic", "Point", "Particle",
           "Body", "AutolevModelError", "MissingValues", "TIME", "Z", "derivative", "derivatives",
           "outer"]
from .functions import *  # noqa: E402,F401,F403  (Autolev's functions: al.dot, al.express, ...)
from .functions import __all__ as _functions_all  # noqa: E402

__all__ += _functions_all
