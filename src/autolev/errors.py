"""Diagnostics and the errors that carry them.

Every problem found in a user's `.al` file becomes a `Diagnostic` that points into
the original file (after macro and RUN expansion, continuation lines and CRLF):
`file:line:col: severity: message`, the source line, and a caret under the column.
"""
from __future__ import annotations

from dataclasses import dataclass, field

# exact numbers beyond this many digits are refused (sympy would compute 10^10^10 in
# full) where the translator folds literals and where the runtime substitutes values
MAX_EXACT_DIGITS = 1000


@dataclass(frozen=True)
class Location:
    """A position in an original source file (1-based line and column)."""

    file: str
    line: int
    col: int
    # the macro call or RUN statement this text was expanded from, if any
    via: "Location | None" = None
    via_what: str = ""

    def __str__(self) -> str:
        return f"{printable(self.file)}:{self.line}:{self.col}"


class Span:
    """Source extent of a statement or expression: start and end locations.

    Built lazily from text offsets (`Span.of(mapped, lo, hi)`): a model has far more
    expression nodes than anyone will ever ask the location of."""

    __slots__ = ("_start", "_end", "_mapped", "_lo", "_hi")

    def __init__(self, start: Location | None = None, end: Location | None = None):
        self._start, self._end = start, end if end is not None else start
        self._mapped = None
        self._lo = self._hi = 0

    @classmethod
    def of(cls, mapped, lo: int, hi: int) -> "Span":
        """The span of text offsets lo..hi (inclusive) of a source.MappedText."""
        span = cls.__new__(cls)
        span._start = span._end = None
        span._mapped, span._lo, span._hi = mapped, lo, hi
        return span

    @property
    def start(self) -> Location:
        if self._start is None:
            self._start = self._mapped.locate(self._lo)
        return self._start

    @property
    def end(self) -> Location:
        if self._end is None:
            self._end = self._mapped.locate(self._hi)
        return self._end

    @property
    def file(self) -> str:
        return self.start.file

    @property
    def text(self) -> str | None:
        """The text as it was read (a macro's with its #k# replaced), when known."""
        return self._mapped.slice(self._lo, self._hi + 1) if self._mapped is not None \
            else None

    @property
    def line(self) -> int:
        return self.start.line

    @property
    def col(self) -> int:
        return self.start.col

    def __eq__(self, other) -> bool:
        return isinstance(other, Span) and (self.start, self.end) == (other.start, other.end)

    def __hash__(self) -> int:
        return hash((self.start, self.end))

    def __repr__(self) -> str:
        return f"Span({self.start}, {self.end})"

    def __str__(self) -> str:
        return str(self.start)


@dataclass(frozen=True)
class Diagnostic:
    location: Location
    code: str
    message: str
    severity: str = "error"  # "error" | "warning" | "note"
    source_line: str | None = None
    notes: tuple[str, ...] = field(default=())

    @property
    def file(self) -> str:
        return self.location.file

    @property
    def line(self) -> int:
        return self.location.line

    @property
    def col(self) -> int:
        return self.location.col

    def format(self, context: bool = True) -> str:
        """`file:line:col: error: message`, then the line and a caret (when known); a
        model's control characters written out, never sent to the terminal."""
        out = [f"{self.location}: {self.severity}: {printable(self.message)} [{self.code}]"]
        if context and self.source_line is not None:
            line = self.source_line.rstrip("\n")
            out.append("    " + printable(line))
            # copy tabs so the caret lines up however the terminal renders them
            prefix = "".join(ch if ch == "\t" else " "
                             for ch in printable(line[: max(self.col - 1, 0)]))
            out.append("    " + prefix + "^")
        via = self.location.via
        what = self.location.via_what
        while via is not None:
            out.append(f"{via}: note: in {what}" if what else f"{via}: note: expanded from here")
            what = via.via_what
            via = via.via
        for note in self.notes:
            out.append(f"{self.location}: note: {note}")
        return "\n".join(out)

    def as_dict(self) -> dict:
        chain = []
        via, what = self.location.via, self.location.via_what
        while via is not None:
            chain.append({"file": via.file, "line": via.line, "col": via.col, "what": what})
            what, via = via.via_what, via.via
        return {"file": self.file, "line": self.line, "col": self.col,
                "severity": self.severity, "code": self.code, "message": self.message,
                "expanded_from": chain, "notes": list(self.notes)}

    def __str__(self) -> str:
        return self.format()


def printable(text: str) -> str:
    """`text` with its control characters (a terminal's escape sequences) written out as
    \\xNN; tabs kept."""
    if all(ch.isprintable() or ch == "\t" for ch in text):
        return text
    return "".join(ch if ch.isprintable() or ch == "\t" else
                   f"\\x{ord(ch):02x}" if ord(ch) < 256 else f"\\u{ord(ch):04x}"
                   for ch in text)


def printable_lines(text: str) -> str:
    """`text` for a terminal: each line printable, the line ends kept."""
    return "\n".join(printable(line) for line in text.split("\n"))


class AutolevError(Exception):
    """Base class of every error this package raises for a user's input."""


# what an internal error asks of the user (there is no public issue tracker to name)
REPORT_REQUEST = "please report it to the autolev developers, with the model and this message"


class AutolevInternalError(Exception):
    """A bug in autolev, not in the user's model: Python raised an exception autolev
    did not expect while it `did` something at `location` (an `.al` statement, or a
    recorded response).  Deliberately not an AutolevError: every `except AutolevError`
    means "the input is at fault", and a bug must not be reported as that.  The
    original exception is chained as `__cause__`."""

    def __init__(self, location, did: str, exc: BaseException):
        self.location = location
        self.did = did
        self.error = f"{type(exc).__name__}: {exc}"
        super().__init__(f"{location}: internal error: a bug in autolev, not in the model, "
                         f"while {did}: {self.error}\n{location}: note: {REPORT_REQUEST}")

    def __reduce__(self):
        # rebuilt whole in another process (a sweep's or a bench's worker), cause and all
        return (_rebuilt_internal_error, (self.location, self.did, self.error, self.args))


def _rebuilt_internal_error(location, did: str, error: str, args: tuple):
    exc = AutolevInternalError.__new__(AutolevInternalError)
    Exception.__init__(exc, *args)
    exc.location, exc.did, exc.error = location, did, error
    return exc


class AutolevSyntaxError(AutolevError):
    """The file could not be read as Autolev.  Carries *all* diagnostics found."""

    def __init__(self, diagnostics: list[Diagnostic]):
        self.diagnostics = list(diagnostics)
        errors = [d for d in self.diagnostics if d.severity == "error"]
        head = f"{len(errors)} error{'s' if len(errors) != 1 else ''}"
        super().__init__(head + "\n" + "\n".join(d.format() for d in errors))


class AutolevFileError(AutolevError):
    """A model file could not be found or read: `path`, and `reason` (why)."""

    def __init__(self, path, reason: str):
        self.path = path
        self.reason = reason
        super().__init__(f"{path}: {reason}")


class AutolevTranslationError(AutolevError):
    """The model reads, but a construct cannot be translated.  Carries all diagnostics."""

    def __init__(self, diagnostics: list[Diagnostic]):
        self.diagnostics = list(diagnostics)
        errors = [d for d in self.diagnostics if d.severity == "error"]
        head = f"{len(errors)} error{'s' if len(errors) != 1 else ''}"
        super().__init__(head + "\n" + "\n".join(d.format() for d in errors))


class AutolevRuntimeError(AutolevError):
    """The translated model failed while building (a missing mass, velocity, ...);
    the diagnostic points at the Autolev statement."""

    def __init__(self, diagnostic: Diagnostic):
        self.diagnostic = diagnostic
        self.diagnostics = [diagnostic]
        super().__init__(diagnostic.format())


def some_names(names, shown: int = 8) -> str:
    """A list of names for a message: the first `shown` of them and how many more."""
    names = list(names)
    more = len(names) - shown
    return ", ".join(names[:shown]) + (f", ... and {more} more" if more > 0 else "")
