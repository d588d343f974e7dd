"""Integrating a CODE DYNAMICS or ODE command: Autolev's print schedule, the
rows written as they come, the mass matrix's conditioning watched.
"""
from __future__ import annotations

import math
import time
import warnings

import numpy as np

from .errors import AutolevModelError
from .integrate import (Integration, IntegrationFailure, Schedule, failure_basis,
                        integrate_projected)
from .integration_notes import loose_tolerance_note, stiff_note, switch_when_stiff
from .integrators import Integrator
from .results import split_output_rows, split_outputs, tables_of
from .massmatrix import SingularMassMatrix, scaled_condition
from .progress import Progress

# the scaled condition number of the mass matrix beyond which a run warns (the
# accelerations then keep fewer than 6 of their 16 significant digits)
COND_WARN = 1e10


class Conditioning:
    """The scaled condition number of the mass matrix at every row, in batches (its
    memory does not grow with the run): the largest value and where, and the first
    row past COND_WARN (an exactly singular matrix stops the run with its own
    message).  A recursion's rows (runtime/articulated.py) give their pivots over the
    entries they come from instead (the mass matrix's L D L^T pivots, leaves first):
    the largest entry over its pivot stands for the condition."""

    BATCH = 4096

    def __init__(self):
        self.largest = None          # (cond, t)
        self.first_bad = None        # (cond, t, state)
        self._batch = []             # (t, state, matrix or pivot ratios)
        self.pivots = False          # judged by pivot ratios

    def add(self, t, state, matrix) -> None:
        self._batch.append((t, state, matrix))
        if len(self._batch) >= self.BATCH:
            self._flush()

    def _flush(self) -> None:
        if not self._batch:
            return
        judged = np.array([m for _, _, m in self._batch])
        self.pivots = judged.ndim == 2
        if self.pivots:
            with np.errstate(divide="ignore", invalid="ignore"):
                smallest = np.min(judged, axis=1)
                conds = np.where(smallest > 0, 1.0 / smallest, np.inf)
        else:
            conds = scaled_condition(judged)
        k = int(np.argmax(conds))
        if self.largest is None or conds[k] > self.largest[0]:
            self.largest = (float(conds[k]), self._batch[k][0])
        bad = np.nonzero((conds > COND_WARN) & np.isfinite(conds))[0]
        if len(bad) and self.first_bad is None:
            i = int(bad[0])
            self.first_bad = (float(conds[i]), self._batch[i][0], self._batch[i][1])
        self._batch = []

    def report(self, result) -> None:
        """The stats, and a warning with the time and state of the first bad row."""
        self._flush()
        if self.largest is None:
            return
        result.stats["cond_max"], result.stats["cond_max_t"] = self.largest
        if self.first_bad is not None:
            cond, t, state = self.first_bad
            shown = ", ".join(f"{n} = {v:.6g}" for n, v in zip(result.state_names, state))
            measure = (f"a pivot of its factorization is {1 / cond:.2g} of the entry it "
                       "comes from" if self.pivots else
                       f"condition number {cond:.2g} after scaling by its diagonal")
            warnings.warn(
                f"the mass matrix is nearly singular at T = {t:.6g} ({measure}: the "
                f"accelerations may have lost {min(16, int(math.log10(min(cond, 1e16))))} "
                f"of their 16 digits); the state there: {shown}", stacklevel=4)


class _Rows:
    """The print rows of a run as they come: written, kept (all, or only the last), and
    the mass matrix's conditioning watched."""

    def __init__(self, system, result, writer, keep_rows: bool):
        self.system, self.result, self.writer, self.keep_rows = system, result, writer, keep_rows
        self.times: list = []
        self.states: list = []
        self.rows: list = [[] for _ in system.files]
        self.encoded: dict = {}
        self.conditioning = Conditioning()

    def __call__(self, t, y) -> None:
        values = self.system.outputs(t, y)       # solves for the accelerations once
        self._add(t, np.array(y), values, self.system.last_conditioning())

    def block(self, times: np.ndarray, states: np.ndarray) -> None:
        """Rows the compiled loop gave, their outputs computed in one call and written
        together."""
        if not len(times):
            return
        values, matrices = self.system.outputs_rows(times, states)
        if not self.keep_rows:
            self.times.clear()
            self.states.clear()
        kept = slice(None) if self.keep_rows else slice(-1, None)
        self.times.extend(times[kept].tolist())
        self.states.extend(states[kept])
        split_output_rows(self.system, np.asarray(values), self.rows, self.writer,
                          self.encoded, self.keep_rows)
        self.result.stats["rows"] = self.result.stats.get("rows", 0) + len(times)
        if matrices:
            for t, state, mm in zip(times.tolist(), states, matrices):
                self.conditioning.add(t, state, mm)

    def _add(self, t: float, state: np.ndarray, values: np.ndarray, mm) -> None:
        if not self.keep_rows and self.times:
            self.times.clear()
            self.states.clear()
            for r in self.rows:
                r.clear()
        self.times.append(t)
        self.states.append(state)
        split_outputs(self.system, values, self.rows, self.writer, self.encoded)
        self.result.stats["rows"] = self.result.stats.get("rows", 0) + 1
        if mm is not None:
            self.conditioning.add(t, state, mm)

    def finish(self) -> None:
        result, system = self.result, self.system
        result.t = np.array(self.times)
        result.states = np.array(self.states).reshape(len(self.states), system.nstate)
        result.outputs = tables_of(system, self.rows, result.name)
        result.encoded = self.encoded


def print_schedule(inputs, program: str) -> Schedule:
    """The print schedule of the INPUT integration parameters, integrated the way
    Autolev's program in that language integrated."""
    sched = Schedule(inputs.internal("TINITIAL"), inputs.internal("TFINAL"),
                     inputs.internal("INTEGSTP"), int(inputs.internal("PRINTINT")),
                     fresh_derivatives=program == "c",
                     restart_each_step=program == "m")
    try:
        sched.check()
    except ValueError as exc:
        raise AutolevModelError(str(exc)) from None
    return sched


def run_dynamics(system, inputs, result, writer, integrator: Integrator, progress,
                 compiled: bool = True, projector=None, advise=None, program: str = "",
                 keep_rows: bool = True, known_failure: tuple | None = None) -> None:
    """`program`: the language of Autolev's program for the CODE file ("c", "m", ...),
    whose way of integrating is followed.  `keep_rows`: the Result holds every row
    (else only the last: a run's memory is then independent of its length).
    `projector`: puts a state back onto the configuration constraints at each print
    time (the model's, compiled; None: no projection).  `advise(failure, result,
    integration)`: the message of a failed `Integration`, with what the model tells of
    its cause (None: the failure alone).  `known_failure`: (T, message) of the failure
    this run ended with before (a run plan's), said again when it fails there."""
    if not system.nstate:
        raise AutolevModelError("nothing to integrate: no variable has a defined "
                                "derivative and there are no generalized speeds")
    y0 = np.array(inputs.vector(system.states))
    sched = print_schedule(inputs, program)
    on_row = _Rows(system, result, writer, keep_rows)

    compiling = system.rhs_compiling is not None
    took_over = []          # T where a cold build's C took over from its Python

    def f(t, y):
        if system.rhs_compiling is not None and system.compiled_loop() is not None:
            took_over.append(t)
        try:
            return system.derivatives(t, y)
        except SingularMassMatrix as exc:
            raise IntegrationFailure(str(exc), t, y) from None

    bar = Progress(None if progress is False else progress, "T", sched.tinitial,
                   sched.tfinal)
    start = time.perf_counter()
    abserr, relerr = inputs.internal("ABSERR"), inputs.internal("RELERR")
    try:
        use_loop = compiled and not system.specified_functions
        # a cold build's C compiles while the run starts on its Python (the back ends
        # give the same numbers): Kutta-Merson, and RK45 afresh over each step
        # (Autolev's Matlab loop), go on in the compiled loop once it is there, the
        # other methods call the C then; DOP853 in the loop waits for it (scipy's
        # DOP853, which Python would step with, sums in another order)
        ready = system.compiled_loop(wait=use_loop and integrator.waits_for_loop)
        loop = ready if use_loop else None
        loop_when_built = system.compiled_loop \
            if use_loop and integrator.hands_over(sched) and loop is None else None
        integration = Integration(
            f, sched, integrator, abserr, relerr, on_row, bar, loop,
            switch_when_stiff if integrator.switches_when_stiff else None, loop_when_built,
            on_row.block)
        loose_tolerance_note(integrator, relerr)
        if projector is not None:
            result.stats.update(integrate_projected(integration, y0, projector))
        else:
            result.stats.update(integration.run(y0))
        stiff_note(result.stats, integrator)
        if compiling and loop_when_built is None:      # (a loop taking over says itself)
            result.stats.update({"python_until": took_over[0]} if took_over
                                else {"python_only": True})
    except IntegrationFailure as exc:
        on_row(exc.t, exc.y)              # Autolev's last row: where it stopped
        if known_failure is not None and known_failure[0] == exc.t:
            result.failure = known_failure[1]
        elif advise is not None:
            result.failure = advise(exc, result, integration)
        else:
            result.failure = failure_basis(exc, result.state_names)
        result.failure_time = exc.t
        if writer is not None:
            writer.note("Error: " + result.failure)
    except ValueError as exc:
        raise AutolevModelError(str(exc)) from None
    finally:
        bar.done()
        result.stats["seconds"] = time.perf_counter() - start
        on_row.conditioning.report(result)
    on_row.finish()
