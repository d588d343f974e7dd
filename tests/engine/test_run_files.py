"""A run's files are written as a set (issue 15, item 3): a refused, interrupted or
failed-to-write run leaves the previous run's files as they were, with no temporaries,
and two runs cannot write into one folder at once."""
import collections
import errno
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import autolev
from autolev.runtime import AutolevModelError
from autolev.engine import files
from helpers import EXAMPLES

PENDULUM = EXAMPLES / "double_pendulum.al"


@pytest.fixture(scope="module")
def model():
    return autolev.load(PENDULUM)


def snapshot(folder):
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


def first_run(model, out):
    result = model.simulate(out_dir=out, TFINAL=0.2)
    assert result.ok and (out / "double_pendulum.in").exists()
    return snapshot(out)


def test_a_refused_run_leaves_the_previous_files(model, tmp_path):
    out = tmp_path / "out"
    before = first_run(model, out)
    with pytest.raises(AutolevModelError, match="must be finite and not negative"):
        model.simulate(out_dir=out, TFINAL=0.2, M1=-1)
    assert snapshot(out) == before


def test_a_full_disk_mid_run_leaves_the_previous_files(model, tmp_path, monkeypatch):
    out = tmp_path / "out"
    before = first_run(model, out)
    written = []
    real_write = files.OutputFiles.write

    class NoRoom:                               # the disk, full from the fourth row on
        def __init__(self, handle):
            self.handle = handle

        def write(self, text):
            raise OSError(errno.ENOSPC, "No space left on device")

        def close(self):
            self.handle.close()

    def fills_up(self, k, values):
        written.append(values)
        if len(written) > 3:
            self._handles[k] = NoRoom(self._handles[k])
        real_write(self, k, values)

    def fills_up_rows(self, k, block):          # the compiled loop's rows, a block at once
        for values in block:
            fills_up(self, k, values)
    monkeypatch.setattr(files.OutputFiles, "write", fills_up)
    monkeypatch.setattr(files.OutputFiles, "write_rows", fills_up_rows)
    with pytest.raises(AutolevModelError, match="No space left on device"):
        model.simulate(out_dir=out, TFINAL=0.4, Q1=80)
    assert len(written) == 4
    assert snapshot(out) == before          # the new .in (Q1 = 80) is not beside old rows


def test_a_second_run_into_a_locked_folder_is_refused(model, tmp_path):
    out = tmp_path / "out"
    before = first_run(model, out)
    holder = files.RunFiles(out, "other")
    try:
        with pytest.raises(AutolevModelError, match="another autolev run is writing into"):
            model.simulate(out_dir=out, TFINAL=0.2, Q1=80)
    finally:
        holder.discard()
        holder.release()
    assert snapshot(out) == before
    assert model.simulate(out_dir=out, TFINAL=0.2, Q1=80).ok      # free again


def test_temporaries_of_a_killed_run_are_removed_by_the_next(model, tmp_path):
    out = tmp_path / "out"
    first_run(model, out)
    stale = out / f".double_pendulum.1.99999{files.PART}"
    stale.write_text("% FILE: double_pendulum.1\n 1.0\n")
    model.simulate(out_dir=out, TFINAL=0.2)
    assert not stale.exists()
    assert not [p for p in out.iterdir() if p.name.endswith(files.PART)]


def test_tables_of_the_previous_run_that_this_run_did_not_write_go(model, tmp_path):
    # the previous run had two OUTPUT statements more: its .3 and .4 would pass for
    # this run's; a .5 autolev did not write (laid out as its own) stays
    out = tmp_path / "out"
    text = PENDULUM.read_text()
    assert text.count("\nOUTPUT") == 2
    more = tmp_path / "more" / "double_pendulum.al"
    more.parent.mkdir()
    more.write_text(text.replace("CODE DYNAMICS", "OUTPUT T\nOUTPUT Q1\nCODE DYNAMICS"))
    autolev.load(more).simulate(out_dir=out, TFINAL=0.2)
    assert (out / "double_pendulum.4").exists()
    (out / "double_pendulum.5").write_text("% FILE: double_pendulum.5\n")
    result = model.simulate(out_dir=out, TFINAL=0.2)
    names = {p.name for p in out.iterdir()}
    assert not {"double_pendulum.3", "double_pendulum.4"} & names
    assert "double_pendulum.5" in names
    assert {p.name for p in result.files} <= names


def test_an_integration_failure_keeps_its_rows_as_autolev_did(tmp_path):
    path = tmp_path / "blowup.al"
    path.write_text("VARIABLES X'\nINPUT X = 1, TFINAL = 2, INTEGSTP = 0.1\nX' = X^2\n"
                    "OUTPUT T, X\nCODE ODE() blowup.c\n")
    result = autolev.load(path).simulate(out_dir=tmp_path / "out")
    assert not result.ok and len(result.t) > 5
    table = (tmp_path / "out" / "blowup.1").read_text()
    assert table.count("\n") > 5 and "% Error: Numerical integration failed" in table


def cli(*args, **kw):
    return subprocess.Popen([sys.executable, "-m", "autolev", *map(str, args)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kw)


@pytest.mark.skipif(not hasattr(signal, "SIGTERM") or os.name != "posix",
                    reason="POSIX signals")
def test_sigterm_mid_run_leaves_the_previous_files_and_no_temporaries(model, tmp_path):
    out = tmp_path / "out"
    before = first_run(model, out)
    proc = cli("run", PENDULUM, "--out", out, "--tfinal", "1e6", "--set", "Q1=80",
               "--method", "rk45")          # the Python loop: long, and rows come slowly
    deadline = time.monotonic() + 60
    while not [p for p in out.iterdir() if p.name.endswith(files.PART)]:
        assert proc.poll() is None and time.monotonic() < deadline
        time.sleep(0.05)
    time.sleep(0.3)
    proc.send_signal(signal.SIGTERM)
    proc.communicate(timeout=60)
    assert proc.returncode == -signal.SIGTERM        # ended as the signal would end it
    assert snapshot(out) == before


def test_two_cli_runs_into_one_folder(model, tmp_path):
    out = tmp_path / "out"
    first_run(model, out)
    slow = cli("run", PENDULUM, "--out", out, "--tfinal", "1e6", "--method", "rk45")
    try:
        deadline = time.monotonic() + 60
        while not [p for p in out.iterdir() if p.name.endswith(files.PART)]:
            assert slow.poll() is None and time.monotonic() < deadline
            time.sleep(0.05)
        second = cli("run", PENDULUM, "--out", out, "--set", "Q1=80")
        _, err = second.communicate(timeout=120)
        assert second.returncode == 1
        assert f"another autolev run is writing into {out}" in err
        assert "Traceback" not in err
    finally:
        slow.kill()
        slow.communicate()


def test_a_run_that_keeps_only_its_last_row_writes_the_same_files(model, tmp_path):
    kept = model.simulate(out_dir=tmp_path / "a", TFINAL=1)
    last = model.simulate(out_dir=tmp_path / "b", TFINAL=1, keep_rows=False)
    assert snapshot(tmp_path / "a") == snapshot(tmp_path / "b")
    assert len(kept.t) == 101 and kept.stats["rows"] == last.stats["rows"] == 101
    assert len(last.t) == 1 and last.t[0] == kept.t[-1]
    assert np.array_equal(last.states[0], kept.states[-1])
    assert np.array_equal(last.outputs[1].data[0], kept.outputs[1].data[-1])
    assert last.stats["cond_max"] == kept.stats["cond_max"]


def test_a_folder_that_refuses_files_is_one_message_and_no_partial_set(model, tmp_path,
                                                                       monkeypatch):
    # root may write anywhere: the refusal of a read-only folder is the kernel's EACCES
    real_open = os.open

    def read_only(path, flags, *args, **kw):
        if str(path).endswith(files.PART):
            raise PermissionError(errno.EACCES, "Permission denied", str(path))
        return real_open(path, flags, *args, **kw)
    monkeypatch.setattr(files.os, "open", read_only)
    out = tmp_path / "out"
    with pytest.raises(AutolevModelError, match=f"cannot write the output files into {out}: "
                       "Permission denied"):
        model.simulate(out_dir=out, TFINAL=0.2)
    assert list(out.iterdir()) == []


def test_a_full_disk_is_the_users_error_and_leaves_no_temporary(tmp_path, monkeypatch):
    # the disk fills while rows are written; closing the buffered files then fails too
    from autolev.engine import files
    real = files.os.fdopen

    class Full:
        def __init__(self, handle):
            self.handle, self.written = handle, 0

        def write(self, text):
            self.written += len(text)
            if self.written > 2000:
                raise OSError(errno.ENOSPC, "No space left on device")
            return self.handle.write(text)

        def close(self):
            self.handle.close()
            raise OSError(errno.ENOSPC, "No space left on device")

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.close()

    monkeypatch.setattr(files.os, "fdopen", lambda *a, **k: Full(real(*a, **k)))
    out = tmp_path / "out"
    model = autolev.load(EXAMPLES / "simple_pendulum.al")
    with pytest.raises(AutolevModelError,
                       match=f"cannot write the output files into {out}: No space left"):
        model.simulate(out_dir=out)
    assert list(out.iterdir()) == []


Usage = collections.namedtuple("Usage", "total used free")     # as shutil.disk_usage's
DECAY = "VARIABLES X'\nX' = -X\nINPUT X=1, TINITIAL=0, TFINAL={tfinal}, INTEGSTP={step}, " \
        "PRINTINT={printint}\nOUTPUT T, X\nCODE ODE() decay.c\n"


@pytest.mark.parametrize("tfinal, step, printint", [(1, 0.1, 1), (1, 0.1, 3), (2, 0.25, 8),
                                                    (1, 0.3, 1)])
def test_the_rows_a_run_expects_are_the_rows_it_writes(tmp_path, tfinal, step, printint):
    from autolev.engine.integrate import Schedule
    path = tmp_path / "decay.al"
    path.write_text(DECAY.format(tfinal=tfinal, step=step, printint=printint))
    result = autolev.load(path).simulate(out_dir=tmp_path / "o")
    written = [line for line in (tmp_path / "o" / "decay.1").read_text().splitlines()
               if line.strip() and not line.startswith("%")]
    expected = Schedule(0.0, tfinal, step, printint).printed_rows()
    assert expected == len(written) == len(result.t)


def test_a_run_too_big_for_the_disk_is_refused_before_it_computes(tmp_path, monkeypatch,
                                                                   capsys):
    from autolev.cli import main
    path = tmp_path / "decay.al"
    # 10001 rows of two 15-character values and a newline: 310 kB, where 100 kB is free
    path.write_text(DECAY.format(tfinal=10, step=0.001, printint=1))
    monkeypatch.setattr(files, "ANNOUNCED_BYTES", 1000)
    monkeypatch.setattr(files.shutil, "disk_usage",
                        lambda folder: Usage(10 ** 9, 10 ** 9, 100_000))
    assert main(["run", str(path), "--out", str(tmp_path / "o"), "-q"]) == 1
    err = capsys.readouterr().err
    assert "would write about 310 kB (1e+04 rows, 2 value(s) a row" in err
    assert "100 kB is free" in err and "decay.al:5:" in err
    assert not (tmp_path / "o").exists() or not any((tmp_path / "o").iterdir())


def test_a_run_that_writes_much_says_so_first(tmp_path, monkeypatch, capsys):
    from autolev.cli import main
    path = tmp_path / "decay.al"
    path.write_text(DECAY.format(tfinal=1, step=0.01, printint=1))
    monkeypatch.setattr(files, "ANNOUNCED_BYTES", 1000)
    assert main(["run", str(path), "--out", str(tmp_path / "o"), "-q"]) == 0
    # 101 rows of two 15-character values and a newline
    assert f"this run writes about {101 * 31 / 1000:.3g} kB" in capsys.readouterr().err


# the head of a Matlab program as Autolev 4.1 wrote it (MAE-223's bicycle14.m, cut to a
# spring's names): the input values sit in ReadUserInput, one `NAME = value;` a line
AUTOLEVS_MATLAB = """function SPRING
SolveOrdinaryDifferentialEquations
% File  SPRING.m  created by Autolev 4.1 on Thu Jul 06 17:45:29 2006


%===========================================================================
function VAR = ReadUserInput
global   K M;
global   X V;
global   Xp Vp;
global   DEGtoRAD RADtoDEG z;
global   TINITIAL TFINAL INTEGSTP PRINTINT ABSERR RELERR;

%-------------------------------+--------------------------+-------------------+-----------------
% Quantity                      | Value                    | Units             | Description
%-------------------------------|--------------------------|-------------------|-----------------
K                               =  9.0;                    % UNITS               Constant
M                               =  1.0;                    % UNITS               Constant

X                               =  0.25;                   % UNITS               Initial Value
V                               =  0.0;                    % UNITS               Initial Value

TINITIAL                        =  0.0;                    % sec                 Initial Time
TFINAL                          =  1.0;                    % sec                 Final Time
INTEGSTP                        =  0.1;                    % sec                 Integration Step
PRINTINT                        =  1;                      % Positive Integer    Print-Integer
ABSERR                          =  1.0E-08;                %                     Absolute Error
RELERR                          =  1.0E-07 ;               %                     Relative Error
%-------------------------------+--------------------------+-------------------+-----------------

% Unit conversions
Pi       = 3.141592653589793;

% Evaluate constants
z(1) = K/M;

%===========================================================================
function sys = mdlDerivatives(T,VAR,u)
X = 7.0;
"""

SPRING = """VARIABLES X', V'
CONSTANTS K, M
X' = V
V' = -K/M*X
INPUT K = 4, M = 1, X = 1, V = 0, TFINAL = 2, INTEGSTP = 0.5
OUTPUT X
CODE DYNAMICS() spring.m
"""


def test_the_inputs_of_an_autolev_matlab_program_are_read_by_in(tmp_path):
    # Autolev's Matlab programs hold their input values inline: a Matlab user has that
    # file, not an .in (it was refused: "no values found")
    model = tmp_path / "spring.al"
    model.write_text(SPRING)
    program = tmp_path / "SPRING.m"
    program.write_text(AUTOLEVS_MATLAB)
    result = autolev.load(model).simulate(infile=program, out_dir=tmp_path / "out")
    assert result.inputs["K"] == 9.0 and result.inputs["X"] == 0.25
    assert result.t[-1] == pytest.approx(1.0)               # its integration too
    # X = 0.25 cos(3 T): the values came from ReadUserInput, not from mdlDerivatives
    assert np.allclose(result.outputs[0]["X"], 0.25 * np.cos(3 * result.t), atol=1e-6)
    written = (tmp_path / "out" / "spring.in").read_text()
    assert "| 9.0" in written and "| 0.25" in written


@pytest.mark.skipif(__import__("autolev.engine.clibrary", fromlist=["compiler"]).compiler()
                    is None, reason="no C compiler: nothing is compiled")
@pytest.mark.parametrize("foreground", ["1", "0"])
def test_a_compiler_that_cannot_start_is_a_python_run_not_a_disk_error(tmp_path, monkeypatch,
                                                                       foreground):
    # a loaded machine refuses gcc's fork (EAGAIN): the path table saw a warm run say
    # "cannot write the output files" for it; the run's numbers are the Python tier's
    from autolev.engine import clibrary
    monkeypatch.setenv("AUTOLEV_CACHE", str(tmp_path / "cache"))
    monkeypatch.setenv("AUTOLEV_FOREGROUND", foreground)
    model = autolev.load(PENDULUM)
    model.simulate(out_dir=tmp_path / "python", TFINAL=20, backend="python")

    def no_fork(*args, **kw):
        raise BlockingIOError(errno.EAGAIN, "Resource temporarily unavailable")
    monkeypatch.setattr(clibrary.subprocess, "Popen", no_fork)
    monkeypatch.setattr(clibrary.subprocess, "run", no_fork)
    with pytest.warns(UserWarning, match="failed; using Python.*Resource temporarily"):
        result = model.simulate(out_dir=tmp_path / "out", TFINAL=20, backend="auto")
    assert snapshot(tmp_path / "out") == snapshot(tmp_path / "python")
    assert result.ok
