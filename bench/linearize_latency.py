#!/usr/bin/env python3
"""How long `autolev linearize` keeps a user waiting: cold (an empty cache) and warm,
whole process, for large corpus models; several source trees side by side, alternated
in one run (machines are noisy: compare the ratios).

    python bench/linearize_latency.py                         # this tree
    python bench/linearize_latency.py --src OLD/src --src src # before and after

Each model's constants come from its own INPUT statements, else a value in [0.5, 1)
fixed by the constant's name (products of inertia 0: the inertias stay positive).
"""
from __future__ import annotations

import argparse
import hashlib
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CORPUS = Path(os.environ.get("AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus"))

MODELS = [
    ("MAE-223 bicycle 14 (BICYCLE14)",
     "moorepants+MAE-223/BicycleDynamicsProject/AutolevSRC/BICYCLE14.AL"),
    ("MAE-223 bicycle 13 (BICYCLE13)",
     "moorepants+MAE-223/BicycleDynamicsProject/AutolevSRC/BICYCLE13.AL"),
    ("Whipple benchmark (shipped example)", str(ROOT / "autolev_examples" /
                                                "whipple_benchmark.al")),
]

IN_LINE = re.compile(r"^Constant\s+(\S+)\s+\S+\s+\|")
PRODUCT_OF_INERTIA = re.compile(r"^I[A-Z0-9]*?(12|23|31|21|32|13)$")


def value_of(name: str) -> float:
    if PRODUCT_OF_INERTIA.match(name.upper()):
        return 0.0
    digest = hashlib.sha256(name.lower().encode()).digest()
    return 0.5 + 0.5 * int.from_bytes(digest[:6], "big") / 2.0 ** 48


def autolev(src: Path, args: list, cache: Path, limit: float, **more_env):
    """(seconds, completed process) of `python -m autolev ARGS` on the tree `src`."""
    env = dict(os.environ, AUTOLEV_CACHE=str(cache), PYTHONPATH=str(src), **more_env)
    start = time.perf_counter()
    try:
        done = subprocess.run([sys.executable, "-m", "autolev", *args], env=env,
                              capture_output=True, text=True, timeout=limit)
    except subprocess.TimeoutExpired:
        return None, None
    return time.perf_counter() - start, done


def filled_in(src: Path, model: Path, work: Path, limit: float) -> Path | None:
    """An .in file of the model's first CODE DYNAMICS: its template, every constant
    without an INPUT value given value_of."""
    cache = Path(tempfile.mkdtemp(prefix="autolev-lin-"))
    try:
        # in the foreground: no compile left running into the cache removed below
        autolev(src, ["run", str(model), "--out", str(work / "template"), "--tfinal", "0"],
                cache, limit, AUTOLEV_FOREGROUND="1")
    finally:
        shutil.rmtree(cache, ignore_errors=True)
    templates = sorted((work / "template").glob("*-template.in"))
    if not templates:
        return None
    lines = []
    for line in templates[0].read_text().splitlines():
        m = IN_LINE.match(line)
        if m:
            line = line.rsplit("|", 1)[0] + f"| {value_of(m.group(1)):.15g}"
        lines.append(line)
    path = work / "values.in"
    path.write_text("\n".join(lines) + "\n")
    return path


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--src", action="append", type=Path,
                    help="a source tree (its src folder); several: side by side")
    ap.add_argument("--only", help="models whose label contains this text")
    ap.add_argument("--warm", type=int, default=2, help="warm runs per model and tree")
    ap.add_argument("--limit", type=float, default=900.0, help="seconds per command")
    ns = ap.parse_args(argv)
    trees = [p.resolve() for p in (ns.src or [ROOT / "src"])]
    print(f"{'model':38s} {'tree':24s} {'cold s':>8s} {'warm s':>8s}")
    for label, rel in MODELS:
        if ns.only and ns.only.lower() not in label.lower():
            continue
        model = Path(rel) if Path(rel).is_absolute() else CORPUS / rel
        if not model.exists():
            print(f"{label}: not in the corpus ({rel})")
            continue
        with tempfile.TemporaryDirectory(prefix="autolev-lin-") as work:
            work = Path(work)
            values = filled_in(trees[-1], model, work, ns.limit)
            args = ["linearize", str(model), "--out", str(work / "out")]
            if values is not None:
                args += ["--in", str(values)]
            caches = {tree: Path(tempfile.mkdtemp(prefix="autolev-lin-")) for tree in trees}
            cold, warm = {}, {tree: [] for tree in trees}
            for tree in trees:                # alternated: cold of each, then the warm runs
                cold[tree] = autolev(tree, args, caches[tree], ns.limit)
            for _ in range(ns.warm):
                for tree in trees:
                    warm[tree].append(autolev(tree, args, caches[tree], ns.limit))
            for tree in trees:
                seconds, done = cold[tree]
                name = str(tree.parent.name if tree.name == "src" else tree)[-24:]
                if seconds is None:
                    print(f"{label:38s} {name:24s} {'> limit':>8s}")
                elif done.returncode != 0:
                    why = (done.stderr.strip().splitlines() or ["?"])[-1][:60]
                    print(f"{label:38s} {name:24s} failed: {why}")
                else:
                    best = min((s for s, d in warm[tree] if s is not None and
                                d.returncode == 0), default=float("nan"))
                    print(f"{label:38s} {name:24s} {seconds:8.1f} {best:8.1f}", flush=True)
                shutil.rmtree(caches[tree], ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
