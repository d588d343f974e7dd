"""Autolev's .in files: their lines of values, and numbers as they write them, read (a
Fortran D exponent too) and written (' 0.0', '-9.81'); and the rows of its output
files.  No sympy: the command line reads the names an .in file gives before the model
is built."""
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


def row(values) -> str:
    """A line of Autolev's output files: each value as its programs' printf("%- 14.6E")
    wrote it."""
    return "".join(" " + ("%- 14.6E" % v) for v in values) + "\n"


# a value line of a Matlab program's ReadUserInput: NAME = value; % UNIT  Description
_MATLAB_VALUE = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*)\s*=\s*([^;%]*?)\s*;\s*%(.*)$")


def in_file_lines(text: str) -> list[tuple[int, str, str, str]]:
    """(line number, name, value as written, unit) of each value line of an .in file's
    text: Autolev's layout, the name in columns 22-42, the unit to column 58, a '|' in
    column 59 and the value after it (headings and rules skipped).  The text of a
    Matlab program Autolev wrote holds its inputs in ReadUserInput instead (`NAME =
    value;  % UNIT  Description`): those are its value lines."""
    if re.search(r"^function\s+(VAR\s*=\s*)?ReadUserInput\b", text, re.M):
        return _matlab_input_lines(text)
    lines = []
    for lineno, line in enumerate(text.splitlines(), 1):
        line = line.rstrip("\r\n")
        if len(line) < 60 or line[58] != "|":
            continue
        name = line[21:42].strip()
        if not name or name.lower() == "quantity" or set(line[:58]) <= {"-", " "}:
            continue
        lines.append((lineno, name, line[59:].strip(), line[42:58].strip()))
    return lines


def _matlab_input_lines(text: str) -> list[tuple[int, str, str, str]]:
    """The value lines of a Matlab program's ReadUserInput (to its next function)."""
    lines, inside = [], False
    for lineno, line in enumerate(text.splitlines(), 1):
        if line.startswith("function"):
            inside = re.match(r"function\s+(VAR\s*=\s*)?ReadUserInput\b", line) is not None
            continue
        found = _MATLAB_VALUE.match(line.strip()) if inside else None
        if found is not None:
            # the comment: the unit in its first 20 characters (after a space), then
            # what the value is
            name, value, comment = found.groups()
            lines.append((lineno, name, value, comment[1:21].strip()))
    return lines
