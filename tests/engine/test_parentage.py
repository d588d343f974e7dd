"""A compiler a run starts dies with it: a run killed while it compiles (as the system
kills for memory) left the compiler running on (bench/fuzz.py --mode background found
one alive 15 s after the background child compiling it was killed)."""
import os
import signal
import subprocess
import sys
import time

import pytest

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"),
                                reason="PR_SET_PDEATHSIG and /proc: Linux")

_BUILD = """
from autolev.engine.clibrary import build_shared_library
build_shared_library("int f(void) { return 1; }")
"""


def _compilers(marker: str) -> list[int]:
    found = []
    for entry in os.listdir("/proc"):
        try:
            line = open(f"/proc/{entry}/cmdline", "rb").read()
            state = open(f"/proc/{entry}/stat").read().rsplit(") ", 1)[1][0]
        except (OSError, IndexError):
            continue
        if marker.encode() in line and state not in "ZX":
            found.append(int(entry))
    return found


@pytest.mark.parametrize("unit", ["compile", "link"])
def test_a_compiler_dies_with_the_run_that_started_it(tmp_path, unit):
    marker = f"{61 + (unit == 'link')}.{os.getpid()}"
    # the "compiler": a pause (exec'd: the process the run started) where it compiles
    # or where it links, the real compiler elsewhere
    pattern = "*-shared*" if unit == "link" else "*-c*"
    cc = tmp_path / "cc"
    cc.write_text(f"#!/bin/sh\ncase \"$*\" in {pattern}) exec sleep {marker};; esac\n"
                  "exec gcc \"$@\"\n")
    cc.chmod(0o755)
    env = dict(os.environ, CC=str(cc), AUTOLEV_CACHE=str(tmp_path / "cache"))
    env.pop("AUTOLEV_NO_C", None)
    run = subprocess.Popen([sys.executable, "-c", _BUILD], env=env)
    try:
        deadline = time.monotonic() + 60
        while not _compilers(marker):
            assert run.poll() is None, "the build ended before its compiler paused"
            assert time.monotonic() < deadline, "the compiler never started"
            time.sleep(0.05)
        run.kill()
        run.wait()
        deadline = time.monotonic() + 10
        while _compilers(marker):
            assert time.monotonic() < deadline, "the compiler outlived the killed run"
            time.sleep(0.05)
    finally:
        for pid in _compilers(marker):
            os.kill(pid, signal.SIGKILL)
        if run.poll() is None:
            run.kill()
            run.wait()


def test_no_subprocess_is_started_with_a_preexec_fn():
    # a preexec_fn makes subprocess fork plainly, which runs OpenBLAS's fork handler: it
    # stopped OpenBLAS's threads under a solve in another thread (a cold run's compile
    # beside its integration), and the solve waited for ever (CI hung in a linearize)
    from pathlib import Path
    src = Path(__file__).resolve().parents[2] / "src" / "autolev"
    assert [p.name for p in src.rglob("*.py") if "preexec_fn=" in p.read_text()] == []
