#!/usr/bin/env python3
"""How soon `autolev run` names the constants nothing gives a value (issue 32, target 4:
at most 2 s for any corpus model, before any formation).

    python bench/missing_values.py [--corpus DIR] [--only TEXT] [--limit S]

For every visible corpus model, `autolev run FILE --out DIR` (this interpreter, a fresh
working folder) with an empty cache folder (AUTOLEV_CACHE: the model is translated and
formed from nothing, the cold case) and its INPUT values alone (no .in file).  The
seconds from the start of the process to its line "note: no value given for ..." are
its time; the process is stopped there, or at --limit seconds (`late`); a run that
ends without the note lacks nothing the translation can tell (`-`).  Prints one line per model,
then the largest and the median time and how many are within 2 s.
"""
from __future__ import annotations

import argparse
import os
import selectors
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "bench"))

from corpus import corpus_models  # noqa: E402

TARGET_SECONDS = 2.0
NOTE = "note: no value given for"


def seconds_to_note(path: Path, limit: float) -> float | str:
    """Seconds until the run's note naming constants without a value; "-" when the run
    ended without one, "late" when `limit` passed first."""
    with tempfile.TemporaryDirectory() as work:
        env = dict(os.environ, AUTOLEV_CACHE=str(Path(work) / "cache"))
        start = time.perf_counter()
        proc = subprocess.Popen([sys.executable, "-m", "autolev", "run", str(path), "--out",
                                 str(Path(work) / "out")], cwd=work, env=env,
                                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        found: float | str = "late"
        with selectors.DefaultSelector() as sel:
            sel.register(proc.stderr, selectors.EVENT_READ)
            while found == "late" and time.perf_counter() - start < limit:
                if not sel.select(timeout=0.05):
                    continue
                line = proc.stderr.readline()
                if not line:
                    found = "-"                    # the run ended without the note
                    break
                if NOTE in line:
                    found = time.perf_counter() - start
        proc.kill()
        proc.wait()
        proc.stderr.close()
    return found


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corpus", type=Path, default=Path(os.environ.get(
        "AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus")))
    ap.add_argument("--only", default=None, help="models whose id contains TEXT")
    ap.add_argument("--limit", type=float, default=20.0, help="seconds per model")
    ns = ap.parse_args(argv)
    times, late = [], []
    for ident, path in corpus_models(ns.corpus):
        if ns.only and ns.only not in ident:
            continue
        t = seconds_to_note(path, ns.limit)
        print(f"{ident:60s} {t if isinstance(t, str) else f'{t:6.2f} s'}", flush=True)
        if isinstance(t, float):
            times.append(t)
        elif t == "late":
            late.append(ident)
    if times:
        within = sum(t <= TARGET_SECONDS for t in times)
        print(f"\n{len(times)} models named constants without a value: largest "
              f"{max(times):.2f} s, median {statistics.median(times):.2f} s; {within} within "
              f"{TARGET_SECONDS:g} s")
    if late:
        print(f"{len(late)} gave no note within {ns.limit:g} s: {', '.join(late)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
