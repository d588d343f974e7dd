#!/usr/bin/env python3
"""A speed sweep of bicycle linearizations: what building costs once, and what 200
points cost after it, in this process, on forked local workers, and on a Dask
LocalCluster (when Dask is installed), with whether every way gives the same numbers
bit for bit.

    python bench/sweep.py                 # autolev_examples/whipple_benchmark.al, and
                                          # the corpus's WhipplePlusRiderLean.AL (massless
                                          # rider, lean locked) when the corpus is there
    python bench/sweep.py --points 1000 --workers 2
    python bench/sweep.py --memory 20000  # what a sweep holds: the shipped simple
                                          # pendulum's peak Python memory per point

Each model is loaded (translated and executed), linearized once at 5 m/s (which
builds and compiles the Jacobians: "build"), then swept over rear-wheel rates for
0.5 to 10 m/s.  "here" runs every point in this process; "forked" makes the local
sweep fork its workers whatever the cost (studies.LOCAL_SECONDS = 0); "dask" is a
LocalCluster of --workers processes, one thread each, whose workers rebuild the model
from its translation: its first sweep includes that rebuild, the second does not.
"""
from __future__ import annotations

import argparse
import math
import os
import sys
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

import autolev                                  # noqa: E402
from autolev.runtime import studies             # noqa: E402

CORPUS = Path(os.environ.get("AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus"))
BENCHMARK = dict(W=1.02, C=0.08, LAMBDA=math.pi / 10, G=9.81, RR=0.3, M_R=2, IRXX=0.0603,
                 IRYY=0.12, XB=0.3, ZB=-0.9, M_B=85, IBXX=9.2, IBYY=11, IBZZ=2.8,
                 IBXZ=2.4, XH=0.9, ZH=-0.7, M_H=4, IHXX=0.05892, IHYY=0.06,
                 IHZZ=0.00708, IHXZ=-0.00756, RF=0.35, M_F=3, IFXX=0.1405, IFYY=0.28,
                 HH=0.9, XBR=0.3, ZBR=-1.0, M_BR=0, IBRXX=0, IBRYY=0, IBRZZ=0, IBRXZ=0)


def cases():
    """(label, model file, fixed point values, options)."""
    yield ("whipple_benchmark", ROOT / "autolev_examples" / "whipple_benchmark.al",
           {"Q5": math.pi / 10}, {})
    rider = CORPUS / "moorepants+RiderModel" / "autolev" / "WhipplePlusRiderLean.AL"
    if rider.is_file():
        yield ("WhipplePlusRiderLean", rider, dict(BENCHMARK), {"locked": ["Q9"]})


def timed(fn):
    start = time.perf_counter()
    value = fn()
    return value, time.perf_counter() - start


def same(a, b) -> bool:
    return a.names == b.names and all(np.array_equal(a[n], b[n]) for n in a.names)


def memory(count: int) -> None:
    """Peak Python memory and time of a linearization sweep of `count` points of the
    shipped simple pendulum in this process, per point."""
    import tracemalloc
    model = autolev.load(ROOT / "autolev_examples" / "simple_pendulum.al")
    model.linearize({"THETA": 0.0})                 # build and compile once
    points = {"L": np.linspace(1.0, 2.0, count), "THETA": np.zeros(count)}
    tracemalloc.start()
    table, seconds = timed(lambda: model.sweep(points, workers=1, as_frame=False,
                                               progress=False))
    held, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    print(f"{count} points: peak {peak / 1e6:.2f} MB ({peak / count:.0f} B a point), "
          f"table {held / 1e6:.2f} MB, {seconds:.2f} s ({1e3 * seconds / count:.2f} ms a "
          f"point), {len(table['L'])} rows")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=200)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--memory", type=int, metavar="N",
                        help="instead: the memory a sweep of N pendulum points holds")
    args = parser.parse_args()
    if args.memory:
        memory(args.memory)
        return 0
    speeds = np.linspace(0.5, 10.0, args.points)
    warnings.simplefilter("ignore")
    print(f"{args.points} speeds, {args.workers} workers")
    print(f"{'model':22} {'load s':>7} {'build s':>8} {'here s':>7} {'forked s':>9} "
          f"{'dask 1st s':>10} {'dask 2nd s':>10}  same")
    for label, path, fixed, options in cases():
        model, load_s = timed(lambda: autolev.load(path))
        _, build_s = timed(lambda: model.linearize(dict(fixed, U6=-5 / 0.3), **options))
        points = [dict(fixed, U6=-v / 0.3) for v in speeds]
        here, here_s = timed(lambda: model.sweep(points, workers=1, as_frame=False,
                                                 progress=False, **options))
        studies.LOCAL_SECONDS = 0.0
        forked, forked_s = timed(lambda: model.sweep(points, workers=args.workers,
                                                     as_frame=False, progress=False,
                                                     **options))
        studies.LOCAL_SECONDS = 2.0
        identical = same(here, forked)
        dask_cells = f"{'-':>10} {'-':>10}"
        try:
            import distributed
        except ImportError:
            distributed = None
        if distributed is not None:
            with distributed.LocalCluster(n_workers=args.workers, threads_per_worker=1,
                                          processes=True, dashboard_address=None) as cluster, \
                    distributed.Client(cluster) as client:
                first, first_s = timed(lambda: model.sweep(points, executor=client,
                                                           as_frame=False, progress=False,
                                                           **options))
                second, second_s = timed(lambda: model.sweep(points, executor=client,
                                                             as_frame=False, progress=False,
                                                             **options))
            identical = identical and same(here, first) and same(here, second)
            dask_cells = f"{first_s:10.2f} {second_s:10.2f}"
        print(f"{label:22} {load_s:7.2f} {build_s:8.2f} {here_s:7.2f} {forked_s:9.2f} "
              f"{dask_cells}  {'yes' if identical else 'NO'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
