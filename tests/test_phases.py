"""bench/phases.py: each sample of a command's stack given to its phase, and a cold run's
time split into them."""
import importlib.util
import json
import os
import subprocess
import sys
from types import SimpleNamespace

import pytest

from helpers import EXAMPLES, ROOT

spec = importlib.util.spec_from_file_location("phases", ROOT / "bench" / "phases.py")
phases = importlib.util.module_from_spec(spec)
spec.loader.exec_module(phases)

SITE = "/venv/lib/python3.11/site-packages/"
SRC = "/repo/src/autolev/"


def stack(*frames):
    """A fake frame chain, outermost first: (file, function) each."""
    frame = None
    for filename, name in frames:
        frame = SimpleNamespace(f_code=SimpleNamespace(co_filename=filename, co_name=name),
                                f_back=frame)
    return frame


@pytest.mark.parametrize("frames, phase", [
    # sympy's own frames count for the autolev code that called them
    ([(SRC + "cli/run.py", "cmd_run"), (SRC + "runtime/calculus.py", "jacobian"),
      (SITE + "sympy/core/mul.py", "flatten")], "forming"),
    # a module's body is an import, wherever it happens
    ([(SRC + "runtime/numerics/prepare.py", "prepare_command"),
      ("<frozen importlib._bootstrap>", "_load"), (SRC + "engine/integrate.py", "<module>")],
     "start-up"),
    # ... but the translated model's body is the model being formed
    ([(SRC + "loader.py", "_execute"), ("/cache/pendulum.al.py", "<module>"),
      (SITE + "sympy/core/add.py", "flatten")], "forming"),
    ([(SRC + "runtime/numerics/prepare.py", "numeric_system"),
      (SRC + "runtime/numerics/codegen.py", "compile_python")], "compile"),
    ([(SRC + "runtime/numerics/prepare.py", "numeric_system"),
      (SRC + "runtime/numerics/codegen.py", "walk")], "code generation"),
    ([(SRC + "engine/integrate.py", "integrate"),
      ("<autolev generated autolev_rhs>", "autolev_rhs")], "evaluation"),
    ([(SRC + "cli/run.py", "cmd_run"), (SRC + "engine/outputs.py", "write_whole")],
     "writing"),
    ([(SRC + "syntax.py", "parse"), (SITE + "antlr4/Parser.py", "match")], "parsing"),
    ([(SRC + "translate/statements.py", "assignment")], "translation"),
    ([(SRC + "modelcache.py", "key"), ("/usr/lib/python3.11/hashlib.py", "new")], "other"),
    ([("/usr/lib/python3.11/threading.py", "wait")], "other"),
])
def test_a_sample_is_given_the_phase_of_its_innermost_frame_with_a_rule(frames, phase):
    assert phases.phase_of(stack(*frames))[0] == phase


def test_a_cold_runs_time_is_split_into_its_phases(tmp_path):
    report = tmp_path / "phases.json"
    done = subprocess.run(
        [sys.executable, ROOT / "bench" / "phases.py", "--json", report, "--", "run",
         EXAMPLES / "double_pendulum.al", "--out", tmp_path / "out", "-q"],
        env=dict(os.environ, AUTOLEV_CACHE=str(tmp_path / "cache")), cwd=tmp_path,
        capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    found = json.loads(report.read_text())
    seconds = found["seconds"]
    assert set(seconds) == set(phases.ORDER)
    # every sample is some phase's: they add up to the time sampled
    assert sum(seconds.values()) == pytest.approx(found["sampled"], rel=0.1, abs=0.05)
    for phase in ("start-up", "parsing", "forming", "evaluation"):
        assert seconds[phase] > 0, phase
    assert 0 < found["first_numbers"] < found["sampled"]
    assert (tmp_path / "out" / "double_pendulum.1").is_file()
