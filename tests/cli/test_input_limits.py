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


def test_a_value_beyond_a_double_is_named_as_such_not_as_a_negative_inertia(tmp_path):
    path = tmp_path / "big.al"
    path.write_text("NEWTONIAN N\nBODIES A\nMOTIONVARIABLES' Q', U'\nCONSTANTS L, M, G\n"
                    "SIMPROT(N, A, 3, Q)\nQ' = U\nW_A_N> = U*N3>\nP_NO_AO> = L*A1>\n"
                    "V_AO_N> = DT(P_NO_AO>, N)\nMASS A = M\nINERTIA A, 0, 0, M*L^2/12\n"
                    "GRAVITY(G*N1>)\nZERO = FR() + FRSTAR()\nKANE()\n"
                    "INPUT L=1E308, M=1, G=9.81, Q=0.1, U=0\nOUTPUT T, Q\n"
                    "CODE DYNAMICS() big.c\n")
    r = cli("run", path, "--out", tmp_path / "o", "-q")
    assert r.returncode == 1
    assert ("body A has a central inertia that is not a finite number (a value beyond "
            "double precision?)") in r.stderr
    negative = cli("run", path, "--set", "L=1", "--set", "RELERR=-1E-7", "--out",
                   tmp_path / "o", "-q")
    assert negative.returncode == 1
    assert "error tolerances cannot be negative: RELERR = -1e-07 (from override)" in \
        negative.stderr


@pytest.mark.parametrize("written, why", [
    ("1_0", "expected a number"), ("\u0661\u0662", "expected a number"),
])
def test_the_in_reader_takes_numbers_as_autolevs_programs_read_them(tmp_path, written, why):
    # C's strtod takes neither digit separators nor other scripts' digits
    out = tmp_path / "o"
    assert cli("run", EXAMPLES / "simple_pendulum.al", "--out", out, "-q").returncode == 0
    infile = out / "simple_pendulum.in"
    lines = infile.read_text().splitlines()
    k = next(i for i, line in enumerate(lines) if line.startswith("Constant"))
    lines[k] = lines[k][:59] + " " + written
    edited = tmp_path / "edited.in"
    edited.write_text("\n".join(lines) + "\n")
    r = cli("run", EXAMPLES / "simple_pendulum.al", "--in", edited, "--out", out, "-q")
    assert r.returncode == 1 and f"{edited}:{k + 1}:60: {why}" in r.stderr


def test_a_name_given_twice_in_an_in_file_is_an_error(tmp_path):
    out = tmp_path / "o"
    assert cli("run", EXAMPLES / "simple_pendulum.al", "--out", out, "-q").returncode == 0
    lines = (out / "simple_pendulum.in").read_text().splitlines()
    k = next(i for i, line in enumerate(lines) if line.startswith("Constant"))
    name = lines[k][21:42].strip()
    edited = tmp_path / "twice.in"
    edited.write_text("\n".join(lines[:k + 1] + [lines[k]] + lines[k + 1:]) + "\n")
    r = cli("run", EXAMPLES / "simple_pendulum.al", "--in", edited, "--out", out, "-q")
    assert r.returncode == 1
    assert f"{edited}:{k + 2}:22: {name} is given twice (line {k + 1} and here)" in r.stderr


def test_a_models_control_characters_never_reach_the_terminal(tmp_path):
    path = tmp_path / "esc.al"
    path.write_text("X = 1\nY = \x1b[31m)\n")
    r = cli("check", path)
    assert r.returncode == 1 and "\x1b" not in r.stdout + r.stderr
    assert "Y = \\x1b[31m)" in r.stdout + r.stderr
    session = tmp_path / "esc.all"
    session.write_text("   (1) VARIABLES X\n-> (2) \x1b[2JX = 1\n")
    v = cli("verify", session)
    assert "\x1b" not in v.stdout + v.stderr
    # the response is read by the grammar, which names the character it cannot read
    assert "(2) \\x1b[2JX: not comparable" in v.stdout
    assert "unexpected character U+001B [E001]" in v.stdout


def _limited(gigabytes: float):
    """A child's address space limit (ulimit -v), as a sweep's run would meet it."""
    import resource
    limit = int(gigabytes * 2 ** 30)
    return lambda: resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


BIG_SWEEP = SWEEP.format(start=0, stop="1E8", step=1)


@pytest.mark.skipif(sys.platform != "linux", reason="RLIMIT_AS and /proc: Linux")
def test_a_sweep_of_1e8_points_is_streamed_under_a_memory_limit(tmp_path):
    # the points were built whole before the first was evaluated (2.9 GB: "out of
    # memory"), and Q was said to have no value; now the run goes on from point to point
    import os
    import signal
    import time
    model = tmp_path / "s.al"
    model.write_text(BIG_SWEEP)
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", AUTOLEV_FOREGROUND="1")
    proc = subprocess.Popen([sys.executable, "-m", "autolev", "run", model, "--out",
                             tmp_path / "out"], stderr=subprocess.PIPE, text=True, env=env,
                            preexec_fn=_limited(1.5))
    time.sleep(12)
    running = proc.poll() is None
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    assert running, err
    assert "out of memory" not in err and "no value given for Q" not in err
    assert "point = " in err                  # how far it is, as it goes
    assert not [p for p in (tmp_path / "out").iterdir() if p.name.startswith(".")]


@pytest.mark.skipif(sys.platform != "linux", reason="RLIMIT_AS and /proc: Linux")
def test_rows_to_be_kept_beyond_the_memory_are_refused_up_front_with_the_numbers(tmp_path):
    import os
    model = tmp_path / "s.al"
    model.write_text(BIG_SWEEP)
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", AUTOLEV_FOREGROUND="1")
    done = subprocess.run([sys.executable, "-m", "autolev", "run", model, "--out",
                           tmp_path / "out", "--csv"], capture_output=True, text=True,
                          env=env, preexec_fn=_limited(1.5), timeout=120)
    assert done.returncode == 1, done.stderr
    assert "keeping every row of this run in memory needs about 4.8 GB (1e+08 rows of 1 " \
           "value)" in done.stderr
    assert not (tmp_path / "out").exists() or not list((tmp_path / "out").iterdir())
