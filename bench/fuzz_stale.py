"""The stale mode of bench/fuzz.py: inputs changed between runs.

autolev keeps answers in its cache: a translation, a built model, a run plan (a warm
`autolev run` without the model), a kept linearization, a kept outcome (what a model
without a CODE command printed) and a transcript, each filed under the digests of the
files as the command read them.  A cold run returns once its files are written and
compiles its C on in a background child, which then writes the plan: an input edited
meanwhile must not make a later run repeat the old answer.

Each case runs a command on a small model, changes ONE input at a random moment, runs
the command twice more (the second of them may come from a plan), and holds each of
those answers against a fresh run of the final inputs in an empty cache
(AUTOLEV_FOREGROUND=1): the output files byte for byte (NAME.1 ..., NAME.dir, NAME.in),
a linearization's eigenvalues (stdout), a kept outcome's or a transcript's stdout and
stderr, and the exit status.  What changes (the case's kind):

  in         a value of the --in file
  model      a statement of the model: an INPUT value, a force's constant, an OUTPUT item
  macro      a macro file (NAME.A) the model calls
  run-file   a file the model includes by RUN
  set        the --set value
  specified  a --specified NAME=EXPR
  env        AUTOLEV_NO_C or AUTOLEV_NO_PYEXT, set or unset (how numbers are computed)
  added      a file added beside the model: a macro in another case of letters that
             the call now finds first, a macro, RUN or function file that was missing,
             or a stray file nothing calls

and when (its moment; the case's generator is KIND@MOMENT):

  before     before the first command: a control, every answer is of the final inputs
  during     while the first command runs: a file edited, or the second command started
  locked     right after the first command returned, while its background child holds
             the model's lock (the compiler is a wrapper that sleeps before it links the
             loop's shared.o, so the child is still compiling)
  after      after the child finished

The commands: mostly `autolev run --out` (a fresh folder each time), some `autolev
linearize` (a fifth of them a --sweep long enough to compile its Jacobians), `autolev
run` of a model without CODE (a kept outcome) and `autolev transcript`.  The models:
the shipped examples, tests/data/numerics/harmonic.al, generated pendulums and spring
chains (with macros, RUN files, a SPECIFIED torque or force), and a few small corpus
models when ~/.cache/autolev-corpus is there.

Outcomes: ok; stale (an answer equal to the old inputs' one, or otherwise not the fresh
run's); crash (exit status 70, a traceback, a signal); hang (a command or a background
child over its time limit); error (an exit status other than the fresh run's).  A
result's stage, for an ok case, says whether the change moved the answer ("moved": the
first command's answer, of the old inputs, differs from the fresh one; "still").

Every case has its own folder, cache and home (XDG_*); every process it starts carries
a tag in its environment, and whatever is left at the case's end is killed by its id.
The fresh answers are kept by the content of the final inputs for one run of the fuzzer
(in the folder its workers share), so repeated final states cost one fresh run.

    python bench/fuzz.py --mode stale --cases 2000 --seeds 1,2 --jobs 2
    python bench/fuzz.py --mode stale --replay SEED:INDEX [--into DIR]
    PYTHONPATH=/tmp/landed/src python bench/fuzz.py --mode stale --cases 300
        # the commands import the tree PYTHONPATH names (the worker imports this one)
"""
from __future__ import annotations

import difflib
import fcntl
import hashlib
import json
import os
import random
import re
import resource
import shlex
import shutil
import signal
import subprocess
import sys
import time
from dataclasses import dataclass, field, replace
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "autolev_examples"
HARMONIC = ROOT / "tests" / "data" / "numerics" / "harmonic.al"
CORPUS = Path(os.environ.get("AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus"))

KINDS = ("in", "model", "macro", "run-file", "set", "specified", "env", "added")
KIND_WEIGHTS = (14, 16, 12, 12, 12, 10, 12, 12)
MOMENTS = ("before", "during", "locked", "after")
GENERATORS = tuple(f"{kind}@{moment}" for kind in KINDS for moment in MOMENTS)
# the kinds that change the command line or the environment (no file is written)
ARGUMENT_KINDS = ("set", "specified", "env")
COMMAND_WEIGHTS = {"run": 60, "linearize": 15, "outcome": 12, "transcript": 13}
# the commands whose answer each kind can change
COMMANDS_OF = {"in": ("run", "linearize"), "set": ("run", "linearize"),
               "specified": ("run", "linearize"), "env": ("run", "linearize", "outcome")}
OUTCOMES = ("ok", "crash", "hang", "stale", "error")
SEVERITY = ("crash", "hang", "stale", "error", "ok")
# the knobs of request.NUMBER_KNOBS a case turns (CC is the case's slow compiler)
KNOBS = ("AUTOLEV_NO_C", "AUTOLEV_NO_PYEXT")
# what the commands must not inherit from the fuzzer's environment
CLEARED = KNOBS + ("CC", "AUTOLEV_CACHE", "AUTOLEV_FOREGROUND", "AUTOLEV_NO_MODEL_CACHE",
                   "AUTOLEV_CACHE_LIMIT_MB")
TAG_VARIABLE = "AUTOLEV_FUZZ_TAG"
SLEEP_VARIABLE = "AUTOLEV_FUZZ_LINK_SLEEP"
COMMAND_SECONDS = 120.0          # a command over this is a hang
CHILD_SECONDS = 120.0            # so is a background child still holding its lock
# a case's commands and waits all end by then (its fresh runs have their own limits: the
# whole case stays within fuzz.TIMEOUTS["stale"], whose kill would leave the commands)
CASE_SECONDS = 480.0

# values drawn for constants and initial values (a few, so final states repeat)
# a linearization sweep's points: more than compiling its Jacobians costs on dual numbers
# for these models' sizes (runtime/numerics/linearize.py: _compiling_pays)
SWEEP_POINTS = 400
VALUES = ("0", "0.05", "0.3", "0.8", "1.5", "2.5", "-0.4", "7")
FACTORS = ("0.5", "1.5", "2", "-1")
EXPRESSIONS = ("0.5*SIN(2*T)", "0.3", "-0.2*T", "0.4*COS(3*T)", "0", "T^2")
# an INPUT name that is not a constant or initial value
_SETTINGS = {"TFINAL", "INTEGSTP", "ABSERR", "RELERR", "PRINTINT", "TINITIAL"}
_NUMBER = r"-?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?"
_INPUT_VALUE = re.compile(rf"(?i)\b([A-Z]\w*)(\s*=\s*)({_NUMBER})")
# a decimal written with a point in a macro or RUN file: never a #k# or part of a name
_DECIMAL = re.compile(r"(?<![\w#.])\d+\.\d+(?![\w#])")
_CODE_STATEMENT = re.compile(r"(?im)^[ \t]*CODE\b[^\n]*\n?")


@dataclass
class Source:
    """A model and the files beside it, with what a case may change of it."""

    label: str                  # example, chain or corpus: what it is
    model: str                  # the model's file name
    files: dict                 # name: text, the model's among them
    values: list                # names given a number by INPUT (for --set)
    specified: list = field(default_factory=list)   # SPECIFIED names left undefined
    macros: list = field(default_factory=list)      # macro files the model calls
    runs: list = field(default_factory=list)        # files it includes by RUN
    added: dict = field(default_factory=dict)       # a file added: {name: text}
    arguments: list = field(default_factory=list)   # given to its runs and linearizations
    tfinal: str | None = None                       # its runs' --tfinal


# ---------------------------------------------------------------------------------
# The models

def _input_names(text: str) -> list[str]:
    """The names an INPUT statement gives a number, settings aside."""
    names = []
    for line in text.splitlines():
        if line.lstrip().upper().startswith("INPUT"):
            names += [m.group(1) for m in _INPUT_VALUE.finditer(line.split("%")[0])
                      if m.group(1).upper() not in _SETTINGS]
    return list(dict.fromkeys(names))


def _undefined_specified(text: str) -> list[str]:
    """SPECIFIED names that no statement `NAME = ...` defines."""
    declared = []
    for line in text.splitlines():
        if re.match(r"(?i)\s*SPECIFIED\b", line):
            declared += re.findall(r"\b([A-Za-z]\w*)\b(?!\s*\{)", line.split("%")[0])[1:]
    return [name for name in declared
            if not re.search(rf"(?im)^\s*{name}\s*=", text)]


def example_sources() -> list[Source]:
    """The shipped examples and the harmonic oscillator of the tests."""
    found = []
    for path in sorted(EXAMPLES.glob("*.al")) + [HARMONIC]:
        text = path.read_text(encoding="utf-8")
        found.append(Source(f"example {path.stem}", path.name, {path.name: text},
                            _input_names(text), _undefined_specified(text)))
    return found


_CORPUS_SOURCES: dict = {}


def corpus_sources() -> list[Source]:
    """Small corpus models with a CODE DYNAMICS that include no file: run for 0.5 s, with
    0 for the constants they give no value (a singular mass matrix is an answer too)."""
    if CORPUS not in _CORPUS_SOURCES:
        found = []
        for path in sorted(CORPUS.rglob("*.al") if CORPUS.is_dir() else ()):
            if not path.is_file() or not 300 < path.stat().st_size < 6000:
                continue
            text = path.read_bytes().decode("latin-1")
            if re.search(r"(?im)^\s*CODE\s+DYNAMICS", text) and _input_names(text) and \
                    not re.search(r"(?im)^\s*RUN\b", text):
                name = re.sub(r"\W", "_", path.stem) + ".al"
                found.append(Source(f"corpus {path.relative_to(CORPUS)}", name,
                                    {name: text}, _input_names(text),
                                    _undefined_specified(text),
                                    arguments=["--zero-missing"], tfinal="0.5"))
        _CORPUS_SOURCES[CORPUS] = found
    return _CORPUS_SOURCES[CORPUS]


# each link's or mass's numbers, fixed (the cases' final states repeat, their fresh
# answers are kept)
_LENGTHS = ("1.0", "0.5", "0.8")
_MASSES = ("1.0", "2.0", "0.5")
_STIFFNESSES = ("20.0", "35.0", "12.0")
_ANGLES = ("0.3", "-0.2", "0.1")
# what a missing file, once added, brings: a torque (pendulum) or a force (chain)
_BROUGHT = {"pendulum": ("TORQUE(N/A#1#, -0.15*Q#1#'*N3>)", "TORQUE(N/A1, 0.2*N3>)",
                         "TORQUE(N/A{n}, -DAMPING(Q{n}')*N3>)"),
            "spring": ("FORCE(P#1#, -0.15*Q#1#'*N1>)", "FORCE(P1, 0.2*N1>)",
                       "FORCE(P{n}, -DAMPING(Q{n}')*N1>)")}


def chain_source(rng: random.Random, need: str | None, code: bool = True) -> Source:
    """A pendulum of 1-3 links or 1-3 masses on springs along N1>: its links or springs
    by a macro or written out, its constants' values (and the gravity) in a RUN file or
    not, a SPECIFIED torque or force or not, one damping force with a number written
    in the model; `need` (a case's kind) asks for what it changes."""
    shape = rng.choice(("pendulum", "spring"))
    n = rng.randint(1, 3)
    missing = rng.choice(("variant", "macro", "run", "function", "stray")) \
        if need == "added" else None
    macros = need == "macro" or missing == "variant" or rng.random() < 0.5
    run_file = need == "run-file" or rng.random() < 0.35
    specified = need == "specified" or rng.random() < 0.15
    stem = "chain"
    files: dict = {}
    idx = range(1, n + 1)
    head = [f"% {'a pendulum of' if shape == 'pendulum' else 'masses on springs,'} "
            f"{n} (bench/fuzz_stale.py)", "NEWTONIAN N"]
    if shape == "pendulum":
        head += ["FRAMES " + ", ".join(f"A{i}" for i in idx)]
        constants = ["G"] + [f"{x}{i}" for i in idx for x in "LM"]
        numbers = {"G": "9.81", **{f"L{i}": _LENGTHS[i - 1] for i in idx},
                   **{f"M{i}": _MASSES[i - 1] for i in idx}}
    else:
        constants = [f"{x}{i}" for i in idx for x in "KM"]
        numbers = {**{f"K{i}": _STIFFNESSES[i - 1] for i in idx},
                   **{f"M{i}": _MASSES[i - 1] for i in idx}}
    head += ["PARTICLES " + ", ".join(f"P{i}" for i in idx),
             "MOTIONVARIABLES' " + ", ".join(f"Q{i}''" for i in idx),
             "CONSTANTS " + ", ".join(constants)]
    spec = "TQ" if shape == "pendulum" else "FX"
    if specified:
        head.append(f"SPECIFIED {spec}")
    body: list[str] = []
    macro_names: list[str] = []
    for i in idx:
        base = "NO" if i == 1 else f"P{i - 1}"
        if shape == "spring":
            body += [f"P_{base}_P{i}> = Q{i}*N1>",
                     f"V_P{i}_N> = ({' + '.join(f'Q{j}' + chr(39) for j in range(1, i + 1))})"
                     "*N1>"]
        if macros:
            body.append(f"{'LINK' if shape == 'pendulum' else 'SPRING'}({i}, {base})")
        elif shape == "pendulum":
            body += [f"SIMPROT(N, A{i}, 3, Q{i})", f"P_{base}_P{i}> = {_LENGTHS[0]}*L{i}*A{i}1>",
                     f"V2PTS(N, A{i}, {base}, P{i})", f"MASS P{i} = M{i}"]
        else:
            body += [f"FORCE({base}/P{i}, -K{i}*Q{i}*N1> - 0.3*Q{i}'*N1>)",
                     f"MASS P{i} = M{i}"]
    if macros and shape == "pendulum":
        files["link.a"] = ("% one link: #1# its number, #2# the point it hangs from\n"
                           "SIMPROT(N, A#1#, 3, Q#1#)\nP_#2#_P#1#> = 1.0*L#1#*A#1#1>\n"
                           "V2PTS(N, A#1#, #2#, P#1#)\nMASS P#1# = M#1#\n")
        files["damp.a"] = "% a damper at link #1#\nTORQUE(N/A#1#, -0.25*Q#1#'*N3>)\n"
        body.append(f"DAMP({n})")
        macro_names = ["link.a", "damp.a"]
    elif macros:
        files["spring.a"] = ("% spring #1# between #2# and P#1#\n"
                             "FORCE(#2#/P#1#, -K#1#*Q#1#*N1> - 0.3*Q#1#'*N1>)\n"
                             "MASS P#1# = 1.0*M#1#\n")
        macro_names = ["spring.a"]
    # a force with a number in the model itself, for the model kind's edits
    body.append("TORQUE(N/A1, -0.2*Q1'*N3>)" if shape == "pendulum"
                else f"FORCE(P{n}, -0.05*Q{n}'*N1>)")
    if specified:
        body.append(f"TORQUE(N/A1, {spec}*N3>)" if shape == "pendulum"
                    else f"FORCE(P1, {spec}*N1>)")
    values = "INPUT " + ", ".join(f"{k} = {v}" for k, v in numbers.items())
    runs: list[str] = []
    if run_file:
        files["values.al"] = values + "\n" + ("GRAVITY(G*N1>)\n" if shape == "pendulum" else "")
        body.append("RUN VALUES.AL")
        runs = ["values.al"]
    elif shape == "pendulum":
        body.append("GRAVITY(G*N1>)")
    brings_macro, brings_run, brings_function = _BROUGHT[shape]
    added: dict = {}
    if missing == "variant":
        # the same file in capitals: a call in capitals finds it first (sorted)
        name = rng.choice(macro_names + runs)
        text = files[name]
        added[name.upper()] = _DECIMAL.sub(lambda m: rng.choice(("1.3", "0.7", "2.0")), text,
                                           count=1)
    elif missing == "macro":
        body.append("EXTRA(1)")
        added["extra.a"] = brings_macro + "\n"
    elif missing == "run":
        body.append("RUN more.al")
        added["more.al"] = brings_run + "\n"
    elif missing == "function":
        body.append(brings_function.format(n=n))
        added["damping.r"] = "0.2*#1#\n"
    elif missing == "stray":
        added[rng.choice(("spare.r", "Notes.A", "unused.al"))] = "#1# + 1\n"
    tail = ["ZERO = FR() + FRSTAR()", "KANE()"]
    if not run_file:
        tail.append(values)
    tail += ["INPUT " + ", ".join([f"Q{i} = {_ANGLES[i - 1]}" for i in idx]
                                  + [f"Q{i}' = 0.0" for i in idx]),
             "INPUT TFINAL = 0.5, INTEGSTP = 0.01",
             "OUTPUT T, " + ", ".join(f"Q{i}" for i in idx)]
    if rng.random() < 0.3:
        tail.append("OUTPUT T, " + ", ".join(f"Q{i}'" for i in idx))
    if code:
        tail.append(f"CODE DYNAMICS() {stem.lower()}.c")
    model = f"{stem}.al"
    files[model] = "\n".join(head + body + tail) + "\n"
    names = list(numbers) + [f"Q{i}" for i in idx]
    label = (f"chain {shape} {n}" + " macros" * macros + " run-file" * run_file
             + " specified" * specified + (f" missing-{missing}" if missing else ""))
    return Source(label, model, files, names, [spec] if specified else [], macro_names,
                  runs, added)


def _without_code(source: Source) -> Source:
    """The same model with its CODE statements taken out."""
    files = dict(source.files)
    files[source.model] = _CODE_STATEMENT.sub("", files[source.model])
    return Source(source.label + " no-CODE", source.model, files, source.values,
                  source.specified, source.macros, source.runs, source.added,
                  source.arguments)


def pick_source(rng: random.Random, kind: str, command: str) -> Source:
    """A model for the kind of change and the command."""
    code = command in ("run", "linearize") or (command == "transcript" and
                                               rng.random() < 0.5)
    if kind in ("macro", "run-file") or (kind == "added" and rng.random() < 0.85):
        return chain_source(rng, kind, code)
    if kind == "specified":
        examples = [s for s in example_sources() if s.specified]
        if examples and rng.random() < 0.25:
            return rng.choice(examples)
        return chain_source(rng, kind, code)
    choice = rng.random()
    corpus = corpus_sources()
    if kind == "added":             # an example, and a stray file beside it
        source = replace(rng.choice(example_sources()),
                         added={rng.choice(("spare.r", "NOTES.A")): "#1# + 1\n"})
    elif corpus and choice < 0.08:
        source = replace(rng.choice(corpus))
    elif choice < 0.55:
        source = rng.choice(example_sources())
    else:
        return chain_source(rng, None, code)
    return source if code else _without_code(source)


# ---------------------------------------------------------------------------------
# The edits of a model's statements

def _edit_input(rng: random.Random, text: str) -> str | None:
    lines = text.split("\n")
    spots = [(k, m) for k, line in enumerate(lines)
             if line.lstrip().upper().startswith("INPUT")
             for m in _INPUT_VALUE.finditer(line.split("%")[0])
             if m.group(1).upper() not in ("INTEGSTP", "PRINTINT", "ABSERR", "RELERR")]
    if not spots:
        return None
    k, m = rng.choice(spots)
    value = rng.choice(("0.5", "1.0", "2.0")) if m.group(1).upper() in _SETTINGS \
        else rng.choice(VALUES)
    lines[k] = lines[k][:m.start(3)] + value + lines[k][m.end(3):]
    return "\n".join(lines)


def _edit_force(rng: random.Random, text: str) -> str | None:
    """A force, torque or gravity statement's constant changed, or a factor put on it."""
    lines = text.split("\n")
    spots = [k for k, line in enumerate(lines)
             if re.match(r"(?i)\s*((FORCE|TORQUE|GRAVITY)\s*\(|(FORCE|TORQUE)_\w+>\s*=)",
                         line.split("%")[0])]
    if not spots:
        return None
    k = rng.choice(spots)
    code, comment = (lines[k].split("%", 1) + [""])[:2]
    comment = "%" + comment if comment else ""
    numbers = list(re.finditer(r"(?<![\w.])\d+\.\d+|(?<![\w.#])\d+(?![\w.>#])", code))
    if numbers and rng.random() < 0.6:
        m = rng.choice(numbers)
        code = code[:m.start()] + rng.choice(("0.05", "0.7", "3.0")) + code[m.end():]
    elif re.match(r"(?i)\s*(FORCE|TORQUE)_\w+>\s*=", code):
        left, right = code.split("=", 1)
        code = f"{left}= {rng.choice(FACTORS)}*({right.strip()})"
    else:
        start = code.index("(") + 1
        depth, comma = 0, None
        for pos in range(start, len(code)):
            depth += {"(": 1, ")": -1}.get(code[pos], 0)
            if code[pos] == "," and depth == 0:
                comma = pos
                break
        end = code.rindex(")")
        at = start if comma is None else comma + 1
        code = f"{code[:at]} {rng.choice(FACTORS)}*({code[at:end].strip()}){code[end:]}"
    lines[k] = code.rstrip() + (" " + comment if comment else "")
    return "\n".join(lines)


def _edit_output(rng: random.Random, text: str) -> str | None:
    """An OUTPUT statement's item dropped, repeated or moved."""
    lines = text.split("\n")
    spots = [k for k, line in enumerate(lines) if re.match(r"(?i)\s*OUTPUT\s", line)]
    if not spots:
        return None
    k = rng.choice(spots)
    code, _, comment = lines[k].partition("%")
    keyword, rest = re.match(r"(?i)(\s*OUTPUT\s+)(.*)", code).groups()
    items = [item.strip() for item in rest.split(",") if item.strip()]
    if len(items) >= 3 and rng.random() < 0.5:
        del items[rng.randrange(1, len(items))]
    elif len(items) >= 3 and rng.random() < 0.5:
        i, j = rng.sample(range(1, len(items)), 2)
        items[i], items[j] = items[j], items[i]
    else:
        items.append(rng.choice(items[1:] or items))
    lines[k] = keyword + ", ".join(items) + (" %" + comment if comment else "")
    return "\n".join(lines)


def edit_model(rng: random.Random, text: str) -> str:
    """A statement of the model changed: an INPUT value, a force's constant, an OUTPUT
    item (the first of those the model has, from one drawn at random)."""
    edits = [_edit_input, _edit_force, _edit_output]
    rng.shuffle(edits)
    for edit in edits:
        edited = edit(rng, text)
        if edited is not None and edited != text:
            return edited
    return text + "% edited\n"


def edit_decimal(rng: random.Random, text: str) -> str:
    """One number written with a point changed (a macro's, a RUN file's)."""
    spots = list(_DECIMAL.finditer(text))
    if not spots:
        return text + "% edited\n"
    m = rng.choice(spots)
    value = rng.choice([v for v in ("0.05", "0.4", "1.3", "2.0", "0.0") if v != m.group()])
    return text[:m.start()] + value + text[m.end():]


# ---------------------------------------------------------------------------------
# A case

def stale_case(seed: int, index: int) -> dict:
    """The fields of case `index` of seed `seed` (a fuzz.Case): the model and its files
    as the first command finds them, the first command and the one run after the change
    (`commands`), and the change (`change`)."""
    rng = random.Random(f"autolev-fuzz:stale:{seed}:{index}")
    kind = rng.choices(KINDS, weights=KIND_WEIGHTS)[0]
    moment = rng.choice(MOMENTS)
    allowed = COMMANDS_OF.get(kind, tuple(COMMAND_WEIGHTS))
    command = rng.choices(allowed, weights=[COMMAND_WEIGHTS[c] for c in allowed])[0]
    source = pick_source(rng, kind, command)
    model = source.model
    edits: dict = {}
    in_file, in_edit = False, None
    first: list[str] = []
    after: list[str] = []
    knobs = [{}, {}]
    if command in ("run", "linearize"):
        if rng.random() < 0.08:
            first += ["--backend", "python"]
        if command == "run" and (source.tfinal or rng.random() < 0.3):
            first += ["--tfinal", source.tfinal or rng.choice(("0.5", "1"))]
        first += source.arguments
        if rng.random() < 0.1:
            knobs[0][rng.choice(KNOBS)] = "1"
        knobs[1] = dict(knobs[0])
        in_file = kind == "in" or (kind != "added" and rng.random() < 0.12)
        if in_file:
            first += ["--in", "vals.in"]
        names = [n for n in source.values if n.upper() not in
                 {s.upper() for s in source.specified}]
        if source.specified and kind != "specified":
            first += ["--specified", f"{source.specified[0]}={EXPRESSIONS[0]}"]
        if command == "linearize" and names and rng.random() < 0.2:
            # long enough that its Jacobians are compiled to C: the sweep's own tier
            first += ["--sweep", f"{rng.choice(names)}=0.1:0.9:{SWEEP_POINTS}"]
        after = list(first)
        if kind == "set" and names:
            name = rng.choice(names)
            old, new = rng.sample(VALUES, 2)
            shown = rng.random()
            first += [] if shown < 0.2 else ["--set", f"{name}={old}"]
            after += [] if 0.2 <= shown < 0.4 else ["--set", f"{name}={new}"]
        elif kind == "specified" and source.specified:
            name = source.specified[0]
            old, new = rng.sample(EXPRESSIONS, 2)
            first += ["--specified", f"{name}={old}"]
            after += ["--specified", f"{name}={new}"]
        elif kind == "in":
            in_edit = [rng.randrange(1000), rng.choice(VALUES)]
    if kind == "env":
        knob = rng.choice(KNOBS)
        turned = dict(knobs[0])
        if turned.pop(knob, None) is None:
            turned[knob] = "1"
        knobs = [knobs[0], turned] if rng.random() < 0.5 else [turned, knobs[0]]
    if command in ("run", "outcome"):
        first, after = ["run", "--out", "{out}", *first], ["run", "--out", "{out}", *after]
    else:
        first, after = [command, *first], [command, *after]
    first.append(model)
    after.append(model)
    if kind == "model":
        edits[model] = edit_model(rng, source.files[model])
    elif kind == "macro":
        name = rng.choice(source.macros)
        edits[name] = edit_decimal(rng, source.files[name])
    elif kind == "run-file":
        name = rng.choice(source.runs)
        edits[name] = edit_decimal(rng, source.files[name])
    elif kind == "added":
        edits.update(source.added)
    others = {name: text for name, text in source.files.items() if name != model}
    change = {"kind": kind, "moment": moment, "command": command, "source": source.label,
              "edits": edits, "in_file": in_file, "in_edit": in_edit, "knobs": knobs,
              "delay": round(rng.uniform(0.05, 1.5), 2),
              "write": "replace" if rng.random() < 0.7 else "rewrite",
              "warm": rng.random() < 0.1,
              "link_sleep": round(rng.uniform(0.5, 1.2), 1) if moment in ("during", "locked")
              else 0.0}
    return {"index": index, "generator": f"{kind}@{moment}", "filename": model,
            "text": source.files[model], "mode": "stale", "files": others,
            "commands": [first, after], "change": change}


def described(case) -> list[str]:
    """The change of a case as it can be read: what, when, how; each file's diff."""
    change = case.change
    lines = [f"change: {change['kind']} {change['moment']} ({change['command']} of "
             f"{change['source']}; delay {change['delay']} s, link sleep "
             f"{change['link_sleep']} s, files written by {change['write']}"
             + ("; a warm-up run first" if change["warm"] else "") + ")"]
    if change["knobs"][0] or change["knobs"][1]:
        lines.append(f"environment: {change['knobs'][0]} -> {change['knobs'][1]}")
    if change["in_edit"]:
        lines.append(f"vals.in (from `autolev code`): value line {change['in_edit'][0]} "
                     f"(mod their number) becomes {change['in_edit'][1]}")
    files = {case.filename: case.text, **case.files}
    for name, text in change["edits"].items():
        before = files.get(name, "").splitlines()
        lines += list(difflib.unified_diff(before, text.splitlines(),
                                           f"{name} (before)" if name in files else "(none)",
                                           f"{name} (after)", n=1, lineterm=""))[:30]
    return lines


# ---------------------------------------------------------------------------------
# Running the commands of a case

@dataclass
class Ran:
    """A command's end: its exit status (None: killed over its time limit), what it
    printed, when it started and ended (seconds into the case), its output folder."""

    label: str
    argv: list
    knobs: dict
    status: int | None
    stdout: str
    stderr: str
    began: float
    ended: float
    out: Path | None


def _lift_memory_limit() -> None:
    """The worker's memory limit is on the soft limit: the commands have the hard one."""
    hard = resource.getrlimit(resource.RLIMIT_AS)[1]
    resource.setrlimit(resource.RLIMIT_AS, (hard, hard))


class Running:
    """A command started, its output going to files."""

    def __init__(self, session: "Session", label: str, argv: list, knobs: dict):
        self.session, self.label, self.argv, self.knobs = session, label, argv, knobs
        logs = session.work / "logs"
        logs.mkdir(parents=True, exist_ok=True)
        self.out = session.work / label if "{out}" in argv else None
        args = [str(self.out) if a == "{out}" else a for a in argv]
        self.streams = (logs / f"{label}.stdout", logs / f"{label}.stderr")
        self.began = session.now()
        with open(self.streams[0], "wb") as out, open(self.streams[1], "wb") as err:
            # a session of its own: a hang's kill takes what it started
            self.proc = subprocess.Popen(
                [sys.executable, "-m", "autolev", *args], cwd=session.model_dir,
                env=session.environment(knobs), stdin=subprocess.DEVNULL, stdout=out,
                stderr=err, start_new_session=True, preexec_fn=_lift_memory_limit)

    def wait(self, seconds: float) -> bool:
        """Whether it ended within `seconds`."""
        try:
            self.proc.wait(timeout=seconds)
        except subprocess.TimeoutExpired:
            return False
        return True

    def finish(self) -> Ran:
        left = min(COMMAND_SECONDS - (self.session.now() - self.began), self.session.left())
        try:
            status = self.proc.wait(timeout=max(left, 0.01))
        except subprocess.TimeoutExpired:
            os.killpg(self.proc.pid, signal.SIGKILL)
            self.proc.wait()
            status = None
        texts = [p.read_bytes().decode("utf-8", "replace") for p in self.streams]
        return Ran(self.label, self.argv, self.knobs, status, texts[0], texts[1],
                   self.began, self.session.now(), self.out)


class Session:
    """The commands on one copy of a case's model: its folder, its cache and home, the
    tag every process it starts carries; `end` leaves none of them running."""

    def __init__(self, work: Path, model_dir: Path, compiler: str | None,
                 link_sleep: float = 0.0, foreground: bool = False):
        self.work, self.model_dir = work, model_dir
        self.cache = work / "cache"
        self.compiler, self.link_sleep, self.foreground = compiler, link_sleep, foreground
        self.tag = f"{os.getpid()}-{time.time_ns()}"
        self.start_time = time.monotonic()

    def now(self) -> float:
        return time.monotonic() - self.start_time

    def left(self) -> float:
        """Seconds until the session's commands must have ended."""
        return CASE_SECONDS - self.now()

    def environment(self, knobs: dict) -> dict:
        env = {k: v for k, v in os.environ.items() if k not in CLEARED}
        home = self.work / "home"
        env.update(AUTOLEV_CACHE=str(self.cache), XDG_CACHE_HOME=str(home / "cache"),
                   XDG_CONFIG_HOME=str(home / "config"), XDG_STATE_HOME=str(home / "state"),
                   AUTOLEV_TRACEBACK="1", **{TAG_VARIABLE: self.tag,
                                             SLEEP_VARIABLE: f"{self.link_sleep:g}"})
        if self.compiler:
            env["CC"] = self.compiler
        if self.foreground:
            env["AUTOLEV_FOREGROUND"] = "1"
        env.update(knobs)
        return env

    def start(self, label: str, argv: list, knobs: dict) -> Running:
        return Running(self, label, argv, knobs)

    def run(self, label: str, argv: list, knobs: dict) -> Ran:
        return self.start(label, argv, knobs).finish()

    def locked(self) -> bool:
        """Whether a background child holds a lock in the cache now."""
        return any(_held(lock) for lock in self.cache.glob("finishing_*.lock"))

    def wait_for_children(self, seconds: float = CHILD_SECONDS) -> bool:
        """Until no background child holds its lock; False when one still does after
        `seconds`."""
        deadline = time.monotonic() + min(seconds, max(self.left(), 1.0))
        while self.locked():
            if time.monotonic() > deadline:
                return False
            time.sleep(0.05)
        return True

    def end(self) -> str | None:
        """Wait for the background children, then kill whatever of the case is left;
        what was over its time limit, or None."""
        late = None if self.wait_for_children() else \
            f"a background child still held its lock at {self.now():.0f} s"
        deadline = time.monotonic() + 10
        while tagged(self.tag) and time.monotonic() < deadline:
            time.sleep(0.05)        # a child that released its lock is exiting
        for pid in tagged(self.tag):
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        return late


def _held(lock: Path) -> bool:
    """Whether a process holds `lock` (flock), as a later command would wait for it."""
    try:
        fd = os.open(lock, os.O_RDONLY | os.O_NOFOLLOW)
    except OSError:
        return False
    try:
        fcntl.flock(fd, fcntl.LOCK_SH | fcntl.LOCK_NB)
    except BlockingIOError:
        return True
    finally:
        os.close(fd)
    return False


def tagged(tag: str) -> list[int]:
    """The processes (not zombies) whose environment carries the tag."""
    mark = f"{TAG_VARIABLE}={tag}\0".encode()
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit() or int(entry) == os.getpid():
            continue
        try:
            environ = Path(f"/proc/{entry}/environ").read_bytes()
        except OSError:
            continue
        if environ.startswith(mark) or b"\0" + mark in environ:
            found.append(int(entry))
    return found


def slow_compiler(shared: Path) -> str | None:
    """A C compiler that sleeps $AUTOLEV_FUZZ_LINK_SLEEP seconds before it links the
    loop's shared object (the background child is then compiling for that long); one for
    every case of a run (CC is part of every request)."""
    cc = shutil.which("gcc") or shutil.which("cc")
    if cc is None:
        return None
    path = shared / "stale-cc"
    if not path.exists():
        shared.mkdir(parents=True, exist_ok=True)
        partial = shared / f".stale-cc.{os.getpid()}"
        partial.write_text(f"#!/bin/sh\ncase \"$*\" in *shared.o*) sleep "
                           f"\"${{{SLEEP_VARIABLE}:-0}}\";; esac\nexec {shlex.quote(cc)} \"$@\"\n")
        partial.chmod(0o755)
        os.replace(partial, path)
    return str(path)


# ---------------------------------------------------------------------------------
# Answers

# SlowStep's notes (a step announced after two seconds): the load's, not the answer's
_SLOW_NOTE = re.compile(r"(?m)^  .*(?: \.\.\.|: \d+(?:\.\d+)? s)\n")


def answer_of(command: str, ran: Ran, places: dict) -> dict:
    """What is compared of a command's end: its exit status and, by command, its output
    files, its eigenvalue text, or what it printed (`places`: paths shown as names)."""
    def plain(text: str) -> str:
        for path, name in places.items():
            text = text.replace(path, name)
        return _SLOW_NOTE.sub("", text)
    parts: dict = {}
    if command == "run":
        if ran.out is not None and ran.out.is_dir():
            for path in sorted(ran.out.rglob("*")):
                if path.is_file():
                    parts[f"file {path.relative_to(ran.out)}"] = \
                        path.read_bytes().decode("latin-1")
        if ran.status:
            parts["errors"] = "\n".join(line for line in plain(ran.stderr).splitlines()
                                        if ": error:" in line)
    elif command == "linearize":
        parts["stdout"] = plain(ran.stdout)
    else:
        parts["stdout"], parts["stderr"] = plain(ran.stdout), plain(ran.stderr)
    return {"status": ran.status, "parts": parts}


def crashed(ran: Ran) -> str | None:
    """How a command crashed (exit status 70, a signal, a traceback), or None."""
    if ran.status is None:
        return None
    if ran.status == 70 or ran.status < 0 or \
            "Traceback (most recent call last)" in ran.stdout + ran.stderr:
        return f"exit status {ran.status}:\n{ran.stderr[-3000:]}"
    return None


def difference(got: dict, wanted: dict) -> str:
    """How one answer differs from another: the status, each part's first line that
    differs."""
    said = []
    if got["status"] != wanted["status"]:
        said.append(f"exit status {got['status']}, not {wanted['status']}")
    for name in sorted(got["parts"].keys() | wanted["parts"].keys()):
        a, b = got["parts"].get(name), wanted["parts"].get(name)
        if a == b:
            continue
        if a is None or b is None:
            said.append(f"{name}: {'missing' if a is None else 'not in the fresh answer'}")
            continue
        la, lb = a.splitlines(), b.splitlines()
        k = next((k for k, (x, y) in enumerate(zip(la, lb)) if x != y), min(len(la), len(lb)))
        said.append(f"{name} differs at line {k + 1}: {la[k:k + 1]} instead of {lb[k:k + 1]}")
    return "; ".join(said) or "the same"


def _digest(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def snapshot(folder: Path) -> dict:
    """Every file under `folder`: relative name -> bytes."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*"))
            if p.is_file()}


def _write(path: Path, data: bytes | str, how: str = "replace") -> None:
    """A file written whole by a rename (an editor's save), or rewritten in place
    (truncated, then written: a reader may see it empty)."""
    raw = data.encode("utf-8", "surrogateescape") if isinstance(data, str) else data
    path.parent.mkdir(parents=True, exist_ok=True)
    if how == "rewrite":
        with open(path, "wb") as f:
            f.write(raw)
        return
    partial = path.parent / f".{path.name}.fuzz-part"
    partial.write_bytes(raw)
    os.replace(partial, path)


def kept(shared: Path, key: str, make) -> dict:
    """What `make()` gives, kept under `key` for the workers of this run."""
    store = shared / "stale-fresh"
    path = store / f"{_digest(key.encode())[:40]}.json"
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        pass
    made = make()
    store.mkdir(parents=True, exist_ok=True)
    partial = store / f".{path.name}.{os.getpid()}"
    partial.write_text(json.dumps(made))
    os.replace(partial, path)
    return made


def fresh_answer(shared: Path, scratch: Path, files: dict, command: str, argv: list,
                 knobs: dict) -> dict:
    """The answer of `argv` on `files` in an empty cache, in the foreground (the same
    files, command and knobs: the same answer, kept)."""
    key = json.dumps(["fresh", command, argv, sorted(knobs.items()),
                      sorted((name, _digest(raw)) for name, raw in files.items())])

    def make() -> dict:
        work = scratch / "fresh"
        shutil.rmtree(work, ignore_errors=True)
        model_dir = work / "model"
        model_dir.mkdir(parents=True)
        for name, raw in files.items():
            _write(model_dir / name, raw)
        session = Session(work, model_dir, slow_compiler(shared), foreground=True)
        ran = session.run("fresh", argv, knobs)
        late = session.end()
        answer = answer_of(command, ran, {str(model_dir): "{case}", str(work): "{work}"})
        answer["crash"] = crashed(ran)
        answer["hang"] = late if ran.status is not None else "the fresh run was over time"
        return answer
    return kept(shared, key, make)


def in_template(shared: Path, scratch: Path, files: dict, model: str) -> str | None:
    """The .in file `autolev code` writes for the model (None when it writes none)."""
    key = json.dumps(["in", model, sorted((name, _digest(raw)) for name, raw in files.items())])

    def make() -> dict:
        work = scratch / "template"
        shutil.rmtree(work, ignore_errors=True)
        model_dir = work / "model"
        model_dir.mkdir(parents=True)
        for name, raw in files.items():
            _write(model_dir / name, raw)
        session = Session(work, model_dir, None, foreground=True)
        session.run("code", ["code", "--out", "{out}", "-q", model], {})
        session.end()
        written = sorted((work / "code").glob("*.in")) if (work / "code").is_dir() else []
        return {"text": written[0].read_text() if written else None}
    return kept(shared, key, make)["text"]


_IN_VALUE = re.compile(r"(?m)^((?:Constant|Initial Value)\b[^|\n]*\|)([^\n]*)$")


def edited_in(text: str, line: int, value: str) -> str:
    """The .in text with its value line `line` (mod their number) set to `value`."""
    spots = list(_IN_VALUE.finditer(text))
    if not spots:
        return text
    m = spots[line % len(spots)]
    return text[:m.start(2)] + " " + value + text[m.end(2):]


def prepared(case, model_dir: Path, shared: Path, scratch: Path) -> tuple[dict, list, list]:
    """The case's files written into `model_dir` (with vals.in, made by `autolev code`,
    when the case reads one); the files its change writes, and its two commands."""
    change = case.change
    for name, text in {case.filename: case.text, **case.files}.items():
        _write(model_dir / name, text)
    edits = dict(change["edits"])
    first_argv, after_argv = (list(argv) for argv in case.commands)
    if change["in_file"]:
        template = in_template(shared, scratch, snapshot(model_dir), case.filename)
        if template is None:        # the model writes none: the case runs without
            first_argv, after_argv = (_without_in(a) for a in (first_argv, after_argv))
        else:
            _write(model_dir / "vals.in", template)
            if change["in_edit"]:
                edits["vals.in"] = edited_in(template, *change["in_edit"])
    return edits, first_argv, after_argv


def _without_in(argv: list) -> list:
    k = argv.index("--in")
    return argv[:k] + argv[k + 2:]


# ---------------------------------------------------------------------------------
# A case, checked

def check_stale_case(case, folder: Path) -> dict:
    """Run a stale case in `folder` (its own model folder, cache and home; the fresh
    answers kept in the folder above, which the run's workers share) and judge it."""
    t0 = time.perf_counter()
    shared = folder.parent
    work = folder / "stale"
    shutil.rmtree(work, ignore_errors=True)
    model_dir = work / "model"
    model_dir.mkdir(parents=True)
    edits, first_argv, after_argv = prepared(case, model_dir, shared, folder)
    session = Session(work, model_dir, slow_compiler(shared), case.change["link_sleep"])
    play = Play(case, session, edits, shared, folder)
    try:
        found, stage = play.judged(first_argv, after_argv)
    finally:
        late = session.end()
    if late:
        found.append(("hang", "children", late))
    found.sort(key=lambda f: SEVERITY.index(f[0]))
    outcome, where, detail = found[0]
    if outcome == "ok":
        where = stage
    else:       # every problem found, the worst first; what happened when; the worst again
        detail = "\n".join(f"{o}: {d}" for o, _, d in found if o != "ok") + "\n" \
            + play.timeline() + f"\n{outcome}: {detail.splitlines()[0]}"
    return {"outcome": outcome, "stage": where, "detail": detail,
            "seconds": time.perf_counter() - t0,
            "rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}


class Play:
    """A case's commands, its change at its moment, and the judgement of the answers."""

    def __init__(self, case, session: Session, edits: dict, shared: Path, scratch: Path):
        self.case, self.change, self.session = case, case.change, session
        self.edits, self.shared, self.scratch = edits, shared, scratch
        self.runs: list[Ran] = []
        self.notes: list[tuple[float, str]] = []

    def note(self, text: str) -> None:
        self.notes.append((self.session.now(), text))

    def apply(self) -> None:
        """The change: its files written (an argument or a knob changes in the command)."""
        for name, text in self.edits.items():
            _write(self.session.model_dir / name, text, self.change["write"])
        self.note(f"the change ({self.change['kind']}"
                  + (f": {', '.join(self.edits)} written by {self.change['write']}"
                     if self.edits else "")
                  + ("; a background child holds its lock" if self.session.locked() else "")
                  + ")")

    def play(self, first_argv: list, after_argv: list) -> None:
        """The commands and the change at its moment; self.runs, the last three: the
        first command and the two after the change."""
        session, change = self.session, self.change
        moment = change["moment"]
        knobs_first, knobs_after = change["knobs"]
        if change["warm"]:
            self.runs.append(session.run("out0", first_argv, knobs_first))
            session.wait_for_children()
        if moment == "before":
            self.apply()
            first_argv, knobs_first = after_argv, knobs_after      # the control
        first = session.start("out1", first_argv, knobs_first)
        second = None
        if moment == "during":
            if first.wait(change["delay"]):
                self.note(f"the first command had returned within the delay "
                          f"({change['delay']} s)")
            if change["kind"] in ARGUMENT_KINDS:
                self.note("the second command starts, the first maybe running")
                second = session.start("out2", after_argv, knobs_after)
            else:
                self.apply()
        self.runs.append(first.finish())
        if moment == "locked":
            self.apply()
        elif moment == "after":
            session.wait_for_children()
            self.apply()
        self.runs.append(second.finish() if second is not None
                         else session.run("out2", after_argv, knobs_after))
        self.runs.append(session.run("out3", after_argv, knobs_after))
        session.wait_for_children()

    def judged(self, first_argv: list, after_argv: list) -> tuple[list, str]:
        """Play the case; what was found (outcome, stage, detail) and the stage of an ok
        case: its command, and whether the change moved the answer."""
        session, change = self.session, self.change
        command, moment = change["command"], change["moment"]
        initial = snapshot(session.model_dir)
        self.play(first_argv, after_argv)
        final = snapshot(session.model_dir)
        knobs_first, knobs_after = change["knobs"]
        fresh = fresh_answer(self.shared, self.scratch, final, command, after_argv,
                             knobs_after)
        found = [("ok", "", None)]
        for ran in self.runs:
            problem = crashed(ran)
            if problem:
                found.append(("crash", ran.label, f"{_said(ran)} crashed: {problem}"))
            elif ran.status is None:
                found.append(("hang", ran.label, f"{_said(ran)} over {COMMAND_SECONDS:g} s"))
        if fresh["crash"] or fresh["hang"]:
            found.append(("crash" if fresh["crash"] else "hang", "fresh",
                          f"the fresh run ($ autolev {' '.join(after_argv)}): "
                          f"{fresh['crash'] or fresh['hang']}"))
        places = {str(session.model_dir): "{case}", str(session.work): "{work}"}
        answers = {ran.label: answer_of(command, ran, places) for ran in self.runs}
        first = answers[self.runs[-3].label]
        old = None
        for ran in self.runs[-3:] if moment == "before" else self.runs[-2:]:
            got = answers[ran.label]
            if ran.status is None or crashed(ran) or got == _compared(fresh):
                continue
            if old is None:
                old = _compared(fresh_answer(self.shared, self.scratch, initial, command,
                                             first_argv, knobs_first))
            if moment != "before" and got == old:
                outcome, how = "stale", "the answer of the old inputs"
            elif got["status"] != fresh["status"]:
                outcome, how = "error", "an exit status other than the fresh run's"
            else:
                outcome, how = "stale", "another answer than the fresh run's"
            found.append((outcome, ran.label,
                          f"{_said(ran)} gave {how}: {difference(got, fresh)}"
                          + ("; the first command's answer too" if got == first and
                             ran is not self.runs[-3] else "")
                          + f"\n  against the old inputs' fresh answer: {difference(got, old)}"))
        stage = command
        if moment in ("locked", "after"):
            stage += ":moved" if first != _compared(fresh) else ":still"
        return found, stage

    def timeline(self) -> str:
        """The case's events in order: each command's start and end, the change, notes."""
        events = [(r.began, f"{r.label} started: $ {_shown(r.knobs, r.argv)}")
                   for r in self.runs]
        events += [(r.ended, f"{r.label} ended, exit status {r.status}") for r in self.runs]
        events += self.notes
        return "timeline:\n" + "\n".join(f"  {at:6.2f} s  {text}"
                                           for at, text in sorted(events))


def _compared(answer: dict) -> dict:
    return {"status": answer["status"], "parts": answer["parts"]}


def _shown(knobs: dict, argv: list) -> str:
    return "".join(f"{k}={v} " for k, v in knobs.items()) + "autolev " + " ".join(argv)


def _said(ran: Ran) -> str:
    return f"{ran.label} ($ {_shown(ran.knobs, ran.argv)})"


# ---------------------------------------------------------------------------------
# Replay: a case's files and the commands that play it by hand

def write_case(case, into: Path) -> list[str]:
    """The case's files written into `into` (model/, the files the change writes in
    change/, the slow compiler) and the shell commands that play it (the moment as near
    as a shell gets) and compare the second answer with a fresh one."""
    change = case.change
    model_dir, changed = into / "model", into / "change"
    for old in (model_dir, changed):
        shutil.rmtree(old, ignore_errors=True)
    model_dir.mkdir(parents=True)
    edits, first_argv, after_argv = prepared(case, model_dir, into, into)
    for name, text in edits.items():
        _write(changed / name, text)
    cc = slow_compiler(into)
    autolev = f"{shlex.quote(sys.executable)} -m autolev"
    home = into / "home"
    lines = [f"cd {shlex.quote(str(model_dir))}",
             f"export AUTOLEV_CACHE={into / 'cache'} XDG_CACHE_HOME={home / 'cache'} "
             f"XDG_CONFIG_HOME={home / 'config'} XDG_STATE_HOME={home / 'state'} "
             + (f"CC={cc} " if cc else "") + f"{SLEEP_VARIABLE}={change['link_sleep']:g}"]
    wait = (f"for lock in {into / 'cache'}/finishing_*.lock; do [ -e \"$lock\" ] && "
            "flock -s \"$lock\" true; done   # the background child finished")
    apply = [f"cp {shlex.quote(str(changed / name))} {shlex.quote(name)}" for name in edits]

    def command(argv: list, knobs: dict, out: str, tail: str = "") -> str:
        env = "".join(f"{k}={v} " for k, v in knobs.items())
        args = " ".join(shlex.quote(str(into / out)) if a == "{out}" else shlex.quote(a)
                        for a in argv)
        return f"{env}{autolev} {args}{tail}"
    knobs_first, knobs_after = change["knobs"]
    if change["warm"]:
        lines += [command(first_argv, knobs_first, "out0"), wait]
    if change["moment"] == "before":
        lines += apply
        first_argv, knobs_first = after_argv, knobs_after
    if change["moment"] == "during":
        lines.append(command(first_argv, knobs_first, "out1", " &"))
        lines.append(f"sleep {change['delay']}")
        lines += [command(after_argv, knobs_after, "out2", " &")] \
            if change["kind"] in ARGUMENT_KINDS else apply
        lines.append("wait")
    else:
        lines.append(command(first_argv, knobs_first, "out1"))
    if change["moment"] == "locked":
        lines += apply
    elif change["moment"] == "after":
        lines += [wait] + apply
    if not (change["moment"] == "during" and change["kind"] in ARGUMENT_KINDS):
        lines.append(command(after_argv, knobs_after, "out2"))
    lines.append(command(after_argv, knobs_after, "out3"))
    knobs_fresh = {**knobs_after, "AUTOLEV_CACHE": str(into / "fresh-cache"),
                   "AUTOLEV_FOREGROUND": "1", SLEEP_VARIABLE: "0"}
    lines.append(command(after_argv, knobs_fresh, "fresh"))
    if change["command"] == "run":
        lines.append(f"diff -r {into / 'out2'} {into / 'fresh'}; "
                     f"diff -r {into / 'out3'} {into / 'fresh'}")
    return lines
