"""Numerics of Autolev's CODE commands: compiled functions, integration on Autolev's
print schedule, its input and output files."""
from .run import OutputTable, Result, run_command

__all__ = ["OutputTable", "Result", "run_command"]
