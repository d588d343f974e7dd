"""Reading Autolev source: encodings, line ends, continuation lines, macros, RUN files.

The lexer sees `MappedText`: the text after continuation lines are joined (and, for a
user macro, after `#k#` placeholders are replaced).  Every character of it maps back
to a file, line and column of an original file, so diagnostics point at what the
user wrote.

Continuation: a line whose code (before any `%` comment) ends with `&` continues on
the next line, whose leading blanks are dropped.  Autolev printed long responses
broken mid-token this way (`SIN(THET&` / `   A)`), and users pasted them back into
their models, so the pieces are glued without a separator.
"""
from __future__ import annotations

import bisect
import codecs
import os
import re
from dataclasses import dataclass, field
from pathlib import Path

from .errors import AutolevFileError, Location
from .engine import reading
from .engine.reading import find_file

MAX_INCLUDE_DEPTH = 16
_PLACEHOLDER = re.compile(r"#(\d+)#")


def decode(raw: bytes) -> str:
    """UTF-8 (with or without BOM) or UTF-16 with BOM; anything else is Latin-1."""
    if raw.startswith(codecs.BOM_UTF8):
        return raw[len(codecs.BOM_UTF8):].decode("utf-8", errors="replace")
    if raw.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        return raw.decode("utf-16", errors="replace")
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        return raw.decode("latin-1")


def normalize_newlines(text: str) -> str:
    return text.replace("\r\n", "\n").replace("\r", "\n")


@dataclass
class SourceFile:
    """One original file (or string) as the user wrote it."""

    name: str                  # the name shown in diagnostics
    text: str                  # with '\n' line ends
    path: Path | None = None   # where it lives, when it is a file
    lines: list[str] = field(init=False)

    def __post_init__(self) -> None:
        self.text = normalize_newlines(self.text)
        self.lines = self.text.split("\n")

    @classmethod
    def read(cls, path: str | os.PathLike, name: str | None = None) -> "SourceFile":
        p = Path(path)
        try:
            raw = reading.read_bytes(p)
        except OSError as exc:
            raise AutolevFileError(p, f"cannot read: {exc.strerror or exc}") from None
        return cls(name or str(path), decode(raw), p)

    def line_text(self, line: int) -> str | None:
        return self.lines[line - 1] if 1 <= line <= len(self.lines) else None


@dataclass(frozen=True)
class _Anchor:
    """Text from `offset` on comes from (file, line, col); with advance=False every
    character maps to that same column (text substituted for a macro placeholder)."""

    offset: int
    file: SourceFile
    line: int
    col: int
    advance: bool = True


class MappedText:
    """Text ready for the lexer, with a map back to original positions."""

    def __init__(self, text: str, anchors: list[_Anchor],
                 via: Location | None = None, via_what: str = ""):
        self.text = text
        self._anchors = anchors
        self._offsets = [a.offset for a in anchors]
        self.via = via
        self.via_what = via_what

    def _anchor(self, offset: int) -> _Anchor:
        i = bisect.bisect_right(self._offsets, offset) - 1
        return self._anchors[max(i, 0)]

    def locate(self, offset: int) -> Location:
        a = self._anchor(offset)
        col = a.col + (offset - a.offset if a.advance else 0)
        return Location(a.file.name, a.line, col, self.via, self.via_what)

    def source_line(self, offset: int) -> str | None:
        a = self._anchor(offset)
        return a.file.line_text(a.line)

    def substituted(self, offset: int) -> bool:
        """Whether the text at `offset` was put there for a macro's or function's
        placeholder (an argument of the call), not written in the file itself."""
        return not self._anchor(offset).advance

    def source_file(self, offset: int) -> SourceFile:
        return self._anchor(offset).file

    def slice(self, start: int, stop: int) -> str:
        return self.text[start:stop]


@dataclass
class _PhysicalLine:
    text: str
    anchors: list[_Anchor]   # offsets relative to the line; the first is at 0


def _plain_lines(src: SourceFile) -> list[_PhysicalLine]:
    return [_PhysicalLine(t, [_Anchor(0, src, i, 1)]) for i, t in enumerate(src.lines, 1)]


def _code_end(text: str) -> int:
    """Index where the code of a line ends (its `%` comment starts), or len(text)."""
    pct = text.find("%")
    return len(text) if pct < 0 else pct


def _join(lines: list[_PhysicalLine], via: Location | None, via_what: str) -> MappedText:
    out: list[str] = []
    anchors: list[_Anchor] = []
    pos = 0
    continuing = False

    def copy(line: _PhysicalLine, start: int, stop: int) -> None:
        nonlocal pos
        # the anchor in force at `start`, shifted there, then the later ones
        # (the last of those at one offset: a placeholder at a line's start is the text)
        active = [a for a in line.anchors if a.offset <= start][-1]
        shift = (start - active.offset) if active.advance else 0
        anchors.append(_Anchor(pos, active.file, active.line, active.col + shift, active.advance))
        for a in line.anchors:
            if start < a.offset < stop:
                anchors.append(_Anchor(pos + a.offset - start, a.file, a.line, a.col, a.advance))
        out.append(line.text[start:stop])
        pos += stop - start

    for n, line in enumerate(lines):
        text = line.text
        start = len(text) - len(text.lstrip(" \t")) if continuing else 0
        code = text[:_code_end(text)].rstrip(" \t")
        if code.endswith("&"):
            copy(line, start, len(code) - 1)
            continuing = True
            continue
        copy(line, start, len(text))
        continuing = False
        if n < len(lines) - 1:
            out.append("\n")
            pos += 1
    return MappedText("".join(out), anchors, via, via_what)


def mapped_source(src: SourceFile, via: Location | None = None, via_what: str = "") -> MappedText:
    """The text of `src` with continuation lines joined."""
    return _join(_plain_lines(src), via, via_what)


def placeholders(src: SourceFile) -> set[int]:
    return {int(m.group(1)) for m in _PLACEHOLDER.finditer(src.text)}


def expand_macro(macro: SourceFile, args: list[str], call: Location, what: str) -> MappedText:
    """Replace `#k#` by the k-th argument text (k counts from 1) in every line of `macro`."""
    lines = []
    for lineno, text in enumerate(macro.lines, 1):
        parts: list[str] = []
        anchors = [_Anchor(0, macro, lineno, 1)]
        length, last = 0, 0
        for m in _PLACEHOLDER.finditer(text):
            k = int(m.group(1))
            if not 1 <= k <= len(args):
                continue  # reported by the caller; leave the text as it is
            parts.append(text[last:m.start()])
            length += m.start() - last
            anchors.append(_Anchor(length, macro, lineno, m.start() + 1, advance=False))
            parts.append(args[k - 1])
            length += len(args[k - 1])
            anchors.append(_Anchor(length, macro, lineno, m.end() + 1))
            last = m.end()
        parts.append(text[last:])
        lines.append(_PhysicalLine("".join(parts), anchors))
    return _join(lines, call, what)


# ---------------------------------------------------------------------------
# Finding files the way Autolev users named them (any case, '\' or '/': the searches
# themselves are engine.reading's, which a kept answer asks again)

def is_within(path: Path, root: Path) -> bool:
    # realpath, not Path.resolve: a link that leads to itself is a name, not an exception
    real, real_root = os.path.realpath(path), os.path.realpath(root)
    return real == real_root or real.startswith(real_root.rstrip(os.sep) + os.sep)


class RunRefused(Exception):
    """RUN names a file outside the model's folder tree."""


def resolve_run(name: str, including: Path, model_root: Path) -> Path | None:
    """Find the file a `RUN name` statement includes.

    Autolev resolved RUN paths against its working directory, which was usually the
    model's folder but sometimes its parent (`RUN gait3d_pelvis213/x.al` written in
    gait3d_pelvis213/).  So the including file's folder and then its ancestors are
    tried, and only a file inside the model's folder tree is taken.  A path that
    itself leaves the tree (`../../x.al`, an absolute path) is refused.
    """
    rel = name.replace("\\", "/")
    lexical = Path(os.path.normpath(including.parent / rel))
    if os.path.isabs(rel) or not is_within(lexical, model_root):
        raise RunRefused(rel)
    base = including.parent
    for _ in range(4):
        found = find_file(base, rel)
        if found is not None and is_within(found, model_root):
            return found
        if base.parent == base:
            break
        base = base.parent
    return None


def find_macro(name: str, search_dirs: list[Path], suffix: str = ".a") -> Path | None:
    """The user macro file `name.a` (a user function: `name.r`), any case, in the first
    folder that has it."""
    for d in search_dirs:
        found = find_file(d, name + suffix)
        if found is not None:
            return found
    return None
