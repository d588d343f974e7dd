"""What tests share: paths, and short ways to parse and load models."""
import os
from pathlib import Path

import pytest

import autolev

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "autolev_examples"
CORPUS = Path(os.environ.get("AUTOLEV_CORPUS", Path.home() / ".cache" / "autolev-corpus"))
# the project's shared folder (beside the repository; AUTOLEV_SHARED from a worktree elsewhere)
SHARED = Path(os.environ.get("AUTOLEV_SHARED", ROOT.parent / "shared"))
NUMERICS_DATA = ROOT / "tests" / "data" / "numerics"


def load_model(name: str):
    """A model of tests/data/numerics, else of autolev_examples, by file stem."""
    path = NUMERICS_DATA / f"{name}.al"
    return autolev.load(path if path.exists() else EXAMPLES / f"{name}.al")


def parse(text: str, filename: str = "test.al") -> autolev.Program:
    return autolev.parse(text, filename)


def errors_of(text: str, filename: str = "test.al") -> list[autolev.Diagnostic]:
    """The diagnostics of text that must fail to parse."""
    with pytest.raises(autolev.AutolevSyntaxError) as info:
        autolev.parse(text, filename)
    return [d for d in info.value.diagnostics if d.severity == "error"]


def only(program: autolev.Program, kind: str | None = None):
    """The single statement of a one-statement program (optionally of that kind)."""
    sts = [s for s in program.statements if kind is None or s.kind == kind]
    assert len(sts) == 1, sts
    return sts[0]


def expr(text: str):
    """The IR of an expression, read as the right side of an assignment."""
    return only(parse(f"X_ = {text}")).value
