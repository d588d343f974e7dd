"""A run's files change as one set (issue 31, item 7): a signal that arrives while they
are renamed into place waits until the set is complete; one that cannot wait (SIGKILL)
leaves no .dir, so a cut-short set never passes for a complete one."""
import os
import signal
import subprocess
import sys

import numpy as np
import pytest

# five output files: the set is the .in, NAME.1 ... NAME.5 and the .dir
MODEL = """VARIABLES X'
CONSTANTS K
X' = -K*X
INPUT X = 1, K = 1
OUTPUT T, X
OUTPUT X
OUTPUT T
OUTPUT K
OUTPUT X, K
CODE ODE() decay.c
"""
RENAMES = 9        # the record of what autolev wrote, the 7 files, the record again

SCRIPT = """
import os, signal, sys
# a shell's background job starts with SIGINT ignored, and Python then keeps it so:
# Ctrl-C as a terminal delivers it, whatever started the tests
signal.signal(signal.SIGINT, signal.default_int_handler)
import autolev
from autolev.engine import files
model = autolev.load(sys.argv[1])
model.simulate(out_dir=sys.argv[2], TFINAL=1)            # the previous run's set
real, count = os.replace, [0]
from autolev.engine.outputs import records_dir
# os.replace is process-wide: a compile thread's renames in the cache do not count
counted = {os.path.realpath(sys.argv[2]), os.path.realpath(records_dir())}
def replace(src, dst):
    if os.path.dirname(os.path.realpath(dst)) in counted:
        count[0] += 1
        if count[0] == int(sys.argv[3]):
            os.kill(os.getpid(), int(sys.argv[4]))
    return real(src, dst)
files.os.replace = replace
model.simulate(out_dir=sys.argv[2], TFINAL=2)
"""


def final_times(out):
    return {p.name: np.loadtxt(p, comments="%", ndmin=2)[-1, 0]
            for p in sorted(out.glob("decay.[0-9]")) if p.name in ("decay.1", "decay.3")}


# every signal at every third rename; the middle one in the default run
CASES = [pytest.param(signum, at, marks=() if at == 4 else pytest.mark.slow)
         for signum in (signal.SIGTERM, signal.SIGINT, signal.SIGKILL) for at in (1, 4, RENAMES)]


@pytest.mark.parametrize("signum, at", CASES)
def test_a_signal_at_a_rename_never_leaves_a_mixed_set_that_looks_complete(tmp_path, at,
                                                                          signum):
    model = tmp_path / "decay.al"
    model.write_text(MODEL)
    out = tmp_path / "out"
    # the Python tier alone: no compile thread runs beside the renames (what is renamed,
    # and when, is then the run's own doing; a compile's timing once moved the signal)
    done = subprocess.run([sys.executable, "-c", SCRIPT, model, out, str(at), str(signum)],
                          capture_output=True, text=True, timeout=300,
                          env=os.environ | {"AUTOLEV_NO_C": "1"})
    assert done.returncode != 0, done.stderr          # the signal ended the process
    names = sorted(p.name for p in out.iterdir())
    temporaries = [n for n in names if n.startswith(".")]
    if signum != signal.SIGKILL:     # held off until the new set was whole
        assert not temporaries
        assert "decay.dir" in names and set(final_times(out).values()) == {2.0}, \
            (done.returncode, done.stderr[-2000:])
    elif "decay.dir" in names:       # killed: a .dir means one run's whole set
        assert len(set(final_times(out).values())) == 1
        # the next run in the folder removes what the killed one left
        rerun = subprocess.run([sys.executable, "-m", "autolev", "run", model, "--out", out,
                                "-q"], capture_output=True, text=True, timeout=300)
        assert rerun.returncode == 0, rerun.stderr
        assert not [p for p in out.iterdir() if p.name.startswith(".")]
        assert (out / "decay.dir").exists()
