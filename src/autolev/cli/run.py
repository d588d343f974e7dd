"""`autolev run` and `autolev animate`: a model's CODE commands performed, their
files written, plotted and animated.
"""
from __future__ import annotations

import argparse
import importlib.util
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from ..errors import printable_lines
from . import background
from .common import (UsageError, failed_write, has_matplotlib, load_model, name_values,
                     positive_int, refuse_unknown_names, run_options, specified_values,
                     statement_label)
from .responses import transcript_text


def cmd_run(ns: argparse.Namespace) -> int:
    """Translate, build and run the model's CODE commands; write Autolev's files.  A
    run repeats its run plan when it has one (runplan.py), else may leave one; every
    file it reads is noted as read (engine.reading), and what it keeps is filed under
    those digests."""
    from ..engine import reading
    path = Path(ns.file)
    request = _plan_request(ns, path)
    progress = None if ns.quiet else sys.stderr
    if path.suffix.lower() != ".py":
        background.wait_for_finishing(path, progress)
    with reading.recording() as reads:
        if request is None:
            return _run_from_model(path, ns, progress, None)
        from ..engine.keeping import Recorder, kept
        plan = kept(request, reads, _plans)
        if plan is not None:
            from ..engine.runplan import KeptOutcome
            if isinstance(plan, KeptOutcome):
                sys.stderr.write(plan.messages)
                sys.stdout.write(printable_lines(plan.transcript))
                return plan.status
            return _run_from_plan(plan, path, ns)
        recorder = sys.stderr = Recorder(sys.stderr)
        try:
            return _run_from_model(path, ns, progress, Keeping(request, reads, recorder))
        finally:
            sys.stderr = recorder.through


def _plans() -> tuple:
    """What a run keeps: a plan to repeat, or the outcome of a run that wrote nothing."""
    from ..engine.runplan import KeptOutcome, RunPlan
    return RunPlan, KeptOutcome


@dataclass(frozen=True)
class Keeping:
    """What keeps a run's answer: its request, the record of what it read, and the
    stream recording what it prints on stderr."""

    request: object             # request.RunRequest
    reads: object               # engine.reading.Reads
    recorder: object            # keeping.Recorder, which is sys.stderr meanwhile

    def keep(self, make) -> None:
        from ..engine.keeping import keep
        keep(self.request, self.reads, make)


def _plan_request(ns: argparse.Namespace, path: Path):
    """The run's request (request.RunRequest) when a run plan can repeat it: a model
    file run without an output format drawn from the model (an animation; plots and
    tables are drawn from the rows); else None."""
    if path.suffix.lower() == ".py" or ns.func is not cmd_run or \
            any(f.asked(ns) for f in OUTPUT_FORMATS if f.from_model):
        return None
    from ..engine.request import RunRequest
    return RunRequest.of(ns)


def _run_from_model(path: Path, ns: argparse.Namespace, progress,
                    keeping: Keeping | None) -> int:
    """The run from the model; with `keeping`, its plan kept when it can be repeated
    from one."""
    import time

    recorder = keeping.recorder if keeping is not None else None
    overrides = _run_overrides(ns)
    if path.suffix.lower() != ".py" and not ns.first_dynamics:
        translation = _translation_or_none(path)
        if translation is not None and not translation.code_lines:
            return _responses_instead(path, translation, keeping)
    # the compile for later runs may finish after this command returns (background.py)
    finishing = background.split_off(Path(ns.out))
    start = time.monotonic()
    # the note of values lacking is about forming the model: a run plan never says it
    model = load_model(path, progress, None if ns.zero_missing
                       else _values_lacking(path, overrides, ns.infile,
                                            sys.stderr if recorder is None
                                            else recorder.through))
    if model is None:
        print(f"{path}: not run", file=sys.stderr)
        if keeping is not None:
            _keep_outcome(keeping, "", 1)
        return 1
    if not ns.quiet and (model.code_commands or ns.first_dynamics):
        print(f"{path}: built in {time.monotonic() - start:.1f} s")
    if not model.code_commands and not ns.first_dynamics and path.suffix.lower() == ".py":
        # a converted module runs; the responses are read from the .al model
        print(f"{path}: no CODE command: nothing to run (`autolev transcript` of the .al "
              "model shows the responses Autolev displayed)", file=sys.stderr)
        return 0
    refuse_unknown_names(model, overrides)
    commands = _commands_to_run(model, ns, path)
    if not commands:
        print(f"{path}: error: no CODE DYNAMICS or ODE to animate", file=sys.stderr)
        return 1
    if isinstance(ns.plot, str):
        ns.plot = _plotted_columns(_labels_of(model, commands), ns.plot)
    load_messages = recorder.take() if recorder is not None else ""
    planned: list = []
    status = _run_and_report(model, commands, overrides, specified_values(model, ns), ns,
                             path, progress, recorder, planned, finishing)
    # a command that failed (an integration's failure) is planned, and fails again
    if keeping is not None and len(planned) == len(commands):
        from ..engine.runplan import RunPlan
        keeping.keep(lambda reads: RunPlan(reads, load_messages, planned))
    return status


def _translation_or_none(path: Path):
    """The model's translation; None when it fails (loading the model says why)."""
    from ..errors import AutolevSyntaxError, AutolevTranslationError
    from ..loader import translation_of
    try:
        return translation_of(path)
    except (AutolevSyntaxError, AutolevTranslationError):
        return None


def _responses_instead(path: Path, translation, keeping: Keeping | None) -> int:
    """A model that writes no program: what Autolev showed for it, its responses (the
    model is not built for a run)."""
    from ..loader import translation_warnings
    for note in translation_warnings(translation):
        print(note, file=sys.stderr)
    text = transcript_text(path)
    if text is not None:
        print(f"{path}: no CODE command: the responses Autolev displayed follow "
              "(autolev transcript FILE --out DIR writes them as NAME.all)", file=sys.stderr)
        sys.stdout.write(printable_lines(text))
    status = 0 if text is not None else 1
    if keeping is not None:
        _keep_outcome(keeping, text or "", status)
    return status


def _keep_outcome(keeping: Keeping, transcript: str, status: int) -> None:
    """Keep a run that wrote no file (runplan.KeptOutcome): what the recorder took of
    its stderr, `transcript` on its stdout."""
    from ..engine.runplan import KeptOutcome
    messages = keeping.recorder.take()
    keeping.keep(lambda reads: KeptOutcome(reads, messages, transcript, status))


def _run_from_plan(plan, path: Path, ns: argparse.Namespace) -> int:
    """A run repeated from its plan: the same files and messages, without the model."""
    import time
    import warnings

    from ..engine.errors import AutolevModelError
    from ..engine.execute import execute
    from ..engine.options import RunOptions
    from ..engine.results import command_error, run_summary
    start = time.monotonic()
    _check_needs(ns)
    if isinstance(ns.plot, str):
        ns.plot = _plotted_columns([label for planned in plan.commands
                                    for labels, _ in planned.execution.columns
                                    for label in labels], ns.plot)
    sys.stderr.write(plan.load_messages)
    if not ns.quiet:
        print(f"{path}: built in {time.monotonic() - start:.1f} s (its run plan)")
    status = 0
    for planned in plan.commands:
        sys.stderr.write(planned.messages)
        e = planned.execution
        began = time.monotonic()
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")      # its run's are among its messages
                result = execute(e, Path(ns.out), RunOptions(
                    progress=None if ns.quiet else sys.stderr, infile=ns.infile,
                    keep_rows=_rows_needed(ns), overwrite=ns.overwrite))
        except AutolevModelError as exc:
            print(f"{planned.label}: error: {command_error(e.kind, exc)}", file=sys.stderr)
            status = 1
            continue
        if result.failure:
            status = 1                  # (its message is among the plan's messages)
        if not ns.quiet:
            print(run_summary(e.kind, e.filename, result, time.monotonic() - began))
            for f in result.files:
                print(f"  wrote {f}")
        status = max(status, _write_formats(FinishedRun(result, Path(ns.out), ns,
                                                        planned.label)))
    return status


def _values_lacking(path: Path, overrides: dict, infile, stream):
    """Before a model is built (its equations formed: a minute on a large model), the
    note naming the constants that nothing gives a value (INPUT, an assignment, --set,
    the --in file), and the variables for a CODE ALGEBRAIC or NONLINEAR, whose program
    reads those too; the run refuses once it knows its programs read them; printed on
    `stream`."""
    given = {name.upper() for name in overrides}

    def note(translation) -> None:
        from ..errors import some_names
        from_file = _names_in_file(infile, translation)
        if from_file is None:
            return                  # the file decides, and the run says what it lacks
        lacking = [name for name in translation.inputs_without_value
                   if name.upper() not in given and name.upper() not in from_file]
        if lacking:
            print(f"{path}: note: no value given for {some_names(lacking)} (INPUT, --set "
                  "NAME=VALUE or --in FILE.in); the run stops before computing if its "
                  "programs read them", file=stream, flush=True)
    return note


def _names_in_file(infile, translation) -> set | None:
    """The names (upper case) the --in file gives values, none without one or when the
    values it has for them are all 0 (a template never filled in gives none: the run's
    rule); None when it cannot be read, or names what the model does not (its values
    are then read in Autolev's order, whatever the labels say)."""
    from ..engine import reading
    from ..engine.code_kinds import INTEGRATION_PARAMETERS
    from ..engine.numbers import in_file_lines, parse_number
    if infile is None:
        return set()
    try:
        text = reading.read_bytes(infile).decode("latin-1")
    except OSError:
        return None
    values = {name.upper(): parse_number(raw) for _, name, raw, _ in in_file_lines(text)}
    known = {name.upper() for name in translation.names} | set(INTEGRATION_PARAMETERS)
    if not values or any(name.rstrip("'") not in known for name in values):
        return None
    lacking = {name.upper() for name in translation.inputs_without_value}
    if all(v == 0 for name, v in values.items() if name in lacking):
        return set()
    return set(values)


def _run_overrides(ns: argparse.Namespace) -> dict:
    """--set and --tfinal as {NAME: value}, after checking --method and what the output
    formats asked for need (UsageError)."""
    from ..engine.integrators import METHODS
    if ns.method is not None and ns.method not in METHODS:
        raise UsageError(f"unknown --method {ns.method} (one of {', '.join(METHODS)})")
    overrides = name_values(ns.set, "--set", numbers=True)
    if ns.tfinal is not None:
        overrides["TFINAL"] = ns.tfinal
    _check_needs(ns)
    return overrides


def _labels_of(model, commands: list) -> list[str]:
    """The output columns the commands write."""
    from ..engine.errors import AutolevModelError
    from ..runtime.numerics.command import output_columns
    labels: list[str] = []
    for command in commands:
        try:
            files = output_columns(model.snapshot_for(command), command)
        except AutolevModelError:
            continue                # its run reports the OUTPUT it cannot write
        labels += [c.label for cols in files for c in cols]
    return labels


def _plotted_columns(written: list[str], text: str) -> list[str]:
    """--plot COLUMNS as output labels, each one among those the runs write (UsageError
    naming those, before anything runs)."""
    wanted = [name.strip() for name in text.split(",") if name.strip()]
    if not wanted:
        raise UsageError("--plot: name the output columns to draw (e.g. --plot Q1,U1), "
                         "or give --plot alone for every output file")
    labels: list[str] = []
    for label in written:
        if label.upper() not in {x.upper() for x in labels}:
            labels.append(label)
    unknown = [name for name in wanted if name.upper() not in {x.upper() for x in labels}]
    if unknown:
        raise UsageError(f"--plot: no output column {', '.join(unknown)}; the runs write "
                         + (", ".join(labels) if labels else "no output column"))
    return wanted


def _commands_to_run(model, ns: argparse.Namespace, path: Path) -> list:
    """The CODE commands --code or --first-dynamics chose (all by default; none when
    there is nothing to animate)."""
    from ..engine.errors import AutolevModelError
    if not model.code_commands:
        print(f"{path}: no CODE command; animating it as CODE DYNAMICS", file=sys.stderr)
        return [model.plain_dynamics()]
    if ns.code:
        try:
            return model.commands_named([int(name) if name.isdigit() else name
                                         for name in ns.code])
        except AutolevModelError as exc:
            raise UsageError(f"--code: {exc}") from None
    if ns.first_dynamics:
        return [c for c in model.code_commands if c.kind.integrates][:1]
    return list(model.code_commands)


def _run_and_report(model, commands: list, overrides: dict, specified: dict,
                    ns: argparse.Namespace, path: Path, progress, recorder=None,
                    planned: list | None = None, finishing=None) -> int:
    """Run the commands and report each; with `recorder`, each command that a run plan
    can repeat goes into `planned` with what it printed on stderr.  With `finishing`
    (background.Finishing), the command returns once the last run's files are written,
    and the C its run began in Python compiles on in the background."""
    from ..engine.errors import AutolevModelError
    from ..engine import rowtext
    from ..runtime.steps import SlowStep
    from ..runtime.tools import program_file_name, safe_stem
    label = statement_label(model, path)
    written_by: dict[str, str] = {}
    for command in commands:
        try:
            stem = safe_stem(program_file_name(command.filename))
        except AutolevModelError:
            continue                # an unusable name: its run says so
        if stem.lower() in written_by:
            print(f"{label(command)}: warning: CODE {command.filename} writes the same "
                  f"files ({stem}.1, ...) as CODE {written_by[stem.lower()]}; "
                  "its run replaces them (give --out per program to keep both)",
                  file=sys.stderr)
        written_by[stem.lower()] = command.filename
    out_dir = Path(ns.out)
    status = 0
    plannable: list = []         # (execution, result, label, messages) of each run
    from ..runtime.tools import RunOptions
    runs = model.run_commands(commands, out_dir, keep_going=True, options=RunOptions(
        method=ns.method, backend=ns.backend, infile=ns.infile,
        progress=progress, overrides=overrides, specified=specified,
        quirks=ns.quirks, keep_rows=_rows_needed(ns),
        overwrite=ns.overwrite,
        missing_values="zero" if ns.zero_missing else "refuse"))
    for number, done in enumerate(runs, 1):
        if done.error is not None:
            print(f"{label(done.command)}: error: {done.error}", file=sys.stderr)
            status = 1
            continue
        if done.result.failure:
            print(f"{label(done.command)}: {done.result.failure}", file=sys.stderr)
            status = 1
        if not ns.quiet:
            print(done.summary())
            for f in done.result.files:
                print(f"  wrote {f}")
        status = max(status, _write_formats(FinishedRun(done.result, out_dir, ns,
                                                        label(done.command), model)))
        # what is left is for the runs to come: the C a cold run began in Python, the
        # built model and the run plan kept; the user has the files now
        system = done.result.execution.system
        if finishing is not None and number == len(commands):
            if progress is not None and system.compiling():
                print(f"  {label(done.command)}: its C compiles on in the background, for "
                      "later runs", file=progress)
            finishing.detach(status, path)
        with SlowStep(progress, f"{label(done.command)}: compiling its C for later runs"):
            if system.compiled_loop(wait=True) is not None:
                rowtext.prepare()       # what the loop writes its rows with
        if recorder is not None:
            messages = recorder.take()
            plannable.append((done.result.execution, done.result, label(done.command),
                              messages))
    if plannable:
        # planned once the last files are written: the plan's programs compile (in the
        # background child when there is one)
        from ..engine.runplan import can_plan, planned_command
        planned.extend(planned_command(*run) for run in plannable if can_plan(*run[:2]))
    return status


def cmd_animate(ns: argparse.Namespace) -> int:
    """`run` of one CODE DYNAMICS (the first, or --code), with its motion written."""
    if any(f in ("gif", "mp4") for f in ns.formats or ()) and not has_matplotlib():
        raise UsageError("a GIF or MP4 needs matplotlib (pip install 'autolev[plot]'); "
                         "--format html needs nothing more")
    ns.code = [ns.code] if ns.code is not None else None
    return cmd_run(ns)


def _animate(model, result, out_dir: Path, ns, label: str) -> list[Path]:
    from ..runtime.animation import MAX_FRAMES, motion
    from ..runtime.animation_output import write_html, write_movie
    m = motion(model, result, ns.frames or MAX_FRAMES, _run_overrides(ns))
    for note in m.notes:
        print(f"{label}: note: {note}", file=sys.stderr)
    formats = ns.formats or ["html"] + (["gif"] if has_matplotlib() else [])
    if not ns.formats and not has_matplotlib():
        print("autolev: note: no GIF: it needs matplotlib (pip install 'autolev[plot]'); "
              "the HTML page needs nothing more", file=sys.stderr)
    from ..runtime.tools import Written
    names = [f"{result.name}.{fmt}" for fmt in formats]
    record = Written(out_dir)
    record.check(names, ns.overwrite)        # before drawing: nothing of theirs replaced
    written = []
    for fmt, name in zip(formats, names):
        path = out_dir / name
        if fmt == "html":
            written.append(write_html(m, path, f"{result.name} ({model.name})"))
        else:
            written.append(write_movie(m, path, progress=None if ns.quiet else sys.stderr))
        record.record([name])
    return written


@dataclass(frozen=True)
class FinishedRun:
    """A finished run, as the output formats write from it: its Result, the output
    folder, the command line, the label its messages begin with, and its model (None:
    the run was repeated from its run plan, which no format drawn from the model is)."""

    result: object              # engine.results.Result
    out_dir: Path
    ns: argparse.Namespace
    label: str
    model: object = None


@dataclass(frozen=True)
class OutputFormat:
    """A file `autolev run` also writes from a finished run when its flag (--NAME) asks:
    `write(finished)` writes it and returns the files written (AutolevModelError: the
    model cannot give it); `called`: what a failure to write it calls it ({name}: the
    run's name); `needs_rows`: the run keeps every row for it, not only the last;
    `needs`: the package without which the flag is refused, installed by autolev's
    extra `extra`; `from_model`: drawn from the model as well as the rows, so no run
    plan repeats a run asking for it; `value`: the metavar of the value the flag may
    take (None: a plain switch)."""

    name: str
    help: str
    write: Callable[[FinishedRun], list]
    called: str
    needs_rows: bool = True
    needs: str | None = None
    extra: str | None = None
    from_model: bool = False
    value: str | None = None

    @property
    def flag(self) -> str:
        return "--" + self.name

    def asked(self, ns: argparse.Namespace) -> bool:
        return bool(getattr(ns, self.name))

    def add_flag(self, parser) -> None:
        if self.value is None:
            parser.add_argument(self.flag, action="store_true", help=self.help)
        else:
            parser.add_argument(self.flag, nargs="?", const=True, metavar=self.value,
                                help=self.help)


def _write_plots(run: FinishedRun) -> list[Path]:
    """A PNG per output file, or one of the --plot COLUMNS."""
    if not run.result.outputs:
        return []
    from ..plots import write_chosen_png, write_pngs
    ns = run.ns
    if ns.plot is True:
        return write_pngs(run.result, run.out_dir, ns.overwrite)
    return write_chosen_png(run.result, run.out_dir, ns.plot, ns.overwrite)


def _write_table(run: FinishedRun, name: str, content) -> list[Path]:
    """The output columns in one file, `content()` its text or bytes."""
    if not run.result.outputs:
        return []
    from ..engine.outputs import write_output
    return [write_output(run.out_dir, name, content(), run.ns.overwrite)]


def _write_csv(run: FinishedRun) -> list[Path]:
    return _write_table(run, f"{run.result.name}.csv", run.result.csv_text)


def _write_mat(run: FinishedRun) -> list[Path]:
    return _write_table(run, f"{run.result.name}.mat", run.result.mat_bytes)


def _write_animation(run: FinishedRun) -> list[Path]:
    """The motion of a CODE DYNAMICS or ODE that took a step."""
    from ..engine.errors import AutolevModelError
    result = run.result
    if not (result.kind.integrates and len(result.t)):
        return []
    try:
        return _animate(run.model, result, run.out_dir, run.ns, run.label)
    except AutolevModelError as exc:
        raise AutolevModelError(f"cannot animate {result.execution.filename}: {exc}") \
            from None


ANIMATION = OutputFormat(
    "animate", "also write the motion of each CODE DYNAMICS: NAME.html (a 3-D view to "
    "rotate and scrub) and, with matplotlib, NAME.gif", _write_animation, "the animation",
    from_model=True)
# in the order of `autolev run --help`, and of the files written
OUTPUT_FORMATS = (
    OutputFormat("plot", "also write a PNG per output file; with COLUMNS (e.g. Q1,U1: "
                 "output labels, any case) one picture NAME.plot.png of those columns "
                 "against time (needs matplotlib)", _write_plots, "the plots",
                 needs="matplotlib", extra="plot", value="COLUMNS"),
    OutputFormat("csv", "also write NAME.csv: every output column (T once), a row per "
                 "printed row, the labels as its header", _write_csv, "{name}.csv"),
    OutputFormat("mat", "also write NAME.mat (Matlab): a column vector per output label, "
                 "with `labels` and `units`", _write_mat, "{name}.mat"),
    ANIMATION,
)


def _rows_needed(ns: argparse.Namespace) -> bool:
    """Whether the output formats asked for need every row of a run."""
    return any(f.needs_rows and f.asked(ns) for f in OUTPUT_FORMATS)


def _check_needs(ns: argparse.Namespace) -> None:
    """UsageError when an output format asked for lacks the package it needs."""
    for f in OUTPUT_FORMATS:
        if f.needs is not None and f.asked(ns) and importlib.util.find_spec(f.needs) is None:
            raise UsageError(f"{f.flag} needs {f.needs} (pip install 'autolev[{f.extra}]')")


def _write_formats(run: FinishedRun) -> int:
    """The files of every output format the command line asks for, each said as
    written, or its failure (1) said and the others written still."""
    from ..engine.errors import AutolevModelError
    status = 0
    for f in OUTPUT_FORMATS:
        if not f.asked(run.ns):
            continue
        try:
            written = f.write(run)
        except AutolevModelError as exc:
            print(f"{run.label}: error: {exc}", file=sys.stderr)
            status = 1
            continue
        except OSError as exc:
            print(f"{run.label}: error: cannot write {f.called.format(name=run.result.name)} "
                  f"into {run.out_dir}: {failed_write(exc)}", file=sys.stderr)
            status = 1
            continue
        if not run.ns.quiet:
            for path in written:
                print(f"  wrote {path}")
    return status


def add_run(sub) -> None:
    run = sub.add_parser("run", help="run a model's CODE commands (simulate)",
                         description="Translate and build FILE, then perform its CODE "
                         "commands with its INPUT values: DYNAMICS and ODE are integrated, "
                         "ALGEBRAIC and NONLINEAR solved.  Writes Autolev's files NAME.in, "
                         "NAME.1 ... NAME.k (one per OUTPUT) and NAME.dir into --out.")
    run_options(run)
    for output_format in OUTPUT_FORMATS:
        output_format.add_flag(run)
    run.add_argument("--code", action="append", metavar="FILE",
                     help="run only this CODE command (its file name, e.g. bike.c, or "
                     "its 0-based index); repeatable")
    run.set_defaults(func=cmd_run, formats=None, frames=None, first_dynamics=False)


def add_animate(sub) -> None:
    anim = sub.add_parser("animate", help="run a model and write its motion as a picture",
                          description="Run FILE's first CODE DYNAMICS (or --code) and write "
                          "a stick figure of its points in the Newtonian frame over the run: "
                          "NAME.html, a self-contained page with a 3-D view to rotate and a "
                          "time slider, and NAME.gif (or .mp4) with matplotlib.  The run's "
                          "own files are written too.")
    run_options(anim)
    anim.add_argument("--code", metavar="FILE",
                      help="the CODE command to animate (default: the first DYNAMICS/ODE)")
    anim.add_argument("--format", dest="formats", action="append",
                      choices=("html", "gif", "mp4"),
                      help="what to write (repeatable; default: html, and gif when "
                      "matplotlib is installed)")
    anim.add_argument("--frames", type=positive_int, default=None, metavar="N",
                      help="frames at most (default 400; the rows are sampled evenly)")
    anim.set_defaults(func=cmd_animate, first_dynamics=True,
                      **{f.name: f is ANIMATION for f in OUTPUT_FORMATS})
