"""Text from outside in the generated module: the one place that quotes it.

File names, the model's own lines and `%` comments, labels, units and names come from
files a user may not have written.  None of it becomes code: every piece goes into the
module through `quote` (a Python string literal), `comment` (the body of a one-line
comment) or `docstring` (a line inside the module's docstring).
"""
from __future__ import annotations

import re

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
