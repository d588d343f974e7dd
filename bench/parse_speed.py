#!/usr/bin/env python3
"""Parse speed over the visible corpus, and the ratio to SymPy's parse_autolev.

    python bench/parse_speed.py [--corpus DIR] [--sympy-python PYTHON] [--repeat 3]

Every model of shared/corpus/visible.tsv (kind `al`; macro files are read through the
models that call them) is parsed with `autolev.parse`; lines/s and total seconds are
printed.  SymPy's parser needs antlr4-python3-runtime 4.11, which cannot live beside
our 4.13.2, so it runs in another interpreter given by --sympy-python (a venv with
`sympy antlr4-python3-runtime==4.11.1`); both sides time only the parse calls, on the
same files, in the same run.  SymPy's parser stops at exceptions and skips past syntax
errors (printing them), so the ratio is also given over the models it reads cleanly.
"""
from __future__ import annotations

import argparse
import csv
import json
import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

# What sympy's parse_autolev does, step by step, so we can also see whether its
# parser read the whole file: its `prog : stat+` rule stops quietly at the first
# statement it cannot match.
SYMPY_SIDE = r"""
import io, json, sys, time, warnings
warnings.simplefilter("ignore")
import antlr4
from sympy.parsing.autolev._antlr.autolevlexer import AutolevLexer
from sympy.parsing.autolev._antlr.autolevparser import AutolevParser
from sympy.parsing.autolev._listener_autolev_antlr import MyListener
files = json.load(sys.stdin)
times = {f: None for f in files}
ok = {}
for _ in range(%(repeat)d):
    for f in files:
        text = open(f, "rb").read().decode("latin-1")
        err, sys.stderr = sys.stderr, io.StringIO()   # ANTLR prints syntax errors here
        t0 = time.perf_counter()
        try:
            tokens = antlr4.CommonTokenStream(AutolevLexer(antlr4.InputStream(text)))
            tree = AutolevParser(tokens).prog()
            whole = tokens.LA(1) == antlr4.Token.EOF
            antlr4.ParseTreeWalker().walk(MyListener(False), tree)
            ok[f] = whole
        except BaseException:
            ok[f] = False
        dt = time.perf_counter() - t0
        complaints, sys.stderr = sys.stderr.getvalue(), err
        ok[f] = ok[f] and "line " not in complaints
        times[f] = dt if times[f] is None else min(times[f], dt)
print(json.dumps({"times": times, "ok": ok}))
"""


def corpus_files(corpus: Path) -> list[Path]:
    listing = ROOT.parent / "shared" / "corpus" / "visible.tsv"
    out = []
    for row in csv.DictReader(open(listing), delimiter="\t"):
        if row["kind"] != "al" or row["path"].lower().endswith(".a"):
            continue
        p = corpus / row["repo"].replace("/", "+") / row["path"]
        if p.exists() and p not in out:
            out.append(p)
    return out


def time_ours(files: list[Path], repeat: int) -> tuple[dict[str, float], int, int]:
    """Best-of-`repeat` seconds per file, syntax-error count, lines read (with includes)."""
    import autolev
    times: dict[str, float] = {}
    errors = lines_read = 0
    for r in range(repeat):
        for f in files:
            t0 = time.perf_counter()
            try:
                program = autolev.parse(f)
            except autolev.AutolevSyntaxError:
                program = None
            dt = time.perf_counter() - t0
            times[str(f)] = min(dt, times.get(str(f), dt))
            if r == 0:
                errors += program is None
                lines_read += sum(_lines(name) for name in program.files) if program else 0
    return times, errors, lines_read


def _lines(name: str) -> int:
    p = Path(name)
    return p.read_bytes().count(b"\n") + 1 if p.exists() else 0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corpus", type=Path, default=Path(os.environ.get(
        "AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus")))
    ap.add_argument("--sympy-python", help="interpreter with sympy and antlr4 4.11")
    ap.add_argument("--repeat", type=int, default=3, help="best of N passes")
    ns = ap.parse_args()
    files = corpus_files(ns.corpus)
    if not files:
        print(f"no corpus under {ns.corpus}: see shared/corpus/materialize.py")
        return 1
    n_lines = sum(f.read_bytes().count(b"\n") + 1 for f in files)
    times, errors, read = time_ours(files, ns.repeat)
    ours = sum(times.values())
    print(f"autolev.parse: {len(files)} models, {n_lines} lines ({read} with RUN files "
          f"and macros): {ours:.2f} s, {n_lines / ours:.0f} lines/s, "
          f"{errors} with syntax errors")
    if ns.sympy_python:
        r = subprocess.run([ns.sympy_python, "-c", SYMPY_SIDE % {"repeat": ns.repeat}],
                           input=json.dumps([str(f) for f in files]), text=True,
                           capture_output=True)
        if r.returncode != 0:
            print("sympy parse_autolev: could not run:", r.stderr.strip().splitlines()[-1:])
            return 0
        data = json.loads(r.stdout)
        theirs = sum(data["times"].values())
        good = [f for f, ok in data["ok"].items() if ok]
        ours_good = sum(times[f] for f in good)
        theirs_good = sum(data["times"][f] for f in good)
        print(f"sympy parse_autolev: {theirs:.2f} s over all {len(files)} models "
              f"({len(files) - len(good)} raised, reported syntax errors or stopped early); "
              "time ratio sympy/autolev "
              f"{theirs / ours:.2f}")
        print(f"  on the {len(good)} models sympy reads without an error: sympy "
              f"{theirs_good:.2f} s, autolev {ours_good:.2f} s, ratio "
              f"{theirs_good / ours_good:.2f}")
    else:
        print("sympy parse_autolev: not measured (give --sympy-python)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
