"""Integration on Autolev's print schedule.

The schedule is that of Autolev's programs: time advances by INTEGSTP per step (T is
accumulated by repeated addition, as there); a row is printed at TINITIAL, after every
PRINTINT steps, and at the first step where T + 0.01*INTEGSTP reaches TFINAL, so the
last row may lie past TFINAL when TFINAL is not on the grid.

The integrators are engine/integrators.py's records; an integration's parts are one
`Integration`.  The ways of stepping:

* Kutta-Merson -- the adaptive Kutta-Merson of Autolev's C and Fortran programs, step
  for step: each call advances exactly INTEGSTP; the error estimate of a step is
  |y1 - y2|/5 (third- against fourth-order); a step fails when, for some state, it is
  at least both RELERR*|y1| and ABSERR, and is then halved; a step is doubled (within
  INTEGSTP) when every error is 64 times smaller; the net number of halvings is capped
  at 20 over the run, after which the integration fails, as Autolev's did.  Autolev
  4.1's C programs evaluate the derivatives at the start of every step; 3.2's Fortran
  reused the last stage's (``Schedule.fresh_derivatives``).
* scipy's ``RK45``, ``DOP853``, ``Radau``, ``BDF``, ``LSODA``, ``RK23`` with
  ``max_step=INTEGSTP``, ``rtol=RELERR``, ``atol=ABSERR``; rows come from each
  method's dense output.
* RK45 started afresh over every INTEGSTP (Autolev's Matlab programs: ode45 from T to
  T + INTEGSTP in their loop) is scipy's RK45 step for step, computed here in the
  compiled loop's order of operations (`RK45Interval`: the same sums, in the same
  order), so that a run's rows are the same whether Python or C took each step (a
  cold run starts in Python and goes on in C once it is compiled).
"""
from __future__ import annotations

import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from . import cloop, rk45_tableau
from .integrators import SCIPY_METHODS, Integrator, integrator_named
from .progress import Progress

__all__ = ["SCIPY_METHODS", "Integration", "IntegrationFailure", "KuttaMerson",
           "RK45Interval", "Schedule", "failure_basis", "integrate", "integrate_projected"]


class IntegrationFailure(Exception):
    """The integration stopped at time t with state y; `cuts`: because Kutta-Merson's
    step was halved more than it allows (the failure that needs explaining)."""

    def __init__(self, message: str, t: float, y: np.ndarray, cuts: bool = False):
        super().__init__(message)
        self.t = t
        self.y = np.array(y, dtype=float)
        self.cuts = cuts


@dataclass
class Schedule:
    tinitial: float
    tfinal: float
    integstp: float
    printint: int
    # Kutta-Merson as Autolev 4.1's C programs call it (kutta(..., 2)): the derivatives
    # evaluated at the start of every step; False: as Autolev 3.2's Fortran (kutta(...,
    # 1)), the last stage's derivatives reused there
    fresh_derivatives: bool = False
    # as Autolev's Matlab programs: the integrator started afresh over every INTEGSTP
    # (ode45(@f, [T T+INTEGSTP], VAR, ...) in their loop)
    restart_each_step: bool = False

    def check(self) -> None:
        h, span = self.integstp, self.tfinal - self.tinitial
        if not np.isfinite(h) or h == 0:
            raise ValueError("INTEGSTP must be a nonzero number")
        if span != 0 and (span > 0) != (h > 0):
            raise ValueError(f"INTEGSTP ({h:g}) must have the sign of TFINAL - TINITIAL "
                             f"({span:g})")
        if self.printint < 1 or self.printint != int(self.printint):
            raise ValueError("PRINTINT must be a positive integer")
        for t in (self.tinitial, self.tfinal):
            if np.isfinite(t) and t + h == t:
                raise ValueError(f"INTEGSTP ({h:g}) is too small to advance the time from "
                                 f"T = {t:g} in floating point")

    def printed_rows(self) -> int:
        """How many rows the schedule prints (the first, every PRINTINT-th step, the last)."""
        span = self.tfinal - self.tinitial
        if span == 0 or not math.isfinite(span):
            return 1
        steps = math.ceil(span / self.integstp - 1e-9)
        return 1 + steps // self.printint + (steps % self.printint != 0)

    # steps per block of the schedule: its memory is this, whatever TFINAL is
    BLOCK = 1 << 16

    def blocks(self, size: int | None = None):
        """The schedule in blocks: (T after each step, printed?) as two arrays, T
        accumulated step by step as Autolev's loop did (np.add.accumulate adds in
        order)."""
        size = size or self.BLOCK
        t, h = self.tinitial, self.integstp
        if self._done(t):
            return
        done_steps = 0
        while True:
            times = np.add.accumulate(np.concatenate(([t], np.full(size, h))))[1:]
            finished = self._done(times)
            last = int(np.argmax(finished)) if finished.any() else None
            if last is not None:
                times = times[:last + 1]
            index = np.arange(done_steps + 1, done_steps + len(times) + 1)
            printed = index % self.printint == 0
            if last is not None:
                printed[-1] = True
            yield times, printed
            if last is not None:
                return
            t = float(times[-1])
            done_steps += len(times)

    def steps(self):
        """(T after the step, print?) for every INTEGSTP step, as Autolev's loop."""
        for times, printed in self.blocks():
            yield from zip(times.tolist(), printed.tolist())

    def print_blocks(self, size: int | None = None):
        """The print times after TINITIAL, in blocks."""
        for times, printed in self.blocks(size):
            if printed.any():
                yield times[printed]

    def final_time(self) -> float:
        """T after the last step (TINITIAL when there is none): a walk over the whole
        schedule (memory of one block)."""
        t = self.tinitial
        for times, _ in self.blocks():
            t = float(times[-1])
        return t

    def bounded_print_blocks(self, size: int | None = None):
        """(print times, end) for each block of print times: `end` is T after the last
        step once the blocks ahead show it (the last block is at most two ahead), else a
        time beyond it.  A solver bounded by `end` cannot pass the next block's last
        row (its steps are at most INTEGSTP), so it never steps past the true end, and
        no pass over the whole schedule is needed before the first step."""
        blocks = self.print_blocks(size)
        beyond = self.tfinal + 2 * self.integstp
        window = list(itertools.islice(blocks, 2))
        while window:
            ahead = next(blocks, None)
            if ahead is not None:
                window.append(ahead)
            end = float(window[-1][-1]) if ahead is None else beyond
            yield window.pop(0), end

    def _done(self, t):
        """Whether T (a number or an array) is where Autolev's loop stops."""
        h = self.integstp
        ahead = np.asarray(t) + 0.01 * h
        done = np.zeros(np.shape(t), dtype=bool)
        if self.tfinal >= self.tinitial:
            done |= ahead >= self.tfinal
        if self.tfinal <= self.tinitial:
            done |= ahead <= self.tfinal
        return done if np.ndim(t) else bool(done)

    def print_times(self) -> list[float]:
        return [self.tinitial] + [t for block in self.print_blocks() for t in block.tolist()]


class KuttaMerson:
    """Autolev's Kutta-Merson integrator (the state carries over between calls)."""

    def __init__(self, f, n: int, abserr: float, relerr: float, fresh: bool = False):
        self.f = f
        self.abserr = abserr
        self.relerr = relerr
        self.fresh = fresh
        self.hc = 0.0
        self.numcuts = 20
        self.evaluations = 0
        self.steps = 0
        self.rejected = 0
        self.stiff_t = None                 # time at which the stiffness test fired
        self._iasti = self._nonsti = 0

    def advance(self, y: np.ndarray, t: float, integstp: float) -> tuple[np.ndarray, float]:
        """Advance y from t by exactly integstp (several adaptive steps)."""
        f = self.f
        if integstp == 0:
            raise IntegrationFailure("INTEGSTP is zero", t, y)
        if self.hc * integstp < 0:
            self.hc = -self.hc
        if self.hc == 0:
            self.hc = integstp
        h = self.hc
        tt = t + h
        tfinal = t + integstp
        abserr, relerr = self.abserr, self.relerr
        f0 = f(tt - h, y)
        self.evaluations += 1
        while True:
            if tt + h == tt:
                raise IntegrationFailure(
                    f"the step size {h:.14E} is too small relative to the time {tt:.14E}; "
                    "integration halted because of numerical round-off", tt, y)
            h2, h3, h6, h8 = h * 0.5, h / 3.0, h / 6.0, h * 0.125
            ya = y + h3 * f0
            fa = f(tt - 2.0 * h3, ya)
            y1 = y + h6 * (f0 + fa)
            f1 = f(tt - 2.0 * h3, y1)
            lden = float(np.dot(y1 - ya, y1 - ya))
            f1s = f1
            y1 = y + h8 * (f0 + 3.0 * f1)
            f2 = f(tt - h2, y1)
            y1 = y + h2 * (f0 - 3.0 * f1 + 4.0 * f2)
            f1 = f(tt, y1)
            y2 = y + h6 * (f0 + 4.0 * f2 + f1)
            self.evaluations += 4
            error = np.abs(y1 - y2) * 0.2
            test = np.abs(y1) * relerr
            bad = (error >= test) & (error >= abserr)
            if bad.any():
                self.hc = h = h2
                tt = tt - h2
                self.numcuts -= 1
                self.rejected += 1
                if self.numcuts >= 0:
                    continue
                raise IntegrationFailure(
                    f"the step size has been halved too many times at T = {tt - h:.4E}",
                    tt - h, y, cuts=True)
            if not np.all(np.isfinite(y2)):
                raise IntegrationFailure(f"the state is not finite at T = {tt:.6g}", tt - h, y)
            self.steps += 1
            if lden > 0:
                self._stiffness(abs(h) * math.sqrt(float(np.dot(f1s - fa, f1s - fa)) / lden),
                                tt)
            double = not np.any((64.0 * error > test) & (64.0 * error > abserr))
            y = y2
            if double and abs(h + h) <= abs(integstp) and abs(tt + h + h) <= abs(tfinal):
                self.hc = h = h + h
                self.numcuts += 1
            if tt == tfinal:
                return y, tfinal
            tt = tt + h
            if (h > 0 and tt > tfinal - 0.1 * h) or (h < 0 and tt < tfinal - 0.1 * h):
                h = tfinal - (tt - h)
                tt = tfinal
            if self.fresh:
                f0 = f(tt - h, y)
                self.evaluations += 1
            else:
                f0 = f1

    def steps_state(self) -> cloop.KuttaMersonState:
        """Where the stepping stands, for the compiled loop to go on from."""
        return cloop.KuttaMersonState(self.hc, self.numcuts, self._iasti, self._nonsti,
                                      math.nan if self.stiff_t is None else self.stiff_t)

    def _stiffness(self, hlamb: float, t: float) -> None:
        """loop.c's al_stiff_count with Kutta-Merson's limit."""
        if hlamb > 1.75:
            self._nonsti = 0
            self._iasti += 1
            if self._iasti >= 15 and self.stiff_t is None:
                self.stiff_t = t
        else:
            self._nonsti += 1
            if self._nonsti >= 6:
                self._iasti = 0


class RK45Interval:
    """scipy's RK45 from (t, y) to t_bound, started afresh, as loop.c's
    al_rk45_interval computes it: the same stages, sums and error norm, component by
    component in the same order (numpy's elementwise operations are C's; its sums and
    dot products are not, so none is used), hence the same numbers to the last bit."""

    A, B, C, E = (rk45_tableau.A, rk45_tableau.B, rk45_tableau.C, rk45_tableau.E)

    def __init__(self, f, rtol: float, atol: float, max_step: float):
        self.f, self.rtol, self.atol, self.max_step = f, rtol, atol, max_step
        self.evaluations = self.steps = self.rejected = 0

    def _f(self, t: float, y: np.ndarray) -> np.ndarray:
        self.evaluations += 1
        return np.asarray(self.f(t, y), dtype=float)

    @staticmethod
    def _rms(v: np.ndarray) -> float:
        return math.sqrt(float(np.add.accumulate(v * v)[-1]) / len(v))

    @staticmethod
    def _factor(err: float, rejected: bool) -> float:
        """loop.c's al_step_factor (a NaN error: 0.2, as C's comparisons give it)."""
        factor = 10.0 if err == 0 else 0.9 * math.pow(err, -1.0 / 5)
        if err < 1:
            factor = 10.0 if factor > 10.0 else factor
            return 1.0 if rejected and factor > 1 else factor
        return factor if factor > 0.2 else 0.2

    def _first_step(self, t: float, y, f0, t_bound: float) -> float:
        length, sign = abs(t_bound - t), 1.0 if t_bound >= t else -1.0
        if length == 0.0:
            return 0.0
        scale = self.atol + np.abs(y) * self.rtol
        d0, d1 = self._rms(y / scale), self._rms(f0 / scale)
        h0 = 1e-6 if d0 < 1e-5 or d1 < 1e-5 else 0.01 * d0 / d1
        h0 = length if h0 > length else h0
        f1 = self._f(t + h0 * sign, y + h0 * sign * f0)
        d2 = self._rms((f1 - f0) / scale) / h0
        if d1 <= 1e-15 and d2 <= 1e-15:
            h1 = 1e-6 if 1e-6 > h0 * 1e-3 else h0 * 1e-3
        else:
            h1 = math.pow(0.01 / (d1 if d1 > d2 else d2), 1.0 / 5)
        h = 100 * h0
        h = h1 if h1 < h else h
        h = length if length < h else h
        return self.max_step if self.max_step < h else h

    def __call__(self, t: float, y: np.ndarray, t_bound: float) -> np.ndarray:
        """The state at t_bound; IntegrationFailure as the compiled loop's."""
        A, B, C, E = self.A, self.B, self.C, self.E
        n = len(y)
        sign = 1.0 if t_bound >= t else -1.0
        K = [self._f(t, y)] + [None] * 6
        h_abs = self._first_step(t, y, K[0], t_bound)
        while t != t_bound:
            min_step = 10 * abs(math.nextafter(t, sign * math.inf) - t)
            h_abs = self.max_step if h_abs > self.max_step else \
                min_step if h_abs < min_step else h_abs
            rejected = False
            while True:
                if h_abs < min_step:
                    raise IntegrationFailure(
                        f"RK45 failed at T = {t:.6g}: Required step size is less than "
                        "spacing between numbers.", t, y)
                t_new = t + h_abs * sign
                if sign * (t_new - t_bound) > 0:
                    t_new = t_bound
                h = t_new - t
                h_abs = abs(h)
                for s in range(1, 6):
                    acc = np.zeros(n)
                    for j in range(s):
                        acc = acc + K[j] * A[s * 6 + j]
                    K[s] = self._f(t + C[s] * h, y + acc * h)
                acc = np.zeros(n)
                for s in range(6):
                    acc = acc + K[s] * B[s]
                y_new = y + h * acc
                K[6] = self._f(t + h, y_new)
                acc = np.zeros(n)
                for s in range(7):
                    acc = acc + K[s] * E[s]
                a, b = np.abs(y), np.abs(y_new)
                q = acc * h / (self.atol + np.where(a > b, a, b) * self.rtol)
                err = math.sqrt(float(np.add.accumulate(q * q)[-1]) / n)
                h_abs *= self._factor(err, rejected)
                if err < 1:
                    break
                rejected = True
                self.rejected += 1
            self.steps += 1
            if not np.all(np.isfinite(y_new)):
                raise IntegrationFailure(f"the state is not finite at T = {t + h:.6g}", t, y)
            y, K[0], t = y_new, K[6], t_new
        return y


@dataclass(frozen=True)
class Integration:
    """One integration of y' = f(t, y) on `schedule` with `integrator` to ABSERR and
    RELERR, on_row(t, y) taking each printed row.

    `progress`: the Progress line it updates.  `loop`: a CompiledLoop of the same
    right-hand side, in which the integrators it runs (Integrator.in_loop) then run
    (the same steps; DOP853's and RK45's sums in C differ from scipy's at rounding
    level).  `on_stiff(t, hlamb)`: called when the compiled loop finds the equations
    stiff at time t for an integrator that switches then (DOP853): the integrator to go
    on with from there (scipy's), or None (the same method goes on, scipy's).
    `loop_when_built()`: while the loop is being compiled, it or None (not yet); an
    integrator that hands over (Kutta-Merson) steps in Python until it is there, then
    goes on in C from the same state and step.  `on_rows(times, states)`: takes the
    compiled loop's rows a slice at a time, in place of on_row for each."""

    f: Callable
    schedule: Schedule
    integrator: Integrator
    abserr: float
    relerr: float
    on_row: Callable
    progress: Progress | None = None
    loop: cloop.CompiledLoop | None = None
    on_stiff: Callable | None = None
    loop_when_built: Callable | None = None
    on_rows: Callable | None = None

    def run(self, y0: np.ndarray) -> dict:
        """Integrate from y0 at TINITIAL; its stats (method, evaluations, steps, ...).
        Raises IntegrationFailure (after the rows up to then were given)."""
        schedule = self.schedule
        schedule.check()
        y = np.array(y0, dtype=float)
        t = schedule.tinitial
        stats = {"method": self.integrator.name, "evaluations": 0, "steps": 0}
        if not np.all(np.isfinite(self.f(t, y))):
            raise IntegrationFailure(f"the derivatives are not finite at T = {t:.6g}", t, y)
        self.on_row(t, y)
        if self.loop is not None and self.integrator.in_loop(schedule):
            return _integrate_compiled(self, y)
        if self.loop_when_built is not None and self.integrator.hands_over(schedule):
            return _integrate_until_compiled(self, y, t, stats)
        return _integrate_python(self, y, t, stats)


def integrate(f, y0: np.ndarray, schedule: Schedule, method: str, abserr: float,
              relerr: float, on_row, progress: Progress | None = None, loop=None,
              on_stiff=None, loop_when_built=None, on_rows=None) -> dict:
    """Integration.run with the integrator given by name (ValueError for an unknown
    one) and the other parts one by one (Integration says what each is)."""
    return Integration(f, schedule, integrator_named(method), abserr, relerr, on_row,
                       progress, loop, on_stiff, loop_when_built, on_rows).run(y0)


def _integrate_python(run: Integration, y, t, stats) -> dict:
    schedule = run.schedule
    if run.integrator.kutta_merson:
        km = KuttaMerson(run.f, len(y), run.abserr, run.relerr, schedule.fresh_derivatives)
        for t_next, printed in schedule.steps():
            y = _km_step(km, y, t, schedule.integstp, stats)
            t = t_next                     # Autolev's accumulated T
            if printed:
                run.on_row(t, y)
            if run.progress is not None:
                run.progress.update(t)
        return stats
    if schedule.restart_each_step:
        return _scipy_each_step(run, y, t, stats)
    return _scipy_rows(run, y, t, schedule.print_blocks(), schedule.final_time(), stats)


def _km_step(km: KuttaMerson, y, t: float, integstp: float, stats: dict) -> np.ndarray:
    """One INTEGSTP step of Kutta-Merson in Python, its counts in `stats`."""
    try:
        y, _ = km.advance(y, t, integstp)
    finally:
        stats["evaluations"] = km.evaluations
        stats["steps"] = km.steps
        stats["rejected"] = km.rejected
        if km.stiff_t is not None:
            stats["stiff_t"] = km.stiff_t
    return y


def _integrate_until_compiled(run: Integration, y, t, stats) -> dict:
    """Kutta-Merson, or RK45 afresh over each step (Autolev's Matlab loop), in Python
    while the compiled loop is built, then the loop from the same T and state
    (Kutta-Merson's step too: the back ends give the same numbers; RK45 starts each
    step anew, its sums in C at rounding level from scipy's).  stats["python_until"]:
    the T where C took over, when Python took a step; stats["python_only"]: it never
    did."""
    schedule = run.schedule
    km = KuttaMerson(run.f, len(y), run.abserr, run.relerr, schedule.fresh_derivatives) \
        if run.integrator.kutta_merson else None
    blocks = schedule.blocks()
    for times, printed in blocks:
        for k, (t_next, shown) in enumerate(zip(times.tolist(), printed.tolist())):
            loop = run.loop_when_built()
            if loop is not None:
                rest = itertools.chain([(times[k:], printed[k:])], blocks)
                more = _integrate_compiled(
                    replace(run, loop=loop, on_stiff=None), y, t0=t, stepped_blocks=rest,
                    steps_state=km.steps_state() if km is not None else None)
                for count in ("evaluations", "steps", "rejected"):
                    if count in more or count in stats:
                        more[count] = more.get(count, 0) + stats.get(count, 0)
                return dict(more, python_until=t) if stats["evaluations"] else more
            if km is not None:
                y = _km_step(km, y, t, schedule.integstp, stats)
            else:
                y = _rk45_interval(run, y, t, t_next, stats)
            t = t_next
            if shown:
                run.on_row(t, y)
            if run.progress is not None:
                run.progress.update(t)
    return dict(stats, python_only=True)


def _scipy_method(name: str):
    """scipy's public solver class of that name (RK45, DOP853, Radau, BDF, LSODA, RK23)."""
    import scipy.integrate   # 0.14 s to import: only runs with a scipy method pay it
    return getattr(scipy.integrate, name)


def _scipy_each_step(run: Integration, y, t, stats) -> dict:
    """A scipy solver started afresh from (T, y) to T + INTEGSTP, step after step
    (RK45 as the compiled loop computes it)."""
    for t_next, printed in run.schedule.steps():
        y = _rk45_interval(run, y, t, t_next, stats) if run.integrator.loop_afresh_only \
            else _scipy_interval(run, y, t, t_next, stats)
        t = t_next                         # Autolev's accumulated T
        if printed:
            run.on_row(t, y)
        if run.progress is not None:
            run.progress.update(t)
    return stats


def _rk45_interval(run: Integration, y, t, t_next, stats) -> np.ndarray:
    """The state at t_next from RK45 started afresh at (t, y), as the compiled loop."""
    step = RK45Interval(run.f, run.relerr, run.abserr, abs(run.schedule.integstp))
    try:
        return step(t, np.array(y, dtype=float), t_next)
    finally:
        stats["evaluations"] += step.evaluations
        stats["steps"] += step.steps
        stats["rejected"] = stats.get("rejected", 0) + step.rejected


def _scipy_interval(run: Integration, y, t, t_next, stats) -> np.ndarray:
    """The state at t_next from a scipy solver started afresh at (t, y)."""
    name = run.integrator.scipy_name
    solver = _scipy_method(name)(run.f, t, y, t_next, max_step=abs(run.schedule.integstp),
                                 rtol=run.relerr, atol=run.abserr)
    try:
        while solver.status == "running":
            _step(solver, name, stats)
    finally:
        stats["evaluations"] += solver.nfev
    return solver.y.copy()


def _step(solver, name: str, stats: dict) -> None:
    """One step of a scipy solver; IntegrationFailure when it fails or leaves the
    finite numbers."""
    message = solver.step()
    stats["steps"] += 1
    if solver.status == "failed":
        raise IntegrationFailure(f"{name} failed at T = {solver.t:.6g}: {message}",
                                 solver.t, solver.y)
    if not np.all(np.isfinite(solver.y)):
        raise IntegrationFailure(f"the state is not finite at T = {solver.t:.6g}",
                                 solver.t_old, solver.dense_output()(solver.t_old))


def _scipy_rows(run: Integration, y, t, blocks, t_end, stats) -> dict:
    """Rows at the print times of `blocks` (arrays of times after t, up to t_end) from
    a scipy solver started at (t, y) and bounded by t_end (scipy's solvers take their
    end once, at the start)."""
    if t_end == t:
        return stats
    name = run.integrator.scipy_name
    solver = _scipy_method(name)(run.f, t, y, t_end, max_step=abs(run.schedule.integstp),
                                 rtol=run.relerr, atol=run.abserr)
    direction = 1 if t_end >= t else -1
    for times in blocks:
        k = 0
        while k < len(times):
            if solver.status == "finished":    # the end reached exactly: the rest coincide
                for tk in times[k:].tolist():
                    run.on_row(tk, solver.y.copy())
                break
            try:
                _step(solver, name, stats)
            finally:
                stats["evaluations"] = solver.nfev
            interp = None
            while k < len(times) and (times[k] - solver.t) * direction <= 0:
                tk = float(times[k])
                if tk == solver.t:
                    yk = solver.y.copy()
                else:
                    interp = interp or solver.dense_output()
                    yk = interp(tk)
                run.on_row(tk, yk)
                k += 1
            if run.progress is not None:
                run.progress.update(solver.t)
    return stats


def _integrate_compiled(run: Integration, y, t0=None, stepped_blocks=None,
                        steps_state=None) -> dict:
    """The schedule in C; a stepped integrator (Integrator.stepped) from `t0` over
    `stepped_blocks` (the schedule's blocks from there) in `steps_state`, when Python
    stepped until then."""
    schedule, integrator = run.schedule, run.integrator
    t0 = schedule.tinitial if t0 is None else t0
    opts = {"t0": t0, "rtol": run.relerr, "atol": run.abserr, "integstp": schedule.integstp,
            "max_step": abs(schedule.integstp), "fresh": schedule.fresh_derivatives}
    if integrator.stepped:
        blocks = ((times, printed, None) for times, printed in
                  (schedule.blocks() if stepped_blocks is None else stepped_blocks))
    else:
        blocks = ((times, None, end) for times, end in schedule.bounded_print_blocks())

    def row_by_row(ts, rows):
        for tk, yk in zip(ts.tolist(), rows):
            run.on_row(tk, yk)

    out = run.loop.run(integrator.name, y, blocks, opts, run.on_rows or row_by_row,
                       run.progress, stiff_stop=run.on_stiff is not None,
                       steps_state=steps_state)
    stats = dict(out["stats"], method=integrator.name, compiled=True)
    r, tf, hf = out["status"], out["fail_t"], out["fail_h"]
    if out["stiff_t"] == out["stiff_t"]:
        stats["stiff_t"] = out["stiff_t"]
    if r == cloop.DONE:
        return stats
    if r == cloop.STIFF:
        switch = run.on_stiff(out["stiff_t"], out["hlamb"])
        if switch is None:       # go on with the same method (scipy's, from the same state)
            switch = integrator
        stats["switched_to"] = switch.name
        more = {"method": switch.name, "evaluations": 0, "steps": 0}
        rest = itertools.chain([out["rest"]], (times for times, _, _ in blocks))
        _scipy_rows(replace(run, integrator=switch), out["y"], out["t"], rest,
                    schedule.final_time(), more)
        stats["evaluations"] += more["evaluations"]
        stats["steps"] += more["steps"]
        return stats
    y_last = out["y"]
    if r == cloop.SINGULAR:
        raise IntegrationFailure(f"the mass matrix is singular at T = {tf:.6g}", tf,
                                 run.loop.yfail)
    if r == cloop.CUTS:
        raise IntegrationFailure(
            f"the step size has been halved too many times at T = {tf:.4E}", tf, y_last,
            cuts=True)
    if r == cloop.SMALL_STEP:
        if integrator.kutta_merson:
            raise IntegrationFailure(
                f"the step size {hf:.14E} is too small relative to the time {tf:.14E}; "
                "integration halted because of numerical round-off", tf, y_last)
        raise IntegrationFailure(f"{integrator.scipy_name} failed at T = {tf:.6g}: "
                                 "Required step size is less than spacing between "
                                 "numbers.", tf, y_last)
    if r == cloop.NONFINITE:
        # Kutta-Merson and RK45 name the time they stepped to, as their Python loops
        shown = tf + hf if integrator.stepped else tf
        raise IntegrationFailure(f"the state is not finite at T = {shown:.6g}", tf, y_last)
    raise IntegrationFailure(f"the compiled integrator stopped with code {r}", out["t"],
                             y_last)


def integrate_projected(run: Integration, y0, project) -> dict:
    """The integration from print time to print time, projecting the state at each
    (`project(t, x)`: the state on the constraints; its `largest_correction` is
    reported); neither its progress nor a loop being built goes to the segments."""
    schedule = run.schedule
    schedule.check()
    y = np.array(y0, dtype=float)
    run.on_row(schedule.tinitial, y)
    stats = {"method": run.integrator.name, "evaluations": 0, "steps": 0,
             "projected": True}
    a = schedule.tinitial
    for b in (t for block in schedule.print_blocks() for t in block.tolist()):
        got = []
        seg = Schedule(a, b, schedule.integstp, 10 ** 9, schedule.fresh_derivatives,
                       schedule.restart_each_step)
        segment = replace(run, schedule=seg, on_row=lambda t, yy: got.append(np.array(yy)),
                          progress=None, loop_when_built=None, on_rows=None)
        try:
            st = segment.run(y)
        except IntegrationFailure:
            stats["largest_correction"] = project.largest_correction
            raise
        stats["evaluations"] += st.get("evaluations", 0)
        stats["steps"] += st.get("steps", 0)
        for key in ("stiff_t", "switched_to", "compiled"):
            if key in st and key not in stats:
                stats[key] = st[key]
        y = project(b, got[-1])
        run.on_row(b, y)
        a = b
        if run.progress is not None:
            run.progress.update(b)
    stats["largest_correction"] = project.largest_correction
    return stats


def failure_basis(exc: IntegrationFailure, state_names: list) -> str:
    """Autolev's message for a failed integration, and the state where it stopped."""
    state = ", ".join(f"{n} = {v:.6g}" for n, v in zip(state_names, exc.y))
    return f"Numerical integration failed to converge: {exc}; the state there: {state}"
