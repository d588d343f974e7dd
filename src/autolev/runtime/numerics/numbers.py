"""Numbers as Autolev's .in files write them: read (a Fortran D exponent too) and
written (' 0.0', '-9.81')."""
from __future__ import annotations

import math
import re

# a number as Autolev's programs read it (C's strtod, Fortran's D exponents): ASCII
# digits only, no digit separators (Python's float takes '1_0' and other scripts' digits)
_NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eEdD][+-]?\d+)?", re.ASCII)


def parse_number(text: str):
    """The finite number `text` writes, or None."""
    t = text.strip()
    if not _NUMBER.fullmatch(t):
        return None
    v = float(t.replace("D", "E").replace("d", "e"))
    return v if math.isfinite(v) else None


def format_value(v: float) -> str:
    """A value as Autolev's .in files and Matlab tables show it (' 0.0', '-9.81')."""
    if v == int(v) and abs(v) < 1e15:
        s = f"{v:.1f}"
    else:
        s = f"{v:.15G}"
        if "E" in s:
            mant, exp = s.split("E")
            s = f"{mant}E{int(exp):+03d}"
    return s if s.startswith("-") else " " + s
