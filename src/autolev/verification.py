"""`autolev verify`: replay Autolev's recorded responses against our translation.

Autolev's saved sessions (`.all`, written by SAVE) hold every input line numbered `(n)`
and every response `-> (n) NAME = expression`; some `.al` files carry the responses as
`% -> NAME = expression` comments.  For each response we evaluate Autolev's expression
and our value of NAME at that point of the model, numerically, at several pseudo-random
values of every constant, variable and derivative (the same for both), and compare to
the digits Autolev displayed (about 7).

How our value is taken: a capture statement `VERIFYn = NAME` (or `VERIFYn> = NAME>`) is
inserted into the model's source right after the input that printed the response, so
the value is the one the model had then.  Autolev's expression is read by a small
evaluator of its printed syntax (numbers, names with primes, unit vectors `A2>`, dyadic
products, functions, matrices): names are the model's own symbols, valued as in our
evaluation (through our definitions), and Z variables through the Z responses recorded
before them.  Vectors and dyadics are compared by their measure numbers in the
Newtonian frame, with the direction cosines of our model.  Nothing from the file is
executed as code.
"""
from __future__ import annotations

import cmath
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from sympy import Symbol

from .errors import (AutolevInternalError, AutolevRuntimeError, AutolevSyntaxError,
                     AutolevTranslationError, Location, printable)
from .loader import load_translation
from .pipeline import translation
from .runtime.calculus import NumericPoint
from .runtime.symbols import TIME, Z
from .runtime.vector import Dyadic, Vector
from .source import decode

_INPUT = re.compile(r"^\s*\((\d+)\)\s?(.*)$")
_RESPONSE = re.compile(r"^->\s*\((\d+)\)\s*(.*)$")
_COMMENT_RESPONSE = re.compile(r"^\s*%\s*->\s*(?:\((\d+)\)\s*)?(.*)$")


@dataclass
class Response:
    number: int           # Autolev's number of the response (or its order in a .al)
    after: int            # the source line (1-based, of the replayed model) it follows
    lhs: str              # NAME, NAME', NAME[i], NAME>, NAME>>, A_B
    expr: str
    line: int             # where the response is in the file


@dataclass
class Session:
    source: str           # the model's statements, one per line as Autolev read them
    responses: list
    path: str


def read_session(text: str, path: str = "<session>") -> Session:
    """Inputs and responses of an `.all` transcript, or of a `.al` file with `% ->`
    response comments (continuation lines of a response are indented)."""
    lines = text.splitlines()
    is_all = any(_RESPONSE.match(ln) for ln in lines) or \
        sum(bool(_INPUT.match(ln)) for ln in lines[:20]) > 5
    src: list[str] = []
    responses: list[Response] = []
    current: Response | None = None
    for no, ln in enumerate(lines, 1):
        if is_all:
            m = _RESPONSE.match(ln)
            if m:
                current = Response(int(m.group(1)), len(src), "", m.group(2).strip(), no)
                responses.append(current)
                continue
            if current is not None and ln.startswith(" ") and not _INPUT.match(ln):
                current.expr += ln.strip()
                continue
            current = None
            m = _INPUT.match(ln)
            if m:
                src.append(m.group(2))
        else:
            m = _COMMENT_RESPONSE.match(ln)
            if m:
                current = Response(len(responses) + 1, len(src), "", m.group(2).strip(), no)
                responses.append(current)
                continue
            if current is not None and re.match(r"^\s*%\s{3,}\S", ln):
                current.expr += ln.strip().lstrip("%").strip()
                continue
            current = None
            src.append(ln)
    out = []
    for r in responses:
        if "=" not in r.expr:
            continue
        lhs, _, rhs = r.expr.partition("=")
        r.lhs, r.expr = lhs.strip(), rhs.strip()
        out.append(r)
    return Session("\n".join(src) + "\n", out, path)


# -- the evaluator of Autolev's printed expressions ----------------------------------------
_TOKEN = re.compile(r"\s*(?:(?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)"
                    r"|(?P<name>[A-Za-z_][A-Za-z0-9_]*'*(?:>>|>)?)"
                    r"|(?P<op>[-+*/^()\[\],;]))")
_FUNCS = {"SIN": cmath.sin, "COS": cmath.cos, "TAN": cmath.tan, "ASIN": cmath.asin,
          "ACOS": cmath.acos, "ATAN": cmath.atan, "SINH": cmath.sinh, "COSH": cmath.cosh,
          "TANH": cmath.tanh, "EXP": cmath.exp, "LOG": cmath.log, "SQRT": cmath.sqrt,
          "LOG10": cmath.log10, "ABS": abs,
          "SIGN": lambda x: complex(np.sign(x.real)),
          "SQR": lambda x: x * x}


class NotComparable(Exception):
    pass


class _Parser:
    """Recursive descent over the printed syntax; evaluates as it goes.  Values are
    complex scalars, 3-vectors or 3x3 dyadics (numpy, in the Newtonian frame), or
    matrices (numpy object arrays of scalars)."""

    def __init__(self, text: str, scalar, unit_vector):
        self.toks = []
        pos = 0
        text = text.strip()
        while pos < len(text):
            m = _TOKEN.match(text, pos)
            if not m or m.end() == pos:
                raise NotComparable(f"cannot read {text[pos:pos + 20]!r}")
            self.toks.append((m.lastgroup, m.group(m.lastgroup)))
            pos = m.end()
        self.i = 0
        self.scalar = scalar
        self.unit_vector = unit_vector

    def peek(self):
        return self.toks[self.i] if self.i < len(self.toks) else (None, None)

    def take(self, want=None):
        tok = self.peek()
        if tok[0] is None or (want is not None and tok[1] != want):
            raise NotComparable(f"expected {want or 'more'} in the response")
        self.i += 1
        return tok

    def parse(self):
        v = self.sum()
        if self.i != len(self.toks):
            raise NotComparable(f"unexpected {self.peek()[1]!r} in the response")
        return v

    def sum(self):
        v = self.product()
        while self.peek()[1] in ("+", "-"):
            op = self.take()[1]
            v, w = _operands(v, self.product())
            v = v + w if op == "+" else v - w
        return v

    def product(self):
        v = self.unary()
        while self.peek()[1] in ("*", "/"):
            op = self.take()[1]
            v, w = _operands(v, self.unary())
            if op == "*":
                v = _mul(v, w)
            else:
                v = v / w
        return v

    def unary(self):
        if self.peek()[1] == "-":
            self.take()
            return -_operands(self.unary())[0]
        if self.peek()[1] == "+":
            self.take()
            return self.unary()
        return self.power()

    def power(self):
        base = self.atom()
        if self.peek()[1] == "^":
            self.take()
            # right-associative, binds -x tighter
            base, exponent = _operands(base, self.unary())
            return base ** exponent
        return base

    def atom(self):
        kind, text = self.take()
        if kind == "num":
            return complex(float(text))
        if text == "(":
            v = self.sum()
            self.take(")")
            return v
        if text == "[":
            return self.matrix()
        if kind != "name":
            raise NotComparable(f"unexpected {text!r} in the response")
        if self.peek()[1] == "(" and text.upper() in _FUNCS | {"ATAN2": 0}:
            self.take("(")
            args = [self.sum()]
            while self.peek()[1] == ",":
                self.take()
                args.append(self.sum())
            self.take(")")
            return _apply(text.upper(), args)
        if text.endswith(">"):
            return self.unit_vector(text)
        if self.peek()[1] == "[":              # an indexed name
            raise NotComparable(f"indexed name {text}[...] in the response")
        return self.scalar(text)

    def matrix(self):
        rows, row = [], [self.sum()]
        while True:
            t = self.take()[1]
            if t == ",":
                row.append(self.sum())
            elif t == ";":
                rows.append(row)
                row = [self.sum()]
            elif t == "]":
                rows.append(row)
                break
            else:
                raise NotComparable("bad matrix in the response")
        if len({len(r) for r in rows}) != 1:
            raise NotComparable("ragged matrix in the response")
        if not all(isinstance(x, complex) for r in rows for x in r):
            raise NotComparable("a matrix of vectors or matrices in the response")
        return _Matrix(np.array(rows, dtype=complex))


class _Matrix:
    """A matrix the response writes out, `[a, b; c, d]`: a value, never an operand."""

    def __init__(self, a):
        self.a = a


def _operands(*values) -> tuple:
    """The values, which the response combines: none may be a written-out matrix."""
    if any(isinstance(v, _Matrix) for v in values):
        raise NotComparable("arithmetic on a matrix in the response")
    return values


def _apply(name: str, args: list) -> complex:
    """A function of the response (SIN, ATAN2, ...) at scalar arguments."""
    if not all(isinstance(a, complex) for a in args):
        raise NotComparable(f"{name} of a vector or matrix in the response")
    if name == "ATAN2":
        if len(args) != 2:
            raise NotComparable(f"ATAN2 takes two arguments, the response gives {len(args)}")
        return complex(math.atan2(args[0].real, args[1].real))
    if len(args) != 1:
        raise NotComparable(f"{name} takes one argument, the response gives {len(args)}")
    try:
        return complex(_FUNCS[name](args[0]))
    except ValueError as exc:     # cmath's domain error: LOG(0) at this point
        raise NotComparable(f"cannot evaluate: {name}: {exc}") from None


def _mul(v, w):
    if isinstance(v, np.ndarray) and isinstance(w, np.ndarray) and v.shape == w.shape == (3,):
        return np.outer(v, w)                    # two vectors: the dyadic product
    return v * w


# -- verification ------------------------------------------------------------------------------
@dataclass
class Outcome:
    response: Response
    status: str                  # match, mismatch, not comparable
    detail: str = ""
    ours: object = None
    theirs: object = None

    def as_dict(self) -> dict:
        return {"number": self.response.number, "line": self.response.line,
                "name": self.response.lhs, "status": self.status, "detail": self.detail,
                "ours": _plain(self.ours), "autolev": _plain(self.theirs)}


@dataclass
class Report:
    path: str
    outcomes: list = field(default_factory=list)
    error: str | None = None

    def count(self, status: str) -> int:
        return sum(o.status == status for o in self.outcomes)

    @property
    def ok(self) -> bool:
        return self.error is None and self.count("mismatch") == 0

    def summary(self) -> str:
        return (f"{self.path}: {self.count('match')} match, {self.count('mismatch')} "
                f"mismatch, {self.count('not comparable')} not comparable "
                f"({len(self.outcomes)} responses)")

    def as_dict(self) -> dict:
        return {"file": self.path, "error": self.error, "match": self.count("match"),
                "mismatch": self.count("mismatch"),
                "not_comparable": self.count("not comparable"),
                "responses": [o.as_dict() for o in self.outcomes]}


def _plain(v):
    if v is None:
        return None
    a = np.asarray(v, dtype=complex)
    if np.all(np.abs(a.imag) < 1e-12 * (1 + np.abs(a.real))):
        return a.real.tolist()
    return [[z.real, z.imag] for z in a.ravel()]


# the generated module's dictionary of the definitions (symbol -> right side) known at
# each capture (a dunder name: the translation gives no user name that form)
_KNOWN = "__verify_defs__"


def _capture_prefix(source: str) -> str:
    """A prefix for the capture statements' names that no name of the session starts
    with (a model's own VERIFY0 must not become the capture of a response)."""
    words = {w.upper() for w in re.findall(r"[A-Za-z_][A-Za-z0-9_]*", source)}
    prefix = "VERIFY"
    while any(w.startswith(prefix) for w in words):
        prefix += "X"
    return prefix


def _capture_statement(k: int, lhs: str, prefix: str) -> tuple[str, str] | None:
    """The Autolev statement that captures our value of lhs, and its kind."""
    name = lhs.strip()
    if name.endswith(">>"):
        return f"{prefix}{k}>> = {name}", "dyadic"
    if name.endswith(">"):
        return f"{prefix}{k}> = {name}", "vector"
    return f"{prefix}{k} = {name}", "value"


def verify(path, points: int = 3, tolerance: float = 2e-6) -> Report:
    """Replay the responses recorded in an `.all` session (or the `% ->` comments of a
    `.al` file) against our translation; a Report of each response's outcome."""
    p = Path(path)
    session = read_session(decode(p.read_bytes()), str(p))
    report = Report(str(p))
    if not session.responses:
        report.error = "no responses recorded (an .all transcript, or % -> comments)"
        return report
    # a left side that is not a name is never spliced into the replayed model
    refused = {k: f"its left side '{printable(r.lhs)}' is not a name (NAME, NAME', NAME[i], "
               "NAME>, NAME>>)" for k, r in enumerate(session.responses)
               if not _NAME_LHS.fullmatch(r.lhs.strip())}
    model, captured, skipped = _build(session, p, refused)
    if model is None:
        report.error = skipped
        return report
    names = _names_of(model)
    for k, r in enumerate(session.responses):
        if _is_z(r.lhs):
            report.outcomes.append(None)         # judged with the responses using it
            continue
        if k in skipped:
            # a name the engine made (NICHECK's WCHECK1'): compare with its definition
            sym = next((x for x in model.defs.rhs if not isinstance(x, Z)
                        and x.name.upper() == r.lhs.upper()), None)
            if sym is None:
                report.outcomes.append(Outcome(r, "not comparable", skipped[k]))
                continue
            o = _compare(model, names, r, sym, None, session, points, tolerance)
            o.detail += " (a name the engine defines, compared with its definition)"
            report.outcomes.append(o)
            continue
        value, known = captured[k]
        report.outcomes.append(_compare(model, names, r, value, known, session, points,
                                        tolerance))
    _judge_z_responses(session, report)
    return report


# what a response may name: NAME, NAME', NAME[i], NAME[i,j], NAME>, NAME>>
_NAME_LHS = re.compile(r"[A-Za-z_][A-Za-z0-9_]*('{1,3}|>{1,2}|\[\s*\d+(\s*,\s*\d+)?\s*\])?")


def _is_z(lhs: str) -> bool:
    return re.fullmatch(r"Z\d+", lhs.strip().upper()) is not None


def _judge_z_responses(session: Session, report: Report) -> None:
    """A Z response (`Z68 = 0.25*u2*Z56 - ...`) names a piece of a result Autolev went on
    to print: it is compared through the first later response that uses it (directly or
    through other Z's) and could be compared."""
    responses = session.responses
    uses = [{t.upper() for t in re.findall(r"\b[Zz]\d+\b", r.expr)} for r in responses]
    for k, r in enumerate(responses):
        if report.outcomes[k] is not None:
            continue
        name = r.lhs.strip().upper()
        reach = {name}
        judged = None
        for j in range(k + 1, len(responses)):
            if responses[j].lhs.strip().upper() == name:
                break                            # Z renumbered: later uses are another's
            if not (uses[j] & reach):
                continue
            if _is_z(responses[j].lhs):
                reach.add(responses[j].lhs.strip().upper())
                continue
            o = report.outcomes[j]
            if o is not None and o.status in ("match", "mismatch"):
                judged = (o, responses[j])
                break
        if judged is None:
            report.outcomes[k] = Outcome(r, "not comparable", "Autolev's intermediate "
                                         "variable, used by no later response that could "
                                         "be compared")
        else:
            o, user = judged
            report.outcomes[k] = Outcome(r, o.status, f"{o.detail}, as part of "
                                         f"({user.number}) {user.lhs}")


def _build(session: Session, p: Path, refused: dict | None = None):
    """Translate and run the model with the capture statements; drop the captures our
    translation cannot make (reported as not comparable, as are the `refused` ones
    {index: why}) and retry."""
    lines = session.source.splitlines()
    capture = _capture_prefix(session.source)
    skipped: dict[int, str] = dict(refused or {})
    for _attempt in range(6):
        text, where, kinds = [], {}, {}
        after: dict[int, list[int]] = {}
        for k, r in enumerate(session.responses):
            if k not in skipped and not _is_z(r.lhs):
                after.setdefault(r.after, []).append(k)
        for i, ln in enumerate(lines, 1):
            text.append(ln)
            for k in after.get(i, []):
                stmt, kind = _capture_statement(k, session.responses[k].lhs, capture)
                text.append(stmt)
                where[len(text)] = k
                kinds[k] = kind
        src = "\n".join(text) + "\n"
        try:
            tr = translation(src, str(p))
        except AutolevTranslationError as exc:
            bad = {where[d.location.line]: d.message for d in exc.diagnostics
                   if d.severity == "error" and d.location.line in where}
            if not bad:
                first = next(d for d in exc.diagnostics if d.severity == "error")
                return None, None, f"the model does not translate: {first.format()}"
            for k, msg in bad.items():
                skipped[k] = f"our translation has no such value there ({msg})"
            continue
        except AutolevSyntaxError as exc:
            return None, None, f"the model does not parse: {exc}"
        code = tr.code.splitlines()
        for n, text in enumerate(code):
            m = re.match(rf"^({capture}(\d+)\w*) = ", text)
            if m and int(m.group(2)) in kinds:
                # same line (the line map stays right): the definitions known then
                code[n] = text + (f"; {_KNOWN}[{int(m.group(2))}] = "
                                  "dict(model.defs.rhs)")
        code.insert(0, f"{_KNOWN} = {{}}")
        tr.code = "\n".join(code) + "\n"
        tr.line_map = {k + 1: v for k, v in tr.line_map.items()}
        try:
            model = load_translation(tr, str(p))
        except AutolevRuntimeError as exc:
            d = exc.diagnostics[0] if getattr(exc, "diagnostics", None) else None
            line = d.location.line if d is not None else None
            if line in where:
                skipped[where[line]] = f"our model cannot give it there ({d.message})"
                continue
            return None, None, f"the model does not run: {exc}"
        ns = model.loaded.namespace
        captured = {}
        for k in range(len(session.responses)):
            if k in skipped or _is_z(session.responses[k].lhs):
                continue
            name = tr.names.get(f"{capture}{k}" + {"vector": ">", "dyadic": ">>"}.get(
                kinds.get(k), ""), None)
            value = ns.get(name) if name else None
            if value is None:
                name = next((v for a, v in tr.names.items()
                             if a.upper().rstrip(">") == f"{capture}{k}"), None)
                value = ns.get(name) if name else None
            if value is None:
                skipped[k] = "our translation keeps no value for it"
            else:
                captured[k] = (value, ns[_KNOWN].get(k))
        return model, captured, skipped
    return None, None, "too many responses our translation cannot capture"


# (seed, span of the pseudo-random values) of the points tried, in order
_POINTS = ([(seed, (0.5, 1.5)) for seed in range(1, 4)]
           + [(seed, (0.1, 0.5)) for seed in range(1, 4)]
           + [(seed, (-0.5, 0.5)) for seed in range(1, 7)])


def _is_real(a) -> bool:
    a = np.asarray(a, dtype=complex)
    return bool(np.all(np.isfinite(a)) and
                np.all(np.abs(a.imag) <= 1e-12 * (1 + np.abs(a.real))))


def _assigned_value(model, text: str):
    """A name the session assigned without declaring it (u1 = dot(W_DiskA_N>, DiskA1>)):
    Autolev kept it as a name in later responses; its value is our value of it."""
    try:
        value = model.quantity(text)
    except KeyError as exc:
        if exc.args != (text,):
            raise                        # another key missing: a bug, not an unknown name
        raise NotComparable(f"{text} is not a name of our model") from None
    if not hasattr(value, "free_symbols") or hasattr(value, "shape"):
        raise NotComparable(f"{text} is not a scalar of our model")
    return value


def _names_of(model) -> dict:
    """Autolev's (upper-case) spelling -> the model's symbol: declared names, defined
    names and every name their definitions use (built once per verification)."""
    defs = model.defs
    by_name: dict = {}
    for sym in list(model.info) + list(defs.rhs):
        by_name.setdefault(sym.name.upper(), sym)
    for sym in list(defs.rhs):
        for s in defs.free(sym):
            by_name.setdefault(s.name.upper(), s)
    return by_name


class _Comparison:
    """One response against our value: what evaluating both needs at every point."""

    def __init__(self, model, by_name: dict, r: Response, ours, known, session: Session):
        self.model, self.defs, self.by_name = model, model.defs, by_name
        self.response, self.ours, self.known = r, ours, known
        self.frames = {n.upper(): f for n, f in model.frames_by_name.items()}
        self.newton = model.newtonian_frame or next(iter(model.frames_by_name.values()),
                                                    None)
        self.z_text = {o.lhs.upper(): o.expr for o in session.responses
                       if re.fullmatch(r"Z\d+", o.lhs.upper()) and o.number < r.number}

    def values_at(self, point: NumericPoint):
        """(ours, Autolev's) at one point, as complex arrays of the same shape."""
        self._normalize_quaternions(point)
        if self.known is not None:
            # names defined only after the response are free there (a later CONSTRAIN
            # defines the dependent speeds): they get values of their own.  Z's made
            # later name expressions, whatever is defined: they keep their values
            for s in self.defs.rhs:
                if s not in self.known and not isinstance(s, Z):
                    point.cache[s] = point.value(s, {})
        at = _AtPoint(self, point)
        theirs = np.asarray(at.theirs(), dtype=complex)
        mine = np.asarray(at.ours(), dtype=complex)
        if mine.shape != theirs.shape:
            if mine.size != theirs.size:
                raise NotComparable(f"shapes differ: ours {mine.shape}, Autolev's "
                                    f"{theirs.shape}")
            mine = mine.reshape(theirs.shape)
        return mine, theirs

    def _normalize_quaternions(self, point: NumericPoint) -> None:
        """Euler parameters of unit length, as Autolev's responses assume."""
        for quaternion in self.model.unit_quaternions:
            free = [e for e in quaternion if isinstance(e, Symbol) and e not in self.defs.rhs]
            if len(free) == 4:
                values = [float(point.value(e, {})) for e in free]
                norm = math.sqrt(sum(v * v for v in values))
                point.values.update({e: v / norm for e, v in zip(free, values)})


class _AtPoint:
    """The numbers of one comparison at one point: our value, Autolev's response, and
    the names, unit vectors and Z's the response uses."""

    def __init__(self, comparison: _Comparison, point: NumericPoint):
        self.c, self.point = comparison, point
        self.znum: dict = {}

    def num(self, e) -> complex:
        return complex(self.c.defs.numeric(e, self.point))

    def dcm(self, frame) -> np.ndarray:
        newton = self.c.newton
        if newton is None or not newton.orientation_known(frame):
            raise NotComparable(f"frame {frame.name} is not oriented in the Newtonian frame")
        m = newton.dcm(frame)
        return np.array([[self.num(m[i, j]) for j in range(3)] for i in range(3)])

    def scalar(self, text: str) -> complex:
        key = text.upper()
        if key == "PI":
            return complex(math.pi)
        if key in self.c.z_text:
            if key not in self.znum:
                self.znum[key] = self.parse(self.c.z_text[key])
            return self.znum[key]
        if key == "T":
            return self.num(TIME)
        sym = self.c.by_name.get(key)
        if sym is not None:
            return self.num(sym)
        return self.num(_assigned_value(self.c.model, text))

    def unit_vector(self, text: str) -> np.ndarray:
        body = text.rstrip(">")
        if text == "0>":
            return np.zeros(3, dtype=complex)
        frame = self.c.frames.get(body[:-1].upper()) if body[-1:] in "123" else None
        if frame is None:
            raise NotComparable(f"{text} is not a unit vector of our model")
        return self.dcm(frame)[:, int(body[-1]) - 1]

    def parse(self, text: str):
        return _Parser(text, self.scalar, self.unit_vector).parse()

    def theirs(self):
        """Autolev's response, evaluated."""
        text = self.c.response.expr.strip()
        if text in ("0>", "0>>"):
            return np.zeros(3 if text == "0>" else (3, 3), dtype=complex)
        value = self.parse(text)
        return value.a if isinstance(value, _Matrix) else value

    def ours(self):
        """Our value, in the Newtonian frame for a vector or dyadic."""
        ours = self.c.ours
        if isinstance(ours, Vector):
            out = np.zeros(3, dtype=complex)
            for f, comps in ours.terms.items():
                out = out + self.dcm(f) @ np.array([self.num(c) for c in comps])
            return out
        if isinstance(ours, Dyadic):
            out = np.zeros((3, 3), dtype=complex)
            for (fa, fb), m in ours.terms.items():
                mm = np.array([[self.num(m[i, j]) for j in range(3)] for i in range(3)])
                out = out + self.dcm(fa) @ mm @ self.dcm(fb).T
            return out
        if hasattr(ours, "shape") and not isinstance(ours, np.ndarray):
            return np.array([[self.num(ours[i, j]) for j in range(ours.shape[1])]
                             for i in range(ours.shape[0])])
        return self.num(ours)


def _compare(model, by_name, r: Response, ours, known, session, points, tol) -> Outcome:
    """Our value against Autolev's response at sample points: match within `tol`,
    mismatch, or not comparable."""
    comparison = _Comparison(model, by_name, r, ours, known, session)
    sampled = _sample(comparison, session.path, points)
    if isinstance(sampled, Outcome):
        return sampled
    a, b = sampled
    # values are O(1) at the sample points; a scale below 1e-6 is cancellation to zero
    scale = max(float(np.abs(a).max(initial=0)), float(np.abs(b).max(initial=0)), 1e-6)
    err = float(np.abs(a - b).max(initial=0)) / scale
    if err <= tol:
        return Outcome(r, "match", f"relative difference {err:.1e}", a[0], b[0])
    return Outcome(r, "mismatch", f"relative difference {err:.1e} at {len(a)} points",
                   a[0], b[0])


def _sample(comparison: _Comparison, path: str, points: int):
    """(ours, Autolev's) at up to `points` points, as arrays, or the Outcome of a
    response that cannot be evaluated.  The points are those where both values are
    real: equal expressions may take different branches of a root or logarithm where
    they are complex (Euler parameters far from unit length make 1 - Z10^2 negative)."""
    r = comparison.response
    ours_all, theirs_all, complex_pairs = [], [], []
    for seed, span in _POINTS:
        try:
            mine, theirs = comparison.values_at(NumericPoint(comparison.defs, seed=seed,
                                                             span=span))
        except NotComparable as exc:
            return Outcome(r, "not comparable", str(exc))
        except (ZeroDivisionError, OverflowError) as exc:
            return Outcome(r, "not comparable", f"cannot evaluate: {exc}")
        except RecursionError:
            return Outcome(r, "not comparable", "the response is nested too deeply to read")
        except MemoryError:
            raise                 # the machine's limit, neither the response's nor a bug
        except Exception as exc:  # any other is autolev's bug: re-raised as one
            raise AutolevInternalError(Location(path, r.line, 1), f"comparing response "
                                       f"({r.number}) {r.lhs}", exc) from exc
        if _is_real(mine) and _is_real(theirs):
            ours_all.append(mine)
            theirs_all.append(theirs)
            if len(ours_all) == points:
                break
        elif len(complex_pairs) < points:
            complex_pairs.append((mine, theirs))
    if not ours_all:
        if any(np.isnan(m).any() or np.isnan(t).any() for m, t in complex_pairs):
            # no value anywhere (a function refusing its argument, MIN a complex number)
            return Outcome(r, "not comparable", "cannot evaluate: no value at the points "
                           "tried")
        ours_all = [m for m, _ in complex_pairs]
        theirs_all = [t for _, t in complex_pairs]
    return np.array(ours_all), np.array(theirs_all)


__all__ = ["verify", "read_session", "Report", "Outcome", "Session", "Response"]
