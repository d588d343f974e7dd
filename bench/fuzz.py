#!/usr/bin/env python3
"""Fuzzing: no input may end in a Python traceback, a hang, a blown memory limit, a file
written or read outside its place, or a wrong answer.

Eight modes.

mutation (the default): takes the models of the public corpus (or, without it, the
project's own examples), mutates them (characters and lines deleted, inserted,
duplicated; seeded), parses each mutant with `autolev.parse` and counts the outcomes:

  parsed     the mutant is still valid Autolev
  diagnosed  AutolevSyntaxError with well-formed diagnostics (line/col inside the file)
  crash      anything else: a bug (the traceback is printed)

grammar: generates random well-formed models, each tagged with its generator:

  model     declarations and statements using the names declared before them
  nesting   parentheses, calls, unary minus and powers nested up to a few hundred deep
  long      sums, products, `&` continuation lines, lists of hundreds to thousands
  literals  huge numbers, exponent towers, big FACTORIAL/TAYLOR orders, huge ranges
  hostile   names and file names that collide with Python or the tool, quotes,
            backslashes, control characters, non-ASCII; escape attempts in CODE/RUN

files: a model with several files beside it, loaded (and now and then `autolev check`ed
with its files), each case tagged with what it is mostly about:

  runs       RUN files that RUN each other: fan-out, chains of up to thousands of
             inclusions and far beyond, cycles, sub-folders, names in another case
  macros     macros (.a) that call each other with arguments, now and then themselves
  functions  user functions (.r) that call each other, in their own arguments too
  stray      files named as Autolev's own commands and functions (gravity.a, cos.r,
             kane.a, ...) with random content: the model's translation must be the
             one without them
  links      links in the model's folder to files outside it, to itself, to nothing

commands: a model -- a shipped example, a pendulum or spring chain, a generated model,
a corpus model, each lightly retouched and its CODE file names chosen (sub-folders,
odd and hostile names) -- run through `autolev code` (each C program written then
compiled and linked with cc), `run`, `animate --format html` and `transcript`, all
with --out into the case's output folder, where things were planted at the names they
write: links to a victim's files and folder outside, links to nothing and to
themselves, a hard link to a victim's file, a user's own file, a folder, a FIFO.

threads: two or three small models (pendulums, spring chains; constants drawn at
random) each swept (Model.sweep: linearize or simulate, a few points) from its own
thread at once: on worker processes, on a shared thread pool or process pool, loaded
in the thread or before; now and then one more afterwards on workers forked from the
worker.  Each table must be the one the same sweep gives alone in one process.

stale: a command run on a small model, ONE input changed at a random moment (an .in
value, a statement, a macro or RUN file, --set, --specified, a number knob, a file
added), the command run twice more: each answer must be a fresh run's of the final
inputs in an empty cache (bench/fuzz_stale.py says how; outcomes stale and error).

background: a cold `autolev run --out` on a small model and ONE fault at a random moment:
a signal to the command or to its background child (SIGINT, SIGTERM, SIGHUP, SIGKILL,
SIGSTOP or SIGTSTP then SIGCONT), a terminal with `stty tostop` (left alone, ^C, ^Z and
fg, a hang-up), the cache folder removed, read-only or a file, the config folder
read-only or the cache key cut short; then a recovery run, held against a fresh run in
an empty cache (bench/fuzz_background.py says how; outcomes leaked, leftover, wrong).

hostile: a FIFO, a folder, a device or a terminal behind a link, a socket, an unreadable
file, a link to itself where a command reads (the model, an --in file, a RUN, macro or
function file, a session) or writes (an output's name), under check, run, code,
convert, linearize, transcript, verify and animate --format html: each command ends
within seconds, with a message naming the file, writing nothing through the object nor
outside its output folder, leaving no process (bench/fuzz_hostile.py).

Each case is written (under its own file name) into a private folder of a long-lived
worker subprocess, which parses, translates and loads it (`autolev.parse`,
`autolev.translation`, `autolev.loader.load_translation`), or runs its commands
(`autolev.cli.main`, in the worker) or its sweeps, under a memory limit (RLIMIT_AS);
the parent enforces the time limit, kills a worker that exceeds it (with what it
started) and starts a fresh one.  autolev's own state (its cache, key and record of
the files it wrote) lives in the run's folder, never the user's.  Outcomes:

  ok         the model loaded, the command exited 0, the sweeps agreed
  diagnosed  an AutolevError with well-formed diagnostics (line/col >= 1, a message);
             a command's exit status 1 or 2 with a message
  crash      any other exception, exit status 70 or a traceback, or a worker that died
             otherwise (the first ones are printed with the case, then one line each)
  hang       over the time limit
  memory     MemoryError, or the worker was killed (over the memory limit)
  escaped    a file appeared outside the case's folder (grammar: any new file in the
             worker's own folders, or one the case names in the temp folder, the
             repository or the home folder); files: any file outside the case's folder
             read (an audit hook on open) or anything outside it changed; commands:
             anything written outside the output folder, a victim changed above all
  clobbered  commands: a user's own file (not a link) at an output's name replaced by
             a command without --overwrite
  leftover   commands: a temporary (a hidden file) left by a command that was not killed
  wrong      files: stray files changed the model's translation; commands: a C program
             autolev wrote does not compile; threads: a table that is not the sweep's
             own (the model whose rows it holds is named)
  leaked     background, hostile: a process of the case alive after its command and its
             background child ended

Each case has its own random stream (from the mode, the seed and its index), so
`--replay` regenerates it alone.  A table follows: one row per mode and seed (wall
time; "-" marks what a mode does not measure; for mutants "ok" counts those that
parsed), then one row per seed and generator (summed case times); and the three
slowest cases of each mode and seed.  The exit status is 1 on any failure.

    python bench/fuzz.py [--mutants 10000] [--seed 1] [--corpus DIR]
    python bench/fuzz.py --mode grammar|files|commands|threads|stale|background|hostile|all
                         (or several,
                         comma-separated) [--cases 10000] [--seeds 1,2] [--jobs 1]
                         [--minutes M] [--timeout S] [--memory-mb 2048]
    python bench/fuzz.py --replay SEED:INDEX > case.al   # one grammar case's source
    python bench/fuzz.py --mode M --replay SEED:INDEX [--into DIR]
        # a case of mode M run alone, its outcome shown; or its files written into DIR
        # (DIR/case, DIR/outside) and its commands printed

One file over 600 lines on purpose: the script is also its own worker subprocess
(`--worker`), which must run from a checkout with nothing of the bench but itself (and
the modules of the later modes beside it: fuzz_stale.py, fuzz_background.py,
fuzz_hostile.py).
"""
from __future__ import annotations

import argparse
import contextlib
import csv
import hashlib
import io
import json
import math
import os
import random
import re
import resource
import select
import shlex
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import time
import traceback
from collections import Counter, deque
from dataclasses import asdict, dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

import autolev  # noqa: E402

if str(Path(__file__).resolve().parent) not in sys.path:     # loaded by path (the tests)
    sys.path.append(str(Path(__file__).resolve().parent))
import fuzz_background  # noqa: E402
import fuzz_hostile  # noqa: E402
import fuzz_stale  # noqa: E402

# characters that matter to the lexer, plus some that never should appear
ALPHABET = ("abcdefghijklmnopqrstuvwxyzQ0123456789 \t\n\r&%'><=+-*/^()[]{},;:._#$\\\"!?@~`|"
            "\x00\x1aé\u00a0")


def mutate(text: str, rng: random.Random) -> str:
    """Apply 1-4 random edits: delete, insert or duplicate a character or a line."""
    for _ in range(rng.randint(1, 4)):
        op = rng.randrange(6)
        if op < 3 or not text:
            pos = rng.randint(0, len(text))
            if op == 0 and text:
                pos = min(pos, len(text) - 1)
                text = text[:pos] + text[pos + 1:]
            elif op == 1 or not text:
                text = text[:pos] + rng.choice(ALPHABET) + text[pos:]
            else:
                pos = min(pos, len(text) - 1)
                text = text[:pos] + text[pos] + text[pos:]
        else:
            lines = text.split("\n")
            i = rng.randrange(len(lines))
            if op == 3:
                del lines[i]
            elif op == 4:
                lines.insert(i, lines[rng.randrange(len(lines))])
            else:
                j = rng.randrange(len(lines))
                lines[i], lines[j] = lines[j], lines[i]
            text = "\n".join(lines)
    return text


def diagnostics_problem(exc: autolev.AutolevError, filename: str, text: str) -> str | None:
    """What is wrong with the diagnostics an AutolevError carries (None: nothing)."""
    diagnostics = getattr(exc, "diagnostics", None)
    if diagnostics is None:
        return None if str(exc) else f"{type(exc).__name__} without a message"
    n_lines = text.count("\n") + text.count("\r") + 1
    for d in diagnostics:
        if d.line < 1 or d.col < 1 or (d.file == filename and d.line > n_lines + 1):
            return f"diagnostic outside the file: {d.format()}"
        if not d.message:
            return f"empty message: {d!r}"
    if not any(d.severity == "error" for d in diagnostics):
        return f"{type(exc).__name__} without an error diagnostic"
    return None


def check_one(text: str, filename: str) -> tuple[str, str | None]:
    """('parsed' | 'diagnosed' | 'crash', traceback or problem)."""
    try:
        autolev.parse(text, filename)
    except autolev.AutolevSyntaxError as exc:
        problem = diagnostics_problem(exc, filename, text)
        return ("crash", problem) if problem else ("diagnosed", None)
    except Exception:  # noqa: BLE001 -- the point of a fuzzer is to catch everything
        return "crash", traceback.format_exc()
    return "parsed", None


def corpus_models(corpus: Path) -> list[Path]:
    # the listing beside the lead's tree (/work/main -> /work/shared), else every .al
    listing = ROOT.parent / "shared" / "corpus" / "visible.tsv"
    out = []
    if not listing.exists():
        return sorted(p for p in corpus.rglob("*") if p.suffix.lower() == ".al" and
                      p.is_file())
    for row in csv.DictReader(open(listing), delimiter="\t"):
        if row["kind"] == "al" and not row["path"].lower().endswith(".a"):
            p = corpus / row["repo"].replace("/", "+") / row["path"]
            if p.exists():
                out.append(p)
    return sorted(set(out))


def seeds(corpus: Path | None) -> list[Path]:
    found = corpus_models(corpus) if corpus is not None and corpus.is_dir() else []
    if not found:
        found = sorted((ROOT / "autolev_examples").glob("*.al")) + \
            sorted((ROOT / "tests" / "data").glob("*.al"))
    return found


def mutation_run(n: int, seed: int, files: list[Path],
                 quiet: bool = False) -> tuple[Counter, float]:
    """The outcomes of n mutants, and the slowest mutant's seconds."""
    rng = random.Random(seed)
    texts = [(f, f.read_bytes().decode("latin-1")) for f in files]
    outcomes: Counter = Counter()
    shown = 0
    slowest = 0.0
    for _ in range(n):
        path, text = texts[rng.randrange(len(texts))]
        mutant = mutate(text, rng)
        t0 = time.perf_counter()
        outcome, detail = check_one(mutant, str(path))
        slowest = max(slowest, time.perf_counter() - t0)
        outcomes[outcome] += 1
        if outcome == "crash" and shown < 3 and not quiet:
            shown += 1
            print(f"--- crash on a mutant of {path}:\n{detail}", file=sys.stderr)
    return outcomes, slowest


def run(n: int, seed: int, files: list[Path], quiet: bool = False) -> Counter:
    return mutation_run(n, seed, files, quiet)[0]


# ---------------------------------------------------------------------------------
# Grammar mode: the generators

GENERATORS = ("model", "nesting", "long", "literals", "hostile")
GENERATOR_WEIGHTS = (40, 15, 15, 15, 15)

# names the model generator never makes up: Autolev's functions, commands and keywords
_AUTOLEV_WORDS = set("""
ABS ACOS ACOSH ARRANGE ASIN ASINH ATAN ATAN2 ATANH AUTOZ CEIL CM COEF COLS COS COSH COT
CROSS CSC D DET DIAGMAT DOT DT DYADIC EIG ELEMENT EPSILON EVALUATE EXCLUDE EXP EXPAND
EXPLICIT EXPRESS FACTOR FACTORIAL FLOOR FR FRSTAR GYROSTAT INCLUDE INERTIA INPUT INT INV
INVERSE KE LOG LOG10 MAG MASS MATRIX MAX MIN MOMENTUM NICHECK PARTIALS POLYNOMIAL REPLACE
RHS ROOTS ROUND ROWS SEC SIGN SIMPLIFY SIN SINH SQR SQRT TAN TANH TAYLOR TRACE TRANSPOSE
UNITS UNITVEC VECTOR ZEE SIMPROT DIRCOS KINDIFFS ANGVEL GRAVITY FORCE TORQUE CONSTRAIN
CONSTRAINT KANE SOLVE ANIMATE V2PTS V1PT A2PTS A1PT T PI ZERO DEPENDENT AUXILIARY
NEWTONIAN FRAME FRAMES BODY BODIES PARTICLE PARTICLES POINT POINTS CONSTANT CONSTANTS
VARIABLE VARIABLES MOTIONVARIABLE MOTIONVARIABLES SPECIFIED SPECIFIEDS IMAGINARY OUTPUT
OUTPUTS INPUTS UNITSYSTEM CODE SAVE ENCODE RUN EXIT QUIT AUTORHS AUTOEPSILON AUTOEXPRESS
COMPLEX DEGREES DIGITS FACTORING OVERWRITE BEEPSOUND PAUSE ON OFF ALL
""".split())

_ELEMENTARY = ("SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SINH", "COSH", "TANH", "EXP",
               "LOG", "SQRT", "ABS", "SIGN", "SQR", "LOG10", "CEIL", "FLOOR", "SEC", "CSC",
               "COT", "ASINH", "ACOSH", "ATANH", "INT", "ROUND")
_UNITS = ("m", "kg", "sec", "s", "deg", "rad", "rad/sec", "m/s", "N", "N*m", "kg*m^2",
          "m/sec^2", "joules", "deg/s", "UNITS")


@dataclass
class Case:
    """One generated model: its source and the name of its file; in the modes beyond
    grammar, the files around it and what is done with it.  '@OUTSIDE@' in any text or
    link stands for the folder beside the case's own (victims and bait live there)."""

    index: int
    generator: str
    filename: str
    text: str
    mode: str = "grammar"
    # files mode and commands mode: other files in the case's folder (relative path: text)
    files: dict = field(default_factory=dict)
    # planted things (relative path: [kind, target]): "symlink" (target: the link's text,
    # '@SELF@' its own name),
    # "hardlink" (target: a file outside), "file" (target: its text), "dir", "fifo"
    links: dict = field(default_factory=dict)
    outside: dict = field(default_factory=dict)     # files outside the case's folder
    strays: list = field(default_factory=list)      # files named as Autolev's own words
    commands: list = field(default_factory=list)    # autolev's arguments, per command
    sweeps: list = field(default_factory=list)      # threads mode: one per thread
    change: dict = field(default_factory=dict)      # stale mode: what changes, when


def log_uniform(rng: random.Random, lo: int, hi: int) -> int:
    """An integer in [lo, hi], small ones as likely per decade as large ones."""
    return min(hi, max(lo, round(math.exp(rng.uniform(math.log(lo), math.log(hi))))))


def _letters(n: int) -> str:
    out = ""
    while n:
        n, r = divmod(n - 1, 26)
        out = chr(65 + r) + out
    return out


def _grouped(text: str) -> str:
    """text as an operand of *, / or ^ (written with spaces around + and -)."""
    return f"({text})" if " " in text else text


class ModelWriter:
    """A random model whose statements mostly use the names declared before them."""

    def __init__(self, rng: random.Random):
        self.rng = rng
        self.lines: list[str] = []
        self.count = 0
        self.newtonian: str | None = None
        self.frames: list[str] = []         # the Newtonian frame, frames and bodies
        self.bodies: list[str] = []
        self.particles: list[str] = []
        self.points: list[str] = []         # points, particles and origins
        self.located: list[str] = []        # points with a position from the origin
        self.constants: list[str] = []
        self.variables: dict[str, int] = {}  # name: primes declared
        self.coordinates: list[str] = []
        self.speeds: list[str] = []
        self.specified: list[str] = []
        self.scalars: dict[str, str] = {}   # name assigned a scalar: its definition
        self.vectors: list[str] = []        # names assigned a vector (with the >)
        self.matrices: dict[str, tuple[int, int]] = {}
        self.inputs: list[str] = []

    def fresh(self, prefix: str) -> str:
        while True:
            self.count += 1
            name = prefix + _letters(self.count)
            if name.upper() not in _AUTOLEV_WORDS:
                return name

    def emit(self, line: str) -> None:
        r = self.rng.random()
        if r < 0.05:
            line += ";"
        elif r < 0.1:
            line += "   % " + self.rng.choice(("a comment", "units: m", "&", "%%", "'"))
        self.lines.append(line)
        if self.rng.random() < 0.04:
            self.lines.append(self.rng.choice(("", "% comment line", "   ")))

    def text(self) -> str:
        return "\n".join(self.lines) + ("\n" if self.rng.random() < 0.9 else "")

    # -- declarations --------------------------------------------------------------
    def declare(self, newtonian: bool = False) -> None:
        """The declarations; `newtonian`: always a Newtonian frame (else now and then
        none, which a model may lack)."""
        r = self.rng
        if newtonian or r.random() < 0.97:
            self.newtonian = "N" if r.random() < 0.6 else self.fresh("N")
            self.emit(f"NEWTONIAN {self.newtonian}")
            self.frames.append(self.newtonian)
            self.points.append(self.newtonian + "O")
            self.located.append(self.newtonian + "O")
        for keyword, prefix in (("FRAMES", "F"), ("BODIES", "B"), ("PARTICLES", "P"),
                                ("POINTS", "O")):
            if r.random() < 0.6:
                names = [self.fresh(prefix) for _ in range(r.randint(1, 3))]
                self.emit(f"{keyword} {', '.join(names)}")
                if keyword in ("FRAMES", "BODIES"):
                    self.frames.extend(names)
                    self.points.extend(n + "O" for n in names)
                else:
                    self.points.extend(names)
                if keyword == "BODIES":
                    self.bodies.extend(names)
                if keyword == "PARTICLES":
                    self.particles.extend(names)
        self.declare_motion()
        self.declare_constants()
        if r.random() < 0.5:
            items = []
            for _ in range(r.randint(1, 3)):
                name, primes = self.fresh("X"), r.randint(0, 3)
                self.variables[name] = primes
                items.append(name + "'" * primes)
            self.emit("VARIABLES " + ", ".join(items))
        if r.random() < 0.3:
            name = self.fresh("S")
            self.specified.append(name)
            self.emit(f"SPECIFIED {name}")
        if r.random() < 0.3:
            self.input_statement()

    def declare_motion(self) -> None:
        r = self.rng
        n = r.randint(1, 3)
        q, u = self.fresh("Q"), self.fresh("U")
        qs, us = [f"{q}{i}" for i in range(1, n + 1)], [f"{u}{i}" for i in range(1, n + 1)]
        form = r.randrange(3)
        if form == 0:
            self.emit(f"MOTIONVARIABLES' {q}{{{n}}}', {u}{{{n}}}'")
        elif form == 1:
            self.emit(f"VARIABLES {q}{{1:{n}}}'")
            self.emit(f"MOTIONVARIABLES' {u}{{{n}}}'")
        else:
            self.emit(f"VARIABLES {', '.join(x + chr(39) for x in qs)}, {u}{{{n}}}'")
        self.coordinates, self.speeds = qs, us
        for name in qs + us:
            self.variables[name] = 1

    def declare_constants(self) -> None:
        r = self.rng
        items = []
        for _ in range(r.randint(1, 5)):
            name = self.fresh("K")
            form = r.randrange(6)
            if form < 2:
                n = r.randint(1, 3)
                items.append(f"{name}{{1:{n}}}" if form == 0 else f"{name}{{{n}}}")
                self.constants.extend(f"{name}{i}" for i in range(1, n + 1))
            elif form == 2:
                items.append(f"{name}{r.choice('+-')}")
                self.constants.append(name)
            elif form == 3:
                items.append(f"{name} = {self.number()}")
                self.constants.append(name)
            else:
                items.append(name)
                self.constants.append(name)
        self.emit("CONSTANTS " + ", ".join(items))

    # -- expressions ---------------------------------------------------------------
    def number(self) -> str:
        r = self.rng
        return r.choice((str(r.randint(0, 12)), f"{r.randint(1, 99)}.{r.randint(0, 9)}",
                         f"{r.randint(1, 9)}.0E-{r.randint(1, 8)}", ".5", "9.81", "1E3"))

    def quantity(self) -> str:
        """A declared or assigned scalar name (a number when there is none)."""
        r = self.rng
        pools = [p for p in (self.constants, list(self.variables), list(self.scalars),
                             self.specified) if p]
        if not pools or r.random() < 0.1:
            return self.number()
        name = r.choice(r.choice(pools))
        primes = self.variables.get(name, 0)
        if primes and r.random() < 0.3:
            name += "'" * r.randint(1, primes)
        return name

    def symbol(self) -> str:
        """A declared constant or variable (something to differentiate by)."""
        pool = self.constants + list(self.variables)
        return self.rng.choice(pool) if pool else "T"

    def frame(self) -> str:
        return self.rng.choice(self.frames) if self.frames else "N"

    def scalar(self, depth: int = 0) -> str:
        r = self.rng
        if depth > 3 or r.random() < 0.3:
            return self.scalar_atom()
        a = self.scalar(depth + 1)
        choice = r.randrange(22)
        if choice < 3:
            return f"{a} {r.choice('+-')} {self.scalar(depth + 1)}"
        if choice < 5:
            return f"{_grouped(a)}{r.choice('*/')}{_grouped(self.scalar(depth + 1))}"
        if choice == 5:
            return f"({a})"
        if choice == 6:
            return f"-{_grouped(a)}"
        if choice == 7:
            return f"{_grouped(a)}^{r.choice(('2', '3', '-1', '0.5', '(1/3)', '-2'))}"
        if choice < 11:
            return f"{r.choice(_ELEMENTARY)}({a})"
        if choice == 11:
            return f"{r.choice(('ATAN2', 'MAX', 'MIN'))}({a}, {self.scalar(depth + 1)})"
        if choice == 12:
            return f"DOT({self.vector(depth + 1)}, {self.vector(depth + 1)})"
        if choice == 13:
            return f"MAG({self.vector(depth + 1)})"
        if choice == 14:
            return f"D({a}, {self.symbol()})"
        if choice == 15:
            return r.choice((f"DT({a})", f"EXPLICIT({a})", f"EXPAND({a})",
                             f"FACTOR({a}, {self.symbol()})", f"SIMPLIFY({a})"))
        if choice == 16:
            return f"COEF({a}, {self.symbol()})"
        if choice == 17:
            return r.choice((f"EVALUATE({a}, {self.symbol()} = {self.number()})",
                             f"REPLACE({a}, {self.symbol()} = {self.scalar(depth + 1)})"))
        if choice == 18:
            return f"TAYLOR({a}, 0:{r.randint(1, 3)}, {self.symbol()} = 0)"
        if choice == 19 and self.matrices:
            name, (rows, cols) = r.choice(sorted(self.matrices.items()))
            if rows == cols:
                return f"{r.choice(('DET', 'TRACE'))}({name})"
            return f"ELEMENT({name}, {r.randint(1, rows)}, {r.randint(1, cols)})"
        if choice == 20:
            known = [f"INPUT({x})" for x in self.inputs] + [f"RHS({x})" for x in self.scalars]
            return r.choice(["KE()", "MASS()", f"FACTORIAL({r.randint(0, 20)})"] + known)
        return f"{a} {r.choice('+-')} {self.scalar_atom()}"

    def scalar_atom(self) -> str:
        r = self.rng
        choice = r.random()
        if choice < 0.65:
            return self.quantity()
        if choice < 0.8:
            return self.number()
        if choice < 0.85:
            return r.choice(("PI", "T"))
        if self.matrices:
            name, (rows, cols) = r.choice(sorted(self.matrices.items()))
            if cols == 1:
                return f"{name}[{r.randint(1, rows)}]"
            return f"{name}[{r.randint(1, rows)}, {r.randint(1, cols)}]"
        return self.quantity()

    def unit_vector(self) -> str:
        return f"{self.frame()}{self.rng.randint(1, 3)}>"

    def vector(self, depth: int = 0) -> str:
        r = self.rng
        if depth > 3 or r.random() < 0.3:
            return self.vector_atom()
        choice = r.randrange(12)
        if choice < 3:
            return f"{_grouped(self.scalar(depth + 1))}*{_grouped(self.vector(depth + 1))}"
        if choice < 5:
            return f"{self.vector(depth + 1)} {r.choice('+-')} {self.vector(depth + 1)}"
        if choice == 5:
            return f"CROSS({self.vector(depth + 1)}, {self.vector(depth + 1)})"
        if choice == 6:
            return f"EXPRESS({self.vector(depth + 1)}, {self.frame()})"
        if choice == 7:
            return f"DT({self.vector(depth + 1)}, {self.frame()})"
        if choice == 8:
            return f"UNITVEC({self.vector(depth + 1)})"
        if choice == 9:
            s = [self.scalar(depth + 1) for _ in range(3)]
            return f"VECTOR({self.frame()}, {s[0]}, {s[1]}, {s[2]})"
        if choice == 10:
            return f"{_grouped(self.vector(depth + 1))}/{_grouped(self.scalar_atom())}"
        return f"-{_grouped(self.vector_atom())}"

    def vector_atom(self) -> str:
        r = self.rng
        choice = r.random()
        if choice < 0.45 or not self.newtonian:
            return self.unit_vector()
        if choice < 0.55:
            return r.choice(self.vectors) if self.vectors else "0>"
        if choice < 0.7 and len(self.located) > 1:
            a, b = r.sample(self.located, 2)
            return f"P_{a}_{b}>"
        if choice < 0.8 and len(self.frames) > 1:
            a, b = r.sample(self.frames, 2)
            return f"W_{a}_{b}>"
        if choice < 0.9:
            return f"V_{r.choice(self.located)}_{self.newtonian}>"
        return f"{_grouped(self.quantity())}*{self.unit_vector()}"

    def matrix(self) -> tuple[str, int, int]:
        r = self.rng
        rows, cols = r.randint(1, 3), r.randint(1, 3)
        body = "; ".join(", ".join(self.scalar(2) for _ in range(cols)) for _ in range(rows))
        choice = r.randrange(6)
        if choice == 0 and rows == cols:
            return f"INV([{body}])", rows, cols
        if choice == 1:
            return f"TRANSPOSE([{body}])", cols, rows
        if choice == 2:
            n = r.randint(1, 3)
            return f"DIAGMAT({n}, {self.scalar(2)})", n, n
        if choice == 3:
            return f"MATRIX({self.frame()}, {self.vector(2)})", 3, 1
        if choice == 4:
            xs = [self.symbol() for _ in range(cols)]
            exprs = "; ".join(self.scalar(2) for _ in range(rows))
            return f"COEF([{exprs}], [{', '.join(xs)}])", rows, cols
        return f"[{body}]", rows, cols

    # -- statements ----------------------------------------------------------------
    def kinematics(self) -> None:
        """Orientations, kinematical equations, positions and velocities, masses."""
        r, n = self.rng, self.newtonian
        angles = list(self.coordinates)
        for k, f in enumerate(self.frames):
            if f == n or r.random() < 0.03:
                continue
            parent = r.choice(self.frames[:k])
            angle = angles.pop(0) if angles and r.random() < 0.8 else self.scalar(2)
            self.emit(f"SIMPROT({parent}, {f}, {r.choice(('1', '2', '3', '-3'))}, {angle})")
        for q, u in zip(self.coordinates, self.speeds):
            if r.random() < 0.95:
                self.emit(f"{q}' = {u}" if r.random() < 0.8 else f"{q}' = {self.scalar(2)}")
        for f in self.frames:
            if f != n and r.random() < 0.2:
                self.emit(f"W_{f}_{n}> = {self.vector(2)}")
        for p in self.points:
            if p in self.located or r.random() < 0.05:
                continue
            base = r.choice(self.located)
            self.emit(f"P_{base}_{p}> = {self.vector(2)}")
            self.located.append(p)
            if r.random() < 0.2:
                self.emit(f"V_{p}_{n}> = DT(P_{n}O_{p}>, {n})")
            elif r.random() < 0.2:
                self.emit(f"V2PTS({n}, {self.frame()}, {base}, {p})")
        for b in self.bodies + self.particles:
            if r.random() < 0.97:
                self.emit(f"MASS {b} = {self.quantity()}")
        for b in self.bodies:
            if r.random() < 0.97:
                values = ", ".join(self.quantity() for _ in range(r.choice((3, 3, 6))))
                self.emit(f"INERTIA {b}, {values}")

    def dynamics(self) -> None:
        r = self.rng
        if r.random() < 0.7:
            self.emit(f"GRAVITY({self.vector(2)})")
        if r.random() < 0.3 and len(self.located) > 1:
            a, b = r.sample(self.located, 2)
            self.emit(f"FORCE({a}/{b}, {self.vector(2)})")
        if r.random() < 0.3 and len(self.frames) > 1:
            a, b = r.sample(self.frames, 2)
            self.emit(f"TORQUE({a}/{b}, {self.vector(2)})")
        if r.random() < 0.2 and len(self.speeds) > 1:
            self.emit(f"DEPENDENT[1] = {self.speeds[0]} - {self.scalar(2)}*{self.speeds[1]}")
            self.emit(f"CONSTRAIN(DEPENDENT[{self.speeds[0]}])")
        self.emit("ZERO = FR() + FRSTAR()")
        if r.random() < 0.5:
            self.emit("KANE()")
        elif r.random() < 0.5:
            us = ", ".join(u + "'" for u in self.speeds)
            self.emit(f"SOLVE(ZERO, {us})")

    def statement(self) -> None:
        r = self.rng
        choice = r.randrange(20)
        if choice < 5:
            name = r.choice(sorted(self.scalars)) if self.scalars and r.random() < 0.2 \
                else self.fresh("E")
            op = r.choice(("=", "=", "=", ":=", "+=", "*=")) if name in self.scalars else "="
            value = self.scalar()
            self.emit(f"{name} {op} {value}")
            self.scalars.setdefault(name, value)
        elif choice < 8:
            name = self.fresh("V") + ">"
            self.emit(f"{name} = {self.vector()}")
            self.vectors.append(name)
        elif choice < 10:
            name = self.fresh("M")
            value, rows, cols = self.matrix()
            self.emit(f"{name} = {value}")
            self.matrices[name] = (rows, cols)
            if r.random() < 0.3:
                self.emit(f"{name}[{r.randint(1, rows)}, {r.randint(1, cols)}] = "
                          f"{self.scalar(2)}")
        elif choice == 10:
            name = r.choice(sorted(self.variables))
            if self.variables[name]:
                self.emit(f"{name}' = {self.scalar(1)}")
        elif choice == 11 and self.scalars:
            name = r.choice(sorted(self.scalars))
            self.emit(r.choice((f"EXPAND({name})", f"FACTOR({name}, {self.symbol()})",
                                f"{name} := EXPLICIT({name})")))
        elif choice == 12:
            self.emit(r.choice(("AUTOZ ON", "AUTOZ OFF", "DEGREES OFF", "DEGREES ON",
                                "DIGITS 7", "OVERWRITE ALL", "BEEPSOUND OFF", "PAUSE 0",
                                "AUTORHS OFF", "COMPLEX OFF", "AUTOEPSILON 1.0E-7")))
        elif choice == 13:
            self.emit(self.scalar(1))
        elif choice == 14 and len(self.frames) > 1:
            a, b = r.sample(self.frames, 2)
            self.emit(r.choice((f"W_{a}_{b}> = {self.vector(2)}",
                                f"{self.fresh('D')}>> = {self.unit_vector()}*"
                                f"{self.unit_vector()}",
                                f"{self.fresh('E')}> = EXPRESS({self.vector(2)}, {a})")))
        elif choice == 15:
            x = self.symbol()
            name = self.fresh("E")
            self.emit(f"{name} = {_grouped(self.scalar(2))}*{x} + {self.scalar(2)}")
            self.emit(f"SOLVE({name}, {x})")
        elif choice == 16 and self.newtonian:
            self.emit(f"{self.fresh('H')}> = " + r.choice(
                ("MOMENTUM(LINEAR)", f"MOMENTUM(ANGULAR, {self.newtonian}O)",
                 f"CM({self.newtonian}O)")))
        elif choice == 17:
            self.input_statement()
        else:
            name = self.fresh("E")
            value = self.scalar()
            self.emit(f"{name} = {value}")
            self.scalars[name] = value

    def input_statement(self) -> None:
        r = self.rng
        names = self.constants + self.coordinates + self.speeds
        if not names:
            return
        chosen = r.sample(names, min(len(names), r.randint(1, 6)))
        self.emit("INPUT " + ", ".join(
            f"{x} = {self.number()}" + (f" {r.choice(_UNITS)}" if r.random() < 0.5 else "")
            for x in chosen))
        self.inputs.extend(chosen)

    def inputs_and_code(self) -> None:
        r = self.rng
        if r.random() < 0.7:
            self.input_statement()
        if r.random() < 0.4:
            self.emit(f"INPUT TFINAL = {r.randint(1, 10)}, INTEGSTP = 0.{r.randint(1, 9)}")
        if r.random() < 0.2:
            self.emit("UNITSYSTEM kg, meter, sec")
        names = self.constants + self.coordinates + self.speeds
        if r.random() < 0.2 and names:
            self.emit(f"UNITS {r.choice(names)} = {r.choice(_UNITS)}")
        if r.random() < 0.6:
            items = ["T"] + [self.quantity() for _ in range(r.randint(1, 4))]
            self.emit("OUTPUT " + ", ".join(
                x + (f" {r.choice(_UNITS)}" if r.random() < 0.4 else "") for x in items))
        if r.random() < 0.2 and self.scalars:
            self.emit("ENCODE " + r.choice(sorted(self.scalars)))
        if r.random() < 0.5:
            self.emit(f"CODE {r.choice(('DYNAMICS', 'DYNAMICS', 'ALGEBRAIC', 'ODE'))}() "
                      f"{self.fresh('prog').lower()}.{r.choice(('c', 'm', 'for', 'f'))}")

    def write(self, n_statements: int) -> str:
        self.declare()
        if self.newtonian and self.rng.random() < 0.9:
            self.kinematics()
        for _ in range(n_statements):
            self.statement()
        if self.newtonian and self.rng.random() < 0.6:
            self.dynamics()
        self.inputs_and_code()
        return self.text()


def model_case(rng: random.Random) -> tuple[str, str]:
    """(a) a random well-formed model."""
    return "model.al", ModelWriter(rng).write(rng.randint(0, 25))


# the declarations the cases of the other generators build on
_HEADER = "NEWTONIAN N\nFRAMES A\nCONSTANTS A1, B1, C1\nVARIABLES X', Y''\n" \
          "MOTIONVARIABLES' Q{2}', U{2}'\nSIMPROT(N, A, 3, Q1)\n"


def nesting_case(rng: random.Random) -> tuple[str, str]:
    """(b) parentheses, calls, signs and powers nested up to a few hundred deep."""
    depth = log_uniform(rng, 1, 400)
    kind = rng.choice(("parens", "calls", "same_call", "minus", "power_chain",
                       "power_nest", "mixed", "vector", "matrix", "derivative"))
    expr = "A1"
    if kind == "parens":
        expr = "(" * depth + "A1" + ")" * depth
    elif kind == "calls":
        for _ in range(depth):
            expr = f"{rng.choice(_ELEMENTARY)}({expr})"
    elif kind == "same_call":
        f = rng.choice(("SIN", "COS", "SQRT", "ABS", "EXP", "EXPLICIT", "EXPAND"))
        expr = f"{f}(" * depth + "A1" + ")" * depth
    elif kind == "minus":
        expr = rng.choice(("-", "- ", "-(")) * depth + "A1"
        expr += ")" * expr.count("(")
    elif kind == "power_chain":
        expr = "^".join(rng.choice(("A1", "2", "X", "1.5")) for _ in range(depth + 1))
    elif kind == "power_nest":
        for _ in range(depth):
            expr = f"({expr})^{rng.choice(('2', '-1', 'A1', '0.5'))}"
    elif kind == "mixed":
        for _ in range(depth):
            expr = rng.choice((f"({expr})", f"SIN({expr})", f"-{expr}", f"({expr})^2",
                               f"{expr} + B1", f"C1*({expr})", f"ATAN2({expr}, 1)",
                               f"[{expr}]"))
    elif kind == "vector":
        expr = "N1>"
        for _ in range(depth):
            expr = rng.choice((f"CROSS(A1>, {expr})", f"EXPRESS({expr}, A)", f"Q1*({expr})",
                               f"({expr} + N2>)", f"UNITVEC({expr})"))
    elif kind == "matrix":
        expr = rng.choice(("[" * depth + "1" + "]" * depth,
                           "TRANSPOSE(" * depth + "[1, 2]" + ")" * depth,
                           "INV(" * depth + "[2]" + ")" * depth))
    else:
        # each derivative can double the expression's size: a dozen deep at most
        expr = rng.choice(("SIN(X)*Y", "N1>*Q1 + A2>", "X"))
        for _ in range(min(depth, 12)):
            expr = rng.choice((f"D({expr}, X)", f"DT({expr})", f"DT({expr}, N)",
                               f"EXPLICIT({expr})"))
    lhs = "V>" if ">" in expr else "E"
    return "nesting.al", _HEADER + f"{lhs} = {expr}\n"


def long_case(rng: random.Random) -> tuple[str, str]:
    """(c) long sums, products, continuation lines and lists."""
    n = log_uniform(rng, 10, 5000)
    kind = rng.choice(("sum", "product", "continued", "declarations", "matrix", "chain",
                       "output", "vector_sum", "comments", "statements"))
    atoms = ("A1", "B1", "C1", "X", "Y", "Q1", "U2", "2", "0.5", "SIN(X)")
    terms = [rng.choice(atoms) for _ in range(n)]
    body = ""
    if kind == "sum":
        body = "E = " + "".join(rng.choice(("+", "-")) + t for t in terms) + "\n"
    elif kind == "product":
        body = "E = " + terms[0] + "".join(rng.choice("**/") + t for t in terms[1:]) + "\n"
    elif kind == "continued":
        per_line = rng.randint(1, 10)
        parts = [" + ".join(terms[i:i + per_line]) for i in range(0, n, per_line)]
        body = "E = " + " + &\n    ".join(parts) + "\n"
    elif kind == "declarations":
        names = ", ".join(f"K{i}" for i in range(n))
        body = f"CONSTANTS {names}\nE = " + " + ".join(f"K{i}" for i in range(n)) + "\n"
    elif kind == "matrix":
        cols = max(1, round(math.sqrt(n))) if rng.random() < 0.5 else n
        rows = max(1, n // cols)
        body = "M = [" + "; ".join(", ".join(rng.choice(atoms) for _ in range(cols))
                                   for _ in range(rows)) + "]\n"
    elif kind == "chain":
        body = "E0 = A1\n" + "".join(f"E{i} = E{i - 1}*{rng.choice(atoms)} + 1\n"
                                     for i in range(1, n))
    elif kind == "output":
        body = "OUTPUT " + ", ".join(terms) + "\n"
    elif kind == "vector_sum":
        body = "V> = " + " + ".join(f"{t}*{rng.choice(('N', 'A'))}{rng.randint(1, 3)}>"
                                    for t in terms) + "\n"
    elif kind == "comments":
        body = "% " + "x" * (n * 20) + "\n" + "% c\n" * n + "E = A1 % " + "y" * n + "\n"
    else:
        body = "".join(f"E{i} = {rng.choice(atoms)} + {rng.choice(atoms)}\n" for i in range(n))
    return "long.al", _HEADER + body


def literals_case(rng: random.Random) -> tuple[str, str]:
    """(d) huge numbers, exponent towers, big orders and ranges."""
    digits = "".join(rng.choice("0123456789") for _ in range(log_uniform(rng, 10, 20000)))
    big = str(log_uniform(rng, 1000, 10 ** 12))
    huge = rng.choice(("99999999", "99999999999", "4294967297", "2147483648", big))
    statements = (
        f"E = {digits}", f"E = 1{digits}.5", f"E = 0.{digits}", f"E = {digits}E-{big}",
        "E = 1.0E308*10", "E = 1.7976931348623157E308", "E = 1E309", "E = 1E-400",
        "E = 4.9E-324/2", f"E = 1.0E+{big}", f"E = A1^{digits}", f"E = {digits}^{digits}",
        "E = 10^10^10", "E = 9^9^9", "E = " + "^".join(["2"] * rng.randint(3, 8)),
        "E = (10^900)^(10^6)", "E = 10^-10^10", "E = 0^-1", "E = (-8)^(1/3)",
        f"E = FACTORIAL({huge})", "E = FACTORIAL(-1)", "E = FACTORIAL(1.5)",
        f"E = FACTORIAL({rng.randint(400, 500)})", f"E = TAYLOR(SIN(A1), 0:{huge}, A1=0)",
        f"E = TAYLOR(COS(X), {rng.randint(20, 40)}, X=0)",
        f"CONSTANTS C{{1:{huge}}}", f"CONSTANTS C{{{huge}}}", f"VARIABLES W{{{huge}}}'",
        f"CONSTANTS R{{1:{rng.randint(100, 5000)},1:{rng.randint(100, 5000)}}}",
        f"CONSTANTS C{{{huge}:1}}", "CONSTANTS C{0}", f"E = DIAGMAT({huge}, 1)",
        f"E = DIAGMAT({rng.randint(100, 3000)}, A1)", f"M[{huge}] = 1", f"M[{huge}, 1] := 2",
        f"M = [1, 2]\nE = ROWS(M, 1:{huge})", f"M = [1; 2]\nE = M[{huge}]",
        f"M[{huge}] = A1\nE = {rng.choice(('SIN(M)', 'M + M', 'TRANSPOSE(M)*M', 'ROWS(M)'))}",
        "VARIABLES Z" + "'" * log_uniform(rng, 4, 400),
        "E = X" + "'" * log_uniform(rng, 3, 400), "INPUT TFINAL = 1E308, INTEGSTP = 1E-308",
        f"INPUT A1 = {digits} m", f"DIGITS {huge}", f"PAUSE {digits}", "AUTOEPSILON 1E-400",
        f"SIMPROT(N, A, {huge}, Q1)", "SIMPROT(N, A, 3, 1E308)", f"E = EXPAND(X, 1:{huge})",
        f"E = ARRANGE(A1*X, {huge}, X)", f"E = POLYNOMIAL([{', '.join(['1'] * 50)}], X)",
        f"E = EXPAND((A1 + B1 + C1)^{rng.randint(5, 60)})", f"E = (A1 + X)^{huge}",
        f"E = SIN({digits})", f"E = EXP({big})", "E = LOG(1E-400)", f"E = INT({digits}.5)",
        f"E = ROUND(1E{rng.randint(300, 400)})", f"E = {digits} * N1>",
        f"E = D(X^{huge}, X)", f"E = EVALUATE(X^{huge}, X = 2)")
    chosen = [rng.choice(statements) for _ in range(rng.randint(1, 3))]
    return "literals.al", _HEADER + "\n".join(chosen) + "\n"


# names that mean something to Python, sympy, the generated module or the tool itself
_COLLIDING = ("model", "_verify_defs", "__verify_defs__", "__import__", "__builtins__",
              "__name__", "__file__", "__doc__", "T", "t", "PI", "pi", "sm", "al", "me",
              "np", "self", "None", "True", "False", "lambda", "class", "def", "import",
              "return", "yield", "async", "await", "match", "case", "type", "print", "exec",
              "eval", "open", "exit", "quit", "globals", "locals", "vars", "id", "I", "E",
              "S", "N", "O", "oo", "nan", "zoo", "Symbol", "Matrix", "Q1p", "Q1pp", "N_frame",
              "A_body", "ZERO", "NO", "AO", "_", "__", "x_", "sys", "os", "derivatives",
              "Model", "ZEROp", "Ip", "Tp", "dynamicsymbols", "_t", "Function")
# comments and text that must never become code, or break the line numbering
_HOSTILE_TEXT = ('"""', "'''", '\\', '\\"', '"); import os; os.system("touch CANARY")  #',
                 "\x00", "\r", "\x0b", "\x0c", "\x1c", "\x1d", "\x1e", "\x85", "\u2028",
                 "\u2029", "\ufeff", "é", "λ", "\u202e", "\udcff", "\udc80", "$(touch CANARY)",
                 "`touch CANARY`", "{__import__('os').system('touch CANARY')}", "%s%d",
                 "\\N{BULLET}", "\\x00", "\t", "\x1a")
_HOSTILE_FILENAMES = ('"', '"""', "'", "'''", "\\", "\n", "\r", "\t", " ", "$(id)",
                      "`id`", "..", "...", "-rf", "%", "&", ";", "é", "λ", "\u202e",
                      "\ufeff", "\udcff", "{x}", "[1]", "#", "\x1b[31m", "model", "__init__",
                      "autolev", "sympy", "\u2028", "~", "*", "?")
_CODE_FILENAMES = ("../../escape.c", "../escape.c", "/tmp/escape_CANARY.c", "..\\..\\esc.c",
                   "$(id).c", "`id`.c", "x.c/..", "a..b.c", "C:\\x.c", "con.c", "-rf.c",
                   "x" * 300 + ".c", ".c", "escape.py", "__init__.py", "sub/dir/x.m",
                   "/dev/null", "/etc/passwd", "~/x.c")


def _hostile_filename(rng: random.Random) -> str:
    parts = [rng.choice(_HOSTILE_FILENAMES) for _ in range(rng.randint(1, 3))]
    stem = "".join(parts)
    if rng.random() < 0.1:
        stem = stem + "x" * log_uniform(rng, 10, 200)
    suffix = rng.choice((".al", ".al", ".AL", "", ".al.py", ".py", ".a", ".r", ".al "))
    name = stem + suffix
    if name in (".", "..") or len(name.encode("utf-8", "surrogateescape")) > 250:
        name = "x" + name[:100] + ".al"
    return name


def hostile_case(rng: random.Random) -> tuple[str, str]:
    """(e) names and file names that collide with Python or the tool, hostile text."""
    lines = []
    for _ in range(rng.randint(1, 4)):
        kind = rng.randrange(9)
        if kind == 0:
            names = rng.sample(_COLLIDING, rng.randint(1, 4))
            decl = rng.choice(("CONSTANTS", "VARIABLES", "SPECIFIED", "MOTIONVARIABLES",
                               "POINTS", "FRAMES", "BODIES", "PARTICLES"))
            lines.append(f"{decl} {', '.join(names)}")
            for name in names:
                lines.append({"POINTS": f"P_NO_{name}> = Q1*N1>",
                              "FRAMES": f"SIMPROT(N, {name}, 1, Q2)",
                              "BODIES": f"MASS {name} = A1\nINERTIA {name}, 1, 2, 3",
                              "PARTICLES": f"MASS {name} = A1"}.get(decl, f"E = {name}^2"))
        elif kind == 1:
            name = rng.choice(_COLLIDING)
            lines.append(rng.choice((f"{name} = Q1 + 1", f"{name}' = U1", f"{name}> = N1>",
                                     f"{name}[1] = 2", f"NEWTONIAN {name}",
                                     f"P_NO_{name}> = Q1*N1>", f"{name} = [1, 2; 3, 4]",
                                     f"E = {name}(Q1)", f"{name}{{2}}' = U1")))
        elif kind == 2:
            length = log_uniform(rng, 50, 100000)
            name = "L" + "".join(rng.choice("abcXYZ_019") for _ in range(length))
            lines.append(rng.choice((f"CONSTANTS {name}\nE = {name}^2", f"{name} = 1",
                                     f"{name}> = N1>", f"BODIES {name}\nMASS {name} = 1")))
        elif kind == 3:
            text = "".join(rng.choice(_HOSTILE_TEXT) for _ in range(rng.randint(1, 6)))
            lines.append(rng.choice((f"% {text}", f"E = Q1  % {text}", f"E = Q1 & % {text}\n+1",
                                     text, f"OUTPUT Q1 {text}", f"INPUT A1 = 1 {text}",
                                     f"UNITS A1 = {text}", f"SAVE {text}.all")))
        elif kind == 4:
            target = rng.choice(_CODE_FILENAMES)
            lines.append(rng.choice((f"CODE DYNAMICS() {target}", f"CODE ALGEBRAIC() {target}",
                                     f"RUN {target}", f"SAVE {target}",
                                     f"CODE ODE(ZERO, U1') {target}")))
        elif kind == 5:
            lines.append(rng.choice(("CONSTANTS ab, AB, Ab\nE = ab + AB",
                                     "VARIABLES q1'\nMOTIONVARIABLES Q1", "FRAMES N",
                                     "POINTS NO, no", "CONSTANTS NO\nE = NO*N1>",
                                     "BODIES Q1\nE = Q1", "CONSTANTS T\nE = DT(T)",
                                     "CONSTANTS PI\nE = SIN(PI)", "VARIABLES T'")))
        elif kind == 6:
            lines.append(rng.choice(("E = A1 \\", "E = 'A1'", 'E = "A1"', "E = A1\x00+1",
                                     "E = A1\r+1", "E = A1\u00a0+1", "E = A1\x1a", "\ufeffE = 1",
                                     "CONSTANTS é\nE = é", "E\u2028= 1", "E = A1 &",
                                     "&\n&\nE = 1", "E = (A1 &\n% a comment &\n+ 1)")))
        elif kind == 7:
            macro = rng.choice(("RUN", "SAVE"))
            lines.append(f"{macro} {_hostile_filename(rng)}".replace("\n", "_"))
        else:
            lines.append(rng.choice(("E = SIN(Q1) % " + "\\" * rng.randint(1, 4),
                                     "OUTPUT Q1 \"deg\"", "INPUT Q1 = 1 DEG'", "E = Q1'''",
                                     "UNITS Q1 = m\"", "ENCODE \"x\"", "DIGITS '")))
    ending = rng.choice(("\n", "\n", "\r\n", "\r", "\n\x00"))
    text = _HEADER + ending.join(lines) + ending
    filename = _hostile_filename(rng) if rng.random() < 0.7 else "hostile.al"
    return filename, text


_GENERATE = {"model": model_case, "nesting": nesting_case, "long": long_case,
             "literals": literals_case, "hostile": hostile_case}


def grammar_case(seed: int, index: int) -> Case:
    """Case `index` of seed `seed` (each case has its own random stream)."""
    rng = random.Random(f"autolev-fuzz:{seed}:{index}")
    generator = rng.choices(GENERATORS, weights=GENERATOR_WEIGHTS)[0]
    filename, text = _GENERATE[generator](rng)
    return Case(index, generator, filename, text)


# ---------------------------------------------------------------------------------
# Files mode: a model and the files beside it

FILES_GENERATORS = ("runs", "macros", "functions", "stray", "links")
FILES_WEIGHTS = (30, 20, 20, 15, 15)

# the model every files case builds on: it loads as it stands
_FILES_HEAD = ("NEWTONIAN N\nFRAMES A\nPARTICLES P\nMOTIONVARIABLES' Q''\n"
               "CONSTANTS L, G, M, K1, K2\nMASS P = M\nSIMPROT(N, A, 3, Q)\n"
               "P_NO_P> = L*A1>\nV2PTS(N, A, NO, P)\n"
               # Autolev's functions, which stray files of the same names must not replace
               "EC = COS(Q) + SIN(Q) + SQRT(K1) + EXP(K2) + D(Q^2, Q) + DT(Q)\n"
               "EV> = UNITVEC(EXPRESS(CROSS(N1>, A1>), N)) + DOT(N1>, A1>)*MAG(N2>)*N3>\n")
_FILES_TAIL = ("GRAVITY(G*N1>)\nZERO = FR() + FRSTAR()\nKANE()\n"
               "INPUT L = 1, G = 9.81, M = 1, K1 = 2, K2 = 3, Q = 0.1, Q' = 0\n"
               "OUTPUT T, Q\nCODE DYNAMICS() model.c\n")
# files outside the case's folder, which nothing may read: what they would bring in
_BAIT = {"bait.al": "BAIT = 1\n", "bait.a": "BAITM = #1#\n", "bait.r": "#1# + 1000\n",
         "sub/bait.al": "BAIT2 = 2\n"}
# names of Autolev's own commands and functions that a stray file may carry
_BUILT_IN_FILES = ("gravity", "kane", "cos", "sin", "force", "torque", "mass", "inertia",
                   "simprot", "v2pts", "fr", "frstar", "dt", "d", "express", "cross",
                   "dot", "input", "output", "code", "zero", "explicit", "solve", "expand",
                   "sqrt", "exp", "mag", "unitvec", "rhs", "run", "constrain", "matrix")
_STRAY_TEXTS = ("", "42", "E = 1", "#1#", "GRAVITY(#1#)", "% only a comment",
                "RUN model.al", "COS(#1#) + 1", "\x00\xff\xfe garbage", "KANE()\nKANE()",
                "Q = 1/0", "#1# #2# #3#", "X = (", "CONSTANTS G")


def _statement(rng: random.Random, tag: str) -> str:
    """A statement that holds however often it is included."""
    k = rng.randint(1, 99)
    return rng.choice((f"E{tag} = K1*{k} + Q", f"W{tag}> = K1*N1> + Q*A2>",
                       f"Z{tag} = SIN(Q)*K2 + {k}", f"S{tag} = L*{k}", "% a comment",
                       f"M{tag} = [K1, K2; Q, {k}]", f"E{tag} = EXPLICIT(K1^2 + Q)"))


# what goes wrong in a file now and then: a declaration repeated at each inclusion, a
# syntax error, a file that is not there, one outside the case's folder
_DEFECTS = ("CONSTANTS CD", "VARIABLES YD'", "ED = (", "RUN missing.al", "RUN @ESCAPE@")


def _with_defect(rng: random.Random, files: dict, defects: tuple[str, ...]) -> None:
    """One defect inserted into one of the files, in a third of the cases."""
    if files and rng.random() < 0.3:
        name = rng.choice(sorted(files))
        lines = files[name].split("\n")
        defect = rng.choice(defects).replace("@ESCAPE@", _escape_name(rng, ".al"))
        lines.insert(rng.randint(0, len(lines) - 1), defect)
        files[name] = "\n".join(lines)


def _spelt(rng: random.Random, name: str) -> str:
    """A file's name as a model may write it: another case, '\\' for '/', './'."""
    choice = rng.random()
    if choice < 0.15:
        return name.upper()
    if choice < 0.25:
        return name.replace("/", "\\")
    if choice < 0.3:
        return "./" + name
    return name


def _escape_name(rng: random.Random, suffix: str) -> str:
    """A name that leads outside the case's folder."""
    return rng.choice((f"../outside/bait{suffix}", f"@OUTSIDE@/bait{suffix}",
                       f"sub/../../outside/bait{suffix}", f"..\\outside\\bait{suffix}"))


def _run_files(rng: random.Random) -> tuple[dict, list[str]]:
    """RUN files that RUN each other (fan-out, cycles): {path: text}, and the RUN lines
    of the model."""
    n = rng.randint(2, 9)
    folders = ("", "", "", "sub/", "Sub/Deep/")
    paths = [f"{rng.choice(folders)}r{i}.al" for i in range(n)]
    if rng.random() < 0.2:
        paths = [p.upper() for p in paths]
    fan = log_uniform(rng, 1, 8)
    cycles = rng.random() < 0.2
    # a chain: each file RUNs the next `fan` times (fan^n inclusions: thousands, or
    # far beyond the budget)
    chain = not cycles and rng.random() < 0.3
    files = {}
    for i, path in enumerate(paths):
        lines = [_statement(rng, f"R{i}") for _ in range(rng.randint(0, 3))]
        others = list(range(n)) if cycles else list(range(i + 1, n))
        if chain:
            lines += [f"RUN {_spelt(rng, paths[i + 1])}"] * max(fan, 2) if i + 1 < n else []
            others = []
        for _ in range(rng.randint(0, fan) if others else 0):
            lines.insert(rng.randint(0, len(lines)),
                         f"RUN {_spelt(rng, paths[rng.choice(others)])}")
        files[path] = "\n".join(lines) + "\n"
    _with_defect(rng, files, _DEFECTS)
    runs = [f"RUN {_spelt(rng, paths[0])}"] * rng.randint(1, 3)
    return files, runs


def _macro_files(rng: random.Random) -> tuple[dict, list[str]]:
    """Macros (.a) that call each other: {path: text}, and the calls of the model; #1#
    stands for a name, #2# for an expression."""
    n = rng.randint(1, 6)
    names = [f"MAC{i}" for i in range(n)]
    fan = log_uniform(rng, 1, 6)
    files = {}
    for i, name in enumerate(names):
        lines = []
        for _ in range(rng.randint(1, 4)):
            lines.append(rng.choice(("V#1# = #2# + K1", "X#1# = #2#*2", "E = #1#",
                                     "% #1# and #2#", "#1#", f"E{i} = SIN(#2#)",
                                     _statement(rng, f"A{i}"))))
        callees = names[i + 1:] if rng.random() < 0.8 else names
        for _ in range(rng.randint(0, fan) if callees else 0):
            callee = rng.choice(callees)
            lines.insert(rng.randint(0, len(lines)), rng.choice(
                (f"{callee}(#1#, #2#)", f"{callee}(#1#, #2#*2)", f"{callee}(#1#, 1)")))
        spelt = name if rng.random() < 0.3 else name.lower()
        files[spelt + rng.choice((".a", ".a", ".A"))] = "\n".join(lines) + "\n"
    _with_defect(rng, files, _DEFECTS + ("X#3# = 1", "E = #2#(#1#)", f"{names[-1]}(#1#)",
                                         f"{names[0]}()", "#1#(#2#)"))
    calls = [f"{names[0]}({rng.choice(('K1', 'K2', 'L'))}, "
             f"{rng.choice(('K1', 'Q', 'SIN(Q)', 'K1 + 1', '1E3'))})"
             for _ in range(rng.randint(1, 3))]
    return files, calls


def _function_files(rng: random.Random) -> tuple[dict, list[str]]:
    """User functions (.r) of two arguments that call each other: {path: text}, and the
    statements of the model that call them."""
    n = rng.randint(1, 6)
    names = [f"FN{i}" for i in range(n)]
    files = {}
    for i, name in enumerate(names):
        callees = names[i + 1:] if rng.random() < 0.8 else names
        pool = ["#1# + K1", "#1#*#2#", "SIN(#1#) + #2#", "#1#^2 - #2#", "(#1#)",
                "% a comment\n#1# - #2#"]
        if callees:
            f = rng.choice(callees)
            pool += [f"{f}(#1#, #2#) + {f}(#2#, #1#)", f"{f}(#1#*#1#, #2#)",
                     f"{f}({f}(#1#, #2#), #2#)",
                     f"{f}(#1#, #2#) - {rng.choice(callees)}(#2#, #1#)"] * 3
        files[name.lower() + rng.choice((".r", ".r", ".R"))] = rng.choice(pool) + "\n"
    _with_defect(rng, files, ("", "1 +", "X = 1", "#5#", "1\n2", f"{names[0]}(#1#)",
                              f"{names[-1]}()"))
    args = ("Q", "K1", "Q*K2", "SIN(Q)", "1")
    calls = [f"EF{k} = {names[0]}({rng.choice(args)}, {rng.choice(args)})"
             for k in range(rng.randint(1, 3))]
    if rng.random() < 0.1:
        calls.append(rng.choice((f"EF = {names[0]}()", f"EF = {names[0]}(Q)",
                                 f"EF = {names[0]}(Q, Q, Q)")))
    return files, calls


def _stray_files(rng: random.Random) -> dict:
    """Files named as Autolev's own commands and functions, with random content."""
    files = {}
    for _ in range(rng.randint(1, 5)):
        name = rng.choice(_BUILT_IN_FILES)
        name = name.upper() if rng.random() < 0.3 else name
        text = rng.choice(_STRAY_TEXTS)
        if rng.random() < 0.05:
            text = "E = 1\n" * log_uniform(rng, 100, 20000)
        files[name + rng.choice((".a", ".r", ".A", ".R"))] = text + "\n"
    return files


def _link_files(rng: random.Random) -> tuple[dict, dict, list[str]]:
    """Links in the case's folder (most leading outside it): ({path: [kind, target]},
    {path: text} of files they may lead to, and the model's statements that use them)."""
    links, files, lines = {}, {"linside.al": "EINSIDE = 1\n"}, []
    for _ in range(rng.randint(1, 4)):
        kind = rng.randrange(8)
        if kind == 0:
            links["lrun.al"] = ["symlink", "@OUTSIDE@/bait.al"]
            lines.append("RUN lrun.al")
        elif kind == 1:
            links["lsub"] = ["symlink", "../outside"]
            lines.append(rng.choice(("RUN lsub/bait.al", "RUN lsub/sub/bait.al")))
        elif kind == 2:
            links["lmac.a"] = ["symlink", "../outside/bait.a"]
            lines.append("LMAC(Q)")
        elif kind == 3:
            links["lfun.r"] = ["symlink", "@OUTSIDE@/bait.r"]
            lines.append("EK = LFUN(Q)")
        elif kind == 4:
            links["lalias.al"] = ["symlink", "linside.al"]       # inside: may be read
            lines.append("RUN lalias.al")
        elif kind == 5:
            links["lloop.al"] = ["symlink", "lloop.al"]
            lines.append("RUN lloop.al")
        elif kind == 6:
            links["lgone.al"] = ["symlink", "nothing.al"]
            lines.append(rng.choice(("RUN lgone.al", "RUN nothing.al")))
        else:
            lines.append(f"RUN {_escape_name(rng, '.al')}")
    return links, files, lines


def files_case(seed: int, index: int) -> Case:
    """Case `index` of seed `seed` of the files mode: the model with RUN files, macros,
    functions, stray files with built-in names and links beside it."""
    rng = random.Random(f"autolev-fuzz:files:{seed}:{index}")
    generator = rng.choices(FILES_GENERATORS, weights=FILES_WEIGHTS)[0]
    files: dict = {}
    links: dict = {}
    body: list[str] = []
    kinds = {generator} | {g for g in ("runs", "macros", "functions", "links")
                           if rng.random() < 0.15}
    if "runs" in kinds:
        found, lines = _run_files(rng)
        files.update(found)
        body += lines
    if "macros" in kinds:
        found, lines = _macro_files(rng)
        files.update(found)
        body += lines
    if "functions" in kinds:
        found, lines = _function_files(rng)
        files.update(found)
        body += lines
    if "links" in kinds:
        planted, found, lines = _link_files(rng)
        links.update(planted)
        files.update({k: v for k, v in found.items() if k not in files})
        body += lines
    strays = {}
    if generator == "stray" or rng.random() < 0.15:
        strays = {k: v for k, v in _stray_files(rng).items() if k.lower() not in
                  {f.lower() for f in files}}
        files.update(strays)
    rng.shuffle(body)
    text = _FILES_HEAD + "".join(line + "\n" for line in body) + _FILES_TAIL
    # now and then `autolev check` of the model and the files beside it (macros alone)
    commands = [["check", "{model}", *(f"{{case}}/{name}" for name in sorted(files)
                                       if name not in strays)]] if rng.random() < 0.3 else []
    return Case(index, generator, "model.al", text, mode="files", files=files, links=links,
                outside=dict(_BAIT), strays=sorted(strays), commands=commands)


# ---------------------------------------------------------------------------------
# Commands mode: models run through the commands that write files, links planted at
# the names they write

COMMANDS_GENERATORS = ("example", "chain", "generated", "corpus")
COMMANDS_WEIGHTS = (35, 30, 20, 15)

# a CODE statement and its file name (the name alone is replaced)
_CODE_LINE = re.compile(r"(?im)^([ \t]*CODE[ \t]+\w+[ \t]*\([^)\n]*\)[ \t]*)([^\s%]+)")
# CODE file names: mostly ordinary ones, with a folder too; then odd and hostile ones
_CODE_NAMES = ("{s}.c", "{s}.c", "{s}.m", "prog.c", "sub/{s}.c", "sub/deeper/{s}.c")
_ODD_CODE_NAMES = ("{s}.for", "a.b.c", "x y.c", "-rf.c", "é.c", "../escape.c",
                   "sub/../{s}2.c", "./{s}3.c", "{s}.C", "@OUTSIDE@/abs.c", "sub\\win.c",
                   "{s}.M", "{s}", ".c", "{s}.al", "{s}.in", "{s}.1", "sub/{s}.dir",
                   "sub//{s}.c", "{s}.c.c")


def _code_name(rng: random.Random, stem: str) -> str:
    names = _CODE_NAMES if rng.random() < 0.7 else _ODD_CODE_NAMES
    return rng.choice(names).format(s=stem)


# what a case finds outside its folder: the files planted links lead to
_VICTIMS = {"victim1": "the victim's first file\n", "victim2": "the victim's second file\n",
            "vdir/inside.txt": "a file in the victim's folder\n"}
# what the output files of a CODE command NAME.x are called beside NAME
_OUTPUT_SUFFIXES = (".1", ".2", ".3", ".dir", ".in", ".html", ".gif", ".1.png")


def runnable_model(rng: random.Random) -> str:
    """A generated model that means to run: Kane's equations, every constant and
    state given a value, outputs; its CODE line is added by the caller."""
    w = ModelWriter(rng)
    w.declare(newtonian=True)        # the kinematics hang from it
    w.kinematics()
    for _ in range(rng.randint(0, 4)):
        w.statement()
    w.dynamics()
    if "KANE()" not in w.lines:
        w.emit("KANE()")
    named = w.constants + w.coordinates + w.speeds + \
        [x for x in w.variables if x not in w.coordinates + w.speeds]
    w.emit("INPUT " + ", ".join(f"{x} = {rng.choice(('1', '2', '0.5', '9.81', '3'))}"
                                for x in named))
    w.emit(f"INPUT TFINAL = {rng.choice(('0.5', '1', '2'))}, INTEGSTP = 0.05")
    w.emit("OUTPUT T, " + ", ".join(w.coordinates + w.speeds))
    return w.text()


def _command_bases() -> list[Path]:
    """Corpus models with a CODE command, small enough to run in seconds."""
    if CORPUS not in _COMMAND_BASES:
        found = []
        if CORPUS.is_dir():
            for path in sorted(CORPUS.rglob("*")):
                if path.suffix.lower() == ".al" and path.is_file() and \
                        path.stat().st_size < 12_000:
                    text = path.read_bytes().decode("latin-1")
                    if re.search(r"(?im)^\s*CODE\s+(DYNAMICS|ALGEBRAIC)", text):
                        found.append(path)
        _COMMAND_BASES[CORPUS] = found
    return _COMMAND_BASES[CORPUS]


# the public corpus (--corpus); the models with CODE commands in it, by its folder
CORPUS = Path(os.environ.get("AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus"))
_COMMAND_BASES: dict = {}


def _siblings(path: Path) -> dict:
    """The RUN files, macros and functions beside a corpus model (none when large)."""
    found = {p.name: p.read_bytes().decode("latin-1") for p in sorted(path.parent.iterdir())
             if p != path and p.is_file() and p.suffix.lower() in (".al", ".a", ".r")}
    return found if sum(len(t) for t in found.values()) < 200_000 else {}


def _retouched(rng: random.Random, text: str) -> str:
    """A model changed lightly: a number of its INPUT, its OUTPUT lines, a character."""
    lines = text.split("\n")
    inputs = [i for i, line in enumerate(lines) if line.lstrip().upper().startswith("INPUT")]
    if inputs and rng.random() < 0.3:
        i = rng.choice(inputs)
        lines[i] = re.sub(r"(?<![\w.])\d+(\.\d*)?", lambda m: rng.choice(
            (m.group(), "0", "-1", "1E3", str(rng.randint(1, 50)))), lines[i], count=1)
    outputs = [i for i, line in enumerate(lines) if line.lstrip().upper().startswith("OUTPUT")]
    if outputs and rng.random() < 0.15:
        i = rng.choice(outputs)
        if rng.random() < 0.5:
            lines.insert(i, lines[i])
        else:
            del lines[i]
    text = "\n".join(lines)
    return mutate(text, rng) if rng.random() < 0.08 else text


def _planted(rng: random.Random) -> list:
    """What a case leaves at an output's name before autolev writes it: mostly links
    (which autolev replaces), a quarter a user's own things (which it must not replace
    without --overwrite)."""
    choice = rng.random()
    if choice < 0.35:
        return ["symlink", f"@OUTSIDE@/{rng.choice(('victim1', 'victim2'))}"]
    if choice < 0.55:
        return ["symlink", "@OUTSIDE@/missing"]
    if choice < 0.65:
        return ["symlink", "@OUTSIDE@/vdir"]
    if choice < 0.7:
        return ["symlink", "@SELF@"]            # a link that leads to itself
    if choice < 0.78:
        return ["hardlink", "victim2"]
    if choice < 0.92:
        return ["file", "the user's own file\n"]
    return ["dir", ""] if choice < 0.96 else ["fifo", ""]


def _plants(rng: random.Random, code_names: list[str], stem: str) -> dict:
    """Things planted in the output folder at the names the commands write."""
    links: dict = {}
    names = [f"out/{stem}.all"]
    for name in code_names:
        folder, base = os.path.split(name.replace("\\", "/"))
        if folder in ("", ".") or ".." in folder.split("/") or folder.startswith(("/", "@")):
            folder = ""
        short = base.rsplit(".", 1)[0] if "." in base[1:] else base
        if folder and rng.random() < 0.3:
            links[f"out/{folder}"] = ["symlink", rng.choice(("@OUTSIDE@/vdir", "@SELF@"))]
        for where in {folder, ""}:
            if where and f"out/{where}" in links:
                continue
            prefix = f"out/{where}/" if where else "out/"
            names += [prefix + short + suffix for suffix in _OUTPUT_SUFFIXES]
            names.append(prefix + base)
    for name in dict.fromkeys(names):
        if name not in links and not name.startswith(tuple(f"{k}/" for k in links)) and \
                rng.random() < 0.25:
            links[name] = _planted(rng)
    return links


def _commands(rng: random.Random) -> list[list[str]]:
    """The commands of a case: code, and some of run, animate and transcript."""
    def overwrite() -> list[str]:
        return ["--overwrite"] if rng.random() < 0.4 else []

    def running() -> list[str]:
        args = ["--backend", "python" if rng.random() < 0.85 else "auto"]
        if rng.random() < 0.85:
            args += ["--tfinal", rng.choice(("0.05", "0.2", "0.5", "1"))]
        if rng.random() < 0.2:
            args.append("--zero-missing")
        if rng.random() < 0.1:
            args += ["--code", "0"]
        return args + overwrite()
    commands = [["code", "--out", "{out}", "-q", *overwrite(), "{model}"]]
    if rng.random() < 0.6:
        commands.append(["run", "--out", "{out}", "-q", *running(),
                         *(["--plot"] if rng.random() < 0.1 else []), "{model}"])
    if rng.random() < 0.5:
        commands.append(["animate", "--out", "{out}", "-q", "--format", "html", "--frames",
                         str(rng.randint(1, 60)), *running(), "{model}"])
    if rng.random() < 0.5:
        commands.append(["transcript", "--out", "{out}", *overwrite(), "{model}"])
    rng.shuffle(commands)
    if rng.random() < 0.15:
        commands.append(list(rng.choice(commands)))      # the same command again
    return commands


def commands_case(seed: int, index: int) -> Case:
    """Case `index` of seed `seed` of the commands mode: a model (an example, a generated
    one or a corpus model, retouched), its CODE file names chosen, things planted at the
    names of its outputs, and the commands that write them."""
    rng = random.Random(f"autolev-fuzz:commands:{seed}:{index}")
    generator = rng.choices(COMMANDS_GENERATORS, weights=COMMANDS_WEIGHTS)[0]
    files: dict = {}
    if generator == "corpus" and not _command_bases():
        generator = "example"
    if generator == "example":
        path = rng.choice(sorted((ROOT / "autolev_examples").glob("*.al")))
        text, stem = path.read_text(encoding="utf-8"), path.stem
    elif generator == "chain":
        text, names = _chain_model(rng, rng.choice(("pendulum", "spring")),
                                   rng.randint(1, 4), "chain")
        states = names["states"]
        extra = [f"OUTPUT T, {', '.join(q + chr(39) for q in states)}"] * rng.randint(0, 3)
        text, stem = text + "".join(line + "\n" for line in extra), "chain"
    elif generator == "corpus":
        path = rng.choice(_command_bases())
        text = path.read_bytes().decode("latin-1")
        stem = path.stem if re.fullmatch(r"\w+", path.stem) else "model"
        files = _siblings(path)
    else:
        text, stem = runnable_model(rng), "model"
    text = _retouched(rng, text)
    code_names: list[str] = []

    def renamed(found: re.Match) -> str:
        code_names.append(_code_name(rng, stem))
        return found.group(1) + code_names[-1]
    text = _CODE_LINE.sub(renamed, text)
    for kind in ["DYNAMICS"] * (not code_names) + ["ALGEBRAIC"] * (rng.random() < 0.15) + \
            ["DYNAMICS"] * (rng.random() < 0.15):
        code_names.append(_code_name(rng, stem))
        text = text.rstrip("\n") + f"\nCODE {kind}() {code_names[-1]}\n"
    links, commands = _plants(rng, code_names, stem), _commands(rng)
    if generator == "corpus":
        # a corpus model's own TFINAL may be hours of motion (SSOpt's 25200 s): runs of
        # it are cut to a second, as the others' are chosen
        commands = [c if c[0] not in ("run", "animate") or "--tfinal" in c
                    else c[:-1] + ["--tfinal", "1", c[-1]] for c in commands]
    return Case(index, generator, f"{stem}.al", text, mode="commands", files=files,
                links=links, outside=dict(_VICTIMS), commands=commands)


# ---------------------------------------------------------------------------------
# Threads mode: sweeps of different models at once, from several threads

THREADS_GENERATORS = ("linearize", "simulate", "executor", "loading")
THREADS_WEIGHTS = (30, 25, 25, 20)


def _chain_model(rng: random.Random, kind: str, n: int, stem: str) -> tuple[str, dict]:
    """A pendulum of n links or a chain of n masses on springs, its constants' values
    drawn at random (each model of a case differs): its text and the names it has."""
    if kind == "pendulum":
        frames = ", ".join(f"A{i}" for i in range(1, n + 1))
        lines = [f"NEWTONIAN N\nFRAMES {frames}\nPARTICLES " +
                 ", ".join(f"P{i}" for i in range(1, n + 1)),
                 "MOTIONVARIABLES' " + ", ".join(f"Q{i}''" for i in range(1, n + 1)),
                 "CONSTANTS G, " + ", ".join(f"L{i}, M{i}" for i in range(1, n + 1))]
        for i in range(1, n + 1):
            base = "NO" if i == 1 else f"P{i - 1}"
            lines += [f"SIMPROT(N, A{i}, 3, Q{i})", f"P_{base}_P{i}> = L{i}*A{i}1>",
                      f"V2PTS(N, A{i}, {base}, P{i})", f"MASS P{i} = M{i}"]
        lines.append("GRAVITY(G*N1>)")
        values = {"G": round(rng.uniform(1, 20), 3)}
        values.update({f"L{i}": round(rng.uniform(0.3, 3), 3) for i in range(1, n + 1)})
        states = [f"Q{i}" for i in range(1, n + 1)]
        swept = "L1"
    else:
        lines = ["NEWTONIAN N\nPARTICLES " + ", ".join(f"P{i}" for i in range(1, n + 1)),
                 "MOTIONVARIABLES' " + ", ".join(f"Q{i}''" for i in range(1, n + 1)),
                 "CONSTANTS C, " + ", ".join(f"K{i}, M{i}" for i in range(1, n + 1))]
        for i in range(1, n + 1):
            base = "NO" if i == 1 else f"P{i - 1}"
            lines += [f"P_{base}_P{i}> = Q{i}*N1>",
                      f"V_P{i}_N> = ({' + '.join(f'Q{j}' + chr(39) for j in range(1, i + 1))})*N1>",
                      f"FORCE({base}/P{i}, -K{i}*Q{i}*N1> - C*Q{i}'*N1>)", f"MASS P{i} = M{i}"]
        values = {"C": round(rng.uniform(0, 0.5), 3)}
        values.update({f"K{i}": round(rng.uniform(1, 50), 3) for i in range(1, n + 1)})
        states = [f"Q{i}" for i in range(1, n + 1)]
        swept = "K1"
    values.update({f"M{i}": round(rng.uniform(0.5, 5), 3) for i in range(1, n + 1)})
    values.update({q: round(rng.uniform(-0.5, 0.5), 3) for q in states})
    values.update({q + "'": 0 for q in states})
    lines += ["ZERO = FR() + FRSTAR()", "KANE()",
              "INPUT " + ", ".join(f"{k} = {v}" for k, v in values.items()),
              f"INPUT TFINAL = {rng.choice((0.1, 0.2, 0.3))}, INTEGSTP = 0.01",
              "OUTPUT T, " + ", ".join(states), f"CODE DYNAMICS() {stem}.c"]
    return "\n".join(lines) + "\n", {"values": values, "states": states, "swept": swept}


def _sweep_points(rng: random.Random, what: str, names: dict) -> list[dict]:
    """A few points: linearized at rest with the swept constant varied, or simulated
    from varied initial angles or positions over a short time."""
    count = rng.randint(3, 6)
    swept, value = names["swept"], names["values"][names["swept"]]
    if what == "linearize":
        return [{swept: round(value * rng.uniform(0.5, 2), 4),
                 **{q: 0.0 for q in names["states"]}} for _ in range(count)]
    first = names["states"][0]
    return [{first: round(rng.uniform(-0.6, 0.6), 4), "TFINAL": rng.choice((0.1, 0.2))}
            for _ in range(count)]


def threads_case(seed: int, index: int) -> Case:
    """Case `index` of seed `seed` of the threads mode: two or three small models, each
    swept from its own thread (on worker processes, on a shared executor), against the
    same sweeps run alone in one process."""
    rng = random.Random(f"autolev-fuzz:threads:{seed}:{index}")
    generator = rng.choices(THREADS_GENERATORS, weights=THREADS_WEIGHTS)[0]
    files, sweeps = {}, []
    for k in range(rng.randint(2, 3)):
        stem = f"m{k}"
        text, names = _chain_model(rng, rng.choice(("pendulum", "spring")),
                                   rng.randint(1, 3), stem)
        files[f"{stem}.al"] = text
        what = {"linearize": "linearize", "simulate": "simulate"}.get(
            generator, rng.choice(("linearize", "simulate")))
        how = "workers"
        if generator == "executor" or rng.random() < 0.1:
            how = rng.choice(("thread-pool", "thread-pool", "process-pool", "workers"))
        sweeps.append({"model": f"{stem}.al", "what": what,
                       "points": _sweep_points(rng, what, names), "how": how,
                       "load": "thread" if generator == "loading" or rng.random() < 0.1
                       else "before",
                       "backend": "auto" if rng.random() < 0.15 else "python",
                       "chunk": rng.randint(1, 3)})
    if rng.random() < 0.3:      # the first alone afterwards, on workers forked from here
        sweeps.append(dict(sweeps[0], how="forked", load="before"))
    return Case(index, generator, "m0.al", files["m0.al"], mode="threads", files=files,
                sweeps=sweeps)


def stale_case(seed: int, index: int) -> Case:
    """Case `index` of seed `seed` of the stale mode (bench/fuzz_stale.py)."""
    return Case(**fuzz_stale.stale_case(seed, index))


def background_case(seed: int, index: int) -> Case:
    """Case `index` of seed `seed` of the background mode (bench/fuzz_background.py)."""
    return Case(**fuzz_background.background_case(seed, index))


def hostile_files_case(seed: int, index: int) -> Case:
    """Case `index` of seed `seed` of the hostile mode (bench/fuzz_hostile.py)."""
    return Case(**fuzz_hostile.hostile_case(seed, index))


MODES = {"grammar": (GENERATORS, None), "files": (FILES_GENERATORS, files_case),
         "commands": (COMMANDS_GENERATORS, commands_case),
         "threads": (THREADS_GENERATORS, threads_case),
         "stale": (fuzz_stale.GENERATORS, stale_case),
         "background": (fuzz_background.GENERATORS, background_case),
         "hostile": (fuzz_hostile.GENERATORS, hostile_files_case)}


def make_case(mode: str, seed: int, index: int) -> Case:
    """Case `index` of seed `seed` of a mode (each case has its own random stream)."""
    return grammar_case(seed, index) if mode == "grammar" else MODES[mode][1](seed, index)


# ---------------------------------------------------------------------------------
# Grammar mode: the worker (a subprocess: `fuzz.py --worker FOLDER`)

@dataclass
class Result:
    index: int
    generator: str
    outcome: str
    seconds: float
    rss_mb: float
    stage: str = ""
    detail: str | None = None


def load_stages(path: Path, text: str) -> tuple[str, str, str | None, str | None]:
    """(outcome, stage, problem or traceback, the translation's code when it has one)
    of parsing, translating and loading."""
    from autolev.loader import load_translation
    stage, code = "parse", None
    try:
        program = autolev.parse(path)
        stage = "translate"
        translation = autolev.translation(program)
        code = translation.code
        stage = "load"
        load_translation(translation, str(path))
    except autolev.AutolevError as exc:
        problem = diagnostics_problem(exc, str(path), text)
        return ("crash", stage, problem, code) if problem else ("diagnosed", stage, None, code)
    except MemoryError:
        return "memory", stage, "MemoryError", code
    except (Exception, SystemExit):  # noqa: BLE001 -- a fuzzer catches everything
        return "crash", stage, traceback.format_exc(), code
    return "ok", stage, None, code


def load_case(path: Path, text: str) -> tuple[str, str, str | None]:
    """(outcome, stage, problem or traceback) of parsing, translating and loading."""
    return load_stages(path, text)[:3]


def _listing(folder: Path) -> set[str]:
    try:
        return set(os.listdir(folder))
    except OSError:
        return set()


def _escaped_files(private: list[Path], shared: list[Path], before: dict,
                   case: Case) -> list[str]:
    """Entries new since `before`: any in a private folder; in a shared folder (others
    write there too), those whose name the case mentions."""
    found = []
    for folder in private + shared:
        for name in sorted(_listing(folder) - before[folder]):
            if folder in private or name in case.text or name in case.filename:
                found.append(str(folder / name))
    return found


def check_case(case: Case, folder: Path) -> dict:
    """Run one case in this process (its file written into folder/case)."""
    case_dir = folder / "case"
    shutil.rmtree(case_dir, ignore_errors=True)
    case_dir.mkdir()
    path = case_dir / case.filename
    path.write_bytes(case.text.encode("utf-8", "surrogateescape"))
    private = [folder, Path.cwd()]
    shared = [Path(tempfile.gettempdir()), ROOT, ROOT / "bench", Path.home()]
    before = {d: _listing(d) for d in private + shared}
    t0 = time.perf_counter()
    outcome, stage, detail = load_case(path, case.text)
    seconds = time.perf_counter() - t0
    escaped = _escaped_files(private, shared, before, case)
    if escaped:
        outcome, detail = "escaped", "new files outside the case folder: " + ", ".join(escaped)
    rss_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return {"outcome": outcome, "stage": stage, "detail": detail, "seconds": seconds,
            "rss_mb": rss_mb}


# ---------------------------------------------------------------------------------
# Files, commands and threads modes: the worker

OUTSIDE = "@OUTSIDE@"
# the outcomes of one case, the worst first
SEVERITY = ("escaped", "clobbered", "crash", "memory", "wrong", "leftover", "diagnosed", "ok")


def _write_text(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(text.encode("utf-8", "surrogateescape"))


def set_up(case: Case, folder: Path) -> tuple[Path, Path]:
    """The case's folder (its model, the files beside it, what is planted) and the
    folder beside it that planted links lead to, both made afresh."""
    case_dir, outside = folder / "case", folder / "outside"
    for d in (case_dir, outside):
        shutil.rmtree(d, ignore_errors=True)
        d.mkdir()
    for name, text in case.outside.items():
        _write_text(outside / name, text)
    _write_text(case_dir / case.filename, case.text.replace(OUTSIDE, str(outside)))
    for name, text in case.files.items():
        _write_text(case_dir / name, text.replace(OUTSIDE, str(outside)))
    if case.mode == "commands":
        (case_dir / "out").mkdir(exist_ok=True)
    for name, (kind, target) in case.links.items():
        path = case_dir / name
        if any(a.is_symlink() for a in path.parents if a.is_relative_to(case_dir)) or \
                os.path.lexists(path):
            continue        # under a link planted before it (it would land outside), or
            #                 a folder made for one planted before it
        path.parent.mkdir(parents=True, exist_ok=True)
        if not path.parent.resolve().is_relative_to(case_dir.resolve()):
            raise RuntimeError(f"the case plants {name} outside its folder")
        if kind == "symlink":
            os.symlink(target.replace(OUTSIDE, str(outside)).replace("@SELF@", path.name),
                       path)
        elif kind == "hardlink":
            os.link(outside / target, path)
        elif kind == "file":
            path.write_text(target)
        elif kind == "dir":
            path.mkdir()
        else:
            os.mkfifo(path)
    return case_dir, outside


def tree_state(root: Path, skip=()) -> dict:
    """Every entry under root (links not followed) with what identifies its state:
    a link's text, a file's inode, size, time and digest."""
    skipped = {str(p) for p in skip}
    state = {}
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = [d for d in dirnames if os.path.join(dirpath, d) not in skipped]
        for name in dirnames + filenames:
            path = os.path.join(dirpath, name)
            if path in skipped:
                continue
            try:
                st = os.lstat(path)
                if stat.S_ISLNK(st.st_mode):
                    value = ("link", os.readlink(path))
                elif stat.S_ISREG(st.st_mode):
                    digest = hashlib.sha256(Path(path).read_bytes()).hexdigest() \
                        if st.st_size < 1 << 20 else ""
                    value = ("file", st.st_ino, st.st_size, st.st_mtime_ns, digest)
                else:
                    value = (stat.S_IFMT(st.st_mode), st.st_ino)
            except FileNotFoundError:
                continue
            state[os.path.relpath(path, root)] = value
    return state


def changes(before: dict, after: dict) -> list[str]:
    """What differs between two tree states, entry by entry."""
    def how(name: str) -> str:
        return "new" if name not in before else "removed" if name not in after else "changed"
    return [f"{name} {how(name)}" for name in sorted(before.keys() | after.keys())
            if before.get(name) != after.get(name)]


class Watch:
    """The files opened under one folder while a case runs (`sys.addaudithook(watch)`
    once in the worker; `start` and `stop` around what is watched)."""

    WRITING = os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_TRUNC | os.O_APPEND

    def __init__(self):
        self.root: str | None = None
        self.writes_only = False
        self.seen: list[str] = []

    def start(self, root: Path, writes_only: bool) -> None:
        self.root, self.writes_only, self.seen = os.path.realpath(root), writes_only, []

    def stop(self) -> list[str]:
        self.root = None
        return self.seen

    def __call__(self, event: str, args: tuple) -> None:
        root = self.root
        if event != "open" or root is None or isinstance(args[0], int):
            return
        # an exception here would be raised in the caller of open(): none may escape
        try:
            flags = args[2] if isinstance(args[2], int) else 0
            if self.writes_only and not flags & self.WRITING:
                return
            real = os.path.realpath(os.fsdecode(args[0]))
        except (TypeError, ValueError, OSError):
            return
        if real == root or real.startswith(root + os.sep):
            how = "written" if flags & self.WRITING else "read"
            self.seen.append(f"{os.fsdecode(args[0])} ({how})")


WATCH = Watch()


def run_cli(args: list[str]) -> tuple[int | None, str]:
    """autolev's command line in this process: (exit status, or None after an exception
    that escaped it; what it wrote, with the traceback)."""
    from autolev import cli
    err = io.StringIO()
    # both streams: `check` reports on stdout
    with contextlib.redirect_stdout(err), contextlib.redirect_stderr(err):
        try:
            status = cli.main(args)
        except SystemExit as exc:
            status = exc.code if isinstance(exc.code, int) else 2
        except BaseException:  # noqa: BLE001 -- what escapes main is a crash to report
            return None, err.getvalue() + traceback.format_exc()
    return status, err.getvalue()


def command_outcome(status: int | None, stderr: str) -> tuple[str, str | None]:
    """A command's outcome from its exit status and messages."""
    if status not in (0, 1, 2) or "Traceback (most recent call last)" in stderr:
        return "crash", f"exit status {status}:\n{stderr[-4000:]}"
    if "out of memory" in stderr:
        return "memory", stderr[-2000:]
    if status and not stderr.strip():
        return "crash", f"exit status {status} without a message"
    return ("ok" if status == 0 else "diagnosed"), None


def _arguments(argv: list[str], case_dir: Path, model: Path) -> list[str]:
    return [a.replace("{model}", str(model)).replace("{out}", str(case_dir / "out"))
            .replace("{case}", str(case_dir)) for a in argv]


def _worst(found: list[tuple[str, str, str | None]]) -> tuple[str, str, str | None]:
    """The worst (outcome, stage, detail) of those found."""
    return min(found, key=lambda f: SEVERITY.index(f[0]))


def _result(outcome: str, stage: str, detail: str | None, seconds: float) -> dict:
    return {"outcome": outcome, "stage": stage, "detail": detail, "seconds": seconds,
            "rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}


def check_files_case(case: Case, folder: Path) -> dict:
    """Load the model of a files case (and `autolev check` it and its files when the
    case says so): nothing outside its folder may be read or written; stray files with
    built-in names must not change what the model means."""
    case_dir, outside = set_up(case, folder)
    model = case_dir / case.filename
    skip = [folder / "stderr.txt"]
    before = tree_state(folder, skip)
    t0 = time.perf_counter()
    WATCH.start(outside, writes_only=False)
    try:
        outcome, stage, detail, code = load_stages(model, case.text)
        found = [(outcome, stage, detail)]
        for argv in case.commands:
            result, problem = command_outcome(*run_cli(_arguments(argv, case_dir, model)))
            found.append((result, argv[0], problem))
    finally:
        seen = WATCH.stop()
    seconds = time.perf_counter() - t0
    changed = changes(before, tree_state(folder, skip))
    if seen or changed:
        found.append(("escaped", stage, "outside the case's folder: " + ", ".join(
            seen[:5] + changed[:5])))
    elif case.strays and outcome == "ok":
        differs = _meaning_without_strays(case, case_dir, folder / "aside", code)
        if differs:
            found.append(("wrong", "strays", differs))
    return _result(*_worst(found), seconds)


def _meaning_without_strays(case: Case, case_dir: Path, aside: Path, code: str) -> str | None:
    """How the model's translation differs when its stray files are moved away."""
    shutil.rmtree(aside, ignore_errors=True)
    aside.mkdir()
    moved = [(case_dir / name, aside / f"{k}") for k, name in enumerate(case.strays)]
    for there, here in moved:
        there.rename(here)
    try:
        alone = autolev.translation(autolev.parse(case_dir / case.filename)).code
    except autolev.AutolevError as exc:
        return (f"the model translates with its stray files ({', '.join(case.strays)}), "
                f"and without them not: {exc}")
    finally:
        for there, here in moved:
            here.rename(there)
    if alone == code:
        return None
    first = next(k for k, (a, b) in enumerate(zip(alone.splitlines() + [""],
                                                   code.splitlines() + [""])) if a != b)
    return (f"stray files {', '.join(case.strays)} change the translation at its line "
            f"{first + 1}: {code.splitlines()[first:first + 1]} instead of "
            f"{alone.splitlines()[first:first + 1]}")


def compile_problem(program: Path, scratch: Path) -> str | None:
    """Why a C program autolev wrote does not compile and link (None: it does, or no
    compiler is installed)."""
    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None:
        return None
    done = subprocess.run([cc, "-w", "-o", str(scratch / "program"), str(program), "-lm"],
                          capture_output=True, text=True, preexec_fn=_without_memory_limit)
    if done.returncode == 0:
        return None
    return f"{program.name} does not compile:\n{done.stderr[-3000:]}"


def _without_memory_limit() -> None:
    """The compiler's memory is its own (the worker's limit is on the soft limit)."""
    hard = resource.getrlimit(resource.RLIMIT_AS)[1]
    resource.setrlimit(resource.RLIMIT_AS, (hard, hard))


# what a user leaves at a name: autolev may replace it only with --overwrite
_USERS_KINDS = ("file", "hardlink", "dir", "fifo")


def check_commands_case(case: Case, folder: Path) -> dict:
    """Run the commands of a case, one after the other, and judge each: its exit status
    and messages, what changed outside its output folder (the victims of planted links
    first), a user's file replaced without --overwrite, a temporary left behind, a C
    program written that does not compile."""
    case_dir, outside = set_up(case, folder)
    model = case_dir / case.filename
    scratch = folder / "scratch"
    scratch.mkdir(exist_ok=True)
    skip = [folder / "stderr.txt", case_dir / "out", scratch]
    planted = tree_state(case_dir)
    users = {name for name, (kind, _) in case.links.items() if kind in _USERS_KINDS}
    found = [("ok", "", None)]
    t0 = time.perf_counter()
    for argv in case.commands:
        args = _arguments(argv, case_dir, model)
        command = " ".join(argv[:1] + [a for a in argv[1:] if a.startswith("--")])
        around, inside = tree_state(folder, skip), tree_state(case_dir)
        untouched = [n for n in users if inside.get(n) == planted.get(n)]
        WATCH.start(outside, writes_only=True)
        try:
            status, stderr = run_cli(args)
        finally:
            seen = WATCH.stop()
        now = tree_state(case_dir)
        outcome, detail = command_outcome(status, stderr)
        found.append((outcome, command, detail))
        changed = changes(around, tree_state(folder, skip))
        if seen or changed:
            found.append(("escaped", command, "written outside the output folder: "
                          + ", ".join(seen[:5] + changed[:5]) + f"\n{stderr[-1500:]}"))
        if "--overwrite" not in args:
            replaced = [n for n in untouched if now.get(n) != inside.get(n)]
            if replaced:
                found.append(("clobbered", command, "replaced without --overwrite: "
                              + ", ".join(replaced)))
        left = [n for n in now if n not in inside and (
            os.path.basename(n).startswith(".") or n.endswith(".autolev-part"))]
        if left:
            found.append(("leftover", command, "temporaries left: " + ", ".join(left[:5])))
        if argv[0] == "code":
            for name, value in sorted(now.items()):
                if value[0] == "file" and name.endswith(".c") and inside.get(name) != value:
                    problem = compile_problem(case_dir / name, scratch)
                    if problem:
                        found.append(("wrong", "cc", problem))
        if _worst(found)[0] == "memory":
            break
    return _result(*_worst(found), time.perf_counter() - t0)


def _sweep_table(model, spec: dict, how: str, executor=None):
    options = {"backend": spec["backend"]}
    if how in ("thread-pool", "process-pool"):
        return model.sweep(spec["points"], spec["what"], executor=executor,
                           chunk_size=spec["chunk"], as_frame=False, progress=False, **options)
    return model.sweep(spec["points"], spec["what"], workers=1 if how == "alone" else 2,
                       chunk_size=spec["chunk"], as_frame=False, progress=False, **options)


def table_difference(table, truth) -> str | None:
    """How a sweep's table differs from the same sweep run alone (None: it does not)."""
    import numpy as np
    if table.names != truth.names or len(table) != len(truth):
        return f"columns {table.names} ({len(table)} rows), alone {truth.names} ({len(truth)})"
    for name in truth.names:
        got, expected = table[name], truth[name]
        if expected.dtype == object:
            same = list(got) == list(expected)
        else:
            same = np.allclose(got.astype(float), expected.astype(float), rtol=1e-9,
                               atol=1e-12, equal_nan=True)
        if not same:
            return f"column {name}: {list(got)}, alone {list(expected)}"
    return None


def check_threads_case(case: Case, folder: Path) -> dict:
    """Each sweep of a case run alone first, then all at once from their own threads
    (the last, "forked", afterwards from this thread alone): every table must be the one
    of its own model."""
    import multiprocessing

    from autolev.runtime import studies
    # workers started afresh fork from a server that has read autolev once (else each
    # imports it anew: seconds a case)
    multiprocessing.set_forkserver_preload(["__main__", "autolev.loader",
                                            "autolev.runtime.model"])
    case_dir, _ = set_up(case, folder)
    t0 = time.perf_counter()
    try:
        truths = [_sweep_table(autolev.load(case_dir / s["model"]), s, "alone")
                  for s in case.sweeps]
        models = [autolev.load(case_dir / s["model"]) for s in case.sweeps]
    except autolev.AutolevError as exc:
        return _result("diagnosed", "alone", str(exc)[:2000], time.perf_counter() - t0)
    except (Exception, SystemExit):  # noqa: BLE001 -- a fuzzer catches everything
        return _result("crash", "alone", traceback.format_exc(), time.perf_counter() - t0)
    kept, studies.LOCAL_SECONDS = studies.LOCAL_SECONDS, 0.0   # a few points go to workers
    try:
        tables, failures = _sweeps_at_once(case, case_dir, models)
    finally:
        studies.LOCAL_SECONDS = kept
    return _result(*_worst(judge_sweeps(case, tables, failures, truths)),
                   time.perf_counter() - t0)


def _sweeps_at_once(case: Case, case_dir: Path, models: list) -> tuple[list, list]:
    """The tables of a case's sweeps run from their own threads at once (the "forked"
    one afterwards, alone), and the traceback of each that raised."""
    import multiprocessing
    import threading
    from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor
    tables: list = [None] * len(case.sweeps)
    failures: list = [None] * len(case.sweeps)
    pools = {"thread-pool": ThreadPoolExecutor(2),
             "process-pool": ProcessPoolExecutor(
                 2, mp_context=multiprocessing.get_context("forkserver"))}

    def sweep(k: int) -> None:
        spec = case.sweeps[k]
        try:
            model = autolev.load(case_dir / spec["model"]) if spec["load"] == "thread" \
                else models[k]
            tables[k] = _sweep_table(model, spec, spec["how"], pools.get(spec["how"]))
        except BaseException:  # noqa: BLE001 -- reported as the case's crash
            failures[k] = traceback.format_exc()
    threads = [threading.Thread(target=sweep, args=(k,))
               for k, s in enumerate(case.sweeps) if s["how"] != "forked"]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for pool in pools.values():
        pool.shutdown()
    for k, spec in enumerate(case.sweeps):
        if spec["how"] == "forked":
            sweep(k)
    return tables, failures


def judge_sweeps(case: Case, tables: list, failures: list, truths: list) -> list:
    """(outcome, stage, detail) of each sweep: a crash, or wrong when its table is not
    the one it gave alone (naming the model whose rows it holds)."""
    found = [("ok", "threads", None)]
    for k, spec in enumerate(case.sweeps):
        stage = "forked" if spec["how"] == "forked" else "threads"
        label = f"{spec['model']} ({spec['what']}, {spec['how']}, loaded {spec['load']})"
        if failures[k]:
            found.append(("crash", stage, f"{label}:\n{failures[k]}"))
            continue
        difference = table_difference(tables[k], truths[k])
        if difference:
            others = [case.sweeps[j]["model"] for j in range(len(truths))
                      if case.sweeps[j]["model"] != spec["model"] and
                      table_difference(tables[k], truths[j]) is None]
            found.append(("wrong", stage, f"{label}: {difference}"
                          + (f" (the rows of {', '.join(others)})" if others else "")))
    return found


CHECKS = {"files": check_files_case, "commands": check_commands_case,
          "threads": check_threads_case, "stale": fuzz_stale.check_stale_case,
          "background": fuzz_background.check_background_case,
          "hostile": fuzz_hostile.check_hostile_case}


def worker_main(folder: Path, memory_mb: int) -> int:
    """Read cases (JSON lines) on stdin, answer results (JSON lines) on stdout."""
    from autolev import loader  # noqa: F401 -- import everything before the limit
    protocol = os.fdopen(os.dup(1), "w", encoding="utf-8")
    os.dup2(2, 1)                 # what the tool prints must not mix into the answers
    # the soft limit: a compiler started for a case may raise its own
    limit = memory_mb * 1024 * 1024
    resource.setrlimit(resource.RLIMIT_AS, (limit, resource.getrlimit(resource.RLIMIT_AS)[1]))
    sys.addaudithook(WATCH)
    protocol.write("ready\n")
    protocol.flush()
    for line in sys.stdin:
        case = Case(**json.loads(line))
        result = CHECKS.get(case.mode, check_case)(case, folder)
        protocol.write(json.dumps(result) + "\n")
        protocol.flush()
        if result["outcome"] == "memory":
            return 0              # a worker that ran out of memory is not to be trusted
    return 0


# ---------------------------------------------------------------------------------
# Grammar mode: the parent

STARTUP_SECONDS = 300


class Worker:
    """A long-lived worker subprocess; restarted after a hang or a death."""

    def __init__(self, root: Path, number: int, memory_mb: int):
        self.root, self.number, self.memory_mb = root, number, memory_mb
        self.starts = 0
        self.proc: subprocess.Popen | None = None
        self.folder = root
        self.buffer = b""
        self.case: Case | None = None
        self.started = 0.0

    def start(self) -> None:
        self.starts += 1
        self.folder = self.root / f"worker{self.number}-{self.starts}"
        (self.folder / "cwd").mkdir(parents=True)
        # autolev's own state (its cache, its record of files written, its key) in the
        # run's folder, shared by the workers: never the user's
        home = self.root / "home"
        env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1",
                   MKL_NUM_THREADS="1", PYTHONHASHSEED="0", AUTOLEV_TRACEBACK="1",
                   XDG_STATE_HOME=str(home / "state"), XDG_CACHE_HOME=str(home / "cache"),
                   XDG_CONFIG_HOME=str(home / "config"),
                   AUTOLEV_CACHE=str(home / "cache" / "autolev"))
        with open(self.folder / "stderr.txt", "wb") as err:
            # a session of its own: a hang's kill takes the processes it started too
            self.proc = subprocess.Popen(
                [sys.executable, str(Path(__file__).resolve()), "--worker", str(self.folder),
                 "--memory-mb", str(self.memory_mb)],
                stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=err,
                cwd=self.folder / "cwd", env=env, start_new_session=True)
        self.buffer = b""
        line = self._read_line(time.monotonic() + STARTUP_SECONDS)
        if line != "ready":
            self.stop()
            raise RuntimeError(f"fuzz worker did not start:\n{self.stderr_tail()}")

    def stop(self) -> None:
        if self.proc is not None:
            self._kill_group()
            self.proc.wait()
            for stream in (self.proc.stdin, self.proc.stdout):
                stream.close()
            self.proc = None

    def _kill_group(self) -> None:
        """Kill the worker and what it started (its session's group), while its id is
        still the worker's (not yet waited for)."""
        if self.proc.returncode is None:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(self.proc.pid, signal.SIGKILL)

    def stderr_tail(self) -> str:
        try:
            return (self.folder / "stderr.txt").read_bytes()[-2000:].decode("utf-8", "replace")
        except OSError:
            return ""

    def _read_line(self, deadline: float) -> str | None:
        """The next line from the worker; None on a timeout, "" when it died."""
        fd = self.proc.stdout.fileno()
        while b"\n" not in self.buffer:
            left = max(0.0, deadline - time.monotonic())
            if not select.select([fd], [], [], left)[0]:
                return None
            chunk = os.read(fd, 1 << 16)
            if not chunk:
                return ""
            self.buffer += chunk
        line, self.buffer = self.buffer.split(b"\n", 1)
        return line.decode("utf-8")

    def submit(self, case: Case) -> Result | None:
        """Send a case; a Result at once only if the worker died on receiving it."""
        if self.proc is None:
            self.start()
        self.case, self.started = case, time.monotonic()
        try:
            self.proc.stdin.write((json.dumps(asdict(case)) + "\n").encode("ascii"))
            self.proc.stdin.flush()
        except BrokenPipeError:
            return self._died()
        return None

    def peak_rss_mb(self) -> float:
        try:
            status = Path(f"/proc/{self.proc.pid}/status").read_text()
        except OSError:
            return 0.0
        found = re.search(r"VmHWM:\s+(\d+) kB", status)
        return int(found.group(1)) / 1024 if found else 0.0

    def poll(self, timeout: float) -> Result | None:
        """The running case's result if it is done or over time, else None."""
        line = self._read_line(time.monotonic())
        if line is None and time.monotonic() - self.started > timeout:
            rss = self.peak_rss_mb()
            self.stop()
            return self._finish("hang", time.monotonic() - self.started, rss,
                                f"no answer within {timeout:g} s")
        if line is None:
            return None
        if line == "":
            return self._died()
        answer = json.loads(line)
        if answer["outcome"] == "memory":
            self.stop()
        return self._finish(answer["outcome"], answer["seconds"], answer["rss_mb"],
                            answer["detail"], answer["stage"])

    def _died(self) -> Result:
        # its end waited for but not collected: what it started goes, then the status
        os.waitid(os.P_PID, self.proc.pid, os.WEXITED | os.WNOWAIT)
        self._kill_group()
        code = self.proc.wait()
        tail = self.stderr_tail()
        self.stop()
        killed = code in (-signal.SIGKILL, -signal.SIGABRT) or "MemoryError" in tail
        detail = f"worker died (exit status {code}):\n{tail}"
        return self._finish("memory" if killed else "crash",
                            time.monotonic() - self.started, 0.0, detail)

    def _finish(self, outcome: str, seconds: float, rss_mb: float, detail: str | None,
                stage: str = "") -> Result:
        case, self.case = self.case, None
        return Result(case.index, case.generator, outcome, seconds, rss_mb, stage, detail)

    def fileno(self) -> int:
        return self.proc.stdout.fileno()


def run_cases(cases: list[Case], jobs: int = 1, timeout: float = 60.0,
              memory_mb: int = 2048, progress=None,
              deadline: float | None = None) -> list[Result]:
    """Every case through a pool of `jobs` workers (none started after `deadline`, a
    time.monotonic()); the results in case order."""
    queue = deque(cases)
    results: list[Result] = []

    def record(result: Result | None) -> None:
        if result is not None:
            results.append(result)
            if progress is not None:
                progress(results, len(cases))
    with tempfile.TemporaryDirectory(prefix="autolev-fuzz-") as tmp:
        pool = [Worker(Path(tmp), k, memory_mb) for k in range(max(1, min(jobs, len(cases))))]
        try:
            while queue or any(w.case is not None for w in pool):
                if deadline is not None and time.monotonic() > deadline:
                    queue.clear()
                for w in pool:
                    if w.case is None and queue:
                        record(w.submit(queue.popleft()))
                busy = [w for w in pool if w.case is not None]
                if not busy:
                    continue
                wait = min(w.started + timeout for w in busy) - time.monotonic()
                if not any(w.buffer for w in busy):
                    select.select(busy, [], [], max(0.0, wait))
                for w in busy:
                    record(w.poll(timeout))
        finally:
            for w in pool:
                w.stop()
    return sorted(results, key=lambda r: r.index)


# ---------------------------------------------------------------------------------
# Reports

OUTCOMES = ("ok", "diagnosed", "crash", "hang", "memory", "escaped", "clobbered", "leftover",
            "wrong", "stale", "error", "leaked")
FAILURES = OUTCOMES[2:]
# what each mode can tell ("-" in the table for the rest)
MEASURED = {"mutation": ("ok", "diagnosed", "crash"), "grammar": OUTCOMES[:6],
            "files": OUTCOMES[:6] + ("wrong",), "commands": OUTCOMES,
            "threads": OUTCOMES[:5] + ("wrong",), "stale": fuzz_stale.OUTCOMES,
            "background": fuzz_background.OUTCOMES, "hostile": fuzz_hostile.OUTCOMES}
# seconds a case may take, by mode (--timeout overrides)
TIMEOUTS = {"grammar": 60.0, "files": 120.0, "commands": 180.0, "threads": 120.0,
            "stale": 900.0, "background": 600.0, "hostile": 300.0}


@dataclass
class Row:
    label: str
    seed: int
    outcomes: Counter
    slowest: float
    peak_rss_mb: float
    total: float
    measured: tuple[str, ...] = OUTCOMES


def table(rows: list[Row], first: str) -> str:
    width = {o: max(len(o), 5) for o in OUTCOMES}
    label = max([10] + [len(r.label) for r in rows])
    head = (f"{first:<{label}} {'seed':>4} {'cases':>6} "
            + " ".join(f"{o:>{width[o]}}" for o in OUTCOMES)
            + f" {'slowest s':>9} {'peak RSS MB':>11} {'total s':>8}")
    out = [head, "-" * len(head)]
    for r in rows:
        counts = " ".join(f"{r.outcomes[o] if o in r.measured else '-':>{width[o]}}"
                          for o in OUTCOMES)
        out.append(f"{r.label:<{label}} {r.seed:>4} {sum(r.outcomes.values()):>6} {counts} "
                   f"{r.slowest:>9.2f} {r.peak_rss_mb:>11.0f} {r.total:>8.1f}")
    return "\n".join(out)


def _printable(text: str, limit: int = 1500) -> str:
    """The source of a case as it can be shown: control characters as escapes."""
    shown = text[:limit] + (f"\n... ({len(text) - limit} more characters)"
                            if len(text) > limit else "")
    return re.sub("[\x00-\x08\x0b-\x1f\x7f-\x9f\u2028\u2029\ud800-\udfff]",
                  lambda m: m.group().encode("unicode_escape", "backslashreplace")
                  .decode("ascii"), shown)


def describe(case: Case) -> str:
    """A case as it can be shown: its model, the files beside it, what is planted, what
    is run."""
    parts = [f"{case.filename}:\n{_printable(case.text)}"]
    others = [name for name in case.files if name != case.filename]
    for name in others[:6]:
        parts.append(f"{name!r}:\n{_printable(case.files[name], 400)}")
    if len(others) > 6:
        parts.append(f"... and {len(others) - 6} more files: {', '.join(others[6:])}")
    parts += [f"planted {name!r}: {kind} {target!r}" for name, (kind, target)
              in case.links.items()]
    parts += ["$ autolev " + " ".join(argv) for argv in case.commands]
    parts += [f"sweep: {json.dumps(spec)}" for spec in case.sweeps]
    parts += fuzz_stale.described(case) if case.mode == "stale" else []
    parts += fuzz_background.described(case) if case.mode == "background" else []
    parts += fuzz_hostile.described(case) if case.mode == "hostile" else []
    return "\n".join(parts)


def mode_rows(mode: str, seed: int, n: int, jobs: int, timeout: float, memory_mb: int,
              shown: int = 3, minutes: float | None = None,
              first: int = 0) -> tuple[Row, list[Row]]:
    """Run cases first..n-1 of a mode and seed (those that start within `minutes`): its
    row and its rows per generator."""
    cases = {i: make_case(mode, seed, i) for i in range(first, n)}
    t0 = time.perf_counter()
    step = 500 if mode == "grammar" else 100

    def progress(done: list, total: int) -> None:
        # a failure said when found and the tally with each step: a run cut short
        # keeps what it learnt
        last = done[-1]
        if last.outcome in FAILURES:
            print(f"  {last.outcome} {seed}:{last.index} ({last.generator}): "
                  f"{_printable((last.detail or '').strip()[-200:], 200)}",
                  file=sys.stderr, flush=True)
        if len(done) % step == 0:
            tally = Counter(r.outcome for r in done)
            print(f"  {mode} seed {seed}: {len(done)}/{total} cases, "
                  f"{time.perf_counter() - t0:.0f} s; "
                  + ", ".join(f"{o} {tally[o]}" for o in OUTCOMES if tally[o]),
                  file=sys.stderr, flush=True)
    deadline = None if minutes is None else time.monotonic() + 60 * minutes
    results = run_cases(list(cases.values()), jobs, timeout, memory_mb, progress, deadline)
    total = time.perf_counter() - t0
    failures = [r for r in results if r.outcome in FAILURES]
    mode_option = "" if mode == "grammar" else f" --mode {mode}"
    for r in failures[:shown]:
        case = cases[r.index]
        print(f"--- {r.outcome} in {r.stage or 'the worker'}: case {seed}:{r.index} "
              f"({r.generator}, file {case.filename!r}; replay with bench/fuzz.py "
              f"--replay {seed}:{r.index}{mode_option})\n{describe(case)}\n--- {r.detail}",
              file=sys.stderr)
    for r in failures:
        last = (r.detail or "").strip().splitlines()[-1:] or [""]
        print(f"  {r.outcome:<7} {seed}:{r.index:<5} {r.generator:<9} {r.stage or '-':<9} "
              f"{r.seconds:6.1f} s  {_printable(last[0], 120)}", file=sys.stderr)
    slowest = sorted(results, key=lambda r: -r.seconds)[:3]
    print(f"  {mode} seed {seed}: the slowest cases " + ", ".join(
        f"{seed}:{r.index} ({r.generator}, {r.outcome}) {r.seconds:.1f} s" for r in slowest),
        file=sys.stderr)
    generators = MODES[mode][0]

    def row(label: str, rs: list[Result]) -> Row:
        return Row(label, seed, Counter(r.outcome for r in rs),
                   max((r.seconds for r in rs), default=0.0),
                   max((r.rss_mb for r in rs), default=0.0),
                   sum(r.seconds for r in rs) if label in generators else total,
                   MEASURED[mode])
    by_generator = [row(g, [r for r in results if r.generator == g]) for g in generators]
    return row(mode, results), by_generator


def grammar_rows(seed: int, n: int, jobs: int, timeout: float, memory_mb: int,
                 shown: int = 3) -> tuple[Row, list[Row]]:
    """Run n grammar cases of one seed: its row and its rows per generator."""
    return mode_rows("grammar", seed, n, jobs, timeout, memory_mb, shown)


def write_case(case: Case, into: Path) -> list[str]:
    """A case's files written into a folder as the worker makes them (case/, outside/);
    its commands, as they are run there."""
    if case.mode == "stale":
        return fuzz_stale.write_case(case, into)
    if case.mode == "background":
        return fuzz_background.write_case(case, into)
    if case.mode == "hostile":
        return fuzz_hostile.write_case(case, into)
    into.mkdir(parents=True, exist_ok=True)
    case_dir, _ = set_up(case, into)
    model = case_dir / case.filename
    for spec in case.sweeps:
        print(f"sweep: {json.dumps(spec)}")
    return [" ".join(["autolev", *map(shlex.quote, _arguments(argv, case_dir, model))])
            for argv in case.commands]


def replay(mode: str, seed: int, index: int, into: Path | None, timeout: float,
           memory_mb: int) -> int:
    """One case again: written into a folder (`into`), or run in a fresh worker with its
    outcome shown (exit status 1 when it fails)."""
    case = make_case(mode, seed, index)
    if mode == "grammar" and into is None:
        print(f"{case.generator} case, file name {case.filename!r}", file=sys.stderr)
        sys.stdout.buffer.write(case.text.encode("utf-8", "surrogateescape"))
        return 0
    if into is not None:
        for command in write_case(case, into):
            print(command)
        print(f"{case.generator} case written into {into}", file=sys.stderr)
        return 0
    print(describe(case), file=sys.stderr)
    [result] = run_cases([case], 1, timeout, memory_mb)
    print(f"{result.outcome} in {result.stage or 'the worker'} ({result.seconds:.1f} s)"
          + (f"\n{result.detail}" if result.detail else ""))
    return 1 if result.outcome in FAILURES else 0


def main() -> int:
    global CORPUS
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mode", default="mutation",
                    help="mutation, grammar, files, commands, threads, stale, background, "
                    "hostile, or several comma-separated; all: every one")
    ap.add_argument("--mutants", type=int, default=10000, help="mutation mode: mutants")
    ap.add_argument("--cases", type=int, default=10000, help="other modes: cases per seed")
    ap.add_argument("--first", type=int, default=0,
                    help="other modes: start at this case (a run stopped part way goes on)")
    ap.add_argument("--minutes", type=float,
                    help="other modes: start no case after this many minutes per seed")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--seeds", help="several seeds, comma-separated (instead of --seed)")
    ap.add_argument("--jobs", type=int, default=1, help="other modes: worker processes")
    ap.add_argument("--timeout", type=float,
                    help="seconds per case (default: grammar 60, files 120, commands 180, "
                    "threads 120, stale 900, background 600, hostile 300)")
    ap.add_argument("--memory-mb", type=int, default=2048, help="worker memory limit")
    ap.add_argument("--corpus", type=Path, default=CORPUS)
    ap.add_argument("--replay", metavar="SEED:INDEX",
                    help="one case of --mode again: a grammar case's source to stdout (its "
                    "file name to stderr); a case of the other modes run alone, its outcome "
                    "shown")
    ap.add_argument("--into", type=Path,
                    help="with --replay: write the case's files into this folder and print "
                    "its commands")
    ap.add_argument("--worker", type=Path, help=argparse.SUPPRESS)
    ns = ap.parse_args()
    if ns.worker is not None:
        return worker_main(ns.worker, ns.memory_mb)
    modes = ["mutation", *MODES] if ns.mode == "all" else ns.mode.split(",")
    unknown = [m for m in modes if m != "mutation" and m not in MODES]
    if unknown:
        ap.error(f"--mode: no mode {', '.join(unknown)}")
    CORPUS = fuzz_stale.CORPUS = ns.corpus
    if ns.replay:
        seed, index = (int(x) for x in ns.replay.split(":"))
        mode = "grammar" if modes == ["mutation"] else modes[0]
        return replay(mode, seed, index, ns.into, ns.timeout or TIMEOUTS[mode], ns.memory_mb)
    seed_list = [int(s) for s in ns.seeds.split(",")] if ns.seeds else [ns.seed]
    rows: list[Row] = []
    generator_rows: list[Row] = []
    if "mutation" in modes:
        files = seeds(ns.corpus)
        for seed in seed_list:
            print(f"{len(files)} seed files; {ns.mutants} mutants; seed {seed}")
            t0 = time.perf_counter()
            outcomes, slowest = mutation_run(ns.mutants, seed, files)
            dt = time.perf_counter() - t0
            print(f"parsed {outcomes['parsed']}, diagnosed {outcomes['diagnosed']}, "
                  f"crash {outcomes['crash']}  ({dt:.1f} s, {ns.mutants / dt:.0f} mutants/s)")
            counts = Counter(ok=outcomes["parsed"], diagnosed=outcomes["diagnosed"],
                             crash=outcomes["crash"])
            rows.append(Row("mutation", seed, counts, slowest,
                            resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, dt,
                            MEASURED["mutation"]))
    # a terminated run still stops its workers and removes its folders
    signal.signal(signal.SIGTERM, lambda signum, frame: sys.exit(128 + signum))
    for mode in (m for m in MODES if m in modes):
        timeout = ns.timeout or TIMEOUTS[mode]
        for seed in seed_list:
            print(f"{mode}: cases {ns.first}..{ns.cases - 1}; seed {seed}; {ns.jobs} worker(s); "
                  f"timeout {timeout:g} s; memory {ns.memory_mb} MB"
                  + (f"; at most {ns.minutes:g} minutes" if ns.minutes else ""), flush=True)
            row, by_generator = mode_rows(mode, seed, ns.cases, ns.jobs, timeout,
                                          ns.memory_mb, minutes=ns.minutes, first=ns.first)
            rows.append(row)
            generator_rows.extend(by_generator)
    if modes != ["mutation"] or len(seed_list) > 1:
        print("\n" + table(rows, "mode"))
        if generator_rows:
            print("\n" + table(generator_rows, "generator"))
    return 1 if any(r.outcomes[o] for r in rows for o in FAILURES) else 0


if __name__ == "__main__":
    sys.exit(main())
