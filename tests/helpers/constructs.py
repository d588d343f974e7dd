"""tests/fixtures/constructs.txt: Autolev statement -> the Python written for it, one
construct per case (as sqlglot keeps its fixtures).  Read by tests/translate/test_constructs.py,
rewritten only by tools/update_goldens.py."""
from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

import autolev

FIXTURE = Path(__file__).resolve().parents[1] / "fixtures" / "constructs.txt"
TITLE, ARROW = ":: ", "=>"


@dataclass(frozen=True)
class Case:
    title: str
    autolev: tuple[str, ...]     # the scene, then the statement under test
    python: tuple[str, ...]      # what the file says the translator writes for it


def read(path: Path = FIXTURE) -> tuple[list[str], list[Case]]:
    """(the file's heading comment lines, its cases)."""
    heading: list[str] = []
    cases: list[Case] = []
    title, autolev_lines, python_lines, after_arrow = None, [], [], False
    for line in path.read_text().splitlines():
        if line.startswith(TITLE):
            if title is not None:
                cases.append(Case(title, tuple(autolev_lines), tuple(python_lines)))
            title, autolev_lines, python_lines, after_arrow = line[len(TITLE):], [], [], False
        elif title is None:
            heading.append(line)
        elif line == ARROW:
            after_arrow = True
        elif line.strip():
            (python_lines if after_arrow else autolev_lines).append(line)
    if title is not None:
        cases.append(Case(title, tuple(autolev_lines), tuple(python_lines)))
    return heading, cases


def written_for(case: Case) -> tuple[str, ...]:
    """The code lines the translator writes today for the case's last statement."""
    text = "\n".join(case.autolev) + "\n"
    translation = autolev.translation(text, "construct.al")
    last = len(case.autolev)
    return tuple(line for number, line in enumerate(translation.code.splitlines(), 1)
                 if (span := translation.line_map.get(number)) is not None
                 and span.line == last and not line.lstrip().startswith("#"))


def render(heading: list[str], cases: list[Case]) -> str:
    out = list(heading)
    for case in cases:
        out += [TITLE + case.title, *case.autolev, ARROW, *case.python, ""]
    return "\n".join(out)


def updated(path: Path = FIXTURE) -> tuple[str, str]:
    """(the file's text, the text with every case's Python written anew)."""
    heading, cases = read(path)
    fresh = [replace(case, python=written_for(case)) for case in cases]
    return path.read_text(), render(heading, fresh)
