"""Progress and honest timing (issue 32, item 5): a line for a step past two seconds,
nothing for a quick one, and a run's summary that says what it timed."""
import io
import re
import threading
import time

from autolev.cli import main
from autolev.runtime import steps
from autolev.runtime.steps import SlowStep
from helpers import EXAMPLES


def test_a_slow_step_is_announced_and_timed_and_a_quick_one_says_nothing():
    stream = io.StringIO()
    with SlowStep(stream, "compiling x.c", after=0.05):
        time.sleep(0.3)
    lines = stream.getvalue().splitlines()
    assert lines[0] == "  compiling x.c ..."
    assert re.fullmatch(r"  compiling x\.c: 0\.[3-9] s", lines[1])
    quiet = io.StringIO()
    with SlowStep(quiet, "reading", after=5):
        pass
    assert quiet.getvalue() == ""
    assert threading.active_count() == 1       # no timer outlives its step
    with SlowStep(None, "silent", after=0):    # no stream: nothing, no thread
        time.sleep(0.05)


def test_run_announces_its_long_steps_and_says_what_it_timed(tmp_path, capsys,
                                                             monkeypatch):
    monkeypatch.setattr(steps, "ANNOUNCE_AFTER", 0.0)     # every step is "long" here
    assert main(["run", str(EXAMPLES / "simple_pendulum.al"), "--out", str(tmp_path),
                 "--tfinal", "0.5"]) == 0
    captured = capsys.readouterr()
    assert "reading and forming the model ..." in captured.err
    assert "CODE DYNAMICS simple_pendulum.c: forming its equations ..." in captured.err
    assert "generating and compiling its code ..." in captured.err
    summary = next(line for line in captured.out.splitlines() if line.startswith("CODE"))
    total, built, integrated = map(float, re.search(
        r"in ([\d.]+) s \(building ([\d.]+) s; integrating ([\d.]+) s: kutta-merson",
        summary).groups())
    assert built + integrated <= total + 0.01
