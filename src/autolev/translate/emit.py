"""The Python writer's text: quoting what comes from outside, and the layout of long lines.

File names, the model's own lines and `%` comments, labels, units and names come from
files a user may not have written.  None of it becomes code: every piece goes into the
module through `quote` (a Python string literal), `comment` (the body of a one-line
comment) or `docstring` (a line inside the module's docstring).
"""
from __future__ import annotations

import re
import textwrap

# the generated module's longest line where the writer can break one (assignments of
# several names, calls of several items); 92 is the width the golden files were written at
MAX_WIDTH = 92

# what may not appear raw in a comment or docstring: control characters (NUL, CR, form
# feed, ...), Unicode line separators, and lone surrogates (undecodable bytes)
_UNSAFE = re.compile("[\x00-\x08\x0a-\x1f\x7f\x85\u2028\u2029\ud800-\udfff]")


def _escaped(m: re.Match) -> str:
    return m.group().encode("unicode_escape", "backslashreplace").decode("ascii")


def quote(text: str) -> str:
    """A Python string literal whose value is `text` (repr escapes quotes, backslashes,
    control characters and lone surrogates)."""
    return repr(str(text))


def comment(text: str) -> str:
    """`text` as the body of a one-line comment (control characters as escapes)."""
    return _UNSAFE.sub(_escaped, text)


def docstring(text: str) -> str:
    """`text` inside a triple-quoted docstring: backslashes and quotes escaped too."""
    return comment(text.replace("\\", "\\\\").replace('"', '\\"'))


# -- layout -------------------------------------------------------------------------------
def _wrapped(text: str) -> list[str]:
    """`text` in lines that fit after one character (a bracket or an indent); a name is
    never split."""
    return textwrap.wrap(text, MAX_WIDTH - 1, break_long_words=False)


def assign_names(names: list[str], call: str) -> str:
    """`A, B = call`, the names wrapped in parentheses when the line is long (one line
    when the names fit on one: then the call is the long part)."""
    left = ", ".join(names)
    line = f"{left} = {call}"
    wrapped = _wrapped(left)
    if len(line) <= MAX_WIDTH or len(wrapped) == 1:
        return line
    middle = [" " + part for part in wrapped[1:-1]]
    return "\n".join(["(" + wrapped[0], *middle, " " + wrapped[-1] + f") = {call}"])


def quoted_names(names: list[str]) -> str:
    """The names as one string literal, space-separated; a long one as adjacent literals
    in parentheses, each piece ending with the space that follows it."""
    text = " ".join(names)
    parts = _wrapped(text)
    if len(parts) == 1:
        return quote(text)
    return "(" + " ".join(quote(p + (" " if i < len(parts) - 1 else ""))
                          for i, p in enumerate(parts)) + ")"


def call_lines(head: str, items: list[str], close: str = ")") -> str:
    """head + items + close on one line, or one item per line when that is long."""
    line = head + ", ".join(items) + close
    if len(line) <= MAX_WIDTH:
        return line
    return "\n".join([head, *(f"    {it}," for it in items), close])
