"""The kind of a CODE command is typed: it knows whether its program integrates, solves
or starts from guesses, and the language's words for it are its values."""
import re

import pytest

import autolev.runtime as al
from autolev.cli import main
from autolev.irbuild import CODE_KINDS
from autolev.programs import WRITERS
from autolev.runtime.io import CodeKind


def test_the_words_the_reader_takes_are_the_kinds():
    assert CODE_KINDS == tuple(k.value for k in CodeKind)


@pytest.mark.parametrize("word, integrates, guesses", [
    ("DYNAMICS", True, False), ("ode", True, False),
    ("Algebraic", False, False), ("NONLINEAR", False, True)])
def test_a_commands_kind_says_what_its_program_does(word, integrates, guesses):
    model = al.Model("m")
    model.code(word, "m.c")
    kind = model.code_commands[-1].kind
    assert kind is CodeKind(word.lower())
    assert (kind.integrates, kind.solves, kind.from_guesses) == (integrates, not integrates,
                                                                 guesses)
    assert f"CODE {kind}" == f"CODE {word.lower()}"


def test_an_unknown_kind_is_the_models_error():
    with pytest.raises(al.AutolevModelError, match="not a kind of program"):
        al.Model("m").code("SIMULATE", "m.c")


def test_every_program_written_is_of_a_kind():
    assert {kind for kind, _ in WRITERS} == set(CodeKind)


LANGUAGES = {".c": "C", ".m": "Matlab", ".f": "Fortran", ".for": "Fortran"}


def test_code_help_names_each_kind_with_the_languages_written_for_it(capsys):
    """`autolev code --help` says, for each kind, exactly the languages and extensions
    WRITERS holds for it (the help once named only ALGEBRAIC and DYNAMICS in .c, .m)."""
    with pytest.raises(SystemExit):
        main(["code", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    written = text.split("Written: ", 1)[1].split(". ", 1)[0]
    said: dict = {}
    for part in written.split("; "):
        kinds, languages = part.removeprefix("CODE ").split(" into ")
        for kind in kinds.split(" and "):
            said[CodeKind(kind.lower())] = {
                (name, ext) for name, exts in re.findall(r"(\w+)(?: 77)? \(([^:)]+)", languages)
                for ext in exts.split(", ")}
    assert said == {kind: {(LANGUAGES[ext], ext) for k, ext in WRITERS if k is kind}
                    for kind in CodeKind}
