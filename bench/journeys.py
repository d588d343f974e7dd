#!/usr/bin/env python3
"""Every command a user runs, on every model, in a user's order.

    python bench/journeys.py [--examples] [--only ID ...] [--jobs N] [--limit S]
                             [--json FILE] [--compare OLD.json] [--keep DIR]

For each visible corpus model (bench/corpus.py's corpus_models; --examples: the shipped
autolev_examples/*.al instead) the installed command line is run as a user runs it
(`python -m autolev ...`, this interpreter, a fresh working folder per model, --limit
seconds per command), in this order:

  check       autolev check FILE
  convert     autolev convert FILE -o DIR/NAME.py
  run         autolev run FILE --out DIR/run, with the model's own values: its INPUT,
              and the .in its repository ships beside it (--in; rows of kind `in`
              whose companion_of is the model, the one nearest the model's folder)
  code        autolev code FILE --out DIR/code; each program written is compiled and
              run on the values of the run (below) and its output files NAME.1 ... are
              compared with the run's, row by row
  linearize   autolev linearize FILE (the same values), for a model with CODE DYNAMICS
  animate     autolev animate FILE --format html (the same values), likewise
  transcript  autolev transcript FILE --out DIR/tr
  verify      autolev verify DIR/tr/NAME.all

Values by rule.  When the run stops because constants have no value (neither INPUT nor
the shipped .in gives them: "... have no value: NAMES"), it is run again with every
constant it names given 1 (masses, lengths, moments of inertia, gravity...), except
the products of inertia (names written as the 4th-6th argument of an INERTIA
statement), given 0: each central inertia is then the identity, positive definite,
and no value is random.  The names are the ones the run's message lists (12 at most
a time: the run is repeated until it names no more).  linearize and animate get the
same --in and --set.

The programs.  A C program is compiled with `cc -O0 ... -lm`; a Fortran one with
`gfortran -O0` (a program written with NOSUBS gets our KUTTA and SOLVE appended, as
its user links their own); a Matlab one runs under GNU Octave with the values put
into its ReadUserInput table (a .M file run as .m).  Without gfortran or Octave the
cell says so (not a failure).  A program reads the .in the repository ships when the
run took no value by rule and the file has the name the program opens; otherwise the
NAME.in that `autolev run` wrote with the values it used.  Its files are compared with
the run's row by row: each difference, relative to its column's largest magnitude (at
least 1e-6 of the file's, as bench/truth.py's column_errors), must be at most
TOLERANCE = 1e-6 (the 7 significant digits both print).  Where an integrated file
parts from the run's after its first row, the run is made again with RELERR and
ABSERR 1000 times smaller: the rows from where the run parts from that one depend on
the integration error, and only the rows before them must agree (bench/truth.py's
rule for Autolev's own programs; the earliest such row of a command's files counts for
all of them, as they are one integration's).  A Matlab program of a CODE DYNAMICS integrates
with Octave's ode45 and the run with scipy's RK45, two step controllers: only its
first row (the initial values, before any step) and its number of rows are compared.

A cell is ok (exit 0, and what the command writes is there), genuine (exit 1 or 2
for an error in the model file, named with its reason in GENUINE), FAIL (exit 70, a
Python traceback, the time limit, an exit 1/2 not named in GENUINE, a program that
does not compile or run or whose rows differ from the run's), - (the command does
not apply: no CODE command, or no CODE DYNAMICS for linearize and animate) or skipped
(the command before it, run for code/linearize/animate, check for convert ... was not
ok).  Prints the table, the reason of every cell that is not ok, a summary per command
and the time; --json writes every cell (status, reason, seconds, the end of stderr);
--compare OLD.json prints what changed since another run.  Exit status 1 when a cell
is FAIL.

One file over 600 lines on purpose: a bench script runs from a checkout alone
(`python bench/journeys.py`), and its parts (the models' values, the commands, the table)
share one record of each model's journey.
"""
from __future__ import annotations

import argparse
import csv
import datetime
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))
sys.path.insert(0, str(ROOT / "bench"))

import numpy as np  # noqa: E402

import autolev  # noqa: E402
from corpus import corpus_models  # noqa: E402
from truth import read_table  # noqa: E402
from written_programs import octave, run_octave, with_table_values  # noqa: E402

from autolev.cli import EXIT_INTERNAL  # noqa: E402
from autolev.programs.f_subroutines import kutta_and_solve  # noqa: E402
from autolev.engine.clibrary import compiler  # noqa: E402

COMMANDS = ("check", "convert", "run", "code", "linearize", "animate", "transcript",
            "verify")
# the command whose success each command needs (a user stops where one fails)
PREREQUISITE = {"convert": "check", "run": "convert", "code": "run", "linearize": "run",
                "animate": "run", "transcript": "convert", "verify": "transcript"}
TOLERANCE = 1e-6
# a compared file's remark: where a run with tighter tolerances fails, rows part freely
SINGULAR = "equal up to where a run with tolerances 1000 times tighter stops"
LISTING = ROOT.parent / "shared" / "corpus" / "visible.tsv"
CORPUS = Path(os.environ.get("AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus"))
EXAMPLES = ROOT / "autolev_examples"
# how many times the run is repeated to learn the names of constants without a value
RULE_ROUNDS = 50

# (model id, command): what is wrong in the model file itself, quoting its line.  Only
# after reading the model: a shortcoming of autolev is a FAIL, never an entry here.
GENUINE: dict[tuple[str, str], str] = {
    ("mae223-bicycledyn-bicycle2", "check"):
        "line 21 `P_PR_DO>=RR*B3>+D1O*D1>+D03*D3>` uses D1O (letter O); line 5 declares "
        "D01 (digit 0): `CONSTANTS RF,RR,L{3},THETA,D01,D03,FO1,FO3`",
    ("mae223-bicycledyn-bike", "check"):
        "line 86 `W_A_A2> = (Z12*U4 + Z13*U5)*A2>` uses Z12 and Z13, which nothing in the "
        "file defines (no AUTOZ, ZEE or assignment: Z's copied from another session)",
    ("mae223-bicycledyn-bicycle11", "check"):
        "line 289 `XP=[Q1P; ...; U4P; U5P; U6P]` uses U5P, whose definition is commented "
        "out at line 283 (`%U5P=TAYLOR(U5',1,...)`)",
    ("mae223-chapter-1-1-9-2", "check"):
        "line 16 `P_O_P>=R*D1>D_Q1_B>=D(P_O_P>,Q1,B)` runs two statements together",
    ("swingbike-linearize-swing-bike", "check"):
        "a fragment of a session: it declares nothing and RUNs nothing, and line 7 "
        "`A[1,1]=EVALUATE(D(Q4',Q4),Q1=0,...,U6=-V/RR,...)` uses Q4, V and RR (declared in "
        "SB_01.AL)",
    ("ridermodel-leanangle", "run"):
        "line 442 `M=INV(ROWS(B,3:4))`: B is 4x5 (B[1,1] ... B[4,5], lines 416-438), so "
        "ROWS(B,3:4) is 2x5 and has no inverse",
    ("eulerpar-rigidbody", "run"):
        "line 49 `input ma=1, Ixx=1, Iyy=1, Izz=1, Ixy=1, Iyz=1, Ixz=1` gives A an inertia "
        "of all ones (principal moments 0, 0, 3): the mass matrix is singular at T = 0",
    ("biomac-acc-427b529d", "check"):
        "line 18 `RUN gait2d_kin.al`: the repository has no gait2d_kin.al (its kinematics "
        "file is gait2dc_kin.al)",
    ("sprint-7seg-7segsprint", "run"):
        "the integration halts at T = 1.0617E-02 on the shipped BaseModel/7SegSprint.in "
        "(initial rates in DEG/S, read as rad/s as Autolev's programs did: its line "
        "`Initial Value: MTP DEG/S | 1064.10`); Autolev's own 7SegSprint_raw.f halts at "
        "T = 1.0615E-02 on it (shared/truth, run f_raw_repo_in)",
    ("sprint-7seg-stride-7segsprint", "run"):
        "the integration halts at T = 3.5373E-03 on the shipped base/7segsprint.in "
        "(initial rates in DEG/S, read as rad/s as Autolev's programs did: its line "
        "`Initial Value: U4 DEG/S | 1064.10`); Autolev's own 7segsprint_raw.f halts at "
        "the same T on it (shared/truth, run f_raw_repo_in)",
    ("npparser-example5-2", "check"):
        "line 37 `EigenVec = Rows(EigenVec, 1)` uses EigenVec; line 36 "
        "`Eig(..., Lambda, EigenVecs)` named it EigenVecs",
    ("npparser-example5-7", "run"):
        "lines 32-33 `w_B_N> = qA'*B3>`, `w_C_N> = qA'*C3>` give B and C the rate qA', so "
        "the DEPENDENT velocities of lines 43-44 do not involve qB', qC' and line 45 "
        "`Constrain(Dependent[qB', qC'])` cannot solve for them",
    ("sympy-ruletest10", "transcript"):
        "line 40 `V2PTS(N,A,O,P)` needs the velocity of O in N, which the file never "
        "defines (O is placed only from P, line 34, and P has no velocity either): a test "
        "of SymPy's translator, whose own translation (ruletest10.py) stops there too",
}
# transcript runs the model as run does: refused at the same statement
for _ident in ("ridermodel-leanangle", "npparser-example5-7"):
    GENUINE[(_ident, "transcript")] = GENUINE[(_ident, "run")]


@dataclass
class Outcome:
    """One command's process: its exit status (None: stopped at the time limit)."""
    returncode: int | None
    stdout: str
    stderr: str
    seconds: float
    limit: float = 0.0


@dataclass
class Cell:
    status: str                 # ok, genuine, FAIL, -, skipped
    reason: str = ""            # one line, for anything not ok (or a note on an ok)
    seconds: float = 0.0
    detail: str = ""            # the end of stderr, for a failure


@dataclass
class Journey:
    ident: str
    path: str
    values: str = ""            # where the run's values came from
    cells: dict = field(default_factory=dict)
    seconds: float = 0.0


# -- classifying -----------------------------------------------------------------------
def classify(ident: str, command: str, outcome: Outcome, genuine=None) -> Cell:
    """A command's cell from its process alone: exit 0 ok; exit 70, a traceback or the
    time limit FAIL; exit 1 or 2 genuine when `genuine` (default GENUINE) names the
    model and command, else FAIL; any other exit FAIL."""
    genuine = GENUINE if genuine is None else genuine
    cell = Cell("ok", seconds=outcome.seconds, detail=_tail(outcome.stderr))
    if outcome.returncode is None:
        cell.status, cell.reason = "FAIL", f"did not finish in {outcome.limit:g} s"
    elif outcome.returncode == EXIT_INTERNAL:
        cell.status, cell.reason = "FAIL", f"exit {EXIT_INTERNAL}: " + next(
            (line.strip() for line in outcome.stderr.splitlines()
             if "internal error" in line), _last_line(outcome.stderr))
    elif "Traceback (most recent call last)" in outcome.stderr:
        cell.status = "FAIL"
        cell.reason = f"exit {outcome.returncode} with a Python traceback: " \
            + _last_line(outcome.stderr)
    elif outcome.returncode == 0:
        cell.detail = ""
    elif outcome.returncode in (1, 2) and (ident, command) in genuine:
        cell.status, cell.reason = "genuine", genuine[(ident, command)]
    elif outcome.returncode in (1, 2):
        cell.status = "FAIL"
        cell.reason = f"exit {outcome.returncode}: " + _first_error(outcome)
    else:
        cell.status = "FAIL"
        cell.reason = (f"killed by signal {-outcome.returncode}" if outcome.returncode < 0
                       else f"exit {outcome.returncode}: " + _first_error(outcome))
    return cell


def _tail(text: str, size: int = 1500) -> str:
    return text[-size:]


def _last_line(text: str) -> str:
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    return lines[-1] if lines else ""


def _first_error(outcome: Outcome) -> str:
    """The first line saying `error`, else the first that is not a warning, else the
    first line, of what the command said."""
    lines = [line.strip() for line in outcome.stderr.splitlines() if line.strip()]
    lines = lines or [line.strip() for line in outcome.stdout.splitlines() if line.strip()]
    said = [line for line in lines if "error" in line.lower()] \
        + [line for line in lines if "warning:" not in line] + lines
    return said[0] if said else "(nothing said)"


# -- running a command -----------------------------------------------------------------
def process_env(src: Path = ROOT / "src", **more: str) -> dict:
    """The environment of a command's process: autolev from `src`, one thread for BLAS,
    no display, tracebacks of internal errors shown; `more` set besides."""
    return dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(src)] + ([os.environ["PYTHONPATH"]] if os.environ.get("PYTHONPATH") else [])),
        AUTOLEV_TRACEBACK="1", OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1",
        MPLBACKEND="Agg", **more)


def run_process(argv: list, cwd: Path, limit: float, env: dict | None = None) -> Outcome:
    """`argv` in its own process group (killed whole at the time limit); `env`: its
    environment (default process_env())."""
    env = process_env() if env is None else env
    start = time.monotonic()
    proc = subprocess.Popen([str(a) for a in argv], cwd=cwd, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, errors="replace", env=env,
                            start_new_session=True)
    try:
        out, err = proc.communicate(timeout=limit)
        code = proc.returncode
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        code = None
    return Outcome(code, out, err, time.monotonic() - start, limit)


def autolev_cli(*args) -> list:
    return [sys.executable, "-m", "autolev", *args]


# -- one model -------------------------------------------------------------------------
@dataclass
class Model:
    """What the harness reads from the model file itself (the IR)."""
    code: list                  # (kind, file name) of each CODE command
    products_of_inertia: set    # names written as an INERTIA's 4th-6th argument


def read_model(path: Path) -> Model | None:
    """The model's CODE commands and products of inertia; None when it does not parse
    (check reports why)."""
    try:
        program = autolev.parse(path)
    except autolev.AutolevError:
        return None
    products = set()
    for st in program.of_kind("inertia"):
        for value in st.values[3:6]:
            if isinstance(value, autolev.ir.Name):
                products.add(value.name.upper())
    return Model([(c.what, c.filename) for c in program.of_kind("code")], products)


def journey(ident: str, path: Path, companion: Path | None, limit: float,
            work: Path, genuine=None) -> Journey:
    """Every command for one model, in a user's order (see the module's docstring)."""
    start = time.monotonic()
    path = path.resolve()
    out = Journey(ident, str(path))
    model = read_model(path)
    cells = out.cells

    def do(command, argv, problem_of=None) -> Cell:
        """The command's cell; `problem_of(outcome)`: what is wrong after an exit 0."""
        outcome = run_process(argv, work, limit)
        cell = classify(ident, command, outcome, genuine)
        problem = problem_of(outcome) if cell.status == "ok" and problem_of else None
        if problem:
            cell.status, cell.reason = "FAIL", problem
        return cell

    def applies(command) -> bool:
        """False (the cell is set) when the command does not apply or its prerequisite
        was not ok."""
        if command in ("run", "code") and model is not None and not model.code:
            cells[command] = Cell("-", "no CODE command")
            return False
        if command in ("linearize", "animate") and model is not None \
                and not any(kind == "dynamics" for kind, _ in model.code):
            cells[command] = Cell("-", "no CODE DYNAMICS")
            return False
        before = PREREQUISITE.get(command)
        if before and cells[before].status != "ok":
            cells[command] = Cell("skipped", f"{before} was {cells[before].status}")
            return False
        return True

    cells["check"] = do("check", autolev_cli("check", path, "-q", "--no-context"))
    if applies("convert"):
        cells["convert"] = do("convert", autolev_cli("convert", path, "-q", "-o",
                                                     work / "model.py"))
    values = Values([], "")
    if applies("run"):
        cells["run"], values = run_with_values(ident, path, model, companion, work, limit,
                                               genuine)
        out.values = values.source
    if applies("code"):
        cells["code"] = code_cell(ident, model, RunToMatch(
            path, work, values, companion if not values.by_rule else None, limit), genuine)
    if applies("linearize"):
        cells["linearize"] = do("linearize", autolev_cli("linearize", path, *values.options),
                                lambda o: None if "real,imaginary" in o.stdout
                                else "printed no eigenvalues")
    if applies("animate"):
        folder = work / "anim"
        cells["animate"] = do("animate", autolev_cli("animate", path, "--format", "html",
                                                     "--out", folder, "-q",
                                                     *values.options),
                              lambda o: None if any(folder.glob("*.html"))
                              else "wrote no HTML file")
    transcript = work / "tr" / f"{path.stem}.all"
    if applies("transcript"):
        cells["transcript"] = do("transcript", autolev_cli("transcript", path, "--out",
                                                           work / "tr"),
                                 lambda o: None if transcript.exists()
                                 else f"wrote no {transcript.name}")
    if applies("verify"):
        cells["verify"] = do("verify", autolev_cli("verify", transcript))
    for cell in cells.values():        # file names as the model's folder sees them
        for folder in (path.parent, work):
            cell.reason = cell.reason.replace(f"{folder}{os.sep}", "")
    out.seconds = time.monotonic() - start
    return out


@dataclass
class Values:
    """The options giving a run its values, and where they came from."""
    options: list
    source: str
    by_rule: bool = False


MISSING = re.compile(r"(?:constants?|inputs?) of \S+ ha(?:s|ve) no value: (.*?)\.  ")


def missing_names(stderr: str) -> list:
    """The names a run's messages say have no value (12 at most per message)."""
    names = []
    for listed in MISSING.findall(stderr):
        for name in listed.split(", "):
            if name and not name.startswith("..."):
                names.append(name)
    return names


def rule_values(names, products_of_inertia) -> dict:
    """The stated rule: 1 for every constant, 0 for a product of inertia."""
    return {n: "0" if n.upper() in products_of_inertia else "1" for n in names}


def run_with_values(ident, path, model, companion, work, limit, genuine):
    """`autolev run` with the model's values, then (when constants have none) with
    values by rule: (cell, Values)."""
    given = ["--in", companion] if companion else []
    chosen: dict = {}
    seconds = 0.0
    for _ in range(RULE_ROUNDS):
        options = given + [a for n, v in chosen.items() for a in ("--set", f"{n}={v}")]
        run_dir = work / "run"
        shutil.rmtree(run_dir, ignore_errors=True)
        outcome = run_process(autolev_cli("run", path, "--out", run_dir, "-q", *options),
                              work, limit)
        seconds += outcome.seconds
        new = [n for n in missing_names(outcome.stderr) if n not in chosen]
        if outcome.returncode != 1 or not new:
            break
        chosen.update(rule_values(new, model.products_of_inertia if model else set()))
    outcome.seconds = seconds
    cell = classify(ident, "run", outcome, genuine)
    source = "INPUT" + (f" and {companion.name} (shipped)" if companion else "")
    if chosen:
        zeros = sum(v == "0" for v in chosen.values())
        source += (f"; by rule: {len(chosen) - zeros} constants 1"
                   + (f", {zeros} products of inertia 0" if zeros else ""))
        cell.reason = (cell.reason + f" [values {source}]") if cell.reason \
            else f"values {source}"
    return cell, Values(options, source, bool(chosen))


def values_apart(ident, path, companion, work, limit) -> Values:
    """The model's values (run_with_values) found in a cache of their own, waiting for
    their compiles: a bench timing or profiling the model afterwards meets none of that
    work beside its own runs."""
    kept = {k: os.environ.get(k) for k in ("AUTOLEV_CACHE", "AUTOLEV_FOREGROUND")}
    os.environ.update(AUTOLEV_CACHE=str(work / "values-cache"), AUTOLEV_FOREGROUND="1")
    try:
        return run_with_values(ident, path, read_model(path), companion, work, limit, {})[1]
    finally:
        for k, v in kept.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


# -- the written programs --------------------------------------------------------------
@dataclass
class ProgramCheck:
    """One written program: what went wrong (empty: nothing), what was compared, and
    what a reader should know about how it was run."""
    problem: str = ""
    compared: str = ""
    remarks: list = field(default_factory=list)


@dataclass
class RunToMatch:
    """The run the written programs are compared with: its folder and values; the same
    run with tolerances 1000 times tighter is made once, when a comparison needs it."""
    model: Path
    work: Path
    values: Values
    shipped_in: Path | None
    limit: float
    tight_folder: Path | None = None
    tight_status: int | None = None     # the tighter run's exit status

    @property
    def folder(self) -> Path:
        return self.work / "run"

    def tight(self) -> Path | None:
        """The folder of the tighter run (None: it wrote nothing); a run that failed
        keeps the rows it wrote before (its integration stopped there)."""
        if self.tight_folder is None:
            self.tight_folder = self.work / "run-tight"
            given = {}
            for f in self.folder.glob("*.in"):
                given.update(in_values(f))
            relerr = _number(given.get("RELERR"), 1e-7)
            abserr = _number(given.get("ABSERR"), 1e-8)
            done = run_process(autolev_cli(
                "run", self.model, "--out", self.tight_folder, "-q", *self.values.options,
                "--set", f"RELERR={relerr * 1e-3:g}", "--set", f"ABSERR={abserr * 1e-3:g}"),
                self.work, self.limit)
            self.tight_status = done.returncode
        return self.tight_folder if self.tight_folder.is_dir() else None


def _number(text, default: float) -> float:
    try:
        return float(str(text).replace("D", "E"))
    except ValueError:
        return default


def code_cell(ident, model: Model, run: RunToMatch, genuine) -> Cell:
    """`autolev code`, then each program written compiled, run and compared."""
    folder = run.work / "code"
    outcome = run_process(autolev_cli("code", run.model, "--out", folder, "-q"), run.work,
                          run.limit)
    cell = classify(ident, "code", outcome, genuine)
    if cell.status != "ok":
        return cell
    kinds = {Path(name.replace("\\", "/")).name.lower(): kind for kind, name in model.code}
    start = time.monotonic()
    programs = sorted(p for p in folder.rglob("*")
                      if p.suffix.lower() in (".c", ".m", ".f", ".for"))
    checks = {p.name: program_check(p, kinds.get(p.name.lower(), ""), run)
              for p in programs}
    cell.seconds += time.monotonic() - start
    problems = [f"{name}: {c.problem}" for name, c in checks.items() if c.problem]
    if not programs:
        problems.append("wrote no program")
    if problems:
        cell.status, cell.reason = "FAIL", "; ".join(problems)
    else:
        cell.reason = "; ".join(f"{name}: {r}" for name, c in checks.items()
                                for r in c.remarks)
    cell.detail = "; ".join(f"{name}: {c.problem or c.compared}"
                            for name, c in checks.items())
    return cell


def program_check(program: Path, kind: str, run: RunToMatch) -> ProgramCheck:
    """Compile and run one written program, and compare its files with the run's.  It
    runs where `autolev code` wrote (a CODE file name's folders are in the names of
    the files it opens)."""
    root = run.work / "code"
    source_name = program.relative_to(root).as_posix()
    suffix = program.suffix.lower()
    text = program.read_text(errors="replace")
    if suffix == ".m":
        return matlab_check(program, kind, run)
    in_name = _input_name(text)
    if in_name is None:
        return ProgramCheck("names no .in file to read")
    shipped = run.shipped_in
    source = shipped if shipped is not None and \
        shipped.name.lower() == Path(in_name).name.lower() \
        else _run_file(run.folder, Path(in_name).name)
    if source is None:
        return ProgramCheck(f"autolev run wrote no {Path(in_name).name}")
    (root / in_name).parent.mkdir(parents=True, exist_ok=True)
    shutil.copy(source, root / in_name)
    check = ProgramCheck()
    if source == shipped:
        check.remarks.append(f"read the shipped {source.name}")
    exe = Path(source_name).with_suffix(".run").as_posix()
    if suffix == ".c":
        cc = compiler()
        if cc is None:
            return ProgramCheck(remarks=["no C compiler: not compiled"])
        build = [cc, "-O0", "-o", exe, source_name, "-lm"]
    else:
        gfortran = shutil.which("gfortran")
        if gfortran is None:
            return ProgramCheck(remarks=["no gfortran: not compiled"])
        if "SUBROUTINE       KUTTA" not in text and "KUTTA" in text:
            n = int(re.search(r"DIMENSION\s+VAR\((\d+)\)", text).group(1))
            program.write_text(text.rstrip("\n") + "\n\n" + "\n".join(kutta_and_solve(n))
                               + "\n")
            check.remarks.append("NOSUBS: our KUTTA and SOLVE appended")
        build = [gfortran, "-O0", "-o", exe, source_name]
    built = run_process(build, root, run.limit)
    if built.returncode != 0:
        check.problem = f"does not compile: {_first_error(built)}"
        return check
    ran = run_process([f"./{exe}"], root, run.limit)
    if ran.returncode is None:
        check.problem = f"did not finish in {run.limit:g} s"
    elif ran.returncode != 0:
        check.problem = f"exit {ran.returncode}: {_last_line(ran.stdout + ran.stderr)}"
    else:
        compare_files(check, (root / in_name).parent, Path(in_name).stem, run,
                      integrated=kind in ("dynamics", "ode"))
    return check


def matlab_check(program: Path, kind: str, run: RunToMatch) -> ProgramCheck:
    """A .m program under Octave, with the values the run used in its table."""
    if octave() is None:
        return ProgramCheck(remarks=["no octave: not run"])
    check = ProgramCheck()
    values = in_values(_run_file(run.folder, program.stem + ".in"))
    shortened = kind == "dynamics" and _shortened(values)
    if shortened:
        # only its first row is compared: an interpreter need not integrate to TFINAL
        check.remarks.append(f"run to TFINAL = {values['TFINAL']} (its first row is "
                             "compared)")
    text = with_table_values(program.read_text(errors="replace"),
                             lambda name: values.get(name.upper()))
    if program.suffix != ".m":
        # Octave finds a function only in a file named .m (a Windows model wrote .M)
        program.unlink()
        check.remarks.append(f"run as {program.stem}.m: Octave reads only .m files")
    program.with_suffix(".m").write_text(text)
    try:
        ran = run_octave(program.stem, program.parent, timeout=run.limit)
    except subprocess.TimeoutExpired:
        check.problem = f"Octave did not finish in {run.limit:g} s"
        return check
    if ran.returncode != 0:
        said = [line for line in ran.stderr.splitlines() if line.startswith("error:")]
        check.problem = f"Octave exit {ran.returncode}: {said[0] if said else ''}"
        return check
    compare_files(check, program.parent, program.stem, run, integrated=False,
                  first_row_only=kind == "dynamics", all_rows_run=not shortened)
    return check


def _shortened(values: dict) -> bool:
    """Cut TFINAL in `values` to two printed steps past TINITIAL; whether it was later."""
    try:
        start = float(values.get("TINITIAL", "0") or 0)
        step = float(values["INTEGSTP"]) * float(values.get("PRINTINT", "1") or 1)
        end = float(values["TFINAL"])
    except (KeyError, ValueError):
        return False
    if not (step > 0 and end > start + 2 * step):
        return False
    values["TFINAL"] = repr(start + 2 * step)
    return True


def _input_name(text: str) -> str | None:
    """The .in file a C or Fortran program opens."""
    m = re.search(r'strcpy\(fileName, "([^"]+)"\)', text) or \
        re.search(r"OPEN\(UNIT=\d+, FILE='([^']+\.in)'", text, re.IGNORECASE)
    return m.group(1) if m else None


def _run_file(run_dir: Path, name: str) -> Path | None:
    """The file of the run's folder with that name, in any case."""
    return next((p for p in run_dir.iterdir() if p.name.lower() == name.lower()), None) \
        if run_dir.is_dir() else None


def in_values(path: Path | None) -> dict:
    """{NAME: value text} of an Autolev .in file (value from column 60)."""
    values = {}
    for line in path.read_text().splitlines() if path else []:
        name = line[21:42].strip()
        if len(line) >= 60 and line[58] == "|" and name[:1].isalpha() \
                and name.lower() != "quantity":
            values[name.upper()] = line[59:].strip()
    return values


def output_files(folder: Path, stem: str) -> dict:
    """{lower-case name: path} of the files NAME.1, NAME.2 ... in the folder."""
    out = {}
    for p in folder.iterdir() if folder.is_dir() else []:
        name = p.name.lower()
        if name.startswith(stem.lower() + ".") and name[len(stem) + 1:].isdigit():
            out[name] = p
    return out


def first_parting(a, b) -> tuple[int, int, float] | None:
    """(row, column, difference) where two tables of the same shape first part by more
    than TOLERANCE of the column's largest magnitude in `b` (at least 1e-6 of the
    file's largest, as bench/truth.py's column_errors); None when they never do."""
    scale = np.maximum(np.nanmax(np.abs(b), axis=0, initial=0.0),
                       1e-6 * np.nanmax(np.abs(b), initial=0.0))
    scale[scale == 0] = 1.0
    d = np.abs(a - b) / scale
    d[np.isnan(a) & np.isnan(b)] = 0.0
    d[np.isnan(d)] = np.inf
    bad = np.argwhere(d > TOLERANCE)
    if not len(bad):
        return None
    row, col = bad[0]
    return int(row), int(col), float(d[row].max())


def _run_parts_at(run: RunToMatch, stem: str, theirs: dict, tight: Path) -> int | None:
    """The first row where any of the run's files of `stem` parts from the tighter run's
    (None: none does).  Its files are one integration's: a file of aggregates (energy,
    momentum) may stay close past the row where the state itself has parted, and its
    later rows depend on the integration error as much as the state's."""
    rows = []
    for name, path in output_files(tight, stem).items():
        if name not in theirs:
            continue
        b, fine = read_table(theirs[name]), read_table(path)
        if run.tight_status != 0:   # it failed: its last row is where it stopped
            fine = fine[:-1]
        common = min(len(fine), len(b))
        own = first_parting(b[:common], fine[:common]) \
            if fine.shape[1:] == b.shape[1:] else None
        if own is not None:
            rows.append(own[0])
    return min(rows, default=None)


def compare_files(check: ProgramCheck, here: Path, stem: str, run: RunToMatch,
                  integrated: bool, first_row_only: bool = False,
                  all_rows_run: bool = True) -> None:
    """The program's output files against the run's, within TOLERANCE (the first row and
    the number of rows only, for `first_row_only`; the first row alone where the program
    was not run to the run's TFINAL, not `all_rows_run`).  An integrated file may part after
    the row where the run itself parts from a run with tolerances 1000 times tighter:
    there the integration error decides the digits (bench/truth.py's rule)."""
    ours, theirs = output_files(here, stem), output_files(run.folder, stem)
    singular: list = []
    if set(ours) != set(theirs):
        check.problem = (f"the program wrote {', '.join(sorted(ours)) or 'no file'}, "
                         f"autolev run {', '.join(sorted(theirs)) or 'no file'}")
        return
    trusted = []
    run_parts: list = []        # where the run parts from the tighter one (once)
    for name in sorted(theirs):
        a, b = read_table(ours[name]), read_table(theirs[name])
        if not all_rows_run and a.size and b.size and a.shape[1] == b.shape[1]:
            a, b = a[:1], b[:1]
        if a.shape != b.shape:
            check.problem = (f"{name}: {a.shape[0]} rows of {a.shape[1] if a.size else 0} "
                             f"values; autolev run's {b.shape[0]} of "
                             f"{b.shape[1] if b.size else 0}")
            return
        if first_row_only:
            a, b = a[:1], b[:1]
        parting = first_parting(a, b) if b.size else None
        tight = run.tight() if parting is not None and integrated and parting[0] > 0 \
            else None
        fine = output_files(tight, stem).get(name) if tight else None
        if fine is not None:
            fine = read_table(fine)
            if run.tight_status != 0:   # it failed: its last row is where it stopped
                fine = fine[:-1]
            if not run_parts:
                run_parts.append(_run_parts_at(run, stem, theirs, tight))
            own = run_parts[0]
            if own is not None and own <= parting[0]:
                trusted.append(own)
                parting = first_parting(a[:max(own, 1)], b[:max(own, 1)])
            elif run.tight_status != 0 and parting[0] >= len(fine):
                # the tighter run stops there: the motion passes a state no step size
                # integrates, and the rows after it depend on how it was stepped over
                singular.append(len(fine) + 1)
                parting = first_parting(a[:len(fine)], b[:len(fine)])
        if parting is not None:
            row, col, diff = parting
            check.problem = (f"{name} column {col + 1} differs by {diff:.2g} of its largest "
                             f"value from row {row + 1} (where column 1 is {b[row, 0]:.6g})")
            return
    what = ("first rows" if not all_rows_run else "first rows and row counts"
            if first_row_only else "files")
    check.compared = f"{len(theirs)} {what} equal to {TOLERANCE:g}"
    if singular:
        check.remarks.append(
            f"{SINGULAR} (row {min(singular)}): the rows after it are not compared")
    if trusted:
        check.remarks.append(
            f"equal to {TOLERANCE:g} up to where the run itself parts from one with "
            f"tolerances 1000 times tighter (row {min(trusted) + 1} at the earliest)")


# -- the models ------------------------------------------------------------------------
def companions(listing: Path) -> dict:
    """{model id: [(model's path, .in's path) in the repository]} of the rows of kind
    `in` (their companion_of names the model)."""
    rows = list(csv.DictReader(open(listing), delimiter="\t"))
    where = {r.get("id"): r["path"] for r in rows}
    found: dict = {}
    for r in rows:
        if r["kind"] == "in" and r.get("companion_of") in where:
            found.setdefault(r["companion_of"], []).append((where[r["companion_of"]],
                                                            r["path"]))
    return found


def nearest(model: Path, shipped: list) -> Path | None:
    """The .in (of `companions`) that exists beside the model's copy (its overlay, for a
    pinned model), in the folder nearest the model's: the longest common part of the
    two, then the fewest folders below it."""
    def shared(p: Path) -> int:
        n = 0
        for a, b in zip(model.parent.parts, p.parent.parts):
            if a != b:
                break
            n += 1
        return n
    files = []
    for model_path, in_path in shipped:
        root = model.parents[len(Path(model_path).parts) - 1]
        if (root / in_path).is_file():
            files.append(root / in_path)
    return max(files, key=lambda p: (shared(p), -len(p.parts))) if files else None


def chosen_models(ns) -> list[tuple[str, Path, Path | None]]:
    """(id, path, companion .in) of the models asked for."""
    if ns.examples:
        models = [(p.stem, p, None) for p in sorted(EXAMPLES.glob("*.al"))]
    else:
        found = companions(ns.listing)
        models = [(ident, path, nearest(path, found.get(ident, [])))
                  for ident, path in corpus_models(ns.corpus, ns.listing)]
    if ns.only:
        models = [m for m in models if any(o in m[0] for o in ns.only)]
    return models


def run_all(models, limit: float, jobs: int, keep: Path | None = None, genuine=None,
            progress=None, each=None) -> list[Journey]:
    """Every model's journey, `jobs` at a time; `each(journeys done so far)` after each
    (the order of `models`)."""
    done: dict = {}
    lock = threading.Lock()

    def one(item):
        ident, path, companion = item
        if keep is not None:
            work = keep / re.sub(r"[^\w.-]", "_", ident)
            shutil.rmtree(work, ignore_errors=True)
            work.mkdir(parents=True)
            finished = journey(ident, path, companion, limit, work, genuine)
        else:
            with tempfile.TemporaryDirectory(prefix="journey-") as tmp:
                finished = journey(ident, path, companion, limit, Path(tmp), genuine)
        with lock:
            done[ident] = finished
            if progress is not None:
                print(f"  {ident}: " + " ".join(finished.cells[c].status for c in COMMANDS)
                      + f" ({finished.seconds:.0f} s)", file=progress, flush=True)
            if each is not None:
                each([done[m[0]] for m in models if m[0] in done])
        return finished
    with ThreadPoolExecutor(jobs) as pool:
        return list(pool.map(one, models))


# -- the report ------------------------------------------------------------------------
SHORT = {"check": "check", "convert": "convert", "run": "run", "code": "code",
         "linearize": "linearize", "animate": "animate", "transcript": "transcr.",
         "verify": "verify"}


def table(journeys: list[Journey]) -> str:
    """One row per model, a short word per command; the reasons below."""
    width = max([len(j.ident) for j in journeys] + [5])
    lines = [f"{'model':{width}s}  " + " ".join(f"{SHORT[c]:9s}" for c in COMMANDS)]
    for j in journeys:
        lines.append(f"{j.ident:{width}s}  "
                     + " ".join(f"{j.cells[c].status:9s}" for c in COMMANDS).rstrip())
    notes = [f"  {j.ident} {c}: {j.cells[c].status}: {j.cells[c].reason.splitlines()[0]}"
             for j in journeys for c in COMMANDS
             if j.cells[c].status in ("FAIL", "genuine")
             or (j.cells[c].status == "ok" and j.cells[c].reason)]
    if notes:
        lines += ["", "not ok, or ok with a note:"] + notes
    return "\n".join(lines)


def summary(journeys: list[Journey]) -> dict:
    """{command: {status: count}}."""
    out = {}
    for c in COMMANDS:
        counts = {s: 0 for s in ("ok", "genuine", "FAIL", "skipped", "-")}
        for j in journeys:
            counts[j.cells[c].status] += 1
        out[c] = counts
    return out


def summary_lines(counts: dict) -> list[str]:
    return [f"{c:10s} {n['ok']:4d} ok {n['genuine']:3d} genuine {n['FAIL']:4d} FAIL "
            f"{n['skipped']:4d} skipped {n['-']:4d} not applicable"
            for c, n in counts.items()]


def as_json(journeys: list[Journey], seconds: float, ns, asked: int) -> dict:
    """The report: every cell of the `journeys` done of the `asked`."""
    commit = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True,
                            text=True).stdout.strip()
    dirty = bool(subprocess.run(["git", "status", "--porcelain", "--", "src"], cwd=ROOT,
                                capture_output=True, text=True).stdout.strip())
    return {"commit": commit, "src_changed_since_commit": dirty,
            "date": datetime.datetime.now().isoformat(timespec="seconds"),
            "limit_seconds": ns.limit, "jobs": ns.jobs, "tolerance": TOLERANCE,
            "tools": {"cc": compiler(), "gfortran": shutil.which("gfortran"),
                      "octave": octave()},
            "seconds": round(seconds, 1), "models_asked": asked,
            "summary": summary(journeys),
            "models": {j.ident: {"path": j.path, "values": j.values,
                                 "seconds": round(j.seconds, 1),
                                 "cells": {c: dict(asdict(j.cells[c]),
                                                   seconds=round(j.cells[c].seconds, 2))
                                           for c in COMMANDS}}
                       for j in journeys}}


def changes(old: dict, new: dict) -> list[str]:
    """What changed between two --json reports: new failures, fixed cells, others."""
    groups = {"new failures": [], "fixed": [], "other changes": []}
    for ident in sorted(set(old["models"]) | set(new["models"])):
        if ident not in new["models"] or ident not in old["models"]:
            groups["other changes"].append(
                f"  {ident}: only in the {'old' if ident in old['models'] else 'new'} run")
            continue
        for c in COMMANDS:
            a = old["models"][ident]["cells"][c]
            b = new["models"][ident]["cells"][c]
            if a["status"] == b["status"]:
                continue
            line = f"  {ident} {c}: {a['status']} -> {b['status']}"
            if b["status"] == "FAIL":
                groups["new failures"].append(f"{line}: {b['reason']}")
            elif a["status"] == "FAIL":
                groups["fixed"].append(f"{line} (was: {a['reason']})")
            else:
                groups["other changes"].append(line)
    out = []
    for title, lines in groups.items():
        out.append(f"{title}: {len(lines)}")
        out += lines
    return out


def parse_args(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--corpus", type=Path, default=CORPUS)
    ap.add_argument("--listing", type=Path, default=LISTING,
                    help="the corpus's TSV (default shared/corpus/visible.tsv)")
    ap.add_argument("--examples", action="store_true",
                    help="the shipped autolev_examples/*.al instead of the corpus")
    ap.add_argument("--only", action="append", metavar="ID",
                    help="models whose id contains ID (repeatable)")
    ap.add_argument("--jobs", type=int, default=2, help="models at a time (default 2)")
    ap.add_argument("--limit", type=float, default=600,
                    help="seconds per command (default 600)")
    ap.add_argument("--json", type=Path, metavar="FILE", help="write every cell there")
    ap.add_argument("--compare", type=Path, metavar="OLD.json",
                    help="print what changed since that --json report")
    ap.add_argument("--keep", type=Path, metavar="DIR",
                    help="keep each model's working folder under DIR")
    return ap.parse_args(argv)


def main(argv=None) -> int:
    ns = parse_args(argv)
    if not ns.examples and not ns.listing.exists():
        print(f"no listing {ns.listing}: give --listing, or --examples", file=sys.stderr)
        return 2
    models = chosen_models(ns)
    if not models:
        print("no model found (see --corpus, --listing, --only)", file=sys.stderr)
        return 2
    start = time.monotonic()

    def write(journeys):
        if ns.json:     # after each model: a long run stopped early keeps what it did
            report = as_json(journeys, time.monotonic() - start, ns, len(models))
            ns.json.write_text(json.dumps(report, indent=1) + "\n")
    journeys = run_all(models, ns.limit, ns.jobs, ns.keep, progress=sys.stderr, each=write)
    seconds = time.monotonic() - start
    print(table(journeys))
    print()
    print("\n".join(summary_lines(summary(journeys))))
    print(f"{len(journeys)} model{'' if len(journeys) == 1 else 's'} in {seconds:.0f} s")
    report = as_json(journeys, seconds, ns, len(models))
    if ns.compare:
        print("\n".join(changes(json.loads(ns.compare.read_text()), report)))
    return 1 if any(j.cells[c].status == "FAIL" for j in journeys for c in COMMANDS) else 0


if __name__ == "__main__":
    sys.exit(main())
