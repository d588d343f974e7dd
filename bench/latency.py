#!/usr/bin/env python3
"""What a user waits for, on every corpus model: `autolev run` cold and warm, and the
time to be told which constants have no value.

    python bench/latency.py [--examples] [--only ID ...] [--warm N] [--limit S]
                            [--json FILE]

Per model (bench/journeys.py's list and its values: INPUT, the shipped .in, then 1 for
every constant a run names as having no value, 0 for a product of inertia), each run a
fresh process (`python -m autolev run FILE -q`) with its own cache folder (AUTOLEV_CACHE):
    missing   an empty cache, no values by rule: the time until the run names the
              constants without a value (its note, before the model is formed; the
              run is then stopped), for a model that needs values by rule
    cold      an empty cache, the model's values: translate, form, build, run, write
    warm      the same cache again, the least of --warm runs
    exit      the run's exit status (0 ran; 1 a diagnostic, e.g. singular at T = 0)
Targets (issue 32): missing <= 2 s, cold <= 5 s, warm <= 0.3 s.  Models one at a time:
two runs side by side share two cores and measure each other.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import journeys  # noqa: E402

TARGETS = {"missing": 2.0, "cold": 5.0, "warm": 0.3}


def timed_run(path: Path, options: list, work: Path, cache: Path, limit: float):
    """One `autolev run` in a fresh process on `cache`: its Outcome."""
    os.environ["AUTOLEV_CACHE"] = str(cache)
    run_dir = work / "run"
    shutil.rmtree(run_dir, ignore_errors=True)
    return journeys.run_process(
        journeys.autolev_cli("run", path, "--out", run_dir, "-q", *options), work, limit)


NAMED = "no value given for"


def time_to_note(path: Path, options: list, work: Path, cache: Path, limit: float):
    """Seconds from the start of a run on an empty `cache` until its stderr names the
    constants without a value (None: it never did); the run is stopped there."""
    os.environ["AUTOLEV_CACHE"] = str(cache)
    env = dict(os.environ, PYTHONPATH=str(journeys.ROOT / "src"))
    start = time.monotonic()
    proc = subprocess.Popen([str(a) for a in journeys.autolev_cli(
        "run", path, "--out", work / "run", "-q", *options)], cwd=work, env=env,
        stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, errors="replace",
        start_new_session=True)
    seconds = None
    try:
        for line in proc.stderr:
            if NAMED in line:
                seconds = time.monotonic() - start
                break
            if time.monotonic() - start > limit:
                break
    finally:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()
    return seconds


def measure(ident: str, path: Path, companion: Path | None, warm: int, limit: float,
            scratch: Path) -> dict:
    work = scratch / ident
    work.mkdir(parents=True)
    cache = work / "cache"
    model = journeys.read_model(path)
    # the values first (their rounds fill a cache of their own, thrown away)
    os.environ["AUTOLEV_CACHE"] = str(work / "values-cache")
    _, values = journeys.run_with_values(ident, path, model, companion, work, limit, {})
    row = {"id": ident, "values": values.source}
    if values.by_rule:
        given = ["--in", str(companion)] if companion else []
        row["missing"] = time_to_note(path, given, work, cache, limit)
        shutil.rmtree(cache, ignore_errors=True)
    cold = timed_run(path, values.options, work, cache, limit)
    row["cold"] = cold.seconds
    row["exit"] = cold.returncode
    row["warm"] = min(timed_run(path, values.options, work, cache, limit).seconds
                      for _ in range(warm))
    row["reason"] = "" if cold.returncode == 0 else journeys._last_line(cold.stderr)
    return row


def table(rows: list) -> str:
    lines = [f"{'model':44} {'missing':>8} {'cold':>7} {'warm':>6} exit"]
    for r in rows:
        cells = []
        for key in ("missing", "cold", "warm"):
            value = r.get(key)
            if value is None:
                # asked, and the run never named them before it was stopped
                cells.append("never*" if key in r else "-")
                continue
            mark = "" if value <= TARGETS[key] else "*"
            cells.append(f"{value:.2f}{mark}")
        lines.append(f"{r['id'][:44]:44} {cells[0]:>8} {cells[1]:>7} {cells[2]:>6} "
                     f"{r['exit']}")
    for key, target in TARGETS.items():
        over = [r["id"] for r in rows if key in r and (r[key] is None or r[key] > target)]
        lines.append(f"{key} over {target} s: {len(over)}"
                     + (f" ({', '.join(over)})" if over else ""))
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--examples", action="store_true",
                    help="the shipped autolev_examples/*.al instead of the corpus")
    ap.add_argument("--only", action="append", metavar="ID",
                    help="models whose id contains ID (repeatable)")
    ap.add_argument("--warm", type=int, default=2, help="warm runs per model (default 2)")
    ap.add_argument("--limit", type=float, default=300, help="seconds per run")
    ap.add_argument("--json", type=Path, metavar="FILE", help="write the rows there")
    ns = ap.parse_args(argv)
    ns.corpus, ns.listing = journeys.CORPUS, journeys.LISTING
    models = journeys.chosen_models(ns)
    rows = []
    with tempfile.TemporaryDirectory(prefix="autolev-latency-") as scratch:
        for ident, path, companion in models:
            start = time.monotonic()
            rows.append(measure(ident, path, companion, ns.warm, ns.limit, Path(scratch)))
            print(f"{ident}: cold {rows[-1]['cold']:.2f} s, warm {rows[-1]['warm']:.2f} s "
                  f"({time.monotonic() - start:.0f} s)", file=sys.stderr, flush=True)
    print(table(rows))
    if ns.json:
        ns.json.write_text(json.dumps(rows, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
