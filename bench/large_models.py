#!/usr/bin/env python3
"""The largest models of the public corpus: time to translate them and form their
equations, then to generate and compile their numerics (cold: an empty build cache).

    python bench/large_models.py [--corpus DIR]

Each model runs in its own process (a fresh build cache each), so the times are
those a user sees the first time.  Target (issue 6): translate + form < 60 s each.
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

MODELS = [
    ("gait3d pelvis213 FK (33 speeds)", "mad-lab-fau+BioMAC-Sim-Toolbox/src/model/gait3d/"
     "c_files/gait3d_pelvis213/gait3d_pelvis213_FK.al"),
    ("gait3d pelvis213 NoDer (33 speeds)", "mad-lab-fau+BioMAC-Sim-Toolbox/src/model/gait3d/"
     "c_files/gait3d_pelvis213/gait3d_pelvis213_NoDer.al"),
    ("Whipple bicycle + rider, lean", "moorepants+RiderModel/autolev/WhipplePlusRiderLean.AL"),
    ("Whipple bicycle + rider, lean angle",
     "moorepants+RiderModel/autolev/WhipplePlusRiderLeanAngle.AL"),
    ("bicycle + rider, lean torque", "moorepants+RiderModel/autolev/LeanTorque.AL"),
    ("swing bike", "moorepants+SwingBike/SB_01.AL"),
    ("MAE-223 bicycle 13", "moorepants+MAE-223/BicycleDynamicsProject/AutolevSRC/BICYCLE13.AL"),
    ("sprinter, 7 segments", "TomRottier+SprintingModel/Model/7segv2/7segsprint.al"),
]

CHILD = r"""
import json, sys, time, warnings
import autolev
from autolev.runtime.numerics.system import NumericSystem
t0 = time.perf_counter()
m = autolev.load(sys.argv[1])
t1 = time.perf_counter()
out = {"form": t1 - t0, "z": m.defs.z_count}
from autolev.runtime.errors import AutolevModelError
try:
    out["speeds"] = len(m.equations().speeds)
except AutolevModelError:         # a model with no dynamics (kinematics only)
    out["speeds"] = 0
t2 = time.perf_counter()
out["form"] += t2 - t1
with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    codes = [c for c in m.code_commands if c.kind in ("dynamics", "ode")]
    if codes or out["speeds"]:
        ns = NumericSystem(m)
        out["numeric"] = time.perf_counter() - t2
        out["states"] = ns.nstate
        out["backend"] = ns.rhs_function.backend if ns.rhs_function else None
print(json.dumps(out))
"""


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corpus", default=os.environ.get(
        "AUTOLEV_CORPUS", str(Path.home() / ".cache" / "autolev-corpus")))
    ap.add_argument("--limit", type=float, default=300.0, help="seconds per model")
    args = ap.parse_args(argv)
    corpus = Path(args.corpus)
    print(f"{'model':38s} {'speeds':>6s} {'Z':>7s} {'form s':>8s} {'gen+cc s':>9s}  target")
    worst = 0.0
    for label, rel in MODELS:
        path = corpus / rel
        if not path.exists():
            print(f"{label:38s} not in the corpus ({rel})")
            continue
        env = dict(os.environ, AUTOLEV_CACHE=tempfile.mkdtemp(prefix="autolev-bench-"),
                   PYTHONPATH=str(ROOT / "src"))
        try:
            r = subprocess.run([sys.executable, "-c", CHILD, str(path)], capture_output=True,
                               text=True, timeout=args.limit, env=env)
        except subprocess.TimeoutExpired:
            print(f"{label:38s} > {args.limit:.0f} s")
            continue
        if r.returncode != 0:
            print(f"{label:38s} failed: {r.stderr.strip().splitlines()[-1][:80]}")
            continue
        d = json.loads(r.stdout.strip().splitlines()[-1])
        worst = max(worst, d["form"])
        numeric = f"{d['numeric']:9.1f}" if "numeric" in d else f"{'-':>9s}"
        print(f"{label:38s} {d['speeds']:6d} {d['z']:7d} {d['form']:8.1f} {numeric}  "
              f"{'PASS' if d['form'] < 60 else 'FAIL'} (< 60 s)")
    print(f"slowest translate + form: {worst:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
