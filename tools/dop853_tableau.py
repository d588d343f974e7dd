#!/usr/bin/env python3
"""Write src/autolev/runtime/numerics/dop853_tableau.py: the Dormand-Prince 8(5,3)
coefficients the compiled loop integrates with, as exact float literals, so that a run
does not import scipy.integrate (over a second) to read them.

    python tools/dop853_tableau.py            # write the module
    python tools/dop853_tableau.py --check    # exit 1 when the module differs

The numbers are scipy's (Hairer's published dop853 coefficients);
tests/runtime/test_libraries.py checks the module against scipy's table.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

from autolev.runtime.libraries import dormand_prince_853  # noqa: E402

TARGET = ROOT / "src" / "autolev" / "runtime" / "numerics" / "dop853_tableau.py"


def _numbers(name: str, values) -> list[str]:
    items = [repr(float(v)) for v in values]
    lines, line = [f"{name} = ("], "   "
    for item in items:
        if len(line) + len(item) + 2 > 88:
            lines.append(line.rstrip())
            line = "   "
        line += f" {item},"
    lines.append(line.rstrip())
    lines.append(")")
    return lines


def module_text() -> str:
    k = dormand_prince_853()
    out = ['"""The Dormand-Prince 8(5,3) tableau (Hairer\'s dop853 coefficients, as scipy',
           "has them), written by tools/dop853_tableau.py: a run reads it without importing",
           'scipy.integrate.  Flat, row by row; the compiled loop reads A, B, C, E3, E5, D."""',
           "", f"STAGES = {k.stages}", f"EXTENDED = {k.extended}", ""]
    for name, values in (("A", k.a.ravel()), ("B", k.b), ("C", k.c), ("E3", k.e3),
                         ("E5", k.e5), ("D", k.d.ravel())):
        out += _numbers(name, values)
    return "\n".join(out) + "\n"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true")
    ns = ap.parse_args()
    text = module_text()
    if ns.check:
        same = TARGET.exists() and TARGET.read_text() == text
        print(f"{TARGET.relative_to(ROOT)}: {'unchanged' if same else 'differs'}")
        return 0 if same else 1
    TARGET.write_text(text)
    print(f"wrote {TARGET.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
