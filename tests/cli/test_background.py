"""A cold `autolev run` returns once its files are written; the C it compiles for later
runs finishes in the background (cli/background.py), and the next command on the
model waits for it.  A compiler that takes its time linking the right-hand side with
the integration loop (a wrapper sleeping before gcc) keeps that compile pending when
the run's files are done."""
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from helpers import NUMERICS_DATA

HARMONIC = NUMERICS_DATA / "harmonic.al"
SLOW = 4        # seconds the link sleeps: longer than the model's Python run

pytestmark = pytest.mark.skipif(shutil.which("gcc") is None or os.name != "posix",
                                reason="needs gcc and POSIX (fork, flock)")


@pytest.fixture
def setting(tmp_path):
    """(model, environment): a copy of harmonic.al, a private cache, a slow compiler."""
    model = tmp_path / "harmonic.al"
    shutil.copy(HARMONIC, model)
    slow_cc = tmp_path / "slow-cc"
    # the loop's shared object goes into the right-hand side's library only
    slow_cc.write_text(f"#!/bin/sh\ncase \"$*\" in *shared.o*) sleep {SLOW};; esac\n"
                       f"exec {shutil.which('gcc')} \"$@\"\n")
    slow_cc.chmod(0o755)
    env = dict(os.environ, AUTOLEV_CACHE=str(tmp_path / "cache"), CC=str(slow_cc),
               AUTOLEV_NO_MODEL_CACHE="0")
    env.pop("AUTOLEV_FOREGROUND", None)
    return model, env


def autolev(env, *args):
    return subprocess.run([sys.executable, "-m", "autolev", *map(str, args)],
                          capture_output=True, text=True, env=env)


def cache_names(env) -> list[str]:
    return sorted(os.listdir(env["AUTOLEV_CACHE"]))


def libraries(env) -> list[str]:
    return [n for n in cache_names(env) if n.endswith(".so")]


def locks(env) -> list[str]:
    return [n for n in cache_names(env) if n.startswith("finishing_")]


def test_a_cold_run_returns_before_its_c_and_the_next_run_waits_for_it(setting, tmp_path):
    model, env = setting
    first = autolev(env, "run", model, "--out", tmp_path / "one")
    assert first.returncode == 0, first.stderr
    assert "in Python (its C was compiling)" in first.stdout
    assert "its C compiles on in the background, for later runs" in first.stderr
    # returned with the right-hand side's compile still going (the outputs' library
    # may be there), its child holding the model's lock
    before = libraries(env)
    assert len(locks(env)) == 1

    second = autolev(env, "run", model, "--out", tmp_path / "two")
    assert second.returncode == 0, second.stderr
    # it waited, then repeated the plan the first run's child left: the compiled loop
    assert "(its run plan)" in second.stdout and "in Python" not in second.stdout
    assert len(libraries(env)) > len(before) and locks(env) == []
    assert (tmp_path / "two" / "harmonic.1").read_text() == \
        (tmp_path / "one" / "harmonic.1").read_text()


def test_a_failing_run_gives_its_status_and_message_before_its_c(setting, tmp_path):
    model, env = setting
    failed = autolev(env, "run", model, "--set", "M=0", "--out", tmp_path / "out")
    assert failed.returncode == 1
    assert "singular" in failed.stderr.lower() or "not finite" in failed.stderr, failed.stderr
    assert "in the background" in failed.stderr and locks(env)
    again = autolev(env, "run", model, "--set", "M=0", "--out", tmp_path / "out")
    assert again.returncode == 1
    assert again.stderr.splitlines()[-1] in failed.stderr


def test_a_run_with_no_c_returns_before_its_caches_and_the_next_run_waits(setting,
                                                                           tmp_path):
    # CODE ALGEBRAIC() evaluated once compiles nothing: what is left when its files are
    # written is the built model and the run plan for later runs, here written slowly
    # (a sitecustomize that makes the model cache's writes sleep first)
    _, env = setting
    model = tmp_path / "encoded.al"
    shutil.copy(NUMERICS_DATA / "encoded.al", model)
    slow = tmp_path / "slow-writes"
    slow.mkdir()
    (slow / "sitecustomize.py").write_text(
        "import time\nimport autolev.modelcache as m\n_write = m.write\n"
        f"def write(*a):\n    time.sleep({SLOW})\n    return _write(*a)\nm.write = write\n")
    env = dict(env, PYTHONPATH=os.pathsep.join([str(slow), env.get("PYTHONPATH", "")]))
    first = autolev(env, "run", model, "--out", tmp_path / "one")
    assert first.returncode == 0, first.stderr
    assert "in the background" not in first.stderr
    assert (tmp_path / "one" / "encoded.encode").is_file()
    # returned with the built model not yet written, its child holding the model's lock
    assert len(locks(env)) == 1
    assert not [n for n in cache_names(env) if n.startswith("model_")]

    second = autolev(env, "run", model, "--out", tmp_path / "two")
    assert second.returncode == 0, second.stderr
    assert "(its run plan)" in second.stdout, second.stdout
    assert [n for n in cache_names(env) if n.startswith("model_")] and locks(env) == []
    assert (tmp_path / "two" / "encoded.encode").read_text() == \
        (tmp_path / "one" / "encoded.encode").read_text()


def test_autolev_foreground_keeps_the_wait_in_the_command(setting, tmp_path):
    model, env = setting
    done = autolev(dict(env, AUTOLEV_FOREGROUND="1"), "run", model, "--out", tmp_path / "out")
    assert done.returncode == 0, done.stderr
    assert "in the background" not in done.stderr
    assert libraries(env) and locks(env) == []


def test_emptying_the_cache_waits_for_a_compile_in_the_background(setting, tmp_path):
    model, env = setting
    assert autolev(env, "run", model, "--out", tmp_path / "out").returncode == 0
    assert locks(env)
    cleared = autolev(env, "cache", "clear")
    assert cleared.returncode == 0, cleared.stderr
    # what the child wrote came before the emptying, not after it
    assert cache_names(env) == ["CACHEDIR.TAG"]


def long_run(model, env, out) -> tuple[subprocess.Popen, str]:
    """A run of a million seconds in Python's RK45, and the pid of its child (/proc).
    The command has a process group of its own whose parent is the test's: a job, as a
    shell makes (the kernel ignores Ctrl-Z in an orphaned group, as CI's may be)."""
    proc = subprocess.Popen([sys.executable, "-m", "autolev", "run", model, "--out", out,
                             "--tfinal", "1e6", "--method", "rk45"], process_group=0,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    children = Path(f"/proc/{proc.pid}/task/{proc.pid}/children")
    deadline = time.monotonic() + 60
    while not children.read_text().split():
        assert proc.poll() is None and time.monotonic() < deadline
        time.sleep(0.05)
    (child,) = children.read_text().split()
    return proc, child


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="/proc and prctl: Linux")
def test_the_work_ends_with_a_killed_command(setting, tmp_path):
    # the command is the parent; the child doing the work dies with it (SIGKILL cannot
    # be passed on: the child is told by the kernel)
    model, env = setting
    proc, child = long_run(model, env, tmp_path / "out")
    proc.kill()
    proc.wait()
    deadline = time.monotonic() + 30
    while Path(f"/proc/{child}").exists() and _alive(child):
        assert time.monotonic() < deadline, "the child outlived the command"
        time.sleep(0.1)


def _alive(pid: str) -> bool:
    """Not a zombie waiting for its new parent to reap it."""
    try:
        return Path(f"/proc/{pid}/stat").read_text().split(") ")[1][0] != "Z"
    except (OSError, IndexError):
        return False


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="/proc: Linux")
def test_ctrl_z_stops_the_work_with_the_command_and_fg_goes_on(setting, tmp_path):
    model, env = setting
    proc, child = long_run(model, env, tmp_path / "out")
    try:
        proc.send_signal(signal.SIGTSTP)
        _wait_for_state(child, "T")
        _wait_for_state(str(proc.pid), "T")
        proc.send_signal(signal.SIGCONT)
        _wait_for_state(child, "RS")
    finally:
        proc.kill()
        proc.wait()


def _wait_for_state(pid: str, states: str) -> None:
    """Until the process is in one of `states` (/proc's letters: T stopped, R, S)."""
    deadline = time.monotonic() + 30
    while True:
        state = Path(f"/proc/{pid}/stat").read_text().split(") ")[1][0]
        if state in states:
            return
        assert time.monotonic() < deadline, f"{pid} stays {state}, not {states}"
        time.sleep(0.05)


# -- what a kept plan answers: the inputs as the run read them ----------------------
def _rows_of_a_fresh_run(model, args, env, out) -> str:
    """The rows a run of `model` writes in an empty cache, in the foreground."""
    fresh = dict(env, AUTOLEV_CACHE=str(out) + "-cache", AUTOLEV_FOREGROUND="1")
    done = autolev(fresh, "run", model, *args, "--out", out)
    assert done.returncode == 0, done.stderr
    return (out / "harmonic.1").read_text()


def _in_file_with_x(env, model, tmp_path, x: str) -> Path:
    """race.in: the model's own .in file, with the initial X set to `x`."""
    done = autolev(dict(env, AUTOLEV_FOREGROUND="1", AUTOLEV_CACHE=str(tmp_path / "c0")),
                   "run", model, "--out", tmp_path / "template")
    assert done.returncode == 0, done.stderr
    text = (tmp_path / "template" / "harmonic.in").read_text()
    race = tmp_path / "race.in"
    race.write_text(text.replace("| 0.2\n", f"| {x}\n"))
    assert f"| {x}\n" in race.read_text()
    return race


def test_an_in_file_edited_while_the_compile_finishes_is_read_again(setting, tmp_path):
    # the plan is filed under the .in file as the run read it (0.2), not as it is when
    # the background compile ends and the plan is written (1.2)
    model, env = setting
    race = _in_file_with_x(env, model, tmp_path, "0.2")
    first = autolev(env, "run", model, "--in", race, "--out", tmp_path / "one")
    assert first.returncode == 0 and locks(env), first.stderr
    race.write_text(race.read_text().replace("| 0.2\n", "| 1.2\n"))
    expected = _rows_of_a_fresh_run(model, ["--in", race], env, tmp_path / "fresh")
    assert expected != (tmp_path / "one" / "harmonic.1").read_text()
    for n, out in enumerate(("two", "three")):     # after the compile, then from a plan
        again = autolev(env, "run", model, "--in", race, "--out", tmp_path / out)
        assert again.returncode == 0, again.stderr
        assert (tmp_path / out / "harmonic.1").read_text() == expected
        assert "| 1.2\n" in (tmp_path / out / "harmonic.in").read_text()
        assert ("(its run plan)" in again.stdout) == (n == 1)


def test_a_model_edited_while_the_compile_finishes_is_read_again(setting, tmp_path):
    model, env = setting
    first = autolev(env, "run", model, "--out", tmp_path / "one")
    assert first.returncode == 0 and locks(env), first.stderr
    model.write_text(model.read_text().replace("INPUT K = 4", "INPUT K = 9"))
    expected = _rows_of_a_fresh_run(model, [], env, tmp_path / "fresh")
    assert expected != (tmp_path / "one" / "harmonic.1").read_text()
    for out in ("two", "three"):
        again = autolev(env, "run", model, "--out", tmp_path / out)
        assert again.returncode == 0, again.stderr
        assert (tmp_path / out / "harmonic.1").read_text() == expected


# -- faults: a terminal that stops background writers, a child killed ----------------
def test_a_terminal_with_tostop_neither_stops_the_work_nor_hangs_the_command(setting,
                                                                             tmp_path):
    # the child has a process group of its own: on a terminal with `stty tostop` its
    # first write stopped it, and the command waited for it forever
    import fcntl
    import termios
    import threading
    model, env = setting
    master, slave = os.openpty()
    attrs = termios.tcgetattr(slave)
    attrs[3] |= termios.TOSTOP
    termios.tcsetattr(slave, termios.TCSANOW, attrs)

    def controlling_terminal():          # the command is a session on the terminal
        fcntl.ioctl(0, termios.TIOCSCTTY, 0)
    proc = subprocess.Popen([sys.executable, "-m", "autolev", "run", str(model), "--out",
                             str(tmp_path / "out")], stdin=slave, stdout=slave,
                            stderr=slave, env=env, start_new_session=True,
                            preexec_fn=controlling_terminal)
    os.close(slave)
    said = []

    def drain():
        while True:
            try:
                chunk = os.read(master, 4096)
            except OSError:
                return
            if not chunk:
                return
            said.append(chunk)
    reader = threading.Thread(target=drain, daemon=True)
    reader.start()
    try:
        assert proc.wait(timeout=60) == 0, b"".join(said).decode(errors="replace")
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    text = b"".join(said).decode(errors="replace")
    assert "wrote" in text and (tmp_path / "out" / "harmonic.1").exists()
    # the work finished in the background, on the same terminal
    deadline = time.monotonic() + 60
    while locks(env):
        assert time.monotonic() < deadline, "the background compile never finished"
        time.sleep(0.2)
    os.close(master)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="/proc: Linux")
def test_a_child_killed_before_its_outputs_is_said_not_an_internal_error(setting, tmp_path):
    # as the OOM killer would: the parent tried to install a handler for SIGKILL
    # (exit 70, "internal error"); now it says what happened and leaves no part file
    model, env = setting
    out = tmp_path / "out"
    proc = subprocess.Popen([sys.executable, "-m", "autolev", "run", model, "--out", out,
                             "--tfinal", "1e6", "--method", "rk45"], process_group=0,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env,
                            text=True)
    children = Path(f"/proc/{proc.pid}/task/{proc.pid}/children")
    deadline = time.monotonic() + 60
    while not any(p.name.endswith(".autolev-part") for p in out.glob(".*")):
        assert proc.poll() is None and time.monotonic() < deadline
        time.sleep(0.05)
    (child,) = children.read_text().split()
    os.kill(int(child), signal.SIGKILL)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 1, err
    assert "killed (SIGKILL)" in err and "internal error" not in err
    assert [p.name for p in out.iterdir()] == []


def test_autolev_foreground_0_leaves_the_compile_to_the_background(setting, tmp_path):
    model, env = setting
    done = autolev(dict(env, AUTOLEV_FOREGROUND="0"), "run", model, "--out", tmp_path / "o")
    assert done.returncode == 0, done.stderr
    assert "in the background" in done.stderr and locks(env)


def test_a_lock_left_by_a_killed_child_is_removed_by_the_next_run(setting, tmp_path,
                                                                  monkeypatch):
    # a child killed after it detached cannot remove its lock (no exit handlers)
    from autolev.cli.background import lock_file
    model, env = setting
    monkeypatch.setenv("AUTOLEV_CACHE", env["AUTOLEV_CACHE"])
    lock = lock_file(model)
    lock.write_text("")
    os.utime(lock, (time.time() - 3600, time.time() - 3600))
    done = autolev(dict(env, AUTOLEV_FOREGROUND="1"), "run", model, "--out", tmp_path / "o")
    assert done.returncode == 0, done.stderr
    assert not lock.exists()


# a shell that outlives its terminal's hang-up and passes nothing on: the command's job
# meets the hang-up only as EIO on its next write
_SURVIVING_SHELL = r"""
import fcntl, os, signal, sys, termios
report = sys.argv[1]
fcntl.ioctl(0, termios.TIOCSCTTY, 0)
signal.signal(signal.SIGHUP, signal.SIG_IGN)
signal.signal(signal.SIGTTOU, signal.SIG_IGN)
job = os.fork()
if job == 0:
    os.setpgid(0, 0)
    signal.signal(signal.SIGHUP, signal.SIG_DFL)
    signal.signal(signal.SIGTTOU, signal.SIG_DFL)
    os.execv(sys.executable, [sys.executable, "-m", "autolev", *sys.argv[2:]])
os.setpgid(job, job)
os.tcsetpgrp(0, job)
open(report + ".started", "w").close()
_, how = os.waitpid(job, 0)
with open(report, "w") as f:
    f.write(str(os.waitstatus_to_exitcode(how)))
"""


@pytest.mark.parametrize("foreground", ["1", "0"])
def test_a_terminal_that_hangs_up_ends_the_command_as_a_hang_up(setting, tmp_path,
                                                                 foreground):
    # its write's EIO was an internal error (exit 70), or exit 1 when even that message
    # failed: a user closing a window is no bug of autolev's
    model, env = setting
    env["AUTOLEV_FOREGROUND"] = foreground
    master, slave = os.openpty()
    report = tmp_path / "status"
    shell = subprocess.Popen([sys.executable, "-c", _SURVIVING_SHELL, str(report), "run",
                              str(model), "--out", str(tmp_path / "out")],
                             stdin=slave, stdout=slave, stderr=slave, env=env,
                             start_new_session=True)
    os.close(slave)
    deadline = time.monotonic() + 30
    while not Path(f"{report}.started").exists():
        assert time.monotonic() < deadline and shell.poll() is None, "the shell never began"
        time.sleep(0.02)
    os.close(master)                    # the window closed before the command wrote
    assert shell.wait(timeout=60) == 0
    assert report.read_text() == str(-signal.SIGHUP)


def test_a_lock_just_left_by_a_killed_child_is_removed_by_the_next_run(setting, tmp_path,
                                                                       monkeypatch):
    # a child killed while it compiled (or whose cache turned read-only) left its lock;
    # the next run, warm, forked no child to take it over, and it stayed for a minute
    from autolev.cli.background import lock_file
    model, env = setting
    monkeypatch.setenv("AUTOLEV_CACHE", env["AUTOLEV_CACHE"])
    lock = lock_file(model)
    lock.write_text("")                 # as new: only no process holds it
    done = autolev(dict(env, AUTOLEV_FOREGROUND="1"), "run", model, "--out", tmp_path / "o")
    assert done.returncode == 0, done.stderr
    assert not lock.exists()


def test_a_childs_lock_is_made_held_and_a_held_one_is_left_alone(setting, monkeypatch):
    # the lock appears under its name already held (made aside, locked, then linked),
    # so that a lock no process holds is always one left behind, and removed as such
    import fcntl

    from autolev.cli import background
    model, env = setting
    monkeypatch.setenv("AUTOLEV_CACHE", env["AUTOLEV_CACHE"])
    lock = background.lock_file(model)
    lock.write_text("")                 # left by a killed child: taken over
    fd = background._hold(lock)
    assert fd is not None and lock.exists()
    assert os.fstat(fd).st_ino == os.stat(lock).st_ino
    probe = os.open(lock, os.O_RDONLY)
    with pytest.raises(BlockingIOError):
        fcntl.flock(probe, fcntl.LOCK_SH | fcntl.LOCK_NB)
    # held: another child does not take it, nor does a waiter remove it
    assert background._hold(lock) is None
    background._remove_if_left(lock)
    assert lock.exists() and os.stat(lock).st_ino == os.fstat(fd).st_ino
    os.close(probe)
    assert [n for n in os.listdir(lock.parent) if n.startswith(".")] == []
