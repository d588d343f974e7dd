#!/usr/bin/env python3
"""Every call of a general simplifier while a user waits: each model's cold `autolev run`
(and `transcript`, with --transcript) under cProfile, and per simplifier of GENERAL its
calls, seconds (cProfile's, about twice the plain run's) and the autolev functions
that called it.

    python bench/simplifiers.py [--examples] [--only ID ...] [--transcript]
                                [--limit S] [--least S] [--json FILE]

A general simplifier tries many rewritings (trigsimp, simplify, factor, cancel, ...);
issue 51 asks that none runs where a structural rule does the job.  Each row names its
direct callers: an autolev function (it asked for the simplifier), or 'via' a sympy
function that is itself a row (a simplifier calling another: its time is within that
row's).  Models and values as bench/journeys.py gives them (INPUT, the shipped .in,
then values by rule); each run in a fresh process with an empty cache,
AUTOLEV_FOREGROUND=1 (the work in the process profiled).  The table lists the rows of
at least --least seconds; the JSON has them all.
"""
from __future__ import annotations

import argparse
import cProfile
import json
import os
import pstats
import shutil
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import journeys  # noqa: E402

# (file path ending, function): sympy's general simplifiers
GENERAL = [
    ("sympy/simplify/simplify.py", "simplify"),
    ("sympy/simplify/simplify.py", "nsimplify"),
    ("sympy/simplify/trigsimp.py", "trigsimp"),
    ("sympy/simplify/fu.py", "fu"),
    ("sympy/simplify/radsimp.py", "radsimp"),
    ("sympy/simplify/powsimp.py", "powsimp"),
    ("sympy/simplify/ratsimp.py", "ratsimp"),
    ("sympy/polys/polytools.py", "cancel"),
    ("sympy/polys/polytools.py", "factor"),
    ("sympy/polys/rationaltools.py", "together"),
    ("sympy/solvers/solvers.py", "solve"),
]


def _general(key) -> str | None:
    """'file:function' when a pstats key is one of GENERAL."""
    filename, _, name = key
    path = filename.replace(os.sep, "/")
    for ending, function in GENERAL:
        if path.endswith(ending) and name == function:
            return f"{ending.rsplit('/', 1)[-1]}:{function}"
    return None


def _callers(stats: pstats.Stats, key) -> list[str]:
    """Who called `key` directly (cProfile's edges are exact; a path of several edges
    through sympy's shared functions would not be): an autolev function by its module,
    a sympy one as 'via FILE:FUNCTION' (its own row says who called it)."""
    out = set()
    for filename, _, name in stats.stats[key][4]:
        path = filename.replace(os.sep, "/")
        if "/autolev/" in path:
            out.add(f"{path.rsplit('/autolev/', 1)[-1]}:{name}")
        elif path.endswith(".al.py"):
            out.add(f"(the model's module):{name}")
        else:
            out.add(f"via {path.rsplit('/', 1)[-1]}:{name}")
    return sorted(out, key=lambda c: (c.startswith("via "), c))


def profile_one(argv: list, out: Path) -> int:
    """`autolev ARGV` in this process under cProfile; the general simplifiers' rows to
    `out` as JSON."""
    from autolev.cli import main
    profiler = cProfile.Profile()
    profiler.enable()
    try:
        status = main(argv)
    finally:
        profiler.disable()
    stats = pstats.Stats(profiler)
    rows = []
    for key, (_, calls, _, cumulative, _) in stats.stats.items():
        name = _general(key)
        if name is not None:
            rows.append({"simplifier": name, "calls": calls,
                         "seconds": round(cumulative, 3),
                         "callers": _callers(stats, key)})
    out.write_text(json.dumps(rows))
    return status


def measure(path: Path, options: list, command: str, work: Path, limit: float) -> dict:
    """One profiled cold command: {"status", "rows"}."""
    cache, report = work / f"cache-{command}", work / f"{command}.json"
    shutil.rmtree(cache, ignore_errors=True)
    report.unlink(missing_ok=True)
    argv = [command, path, *(("--out", work / "run", "-q") if command == "run" else ()),
            *options]
    done = journeys.run_process(
        [sys.executable, __file__, "--profile", report, "--", *argv], work, limit,
        journeys.process_env(AUTOLEV_CACHE=str(cache), AUTOLEV_FOREGROUND="1"))
    rows = json.loads(report.read_text()) if report.is_file() else []
    return {"status": done.returncode, "rows": rows}


def table(found: dict, least: float) -> str:
    lines = [f"{'model':40} {'command':10} {'simplifier':22} {'calls':>6} {'s':>7}  "
             "called by"]
    total = 0.0
    for ident, commands in found.items():
        for command, result in commands.items():
            for r in sorted(result["rows"], key=lambda r: -r["seconds"]):
                if r["simplifier"] != "solvers.py:solve" \
                        and not all(c.startswith("via ") for c in r["callers"]):
                    total += r["seconds"]
                if r["seconds"] >= least:
                    lines.append(f"{ident[:40]:40} {command:10} {r['simplifier']:22} "
                                 f"{r['calls']:6d} {r['seconds']:7.2f}  "
                                 + ", ".join(r["callers"]))
    lines.append(f"\n{len(found)} models; general simplifiers autolev called (solve apart) "
                 f"{total:.1f} s of cProfile's time in all")
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--examples", action="store_true",
                    help="the shipped autolev_examples/*.al instead of the corpus")
    ap.add_argument("--only", action="append", metavar="ID")
    ap.add_argument("--transcript", action="store_true", help="transcript as well as run")
    ap.add_argument("--limit", type=float, default=900, help="seconds per command")
    ap.add_argument("--least", type=float, default=0.05,
                    help="the table's rows from this many seconds")
    ap.add_argument("--json", type=Path, metavar="FILE")
    ap.add_argument("--profile", type=Path, help=argparse.SUPPRESS)
    ap.add_argument("command", nargs=argparse.REMAINDER, help=argparse.SUPPRESS)
    ns = ap.parse_args(argv)
    if ns.profile:
        command = ns.command[1:] if ns.command[:1] == ["--"] else ns.command
        return profile_one(command, ns.profile)
    ns.corpus, ns.listing = journeys.CORPUS, journeys.LISTING
    commands = ["run"] + (["transcript"] if ns.transcript else [])
    found: dict = {}
    with tempfile.TemporaryDirectory(prefix="autolev-simplifiers-") as scratch:
        for ident, path, companion in journeys.chosen_models(ns):
            start = time.monotonic()
            work = Path(scratch) / ident
            work.mkdir(parents=True)
            values = journeys.values_apart(ident, path, companion, work, ns.limit)
            found[ident] = {c: measure(path, values.options if c == "run" else [], c, work,
                                       ns.limit) for c in commands}
            spent = sum(r["seconds"] for c in found[ident].values() for r in c["rows"]
                        if r["simplifier"] != "solvers.py:solve"
                        and not all(c.startswith("via ") for c in r["callers"]))
            print(f"{ident}: {spent:.2f} s in general simplifiers "
                  f"({time.monotonic() - start:.0f} s)", file=sys.stderr, flush=True)
            if ns.json:
                ns.json.write_text(json.dumps(found, indent=1))
    print(table(found, ns.least))
    return 0


if __name__ == "__main__":
    sys.exit(main())
