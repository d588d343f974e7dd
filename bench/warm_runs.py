#!/usr/bin/env python3
"""Cold and warm runs of the largest corpus models: the time from a fresh Python to the
last row, split by stage, first with an empty cache (cold) and then again (warm: the
built model read back from the cache of built models, the compiled code from the build
cache).  Target (issue 17): warm under 1 s.

    python bench/warm_runs.py [--corpus DIR] [--warm N]

Each run is a process of its own with the same private cache folder; the numbers are
the minimum over the warm runs.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "bench"))

from large_models import MODELS  # noqa: E402

EXTRA = [("Whipple benchmark (example)", str(ROOT / "autolev_examples" /
                                              "whipple_benchmark.al"))]

CHILD = r"""
import json, sys, tempfile, time, warnings
t0 = time.perf_counter()
import autolev
from autolev.loader import load_for_run
t1 = time.perf_counter()
warnings.simplefilter("ignore")
model, notes = load_for_run(sys.argv[1])
t2 = time.perf_counter()
build = run = 0.0
rows = failed = 0
with tempfile.TemporaryDirectory() as out:
    # constants without a value are 0 (the corpus models leave them to their .in files)
    for done in model.run_commands(model.commands_named(None), out, keep_going=True,
                                   missing_values="zero"):
        if done.result is not None:
            build += done.result.stats.get("build_seconds", 0.0)
            rows += done.result.stats.get("rows", 0)
        failed += done.error is not None
        run += done.seconds
t3 = time.perf_counter()
print(json.dumps({"import": t1 - t0, "load": t2 - t1, "build": build,
                  "integrate": run - build, "total": t3 - t0, "rows": rows, "failed": failed,
                  "commands": len(model.code_commands)}))
"""


def one_run(path: Path, cache: str, limit: float) -> dict | str:
    env = dict(os.environ, AUTOLEV_CACHE=cache, PYTHONPATH=str(ROOT / "src"))
    env.pop("AUTOLEV_NO_MODEL_CACHE", None)
    try:
        r = subprocess.run([sys.executable, "-c", CHILD, str(path)], capture_output=True,
                           text=True, timeout=limit, env=env)
    except subprocess.TimeoutExpired:
        return f"> {limit:.0f} s"
    if r.returncode != 0:
        return "failed: " + (r.stderr.strip().splitlines() or ["?"])[-1][:70]
    return json.loads(r.stdout.strip().splitlines()[-1])


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corpus", default=os.environ.get(
        "AUTOLEV_CORPUS", str(Path.home() / ".cache" / "autolev-corpus")))
    ap.add_argument("--warm", type=int, default=2, help="warm runs per model")
    ap.add_argument("--limit", type=float, default=600.0, help="seconds per run")
    args = ap.parse_args(argv)
    corpus = Path(args.corpus)
    models = [(label, corpus / rel) for label, rel in MODELS] + \
        [(label, Path(p)) for label, p in EXTRA]
    print(f"{'model':36s} {'':5s} {'total s':>8s} {'import':>7s} {'load':>7s} "
          f"{'build':>7s} {'run':>7s} {'rows':>6s} {'failed':>6s}")
    for label, path in models:
        if not path.exists():
            print(f"{label:36s} not in the corpus")
            continue
        cache = tempfile.mkdtemp(prefix="autolev-warm-")
        cold = one_run(path, cache, args.limit)
        warm = [one_run(path, cache, args.limit) for _ in range(args.warm)]
        warm_ok = [w for w in warm if isinstance(w, dict)]
        best = min(warm_ok, key=lambda w: w["total"]) if warm_ok else (warm[0] if warm else "-")
        for kind, d in (("cold", cold), ("warm", best)):
            if isinstance(d, str):
                print(f"{label:36s} {kind:5s} {d}")
                continue
            print(f"{label:36s} {kind:5s} {d['total']:8.2f} {d['import']:7.2f} "
                  f"{d['load']:7.2f} {d['build']:7.2f} {d['integrate']:7.2f} {d['rows']:6d} "
                  f"{d['failed']:6d}")
        if isinstance(cold, dict) and isinstance(best, dict):
            print(f"{'':36s} warm/cold {best['total'] / cold['total']:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
