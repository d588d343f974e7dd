"""How INPUT and OUTPUT units change numbers, as Autolev's programs did.

A value given in degrees (`INPUT Q1 = 30 DEG`, or `UNITS Q1 = DEG` for a value read
from the .in file) is stored in radians; an output in degrees is printed in degrees.
Compound units with degrees (`DEG/S`) were NOT converted by Autolev's programs: such
a value is used as radians per second.  That is reproduced, with a warning, because
legacy outputs depend on it.  Every other unit is a label.
"""
from __future__ import annotations

import math
import re

DEGREE_WORDS = {"deg", "degs", "degree", "degrees"}


def _words(unit: str) -> list[str]:
    return re.findall(r"[A-Za-z_]+", unit or "")


def is_degrees(unit: str | None) -> bool:
    """A plain angle in degrees: converted on input and output."""
    return unit is not None and unit.strip().lower() in DEGREE_WORDS


def has_degrees(unit: str | None) -> bool:
    """A compound unit mentioning degrees (DEG/S): NOT converted, as in Autolev."""
    return unit is not None and not is_degrees(unit) and any(
        w.lower() in DEGREE_WORDS for w in _words(unit))


def to_internal(value: float, unit: str | None) -> float:
    return value * math.pi / 180 if is_degrees(unit) else value


def to_output(value: float, unit: str | None) -> float:
    return value * 180 / math.pi if is_degrees(unit) else value
