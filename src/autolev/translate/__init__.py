"""Translation of the IR into a Python module on autolev.runtime."""
from __future__ import annotations

from .. import ir

# the families register their handlers in core's tables when imported, before any use
from . import (  # noqa: F401
    assignments, commands, declarations, dynamics, expressions, functions, io, kinematics,
    session, special,
)
from .core import PROBES, Probe, Translation, Translator
from .functions.table import FUNCTIONS

__all__ = ["translate", "Translation", "vocabulary", "Probe", "PROBES"]


def vocabulary() -> frozenset[str]:
    """Autolev's own commands and functions (upper case): names no macro or user
    function file replaces."""
    return frozenset(FUNCTIONS) | frozenset(commands.COMMANDS) | commands.IN_PLACE


def translate(program: ir.Program, module_name: str | None = None,
              probes: tuple[Probe, ...] = ()) -> Translation:
    """The Python text of a program, its line map and its diagnostics; with the lines
    keeping each of `probes` (see Probe)."""
    name = module_name or _stem(program.filename)
    return Translator(program, name, probes).translate()


def _stem(filename: str) -> str:
    base = filename.replace("\\", "/").rsplit("/", 1)[-1]
    return base.rsplit(".", 1)[0] if "." in base else base
