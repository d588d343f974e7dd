#!/usr/bin/env python3
"""Conformance over the public corpus: how many models each stage accepts.

    python bench/corpus.py [--corpus DIR] [--list]

Reads shared/corpus/visible.tsv, finds the files that shared/corpus/materialize.py
copied (default ~/.cache/autolev-corpus, or $AUTOLEV_CORPUS), and reports per model
the outcome of each stage: parse (syntax and includes).  With --list, every model
that fails is listed with its first diagnostic.
"""
from __future__ import annotations

import argparse
import csv
import os
import sys
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

import autolev  # noqa: E402


def corpus_models(corpus: Path) -> list[tuple[str, Path]]:
    """(id, path) of every model row (kind `al`, not a .a macro) found in the corpus.

    A row pinned to an older commit whose files differ from the newest ones lives in
    `OWNER+NAME@commit/` (materialize.py); it is read from an overlay folder that puts
    those files over the newest ones, so its RUN files and macros are of its commit."""
    listing = ROOT.parent / "shared" / "corpus" / "visible.tsv"
    out, seen = [], set()
    for row in csv.DictReader(open(listing), delimiter="\t"):
        if row["kind"] != "al" or row["path"].lower().endswith(".a"):
            continue
        base = corpus / row["repo"].replace("/", "+")
        pinned_root = corpus / (row["repo"].replace("/", "+") + "@" + row["commit"][:8])
        p = base / row["path"]
        if pinned_root.is_dir() and row["id"].endswith(row["commit"][:8]):
            p = _overlay(base, pinned_root) / row["path"]
        if p.exists() and p not in seen:
            seen.add(p)
            out.append((row["id"], p))
    return out


def _overlay(base: Path, pinned: Path) -> Path:
    """A copy of `base` with the files of `pinned` over it (made once, in the cache)."""
    import shutil
    target = base.parent / ".overlay" / pinned.name
    if not target.exists():
        shutil.copytree(base, target)
        for f in pinned.rglob("*"):
            if f.is_file():
                dest = target / f.relative_to(pinned)
                dest.parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(f, dest)
    return target


def parse_stage(path: Path) -> tuple[str, str]:
    try:
        autolev.parse(path)
    except autolev.AutolevSyntaxError as exc:
        first = next(d for d in exc.diagnostics if d.severity == "error")
        return "syntax error", first.format(context=False).splitlines()[0]
    return "ok", ""


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corpus", type=Path, default=Path(os.environ.get(
        "AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus")))
    ap.add_argument("--list", action="store_true", help="list every failing model")
    ns = ap.parse_args()
    models = corpus_models(ns.corpus)
    if not models:
        print(f"no corpus under {ns.corpus}: see shared/corpus/materialize.py")
        return 1
    outcomes: Counter = Counter()
    failures = []
    for ident, path in models:
        outcome, detail = parse_stage(path)
        outcomes[outcome] += 1
        if outcome != "ok":
            failures.append((ident, detail))
    total = len(models)
    print(f"parse: {outcomes['ok']}/{total} models read without error "
          f"({100 * outcomes['ok'] / total:.1f} %)")
    if ns.list or failures:
        for ident, detail in failures:
            print(f"  {ident}: {detail}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
