"""Input a model or the command line gets wrong is the user's error, with its line,
never an internal error (issue 31, item 12)."""
import subprocess
import sys

import pytest

from helpers import EXAMPLES

DECAY = "VARIABLES X'\nX' = {rate}\nINPUT X=1, TFINAL=1{extra}\nOUTPUT T, X\nCODE ODE() {name}\n"
SWEEP = "CONSTANTS Q\nY = 2*Q\nOUTPUT Y\nCODE ALGEBRAIC() [Q = {start}, {stop}, {step}] s.c\n"


def cli(*args):
    return subprocess.run([sys.executable, "-m", "autolev", *map(str, args)],
                          capture_output=True, text=True)


@pytest.mark.parametrize("text, line, message", [
    (DECAY.format(rate="-X", extra=", PRINTINT=1E19", name="p.c"), 5,
     "PRINTINT must be a whole number from 1 to 2147483647, not 1e+19 (from INPUT)"),
    (DECAY.format(rate="X*1E300*1E10", extra="", name="p.c"), 5,
     "the number 1.00000E+310 is beyond double precision"),
    (SWEEP.format(start=0, stop=1, step="1E-320"), 4,
     "has inf values; at most 1e+09 are swept"),
    (SWEEP.format(start=0, stop="1E8", step="0.01"), 4,
     "has 1e+10 values; at most 1e+09 are swept"),
    (SWEEP.format(start=0, stop="1E400", step=1), 4,
     "its start, end and step must be numbers within double precision"),
    (DECAY.format(rate="-X", extra="", name=".c"), 5, "unusable file name in CODE: '.c'"),
])
def test_a_run_the_model_gets_wrong_is_its_error_at_the_code_line(tmp_path, text, line,
                                                                   message):
    path = tmp_path / "m.al"
    path.write_text(text)
    r = cli("run", path, "--out", tmp_path / "o", "-q")
    assert r.returncode == 1
    assert f"{path}:{line}: error: " in r.stderr and message in r.stderr
    assert "internal error" not in r.stderr
    assert not (tmp_path / "o").exists() or not any((tmp_path / "o").iterdir())


def test_code_refuses_a_number_beyond_a_double_instead_of_writing_inf(tmp_path):
    path = tmp_path / "m.al"
    path.write_text(DECAY.format(rate="X*1E300*1E10", extra="", name="p.c"))
    r = cli("code", path, "--out", tmp_path / "o")
    assert r.returncode == 1 and "beyond double precision" in r.stderr
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("frames", ["-5", "0", "many"])
def test_animate_frames_must_be_a_positive_count(tmp_path, frames):
    r = cli("animate", EXAMPLES / "simple_pendulum.al", "--frames", frames,
            "--out", tmp_path)
    assert r.returncode == 2
    assert f"--frames: expected a whole number of at least 1, not '{frames}'" in r.stderr
