"""What a model does with numbers: its CODE commands run, simulated, linearized and
swept (a mixin of Model).  This layer sits on the numerics, which never import it."""
from __future__ import annotations

import html
import sys
import time
import warnings
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from ..engine.errors import AutolevModelError
from .io import INTEGRATION_PARAMETERS, CodeCommand, CodeKind
from ..engine.files import safe_stem
from ..engine.options import RunOptions

if TYPE_CHECKING:
    # the run machinery (numpy, the engine) is imported where a model computes numbers:
    # forming a model, or its transcript, needs none of it
    from ..engine.results import Result
    from .numerics.snapshot import ModelSnapshot


@dataclass
class CommandRun:
    """One CODE command's run: its result, or why the model could not run it."""

    command: CodeCommand
    result: Result | None
    error: str | None
    seconds: float

    def summary(self) -> str:
        """`CODE DYNAMICS bike.c: 101 rows in 1.30 s (building 1.02 s; integrating
        0.21 s: kutta-merson, 412 steps)` (results.run_summary)."""
        from ..engine.results import run_summary
        return run_summary(self.command.kind, self.command.filename, self.result,
                           self.seconds)


@dataclass
class AnimationView:
    """A model's motion as a self-contained HTML page; shown inline in a notebook (in an
    iframe of its own, so that its script and styles stay in it)."""

    page: str
    notes: list

    def _repr_html_(self) -> str:
        return (f'<iframe srcdoc="{html.escape(self.page, quote=True)}" width="100%" '
                'height="540" style="border: 0"></iframe>')

    def save(self, path) -> Path:
        """Write the page to `path` (whole, never through a link at its name)."""
        from ..engine.outputs import write_output
        target = Path(path)
        return write_output(target.parent, target.name, self.page)


class SimulationMixin:
    def run(self, out_dir=".", verbose: bool = False, code=None, **given):
        """Perform the CODE commands (every one, or those `code` names: a name or index,
        or a list of them) with the INPUT values, as `autolev run` and `python
        model.py` do: writes Autolev's files into out_dir; returns the results.
        `verbose` reports each run on standard output and its progress on standard
        error.  `given`: options and input values, as `simulate` takes them."""
        results = []
        options = RunOptions.split(given).but(progress=sys.stderr if verbose else None)
        for done in self.run_commands(self.commands_named(code), out_dir, options=options):
            results.append(done.result)
            if verbose:
                print(done.summary()
                      + (f"\n  {done.result.failure}" if done.result.failure else "")
                      + "".join(f"\n  wrote {f}" for f in done.result.files))
        return results

    def names_a_quantity(self, name: str) -> bool:
        """Whether `name` (as --set or an override gives it: Q1, Q1', Q1P, TFINAL, T)
        is an integration parameter or a quantity of the model."""
        name = name.strip()
        if name.upper() in INTEGRATION_PARAMETERS or name.upper() in ("INTEGSTEP", "T"):
            return True         # T: the time, which a program without time reads
        primes = len(name) - len(name.upper().rstrip("P"))       # Q1PP is Q1''
        for candidate in [name] + [name[:-k] + "'" * k for k in range(1, primes + 1)]:
            try:
                self.quantity(candidate)
                return True
            except KeyError:
                continue
        return False

    def snapshot_for(self, command: CodeCommand) -> ModelSnapshot:
        """What the numerics read of the model for `command` (they never read the model
        itself): its definitions, symbols, masses, the statements before it, Kane's
        equations formed when asked, the caches of this revision."""
        place = next((k for k, c in enumerate(self.code_commands) if c is command), None)
        if place is None:
            place = "plain" if command is self.plain_dynamics() else id(command)
        from .numerics.snapshot import FormedDynamics, ModelSnapshot
        dynamics = None if self.newtonian_frame is None else FormedDynamics(
            independent_speeds=lambda: self.generalized_speeds()[0],
            equations=self.equations, mass_matrix=lambda: self.mass_matrix,
            forcing=lambda: self.forcing, mechanics=self.kane_system,
            joints=self._joints_over)
        return ModelSnapshot(
            command=command, place=place, definitions=self.defs, symbols=dict(self.info),
            outputs=self.io.outputs[:command.n_outputs],
            encoded=self.io.encoded[:command.n_encoded], units=dict(self.unit_of),
            solved_rates=self.constraints.solved_rates, solved_speeds=self.solved_speeds,
            bodies=self.registry.bodies, particles=self.registry.particles,
            dynamics=dynamics, derived=self.derived, names_a_quantity=self.names_a_quantity,
            systems_changed=self._systems_changed)

    def _joints_over(self, speeds: list):
        """The bodies as a tree of joints over `speeds` (articulated.tree), built once
        for the model's revision (and the view of its definitions) it is asked at;
        articulated.NotATree, with the reason, when they are not one."""
        from . import articulated
        kept = self.derived.table("trees of joints")     # speeds -> (tree, why not)
        key = tuple(speeds)
        if key not in kept:
            try:
                kept[key] = (articulated.tree(self.kane_system(), list(speeds)), "")
            except articulated.NotATree as exc:
                kept[key] = (None, str(exc))
        found, why_not = kept[key]
        if found is None:
            raise articulated.NotATree(why_not)
        return found

    def _systems_changed(self) -> None:
        """A numeric system was built or extended (Jacobians added): the model's entry in
        the cache of built models is written again once the work is done (keep_built)."""
        if self.loaded is not None and self.loaded.keeper is not None:
            self.loaded.keeper.added()

    def keep_built(self) -> None:
        """The numeric systems built so far go to the cache of built models (the loader's
        ModelKeeper), once the work that built them is done."""
        if self.loaded is not None and self.loaded.keeper is not None:
            self.loaded.keeper.flush(self)

    def commands_named(self, code=None) -> list[CodeCommand]:
        """The CODE commands `code` names (see code_command; a list names several, in
        the model's order), or all of them."""
        if code is None:
            return list(self.code_commands)
        names = code if isinstance(code, (list, tuple)) else [code]
        picked = {id(self.code_command(name)) for name in names}
        return [c for c in self.code_commands if id(c) in picked]

    def run_commands(self, commands, out_dir=None, keep_going: bool = False,
                     options: RunOptions = RunOptions()) -> Iterator[CommandRun]:
        """Run each command in turn (the one pipeline behind run, `autolev run` and
        `python model.py`): one CommandRun per command as it finishes.  A command the
        model cannot run stops the rest, or with `keep_going` is reported in its
        CommandRun's `error`."""
        from ..engine.results import command_error
        from .numerics.run import run_command
        try:
            for command in commands:
                start = time.monotonic()
                try:
                    result = run_command(self.snapshot_for(command), out_dir, options)
                except AutolevModelError as exc:
                    if not keep_going:
                        raise
                    yield CommandRun(command, None, command_error(command.kind, exc),
                                     time.monotonic() - start)
                    continue
                yield CommandRun(command, result, None, time.monotonic() - start)
        finally:
            self.keep_built()

    def code_command(self, which):
        """A CODE command by its file name (any case, the extension optional: "bike.c",
        "BIKE") or its 0-based index among the model's CODE commands."""
        commands = list(self.code_commands)
        if isinstance(which, int) and not isinstance(which, bool):
            if 0 <= which < len(commands):
                return commands[which]
        else:
            wanted = str(which).strip().lower()
            for c in commands:
                if c.filename.lower() == wanted:
                    return c
            found = [c for c in commands if safe_stem(c.filename).lower() == wanted]
            if len(found) == 1:
                return found[0]
        shown = ", ".join(f"{k}: {c.filename}" for k, c in enumerate(commands)) or "none"
        raise AutolevModelError(f"no CODE command {which!r} (the model's: {shown})")

    def simulate(self, *, out_dir=None, code=None, **given):
        """Run the model's CODE command (`code`, see code_command; default: its first
        CODE DYNAMICS or ODE, else its first CODE command, else a plain simulation) with
        its INPUT values; files are written only when out_dir is given.  `given`: the
        options of a run, by their names (RunOptions: method, backend, infile,
        specified, progress, compiled, constraints, quirks, keep_rows, missing_values,
        overwrite), and input values by any other name (NAME=value in the quantity's
        unit, TFINAL=...; a number for a specified quantity the model leaves undefined
        is its value).  `specified` gives those quantities a function f(t) or f(t, x),
        called at every evaluation, or a number or sympy expression, compiled into the
        equations as if the model had defined it before its CODE command.
        `constraints`: configuration constraints g(q) (sympy expressions, e.g.
        `al.dot(P5.pos_from(NO), N.x)` for a closed loop) kept at their initial values
        by projecting the coordinates onto them at every print time (closed loops
        drift off them otherwise: only the velocity constraints are in the equations).
        Returns a Result (times, states and outputs as numpy arrays)."""
        from .numerics.run import run_command
        try:
            return run_command(self.snapshot_for(self.command_to_run(code)), out_dir,
                               RunOptions.split(given))
        finally:
            self.keep_built()


    def command_to_run(self, code=None) -> CodeCommand:
        """The CODE command `code` names, else the first CODE DYNAMICS or ODE, else the
        first CODE command, else a plain simulation of the model as it stands."""
        command = self.code_command(code) if code is not None else None
        for c in self.code_commands if command is None else ():
            if c.kind.integrates:
                command = c
                break
        if command is None and self.code_commands:
            command = self.code_commands[0]
        return command if command is not None else self.plain_dynamics()

    def command_to_linearize(self, code=None) -> CodeCommand:
        """The CODE command `code` names, else the first CODE DYNAMICS, else the model's
        equations as they stand."""
        if code is not None:
            return self.code_command(code)
        return next((c for c in self.code_commands if c.kind is CodeKind.DYNAMICS),
                    None) or self.plain_dynamics()

    def animate(self, result=None, frames: int | None = None, **given) -> AnimationView:
        """The motion of a CODE DYNAMICS run as the HTML view `autolev animate` writes (a
        stick figure to rotate, a time slider), shown inline in a notebook; `.save(path)`
        writes the page.  `result`: a finished dynamics run (default: `simulate(**given)`
        with every row kept); `frames`: at most this many frames."""
        from .animation import MAX_FRAMES, motion
        from .animation_output import html_page
        if result is None:
            result = self.simulate(**dict(given, keep_rows=True))
        if not result.kind.integrates or not len(result.t):
            raise AutolevModelError("animate: a run of a CODE DYNAMICS or ODE with rows "
                                    "is drawn")
        m = motion(self, result, frames or MAX_FRAMES, given.get("overrides"))
        return AnimationView(html_page(m, f"{result.name} ({self.name})"), list(m.notes))

    def latex(self, code=None) -> str:
        """The equations of motion of a CODE DYNAMICS or ODE (`code`: which, as
        code_command takes it; default: the first CODE DYNAMICS, else the model's
        equations as they stand) in LaTeX a paper can paste (amsmath): the
        intermediates as definitions, the explicit rates, and M u' = F."""
        from .equations_of import equations_of
        from .equations_text import latex
        return latex(equations_of(self, self.command_to_linearize(code), values=False))

    def plain_dynamics(self) -> CodeCommand:
        """CODE DYNAMICS of the model as it stands (for a model that writes none); the
        same object while the model is unchanged, so its numeric system is reused."""
        kept = self.derived.table("plain dynamics")
        if "command" not in kept:
            kept["command"] = CodeCommand(
                CodeKind.DYNAMICS, f"{self.name}.c", [], None, (), n_outputs=len(self.outputs),
                n_encoded=len(self.encoded), inputs=dict(self.inputs),
                units=dict(self.unit_of))
        return kept["command"]

    def linearize_symbolic(self, point=None, inputs=None, *, code=None, locked=None,
                           max_states: int | None = None):
        """A and B as sympy matrices in the model's symbols, with `point` ({name:
        value}) substituted; refused above `max_states` states (default 12: beyond,
        the expressions outgrow reading).  See Model.linearize for the rest."""
        # imported here: scipy.linalg costs 0.15 s of every start, and only this needs it
        from .numerics.linearize import MAX_SYMBOLIC_STATES, linearize_symbolic
        return linearize_symbolic(self.snapshot_for(self.command_to_linearize(code)), point,
                                  inputs, locked, max_states or MAX_SYMBOLIC_STATES)

    def sweep(self, points, what: str = "linearize", **options):
        """A parameter study: the model linearized (what="linearize") or simulated
        (what="simulate") at every point, translated and compiled once, on the local
        cores or on `executor=` (a Dask Client, any concurrent.futures Executor); one
        table.  See autolev.runtime.studies.sweep."""
        from . import studies
        return studies.sweep(self, points, what, **options)

    def dynamics(self, controls=None, *, code=None, specified=None, backend: str = "auto",
                 infile=None, overrides=None, missing_values: str = "refuse",
                 progress=None, recursion: bool = True):
        """The equations of motion of a CODE DYNAMICS (`code`: which; default the first)
        as compiled functions with exact sparse Jacobians, evaluated at many nodes in one
        call, for trajectory optimization: explicit x' = f(x, u, p, t) and implicit
        r(x, x', u, p, t) = 0 (see autolev.runtime.numerics.dynamics).  `controls`: the
        specified quantities that are u (default: all without a definition);
        `specified`: {name: number or sympy expression} for others; the parameters p
        are the constants without a definition, their values from INPUT, `infile` and
        `overrides` as for `simulate`; `recursion=False`: f's Jacobians from M a - F even
        where the bodies form a tree (whose are by the articulated-body recursion)."""
        from .numerics.dynamics import dynamics
        try:
            return dynamics(self.snapshot_for(self.command_to_linearize(code)), controls,
                            specified=specified, backend=backend, infile=infile,
                            overrides=overrides, missing_values=missing_values,
                            progress=progress, recursion=recursion)
        finally:
            self.keep_built()

    def linearize(self, operating_point=None, inputs=None, *, code=None,
                  backend: str = "auto", infile=None, missing_values: str = "refuse",
                  overrides=None, constraints=None, dependent=None, locked=None,
                  specified=None, progress=None, sweep_size: int = 1):
        """The equations of motion linearized at `operating_point` ({name: value} for
        constants, coordinates, speeds and specified quantities, in SI units and
        radians; the rest from INPUT, the .in file, or 0 for states and specified
        quantities): a Linearization with A, B (columns: `inputs`, default every
        specified quantity without a definition), C, D (rows: the OUTPUT columns),
        `eigenvalues()` and `modes()`.  Exact Jacobians through the Z's, evaluated by
        compiled code.  `code`: which CODE DYNAMICS (see code_command; default: the
        first, else the model's equations as they stand); `overrides`:
        {name: value} in the quantities' own units, as `simulate` takes them.
        `constraints`: configuration constraints g = 0 (sympy expressions, as for
        `simulate`): the point is put on them and the state reduced to the independent
        coordinates (`dependent`: the names of those they fix; default: chosen).
        `locked`: names of coordinates held at their values (with Q' = U: U = U' = 0,
        U's row of Kane's equations dropped), as a rigid joint would.  `specified`:
        {name: number or sympy expression in the model's symbols} defining specified
        quantities the model leaves undefined, as simulate's values for them.
        `progress`: a stream told of steps past two seconds (forming, compiling).
        `sweep_size`: how many points the caller linearizes at (`sweep` says): the
        Jacobians are compiled to C when that many evaluations pay for it, else they are
        the equations' own code run on dual numbers; each size gives every point one
        answer, whatever came before."""
        from .numerics.linearize import linearize   # scipy.linalg: see linearize_symbolic
        if not operating_point:
            warnings.warn("no operating point given: linearized where the INPUT values put "
                          "the state (0 for a state with none); name one with operating_point= "
                          "in Python, --at NAME=VALUE on the command line",
                          stacklevel=2)
        try:
            return linearize(self.snapshot_for(self.command_to_linearize(code)),
                             operating_point, inputs, backend=backend, infile=infile,
                             missing_values=missing_values, overrides=overrides,
                             constraints=constraints, dependent=dependent, locked=locked,
                             specified=specified, progress=progress,
                             sweep_size=sweep_size)
        finally:
            self.keep_built()
