#!/usr/bin/env python3
"""Mutation fuzzing of the parser: no input may end in a Python traceback.

Takes the models of the public corpus (or, without it, the project's own examples),
mutates them (characters and lines deleted, inserted, duplicated; seeded), parses
each mutant with `autolev.parse` and counts the outcomes:

  parsed     the mutant is still valid Autolev
  diagnosed  AutolevSyntaxError with well-formed diagnostics (line/col inside the file)
  crash      anything else: a bug (the traceback is printed)

    python bench/fuzz.py [--mutants 10000] [--seed 1] [--corpus DIR]
"""
from __future__ import annotations

import argparse
import csv
import os
import random
import sys
import time
import traceback
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

import autolev  # noqa: E402

# characters that matter to the lexer, plus some that never should appear
ALPHABET = ("abcdefghijklmnopqrstuvwxyzQ0123456789 \t\n\r&%'><=+-*/^()[]{},;:._#$\\\"!?@~`|"
            "\x00\x1aé\u00a0")


def mutate(text: str, rng: random.Random) -> str:
    """Apply 1-4 random edits: delete, insert or duplicate a character or a line."""
    for _ in range(rng.randint(1, 4)):
        op = rng.randrange(6)
        if op < 3 or not text:
            pos = rng.randint(0, len(text))
            if op == 0 and text:
                pos = min(pos, len(text) - 1)
                text = text[:pos] + text[pos + 1:]
            elif op == 1 or not text:
                text = text[:pos] + rng.choice(ALPHABET) + text[pos:]
            else:
                pos = min(pos, len(text) - 1)
                text = text[:pos] + text[pos] + text[pos:]
        else:
            lines = text.split("\n")
            i = rng.randrange(len(lines))
            if op == 3:
                del lines[i]
            elif op == 4:
                lines.insert(i, lines[rng.randrange(len(lines))])
            else:
                j = rng.randrange(len(lines))
                lines[i], lines[j] = lines[j], lines[i]
            text = "\n".join(lines)
    return text


def check_one(text: str, filename: str) -> tuple[str, str | None]:
    """('parsed' | 'diagnosed' | 'crash', traceback or problem)."""
    try:
        autolev.parse(text, filename)
    except autolev.AutolevSyntaxError as exc:
        n_lines = text.count("\n") + text.count("\r") + 1
        for d in exc.diagnostics:
            if d.line < 1 or d.col < 1 or (d.file == filename and d.line > n_lines + 1):
                return "crash", f"diagnostic outside the file: {d.format()}"
            if not d.message:
                return "crash", f"empty message: {d!r}"
        if not any(d.severity == "error" for d in exc.diagnostics):
            return "crash", "AutolevSyntaxError without an error diagnostic"
        return "diagnosed", None
    except Exception:  # noqa: BLE001 -- the point of a fuzzer is to catch everything
        return "crash", traceback.format_exc()
    return "parsed", None


def corpus_models(corpus: Path) -> list[Path]:
    listing = ROOT.parent / "shared" / "corpus" / "visible.tsv"
    out = []
    if listing.exists():
        for row in csv.DictReader(open(listing), delimiter="\t"):
            if row["kind"] == "al" and not row["path"].lower().endswith(".a"):
                p = corpus / row["repo"].replace("/", "+") / row["path"]
                if p.exists():
                    out.append(p)
    return sorted(set(out))


def seeds(corpus: Path | None) -> list[Path]:
    found = corpus_models(corpus) if corpus is not None and corpus.is_dir() else []
    if not found:
        found = sorted((ROOT / "autolev_examples").glob("*.al")) + \
            sorted((ROOT / "tests" / "data").glob("*.al"))
    return found


def run(n: int, seed: int, files: list[Path], quiet: bool = False) -> Counter:
    rng = random.Random(seed)
    texts = [(f, f.read_bytes().decode("latin-1")) for f in files]
    outcomes: Counter = Counter()
    shown = 0
    for _ in range(n):
        path, text = texts[rng.randrange(len(texts))]
        mutant = mutate(text, rng)
        outcome, detail = check_one(mutant, str(path))
        outcomes[outcome] += 1
        if outcome == "crash" and shown < 3 and not quiet:
            shown += 1
            print(f"--- crash on a mutant of {path}:\n{detail}", file=sys.stderr)
    return outcomes


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mutants", type=int, default=10000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--corpus", type=Path, default=Path(os.environ.get(
        "AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus")))
    ns = ap.parse_args()
    files = seeds(ns.corpus)
    print(f"{len(files)} seed files; {ns.mutants} mutants; seed {ns.seed}")
    t0 = time.perf_counter()
    outcomes = run(ns.mutants, ns.seed, files)
    dt = time.perf_counter() - t0
    print(f"parsed {outcomes['parsed']}, diagnosed {outcomes['diagnosed']}, "
          f"crash {outcomes['crash']}  ({dt:.1f} s, {ns.mutants / dt:.0f} mutants/s)")
    return 1 if outcomes["crash"] else 0


if __name__ == "__main__":
    sys.exit(main())
