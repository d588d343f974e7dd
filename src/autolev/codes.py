"""The registry of diagnostic codes: every code a diagnostic may carry, with its meaning.

A code names a kind of fault, not a message: `E` for reading a file, `W` for warnings,
`T` for translating, `R` for building and running.  docs/language.md's table of codes is
made from this registry (`python -m autolev.codes --markdown`), and a test finds every
code the sources use here and every code here in use.
"""
from __future__ import annotations

import argparse
import sys
from dataclasses import dataclass

FAMILIES = {"E": "reading a file", "W": "warnings", "T": "translating",
            "R": "building and running the translation"}


@dataclass(frozen=True)
class Code:
    """One diagnostic code: what it means, and an example of its message."""

    code: str
    meaning: str
    example: str = ""

    @property
    def family(self) -> str:
        return FAMILIES[self.code[0]]


_ALL = (
    Code("E000", "the file cannot be read: missing, a folder, not text, or refused",
         "bike.al: error: no such file"),
    Code("E001", "a character that no word of the language begins with",
         "unexpected character '$'"),
    Code("E002", "a word where the grammar expects another", "unexpected ')'; expected a name"),
    Code("E003", "the statement ends before the grammar expects it to",
         "unexpected end of line; expected ')'"),
    Code("E004", "a statement nested too deeply to read",
         "this statement is nested too deeply to read"),
    Code("E005", "a declaration or command with no items after it",
         "VARIABLES needs at least one item after it"),
    Code("E006", "a prime apart from its name", "a prime must follow the name directly"),
    Code("E007", "a construct the grammar reads that the IR builder has no handler for",
         "fooStatement: read by the grammar but not supported yet"),
    Code("E010", "a first word that is no setting or command, with no '=' after it",
         "unknown setting or command 'SIMPORT'; did you mean SIMPROT?"),
    Code("E011", "an unknown CODE kind", "unknown CODE kind 'DYNAMIC'; expected ..."),
    Code("E012", "an unknown CODE option", "unknown CODE option 'FAST'; expected ..."),
    Code("E013", "a file name with blanks", "a file name cannot contain blanks"),
    Code("E014", "a setting without a value, or with one it does not take",
         "PRINTINT needs a whole number, not 0.5"),
    Code("E020", "RUN in a model given as text, which has no folder to read files from",
         "RUN x.al: a model given as text has no folder to look in"),
    Code("E021", "RUN of a path that leaves the model's folder",
         "RUN ../x.al: refused, the path leaves the model's folder"),
    Code("E022", "RUN of a file that is not there", "RUN x.al: no such file next to the model"),
    Code("E023", "a file that RUNs itself, directly or through others",
         "RUN a.al: the file includes itself"),
    Code("E024", "RUN files nested too deep", "RUN x.al: files nested deeper than 32 levels"),
    Code("E025", "a macro or function whose file leads outside the model's folder",
         "macro M: refused, its file m.a leads outside the model's folder (...), through a link"),
    Code("E030", "a macro or function call with fewer arguments than its text uses",
         "macro M (m.a) uses #3# but this call gives 2 arguments"),
    Code("E031", "a macro or function that calls itself", "function F calls itself"),
    Code("E032", "a function file that is not one expression",
         "function F (f.r) must hold one expression"),
    Code("E033", "expansion beyond the budget of text or statements",
         "the model with its RUN files, macros and functions expands to more than 1 MB "
         "of text or 20000 statements"),
    Code("E040", "an empty range of names", "empty range {3:1}: 3 is above 1"),
    Code("E041", "a range that declares too many names",
         "this range declares 2000000 names; at most 100000 are allowed"),
    Code("E042", "in MASS B=m=value, a middle part that is not a name",
         "in MASS B=m=value, the middle part must be a name"),
    Code("E043", "a definition inside INERTIA of something other than a name",
         "only a name can be defined inside INERTIA"),
    Code("E044", "INERTIA with a number of values other than 3 or 6",
         "INERTIA takes 3 or 6 values (I11, I22, I33[, I12, I23, I31]), not 4"),
    Code("E045", "a number written with more characters than are read",
         "a number of 5000 characters; at most 400 are read"),
    Code("W001", "a name declared again with the same kind, with no value",
         "'Q' is declared again (first on line 1)"),
    Code("W002", "a name declared again with another kind",
         "'Q' was declared as a variable on line 2; it is now a constant"),
    Code("W101", "a statement translated with a caveat the message states",
         "'A' is declared again; the new frame replaces it"),
    Code("W103", "statements after EXIT, which Autolev ignored",
         "2 statement(s) after EXIT are ignored, as Autolev ignored them"),
    Code("W104", "an INPUT of a name that is not declared: its value is not used",
         "INPUT X: not a declared name nor an integration parameter (...); the value is not used"),
    Code("W105", "T declared as a variable or constant: it is no longer the time",
         "'T' is declared as a variable: in this model T is that variable, not the time"),
    Code("W106", "a stray .a or .R file named as a function of Autolev's own, not read",
         "cos.R has the name of Autolev's own function COS: the function is meant here, "
         "the file is not read"),
    Code("W107", "FRSTAR() where a body that turns has no inertia given",
         "body A has no INERTIA, and it turns (m.al:5): FRSTAR() needs its inertia "
         "(INERTIA A, I11, I22, I33)"),
    Code("T001", "wrong type: an operand, argument or value of a type the operation does "
         "not take", "FORCE takes a vector, not a scalar"),
    Code("T002", "not declared or defined: a name read before any declaration or value; "
         "the statement's other such names are reported with it",
         "'Q9' is not declared or defined"),
    Code("T003", "unknown word: a function, command, keyword argument or unit Autolev "
         "gives no meaning here", "unknown function FOO()"),
    Code("T004", "too deep or too long to translate: functions nested more than 32 deep, "
         "sums of more than 2000 terms, expressions beyond Python's recursion",
         "functions nested more than 32 deep"),
    Code("T005", "a number too large to compute exactly or beyond double precision",
         "this power has about 1e+10 digits"),
    Code("T006", "not supported yet: a construct Autolev has that the translator does not "
         "translate, or an IR node with no handler",
         "a prime on an indexed name is not supported"),
    Code("T007", "wrong number of arguments or items", "SIN takes 1 argument, not 2"),
    Code("T008", "a name of the wrong kind: used as a frame, point, body, declared variable "
         "or matrix that it is not", "a frame or body is needed here"),
    Code("T009", "an argument not in the form the function or command takes: '=' or ':' "
         "where none is taken, a required name or x=v missing", "expected name=value"),
    Code("T010", "an assignment or declaration Autolev does not have: a target that cannot "
         "be assigned or an operator not defined for it", "N1> cannot be assigned"),
    Code("R001", "a statement of the translation failed when it ran, by the model's fault",
         "division by zero"),
    Code("R002", "a Python file given as a translation that is not Python",
         "not Python: invalid syntax"),
    Code("R003", "a Python file given as a translation that defines no model",
         "this module defines no `model`"),
)

CODES: dict[str, Code] = {c.code: c for c in _ALL}


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def markdown() -> str:
    """The table of codes as docs/language.md shows it."""
    rows = ["| code | meaning | for example |", "|---|---|---|"]
    for c in _ALL:
        rows.append(f"| `{c.code}` | {_cell(c.meaning)} | {_cell(c.example)} |")
    return "\n".join(rows) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m autolev.codes",
                                     description="the registry of diagnostic codes")
    parser.add_argument("--markdown", action="store_true",
                        help="print docs/language.md's table of codes")
    ns = parser.parse_args(argv)
    if ns.markdown:
        sys.stdout.write(markdown())
    else:
        for c in _ALL:
            print(f"{c.code}  {c.meaning}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
