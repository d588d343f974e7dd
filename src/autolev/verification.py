"""`autolev verify`: replay Autolev's recorded responses against our translation.

Autolev's saved sessions (`.all`, written by SAVE) hold every input line numbered `(n)`
and every response `-> (n) NAME = expression`; some `.al` files carry the responses as
`% -> NAME = expression` comments.  For each response we evaluate Autolev's expression
and our value of NAME at that point of the model, numerically, at several pseudo-random
values of every constant, variable and derivative (the same for both), and compare to
the digits Autolev displayed (about 7).

Each response is read by the grammar as the assignment `NAME = expression` and built
into the IR like a model's statement.  The translator writes, right after the input
that printed the response, two probes (`translate.Probe`): our value of NAME, with the
definitions known then, and the value of Autolev's expression, whose names are the
model's own (a Z response's value is named for the responses after it).  Both are
evaluated alike; vectors and dyadics are compared by their measure numbers in the
Newtonian frame, with the direction cosines of our model.  Nothing from the file is
executed but what the translator wrote from it.
"""
from __future__ import annotations

import bisect
import heapq
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import sympy as sm
from sympy import Symbol

if TYPE_CHECKING:
    import numpy as np

from . import ir
from .engine import reading
from .errors import (AutolevFileError, AutolevInternalError, AutolevRuntimeError,
                     AutolevSyntaxError, AutolevTranslationError, Location, Span, printable)
from .include import MAX_EXPANDED_BYTES, MAX_EXPANDED_STATEMENTS
from .irbuild import Builder
from .loader import load_translation
from .pipeline import translation
from .printed import read_plain
from .engine.progress import Progress
from .runtime.calculus import NumericPoint, is_real_number
from .runtime.steps import SlowStep
from .runtime.symbols import Z
from .runtime.vectors import Dyadic, Vector
from .source import SourceFile, decode
from .translate import PROBES, Probe, vocabulary

_INPUT = re.compile(r"^\s*\((\d+)\)\s?(.*)$")
_RESPONSE = re.compile(r"^->\s*\((\d+)\)\s*(.*)$")
_COMMENT_RESPONSE = re.compile(r"^\s*%\s*->\s*(?:\((\d+)\)\s*)?(.*)$")


@dataclass
class Response:
    number: int           # Autolev's number of the response (or its order in a .al)
    after: int            # the line of the session's source it follows
    lhs: str              # NAME, NAME', NAME[i], NAME>, NAME>>, A_B
    expr: str
    line: int             # where the response is in the file


@dataclass
class Session:
    source: str           # the model's statements, each at its line of the file
    responses: list
    path: str
    saved: bool = False   # laid out as Autolev's SAVE wrote it: inputs numbered (n)


def read_session(text: str, path: str = "<session>") -> Session:
    """Inputs and responses of an `.all` transcript, or of a `.al` file with `% ->`
    response comments (continuation lines of a response are indented).  The source
    keeps every input at its line of the file (the rest blank), so the model's
    diagnostics name the file's lines."""
    lines = text.splitlines()
    # a response, or every line but blank ones an input (a session of declarations)
    is_all = any(_RESPONSE.match(ln) for ln in lines) or \
        sum(bool(_INPUT.match(ln)) for ln in lines[:20]) > 5 or \
        (any(ln.strip() for ln in lines) and
         all(_INPUT.match(ln) for ln in lines if ln.strip()))
    src: list[str] = []
    responses: list[Response] = []
    current: Response | None = None
    last_input = 0
    for no, ln in enumerate(lines, 1):
        if is_all:
            m = _RESPONSE.match(ln)
            if m:
                current = Response(int(m.group(1)), last_input, "", m.group(2).strip(), no)
                responses.append(current)
                src.append("")
                continue
            src.append("")
            if current is not None and ln.startswith(" ") and not _INPUT.match(ln):
                current.expr += ln.strip()
                continue
            current = None
            m = _INPUT.match(ln)
            if m:
                src[-1] = m.group(2)
                last_input = no
        else:
            src.append(ln)           # a response is a comment of the model
            m = _COMMENT_RESPONSE.match(ln)
            if m:
                current = Response(len(responses) + 1, last_input, "", m.group(2).strip(),
                                   no)
                responses.append(current)
                continue
            if current is not None and re.match(r"^\s*%\s{3,}\S", ln):
                current.expr += ln.strip().lstrip("%").strip()
                continue
            current = None
            last_input = no
    out = []
    for r in responses:
        if "=" not in r.expr:
            continue
        lhs, _, rhs = r.expr.partition("=")
        r.lhs, r.expr = lhs.strip(), rhs.strip()
        out.append(r)
    return Session("\n".join(src) + "\n", out, path, is_all)


# responses read by one builder: half a model's reading budget of characters and statements
_CHUNK = MAX_EXPANDED_BYTES // 2
_CHUNK_RESPONSES = MAX_EXPANDED_STATEMENTS // 2


# -- reading the responses -----------------------------------------------------------------
@dataclass
class ParsedResponse:
    target: ir.Expr                  # NAME, NAME', NAME[i], NAME>, NAME>> as the IR
    value: ir.Expr | None            # Autolev's expression (None: the name alone)


def parse_responses(session: Session) -> tuple[dict[int, ParsedResponse], dict[int, str]]:
    """Each response read as `NAME = expression` (or `NAME` alone when the response
    records no expression): plain arithmetic by printed.read_plain, the rest by the
    grammar; {index: ParsedResponse}, and {index: why} for those that cannot be read,
    naming the file's line."""
    parsed: dict[int, ParsedResponse] = {}
    refused: dict[int, str] = {}
    by_grammar: list[int] = []
    for k, r in enumerate(session.responses):
        plain = read_plain(r.lhs, r.expr, Span(Location(session.path, r.line, 1))) \
            if r.expr else None
        if plain is None:
            by_grammar.append(k)
        else:
            parsed[k] = ParsedResponse(*plain)
    responses = session.responses
    texts = {k: f"{responses[k].lhs} = {responses[k].expr}" if responses[k].expr
             else responses[k].lhs for k in by_grammar}
    first = 0
    while first < len(by_grammar):
        last, size = first, 0
        while last < len(by_grammar) and last - first < _CHUNK_RESPONSES and \
                (last == first or size + len(texts[by_grammar[last]]) < _CHUNK):
            size += len(texts[by_grammar[last]]) + 1
            last += 1
        _parse_chunk(session, by_grammar[first:last], texts, parsed, refused)
        first = last
    for k, r in enumerate(session.responses):
        if k not in parsed and k not in refused:    # a line the builder made nothing of
            refused[k] = f"its left side '{printable(r.lhs)}' is not a name (NAME, NAME', " \
                "NAME[i], NAME>, NAME>>)"
    return parsed, refused


def _parse_chunk(session: Session, chunk: list[int], texts: dict[int, str],
                 parsed: dict[int, ParsedResponse], refused: dict[int, str]) -> None:
    """The responses `chunk` (indices), one a line, read by one builder."""
    builder = Builder(session.path, None, reserved=vocabulary())
    builder.build_source(SourceFile(session.path, "\n".join(texts[k] for k in chunk) + "\n"))
    for d in builder.errors:
        k = chunk[d.location.line - 1]
        refused.setdefault(k, f"Autolev's response does not read: "
                              f"{printable(session.path)}:{session.responses[k].line}: "
                              f"{d.message} [{d.code}]")
    per_line: dict[int, int] = {}
    for st in builder.statements:
        per_line[st.span.start.line] = per_line.get(st.span.start.line, 0) + 1
    for line, count in per_line.items():
        if count > 1:               # Autolev printed one assignment a response
            k = chunk[line - 1]
            refused.setdefault(k, f"Autolev's response holds {count} statements "
                                  f"({printable(session.path)}:{session.responses[k].line}); "
                                  "a response is one NAME = value")
    for st in builder.statements:
        k = chunk[st.span.start.line - 1]
        if k in refused:
            continue
        if isinstance(st, ir.Assignment) and st.op == "=":
            target, value = st.target, st.value
        elif isinstance(st, ir.Display):
            target, value = st.expr, None
        else:
            target = value = None
        if not isinstance(target, (ir.Name, ir.Index, ir.VectorName)):
            refused[k] = (f"its left side '{printable(session.responses[k].lhs)}' is not a "
                          "name (NAME, NAME', NAME[i], NAME>, NAME>>)")
            continue
        parsed[k] = ParsedResponse(target, value)


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
    note: str | None = None       # why a session that is not wrong has nothing compared

    def count(self, status: str) -> int:
        return sum(o.status == status for o in self.outcomes)

    @property
    def ok(self) -> bool:
        return self.error is None and self.count("mismatch") == 0

    def summary(self) -> str:
        if self.note is not None:
            return f"{self.path}: {self.note}"
        return (f"{self.path}: {self.count('match')} match, {self.count('mismatch')} "
                f"mismatch, {self.count('not comparable')} not comparable "
                f"({len(self.outcomes)} responses)")

    def as_dict(self) -> dict:
        return {"file": self.path, "error": self.error, "note": self.note,
                "match": self.count("match"),
                "mismatch": self.count("mismatch"),
                "not_comparable": self.count("not comparable"),
                "responses": [o.as_dict() for o in self.outcomes]}


def _plain(v):
    import numpy as np      # here: a transcript replays without numpy
    if v is None:
        return None
    a = np.asarray(v, dtype=complex)
    if np.all(np.abs(a.imag) < 1e-12 * (1 + np.abs(a.real))):
        return a.real.tolist()
    return [[z.real, z.imag] for z in a.ravel()]


def _is_z(lhs: str) -> bool:
    return re.fullmatch(r"Z\d+", lhs.strip().upper()) is not None


@dataclass
class Replay:
    """The session's model run with its probes: our value of each response's name
    with the definitions known then, and Autolev's expression's value (no Z's: their
    values are named for the responses after them); `error` when the model itself
    cannot be replayed."""

    model: object = None
    ours: dict[int, tuple] = field(default_factory=dict)     # {k: (value, definitions)}
    theirs: dict[int, object] = field(default_factory=dict)
    ours_missing: dict[int, str] = field(default_factory=dict)     # {k: why}
    theirs_missing: dict[int, str] = field(default_factory=dict)   # {k: why}
    error: str | None = None


# a failing probe is dropped and the model run again, this many times at most
_ATTEMPTS = 6


def replay(session: Session, p: Path, parsed: dict[int, ParsedResponse],
           folder: Path | None = None) -> Replay:
    """Translate and run the session's model with a probe of our value of each parsed
    response's name (but a Z's) and of the value of its expression, if it has one; a
    probe our model cannot evaluate is dropped (reported as missing) and the model run
    again.  `folder`: the model's folder (its macros and functions), when not the
    session's."""
    probes: list[Probe] = []
    for k, pr in parsed.items():
        r = session.responses[k]
        span = Span(Location(session.path, r.line, 1))
        if not _is_z(r.lhs):
            probes.append(Probe(f"ours{k}", r.after, pr.target, span))
        if pr.value is not None:
            probes.append(Probe(f"theirs{k}", r.after, pr.value, span,
                                binds=r.lhs.strip() if _is_z(r.lhs) else None))
    result = Replay()
    failed: dict[str, str] = {}            # {probe's key: why it cannot be evaluated}
    for _attempt in range(_ATTEMPTS):
        kept = tuple(probe for probe in probes if probe.key not in failed)
        try:
            tr = translation(session.source, str(p), kept, folder)
        except AutolevSyntaxError as exc:
            result.error = f"the model does not parse: {exc}"
            return result
        except AutolevTranslationError as exc:
            first = next(d for d in exc.diagnostics if d.severity == "error")
            result.error = f"the model does not translate: {first.format()}"
            if first.code in ("T003", "E022") and folder is None:
                result.error += ("\n(a session kept apart from its model finds the model's "
                                 ".a, .R and RUN files with --model-folder DIR)")
            return result
        try:
            model = load_translation(tr, str(p))
        except AutolevRuntimeError as exc:
            d = exc.diagnostics[0]
            at = [probe for probe in kept if probe.span.start == d.location]
            if not at:
                result.error = f"the model does not run: {exc}"
                return result
            for probe in at:
                failed[probe.key] = d.message
            continue
        values = model.loaded.namespace[PROBES] if kept else {}
        for probe in probes:
            kind, k = re.fullmatch(r"(ours|theirs)(\d+)", probe.key).groups()
            ours, k = kind == "ours", int(k)
            if probe.key in tr.probe_errors:
                why = tr.probe_errors[probe.key]
                if ours:
                    result.ours_missing[k] = f"our translation has no such value there ({why})"
                else:
                    result.theirs_missing[k] = f"Autolev's response does not translate: {why}"
            elif probe.key in failed:
                why = failed[probe.key]
                if ours:
                    result.ours_missing[k] = f"our model cannot give it there ({why})"
                else:
                    result.theirs_missing[k] = f"Autolev's response cannot be evaluated " \
                        f"there: {why}"
            elif ours:
                result.ours[k] = values[probe.key]
            elif not probe.binds:
                result.theirs[k] = values[probe.key][0]
        result.model = model
        return result
    result.error = "too many responses our translation cannot evaluate"
    return result


def verify(path, points: int = 3, tolerance: float = 2e-6,
           folder: Path | None = None, progress=None) -> Report:
    """Replay the responses recorded in an `.all` session (or the `% ->` comments of a
    `.al` file) against our translation; a Report of each response's outcome.
    `folder`: the model's folder, where its macros, functions and RUN files are, when
    the session is elsewhere (looked for beside the session first).  `progress`: a
    stream told of steps past two seconds and of the responses compared."""
    p = Path(path)
    try:
        raw = reading.read_bytes(p)
    except OSError as exc:
        raise AutolevFileError(p, f"cannot read: {exc.strerror or exc}") from None
    session = read_session(decode(raw), str(p))
    report = Report(str(p))
    if not session.responses and session.saved:
        # no input of the session printed a response (declarations only): nothing to
        # compare, and nothing wrong (docs/language.md, "autolev verify")
        report.note = "no input of this session printed a response: nothing to compare"
        return report
    if not session.responses:
        report.error = "no responses recorded (an .all transcript, or % -> comments)"
        return report
    count = len(session.responses)
    with SlowStep(progress, f"{p}: reading {count} responses"):
        parsed, refused = parse_responses(session)
    with SlowStep(progress, f"{p}: translating and running the session's model"):
        replayed = replay(session, p, parsed, folder)
    if replayed.error is not None:
        report.error = replayed.error
        return report
    model = replayed.model
    sample = _SamplePoints(model, points)
    compared = Progress(progress, "responses compared", 0, count)
    for k, r in enumerate(session.responses):
        compared.update(k)
        if k in refused:
            report.outcomes.append(Outcome(r, "not comparable", refused[k]))
        elif k in replayed.theirs_missing:
            report.outcomes.append(Outcome(r, "not comparable", replayed.theirs_missing[k]))
        elif _is_z(r.lhs):
            report.outcomes.append(None)         # judged with the responses using it
        elif k in replayed.ours_missing:
            # a name the engine made (NICHECK's WCHECK1'): compare with its definition
            sym = next((x for x in model.defs.rhs if not isinstance(x, Z)
                        and x.name.upper() == r.lhs.upper()), None)
            if sym is None:
                report.outcomes.append(Outcome(r, "not comparable", replayed.ours_missing[k]))
                continue
            o = _compare(sample.wanted(None), r, sym, replayed.theirs[k], session.path,
                         tolerance)
            o.detail += " (a name the engine defines, compared with its definition)"
            report.outcomes.append(o)
        else:
            ours, known = replayed.ours[k]
            report.outcomes.append(_compare(sample.wanted(known), r, ours,
                                            replayed.theirs[k], session.path, tolerance))
    compared.done()
    _judge_z_responses(session, parsed, report)
    return report


def _judge_z_responses(session: Session, parsed: dict[int, ParsedResponse],
                       report: Report) -> None:
    """A Z response (`Z68 = 0.25*u2*Z56 - ...`) names a piece of a result Autolev went on
    to print: it is compared through the first later response that uses it (directly or
    through other Z's) and could be compared."""
    responses = session.responses
    lhs = [r.lhs.strip().upper() for r in responses]
    # the responses using each name, in order, and where each name is given again
    users: dict[str, list[int]] = {}
    given: dict[str, list[int]] = {}
    for k in range(len(responses)):
        given.setdefault(lhs[k], []).append(k)
        if k in parsed and parsed[k].value is not None:
            for name in {n.name.upper() for n in ir.walk(parsed[k].value)
                         if isinstance(n, ir.Name)}:
                users.setdefault(name, []).append(k)
    for k, r in enumerate(responses):
        if report.outcomes[k] is not None:
            continue
        name = lhs[k]
        again = given[name]
        # Z renumbered: later uses are another's
        end = again[i] if (i := bisect.bisect_right(again, k)) < len(again) else len(lhs)
        judged = _first_comparable_user(k, end, name, users, lhs, report.outcomes)
        if judged is None:
            report.outcomes[k] = Outcome(r, "not comparable", "Autolev's intermediate "
                                         "variable, used by no later response that could "
                                         "be compared")
        else:
            user = responses[judged]
            o = report.outcomes[judged]
            report.outcomes[k] = Outcome(r, o.status, f"{o.detail}, as part of "
                                         f"({user.number}) {user.lhs}")


def _first_comparable_user(k: int, end: int, name: str, users: dict, lhs: list,
                           outcomes: list) -> int | None:
    """The first response after k and before `end` that uses `name` (directly, or
    through the Z's after k that use it) and was compared; visited in order, as a scan
    of the responses would, but only those using a name reached."""
    reach = {name}
    waiting = [j for j in users.get(name, ()) if k < j < end]
    heapq.heapify(waiting)
    seen = set(waiting)
    while waiting:
        j = heapq.heappop(waiting)
        if _is_z(lhs[j]):
            if lhs[j] not in reach:
                reach.add(lhs[j])
                for later in users.get(lhs[j], ()):
                    if j < later < end and later not in seen:
                        seen.add(later)
                        heapq.heappush(waiting, later)
            continue
        o = outcomes[j]
        if o is not None and o.status in ("match", "mismatch"):
            return j
    return None


# (seed, span of the pseudo-random values) of the points tried, in order
_POINTS = ([(seed, (0.5, 1.5)) for seed in range(1, 4)]
           + [(seed, (0.1, 0.5)) for seed in range(1, 4)]
           + [(seed, (-0.5, 0.5)) for seed in range(1, 7)])


def _is_real(a) -> bool:
    """A value everywhere, real up to rounding (a NaN is no value: compared apart)."""
    import numpy as np
    return bool(np.all(np.isfinite(np.asarray(a, dtype=complex)))) and is_real_number(a)


class NotComparable(Exception):
    pass


class _SamplePoints:
    """The points of one verification, each with the values of the definitions taken
    there: responses printed with the same definitions known share them (a definition
    is evaluated once per point, not once per response using it).  Only the points of
    the latest set of definitions are kept: responses come in the session's order."""

    def __init__(self, model, count: int):
        self.model, self.count = model, count
        self.newton = model.newtonian_frame or next(iter(model.frames_by_name.values()),
                                                    None)
        self.user_symbols = [s for s in model.defs.rhs if not isinstance(s, Z)]
        self._free_of: tuple = (None, frozenset())   # (known, the definitions not in it)
        self._points: dict[frozenset, list[NumericPoint]] = {}

    def wanted(self, known: dict | None) -> "_PointSet":
        """The points for a response printed with the definitions `known` made (None:
        every definition counts).  A definition made only after the response is free
        there (a later CONSTRAIN defines the dependent speeds): it gets a value of its
        own.  Z's keep their values: each names an expression, whatever is defined."""
        if known is None:
            free = frozenset()
        elif self._free_of[0] is known:
            free = self._free_of[1]
        else:
            free = frozenset(s for s in self.user_symbols if s not in known)
            self._free_of = (known, free)
        if free not in self._points:
            self._points = {free: [self._point(seed, span, free) for seed, span in _POINTS]}
        return _PointSet(self.newton, self._points[free], self.count)

    def _point(self, seed: int, span: tuple, free: frozenset) -> NumericPoint:
        point = NumericPoint(self.model.defs, seed=seed, span=span)
        # Euler parameters of unit length, as Autolev's responses assume
        for quaternion in self.model.unit_quaternions:
            parameters = [e for e in quaternion
                          if isinstance(e, Symbol) and e not in self.model.defs.rhs]
            if len(parameters) == 4:
                values = [float(point.value(e, {})) for e in parameters]
                norm = math.sqrt(sum(v * v for v in values))
                point.values.update({e: v / norm for e, v in zip(parameters, values)})
        for s in free:
            point.cache[s] = point.value(s, {})
        return point


@dataclass(frozen=True)
class _PointSet:
    """The points a response is compared at, in order (it is compared at the first
    `count` where both values are real), and the frame vectors are measured in."""

    newton: object
    points: list
    count: int


class _Comparison:
    """One response against our value: what evaluating both needs at every point."""

    def __init__(self, at: _PointSet, r: Response, ours, theirs):
        self.at, self.newton, self.defs = at, at.newton, at.points[0].defs
        self.response, self.ours, self.theirs = r, ours, theirs

    def values_at(self, point: NumericPoint):
        """(ours, Autolev's) at one point, as complex arrays of the same shape."""
        import numpy as np
        at = _AtPoint(self, point)
        theirs = np.asarray(at.value(self.theirs), dtype=complex)
        mine = np.asarray(at.value(self.ours), dtype=complex)
        if mine.shape != theirs.shape:
            if mine.size != theirs.size:
                raise NotComparable(f"shapes differ: ours {mine.shape}, Autolev's "
                                    f"{theirs.shape}")
            mine = mine.reshape(theirs.shape)
        return mine, theirs


class _AtPoint:
    """The numbers of one comparison at one point."""

    def __init__(self, comparison: _Comparison, point: NumericPoint):
        self.c, self.point = comparison, point

    def num(self, e) -> complex:
        return complex(self.c.defs.numeric(e, self.point))

    def dcm(self, frame) -> np.ndarray:
        import numpy as np
        newton = self.c.newton
        if newton is None or not newton.orientation_known(frame):
            raise NotComparable(f"frame {frame.name} is not oriented in the Newtonian frame")
        m = newton.dcm(frame)
        return np.array([[self.num(m[i, j]) for j in range(3)] for i in range(3)])

    def value(self, v):
        """A value of the model, in the Newtonian frame for a vector or dyadic."""
        import numpy as np
        if isinstance(v, Vector):
            out = np.zeros(3, dtype=complex)
            for f, comps in v.terms.items():
                out = out + self.dcm(f) @ np.array([self.num(c) for c in comps])
            return out
        if isinstance(v, Dyadic):
            out = np.zeros((3, 3), dtype=complex)
            for (fa, fb), m in v.terms.items():
                mm = np.array([[self.num(m[i, j]) for j in range(3)] for i in range(3)])
                out = out + self.dcm(fa) @ mm @ self.dcm(fb).T
            return out
        if hasattr(v, "shape") and not isinstance(v, np.ndarray):
            return np.array([[self.num(v[i, j]) for j in range(v.shape[1])]
                             for i in range(v.shape[0])])
        return self.num(v)


def _compare(at: _PointSet, r: Response, ours, theirs, path: str, tol: float) -> Outcome:
    """Our value against Autolev's response at sample points: match within `tol`,
    mismatch, or not comparable."""
    import numpy as np
    comparison = _Comparison(at, r, ours, theirs)
    sampled = _sample(comparison, path)
    if isinstance(sampled, Outcome):
        return sampled
    a, b = sampled
    # values are O(1) at the sample points; a scale below 1e-6 is cancellation to zero
    scale = max(float(np.abs(a).max(initial=0)), float(np.abs(b).max(initial=0)), 1e-6)
    difference = float(np.abs(a - b).max(initial=0))
    err = difference / scale
    if err <= tol:
        return Outcome(r, "match", f"relative difference {err:.1e}", a[0], b[0])
    # a sum printed with rounded coefficients cancels to zero only as far as they go:
    # its difference is judged against its largest term (a constraint's zero[1])
    largest = _largest_term(comparison)
    if largest > scale and difference <= tol * largest:
        return Outcome(r, "match", f"relative difference {difference / largest:.1e} of its "
                       "largest term (a sum that cancels to zero)", a[0], b[0])
    return Outcome(r, "mismatch", f"relative difference {err:.1e} at {len(a)} points",
                   a[0], b[0])


def _largest_term(comparison: _Comparison) -> float:
    """The largest magnitude of a term of Autolev's value (a scalar sum) at the first
    sample points; 0 for any other value."""
    theirs = comparison.theirs
    if not isinstance(theirs, sm.Add):
        return 0.0
    largest = 0.0
    for point in comparison.at.points[:comparison.at.count]:
        at = _AtPoint(comparison, point)
        try:
            largest = max(largest, max(abs(at.num(term)) for term in theirs.args))
        except (NotComparable, ZeroDivisionError, OverflowError, ValueError):
            return 0.0
    return largest if math.isfinite(largest) else 0.0


def _sample(comparison: _Comparison, path: str):
    """(ours, Autolev's) at up to `count` points, as arrays, or the Outcome of a
    response that cannot be evaluated.  The points are those where both values are
    real: equal expressions may take different branches of a root or logarithm where
    they are complex (Euler parameters far from unit length make 1 - Z10^2 negative)."""
    import numpy as np
    r = comparison.response
    count = comparison.at.count
    ours_all, theirs_all, complex_pairs = [], [], []
    for point in comparison.at.points:
        try:
            mine, theirs = comparison.values_at(point)
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
            if len(ours_all) == count:
                break
        elif len(complex_pairs) < count:
            complex_pairs.append((mine, theirs))
    if not ours_all:
        if any(np.isnan(m).any() or np.isnan(t).any() for m, t in complex_pairs):
            # no value anywhere (a function refusing its argument, MIN a complex number)
            return Outcome(r, "not comparable", "cannot evaluate: no value at the points "
                           "tried")
        ours_all = [m for m, _ in complex_pairs]
        theirs_all = [t for _, t in complex_pairs]
    return np.array(ours_all), np.array(theirs_all)


__all__ = ["verify", "read_session", "parse_responses", "replay", "Replay", "Report",
           "Outcome", "Session", "Response", "ParsedResponse"]
