#!/usr/bin/env python3
"""Fuzzing: no input may end in a Python traceback, a hang, or a blown memory limit.

Two modes.

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

Each case is written (under its own file name) into a private folder of a long-lived
worker subprocess, which parses, translates and loads it (`autolev.parse`,
`autolev.translation`, `autolev.loader.load_translation`) under a memory limit
(RLIMIT_AS); the parent enforces the time limit, kills a worker that exceeds it and
starts a fresh one.  Outcomes:

  ok         the model loaded
  diagnosed  an AutolevError with well-formed diagnostics (line/col >= 1, a message)
  crash      any other exception, or a worker that died otherwise (the first ones are
             printed with the case's source, then one line per failure)
  hang       over the time limit
  memory     MemoryError, or the worker was killed (over the memory limit)
  escaped    a file appeared outside the case's folder: any new file in the worker's
             own folders (its working directory), or one the case names in the temp
             folder, the repository or the home folder

Each case has its own random stream (from the seed and its index), so `--replay`
regenerates it alone.  With several seeds or the grammar mode, a table follows: one
row per mode and seed (wall time; for mutants, "ok" counts those that parsed and "-"
marks what is not measured), then one row per seed and generator (summed case times).
The exit status is 1 when anything crashed, hung, blew the memory limit or escaped.

    python bench/fuzz.py [--mutants 10000] [--seed 1] [--corpus DIR]
    python bench/fuzz.py --mode grammar|all [--cases 10000] [--seeds 1,2] [--jobs 1]
                         [--timeout 60] [--memory-mb 2048]
    python bench/fuzz.py --replay SEED:INDEX > case.al   # one grammar case's source
"""
from __future__ import annotations

import argparse
import csv
import json
import math
import os
import random
import re
import resource
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import traceback
from collections import Counter, deque
from dataclasses import asdict, dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

import autolev  # noqa: E402

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
    listing = ROOT.parent / "shared" / "corpus" / "visible.tsv"
    out = []
    if listing.exists():
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
    """One generated model: its source and the name of its file."""

    index: int
    generator: str
    filename: str
    text: str


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
    def declare(self) -> None:
        r = self.rng
        if r.random() < 0.97:
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


def load_case(path: Path, text: str) -> tuple[str, str, str | None]:
    """(outcome, stage, problem or traceback) of parsing, translating and loading."""
    from autolev.loader import load_translation
    stage = "parse"
    try:
        program = autolev.parse(path)
        stage = "translate"
        translation = autolev.translation(program)
        stage = "load"
        load_translation(translation, str(path))
    except autolev.AutolevError as exc:
        problem = diagnostics_problem(exc, str(path), text)
        return ("crash", stage, problem) if problem else ("diagnosed", stage, None)
    except MemoryError:
        return "memory", stage, "MemoryError"
    except (Exception, SystemExit):  # noqa: BLE001 -- a fuzzer catches everything
        return "crash", stage, traceback.format_exc()
    return "ok", stage, None


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


def worker_main(folder: Path, memory_mb: int) -> int:
    """Read cases (JSON lines) on stdin, answer results (JSON lines) on stdout."""
    from autolev import loader  # noqa: F401 -- import everything before the limit
    protocol = os.fdopen(os.dup(1), "w", encoding="utf-8")
    os.dup2(2, 1)                 # what the tool prints must not mix into the answers
    limit = memory_mb * 1024 * 1024
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    protocol.write("ready\n")
    protocol.flush()
    for line in sys.stdin:
        result = check_case(Case(**json.loads(line)), folder)
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
        env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1",
                   MKL_NUM_THREADS="1", PYTHONHASHSEED="0")
        with open(self.folder / "stderr.txt", "wb") as err:
            self.proc = subprocess.Popen(
                [sys.executable, str(Path(__file__).resolve()), "--worker", str(self.folder),
                 "--memory-mb", str(self.memory_mb)],
                stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=err,
                cwd=self.folder / "cwd", env=env)
        self.buffer = b""
        line = self._read_line(time.monotonic() + STARTUP_SECONDS)
        if line != "ready":
            self.stop()
            raise RuntimeError(f"fuzz worker did not start:\n{self.stderr_tail()}")

    def stop(self) -> None:
        if self.proc is not None:
            if self.proc.poll() is None:
                self.proc.kill()
            self.proc.wait()
            for stream in (self.proc.stdin, self.proc.stdout):
                stream.close()
            self.proc = None

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
              memory_mb: int = 2048, progress=None) -> list[Result]:
    """Every case through a pool of `jobs` workers; the results in case order."""
    queue = deque(cases)
    results: list[Result] = []

    def record(result: Result | None) -> None:
        if result is not None:
            results.append(result)
            if progress is not None:
                progress(len(results), len(cases))
    with tempfile.TemporaryDirectory(prefix="autolev-fuzz-") as tmp:
        pool = [Worker(Path(tmp), k, memory_mb) for k in range(max(1, min(jobs, len(cases))))]
        try:
            while queue or any(w.case is not None for w in pool):
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

OUTCOMES = ("ok", "diagnosed", "crash", "hang", "memory", "escaped")
FAILURES = ("crash", "hang", "memory", "escaped")


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
    head = (f"{first:<10} {'seed':>4} {'cases':>6} " + " ".join(f"{o:>9}" for o in OUTCOMES)
            + f" {'slowest s':>9} {'peak RSS MB':>11} {'total s':>8}")
    out = [head, "-" * len(head)]
    for r in rows:
        counts = " ".join(f"{r.outcomes[o] if o in r.measured else '-':>9}" for o in OUTCOMES)
        out.append(f"{r.label:<10} {r.seed:>4} {sum(r.outcomes.values()):>6} {counts} "
                   f"{r.slowest:>9.2f} {r.peak_rss_mb:>11.0f} {r.total:>8.1f}")
    return "\n".join(out)


def _printable(text: str, limit: int = 1500) -> str:
    """The source of a case as it can be shown: control characters as escapes."""
    shown = text[:limit] + (f"\n... ({len(text) - limit} more characters)"
                            if len(text) > limit else "")
    return re.sub("[\x00-\x08\x0b-\x1f\x7f-\x9f\u2028\u2029\ud800-\udfff]",
                  lambda m: m.group().encode("unicode_escape", "backslashreplace")
                  .decode("ascii"), shown)


def grammar_rows(seed: int, n: int, jobs: int, timeout: float, memory_mb: int,
                 shown: int = 3) -> tuple[Row, list[Row]]:
    """Run n grammar cases of one seed: its row and its rows per generator."""
    cases = [grammar_case(seed, i) for i in range(n)]
    t0 = time.perf_counter()

    def progress(done: int, total: int) -> None:
        if done % 500 == 0:
            print(f"  seed {seed}: {done}/{total} cases, {time.perf_counter() - t0:.0f} s",
                  file=sys.stderr, flush=True)
    results = run_cases(cases, jobs, timeout, memory_mb, progress)
    total = time.perf_counter() - t0
    failures = [r for r in results if r.outcome in FAILURES]
    for r in failures[:shown]:
        case = cases[r.index]
        print(f"--- {r.outcome} in {r.stage or 'the worker'}: case {seed}:{r.index} "
              f"({r.generator}, file {case.filename!r}; replay with bench/fuzz.py --replay "
              f"{seed}:{r.index})\n{_printable(case.text)}\n--- {r.detail}", file=sys.stderr)
    for r in failures:
        last = (r.detail or "").strip().splitlines()[-1:] or [""]
        print(f"  {r.outcome:<7} {seed}:{r.index:<5} {r.generator:<8} {r.stage or '-':<9} "
              f"{r.seconds:6.1f} s  {_printable(last[0], 120)}", file=sys.stderr)

    def row(label: str, rs: list[Result]) -> Row:
        return Row(label, seed, Counter(r.outcome for r in rs),
                   max((r.seconds for r in rs), default=0.0),
                   max((r.rss_mb for r in rs), default=0.0),
                   sum(r.seconds for r in rs) if label in GENERATORS else total)
    by_generator = [row(g, [r for r in results if r.generator == g]) for g in GENERATORS]
    return row("grammar", results), by_generator


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mode", choices=("mutation", "grammar", "all"), default="mutation")
    ap.add_argument("--mutants", type=int, default=10000, help="mutation mode: mutants")
    ap.add_argument("--cases", type=int, default=10000, help="grammar mode: cases")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--seeds", help="several seeds, comma-separated (instead of --seed)")
    ap.add_argument("--jobs", type=int, default=1, help="grammar mode: worker processes")
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds per case")
    ap.add_argument("--memory-mb", type=int, default=2048, help="worker memory limit")
    ap.add_argument("--corpus", type=Path, default=Path(os.environ.get(
        "AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus")))
    ap.add_argument("--replay", metavar="SEED:INDEX",
                    help="write one grammar case's source to stdout (its file name to stderr)")
    ap.add_argument("--worker", type=Path, help=argparse.SUPPRESS)
    ns = ap.parse_args()
    if ns.worker is not None:
        return worker_main(ns.worker, ns.memory_mb)
    if ns.replay:
        seed, index = (int(x) for x in ns.replay.split(":"))
        case = grammar_case(seed, index)
        print(f"{case.generator} case, file name {case.filename!r}", file=sys.stderr)
        sys.stdout.buffer.write(case.text.encode("utf-8", "surrogateescape"))
        return 0
    seed_list = [int(s) for s in ns.seeds.split(",")] if ns.seeds else [ns.seed]
    rows: list[Row] = []
    generator_rows: list[Row] = []
    if ns.mode in ("mutation", "all"):
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
                            ("ok", "diagnosed", "crash")))
    if ns.mode in ("grammar", "all"):
        # a terminated run still stops its workers and removes its folders
        signal.signal(signal.SIGTERM, lambda signum, frame: sys.exit(128 + signum))
        for seed in seed_list:
            print(f"grammar: {ns.cases} cases; seed {seed}; {ns.jobs} worker(s); "
                  f"timeout {ns.timeout:g} s; memory {ns.memory_mb} MB", flush=True)
            row, by_generator = grammar_rows(seed, ns.cases, ns.jobs, ns.timeout,
                                             ns.memory_mb)
            rows.append(row)
            generator_rows.extend(by_generator)
    if ns.mode != "mutation" or len(seed_list) > 1:
        print("\n" + table(rows, "mode"))
        if generator_rows:
            print("\n" + table(generator_rows, "generator"))
    return 1 if any(r.outcomes[o] for r in rows for o in FAILURES) else 0


if __name__ == "__main__":
    sys.exit(main())
