#!/usr/bin/env python3
"""Peak memory of `autolev run` against the length of the run.

Runs the double pendulum of autolev_examples with growing TFINAL (one row per second
of model time: INTEGSTP = 1, tolerances 1e-6 so that the run takes minutes, not
hours) in a fresh process each, and prints rows, seconds, the output size and the
process's peak resident memory.  Rows are streamed to the files and the schedule is
taken in blocks, so the peak should not grow with TFINAL.

    python bench/long_run.py [--tfinal 1e3 1e5 1e7] [--src DIR]

`--src` runs another checkout's sources (e.g. an older commit) side by side.
"""
from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
MODEL = ROOT / "autolev_examples" / "double_pendulum.al"


def one_run(tfinal: float, src: Path) -> dict:
    out = Path(tempfile.mkdtemp(prefix="autolev-long-"))
    env = dict(os.environ, PYTHONPATH=str(src))
    cmd = [sys.executable, "-c", "import sys; from autolev.cli import main; "
           "sys.exit(main(sys.argv[1:]))", "run", str(MODEL), "--out", str(out), "--quiet",
           "--tfinal", repr(tfinal), "--set", "INTEGSTP=1", "--set", "ABSERR=1e-6",
           "--set", "RELERR=1e-6"]
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, env=env, stderr=subprocess.PIPE, text=True)
    _, status, usage = os.wait4(proc.pid, 0)
    seconds = time.perf_counter() - start
    err = proc.stderr.read()
    proc.stderr.close()
    table = out / "double_pendulum.1"
    rows = sum(1 for line in open(table) if not line.startswith("%")) - 1 \
        if table.exists() else 0
    size = sum(p.stat().st_size for p in out.iterdir())
    shutil.rmtree(out)
    return {"tfinal": tfinal, "status": os.waitstatus_to_exitcode(status), "rows": rows,
            "seconds": seconds, "mb_files": size / 1e6,
            "peak_mb": usage.ru_maxrss / 1024, "stderr": err.strip()}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tfinal", type=float, nargs="+", default=[1e3, 1e5, 1e7])
    ap.add_argument("--src", type=Path, default=ROOT / "src")
    ns = ap.parse_args()
    print(f"sources: {ns.src}")
    print(f"{'TFINAL':>8} {'rows':>10} {'seconds':>9} {'files MB':>9} {'peak RSS MB':>12}")
    bad = 0
    for tfinal in ns.tfinal:
        r = one_run(tfinal, ns.src)
        print(f"{tfinal:>8.0e} {r['rows']:>10} {r['seconds']:>9.1f} {r['mb_files']:>9.1f} "
              f"{r['peak_mb']:>12.1f}" + ("" if r["status"] == 0 else
                                          f"  exit {r['status']}: {r['stderr'][-200:]}"),
              flush=True)
        bad += r["status"] != 0
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
