#!/usr/bin/env python3
"""What a user waits for, on every corpus model: `autolev run` cold and warm, and the
time to be told which constants have no value.

    python bench/latency.py [--examples] [--only ID ...] [--warm N] [--limit S]
                            [--against OLD/src] [--json FILE]

Per model (bench/journeys.py's list and its values: INPUT, the shipped .in, then 1 for
every constant a run names as having no value, 0 for a product of inertia), each run a
fresh process (`python -m autolev run FILE -q`) with its own cache folder (AUTOLEV_CACHE):
    missing   an empty cache, no values by rule: the time until the run names the
              constants without a value (its note, before the model is formed; the
              run is then stopped), for a model that needs values by rule
    first     the cold run's first numbers: when it began integrating (or evaluating
              an algebraic program), sampled by bench/phases.py
    cold      an empty cache, the model's values: translate, form, build, run, write,
              until the command returns (its C for later runs may compile on in the
              background: autolev run's own, cli/background.py); sampled by
              bench/phases.py (about 0.4 % of the time), whose seconds per phase
              (start-up, parsing, translation, forming, code generation, compile,
              evaluation, writing, other) a second table prints
    warm      the same cache again, the least of --warm runs (the first waits for
              that compile)
    exit      the cold run's exit status (0 ran; 1 a diagnostic, e.g. singular at T = 0)
--against OLD/src measures another checkout's autolev too, model by model right
before this one (side by side: the machine's load falls on both), and prints
"old > new" per cell, and the models whose cold run is slower than the old tree's.
Targets (issue 32): missing <= 2 s, cold <= 5 s, warm <= 0.3 s (a * marks a miss).
Each tree's modules are byte-compiled first, as an installed package's are.
Models one at a time: two runs side by side share two cores and measure each other.
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
import phases  # noqa: E402

TARGETS = {"missing": 2.0, "cold": 5.0, "warm": 0.3}
PHASES = Path(__file__).resolve().parent / "phases.py"
# a cold run counts as slower than the old tree's beyond this ratio (and 0.1 s): the
# noise of two runs side by side on a loaded machine
SLOWER = 1.10
NAMED = "no value given for"      # the note of a run naming constants without a value


def _argv(path: Path, options: list, work: Path, phases: Path | None = None) -> list:
    """`autolev run` of the model into a fresh folder of `work` (`phases`: sampled by
    bench/phases.py, its report written there)."""
    run_dir = work / "run"
    shutil.rmtree(run_dir, ignore_errors=True)
    args = ["run", path, "--out", run_dir, "-q", *options]
    if phases is None:
        return journeys.autolev_cli(*args)
    return [sys.executable, PHASES, "--json", phases, "--", *args]


def timed_run(src: Path, path: Path, options: list, work: Path, cache: Path,
              limit: float, phases: Path | None = None) -> tuple[float, int | None, str]:
    """(seconds, exit status or None at the limit, stderr) of one run of `src`'s
    autolev on `cache` (`phases`: sampled, as _argv)."""
    done = journeys.run_process(_argv(path, options, work, phases), work, limit,
                                journeys.process_env(src, AUTOLEV_CACHE=str(cache)))
    return done.seconds, done.returncode, done.stderr


def cold_phases(report: Path, seconds: float) -> dict:
    """The cold run's first numbers (since the process started: the interpreter's own
    start before the sampler began counted in) and its seconds per phase."""
    if not report.is_file():        # it ended before reporting (the time limit)
        return {}
    found = json.loads(report.read_text())
    before = max(seconds - found["sampled"], 0.0)
    first = found["first_numbers"]
    return {"first": None if first is None else before + first,
            "phases": found["seconds"], "where": found["where"]}


def time_to_note(src: Path, path: Path, options: list, work: Path, cache: Path,
                 limit: float) -> float | None:
    """Seconds until a run names the constants without a value (None: it never did);
    the run is stopped there."""
    start = time.monotonic()
    proc = subprocess.Popen([str(a) for a in _argv(path, options, work)], cwd=work,
                            env=journeys.process_env(src, AUTOLEV_CACHE=str(cache)),
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                            errors="replace", start_new_session=True)
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


def measure(src: Path, path: Path, companion: Path | None, values, warm: int, limit: float,
            work: Path) -> dict:
    """One tree's numbers for one model (`values`: journeys.Values)."""
    cache = work / "cache"
    shutil.rmtree(cache, ignore_errors=True)
    row: dict = {}
    if values.by_rule:
        given = ["--in", str(companion)] if companion else []
        row["missing"] = time_to_note(src, path, given, work, cache, limit)
        shutil.rmtree(cache, ignore_errors=True)
    report = work / "phases.json"
    report.unlink(missing_ok=True)
    row["cold"], row["exit"], err = timed_run(src, path, values.options, work, cache, limit,
                                              report)
    row |= cold_phases(report, row["cold"])
    row["warm"] = min(timed_run(src, path, values.options, work, cache, limit)[0]
                      for _ in range(warm))
    row["reason"] = "" if row["exit"] == 0 else journeys._last_line(err)
    return row


def _cell(row: dict, key: str) -> str:
    if key not in row:
        return "-"
    value = row[key]
    if value is None:
        return "never*" if key == "missing" else "-"   # never named / no numbers
    target = TARGETS.get(key)
    return f"{value:.2f}{'' if target is None or value <= target else '*'}"


def table(rows: list) -> str:
    """A line per model (`first`: the cold run's first numbers); with an old tree,
    `old > new` per cell; then the new cold run's seconds per phase, and the models
    whose cold run got slower."""
    keys = ("missing", "first", "cold", "warm")
    lines = [f"{'model':44} " + " ".join(f"{k:>13}" for k in keys) + " exit"]
    for r in rows:
        cells = []
        for key in keys:
            new = _cell(r["new"], key)
            cells.append(new if "old" not in r else f"{_cell(r['old'], key)} > {new}")
        lines.append(f"{r['id'][:44]:44} " + " ".join(f"{c:>13}" for c in cells)
                     + f" {r['new']['exit']}")
    lines += ["", "where the new cold run's time goes (s; bench/phases.py):",
              f"{'model':44} " + " ".join(f"{p[:10]:>10}" for p in phases.ORDER)]
    for r in rows:
        spent = r["new"].get("phases")
        if spent:
            lines.append(f"{r['id'][:44]:44} "
                         + " ".join(f"{spent[p]:10.2f}" for p in phases.ORDER))
    if rows and "old" in rows[0]:
        slower = [f"{r['id']} {r['old']['cold']:.2f} > {r['new']['cold']:.2f}"
                  for r in rows if r["new"]["cold"] > SLOWER * r["old"]["cold"] + 0.1]
        lines.append(f"cold slower than the old tree's (by over {SLOWER - 1:.0%} + 0.1 s): "
                     f"{len(slower)}" + (f" ({'; '.join(slower)})" if slower else ""))
    for key, target in TARGETS.items():
        for tree in ("old", "new"):
            if rows and tree not in rows[0]:
                continue
            over = [r["id"] for r in rows if key in r[tree]
                    and (r[tree][key] is None or r[tree][key] > target)]
            lines.append(f"{tree}: {key} over {target} s: {len(over)}"
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
    ap.add_argument("--against", type=Path, metavar="OLD/src",
                    help="another checkout's src folder, measured side by side")
    ap.add_argument("--json", type=Path, metavar="FILE", help="write the rows there")
    ns = ap.parse_args(argv)
    ns.corpus, ns.listing = journeys.CORPUS, journeys.LISTING
    trees = ([("old", ns.against.resolve())] if ns.against else []) + \
        [("new", journeys.ROOT / "src")]
    for _, src in trees:
        # as an installed package's modules are: no measured run compiles them (where
        # PYTHONDONTWRITEBYTECODE is set, every run would)
        subprocess.run([sys.executable, "-m", "compileall", "-q", str(src)], check=True,
                       stdout=subprocess.DEVNULL)
    rows = []
    with tempfile.TemporaryDirectory(prefix="autolev-latency-") as scratch:
        for ident, path, companion in journeys.chosen_models(ns):
            start = time.monotonic()
            work = Path(scratch) / ident
            work.mkdir(parents=True)
            values = journeys.values_apart(ident, path, companion, work, ns.limit)
            row = {"id": ident, "values": values.source}
            for tree, src in trees:
                row[tree] = measure(src, path, companion, values, ns.warm, ns.limit, work)
            rows.append(row)
            print(f"{ident}: " + "; ".join(
                f"{tree} cold {row[tree]['cold']:.2f} s, warm {row[tree]['warm']:.2f} s"
                for tree, _ in trees) + f" ({time.monotonic() - start:.0f} s)",
                file=sys.stderr, flush=True)
    print(table(rows))
    if ns.json:
        ns.json.write_text(json.dumps(rows, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
