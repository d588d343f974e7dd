#!/usr/bin/env python3
"""Regenerate tests/golden/NAME.py from autolev_examples/NAME.al, its SymPy script
(`autolev convert --to sympy`) tests/golden/sympy/NAME_sympy.py, and the Python of every
case of tests/fixtures/constructs.txt, showing the diff.

    python tools/update_goldens.py            # write the changes, print the diff
    python tools/update_goldens.py --check    # only report which goldens differ

Goldens change only through this command, and the printed diff is to be read.
"""
from __future__ import annotations

import argparse
import difflib
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))
sys.path.insert(0, str(ROOT / "tests"))

import autolev  # noqa: E402
from helpers import constructs  # noqa: E402

EXAMPLES = ROOT / "autolev_examples"
GOLDEN = ROOT / "tests" / "golden"
SYMPY_GOLDEN = GOLDEN / "sympy"


def golden_text(model: Path) -> str:
    return autolev.transpile(model)


def sympy_golden_text(model: Path) -> str:
    """The example's SymPy script at the level `auto` chooses."""
    return autolev.export_sympy(autolev.load(model), model.name)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="write nothing")
    ns = ap.parse_args()
    SYMPY_GOLDEN.mkdir(parents=True, exist_ok=True)
    changed = 0
    examples = sorted(EXAMPLES.glob("*.al"))
    goldens = [(GOLDEN / (model.stem + ".py"), model, golden_text) for model in examples]
    goldens += [(SYMPY_GOLDEN / (model.stem + "_sympy.py"), model, sympy_golden_text)
                for model in examples]
    for target, model, text_of in goldens + [(constructs.FIXTURE, None, None)]:
        if model is None:
            old, new = constructs.updated()
        else:
            new = text_of(model)
            old = target.read_text() if target.exists() else ""
        if new == old:
            continue
        changed += 1
        sys.stdout.writelines(difflib.unified_diff(
            old.splitlines(keepends=True), new.splitlines(keepends=True),
            f"a/{target.relative_to(ROOT)}", f"b/{target.relative_to(ROOT)}"))
        if not ns.check:
            target.write_text(new)
    print(f"{changed} golden file(s) {'differ' if ns.check else 'updated'}")
    return 1 if ns.check and changed else 0


if __name__ == "__main__":
    sys.exit(main())
