#!/usr/bin/env python3
"""An independent oracle for models nobody wrote: random multibody models, each written
both as Autolev text and as a sympy.physics.mechanics KanesMethod built directly from the
same description (never through autolev's own exports), and their state derivatives
compared at random states and times.

    python bench/oracle.py --models 500 --seed 1 [--jobs 2] [--timeout 300]
    python bench/oracle.py --replay 1:17      # one case: its .al, its sympy script, values

Each case (seed S, index i) draws from `random.Random(S*1_000_003 + i)` a description
(bench/oracle_models.py) of the family i cycles to:

  planar          chains and trees of 1-4 bodies and particles in a plane: SIMPROT about
                  +-3, q' = u with W implied or written out, slides along the parent's
                  axes; velocities by V2PTS/V1PT, by DT(P_NO_X>, N) or left to autolev
  spatial         the same in space: SIMPROT about +-1, +-2, +-3 or a vector of the
                  parent, products of inertia
  dircos          DIRCOS(A, B, BODYijk | SPACEijk, ...) of all 24 sequences, q' = u
  kindiffs        DIRCOS with KINDIFFS: the speeds are W_B_A>'s measure numbers in the
                  child's or the parent's frame; Euler parameters (EULER) too
  holonomic       one or two differentiated holonomic constraints (a point's velocity
                  along a direction fixed in N), CONSTRAIN(DEPENDENT[...])
  knife_edge      a sleigh: a point's velocity along a direction fixed in its body is zero
  rolling_disc    a disc rolling without slip (contact speeds dependent), links on it
  aux_reaction    auxiliary speeds zero in the motion (AUXILIARY[k] = UAk, a joint's slack
                  speed, or a root's slide speeds), KANE(F, ...) for the reactions, now and
                  then with a DEPENDENT constraint through a slack speed (the fourbar's
                  pattern); the reactions are compared too (OUTPUT F against sympy's
                  auxiliary_eqs)
  aux_constraint  CONSTRAIN(AUXILIARY[U]) of a point's velocity along a direction fixed in
                  N, KANE(F) for the constraint force: Autolev solves the constraint for U,
                  so the oracle's motion is that of the constrained system (u dependent),
                  and F is the multiplier: the unconstrained system's Kane equations
                  M u' = f + J^T F hold at the constrained u' (issue 49 item 9)

Every family has gravity (mostly), and forces and torques on a point or frame alone or as
action and reaction (FORCE(P/Q, v), TORQUE(A/B, v)) whose measure numbers are constants
times 1, sin q, cos q, u, T, cos T or q*u, and springs with dampers between points.

Our side loads the .al (autolev.load), prepares its CODE DYNAMICS command and evaluates
`system.derivatives(t, x)`; the constants are the INPUT values, given to the sympy side
too.  Random states draw every coordinate and speed from its range (angles within 1 rad,
the middle angle of a symmetric sequence within 0.4..1.4 rad, Euler parameters of unit
length); a state where sympy's mass matrix or constraint matrix is ill-conditioned or a
spring's length nearly vanishes is drawn again.  A component agrees within 1e-9 relative
(scaled by max(1, |value|)).

Outcomes per case: agree; DISAGREE; refused (autolev said why: an AutolevError or a
model error with its message); internal (any other exception: a traceback); our-timeout
and oracle-timeout (the case's time limit ran out on that side); oracle-error (this
script's own side failed: a bug here); singular (the generator drew a degenerate model:
sympy finds its constraints singular, or no regular state, or autolev refused a model
whose states sympy finds singular too).  Each case
runs in a worker process (--jobs of them), killed at the time limit.  Exit status 1 on
any disagreement, internal error, our-side timeout or oracle error.
"""
from __future__ import annotations

import argparse
import multiprocessing
import multiprocessing.connection
import os
import random
import shutil
import sys
import tempfile
import time
import traceback
import warnings
from collections import Counter, defaultdict
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import oracle_models as models  # noqa: E402

FAMILIES = list(models.FAMILIES)
TOLERANCE = 1e-9
STATES = 3
DRAWS = 40                 # attempts at a regular state, per state wanted


def case_rng(seed: int, index: int) -> random.Random:
    return random.Random(seed * 1_000_003 + index)


@dataclass
class Case:
    seed: int
    index: int
    family: str
    description: models.Description
    autolev: str
    sympy: str


def make_case(seed: int, index: int, family: str | None = None) -> Case:
    family = family or FAMILIES[index % len(FAMILIES)]
    return described_case(seed, index, models.generate(family, case_rng(seed, index)))


def described_case(seed: int, index: int, d: models.Description) -> Case:
    title = f"oracle case {seed}:{index} ({d.family})"
    return Case(seed, index, d.family, d, models.autolev_text(d, title),
                models.sympy_script(d, title))


@dataclass
class Outcome:
    seed: int
    index: int
    family: str
    status: str            # agree, disagree, refused, internal, our-timeout, ...
    detail: str = ""
    error: float = 0.0     # the largest relative difference
    samples: list = field(default_factory=list)   # (t, state, ours, theirs) per state
    our_seconds: float = 0.0
    oracle_seconds: float = 0.0


# -- our side -------------------------------------------------------------------------------

class OurSide:
    """The .al loaded and its CODE DYNAMICS command prepared."""

    def __init__(self, text: str, folder: Path):
        import autolev
        from autolev.runtime.numerics.prepare import prepare_command
        path = folder / "case.al"
        path.write_text(text)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            model = autolev.load(path)
            self.system = prepare_command(model.snapshot_for(model.code_commands[0]),
                                          model.code_commands[0]).system
        self.states = [str(s) for s in self.system.states]
        self.outputs = [str(c.expr) for cols in self.system.files for c in cols]

    def rates(self, t: float, state: dict) -> dict:
        x = np.array([state[n] for n in self.states], dtype=float)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            xdot = self.system.derivatives(t, x)
            out = self.system.outputs(t, x, xdot)
        values = dict(zip(self.states, xdot))
        values.update({n: v for n, v in zip(self.outputs, out) if n != "t"})
        return values


def refusal(exc: BaseException) -> bool:
    """An error autolev reports with a diagnostic or a message of its own (not a bug)."""
    from autolev import AutolevError
    from autolev.engine.errors import AutolevModelError
    return isinstance(exc, (AutolevError, AutolevModelError))


# -- the oracle side ------------------------------------------------------------------------------

class OurFailure(Exception):
    """Our side failed while evaluating (its cause is the exception chained)."""


class Singular(Exception):
    """sympy found the model's constraints singular for every state."""


class OracleSide:
    """The sympy script executed; its equations as numeric functions."""

    def __init__(self, script: str):
        import sympy as sm
        import sympy.physics.mechanics as me
        ns: dict = {}
        try:
            exec(compile(script, "<oracle sympy script>", "exec"), ns)
        except sm.matrices.exceptions.NonInvertibleMatrixError as exc:
            # KanesMethod solving the velocity constraints for the dependent speeds
            raise Singular(f"sympy: {exc}") from None
        t = me.dynamicsymbols._t
        kane = ns["kane"]
        self.names = {k: v for k, v in ns["names"].items()}
        coordinates, speeds = list(ns["coordinates"]), list(ns["speeds"])
        dependent, auxiliary = list(ns["dependent"]), list(ns["auxiliary"])
        unknowns = list(ns["unknowns"])
        self.state = [self.names[s] for s in coordinates + speeds]
        self.full = [self.names[s] for s in list(kane.q) + list(kane.u)]
        self.dependent = [self.names[s] for s in dependent]
        constants = ns["constants"]
        self.constant_values = [float(v) for v in constants.values()]
        given = coordinates + speeds
        x = [sm.Dummy(self.names[s]) for s in given]
        ud = [sm.Dummy(self.names[s]) for s in dependent]
        accelerations = [sm.Dummy(self.names[s] + "'") for s in speeds + dependent]
        fs = [sm.Dummy(self.names[s]) for s in unknowns]
        tt = sm.Dummy("t")
        # derivatives first: xreplace matches the whole u(t).diff(t) before u(t)
        plain = dict(zip([s.diff(t) for s in speeds + dependent], accelerations))
        plain.update(zip(given, x))
        plain.update(zip(dependent, ud))
        plain.update(dict.fromkeys([a.diff(t) for a in auxiliary] + auxiliary, 0))
        plain.update(zip(unknowns, fs))
        plain[t] = tt
        arguments = [tt, x, ud, list(constants)]

        def numeric(exprs, extra=()):
            exprs = [sm.Matrix(e).xreplace(plain) for e in exprs]
            left = set().union(*(me.find_dynamicsymbols(e) for e in exprs))
            if left:
                raise RuntimeError(f"the oracle's equations still hold {sorted(map(str, left))}")
            return sm.lambdify(arguments + list(extra), exprs, modules="numpy", cse=True)

        no_force = dict.fromkeys(unknowns, 0)
        self.equations = numeric([kane.mass_matrix_full.xreplace(no_force),
                                  kane.forcing_full.xreplace(no_force)])
        self.constraint = None
        if dependent:
            vc = sm.Matrix(ns["velocity_constraints"])
            self.constraint = numeric([vc.jacobian(dependent),
                                       vc.xreplace(dict.fromkeys(dependent, 0))])
        self.guards = numeric([sm.Matrix(ns["guards"] or [1])])
        self.unknowns = [self.names[f] for f in unknowns] if auxiliary or "free" in ns else []
        self.accelerations = [self.names[s] for s in speeds + dependent]
        self.forces = self.multipliers = None
        if auxiliary and unknowns:
            aux = sm.Matrix(kane.auxiliary_eqs)
            self.forces = numeric([aux.jacobian(unknowns), aux.xreplace(no_force)],
                                  extra=[accelerations, fs])
        elif self.unknowns:
            free = ns["free"]
            self.multipliers = numeric([free.mass_matrix, free.forcing.jacobian(unknowns),
                                        free.forcing.xreplace(no_force)])

    def dependent_speeds(self, t: float, state: dict) -> np.ndarray | None:
        """The dependent speeds where the constraints hold (None: ill-conditioned)."""
        if self.constraint is None:
            return np.zeros(0)
        x = [state[n] for n in self.state]
        a, b = (np.asarray(m, dtype=float) for m in
                self.constraint(t, x, np.zeros(len(self.dependent)), self.constant_values))
        if not np.all(np.isfinite(a)) or np.linalg.cond(a) > 1e6:
            return None
        return np.linalg.solve(a, -b.ravel())

    def rates(self, t: float, state: dict) -> dict | None:
        """{name: derivative} of the full state (and the KANE unknowns), or None where the
        state is too near a singular one."""
        x = [state[n] for n in self.state]
        guards = np.asarray(self.guards(t, x, np.zeros(len(self.dependent)),
                                        self.constant_values)[0], dtype=float)
        if np.any(np.abs(guards) < 0.05):
            return None
        ud = self.dependent_speeds(t, state)
        if ud is None:
            return None
        mass, forcing = (np.asarray(m, dtype=float) for m in
                         self.equations(t, x, ud, self.constant_values))
        if not np.all(np.isfinite(mass)) or np.linalg.cond(mass) > 1e8:
            return None
        xdot = np.linalg.solve(mass, forcing.ravel())
        values = dict(zip(self.full, xdot))
        accelerations = [values[n] for n in self.accelerations]
        if self.forces is not None:
            zeros = np.zeros(len(self.unknowns))
            a, b = (np.asarray(m, dtype=float) for m in
                    self.forces(t, x, ud, self.constant_values, accelerations, zeros))
            values.update(zip(self.unknowns, np.linalg.solve(a, -b.ravel())))
        if self.multipliers is not None:
            mass, along, rest = (np.asarray(m, dtype=float) for m in
                                 self.multipliers(t, x, ud, self.constant_values))
            excess = mass @ np.array(accelerations) - rest.ravel()
            forces = np.linalg.lstsq(along, excess, rcond=None)[0]
            values.update(zip(self.unknowns, forces))
        return values


# -- one case --------------------------------------------------------------------------------

def draw_state(d: models.Description, names: list, rng: random.Random) -> dict:
    state = {n: rng.uniform(*d.ranges[n]) for n in names if n in d.ranges}
    for group in d.quaternions:
        v = np.array([rng.gauss(0, 1) for _ in group])
        state.update(zip(group, v / np.linalg.norm(v)))
    return state


def regular_state(case: Case, oracle: OracleSide, rng: random.Random) -> bool:
    """Whether the oracle finds a state where its equations are regular."""
    for _ in range(DRAWS):
        state = draw_state(case.description, oracle.state, rng)
        if oracle.rates(rng.uniform(0.0, 2.0), state) is not None:
            return True
    return False


def compare(case: Case, ours: OurSide, oracle: OracleSide, rng: random.Random,
            outcome: Outcome) -> None:
    if sorted(ours.states) != sorted(oracle.state):
        outcome.status = "disagree"
        outcome.detail = (f"states differ: ours {ours.states}, "
                          f"the oracle's {sorted(oracle.state)}")
        return
    compared = ours.states + [n for n in oracle.unknowns if n in ours.outputs]
    found = 0
    for _ in range(STATES * DRAWS):
        if found == STATES:
            break
        state = draw_state(case.description, ours.states, rng)
        t = rng.uniform(0.0, 2.0)
        theirs = oracle.rates(t, state)
        if theirs is None:
            continue
        found += 1
        try:
            mine = ours.rates(t, state)
        except Exception as exc:        # noqa: BLE001 -- told apart by the caller
            raise OurFailure() from exc
        errors = {n: abs(mine[n] - theirs[n]) / max(1.0, abs(theirs[n])) for n in compared}
        errors = {n: (e if np.isfinite(e) else np.inf) for n, e in errors.items()}
        worst = max(errors.values(), default=0.0)
        outcome.samples.append((t, state, {n: float(mine[n]) for n in compared},
                                {n: float(theirs[n]) for n in compared}))
        outcome.error = max(outcome.error, worst)
    if not found:
        outcome.status = "singular"
        outcome.detail = "no regular state in the ranges drawn"
    elif outcome.error > TOLERANCE:
        outcome.status = "disagree"
        t, state, mine, theirs = outcome.samples[0]
        bad = [n for n in compared
               if not abs(mine[n] - theirs[n]) <= TOLERANCE * max(1.0, abs(theirs[n]))]
        outcome.detail = "differs in " + ", ".join(bad) + f" (max relative {outcome.error:.3g})"
    else:
        outcome.status = "agree"


def run_case(seed: int, index: int, family: str | None = None, mutate=None,
             on_phase=lambda phase: None) -> Outcome:
    """One case, both sides, compared.  `mutate(text)`: the Autolev text changed before
    our side reads it (a test that the comparison fails where it must)."""
    try:
        case = make_case(seed, index, family)
    except Exception:                   # noqa: BLE001 -- the generator's own fault
        return Outcome(seed, index, family or FAMILIES[index % len(FAMILIES)],
                       "oracle-error", traceback.format_exc())
    return check_case(case, mutate, on_phase)


def check_case(case: Case, mutate=None, on_phase=lambda phase: None) -> Outcome:
    seed, index = case.seed, case.index
    outcome = Outcome(seed, index, case.family, "agree")
    text = mutate(case.autolev) if mutate else case.autolev
    on_phase("ours")
    start = time.perf_counter()
    refused = None
    try:
        with tempfile.TemporaryDirectory(prefix="oracle-") as folder:
            ours = OurSide(text, Path(folder))
    except Exception as exc:            # noqa: BLE001 -- every failure is an outcome
        if not refusal(exc):
            outcome.status, outcome.detail = "internal", traceback.format_exc()
            outcome.our_seconds = time.perf_counter() - start
            return outcome
        refused = f"{type(exc).__name__}: {exc}"
    outcome.our_seconds = time.perf_counter() - start
    on_phase("oracle")
    start = time.perf_counter()
    try:
        oracle = OracleSide(case.sympy)
        # a model refused as singular that the oracle finds singular too is the
        # generator's doing (a constraint whose speed does not move its point)
        regular = refused is None or regular_state(case, oracle, case_rng(seed, index))
    except Singular as exc:
        outcome.oracle_seconds = time.perf_counter() - start
        outcome.status = "singular"
        outcome.detail = f"{exc}; ours {refused or 'accepted it'}"
        return outcome
    except Exception:                   # noqa: BLE001
        outcome.oracle_seconds = time.perf_counter() - start
        outcome.status, outcome.detail = "oracle-error", traceback.format_exc()
        return outcome
    outcome.oracle_seconds = time.perf_counter() - start
    if refused is not None:
        outcome.status = "refused" if regular else "singular"
        outcome.detail = refused
        return outcome
    on_phase("compare")
    try:
        compare(case, ours, oracle, case_rng(seed, index + 7_919), outcome)
    except OurFailure as failure:
        cause = failure.__cause__
        outcome.status = "refused" if refusal(cause) else "internal"
        outcome.detail = "".join(traceback.format_exception(cause))
    except Exception:                   # noqa: BLE001
        outcome.status, outcome.detail = "oracle-error", traceback.format_exc()
    return outcome


# -- workers ---------------------------------------------------------------------------------

def _worker(connection) -> None:
    while True:
        job = connection.recv()
        if job is None:
            return
        seed, index = job
        outcome = run_case(seed, index, on_phase=lambda p: connection.send(("phase", p)))
        connection.send(("done", outcome))


class Worker:
    def __init__(self, context):
        self.connection, theirs = context.Pipe()
        self.process = context.Process(target=_worker, args=(theirs,), daemon=True)
        self.process.start()
        theirs.close()
        self.job = None
        self.phase = ""
        self.started = 0.0

    def give(self, job) -> None:
        self.job, self.phase, self.started = job, "case", time.monotonic()
        self.connection.send(job)

    def stop(self) -> None:
        self.process.kill()
        self.process.join()
        self.connection.close()


def run_all(jobs_list: list, jobs: int, timeout: float, report=print) -> list:
    """Every (seed, index) in worker processes, each case killed at `timeout` seconds."""
    context = multiprocessing.get_context("fork")
    workers = [Worker(context) for _ in range(max(1, jobs))]
    pending = list(jobs_list)
    outcomes = []
    try:
        while pending or any(w.job for w in workers):
            for w in workers:
                if w.job is None and pending:
                    w.give(pending.pop(0))
            busy = [w for w in workers if w.job]
            # woken by the first time limit to run out, so no answer is taken after its limit
            first_limit = min(w.started + timeout for w in busy) - time.monotonic()
            ready = multiprocessing.connection.wait([w.connection for w in busy],
                                                    timeout=min(1.0, max(0.0, first_limit)))
            for w in busy:
                if w.connection in ready and time.monotonic() - w.started <= timeout:
                    try:
                        kind, value = w.connection.recv()
                    except EOFError:
                        kind, value = "died", None
                    if kind == "phase":
                        w.phase = value
                        continue
                    if kind == "done":
                        outcomes.append(value)
                    else:
                        # a crash of our side (a C library, say) or of this script's
                        seed, index = w.job
                        status = "internal" if w.phase == "ours" else "oracle-error"
                        outcomes.append(Outcome(seed, index, FAMILIES[index % len(FAMILIES)],
                                                status, f"the worker died ({w.phase})"))
                        workers[workers.index(w)] = Worker(context)
                        w.stop()
                    report(outcomes[-1])
                    w.job = None
                elif time.monotonic() - w.started > timeout:
                    seed, index = w.job
                    side = "our-timeout" if w.phase == "ours" else "oracle-timeout"
                    late = Outcome(seed, index, FAMILIES[index % len(FAMILIES)], side,
                                   f"over {timeout:g} s ({w.phase})")
                    spent = time.monotonic() - w.started
                    if w.phase == "ours":
                        late.our_seconds = spent
                    else:
                        late.oracle_seconds = spent
                    outcomes.append(late)
                    report(outcomes[-1])
                    w.stop()
                    workers[workers.index(w)] = Worker(context)
    finally:
        for w in workers:
            if w.job is None:
                w.connection.send(None)
            w.stop()
    return outcomes


# -- the table ---------------------------------------------------------------------------------

COLUMNS = ["agree", "disagree", "refused", "internal", "our-timeout", "oracle-timeout",
           "oracle-error", "singular"]
FAILING = {"disagree", "internal", "our-timeout", "oracle-error"}


def table(outcomes: list) -> str:
    by_family = defaultdict(Counter)
    seconds = defaultdict(lambda: [0.0, 0.0, 0])
    for o in outcomes:
        by_family[o.family][o.status] += 1
        s = seconds[o.family]
        s[0] += o.our_seconds
        s[1] += o.oracle_seconds
        s[2] += 1
    head = ["family", "cases"] + [c.upper() if c == "disagree" else c for c in COLUMNS]
    head += ["ours s/case", "oracle s/case"]
    rows = []
    for family in FAMILIES + ["all"]:
        counts = by_family[family] if family != "all" else \
            sum(by_family.values(), Counter())
        n = sum(counts.values())
        if not n:
            continue
        s = seconds[family] if family != "all" else [sum(v[0] for v in seconds.values()),
                                                     sum(v[1] for v in seconds.values()), n]
        rows.append([family, str(n)] + [str(counts[c]) for c in COLUMNS]
                    + [f"{s[0] / n:.2f}", f"{s[1] / n:.2f}"])
    widths = [max(len(r[k]) for r in rows + [head]) for k in range(len(head))]
    lines = ["  ".join(h.rjust(w) if k else h.ljust(w) for k, (h, w) in
                       enumerate(zip(head, widths)))]
    for r in rows:
        lines.append("  ".join(c.rjust(w) if k else c.ljust(w) for k, (c, w) in
                               enumerate(zip(r, widths))))
    return "\n".join(lines)


def describe(o: Outcome, full: bool = False) -> str:
    first = o.detail.strip().splitlines()[-1] if o.detail.strip() else ""
    text = (f"{o.seed}:{o.index} {o.family} {o.status} ({o.our_seconds:.1f} + "
            f"{o.oracle_seconds:.1f} s): {o.detail if full else first}")
    if o.status == "disagree" and o.samples:
        t, state, mine, theirs = o.samples[0]
        text += f"\n    at t = {t:.6g}, " + ", ".join(f"{k} = {v:.6g}" for k, v in state.items())
        for n in mine:
            text += f"\n    {n:>6}: ours {mine[n]: .12g}   oracle {theirs[n]: .12g}"
    return text


def replay(seed: int, index: int) -> int:
    case = make_case(seed, index)
    print("% ---- the Autolev model ----")
    print(case.autolev)
    print("# ---- the sympy side ----")
    print(case.sympy)
    outcome = run_case(seed, index)
    print(describe(outcome, full=True))
    print(f"ours {outcome.our_seconds:.2f} s, oracle {outcome.oracle_seconds:.2f} s")
    return 1 if outcome.status in FAILING else 0


def private_folders() -> str:
    """autolev's caches, key and state in a folder of this run's own (never the user's);
    the folder."""
    root = tempfile.mkdtemp(prefix="autolev-oracle-")
    for variable, sub in (("AUTOLEV_CACHE", "cache"), ("XDG_CONFIG_HOME", "config"),
                          ("XDG_STATE_HOME", "state")):
        path = os.path.join(root, sub)
        os.makedirs(path, mode=0o700)
        os.environ[variable] = path
    os.environ["AUTOLEV_NO_MODEL_CACHE"] = "1"
    return root


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--models", type=int, default=90, help="cases (they cycle the families)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=1, help="worker processes")
    parser.add_argument("--timeout", type=float, default=300.0, help="seconds per case")
    parser.add_argument("--family", choices=FAMILIES, help="only this family's cases")
    parser.add_argument("--replay", metavar="SEED:INDEX", help="one case, shown in full")
    parser.add_argument("--quiet", action="store_true", help="no line per case")
    args = parser.parse_args(argv)
    root = private_folders()
    try:
        return _run(args)
    finally:
        shutil.rmtree(root, ignore_errors=True)


def _run(args) -> int:
    if args.replay:
        seed, index = (int(x) for x in args.replay.split(":"))
        return replay(seed, index)
    import autolev  # noqa: F401 -- imported once, before the workers fork
    import sympy.physics.mechanics  # noqa: F401
    indices = [i for i in range(args.models)
               if args.family is None or FAMILIES[i % len(FAMILIES)] == args.family]
    start = time.perf_counter()

    def report(o: Outcome) -> None:
        if not args.quiet or o.status != "agree":
            print(describe(o), flush=True)

    outcomes = run_all([(args.seed, i) for i in indices], args.jobs, args.timeout, report)
    outcomes.sort(key=lambda o: o.index)
    print()
    print(f"seed {args.seed}: {len(outcomes)} cases in {time.perf_counter() - start:.0f} s "
          f"with {args.jobs} jobs")
    print(table(outcomes))
    return 1 if any(o.status in FAILING for o in outcomes) else 0


if __name__ == "__main__":
    sys.exit(main())
