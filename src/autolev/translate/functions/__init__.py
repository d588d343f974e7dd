"""Autolev functions in expressions: one small writer per function, one module per
family of functions.

Each writer gets the translator and the call, checks its arguments (the kinds are
arguments.py's), and returns the Python (with its type).  Elementary functions map onto
sympy; everything with Autolev's own meaning (DT through definitions, EVALUATE, KE, ...)
onto the runtime.  table.py holds the writers by name and refuses a name it lacks;
importing the families fills it.
"""
from . import scalars, vectors, algebra, dynamics, matrices  # noqa: F401
