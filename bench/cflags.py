#!/usr/bin/env python3
"""Per-evaluation cost of the generated C under two sets of compiler flags, side by
side in one run, and whether the two give the same numbers bit for bit.

    python bench/cflags.py                # the double pendulum, bench/chains.py's planar
                                          # 16-link, the corpus's 13-segment sprinter
    python bench/cflags.py MODEL.al ...   # these models
    python bench/cflags.py --old "-O1" --new "-O1 -fno-math-errno"

For each model and flag set: the right-hand side is compiled with those flags (the
build cache keys on them), a short run (TFINAL = 0.2; with NAME.in beside the model
when there is one, 1 for each constant without a value) gives a state, and bench/
rhs_speed.py's C driver times autolev_derivatives (generated code and LU solve) and
autolev_rhs alone there (medians of 7 timed loops).  The two flag sets alternate
three times per model and the least time of each is printed, with old/new.  "same" is
whether the two short runs' rows are identical.
"""
from __future__ import annotations

import argparse
import os
import sys
import tempfile
import warnings
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

import chains                                   # noqa: E402
from rhs_speed import CDriver                   # noqa: E402

CORPUS = Path(os.environ.get("AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus"))
# CODE DYNAMICS models with their values: the 13-segment sprinter (model.al, model.in)
CORPUS_MODELS = ("13seg_tq/model.al",)


def default_models(folder: Path) -> list[Path]:
    models = [ROOT / "autolev_examples" / "double_pendulum.al"]
    planar = folder / "planar16.al"
    planar.write_text(chains.planar(16))
    models.append(planar)
    for name in CORPUS_MODELS:
        found = sorted(p for p in CORPUS.rglob("*.[aA][lL]") if ".overlay" not in p.parts
                       and p.as_posix().lower().endswith("/" + name))
        models.extend(found[:1])
    return models


def measure(path: Path, flags: tuple, driver: CDriver) -> tuple:
    import autolev
    from autolev.runtime import MissingValues
    from autolev.engine import clibrary
    clibrary.C_FLAGS = flags
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        model = autolev.load(path)
        infile = path.with_suffix(".in")
        infile = infile if infile.exists() else None
        try:
            result = model.simulate(TFINAL=0.2, backend="c", infile=infile)
        except MissingValues as missing:
            # a model without its values: 1 for each (a mass, a length, an inertia of 1)
            result = model.simulate(TFINAL=0.2, backend="c", infile=infile,
                                    **{name: 1.0 for name in missing.names})
    if not result.ok:
        raise RuntimeError(f"{path.name}: the short run failed: {result.failure}")
    x = np.array(result.states[-1])
    whole, alone = driver.us_per_eval(result.system, x)
    return whole, alone, np.array(result.states)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("models", nargs="*", type=Path)
    ap.add_argument("--old", default="-O1", help="flags of the first column")
    ap.add_argument("--new", default="-O1 -fno-math-errno", help="flags of the second")
    args = ap.parse_args(argv)
    old, new = tuple(args.old.split()), tuple(args.new.split())
    driver = CDriver()
    print(f"old: {' '.join(old)}    new: {' '.join(new)}    (microseconds per evaluation, "
          "least of 3 alternating measurements)")
    print(f"{'model':28s} {'old':>9s} {'new':>9s} {'old/new':>8s} {'rhs old':>9s} "
          f"{'rhs new':>9s} {'old/new':>8s}  same")
    with tempfile.TemporaryDirectory(prefix="autolev-bench-") as tmp:
        folder = Path(tmp)
        for path in args.models or default_models(folder):
            best = {old: [np.inf, np.inf], new: [np.inf, np.inf]}
            states = {}
            for _ in range(3):
                for flags in (old, new):
                    whole, alone, states[flags] = measure(path, flags, driver)
                    best[flags] = [min(best[flags][0], whole), min(best[flags][1], alone)]
            same = np.array_equal(states[old], states[new])
            (wo, ao), (wn, an) = best[old], best[new]
            print(f"{path.name[:28]:28s} {wo:9.3f} {wn:9.3f} {wo / wn:8.2f} {ao:9.3f} "
                  f"{an:9.3f} {ao / an:8.2f}  {'yes' if same else 'NO'}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
