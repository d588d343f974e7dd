"""Progress and honest timing (issue 32, item 5): a line for a step past two seconds,
nothing for a quick one, and a run's summary that says what it timed; the one reporter
of how far a long task is (issue 52, item 5)."""
import io
import re
import threading
import time

from autolev.cli import main
from autolev.engine import progress
from autolev.engine.progress import Progress
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


class Terminal(io.StringIO):
    def isatty(self):
        return True


def test_on_a_terminal_the_line_is_redrawn_in_place_and_ended_when_done(monkeypatch):
    clock = iter([0.0, 1.0, 1.1, 1.3])
    monkeypatch.setattr(progress.time, "monotonic", lambda: next(clock))
    stream = Terminal()
    bar = Progress(stream, "T", 0.0, 4.0)       # the clock starts: 0 s
    bar.update(1.0)                             # 1.0 s: the first line
    bar.update(2.0)                             # 1.1 s: redrawn at most every 0.2 s
    bar.update(3.0)                             # 1.3 s
    bar.done()
    assert stream.getvalue() == ("\r  T = 1 of 4 (25%), 1.0 s   "
                                 "\r  T = 3 of 4 (75%), 1.3 s   \n")


def test_a_task_in_steps_times_from_its_first_update_and_says_the_time_left(monkeypatch):
    clock = iter([100.0, 101.0, 104.0, 105.0, 106.0])
    monkeypatch.setattr(progress.time, "monotonic", lambda: next(clock))
    stream = Terminal()                         # lines, not redrawn: a study's are kept
    bar = Progress(stream, "sweep", 0, 40, says="{what}: {position}/{end} points",
                   wait=3.0, every=10.0, in_place=False, steps=20, from_first=True)
    bar.advance(1)              # 100 s: the first point (built and compiled) starts the clock
    bar.advance(1)              # 1 s: too early
    bar.advance(2)              # 4 s: a new 1/20 of the way
    bar.advance(0)              # 5 s: the same 1/20, within 10 s
    bar.advance(36)             # 6 s: done
    bar.done()                  # the last line was the end: nothing more
    assert stream.getvalue().splitlines() == ["  sweep: 4/40 points, 4.0 s, about 48 s left",
                                              "  sweep: 40/40 points, 6.0 s"]
