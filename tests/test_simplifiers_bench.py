"""bench/simplifiers.py: the general simplifiers a command calls, with who called them."""
import json
import os
import subprocess
import sys

from helpers import ROOT


def test_a_simplifier_the_model_asks_for_is_listed_with_its_caller(tmp_path):
    model = tmp_path / "m.al"
    model.write_text("NEWTONIAN N\nVARIABLES Q\nX = SIMPLIFY(SIN(Q)^2 + COS(Q)^2)\n"
                     "Y = FACTOR(Q^2 - 1)\n")
    report = tmp_path / "rows.json"
    done = subprocess.run(
        [sys.executable, ROOT / "bench" / "simplifiers.py", "--profile", report, "--",
         "transcript", model], cwd=tmp_path, capture_output=True, text=True, timeout=300,
        env=dict(os.environ, AUTOLEV_CACHE=str(tmp_path / "cache"), AUTOLEV_FOREGROUND="1"))
    assert done.returncode == 0, done.stderr
    assert "X = 1" in done.stdout.replace("-> ", "")
    rows = {r["simplifier"]: r for r in json.loads(report.read_text())}
    assert rows["simplify.py:simplify"]["calls"] >= 1
    assert "runtime/functions.py:_map" in rows["simplify.py:simplify"]["callers"]
    assert "runtime/functions.py:_map" in rows["polytools.py:factor"]["callers"]
    # a simplifier only sympy's own simplify calls is 'via' it
    assert all(c.startswith("via ") for c in rows["trigsimp.py:trigsimp"]["callers"])
