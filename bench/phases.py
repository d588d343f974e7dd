#!/usr/bin/env python3
"""Where a command's time goes: the command run in this process while a thread samples
its main thread's stack every few milliseconds, each sample given to a phase.

    python bench/phases.py [--interval MS] [--json FILE] -- run MODEL.al [options...]

A sample's phase is that of its innermost frame with a rule in PHASES (sympy's and
numpy's own frames have none: they count for the autolev code that called them):

    start-up         importing modules (at start, or the first use of a library)
    parsing          the ANTLR parser and the syntax tree
    translation      the Autolev program translated to Python
    forming          the translated model executed: kinematics, Kane's equations, D(),
                     DT(), the definitions' calculus (runtime/)
    code generation  a CODE command's numerics built: its equations solved, its programs
                     made and printed (runtime/numerics/)
    compile          a generated program compiled (C in the foreground, Python's compile)
    evaluation       integrating, or evaluating an algebraic program: the first numbers
    writing          the output files
    other            the command line, caches, reports

`first numbers` is when the first sample fell in evaluation (the run's first row is
being computed).  bench/latency.py runs each cold run this way.  The sampler costs
about 20 microseconds a sample (0.4 % at 5 ms).  A background child the command
forks (its C compiling on after it returns) is not sampled: the process the user waits
for is.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import signal
import time
from pathlib import Path

# (what the file's path ends with or holds, the function or None for any, the phase):
# the first rule that matches a frame gives it its phase
PHASES: list[tuple[str, str | None, str]] = [
    (".al.py", None, "forming"),           # the translated model, run as a module
    ("", "<module>", "start-up"),          # any other module's body: an import
    ("<frozen importlib._bootstrap", None, "start-up"),
    ("autolev/runtime/numerics/codegen.py", "compile_python", "compile"),
    ("autolev/runtime/numerics/codegen.py", "compile_c", "compile"),
    ("autolev/engine/clibrary.py", None, "compile"),
    ("autolev/engine/pyfunction.py", "__init__", "compile"),
    ("<autolev generated ", None, "evaluation"),
    ("<autolev dual ", None, "evaluation"),
    ("autolev/engine/integrate.py", None, "evaluation"),
    ("autolev/engine/integrators.py", None, "evaluation"),
    ("autolev/engine/cloop.py", None, "evaluation"),
    ("autolev/engine/dynamics.py", None, "evaluation"),
    ("autolev/engine/massmatrix.py", None, "evaluation"),
    ("autolev/engine/algebraic.py", None, "evaluation"),
    ("autolev/engine/evaluation.py", None, "evaluation"),
    ("autolev/engine/pyfunction.py", None, "evaluation"),
    ("autolev/runtime/numerics/interpret.py", None, "evaluation"),
    ("autolev/engine/outputs.py", None, "writing"),
    ("autolev/engine/rowtext.py", None, "writing"),
    ("autolev/engine/results.py", None, "writing"),
    ("autolev/runtime/numerics/", None, "code generation"),
    ("autolev/runtime/printer.py", None, "code generation"),
    ("autolev/runtime/", None, "forming"),
    ("autolev/loader.py", "_execute", "forming"),
    ("autolev/_antlr/", None, "parsing"),
    ("antlr4/", None, "parsing"),
    ("autolev/syntax.py", None, "parsing"),
    ("autolev/translate/", None, "translation"),
    ("autolev/irbuild.py", None, "translation"),
    ("autolev/ir.py", None, "translation"),
    ("autolev/", None, "other"),
]
ORDER = ["start-up", "parsing", "translation", "forming", "code generation", "compile",
         "evaluation", "writing", "other"]
FIRST_NUMBERS = "evaluation"


def phase_of(frame) -> tuple[str, str]:
    """The phase of a sample, and where: its innermost frame with a rule ('other' and
    the innermost frame without one)."""
    innermost = frame
    while frame is not None:
        code = frame.f_code
        path = code.co_filename.replace(os.sep, "/")
        for where, function, phase in PHASES:
            if where in path and (function is None or function == code.co_name):
                return phase, _place(frame)
        frame = frame.f_back
    return "other", _place(innermost)


def _place(frame) -> str:
    code = frame.f_code
    return f"{code.co_filename.replace(os.sep, '/').split('/')[-1]}:{code.co_name}"


class Sampler:
    """Samples the main thread's stack every `interval` seconds of wall time by a timer
    signal (SIGALRM: no thread, so the command may still fork its background child, and
    a wait in a system call is sampled too): seconds per phase (each sample weighs the
    time since the one before) and when the first sample of FIRST_NUMBERS came.  A
    child the command forks samples on from the parent's counts."""

    def __init__(self, interval: float = 0.005) -> None:
        self.interval = interval
        self.seconds: dict[str, float] = dict.fromkeys(ORDER, 0.0)
        self.first_numbers: float | None = None
        self.places: dict[tuple[str, str], float] = {}     # (phase, file:function)
        self._start = self._last = 0.0

    def __enter__(self) -> Sampler:
        self._start = self._last = time.monotonic()
        signal.signal(signal.SIGALRM, self._sample)
        os.register_at_fork(after_in_child=self._arm)    # a fork does not keep timers
        self._arm()
        return self

    def __exit__(self, *exc) -> None:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, signal.SIG_DFL)

    def _arm(self) -> None:
        signal.setitimer(signal.ITIMER_REAL, self.interval, self.interval)

    def _sample(self, _signum, frame) -> None:
        now = time.monotonic()
        phase, place = phase_of(frame)
        self.seconds[phase] += now - self._last
        self.places[phase, place] = self.places.get((phase, place), 0.0) + now - self._last
        self._last = now
        if phase == FIRST_NUMBERS and self.first_numbers is None:
            self.first_numbers = now - self._start

    def report(self, places: int = 3) -> dict:
        """Seconds per phase, the first numbers' time, and each phase's `places` most
        sampled frames (file:function of the frame the rule matched)."""
        top = {p: [f"{where} {s:.2f}" for (q, where), s in sorted(
            self.places.items(), key=lambda item: -item[1]) if q == p][:places]
            for p in ORDER}
        return {"seconds": {p: round(s, 3) for p, s in self.seconds.items()},
                "where": {p: w for p, w in top.items() if w},
                "first_numbers": None if self.first_numbers is None
                else round(self.first_numbers, 3),
                "sampled": round(time.monotonic() - self._start, 3)}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--interval", type=float, default=5.0, help="milliseconds a sample")
    ap.add_argument("--json", type=Path, metavar="FILE",
                    help="write the phases there (else to stderr at the end)")
    ap.add_argument("command", nargs=argparse.REMAINDER,
                    help="the autolev command and its arguments, after --")
    ns = ap.parse_args(argv)
    command = ns.command[1:] if ns.command[:1] == ["--"] else ns.command
    if not command:
        ap.error("no autolev command given (after --)")
    sys.argv = ["autolev", *command]
    sampler = Sampler(ns.interval / 1000)
    reported = []

    def write_report() -> None:
        reported.append(True)
        text = json.dumps(sampler.report())
        if ns.json:
            ns.json.write_text(text)
        else:
            print(text, file=sys.stderr, flush=True)
    with sampler:
        from autolev.cli import background, entry
        # a run that forks its background child: the user waits until the child's
        # outputs are done (its detach), not for the parent's wait nor the compile after
        detach = background.Finishing.detach

        def reported_detach(finishing, *args):
            sampler.__exit__()
            write_report()
            return detach(finishing, *args)
        background.Finishing.detach = reported_detach
        status = entry()
    if not reported:
        write_report()
    return status


if __name__ == "__main__":
    sys.exit(main())
